//! `ovus { bottom_radius, top_radius }`: a sphere of the bottom radius at the origin and
//! one of the top radius centred on the bottom one's top, joined by the inner part of a
//! spindle torus tangent to both. POV-Ray 3.7 gives the joining arc twice the larger
//! radius (measured on its renders); when the top sphere reaches around the bottom one
//! (top radius at least twice the bottom) the ovus is the top sphere alone.

use super::Roots;
use super::lemon::Spindle;
use crate::bounds::Aabb;
use crate::ray::Ray;
use glam::DVec3;

const BOTTOM: u32 = 0;
const TOP: u32 = 1;
const JOIN: u32 = 2;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ovus {
    bottom: f64,
    top: f64,
    /// The joining arc, between the heights where it touches the spheres; `None` when the
    /// top sphere holds the bottom one.
    join: Option<Spindle>,
}

impl Ovus {
    pub fn new(bottom: f64, top: f64) -> Ovus {
        let (b, t) = (bottom.abs(), top.abs());
        if t >= 2.0 * b || b == 0.0 {
            return Ovus {
                bottom: b,
                top: t,
                join: None,
            };
        }
        let r = 2.0 * b.max(t);
        // The arc's centre (-c, h) is r - b from the bottom centre (0, 0) and r - t from
        // the top centre (0, b).
        let h = (b * b - ((r - t).powi(2) - (r - b).powi(2))) / (2.0 * b);
        let c = ((r - b).powi(2) - h * h).max(0.0).sqrt();
        // The tangent points lie on the lines from the arc's centre through each sphere's.
        let y0 = h - h * r / (r - b);
        let y1 = h + (b - h) * r / (r - t);
        Ovus {
            bottom: b,
            top: t,
            join: Some(Spindle {
                c,
                h,
                radius: r,
                y0,
                y1,
            }),
        }
    }

    pub fn bounds(&self) -> Aabb {
        let Some(join) = self.join else {
            let t = self.top;
            return Aabb::new(
                DVec3::new(-t, self.bottom - t, -t),
                DVec3::splat(t) + DVec3::Y * self.bottom,
            );
        };
        let r = self.bottom.max(self.top).max(join.max_radius());
        Aabb::new(
            DVec3::new(-r, -self.bottom, -r),
            DVec3::new(r, self.bottom + self.top, r),
        )
    }

    /// The height below which the bottom sphere is the surface, and above which the top
    /// sphere is.
    fn seams(&self) -> (f64, f64) {
        match self.join {
            Some(j) => (j.y0, j.y1),
            None => (f64::NEG_INFINITY, f64::NEG_INFINITY),
        }
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let (low, high) = self.seams();
        let (o, d) = (ray.origin, ray.direction);
        for (centre, radius, part) in [(0.0, self.bottom, BOTTOM), (self.bottom, self.top, TOP)] {
            let oc = o - DVec3::Y * centre;
            if let Some((t0, t1)) = super::solve_quadratic_half(
                d.length_squared(),
                oc.dot(d),
                oc.length_squared() - radius * radius,
            ) {
                for t in [t0, t1] {
                    let y = o.y + t * d.y;
                    let keep = if part == BOTTOM { y <= low } else { y >= high };
                    if keep {
                        roots.push(t, part);
                    }
                }
            }
        }
        if let Some(join) = &self.join {
            join.intersect(ray, JOIN, roots);
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        let (low, high) = self.seams();
        if p.y <= low {
            p.length_squared() < self.bottom * self.bottom
        } else if p.y >= high {
            (p - DVec3::Y * self.bottom).length_squared() < self.top * self.top
        } else {
            self.join.is_some_and(|j| j.inside(p))
        }
    }

    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match (part, &self.join) {
            (JOIN, Some(join)) => join.normal(p),
            (BOTTOM, _) => p,
            _ => p - DVec3::Y * self.bottom,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_join_touches_both_spheres() {
        let ovus = Ovus::new(1.0, 0.5);
        let join = ovus.join.unwrap();
        // At the seams the arc's radius equals the sphere's, and so does its slope.
        let sphere = |y: f64, centre: f64, r: f64| (r * r - (y - centre).powi(2)).sqrt();
        let arc = |y: f64| ((join.radius.powi(2) - (y - join.h).powi(2)).sqrt()) - join.c;
        assert!((arc(join.y0) - sphere(join.y0, 0.0, 1.0)).abs() < 1e-12);
        assert!((arc(join.y1) - sphere(join.y1, 1.0, 0.5)).abs() < 1e-12);
        let e = 1e-6;
        let slope = |f: &dyn Fn(f64) -> f64, y: f64| (f(y + e) - f(y - e)) / (2.0 * e);
        assert!((slope(&arc, join.y0) - slope(&|y| sphere(y, 0.0, 1.0), join.y0)).abs() < 1e-5);
        // POV-Ray's ovus 1, 0.5 is 0.665 wide at height 1 (measured on its render).
        assert!((arc(1.0) - 0.665).abs() < 0.01, "{}", arc(1.0));
    }

    #[test]
    fn a_vertical_ray_crosses_twice_and_a_wide_top_is_one_sphere() {
        let ovus = Ovus::new(1.0, 0.5);
        let ray = Ray::new(DVec3::new(0.3, -5.0, 0.0), DVec3::Y);
        let mut roots = Roots::new();
        ovus.intersect(&ray, &mut roots);
        assert_eq!(roots.as_slice().len(), 2, "{:?}", roots.as_slice());
        let sphere = Ovus::new(0.5, 1.2);
        assert!(sphere.join.is_none());
        assert!(sphere.inside(DVec3::new(0.0, 1.5, 0.0)));
        assert!(!sphere.inside(DVec3::new(0.0, -0.8, 0.0)));
    }
}
