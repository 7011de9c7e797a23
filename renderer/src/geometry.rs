//! Answers the evaluator's geometric queries (`trace()`, `inside()`, `min_extent()`,
//! `max_extent()`, the `object` pattern) with the renderer's own shapes, so parse-time
//! answers agree with the picture.

use crate::build::{BuildSettings, build_world};
use crate::object::Query;
use crate::ray::{Ray, RayKind};
use crate::tracer::World;
use analysis::scene::{Object, Scene};
use analysis::{InsideTest, Tracer};
use glam::DVec3;
use syntax::Diagnostic;

/// The extent POV-Ray gives unbounded objects.
const HUGE_BOUND: f64 = 1.0e10;

/// The renderer's implementation of [`analysis::Geometry`].
#[derive(Debug, Clone, Copy, Default)]
pub struct SceneGeometry;

/// A world holding just `object`, as the renderer would build it.
fn world_of(object: &Object) -> Result<World, String> {
    let scene = Scene {
        camera: Default::default(),
        lights: Vec::new(),
        objects: vec![object.clone()],
        background: None,
        fogs: Vec::new(),
        rainbows: Vec::new(),
        sky_sphere: None,
        media: Vec::new(),
        settings: Default::default(),
        version: None,
    };
    let settings = BuildSettings {
        quality: 9,
        output_alpha: false,
        max_trace_level: None,
    };
    build_world(&scene, settings).map_err(|error| error.message)
}

impl analysis::Geometry for SceneGeometry {
    fn render_error(&self, main: &str, scene: &Scene) -> Option<Diagnostic> {
        crate::build::check_scene(scene)
            .err()
            .map(|error| error.diagnostic(main))
    }

    fn tracer(&self, object: &Object) -> Result<Tracer, String> {
        let world = world_of(object)?;
        Ok(Tracer::new(move |origin, direction| {
            let direction = direction.normalize_or_zero();
            if direction == DVec3::ZERO {
                return Err("trace() needs a non-zero direction".into());
            }
            let ray = Ray::new(origin, direction);
            let query = Query::new(ray, RayKind::Primary, 0.0, f64::INFINITY);
            let mut scratch = Vec::new();
            Ok(world.bvh.nearest(&query, &mut scratch).map(|hit| {
                let point = ray.at(hit.t);
                (point, hit.leaf.normal(point, hit.part))
            }))
        }))
    }

    fn inside_test(&self, object: &Object) -> Result<InsideTest, String> {
        let world = world_of(object)?;
        Ok(InsideTest::new(move |point| world.bvh.contains(point)))
    }

    fn extent(&self, object: &Object) -> Result<(DVec3, DVec3), String> {
        let world = world_of(object)?;
        if world.bvh.has_unbounded() {
            // POV-Ray reports infinite objects with its "huge" bound.
            return Ok((DVec3::splat(-HUGE_BOUND), DVec3::splat(HUGE_BOUND)));
        }
        let bounds = world.bvh.bounds();
        Ok((bounds.min, bounds.max))
    }
}
