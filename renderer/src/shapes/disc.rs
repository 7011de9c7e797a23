//! `disc { centre, normal, radius, hole }` in its frame: the ring between `hole` and
//! `radius` around the origin in the plane z = 0, whose inside is the half-space below it.

use super::Roots;
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Disc {
    pub radius: f64,
    pub hole: f64,
}

impl Disc {
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        if ray.direction.z == 0.0 {
            return;
        }
        let t = -ray.origin.z / ray.direction.z;
        let p = ray.at(t);
        let r2 = p.x * p.x + p.y * p.y;
        if r2 <= self.radius * self.radius && r2 >= self.hole * self.hole {
            roots.push(t, 0);
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        p.z < 0.0
    }
}
