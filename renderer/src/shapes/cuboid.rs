//! `box { corner1, corner2 }`: an axis-aligned box in its own frame.

use super::{Root, Roots};
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cuboid {
    pub min: DVec3,
    pub max: DVec3,
}

impl Cuboid {
    pub fn new(a: DVec3, b: DVec3) -> Cuboid {
        Cuboid {
            min: a.min(b),
            max: a.max(b),
        }
    }

    /// Parts are faces: `2 * axis` for the low side, `2 * axis + 1` for the high side.
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        if let Some((near, far)) = self.crossings(ray) {
            roots.push(near.t, near.part);
            roots.push(far.t, far.part);
        }
    }

    /// The nearer crossing in `(tmin, tmax)`, without a list of crossings around it.
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        let (near, far) = self.crossings(ray)?;
        [near, far]
            .into_iter()
            .find(|r| r.t.is_finite() && r.t > tmin && r.t < tmax)
    }

    /// Where the ray enters and leaves the box, with the faces it crosses.
    pub(crate) fn crossings(&self, ray: &Ray) -> Option<(Root, Root)> {
        let mut near = f64::NEG_INFINITY;
        let mut far = f64::INFINITY;
        let mut near_part = 0;
        let mut far_part = 0;
        for axis in 0..3 {
            let o = ray.origin[axis];
            let d = ray.direction[axis];
            let (lo, hi) = (self.min[axis], self.max[axis]);
            if d == 0.0 {
                if o < lo || o > hi {
                    return None;
                }
                continue;
            }
            let (mut t1, mut t2) = ((lo - o) / d, (hi - o) / d);
            let (mut p1, mut p2) = (2 * axis as u32, 2 * axis as u32 + 1);
            if t1 > t2 {
                std::mem::swap(&mut t1, &mut t2);
                std::mem::swap(&mut p1, &mut p2);
            }
            if t1 > near {
                near = t1;
                near_part = p1;
            }
            if t2 < far {
                far = t2;
                far_part = p2;
            }
        }
        (near <= far).then_some((
            Root {
                t: near,
                part: near_part,
            },
            Root {
                t: far,
                part: far_part,
            },
        ))
    }

    pub fn inside(&self, p: DVec3) -> bool {
        p.cmpgt(self.min).all() && p.cmplt(self.max).all()
    }

    pub fn normal(&self, part: u32) -> DVec3 {
        let mut n = DVec3::ZERO;
        n[(part / 2) as usize] = if part.is_multiple_of(2) { -1.0 } else { 1.0 };
        n
    }
}
