//! The unit cylinder: radius 1 around the z axis from z = 0 to z = 1, with or without caps.
//! `cylinder { base, cap, radius }` is this, stretched and turned onto its axis.

use super::{Roots, solve_quadratic_half};
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cylinder {
    pub open: bool,
}

const SIDE: u32 = 0;
const BASE: u32 = 1;
const CAP: u32 = 2;

impl Cylinder {
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let (o, d) = (ray.origin, ray.direction);
        let a = d.x * d.x + d.y * d.y;
        let b = o.x * d.x + o.y * d.y;
        let c = o.x * o.x + o.y * o.y - 1.0;
        if a > 0.0
            && let Some((t1, t2)) = solve_quadratic_half(a, b, c)
        {
            for t in [t1, t2] {
                let z = o.z + t * d.z;
                if (0.0..=1.0).contains(&z) {
                    roots.push(t, SIDE);
                }
            }
        }
        if !self.open && d.z != 0.0 {
            for (z, part) in [(0.0, BASE), (1.0, CAP)] {
                let t = (z - o.z) / d.z;
                let (x, y) = (o.x + t * d.x, o.y + t * d.y);
                if x * x + y * y <= 1.0 {
                    roots.push(t, part);
                }
            }
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        p.x * p.x + p.y * p.y < 1.0 && p.z > 0.0 && p.z < 1.0
    }

    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match part {
            BASE => -DVec3::Z,
            CAP => DVec3::Z,
            _ => DVec3::new(p.x, p.y, 0.0),
        }
    }
}
