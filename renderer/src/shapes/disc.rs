//! `disc { centre, normal, radius, hole }` in its frame: the ring between `hole` and
//! `radius` around the origin in the plane z = 0, whose inside is the half-space below it.

use super::{Root, Roots};
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Disc {
    pub radius: f64,
    pub hole: f64,
    /// The unit normal in the world, which the leaf placing the shape works out once
    /// (`Leaf::new`, through [`Disc::place`]); zero until then, or where its frame
    /// flattens the shape.
    world_normal: DVec3,
}

impl Disc {
    pub fn new(radius: f64, hole: f64) -> Disc {
        Disc {
            radius,
            hole,
            world_normal: DVec3::ZERO,
        }
    }

    /// The unit normal in the world that [`Disc::place`] kept, or zero.
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

    /// The crossing in `(tmin, tmax)`, without the list of crossings: camera, secondary
    /// and shadow rays test a disc this way, and the plugin paid for setting up the list.
    #[inline(always)]
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        super::nearest_in(&[self.crossing(ray)?], tmin, tmax).map(|t| Root { t, part: 0 })
    }

    /// Where the ray crosses the plane of the disc, if it does so within the ring.
    #[inline(always)]
    fn crossing(&self, ray: &Ray) -> Option<f64> {
        if ray.direction.z == 0.0 {
            return None;
        }
        let t = -ray.origin.z / ray.direction.z;
        let p = ray.at(t);
        let r2 = p.x * p.x + p.y * p.y;
        (r2 <= self.radius * self.radius && r2 >= self.hole * self.hole).then_some(t)
    }

    pub fn inside(&self, p: DVec3) -> bool {
        p.z < 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The direct test finds what the list of crossings finds, in the interval or not.
    #[test]
    fn first_hit_is_the_crossing_in_the_interval() {
        let disc = Disc::new(2.0, 0.5);
        let rays = [
            Ray::new(DVec3::new(1.0, 0.0, 3.0), DVec3::NEG_Z),
            Ray::new(DVec3::new(0.0, 0.0, 3.0), DVec3::NEG_Z),
            Ray::new(DVec3::new(3.0, 0.0, 3.0), DVec3::NEG_Z),
            Ray::new(DVec3::new(1.0, 0.0, 3.0), DVec3::X),
            Ray::new(
                DVec3::new(1.0, 1.0, -1.0),
                DVec3::new(0.1, 0.0, 1.0).normalize(),
            ),
        ];
        for ray in &rays {
            for (tmin, tmax) in [(0.0, f64::INFINITY), (0.0, 2.0), (1e-6, 3.5), (3.5, 9.0)] {
                let mut roots = Roots::new();
                disc.intersect(ray, &mut roots);
                let listed = roots
                    .as_slice()
                    .iter()
                    .copied()
                    .find(|r| r.t > tmin && r.t < tmax);
                assert_eq!(
                    disc.first_hit(ray, tmin, tmax),
                    listed,
                    "{ray:?} {tmin} {tmax}"
                );
            }
        }
        assert!(disc.first_hit(&rays[0], 0.0, f64::INFINITY).is_some());
    }
}
