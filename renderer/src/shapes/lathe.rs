//! `lathe { spline N, <r, y>... }`: a plane curve in (radius, height) turned about the y
//! axis. Along a segment the radius r(s) and height y(s) are polynomials of degree k; a
//! ray meets the segment where its height is y(s) and its distance from the axis r(s).
//! Multiplying through by the ray's vertical speed keeps the equation free of division:
//!
//!   |o_xz dy + (y(s) - o_y) d_xz|² = r(s)² dy²,
//!
//! a polynomial of degree 2k in s. Each root gives t = (y(s) - o_y) / dy. For a ray
//! nearly level that quotient loses everything, so there the heights where y(s) = o_y
//! come first and the circles of radius r(s) give t; either way Newton's method on the
//! pair of equations in (s, t) then polishes each crossing to full precision.

use super::Roots;
use super::plane_curve::{self, CurveSegment};
use crate::bounds::Aabb;
use crate::ray::Ray;
use analysis::scene::math_shapes::SplineKind;
use glam::{DVec2, DVec3};

/// Below this share of its length a ray's vertical speed counts as level.
const LEVEL: f64 = 1e-4;

/// A segment with the ranges of |r| and y it covers, for culling.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Piece {
    curve: CurveSegment,
    r_lo: f64,
    r_hi: f64,
    y_lo: f64,
    y_hi: f64,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Lathe {
    pieces: Vec<Piece>,
    sturm: bool,
    radius: f64,
    y_lo: f64,
    y_hi: f64,
}

/// The segments of a lathe's spline through `points`.
pub fn lathe_segments(kind: SplineKind, points: &[DVec2]) -> Vec<CurveSegment> {
    let p = points;
    match kind {
        SplineKind::Linear => p
            .windows(2)
            .map(|w| CurveSegment::linear(w[0], w[1]))
            .collect(),
        SplineKind::Quadratic => p
            .windows(3)
            .map(|w| CurveSegment::quadratic(w[0], w[1], w[2]))
            .collect(),
        SplineKind::Cubic | SplineKind::BSpline => p
            .windows(4)
            .map(|w| CurveSegment::cubic(w[0], w[1], w[2], w[3]))
            .collect(),
        SplineKind::Bezier => p
            .chunks_exact(4)
            .map(|w| CurveSegment::bezier(w[0], w[1], w[2], w[3]))
            .collect(),
    }
}

impl Lathe {
    pub fn new(kind: SplineKind, points: &[DVec2], sturm: bool) -> Option<Lathe> {
        let pieces: Vec<Piece> = lathe_segments(kind, points)
            .into_iter()
            .map(|curve| {
                let (lo, hi) = curve.bounds();
                let r_hi = lo.x.abs().max(hi.x.abs());
                let r_lo = if lo.x <= 0.0 && hi.x >= 0.0 {
                    0.0
                } else {
                    lo.x.abs().min(hi.x.abs())
                };
                Piece {
                    curve,
                    r_lo,
                    r_hi,
                    y_lo: lo.y,
                    y_hi: hi.y,
                }
            })
            .collect();
        if pieces.is_empty() {
            return None;
        }
        Some(Lathe {
            radius: pieces.iter().map(|p| p.r_hi).fold(0.0, f64::max),
            y_lo: pieces.iter().map(|p| p.y_lo).fold(f64::INFINITY, f64::min),
            y_hi: pieces
                .iter()
                .map(|p| p.y_hi)
                .fold(f64::NEG_INFINITY, f64::max),
            pieces,
            sturm,
        })
    }

    pub fn bounds(&self) -> Aabb {
        Aabb::new(
            DVec3::new(-self.radius, self.y_lo, -self.radius),
            DVec3::new(self.radius, self.y_hi, self.radius),
        )
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let (o, d) = (ray.origin, ray.direction);
        // Start where the ray enters the bounding cylinder and slab, so that the
        // equations are written with numbers of the lathe's own size.
        let Some((t_in, t_out)) = self.bounds().line_span(ray) else {
            return;
        };
        let start = o + d * t_in;
        let local = Ray::new(start, d);
        let level = d.y.abs() < LEVEL * d.length();
        let (e, f, g) = (
            d.x * d.x + d.z * d.z,
            start.x * d.x + start.z * d.z,
            start.x * start.x + start.z * start.z,
        );
        let mut found = Vec::new();
        for (index, piece) in self.pieces.iter().enumerate() {
            if !piece.crossed(&local, e, f, g, t_out - t_in) {
                continue;
            }
            found.clear();
            let c = &piece.curve;
            if level {
                let mut heights = Vec::new();
                plane_curve::solve(
                    &height_minus(c, start.y),
                    0.0,
                    1.0,
                    self.sturm,
                    &mut heights,
                );
                for s in heights {
                    let r = c.at(s).x;
                    if let Some((a, b)) = super::solve_quadratic_half(e, f, g - r * r) {
                        found.push((s, a));
                        if b != a {
                            found.push((s, b));
                        }
                    }
                }
            } else {
                let mut params = Vec::new();
                plane_curve::solve(&self.equation(c, &local), 0.0, 1.0, self.sturm, &mut params);
                for s in params {
                    found.push((s, (c.at(s).y - start.y) / d.y));
                }
            }
            for &(s, t) in &found {
                let (s, t) = polish(c, &local, s, t);
                if (-1e-9..=1.0 + 1e-9).contains(&s) {
                    roots.push(t_in + t, index as u32);
                }
            }
        }
    }

    /// The polynomial in s whose roots are the ray's crossings with a segment.
    fn equation(&self, c: &CurveSegment, ray: &Ray) -> [f64; 7] {
        let (o, d) = (ray.origin, ray.direction);
        let k = c.degree;
        let u = height_minus(c, o.y);
        let r = c.coordinate(0);
        let mut uu = [0.0; 7];
        let mut rr = [0.0; 7];
        plane_curve::multiply(&u[..=k], &u[..=k], &mut uu);
        plane_curve::multiply(&r[..=k], &r[..=k], &mut rr);
        let e = d.x * d.x + d.z * d.z;
        let f = (o.x * d.x + o.z * d.z) * d.y;
        let g = (o.x * o.x + o.z * o.z) * d.y * d.y;
        let dy2 = d.y * d.y;
        let mut out = [0.0; 7];
        for i in 0..7 {
            out[i] = e * uu[i] - dy2 * rr[i] + if i <= 3 { 2.0 * f * u[i] } else { 0.0 };
        }
        out[0] += g;
        out
    }

    pub fn inside(&self, p: DVec3) -> bool {
        let q = DVec2::new((p.x * p.x + p.z * p.z).sqrt(), p.y);
        if q.x > self.radius || q.y < self.y_lo || q.y > self.y_hi {
            return false;
        }
        let segments: Vec<CurveSegment> = self.pieces.iter().map(|p| p.curve).collect();
        plane_curve::encloses(&segments, q, &mut Vec::new())
    }

    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        let Some(piece) = self.pieces.get(part as usize) else {
            return DVec3::Y;
        };
        revolved_normal(&piece.curve, p)
    }
}

/// The normal at `p` of the surface made by turning `curve` (in radius and height) about
/// the y axis.
pub fn revolved_normal(curve: &CurveSegment, p: DVec3) -> DVec3 {
    let rho = (p.x * p.x + p.z * p.z).sqrt();
    let s = curve.nearest(DVec2::new(rho, p.y));
    let tangent = curve.tangent(s);
    let radial = if rho > 0.0 {
        DVec3::new(p.x / rho, 0.0, p.z / rho)
    } else {
        DVec3::X
    };
    radial * tangent.y - DVec3::Y * tangent.x
}

/// y(s) - height, lowest degree first.
fn height_minus(c: &CurveSegment, height: f64) -> [f64; 4] {
    let mut u = c.coordinate(1);
    u[0] -= height;
    u
}

impl Piece {
    /// Whether the ray can reach this segment's ring of heights and radii at all.
    fn crossed(&self, ray: &Ray, e: f64, f: f64, g: f64, span: f64) -> bool {
        let (o, d) = (ray.origin, ray.direction);
        let (mut t0, mut t1) = (0.0, span);
        if d.y != 0.0 {
            let (a, b) = ((self.y_lo - o.y) / d.y, (self.y_hi - o.y) / d.y);
            t0 = f64::max(t0, a.min(b));
            t1 = f64::min(t1, a.max(b));
        } else if o.y < self.y_lo || o.y > self.y_hi {
            return false;
        }
        // A little slack, since the culling must never lose a crossing to rounding.
        let slack = 1e-9 * (span + 1.0);
        if t0 > t1 + slack {
            return false;
        }
        let rho2 = |t: f64| (e * t + 2.0 * f) * t + g;
        let apex = if e > 0.0 { -f / e } else { t0 };
        let nearest = rho2(apex.max(t0).min(t1.max(t0)));
        let farthest = rho2(t0).max(rho2(t1));
        let (lo, hi) = (self.r_lo * (1.0 - 1e-9), self.r_hi * (1.0 + 1e-9) + slack);
        nearest <= hi * hi && farthest >= lo * lo
    }
}

/// Newton's method on y(s) = o_y + t d_y and r(s)² = |o_xz + t d_xz|² from a first
/// estimate; the estimate stays when the steps do not settle (a grazing ray).
fn polish(c: &CurveSegment, ray: &Ray, s0: f64, t0: f64) -> (f64, f64) {
    let (o, d) = (ray.origin, ray.direction);
    let (mut s, mut t) = (s0, t0);
    for _ in 0..6 {
        let p = c.at(s);
        let tan = c.tangent(s);
        let q = DVec2::new(o.x + t * d.x, o.z + t * d.z);
        let dq = DVec2::new(d.x, d.z);
        let f1 = p.y - (o.y + t * d.y);
        let f2 = p.x * p.x - q.length_squared();
        let (j00, j01, j10, j11) = (tan.y, -d.y, 2.0 * p.x * tan.x, -2.0 * q.dot(dq));
        let det = j00 * j11 - j01 * j10;
        if det == 0.0 || !det.is_finite() {
            break;
        }
        let ds = (f1 * j11 - j01 * f2) / det;
        let dt = (j00 * f2 - j10 * f1) / det;
        if !(ds.is_finite() && dt.is_finite()) || ds.abs() > 0.1 {
            return (s0, t0);
        }
        s -= ds;
        t -= dt;
        if dt.abs() <= 1e-15 * t.abs().max(1e-300) && ds.abs() <= 1e-15 {
            break;
        }
    }
    let p = c.at(s);
    let q = DVec2::new(o.x + t * d.x, o.z + t * d.z);
    let settled = (p.y - (o.y + t * d.y)).abs() <= 1e-9 * (1.0 + p.y.abs())
        && (p.x.abs() - q.length()).abs() <= 1e-9 * (1.0 + p.x.abs());
    if settled { (s, t) } else { (s0, t0) }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn crossings(lathe: &Lathe, ray: &Ray) -> Vec<f64> {
        let mut roots = Roots::new();
        lathe.intersect(ray, &mut roots);
        let mut ts: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
        ts.sort_by(f64::total_cmp);
        ts
    }

    /// The manual's thick-walled cylinder: inner radius 2, outer 3, height 5.
    fn tube() -> Lathe {
        let p = [(2.0, 0.0), (3.0, 0.0), (3.0, 5.0), (2.0, 5.0), (2.0, 0.0)]
            .map(|(r, y)| DVec2::new(r, y));
        Lathe::new(SplineKind::Linear, &p, false).unwrap()
    }

    #[test]
    fn a_level_ray_crosses_both_walls_twice() {
        let lathe = tube();
        let ts = crossings(&lathe, &Ray::new(DVec3::new(-10.0, 2.5, 0.0), DVec3::X));
        assert_eq!(ts.len(), 4, "{ts:?}");
        for (t, want) in ts.iter().zip([7.0, 8.0, 12.0, 13.0]) {
            assert!((t - want).abs() < 1e-9, "{ts:?}");
        }
        // Nearly level: the same crossings, within the tilt.
        let tilted = Ray::new(DVec3::new(-10.0, 2.5, 0.0), DVec3::new(1.0, 1e-7, 0.0));
        let ts = crossings(&lathe, &tilted);
        assert_eq!(ts.len(), 4, "{ts:?}");
        assert!((ts[0] - 7.0).abs() < 1e-6);
        assert!(lathe.inside(DVec3::new(2.5, 1.0, 0.0)));
        assert!(!lathe.inside(DVec3::new(1.0, 1.0, 0.0)));
    }

    #[test]
    fn a_steep_ray_meets_the_top_ring() {
        let lathe = tube();
        let ray = Ray::new(DVec3::new(2.5, 10.0, 0.0), DVec3::new(0.0, -1.0, 0.0));
        let ts = crossings(&lathe, &ray);
        assert!((ts[0] - 5.0).abs() < 1e-9, "{ts:?}");
        let n = lathe.normal(ray.at(ts[0]), 2);
        assert!(n.normalize().y.abs() > 0.999);
    }

    #[test]
    fn cubic_lathe_crossings_lie_on_the_curve() {
        let p = [
            (0.0, -1.0),
            (1.0, 0.0),
            (1.5, 1.0),
            (0.5, 2.0),
            (0.0, 3.0),
            (0.0, 4.0),
        ]
        .map(|(r, y)| DVec2::new(r, y));
        let lathe = Lathe::new(SplineKind::Cubic, &p, false).unwrap();
        let sturm = Lathe::new(SplineKind::Cubic, &p, true).unwrap();
        for k in 0..50 {
            let ray = Ray::new(
                DVec3::new(-4.0, -1.0 + 0.08 * k as f64, 0.3),
                DVec3::new(1.0, 0.05, 0.02),
            );
            let ts = crossings(&lathe, &ray);
            assert_eq!(ts.len(), crossings(&sturm, &ray).len());
            for t in ts {
                let p = ray.at(t);
                let q = DVec2::new((p.x * p.x + p.z * p.z).sqrt(), p.y);
                let near = lathe
                    .pieces
                    .iter()
                    .map(|piece| (piece.curve.at(piece.curve.nearest(q)) - q).length())
                    .fold(f64::INFINITY, f64::min);
                assert!(near < 1e-9, "{near}");
            }
        }
    }
}
