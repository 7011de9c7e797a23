//! The unit sphere at the origin; `sphere { centre, radius }` is this, scaled and moved.

use super::{Roots, solve_quadratic_half};
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere;

impl Sphere {
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let a = ray.direction.length_squared();
        let b = ray.origin.dot(ray.direction);
        let c = ray.origin.length_squared() - 1.0;
        if let Some((t1, t2)) = solve_quadratic_half(a, b, c) {
            roots.push(t1, 0);
            roots.push(t2, 0);
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        p.length_squared() < 1.0
    }
}
