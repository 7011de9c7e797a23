//! `prism { [spline] [sweep] h1, h2, N, <x, z>... [open] }`: closed outlines in the x-z
//! plane swept along y between the two heights, inside where an odd number of outlines
//! surround a point. A linear sweep keeps the outline; a conic sweep scales it with the
//! height, from a point at the origin to the outline itself at y = 1.
//!
//! A ray meets a linearly swept segment c(s) where the segment crosses the ray's shadow
//! on the x-z plane: cross(c(s) - o, d) = 0, a polynomial of the segment's degree. A
//! conically swept one is met where the line from the origin through (x(s), 1, z(s))
//! lies in the plane through the origin and the ray: (o × d) · (x(s), 1, z(s)) = 0,
//! again of the segment's degree.

use super::Roots;
use super::plane_curve::{self, CurveSegment};
use crate::bounds::Aabb;
use crate::ray::Ray;
use analysis::scene::math_shapes::{PrismSweep, SplineKind};
use glam::{DVec2, DVec3};

const BASE: u32 = u32::MAX - 1;
const CAP: u32 = u32::MAX;

#[derive(Debug, Clone, PartialEq)]
pub struct Prism {
    segments: Vec<CurveSegment>,
    /// Each segment's box in the x-z plane, for culling.
    boxes: Vec<(DVec2, DVec2)>,
    sweep: PrismSweep,
    y0: f64,
    y1: f64,
    open: bool,
    sturm: bool,
    /// The outlines' box in the x-z plane at y = 1.
    outline: (DVec2, DVec2),
}

/// The segments of a prism's points: sub-outlines, each closed where its first point
/// comes back, as the manual describes for each spline kind. The last linear outline is
/// closed if the points leave it open.
pub fn prism_segments(kind: SplineKind, p: &[DVec2]) -> Vec<CurveSegment> {
    let n = p.len();
    let mut out = Vec::new();
    match kind {
        SplineKind::Linear => {
            let mut i = 0;
            while i < n {
                let first = p[i];
                let mut j = i + 1;
                while j < n && p[j] != first {
                    out.push(CurveSegment::linear(p[j - 1], p[j]));
                    j += 1;
                }
                if j < n {
                    out.push(CurveSegment::linear(p[j - 1], p[j]));
                    i = j + 1;
                } else {
                    if j - 1 > i {
                        out.push(CurveSegment::linear(p[j - 1], first));
                    }
                    i = n;
                }
            }
        }
        SplineKind::Quadratic => {
            let mut i = 0;
            while i + 2 < n {
                let first = p[i + 1];
                let mut j = i + 2;
                loop {
                    out.push(CurveSegment::quadratic(p[j - 2], p[j - 1], p[j]));
                    if p[j] == first || j + 1 >= n {
                        break;
                    }
                    j += 1;
                }
                i = j + 1;
            }
        }
        SplineKind::Cubic | SplineKind::BSpline => {
            let mut i = 0;
            while i + 3 < n {
                let first = p[i + 1];
                let mut j = i + 2;
                while j + 1 < n {
                    out.push(CurveSegment::cubic(p[j - 2], p[j - 1], p[j], p[j + 1]));
                    if p[j] == first {
                        break;
                    }
                    j += 1;
                }
                i = j + 2;
            }
        }
        SplineKind::Bezier => {
            for w in p.chunks_exact(4) {
                out.push(CurveSegment::bezier(w[0], w[1], w[2], w[3]));
            }
        }
    }
    out
}

impl Prism {
    pub fn new(
        kind: SplineKind,
        sweep: PrismSweep,
        heights: (f64, f64),
        points: &[DVec2],
        open: bool,
        sturm: bool,
    ) -> Option<Prism> {
        let segments = prism_segments(kind, points);
        if segments.is_empty() || heights.0 == heights.1 {
            return None;
        }
        let boxes: Vec<(DVec2, DVec2)> = segments.iter().map(CurveSegment::bounds).collect();
        let outline = boxes.iter().fold(
            (DVec2::INFINITY, DVec2::NEG_INFINITY),
            |(lo, hi), (a, b)| (lo.min(*a), hi.max(*b)),
        );
        Some(Prism {
            segments,
            boxes,
            sweep,
            y0: heights.0.min(heights.1),
            y1: heights.0.max(heights.1),
            open,
            sturm,
            outline,
        })
    }

    pub fn bounds(&self) -> Aabb {
        let (lo, hi) = self.outline;
        let (lo, hi) = match self.sweep {
            PrismSweep::Linear => (lo, hi),
            PrismSweep::Conic => {
                let corners = [lo * self.y0, hi * self.y0, lo * self.y1, hi * self.y1];
                (
                    corners.iter().fold(DVec2::INFINITY, |m, c| m.min(*c)),
                    corners.iter().fold(DVec2::NEG_INFINITY, |m, c| m.max(*c)),
                )
            }
        };
        Aabb::new(
            DVec3::new(lo.x, self.y0, lo.y),
            DVec3::new(hi.x, self.y1, hi.y),
        )
    }

    /// Where the outline's point for `p` lies: p's x and z, unscaled by a conic sweep.
    fn outline_point(&self, p: DVec3) -> Option<DVec2> {
        match self.sweep {
            PrismSweep::Linear => Some(DVec2::new(p.x, p.z)),
            PrismSweep::Conic => (p.y != 0.0).then(|| DVec2::new(p.x / p.y, p.z / p.y)),
        }
    }

    /// For a linear sweep, the ray's shadow on the x-z plane is followed across the whole
    /// outline box, not only where the ray is between the heights: its crossings with the
    /// outline are the walls' candidates, and their parity beyond a cap's point says
    /// whether the outline encloses that point, without an even-odd search of its own.
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let d = ray.direction;
        let Some((t_in, t_out)) = self.bounds().line_span(ray) else {
            return;
        };
        let mut params = Vec::new();
        let slack = 1e-9 * (self.y1 - self.y0);
        // A linear sweep is written from where the ray enters the box, with numbers of the
        // prism's size; a conic one needs the apex at the origin.
        let o = match self.sweep {
            PrismSweep::Linear => ray.at(t_in),
            PrismSweep::Conic => ray.origin,
        };
        let (o2, d2) = (DVec2::new(o.x, o.z), DVec2::new(d.x, d.z));
        let e = d2.length_squared();
        let (lo, hi) = self.outline;
        // Straight up or down, the walls are edge-on and the shadow is a point.
        let follows_shadow = self.sweep == PrismSweep::Linear && e > 0.0;
        // The stretch of the shadow searched, as t - t_in.
        let (u_lo, u_hi) = if follows_shadow {
            let column = Aabb::new(
                DVec3::new(lo.x, f64::NEG_INFINITY, lo.y),
                DVec3::new(hi.x, f64::INFINITY, hi.y),
            );
            let Some((s_in, s_out)) = column.line_span(ray) else {
                return;
            };
            (s_in - t_in, s_out - t_in)
        } else {
            (0.0, t_out - t_in)
        };
        // The shadow is widened by a hair: a straight wall on the box's face (a flat side of
        // the outline) must not be culled when rounding puts the ray's entry just inside,
        // all the more as a cap's parity needs every wall crossing.
        let hair = DVec2::splat(1e-9 * (hi - lo).max_element());
        let (a, b) = (o2 + d2 * u_lo, o2 + d2 * u_hi);
        let shadow = (a.min(b) - hair, a.max(b) + hair);
        // Where along the shadow (as t - t_in) it crosses the outline, each segment's end
        // left to the next segment's start.
        let mut shadow_crossings = Vec::new();
        let n = o.cross(d);
        for (index, segment) in self.segments.iter().enumerate() {
            let equation = match self.sweep {
                PrismSweep::Linear => {
                    let (lo, hi) = self.boxes[index];
                    // The segment's box must meet the ray's shadow on the x-z plane.
                    if !follows_shadow || lo.cmpgt(shadow.1).any() || hi.cmplt(shadow.0).any() {
                        continue;
                    }
                    combine(segment, d2.y, -d2.x, o2.y * d2.x - o2.x * d2.y)
                }
                PrismSweep::Conic => combine(segment, n.x, n.z, n.y),
            };
            params.clear();
            plane_curve::solve(
                &equation[..=segment.degree],
                0.0,
                1.0,
                self.sturm,
                &mut params,
            );
            for &s in &params {
                let c = segment.at(s);
                let t = match self.sweep {
                    PrismSweep::Linear => {
                        let u = (c - o2).dot(d2) / e;
                        if s < 1.0 {
                            shadow_crossings.push(u);
                        }
                        u + t_in
                    }
                    PrismSweep::Conic => {
                        let v = DVec3::new(c.x, 1.0, c.y);
                        let dv = d.cross(v);
                        -ray.origin.cross(v).dot(dv) / dv.length_squared()
                    }
                };
                let y = ray.origin.y + t * d.y;
                if t.is_finite() && y >= self.y0 - slack && y <= self.y1 + slack {
                    roots.push(t, index as u32);
                }
            }
        }
        if self.open || d.y == 0.0 {
            return;
        }
        let mut scratch = Vec::new();
        for (y, part) in [(self.y0, BASE), (self.y1, CAP)] {
            let t = (y - ray.origin.y) / d.y;
            let enclosed = if follows_shadow {
                let u = t - t_in;
                shadow_crossings.iter().filter(|&&c| c > u).count() % 2 == 1
            } else {
                let mut p = ray.at(t);
                p.y = y;
                self.outline_point(p)
                    .is_some_and(|q| plane_curve::encloses(&self.segments, q, &mut scratch))
            };
            if enclosed {
                roots.push(t, part);
            }
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        if !(p.y > self.y0 && p.y < self.y1) {
            return false;
        }
        let Some(q) = self.outline_point(p) else {
            return false;
        };
        let (lo, hi) = self.outline;
        q.cmpge(lo).all()
            && q.cmple(hi).all()
            && plane_curve::encloses(&self.segments, q, &mut Vec::new())
    }

    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match part {
            BASE => return -DVec3::Y,
            CAP => return DVec3::Y,
            _ => {}
        }
        let (Some(segment), Some(q)) = (self.segments.get(part as usize), self.outline_point(p))
        else {
            return DVec3::Y;
        };
        let s = segment.nearest(q);
        let t = segment.tangent(s);
        match self.sweep {
            PrismSweep::Linear => DVec3::new(t.y, 0.0, -t.x),
            PrismSweep::Conic => {
                let c = segment.at(s);
                DVec3::new(-t.y, t.y * c.x - t.x * c.y, t.x)
            }
        }
    }
}

/// a x(s) + b z(s) + c, lowest degree first.
fn combine(segment: &CurveSegment, a: f64, b: f64, c: f64) -> [f64; 4] {
    let mut out = [0.0; 4];
    for (k, v) in segment.a.iter().enumerate() {
        out[k] = a * v.x + b * v.y;
    }
    out[0] += c;
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pts(list: &[(f64, f64)]) -> Vec<DVec2> {
        list.iter().map(|&(x, z)| DVec2::new(x, z)).collect()
    }

    fn crossings(prism: &Prism, ray: &Ray) -> Vec<(f64, u32)> {
        let mut roots = Roots::new();
        prism.intersect(ray, &mut roots);
        let mut v: Vec<(f64, u32)> = roots.as_slice().iter().map(|r| (r.t, r.part)).collect();
        v.sort_by(|a, b| a.0.total_cmp(&b.0));
        v
    }

    /// Two nested rectangles: the frame of the manual's example.
    fn manual_frame() -> Vec<DVec2> {
        pts(&[
            (0.0, 0.0),
            (6.0, 0.0),
            (6.0, 8.0),
            (0.0, 8.0),
            (0.0, 0.0),
            (1.0, 1.0),
            (5.0, 1.0),
            (5.0, 7.0),
            (1.0, 7.0),
            (1.0, 1.0),
        ])
    }

    #[test]
    fn the_manual_frame_has_a_hole() {
        let p = manual_frame();
        let prism = Prism::new(
            SplineKind::Linear,
            PrismSweep::Linear,
            (0.0, 1.0),
            &p,
            false,
            false,
        )
        .unwrap();
        assert_eq!(prism.segments.len(), 8);
        assert!(prism.inside(DVec3::new(0.5, 0.5, 4.0)));
        assert!(!prism.inside(DVec3::new(3.0, 0.5, 4.0)));
        let ray = Ray::new(DVec3::new(-1.0, 0.5, 4.0), DVec3::X);
        let ts: Vec<f64> = crossings(&prism, &ray).iter().map(|c| c.0).collect();
        assert_eq!(ts, vec![1.0, 2.0, 6.0, 7.0]);
        // From above, through the rim: the two caps.
        let down = Ray::new(DVec3::new(0.5, 3.0, 4.0), -DVec3::Y);
        let hits = crossings(&prism, &down);
        assert_eq!(
            hits.iter().map(|c| c.1).collect::<Vec<_>>(),
            vec![CAP, BASE]
        );
        // Through the hole: nothing.
        assert!(crossings(&prism, &Ray::new(DVec3::new(3.0, 3.0, 4.0), -DVec3::Y)).is_empty());
    }

    #[test]
    fn the_last_linear_outline_closes_itself() {
        let p = pts(&[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]);
        let segments = prism_segments(SplineKind::Linear, &p);
        assert_eq!(segments.len(), 4);
        assert!((segments[3].at(1.0) - p[0]).length() < 1e-15);
    }

    #[test]
    fn manual_spline_outlines_split_into_their_segments() {
        let quadratic = pts(&[
            (1.0, -1.0),
            (0.0, 0.0),
            (6.0, 0.0),
            (6.0, 8.0),
            (0.0, 8.0),
            (0.0, 0.0),
            (2.0, 0.0),
            (1.0, 1.0),
            (5.0, 1.0),
            (5.0, 7.0),
            (1.0, 7.0),
            (1.0, 1.0),
        ]);
        assert_eq!(prism_segments(SplineKind::Quadratic, &quadratic).len(), 8);
        let cubic = pts(&[
            (1.0, -1.0),
            (0.0, 0.0),
            (6.0, 0.0),
            (6.0, 8.0),
            (0.0, 8.0),
            (0.0, 0.0),
            (-1.0, 1.0),
            (2.0, 0.0),
            (1.0, 1.0),
            (5.0, 1.0),
            (5.0, 7.0),
            (1.0, 7.0),
            (1.0, 1.0),
            (0.0, 2.0),
        ]);
        let segments = prism_segments(SplineKind::Cubic, &cubic);
        assert_eq!(segments.len(), 8);
        assert!((segments[3].at(1.0) - DVec2::ZERO).length() < 1e-15);
        assert!((segments[4].at(0.0) - DVec2::new(1.0, 1.0)).length() < 1e-15);
    }

    #[test]
    fn rays_through_a_flat_side_on_the_box_meet_it() {
        // The triangle's flat side lies on its box's face at z = -0.5: every ray entering
        // through it, wherever rounding puts the entry point, crosses the prism twice.
        let p = pts(&[(-0.6, -0.5), (0.6, -0.5), (0.0, 0.55), (-0.6, -0.5)]);
        let prism = Prism::new(
            SplineKind::Linear,
            PrismSweep::Linear,
            (-1.0, 1.0),
            &p,
            false,
            false,
        )
        .unwrap();
        let d = DVec3::new(0.8944271909999159, 0.0, 0.4472135954999579);
        for i in 0..1000 {
            let x = -0.55 + 1.1 * f64::from(i) / 1000.0;
            let entry = DVec3::new(x, 0.3, -0.5);
            let ray = Ray::new(entry - d * (7.7 + f64::from(i) / 1700.0), d);
            let hits = crossings(&prism, &ray);
            assert_eq!(hits.len(), 2, "x = {x}: {hits:?}");
            assert_eq!(hits[0].1, 0, "x = {x}: {hits:?}");
        }
    }

    /// A linear prism decides its caps by the parity of its walls along the ray's shadow:
    /// for rays from every side, a cap is crossed exactly where the outline encloses the
    /// point, as the even-odd test from that point says. The outlines are the manual's
    /// frame, whose outer sides lie on its box's faces, and a cubic blob with a hole.
    #[test]
    fn caps_follow_the_even_odd_rule() {
        let frame = manual_frame();
        let blob = pts(&[
            (-1.0, 1.0),
            (0.0, 0.0),
            (4.0, 0.5),
            (4.5, 4.0),
            (0.5, 4.5),
            (0.0, 0.0),
            (4.0, 0.5),
            (1.0, 2.0),
            (1.5, 1.5),
            (3.0, 1.8),
            (2.8, 3.0),
            (1.5, 3.2),
            (1.5, 1.5),
            (3.0, 1.8),
        ]);
        let mut scratch = Vec::new();
        for (kind, points) in [(SplineKind::Linear, frame), (SplineKind::Cubic, blob)] {
            let prism =
                Prism::new(kind, PrismSweep::Linear, (0.0, 1.0), &points, false, false).unwrap();
            let mut caps = 0;
            for k in 0..400 {
                let a = k as f64 * 0.731;
                let origin = DVec3::new(
                    3.0 + 9.0 * a.cos(),
                    4.0 * (1.3 * a).sin(),
                    4.0 + 9.0 * a.sin(),
                );
                let target = DVec3::new(
                    3.0 + 3.5 * (2.1 * a).sin(),
                    0.5,
                    4.0 + 4.5 * (1.7 * a).cos(),
                );
                let ray = Ray::new(origin, target - origin);
                let hits = crossings(&prism, &ray);
                for (y, part) in [(0.0, BASE), (1.0, CAP)] {
                    let t = (y - origin.y) / ray.direction.y;
                    let p = ray.at(t);
                    let expected =
                        plane_curve::encloses(&prism.segments, DVec2::new(p.x, p.z), &mut scratch);
                    let found = hits.iter().any(|h| h.1 == part);
                    assert_eq!(found, expected, "{kind:?} ray {k} at y = {y}");
                    caps += usize::from(found);
                }
            }
            assert!(caps > 50, "{kind:?}: {caps}");
        }
    }

    #[test]
    fn a_conic_square_is_a_pyramid() {
        let p = pts(&[
            (-1.0, -1.0),
            (1.0, -1.0),
            (1.0, 1.0),
            (-1.0, 1.0),
            (-1.0, -1.0),
        ]);
        let prism = Prism::new(
            SplineKind::Linear,
            PrismSweep::Conic,
            (0.0, 1.0),
            &p,
            false,
            false,
        )
        .unwrap();
        // At height 0.5 the square is half as wide.
        let ray = Ray::new(DVec3::new(-2.0, 0.5, 0.0), DVec3::X);
        let ts: Vec<f64> = crossings(&prism, &ray).iter().map(|c| c.0).collect();
        assert_eq!(ts.len(), 2, "{ts:?}");
        assert!((ts[0] - 1.5).abs() < 1e-12 && (ts[1] - 2.5).abs() < 1e-12);
        let n = prism
            .normal(ray.at(ts[1]), crossings(&prism, &ray)[1].1)
            .normalize();
        let expected = DVec3::new(1.0, -1.0, 0.0).normalize();
        assert!(
            (n - expected).length() < 1e-9 || (n + expected).length() < 1e-9,
            "{n}"
        );
        assert!(prism.inside(DVec3::new(0.2, 0.5, 0.2)));
        assert!(!prism.inside(DVec3::new(0.7, 0.5, 0.0)));
    }
}
