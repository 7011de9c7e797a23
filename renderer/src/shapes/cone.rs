//! A cone frustum along the z axis from z = 0 (radius `base_radius`) to z = 1 (radius
//! `cap_radius`), with or without its end discs. `cone { }` is this, turned onto its axis.

use super::{Roots, solve_quadratic_half};
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cone {
    pub base_radius: f64,
    pub cap_radius: f64,
    pub open: bool,
}

const SIDE: u32 = 0;
const BASE: u32 = 1;
const CAP: u32 = 2;

impl Cone {
    fn radius_at(&self, z: f64) -> f64 {
        self.base_radius + (self.cap_radius - self.base_radius) * z
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let (o, d) = (ray.origin, ray.direction);
        let k = self.cap_radius - self.base_radius;
        let r0 = self.radius_at(o.z);
        let a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
        let b = o.x * d.x + o.y * d.y - k * d.z * r0;
        let c = o.x * o.x + o.y * o.y - r0 * r0;
        if let Some((t1, t2)) = solve_quadratic_half(a, b, c) {
            for t in [t1, t2] {
                let z = o.z + t * d.z;
                // The other nappe of the double cone has a negative radius there.
                if (0.0..=1.0).contains(&z) && self.radius_at(z) >= 0.0 {
                    roots.push(t, SIDE);
                }
            }
        }
        if !self.open && d.z != 0.0 {
            for (z, r, part) in [(0.0, self.base_radius, BASE), (1.0, self.cap_radius, CAP)] {
                if r <= 0.0 {
                    continue;
                }
                let t = (z - o.z) / d.z;
                let (x, y) = (o.x + t * d.x, o.y + t * d.y);
                if x * x + y * y <= r * r {
                    roots.push(t, part);
                }
            }
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        let r = self.radius_at(p.z);
        p.z > 0.0 && p.z < 1.0 && p.x * p.x + p.y * p.y < r * r
    }

    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match part {
            BASE => -DVec3::Z,
            CAP => DVec3::Z,
            _ => {
                let k = self.cap_radius - self.base_radius;
                DVec3::new(p.x, p.y, -k * self.radius_at(p.z))
            }
        }
    }
}
