//! `plane { normal, distance }`: the half-space below `normal · p = distance` is inside.

use super::{Root, Roots};
use crate::bounds::Aabb;
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    /// Unit length.
    pub normal: DVec3,
    pub distance: f64,
    /// The unit normal in the world, which the leaf placing the shape works out once
    /// (`Leaf::new`, through [`Plane::place`]); zero until then, or where its frame
    /// flattens the shape.
    world_normal: DVec3,
}

impl Plane {
    pub fn new(normal: DVec3, distance: f64) -> Plane {
        Plane {
            normal,
            distance,
            world_normal: DVec3::ZERO,
        }
    }

    /// The unit normal in the world that [`Plane::place`] kept, or zero.
    pub fn world_normal(&self) -> DVec3 {
        self.world_normal
    }

    /// Keeps the unit normal in the world of the leaf that places the shape.
    pub fn place(&mut self, world_normal: DVec3) {
        self.world_normal = world_normal;
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        if let Some(t) = self.crossing(ray) {
            roots.push(t, 0);
        }
    }

    /// The crossing in `(tmin, tmax)`, without a list of crossings around it.
    #[inline(always)]
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        super::nearest_in(&[self.crossing(ray)?], tmin, tmax).map(|t| Root { t, part: 0 })
    }

    #[inline(always)]
    pub(super) fn crossing(&self, ray: &Ray) -> Option<f64> {
        let denom = self.normal.dot(ray.direction);
        (denom != 0.0).then(|| (self.distance - self.normal.dot(ray.origin)) / denom)
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.normal.dot(p) < self.distance
    }

    /// Planes along an axis are bounded on that axis, on one side.
    pub fn bounds(&self) -> Aabb {
        let mut b = Aabb::INFINITE;
        for axis in 0..3 {
            let n = self.normal[axis];
            if n.abs() == 1.0 {
                let v = self.distance * n;
                if n > 0.0 {
                    b.max[axis] = v;
                } else {
                    b.min[axis] = v;
                }
            }
        }
        b
    }
}
