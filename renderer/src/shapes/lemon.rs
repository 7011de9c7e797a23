//! `lemon { <base>, r1, <cap>, r2, inner_radius [open] }` (POV-Ray 3.8): the arc of a
//! circle of radius inner_radius from the base circle to the cap circle, turned about the
//! axis, with the arc's centre on the far side of the axis, closed by two discs. In its
//! canonical frame the axis is y from 0 to the lemon's length. The curved surface is the
//! inner part of a spindle torus, which the ovus shares.

use super::{Roots, solve_quadratic_half};
use crate::ray::Ray;
use glam::DVec3;

/// The surface (ρ + c)² + (y - h)² = R² about the y axis, ρ = √(x² + z²), between the
/// heights `y0` and `y1`: an arc of radius R whose centre lies a distance c on the other
/// side of the axis, turned about it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Spindle {
    pub c: f64,
    pub h: f64,
    pub radius: f64,
    pub y0: f64,
    pub y1: f64,
}

impl Spindle {
    /// The surface's radius at height y.
    fn radius_at(&self, y: f64) -> f64 {
        let dy = y - self.h;
        (self.radius * self.radius - dy * dy).max(0.0).sqrt() - self.c
    }

    /// The widest the surface gets between its heights.
    pub fn max_radius(&self) -> f64 {
        let peak = self.h.clamp(self.y0, self.y1);
        self.radius_at(peak)
    }

    pub fn inside(&self, p: DVec3) -> bool {
        let rho = (p.x * p.x + p.z * p.z).sqrt();
        let dy = p.y - self.h;
        (rho + self.c).powi(2) + dy * dy < self.radius * self.radius
    }

    pub fn normal(&self, p: DVec3) -> DVec3 {
        let rho = (p.x * p.x + p.z * p.z).sqrt();
        let radial = if rho > 0.0 {
            DVec3::new(p.x / rho, 0.0, p.z / rho)
        } else {
            DVec3::ZERO
        };
        radial * (rho + self.c) + DVec3::Y * (p.y - self.h)
    }

    /// The crossings between the heights: the spindle torus's quartic, whose roots on the
    /// outer branch (ρ - c)² + ... are dropped. It is solved around where the ray enters
    /// the lemon's bounding cylinder, so that the coefficients stay of the shape's size.
    pub fn intersect(&self, ray: &Ray, part: u32, roots: &mut Roots) {
        let (o, d) = (ray.origin, ray.direction);
        let top = self.max_radius();
        // The slab between the heights, then the bounding cylinder.
        let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
        if d.y != 0.0 {
            let (a, b) = ((self.y0 - o.y) / d.y, (self.y1 - o.y) / d.y);
            t0 = a.min(b);
            t1 = a.max(b);
        } else if o.y < self.y0 || o.y > self.y1 {
            return;
        }
        let e = d.x * d.x + d.z * d.z;
        if e == 0.0 {
            // Along the axis: the surface is met where its radius reaches the axis.
            if o.x * o.x + o.z * o.z > 0.0 || self.c >= self.radius {
                return;
            }
            let reach = (self.radius * self.radius - self.c * self.c).sqrt();
            for y in [self.h - reach, self.h + reach] {
                if y >= self.y0 && y <= self.y1 {
                    roots.push((y - o.y) / d.y, part);
                }
            }
            return;
        }
        let f = o.x * d.x + o.z * d.z;
        let g = o.x * o.x + o.z * o.z - top * top;
        let Some((c0, c1)) = solve_quadratic_half(e, f, g) else {
            return;
        };
        let (t0, t1) = (t0.max(c0), t1.min(c1));
        if t0 > t1 {
            return;
        }
        let base = o + d * t0 - DVec3::Y * self.h;
        let coeffs = super::torus::quartic_along(base, d, self.c, self.radius);
        let k2 = self.radius * self.radius;
        // A little beyond the span, so that hits on the rim are not lost to rounding.
        let slack = 1e-9 * (t1 - t0);
        let mut found = Vec::new();
        super::plane_curve::solve(&coeffs, -slack, t1 - t0 + slack, false, &mut found);
        for &s in &found {
            let t = t0 + s;
            let p = ray.at(t);
            let rho = (p.x * p.x + p.z * p.z).sqrt();
            let dy = p.y - self.h;
            let inner = ((rho + self.c).powi(2) + dy * dy - k2).abs();
            let outer = ((rho - self.c).powi(2) + dy * dy - k2).abs();
            if inner <= outer && p.y >= self.y0 - slack && p.y <= self.y1 + slack {
                roots.push(t, part);
            }
        }
    }
}

/// Parts of a lemon's surface.
const SIDE: u32 = 0;
const BASE: u32 = 1;
const CAP: u32 = 2;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lemon {
    spindle: Spindle,
    base_radius: f64,
    cap_radius: f64,
    open: bool,
}

impl Lemon {
    /// The lemon of `length` along y whose arc of radius `inner` runs from radius
    /// `base_radius` at y = 0 to `cap_radius` at the top; an error when no such arc
    /// exists.
    pub fn new(
        length: f64,
        base_radius: f64,
        cap_radius: f64,
        inner: f64,
        open: bool,
    ) -> Result<Lemon, String> {
        if inner.is_nan() || inner <= 0.0 {
            return Err(format!(
                "lemon: the inner radius must be positive, not {inner}"
            ));
        }
        let (l, r1, r2) = (length, base_radius.abs(), cap_radius.abs());
        // The centre (-c, h) is at distance inner from (r1, 0) and (r2, l); the difference
        // of the two conditions gives h in terms of c, h = m + k c, and the first becomes
        // a quadratic in c. The larger c puts the centre farthest across the axis: the
        // lemon rather than the apple.
        let m = (l * l - (r1 * r1 - r2 * r2)) / (2.0 * l);
        let k = -(r1 - r2) / l;
        // (r1 + c)² + (m + k c)² = inner².
        let a = 1.0 + k * k;
        let b = r1 + m * k;
        let c0 = r1 * r1 + m * m - inner * inner;
        let (_, c) = solve_quadratic_half(a, b, c0).ok_or_else(|| {
            format!("lemon: the inner radius {inner} is too small to reach both end circles")
        })?;
        let h = m + k * c;
        Ok(Lemon {
            spindle: Spindle {
                c,
                h,
                radius: inner,
                y0: 0.0,
                y1: l,
            },
            base_radius: r1,
            cap_radius: r2,
            open,
        })
    }

    pub fn bounds(&self) -> crate::bounds::Aabb {
        let r = self.spindle.max_radius();
        crate::bounds::Aabb::new(DVec3::new(-r, 0.0, -r), DVec3::new(r, self.spindle.y1, r))
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        self.spindle.intersect(ray, SIDE, roots);
        if self.open || ray.direction.y == 0.0 {
            return;
        }
        for (y, r, part) in [
            (0.0, self.base_radius, BASE),
            (self.spindle.y1, self.cap_radius, CAP),
        ] {
            let t = (y - ray.origin.y) / ray.direction.y;
            let p = ray.at(t);
            // A lemon pointed at an end has no disc there.
            if r > 0.0 && p.x * p.x + p.z * p.z <= r * r {
                roots.push(t, part);
            }
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        p.y > 0.0 && p.y < self.spindle.y1 && self.spindle.inside(p)
    }

    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match part {
            BASE => -DVec3::Y,
            CAP => DVec3::Y,
            _ => self.spindle.normal(p),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pointed_lemon_meets_the_axis_at_its_ends() {
        // Length 2, radius 1.25: the arc's centre is 0.75 across the axis.
        let lemon = Lemon::new(2.0, 0.0, 0.0, 1.25, false).unwrap();
        assert!((lemon.spindle.c - 0.75).abs() < 1e-12);
        assert!((lemon.spindle.max_radius() - 0.5).abs() < 1e-12);
        let ray = Ray::new(DVec3::new(-3.0, 1.0, 0.0), DVec3::X);
        let mut roots = Roots::new();
        lemon.intersect(&ray, &mut roots);
        let mut ts: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
        ts.sort_by(f64::total_cmp);
        assert_eq!(ts.len(), 2);
        assert!(
            (ts[0] - 2.5).abs() < 1e-9 && (ts[1] - 3.5).abs() < 1e-9,
            "{ts:?}"
        );
        // Along the axis the ray enters at one tip and leaves at the other.
        let axial = Ray::new(DVec3::new(0.0, -1.0, 0.0), DVec3::Y);
        let mut roots = Roots::new();
        lemon.intersect(&axial, &mut roots);
        assert_eq!(roots.as_slice().len(), 2);
        assert!(lemon.inside(DVec3::new(0.2, 1.0, 0.0)));
        assert!(!lemon.inside(DVec3::new(0.6, 1.0, 0.0)));
    }

    #[test]
    fn end_circles_lie_on_the_arc_and_caps_close_it() {
        let lemon = Lemon::new(3.0, 0.5, 0.25, 2.0, false).unwrap();
        let s = lemon.spindle;
        for (y, r) in [(0.0, 0.5), (3.0, 0.25)] {
            assert!((s.radius_at(y) - r).abs() < 1e-12);
        }
        let ray = Ray::new(DVec3::new(0.1, -1.0, 0.0), DVec3::Y);
        let mut roots = Roots::new();
        lemon.intersect(&ray, &mut roots);
        let parts: Vec<u32> = roots.as_slice().iter().map(|r| r.part).collect();
        assert_eq!(parts, vec![BASE, CAP]);
        assert!(Lemon::new(3.0, 0.5, 0.25, 1.0, false).is_err());
    }
}
