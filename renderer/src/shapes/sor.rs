//! `sor { N, <r, h>... [open] }`: a surface of revolution about the y axis whose squared
//! radius is, segment by segment, a cubic in the height, r² = P(h), through the squared
//! radii of the points (the manual's formula), with the slope of r² at each point
//! 2 r dr/dh, dr/dh taken from the point's neighbours (measured on POV-Ray's renders).
//! The first and last points only shape the slopes. Along a ray, height and
//! squared distance from the axis are polynomials in t, so each segment's crossings are
//! the roots of a cubic in t, written around the middle of the ray's stretch inside the
//! shape so that its coefficients stay of the shape's size.

use super::Roots;
use super::plane_curve;
use crate::bounds::Aabb;
use crate::ray::Ray;
use glam::{DVec2, DVec3};

const BASE: u32 = u32::MAX - 1;
const CAP: u32 = u32::MAX;

/// One segment: P(h) = c[0] + c[1] x + c[2] x² + c[3] x³ with x = h - h0, for h in
/// [h0, h1].
#[derive(Debug, Clone, Copy, PartialEq)]
struct Segment {
    c: [f64; 4],
    h0: f64,
    h1: f64,
    /// The smallest and the largest P between the ends.
    low: f64,
    high: f64,
}

impl Segment {
    fn value(&self, h: f64) -> f64 {
        let x = h - self.h0;
        ((self.c[3] * x + self.c[2]) * x + self.c[1]) * x + self.c[0]
    }

    fn slope(&self, h: f64) -> f64 {
        let x = h - self.h0;
        (3.0 * self.c[3] * x + 2.0 * self.c[2]) * x + self.c[1]
    }

    /// The smallest and the largest P between the ends.
    fn extremes(&self) -> (f64, f64) {
        let (a, b) = (self.value(self.h0), self.value(self.h1));
        let (mut low, mut high) = (a.min(b), a.max(b));
        let mut turning = Vec::new();
        let derivative = [self.c[1], 2.0 * self.c[2], 3.0 * self.c[3]];
        crate::polynomial::roots_in(&derivative, 0.0, self.h1 - self.h0, &mut turning);
        for x in turning {
            let v = self.value(self.h0 + x);
            low = low.min(v);
            high = high.max(v);
        }
        (low, high)
    }
}

#[derive(Debug, Clone, PartialEq)]
pub struct Sor {
    segments: Vec<Segment>,
    radius: f64,
    open: bool,
    sturm: bool,
}

impl Sor {
    /// The surface through `points` (at least four, heights increasing: the evaluator
    /// checks).
    pub fn new(points: &[DVec2], open: bool, sturm: bool) -> Option<Sor> {
        let r = |i: usize| points[i].x;
        let h = |i: usize| points[i].y;
        // The slope of r² at a point: 2 r dr/dh, with dr/dh from its two neighbours.
        let slope = |i: usize| 2.0 * r(i) * (r(i + 1) - r(i - 1)) / (h(i + 1) - h(i - 1));
        let mut segments: Vec<Segment> = (1..points.len().saturating_sub(2))
            .map(|j| {
                let (v0, v1) = (r(j) * r(j), r(j + 1) * r(j + 1));
                let (m0, m1) = (slope(j), slope(j + 1));
                let l = h(j + 1) - h(j);
                let secant = (v1 - v0) / l;
                Segment {
                    c: [
                        v0,
                        m0,
                        (3.0 * secant - 2.0 * m0 - m1) / l,
                        (m0 + m1 - 2.0 * secant) / (l * l),
                    ],
                    h0: h(j),
                    h1: h(j + 1),
                    low: 0.0,
                    high: 0.0,
                }
            })
            .collect();
        if segments.is_empty() {
            return None;
        }
        for segment in &mut segments {
            (segment.low, segment.high) = segment.extremes();
        }
        let radius = segments.iter().map(|s| s.high).fold(0.0, f64::max).sqrt();
        Some(Sor {
            segments,
            radius,
            open,
            sturm,
        })
    }

    fn heights(&self) -> (f64, f64) {
        (
            self.segments[0].h0,
            self.segments[self.segments.len() - 1].h1,
        )
    }

    pub fn bounds(&self) -> Aabb {
        let (lo, hi) = self.heights();
        Aabb::new(
            DVec3::new(-self.radius, lo, -self.radius),
            DVec3::new(self.radius, hi, self.radius),
        )
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let (o, d) = (ray.origin, ray.direction);
        let Some((t_in, t_out)) = self.bounds().line_span(ray) else {
            return;
        };
        let e = d.x * d.x + d.z * d.z;
        let mut found = Vec::new();
        let last = self.segments.len() - 1;
        for (index, segment) in self.segments.iter().enumerate() {
            // The stretch of the ray between the segment's heights.
            let (mut t0, mut t1) = (t_in, t_out);
            if d.y != 0.0 {
                let (a, b) = ((segment.h0 - o.y) / d.y, (segment.h1 - o.y) / d.y);
                t0 = t0.max(a.min(b));
                t1 = t1.min(a.max(b));
            } else if o.y < segment.h0 || o.y > segment.h1 {
                continue;
            }
            if t0 > t1 {
                continue;
            }
            let tc = 0.5 * (t0 + t1);
            let pc = o + d * tc;
            let q = DVec2::new(pc.x, pc.z);
            let dq = DVec2::new(d.x, d.z);
            let slack = 1e-9 * (t1 - t0);
            let (s0, s1) = (t0 - tc - slack, t1 - tc + slack);
            // The ray's squared distance from the axis is a convex quadratic along it: no
            // crossing where it stays beyond the segment's largest P or within its
            // smallest, which rules out most segments of most rays at the cost of the
            // cubic's coefficients.
            let distance2 = |s: f64| (q + dq * s).length_squared();
            let closest = if e > 0.0 {
                distance2((-q.dot(dq) / e).clamp(s0, s1))
            } else {
                q.length_squared()
            };
            let farthest = distance2(s0).max(distance2(s1));
            let margin = 1e-8 * (segment.high.abs() + segment.low.abs() + closest);
            if closest > segment.high + margin || farthest < segment.low - margin {
                continue;
            }
            let x = pc.y - segment.h0;
            let c = &segment.c;
            // P(x + τ dy) - |q + τ dq|², by Taylor's expansion of P about x.
            let p0 = ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
            let p1 = (3.0 * c[3] * x + 2.0 * c[2]) * x + c[1];
            let p2 = 3.0 * c[3] * x + c[2];
            let cubic = [
                p0 - q.length_squared(),
                p1 * d.y - 2.0 * q.dot(dq),
                p2 * d.y * d.y - e,
                c[3] * d.y * d.y * d.y,
            ];
            found.clear();
            plane_curve::solve(&cubic, s0, s1, self.sturm, &mut found);
            for &tau in &found {
                // Each height belongs to one segment (the last keeps its top), so that a
                // crossing at a joint is counted once.
                let y = o.y + (tc + tau) * d.y;
                let rim = 1e-9 * (segment.h1 - segment.h0);
                let top = if index == last {
                    y <= segment.h1 + rim
                } else {
                    y < segment.h1
                };
                let bottom = y >= segment.h0 - if index == 0 { rim } else { 0.0 };
                if top && bottom {
                    roots.push(tc + tau, index as u32);
                }
            }
        }
        if self.open || d.y == 0.0 {
            return;
        }
        let (lo, hi) = self.heights();
        for (h, part) in [(lo, BASE), (hi, CAP)] {
            let t = (h - o.y) / d.y;
            let p = ray.at(t);
            let segment = if part == BASE {
                &self.segments[0]
            } else {
                &self.segments[self.segments.len() - 1]
            };
            if p.x * p.x + p.z * p.z <= segment.value(h) {
                roots.push(t, part);
            }
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        let (lo, hi) = self.heights();
        if !(p.y > lo && p.y < hi) {
            return false;
        }
        let i = self.segments.partition_point(|s| s.h1 < p.y);
        self.segments
            .get(i)
            .is_some_and(|s| p.x * p.x + p.z * p.z < s.value(p.y))
    }

    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match part {
            BASE => -DVec3::Y,
            CAP => DVec3::Y,
            _ => {
                let slope = self
                    .segments
                    .get(part as usize)
                    .map_or(0.0, |s| s.slope(p.y));
                DVec3::new(p.x, -0.5 * slope, p.z)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points on the cone r = 1 + h/2, whose r² the cubic reproduces exactly.
    fn cone() -> Sor {
        let p: Vec<DVec2> = (0..6)
            .map(|i| {
                let h = i as f64 * 0.5;
                DVec2::new(1.0 + 0.5 * h, h)
            })
            .collect();
        Sor::new(&p, false, false).unwrap()
    }

    #[test]
    fn the_spline_reproduces_a_cone() {
        let sor = cone();
        for h in [0.5, 0.9, 1.7, 2.0] {
            let i = sor.segments.partition_point(|s| s.h1 < h);
            assert!((sor.segments[i].value(h) - (1.0 + 0.5 * h).powi(2)).abs() < 1e-12);
        }
        let ray = Ray::new(DVec3::new(-5.0, 1.0, 0.0), DVec3::X);
        let mut roots = Roots::new();
        sor.intersect(&ray, &mut roots);
        let mut ts: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
        ts.sort_by(f64::total_cmp);
        assert_eq!(ts.len(), 2, "{ts:?}");
        assert!(
            (ts[0] - 3.5).abs() < 1e-9 && (ts[1] - 6.5).abs() < 1e-9,
            "{ts:?}"
        );
    }

    #[test]
    fn caps_close_it_and_open_leaves_them_off() {
        let sor = cone();
        let ray = Ray::new(DVec3::new(0.2, -5.0, 0.1), DVec3::Y);
        let mut roots = Roots::new();
        sor.intersect(&ray, &mut roots);
        let parts: Vec<u32> = roots.as_slice().iter().map(|r| r.part).collect();
        assert_eq!(parts, vec![BASE, CAP]);
        assert!(sor.inside(DVec3::new(1.4, 1.0, 0.0)));
        assert!(!sor.inside(DVec3::new(1.6, 1.0, 0.0)));
        let open = Sor::new(
            &[(1.0, 0.0), (1.0, 0.5), (1.0, 1.0), (1.0, 1.5)].map(|(r, h)| DVec2::new(r, h)),
            true,
            false,
        )
        .unwrap();
        let mut roots = Roots::new();
        open.intersect(&ray, &mut roots);
        assert!(roots.as_slice().is_empty());
    }
}
