//! The geometric questions a scene may ask while it is evaluated: `trace()`, `inside()`,
//! `min_extent()`, `max_extent()` and the `object` pattern's inside test. Answering them
//! needs the renderer's shapes, so the renderer implements [`Geometry`] and front ends hand
//! it to the evaluator; without one, those calls are located errors rather than made-up
//! answers.

use crate::scene::{Object, Scene};
use glam::DVec3;
use std::fmt;
use std::sync::Arc;
use syntax::Diagnostic;

/// Answers geometric queries about evaluated objects.
pub trait Geometry: Send + Sync {
    /// A tracer of rays against `object`, prepared once: scenes call `trace()` on the same
    /// object over and over (placing things on a terrain), and preparing it (building a
    /// height field's or a mesh's hierarchy) can cost far more than one ray.
    fn tracer(&self, object: &Object) -> Result<Tracer, String>;
    /// A test of whether a point lies inside `object`, prepared once: `inside()` asks it
    /// one question, the `object` pattern one at every point it colours.
    fn inside_test(&self, object: &Object) -> Result<InsideTest, String>;
    /// The corners of `object`'s bounding box.
    fn extent(&self, object: &Object) -> Result<(DVec3, DVec3), String>;
    /// What a render of `scene`, evaluated from `main`, would stop on that evaluating it
    /// does not find (a feature the renderer does not draw yet), so that checking a scene
    /// reports every error rendering it would. Without a renderer, nothing.
    fn render_error(&self, main: &str, scene: &Scene) -> Option<Diagnostic> {
        let _ = (main, scene);
        None
    }
}

/// For front ends without a renderer: every query is refused.
#[derive(Debug, Clone, Copy, Default)]
pub struct NoGeometry;

impl Geometry for NoGeometry {
    fn tracer(&self, _: &Object) -> Result<Tracer, String> {
        Err(REFUSAL.into())
    }

    fn inside_test(&self, _: &Object) -> Result<InsideTest, String> {
        Err(REFUSAL.into())
    }

    fn extent(&self, _: &Object) -> Result<(DVec3, DVec3), String> {
        Err(REFUSAL.into())
    }
}

const REFUSAL: &str =
    "this front end cannot answer geometric queries (trace, inside, extents, object pattern)";

/// The rays a scene traces against one object: for a ray from `origin` along `direction`,
/// the nearest intersection and the surface normal there, `None` when the ray misses.
pub struct Tracer(Box<dyn Fn(DVec3, DVec3) -> TraceResult>);

/// A traced ray's nearest hit and the normal there, if any, or why it could not be traced.
pub type TraceResult = Result<Option<(DVec3, DVec3)>, String>;

impl Tracer {
    pub fn new(trace: impl Fn(DVec3, DVec3) -> TraceResult + 'static) -> Tracer {
        Tracer(Box::new(trace))
    }

    pub fn trace(&self, origin: DVec3, direction: DVec3) -> TraceResult {
        (self.0)(origin, direction)
    }
}

impl fmt::Debug for Tracer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Tracer")
    }
}

/// Whether a point lies inside one object, as the renderer's shapes decide it.
#[derive(Clone)]
pub struct InsideTest(Arc<dyn Fn(DVec3) -> bool + Send + Sync>);

impl InsideTest {
    pub fn new(test: impl Fn(DVec3) -> bool + Send + Sync + 'static) -> InsideTest {
        InsideTest(Arc::new(test))
    }

    pub fn contains(&self, point: DVec3) -> bool {
        (self.0)(point)
    }
}

/// Two tests are equal when they are the same prepared test: a scene compares equal to
/// its clones, and a re-evaluated scene (with a newly prepared test) does not.
impl PartialEq for InsideTest {
    fn eq(&self, other: &InsideTest) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl fmt::Debug for InsideTest {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("InsideTest")
    }
}
