//! The plane curves that lathes and prisms are made of: each segment a polynomial of
//! degree at most 3 in s from 0 to 1, built from the scene's points by POV-Ray's four
//! spline kinds. A linear segment joins two points; a quadratic one follows the parabola
//! through the point before it, its first point and the next; a cubic one is a
//! Catmull-Rom segment between its middle two points, its tangents taken from their
//! neighbours; a Bézier segment has two ends and two control points.

use crate::polynomial;
use glam::DVec2;

/// One segment: `a[0] + a[1] s + a[2] s² + a[3] s³`, s from 0 to 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CurveSegment {
    pub a: [DVec2; 4],
    /// The degree in s (1 to 3), which sizes the equations solved against it.
    pub degree: usize,
}

impl CurveSegment {
    pub fn linear(p0: DVec2, p1: DVec2) -> CurveSegment {
        CurveSegment {
            a: [p0, p1 - p0, DVec2::ZERO, DVec2::ZERO],
            degree: 1,
        }
    }

    /// From `p0` to `p1` along the parabola through `before`, `p0` and `p1` at s = -1, 0
    /// and 1 (POV-Ray's quadratic spline, measured on its renders).
    pub fn quadratic(before: DVec2, p0: DVec2, p1: DVec2) -> CurveSegment {
        CurveSegment {
            a: [
                p0,
                0.5 * (p1 - before),
                0.5 * (before + p1) - p0,
                DVec2::ZERO,
            ],
            degree: 2,
        }
    }

    /// The Catmull-Rom segment from `p1` to `p2`.
    pub fn cubic(p0: DVec2, p1: DVec2, p2: DVec2, p3: DVec2) -> CurveSegment {
        CurveSegment {
            a: [
                p1,
                0.5 * (p2 - p0),
                p0 - 2.5 * p1 + 2.0 * p2 - 0.5 * p3,
                0.5 * (p3 - p0) + 1.5 * (p1 - p2),
            ],
            degree: 3,
        }
    }

    pub fn bezier(p0: DVec2, p1: DVec2, p2: DVec2, p3: DVec2) -> CurveSegment {
        CurveSegment {
            a: [
                p0,
                3.0 * (p1 - p0),
                3.0 * (p0 - 2.0 * p1 + p2),
                p3 - p0 + 3.0 * (p1 - p2),
            ],
            degree: 3,
        }
    }

    pub fn at(&self, s: f64) -> DVec2 {
        ((self.a[3] * s + self.a[2]) * s + self.a[1]) * s + self.a[0]
    }

    pub fn tangent(&self, s: f64) -> DVec2 {
        (self.a[3] * (3.0 * s) + self.a[2] * 2.0) * s + self.a[1]
    }

    /// A range that holds coordinate `axis` over the whole segment: with s from 0 to 1
    /// every power of s lies in [0, 1], so each term adds at most its coefficient's
    /// positive part and at least its negative part. Cheaper than the exact box, it lets
    /// a test skip the segments that cannot matter.
    pub fn coordinate_range(&self, axis: usize) -> (f64, f64) {
        let c = self.coordinate(axis);
        c[1..=self.degree]
            .iter()
            .fold((c[0], c[0]), |(lo, hi), &k| {
                (lo + k.min(0.0), hi + k.max(0.0))
            })
    }

    /// The coefficients of one coordinate (0: first, 1: second), lowest first.
    pub fn coordinate(&self, axis: usize) -> [f64; 4] {
        self.a.map(|v| v[axis])
    }

    /// The box around the segment, from the extremes of each coordinate.
    pub fn bounds(&self) -> (DVec2, DVec2) {
        let mut lo = self.at(0.0).min(self.at(1.0));
        let mut hi = self.at(0.0).max(self.at(1.0));
        for axis in 0..2 {
            for s in self.turning_points(axis) {
                let p = self.at(s);
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
        (lo, hi)
    }

    /// Where one coordinate's derivative vanishes inside (0, 1).
    fn turning_points(&self, axis: usize) -> Vec<f64> {
        let c = self.coordinate(axis);
        let derivative = [c[1], 2.0 * c[2], 3.0 * c[3]];
        let mut out = Vec::new();
        polynomial::roots_in(&derivative, 0.0, 1.0, &mut out);
        out
    }

    /// The parameters in [0, 1) where coordinate `axis` equals `value`, by the closed
    /// forms (a segment is at most cubic).
    pub fn crossings_of(&self, axis: usize, value: f64, out: &mut Vec<f64>) {
        let mut c = self.coordinate(axis);
        c[0] -= value;
        let start = out.len();
        solve(&c[..=self.degree], 0.0, 1.0, false, out);
        let mut kept = start;
        for k in start..out.len() {
            if out[k] < 1.0 {
                out[kept] = out[k];
                kept += 1;
            }
        }
        out.truncate(kept);
    }

    /// The parameter of the point of the segment nearest `q`: among the ends and the
    /// roots of the squared distance's derivative.
    pub fn nearest(&self, q: DVec2) -> f64 {
        // d/ds |c(s) - q|² / 2 = (c - q) · c', a polynomial of degree 2n - 1.
        let mut c = self.a;
        c[0] -= q;
        let d = [self.a[1], 2.0 * self.a[2], 3.0 * self.a[3]];
        let mut product = [0.0; 6];
        for (i, ci) in c.iter().enumerate() {
            for (j, dj) in d.iter().enumerate() {
                product[i + j] += ci.dot(*dj);
            }
        }
        let mut candidates = vec![0.0, 1.0];
        polynomial::roots_in(&product[..2 * self.degree], 0.0, 1.0, &mut candidates);
        candidates
            .into_iter()
            .min_by(|a, b| {
                (self.at(*a) - q)
                    .length_squared()
                    .total_cmp(&(self.at(*b) - q).length_squared())
            })
            .unwrap_or(0.0)
    }
}

/// Even-odd: whether `q` lies inside the closed curves made of `segments`, by counting
/// where the half-line from `q` towards +first coordinate crosses them.
pub fn encloses(segments: &[CurveSegment], q: DVec2, scratch: &mut Vec<f64>) -> bool {
    let mut inside = false;
    for segment in segments {
        // Segments that the half-line cannot meet, or meets only at or behind `q`,
        // change nothing.
        let (z_lo, z_hi) = segment.coordinate_range(1);
        if q.y < z_lo || q.y > z_hi || segment.coordinate_range(0).1 <= q.x {
            continue;
        }
        scratch.clear();
        segment.crossings_of(1, q.y, scratch);
        for &s in scratch.iter() {
            if segment.at(s).x > q.x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Appends the real roots of `coeffs` (lowest degree first, up to degree 15) in
/// `[lo, hi]` to `out`: by Sturm sequences when the scene asked for `sturm`, else by the
/// closed forms up to degree 4 and the general search above.
///
/// The variable is first scaled so that the interval reaches ±1: the solvers judge a
/// coefficient negligible against the largest, which is only right when the powers of
/// the variable are of one size (a ray in a shape scaled by 1e5 has t of 1e5).
pub fn solve(coeffs: &[f64], lo: f64, hi: f64, sturm: bool, out: &mut Vec<f64>) {
    let mut n = coeffs.len().min(polynomial::MAX_DEGREE + 1);
    while n > 0 && coeffs[n - 1] == 0.0 {
        n -= 1;
    }
    let h = lo.abs().max(hi.abs());
    if !(h > 0.0 && h.is_finite()) {
        return;
    }
    let mut scaled = [0.0; polynomial::MAX_DEGREE + 1];
    let mut power = 1.0;
    for (k, c) in coeffs[..n].iter().enumerate() {
        scaled[k] = c * power;
        power *= h;
    }
    let start = out.len();
    solve_scaled(&scaled[..n], lo / h, hi / h, sturm, out);
    for x in &mut out[start..] {
        *x *= h;
    }
}

fn solve_scaled(coeffs: &[f64], lo: f64, hi: f64, sturm: bool, out: &mut Vec<f64>) {
    let n = coeffs.len();
    if sturm && n > 2 {
        let mut found = [0.0; polynomial::MAX_DEGREE];
        let k = crate::sturm::roots_in(coeffs, lo, hi, &mut found);
        out.extend(found[..k].iter().copied().filter(|x| *x >= lo));
        return;
    }
    match n {
        0 | 1 => {}
        2 | 3 => {
            let c = if n == 3 { coeffs[2] } else { 0.0 };
            if let Some((a, b)) = super::solve_quadratic_half(c, 0.5 * coeffs[1], coeffs[0]) {
                out.extend([a, b].into_iter().filter(|x| *x >= lo && *x <= hi));
                if a == b && out.len() >= 2 && out[out.len() - 1] == out[out.len() - 2] {
                    out.pop();
                }
            }
        }
        4 => {
            let (r, k) =
                polynomial::cubic_roots_in(&[coeffs[0], coeffs[1], coeffs[2], coeffs[3]], lo, hi);
            out.extend_from_slice(&r[..k]);
        }
        5 => {
            let (r, k) = polynomial::quartic_roots_in(
                &[coeffs[0], coeffs[1], coeffs[2], coeffs[3], coeffs[4]],
                lo,
                hi,
            );
            out.extend_from_slice(&r[..k]);
        }
        _ => polynomial::roots_in(coeffs, lo, hi, out),
    }
}

/// A product of two polynomials given lowest degree first.
pub fn multiply(a: &[f64], b: &[f64], out: &mut [f64]) {
    out.iter_mut().for_each(|c| *c = 0.0);
    for (i, x) in a.iter().enumerate() {
        for (j, y) in b.iter().enumerate() {
            out[i + j] += x * y;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splines_pass_through_their_points() {
        let p = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 2.0),
            DVec2::new(3.0, 3.0),
            DVec2::new(4.0, 1.0),
        ];
        let cubic = CurveSegment::cubic(p[0], p[1], p[2], p[3]);
        assert!((cubic.at(0.0) - p[1]).length() < 1e-12);
        assert!((cubic.at(1.0) - p[2]).length() < 1e-12);
        assert!((cubic.tangent(0.0) - 0.5 * (p[2] - p[0])).length() < 1e-12);
        assert!((cubic.tangent(1.0) - 0.5 * (p[3] - p[1])).length() < 1e-12);
        let quadratic = CurveSegment::quadratic(p[0], p[1], p[2]);
        assert!((quadratic.at(1.0) - p[2]).length() < 1e-12);
        assert!((quadratic.at(-1.0) - p[0]).length() < 1e-12);
        let bezier = CurveSegment::bezier(p[0], p[1], p[2], p[3]);
        assert!((bezier.at(1.0) - p[3]).length() < 1e-12);
        assert!((bezier.at(0.5) - (p[0] + 3.0 * p[1] + 3.0 * p[2] + p[3]) / 8.0).length() < 1e-12);
    }

    #[test]
    fn a_square_encloses_its_middle_only() {
        let c = [
            DVec2::new(0.0, 0.0),
            DVec2::new(2.0, 0.0),
            DVec2::new(2.0, 2.0),
            DVec2::new(0.0, 2.0),
        ];
        let square: Vec<CurveSegment> = (0..4)
            .map(|i| CurveSegment::linear(c[i], c[(i + 1) % 4]))
            .collect();
        let mut scratch = Vec::new();
        assert!(encloses(&square, DVec2::new(1.0, 1.0), &mut scratch));
        assert!(!encloses(&square, DVec2::new(3.0, 1.0), &mut scratch));
        assert!(!encloses(&square, DVec2::new(-1.0, 1.0), &mut scratch));
        let s = square[1].nearest(DVec2::new(3.0, 0.5));
        assert!((s - 0.25).abs() < 1e-12);
    }

    #[test]
    fn coordinate_ranges_hold_the_segment() {
        let p = [
            DVec2::new(0.0, 1.0),
            DVec2::new(3.0, -2.0),
            DVec2::new(-1.0, 4.0),
            DVec2::new(2.0, 0.5),
        ];
        for segment in [
            CurveSegment::linear(p[0], p[1]),
            CurveSegment::quadratic(p[0], p[1], p[2]),
            CurveSegment::cubic(p[0], p[1], p[2], p[3]),
            CurveSegment::bezier(p[0], p[1], p[2], p[3]),
        ] {
            for axis in 0..2 {
                let (lo, hi) = segment.coordinate_range(axis);
                for k in 0..=100 {
                    let v = segment.at(k as f64 / 100.0)[axis];
                    assert!(v >= lo - 1e-12 && v <= hi + 1e-12, "{v} outside {lo}..{hi}");
                }
            }
        }
    }
}
