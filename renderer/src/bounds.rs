//! Axis-aligned bounding boxes in world space, with the slab test rays use to skip objects.

use crate::ray::Ray;
use glam::{DAffine3, DVec3};

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aabb {
    pub min: DVec3,
    pub max: DVec3,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb {
        min: DVec3::splat(f64::INFINITY),
        max: DVec3::splat(f64::NEG_INFINITY),
    };

    pub const INFINITE: Aabb = Aabb {
        min: DVec3::splat(f64::NEG_INFINITY),
        max: DVec3::splat(f64::INFINITY),
    };

    pub fn new(a: DVec3, b: DVec3) -> Aabb {
        Aabb {
            min: a.min(b),
            max: a.max(b),
        }
    }

    pub fn is_finite(&self) -> bool {
        self.min.is_finite() && self.max.is_finite()
    }

    /// Whether `other` lies wholly inside this box.
    pub fn contains(&self, other: &Aabb) -> bool {
        self.min.cmple(other.min).all() && self.max.cmpge(other.max).all()
    }

    pub fn is_empty(&self) -> bool {
        self.min.x > self.max.x || self.min.y > self.max.y || self.min.z > self.max.z
    }

    pub fn union(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.min(other.min),
            max: self.max.max(other.max),
        }
    }

    pub fn intersection(&self, other: &Aabb) -> Aabb {
        Aabb {
            min: self.min.max(other.min),
            max: self.max.min(other.max),
        }
    }

    pub fn centre(&self) -> DVec3 {
        (self.min + self.max) * 0.5
    }

    /// The eight corners of a finite box.
    pub fn corners(&self) -> [DVec3; 8] {
        std::array::from_fn(|i| {
            DVec3::new(
                if i & 1 == 0 { self.min.x } else { self.max.x },
                if i & 2 == 0 { self.min.y } else { self.max.y },
                if i & 4 == 0 { self.min.z } else { self.max.z },
            )
        })
    }

    /// The box around this box after an affine map. Infinite extents stay infinite along
    /// every axis they can reach.
    pub fn transformed(&self, m: &DAffine3) -> Aabb {
        if self.is_empty() {
            return *self;
        }
        if !self.is_finite() {
            return self.transformed_unbounded(m);
        }
        let mut out = Aabb::EMPTY;
        for corner in self.corners() {
            let p = m.transform_point3(corner);
            out.min = out.min.min(p);
            out.max = out.max.max(p);
        }
        out
    }

    fn transformed_unbounded(&self, m: &DAffine3) -> Aabb {
        // Centre plus half-extent per output axis; an infinite half-extent spreads to
        // every output axis its input axis feeds.
        let centre = self.min.max(DVec3::splat(-1e300)).min(DVec3::splat(1e300));
        let centre = (centre + self.max.max(DVec3::splat(-1e300)).min(DVec3::splat(1e300))) * 0.5;
        let half = (self.max - self.min) * 0.5;
        let c = m.transform_point3(centre);
        let a = m.matrix3;
        let mut extent = DVec3::ZERO;
        for row in 0..3 {
            let mut e = 0.0;
            for col in 0..3 {
                let w = a.col(col)[row].abs();
                if w != 0.0 {
                    e += w * half[col];
                }
            }
            extent[row] = e;
        }
        Aabb {
            min: c - extent,
            max: c + extent,
        }
    }

    /// The parameter interval where the ray's whole line is inside the box.
    pub fn line_span(&self, ray: &Ray) -> Option<(f64, f64)> {
        self.clip(ray, ray.direction.recip(), f64::NEG_INFINITY, f64::INFINITY)
    }

    /// The parameter interval where the ray is inside the box, clipped to `[tmin, tmax]`
    /// (neither NaN); `None` when it misses. `inv_dir` is the componentwise reciprocal of
    /// the direction.
    #[inline]
    pub fn clip(&self, ray: &Ray, inv_dir: DVec3, tmin: f64, tmax: f64) -> Option<(f64, f64)> {
        let t1 = (self.min - ray.origin) * inv_dir;
        let t2 = (self.max - ray.origin) * inv_dir;
        // NaN (0 * inf on a slab boundary) must not reject a hit: the running bounds
        // start from `tmin` and `tmax` and so are never NaN, and a comparison with a NaN
        // slab keeps them.
        let near = t1.min(t2);
        let far = t1.max(t2);
        let lo = raise(raise(raise(tmin, near.x), near.y), near.z);
        let hi = lower(lower(lower(tmax, far.x), far.y), far.z);
        (lo <= hi).then_some((lo, hi))
    }
}

/// The larger of the bound `x` and `y`; `x` when `y` is NaN. One instruction natively
/// (the comparisons of `f64::max` that also drop a NaN `x` are not needed here).
#[inline]
fn raise(x: f64, y: f64) -> f64 {
    if y > x { y } else { x }
}

/// The smaller of the bound `x` and `y`; `x` when `y` is NaN.
#[inline]
fn lower(x: f64, y: f64) -> f64 {
    if y < x { y } else { x }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slab_test() {
        let b = Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0));
        let ray = Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z);
        let (lo, hi) = b
            .clip(&ray, ray.direction.recip(), 0.0, f64::INFINITY)
            .unwrap();
        assert_eq!((lo, hi), (4.0, 6.0));
        let miss = Ray::new(DVec3::new(2.0, 0.0, -5.0), DVec3::Z);
        assert!(
            b.clip(&miss, miss.direction.recip(), 0.0, f64::INFINITY)
                .is_none()
        );
        // A ray lying in a slab's boundary plane still hits.
        let grazing = Ray::new(DVec3::new(1.0, 0.0, -5.0), DVec3::Z);
        assert!(
            b.clip(&grazing, grazing.direction.recip(), 0.0, f64::INFINITY)
                .is_some()
        );
    }

    #[test]
    fn infinite_boxes_transform() {
        let half_space = Aabb {
            min: DVec3::new(f64::NEG_INFINITY, f64::NEG_INFINITY, -1.0),
            max: DVec3::new(f64::INFINITY, f64::INFINITY, 1.0),
        };
        let moved = half_space.transformed(&DAffine3::from_translation(DVec3::Z));
        assert_eq!(moved.min.z, 0.0);
        assert_eq!(moved.max.z, 2.0);
        assert!(moved.min.x.is_infinite());
    }
}
