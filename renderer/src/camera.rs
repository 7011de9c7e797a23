//! Primary rays. The camera's vectors are used as the scene gives them (the evaluator has
//! applied `look_at`, `angle` and `sky`), so a mirrored `right` mirrors the picture, as in
//! POV-Ray.

use crate::ray::Ray;
use analysis::scene::{self, CameraKind};
use glam::DVec3;

#[derive(Debug, Clone)]
pub struct Camera {
    kind: Projection,
    location: DVec3,
    direction: DVec3,
    right: DVec3,
    up: DVec3,
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum Projection {
    Perspective,
    Orthographic,
}

impl Camera {
    pub fn from_scene(camera: &scene::Camera) -> Result<Camera, String> {
        let kind = match camera.kind {
            CameraKind::Perspective => Projection::Perspective,
            CameraKind::Orthographic => Projection::Orthographic,
            other => return Err(format!("not supported yet: {other:?} camera")),
        };
        if camera.focal_blur.is_some() {
            return Err("not supported yet: focal blur".into());
        }
        Ok(Camera {
            kind,
            location: camera.location,
            direction: camera.direction,
            right: camera.right,
            up: camera.up,
        })
    }

    /// The ray through image position `(x, y)`, in pixels from the top-left corner of the
    /// image (pixel centres at half-integers). `None` when the projection has no ray there.
    pub fn ray(&self, x: f64, y: f64, width: f64, height: f64) -> Option<Ray> {
        let x0 = x / width - 0.5;
        let y0 = 0.5 - y / height;
        let ray = match self.kind {
            Projection::Perspective => Ray::new(
                self.location,
                self.direction + x0 * self.right + y0 * self.up,
            ),
            Projection::Orthographic => Ray::new(
                self.location + x0 * self.right + y0 * self.up,
                self.direction,
            ),
        };
        let direction = ray.direction.normalize_or_zero();
        (direction != DVec3::ZERO && ray.origin.is_finite())
            .then(|| Ray::new(ray.origin, direction))
    }
}
