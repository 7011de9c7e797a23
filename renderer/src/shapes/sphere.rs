//! The unit sphere at the origin; `sphere { centre, radius }` is this, scaled and moved.

use super::{Root, Roots, solve_quadratic_half};
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere;

impl Sphere {
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        if let Some((t1, t2)) = crossings(ray) {
            roots.push(t1, 0);
            roots.push(t2, 0);
        }
    }

    /// The nearer crossing in `(tmin, tmax)`, found without collecting both: the same
    /// crossing [`Self::intersect`] gives, for the rays of every pixel.
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        let (t1, t2) = crossings(ray)?;
        super::nearest_in(&[t1, t2], tmin, tmax).map(|t| Root { t, part: 0 })
    }

    /// Where the ray enters and leaves the sphere.
    pub fn span(&self, ray: &Ray) -> Option<(f64, f64)> {
        crossings(ray)
    }

    pub fn inside(&self, p: DVec3) -> bool {
        p.length_squared() < 1.0
    }
}

/// The ray parameters where the ray crosses the unit sphere, in increasing order.
fn crossings(ray: &Ray) -> Option<(f64, f64)> {
    let a = ray.direction.length_squared();
    let b = ray.origin.dot(ray.direction);
    let c = ray.origin.length_squared() - 1.0;
    solve_quadratic_half(a, b, c)
}
