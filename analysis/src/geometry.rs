//! The geometric questions a scene may ask while it is evaluated: `trace()`, `inside()`,
//! `min_extent()` and `max_extent()`. Answering them needs the renderer's shapes, so the
//! renderer implements [`Geometry`] and front ends hand it to the evaluator; without one,
//! those calls are located errors rather than made-up answers.

use crate::scene::Object;
use glam::DVec3;

/// Answers geometric queries about evaluated objects.
pub trait Geometry {
    /// The nearest intersection of the ray from `origin` along `direction` with `object`,
    /// and the surface normal there; `None` when the ray misses.
    fn trace(
        &self,
        object: &Object,
        origin: DVec3,
        direction: DVec3,
    ) -> Result<Option<(DVec3, DVec3)>, String>;
    /// Whether `point` lies inside `object`.
    fn inside(&self, object: &Object, point: DVec3) -> Result<bool, String>;
    /// The corners of `object`'s bounding box.
    fn extent(&self, object: &Object) -> Result<(DVec3, DVec3), String>;
}

/// For front ends without a renderer: every query is refused.
#[derive(Debug, Clone, Copy, Default)]
pub struct NoGeometry;

impl Geometry for NoGeometry {
    fn trace(&self, _: &Object, _: DVec3, _: DVec3) -> Result<Option<(DVec3, DVec3)>, String> {
        Err(REFUSAL.into())
    }

    fn inside(&self, _: &Object, _: DVec3) -> Result<bool, String> {
        Err(REFUSAL.into())
    }

    fn extent(&self, _: &Object) -> Result<(DVec3, DVec3), String> {
        Err(REFUSAL.into())
    }
}

const REFUSAL: &str = "this front end cannot answer geometric queries (trace, inside, extents)";
