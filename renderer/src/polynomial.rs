//! Real roots of polynomials inside an interval, for the shapes whose surfaces are
//! algebraic (torus, later cubic, quartic and poly). The roots of the derivative, found
//! the same way down to a straight line, split the interval into stretches where the
//! polynomial is monotonic; each stretch whose ends differ in sign holds one root, refined
//! by bracketed Newton iteration. Coefficients are given lowest degree first.

use crate::fast_math;
use analysis::trig;

/// The highest degree POV-Ray's `poly` allows.
pub const MAX_DEGREE: usize = 15;

/// A polynomial on the stack, lowest degree first.
#[derive(Debug, Clone, Copy)]
struct Poly {
    c: [f64; MAX_DEGREE + 1],
    len: usize,
}

impl Poly {
    const ZERO: Poly = Poly {
        c: [0.0; MAX_DEGREE + 1],
        len: 0,
    };

    fn coeffs(&self) -> &[f64] {
        &self.c[..self.len]
    }

    fn eval(&self, x: f64) -> f64 {
        self.coeffs().iter().rev().fold(0.0, |acc, c| acc * x + c)
    }

    fn scale(&self) -> f64 {
        self.coeffs()
            .iter()
            .fold(0.0f64, |m, c| fast_math::max(m, c.abs()))
    }

    /// Drops leading coefficients at or below `tolerance`.
    fn trim(&mut self, tolerance: f64) {
        while self.len > 0 && self.c[self.len - 1].abs() <= tolerance {
            self.len -= 1;
        }
    }

    /// The value and the slope at `x`, by one Horner pass.
    fn eval_with_derivative(&self, x: f64) -> (f64, f64) {
        let mut value = 0.0;
        let mut slope = 0.0;
        for c in self.coeffs().iter().rev() {
            slope = slope * x + value;
            value = value * x + c;
        }
        (value, slope)
    }

    fn derivative(&self) -> Poly {
        let mut d = Poly::ZERO;
        for i in 1..self.len {
            d.c[i - 1] = self.c[i] * i as f64;
        }
        d.len = self.len.saturating_sub(1);
        d
    }
}

/// Appends to `out` the real roots of the quartic `coeffs` (lowest degree first) in
/// `[lo, hi]`: Ferrari's closed form through the resolvent cubic, each root then polished
/// by two Newton steps on the quartic itself. Far cheaper than the general search, which
/// it falls back to when the leading coefficient vanishes.
pub fn quartic_roots_in(coeffs: &[f64; 5], lo: f64, hi: f64) -> ([f64; 4], usize) {
    let mut found = ([0.0; 4], 0);
    let mut keep = |x: f64| {
        if x >= lo && x <= hi && x.is_finite() && found.1 < 4 {
            found.0[found.1] = x;
            found.1 += 1;
        }
    };
    let lead = coeffs[4];
    let scale = coeffs
        .iter()
        .fold(0.0f64, |m, c| fast_math::max(m, c.abs()));
    if lead.abs() <= 1e-14 * scale || !scale.is_finite() || lead.is_nan() {
        let mut searched = Vec::new();
        roots_in(coeffs, lo, hi, &mut searched);
        searched.into_iter().for_each(&mut keep);
        return found;
    }
    let (a, b, c, d) = (
        coeffs[3] / lead,
        coeffs[2] / lead,
        coeffs[1] / lead,
        coeffs[0] / lead,
    );
    // Depressed quartic y⁴ + p y² + q y + r with x = y - a/4.
    let sub = a / 4.0;
    let a2 = a * a;
    let p = b - 3.0 / 8.0 * a2;
    let q = c - a * b / 2.0 + a2 * a / 8.0;
    let r = d - a * c / 4.0 + a2 * b / 16.0 - 3.0 / 256.0 * a2 * a2;
    let mut ys = [0.0; 4];
    let mut n = 0;
    if r.abs() < 1e-14 {
        // y (y³ + p y + q) = 0.
        ys[n] = 0.0;
        n += 1;
        let (cubic, count) = cubic_roots(0.0, p, q);
        for &y in &cubic[..count] {
            ys[n] = y;
            n += 1;
        }
    } else {
        // The largest real root of the resolvent z³ - p/2 z² - r z + (r p / 2 - q² / 8):
        // for it both z² - r and 2z - p are non-negative whenever the quartic has a real
        // root, so the factoring below needs the general search only after rounding.
        let z = largest_cubic_root(-p / 2.0, -r, r * p / 2.0 - q * q / 8.0);
        let u = z * z - r;
        let v = 2.0 * z - p;
        let (u, v) = (
            if u < 0.0 {
                if u > -1e-12 { 0.0 } else { f64::NAN }
            } else {
                u.sqrt()
            },
            if v < 0.0 {
                if v > -1e-12 { 0.0 } else { f64::NAN }
            } else {
                v.sqrt()
            },
        );
        if u.is_nan() || v.is_nan() {
            let mut searched = Vec::new();
            roots_in(coeffs, lo, hi, &mut searched);
            searched.into_iter().for_each(&mut keep);
            return found;
        }
        let v = if q < 0.0 { -v } else { v };
        for (bq, cq) in [(v, z - u), (-v, z + u)] {
            let disc = bq * bq - 4.0 * cq;
            if disc >= 0.0 {
                let root = disc.sqrt();
                let qq = -0.5 * (bq + bq.signum() * root);
                if qq != 0.0 {
                    ys[n] = qq;
                    ys[n + 1] = cq / qq;
                    n += 2;
                } else {
                    ys[n] = 0.0;
                    n += 1;
                }
            }
        }
    }
    let poly = |x: f64| {
        let value = (((coeffs[4] * x + coeffs[3]) * x + coeffs[2]) * x + coeffs[1]) * x + coeffs[0];
        let slope = ((4.0 * coeffs[4] * x + 3.0 * coeffs[3]) * x + 2.0 * coeffs[2]) * x + coeffs[1];
        (value, slope)
    };
    for &y in &ys[..n] {
        let mut x = y - sub;
        for _ in 0..2 {
            let (f, df) = poly(x);
            if df != 0.0 {
                let next = x - f / df;
                if next.is_finite() {
                    x = next;
                }
            }
        }
        keep(x);
    }
    found.0[..found.1].sort_by(f64::total_cmp);
    found
}

/// The real roots of the cubic `coeffs` (lowest degree first) in `[lo, hi]`, ascending:
/// the closed form, each root polished by two Newton steps on the cubic itself. A
/// vanishing leading coefficient falls back to the general search. Inlined, so that the
/// roots stay in locals instead of going through memory, as returned arrays do in
/// WebAssembly.
#[inline(always)]
pub fn cubic_roots_in(coeffs: &[f64; 4], lo: f64, hi: f64) -> ([f64; 3], usize) {
    let mut found = ([0.0; 3], 0);
    let lead = coeffs[3];
    let scale = fast_math::max(
        fast_math::max(coeffs[0].abs(), coeffs[1].abs()),
        fast_math::max(coeffs[2].abs(), lead.abs()),
    );
    if lead.abs() <= 1e-14 * scale || !scale.is_finite() || lead.is_nan() {
        return searched_cubic_roots_in(coeffs, lo, hi);
    }
    let (xs, n) = cubic_roots(coeffs[2] / lead, coeffs[1] / lead, coeffs[0] / lead);
    for &x0 in &xs[..n] {
        let x = polish_cubic_root(coeffs, x0);
        if x >= lo && x <= hi && x.is_finite() {
            found.0[found.1] = x;
            found.1 += 1;
        }
    }
    found.0[..found.1].sort_by(f64::total_cmp);
    found
}

/// How far, relative to the coefficients' unit of the variable, two Newton steps may move
/// a root of the closed form: its error is a few ulps at a simple root, about the square
/// root of that at a double one and the cube root at a triple one.
const POLISH_REACH: f64 = 1e-4;

/// The least root of the cubic `coeffs` (lowest degree first) that `keep` accepts, where
/// `keep` accepts nothing outside `near` (widened by [`POLISH_REACH`]): the least of
/// those [`cubic_roots_in`] gives over that interval that `keep` accepts. The
/// closed form's roots are polished least first, only while one may still be the
/// answer, so that a ray asking for its nearest crossing pays for one root's Newton
/// steps instead of three.
#[inline(always)]
pub fn least_cubic_root(
    coeffs: &[f64; 4],
    near: (f64, f64),
    keep: impl Fn(f64) -> bool,
) -> Option<f64> {
    let lead = coeffs[3];
    let scale = fast_math::max(
        fast_math::max(coeffs[0].abs(), coeffs[1].abs()),
        fast_math::max(coeffs[2].abs(), lead.abs()),
    );
    let (lo, hi) = (near.0 - POLISH_REACH, near.1 + POLISH_REACH);
    if lead.abs() <= 1e-14 * scale || !scale.is_finite() || lead.is_nan() {
        let (r, n) = searched_cubic_roots_in(coeffs, lo, hi);
        return r[..n].iter().copied().find(|&x| keep(x));
    }
    let (mut xs, n) = cubic_roots(coeffs[2] / lead, coeffs[1] / lead, coeffs[0] / lead);
    if n == 3 {
        for (i, j) in [(0, 1), (1, 2), (0, 1)] {
            if xs[j] < xs[i] {
                xs.swap(i, j);
            }
        }
    }
    let mut best: Option<f64> = None;
    for &x0 in &xs[..n] {
        if best.is_some_and(|b| x0 > b + POLISH_REACH) || x0 > hi {
            break;
        }
        if x0 < lo {
            continue;
        }
        let x = polish_cubic_root(coeffs, x0);
        if x.is_finite() && keep(x) && best.is_none_or(|b| x < b) {
            best = Some(x);
        }
    }
    best
}

/// A root of the cubic's closed form after two Newton steps on the cubic itself.
#[inline(always)]
fn polish_cubic_root(coeffs: &[f64; 4], x0: f64) -> f64 {
    let mut x = x0;
    for _ in 0..2 {
        let f = ((coeffs[3] * x + coeffs[2]) * x + coeffs[1]) * x + coeffs[0];
        let df = (3.0 * coeffs[3] * x + 2.0 * coeffs[2]) * x + coeffs[1];
        if df != 0.0 {
            let next = x - f / df;
            if next.is_finite() {
                x = next;
            }
        }
    }
    x
}

/// The roots of a cubic whose leading coefficient vanishes, by the general search: out of
/// line, so that the closed form's callers set up no room for it.
#[inline(never)]
fn searched_cubic_roots_in(coeffs: &[f64; 4], lo: f64, hi: f64) -> ([f64; 3], usize) {
    let mut found = ([0.0; 3], 0);
    let mut searched = Vec::new();
    roots_in(coeffs, lo, hi, &mut searched);
    for x in searched.into_iter().take(3) {
        found.0[found.1] = x;
        found.1 += 1;
    }
    found
}

/// The real roots of the monic cubic x³ + a x² + b x + c and how many there are (1 or 3).
/// Inlined, so that they stay in locals instead of going through memory.
#[inline(always)]
fn cubic_roots(a: f64, b: f64, c: f64) -> ([f64; 3], usize) {
    let q = (a * a - 3.0 * b) / 9.0;
    let r = (2.0 * a * a * a - 9.0 * a * b + 27.0 * c) / 54.0;
    let shift = a / 3.0;
    if r * r < q * q * q {
        let theta = (r / (q * q * q).sqrt()).clamp(-1.0, 1.0).acos();
        let m = -2.0 * q.sqrt();
        let (sin, cos) = trig::sin_cos(theta / 3.0);
        let (above, below) = third_turns(sin, cos);
        ([m * cos - shift, m * above - shift, m * below - shift], 3)
    } else {
        let big = -r.signum() * fast_math::cbrt(r.abs() + (r * r - q * q * q).sqrt());
        let small = if big != 0.0 { q / big } else { 0.0 };
        ([big + small - shift, 0.0, 0.0], 1)
    }
}

/// cos(φ + 2π/3) and cos(φ - 2π/3) from the sine and cosine of φ: the angles of the
/// other two roots of a cubic with three, without two more cosines.
fn third_turns(sin: f64, cos: f64) -> (f64, f64) {
    const HALF_ROOT_3: f64 = 0.866_025_403_784_438_6;
    (
        -0.5 * cos - HALF_ROOT_3 * sin,
        -0.5 * cos + HALF_ROOT_3 * sin,
    )
}

/// The largest real root of the monic cubic x³ + a x² + b x + c: of three, the one
/// `cubic_roots` finds second, without the other two.
fn largest_cubic_root(a: f64, b: f64, c: f64) -> f64 {
    let q = (a * a - 3.0 * b) / 9.0;
    let r = (2.0 * a * a * a - 9.0 * a * b + 27.0 * c) / 54.0;
    let shift = a / 3.0;
    if r * r < q * q * q {
        let theta = (r / (q * q * q).sqrt()).clamp(-1.0, 1.0).acos();
        let (sin, cos) = trig::sin_cos(theta / 3.0);
        -2.0 * q.sqrt() * third_turns(sin, cos).0 - shift
    } else {
        let big = -r.signum() * fast_math::cbrt(r.abs() + (r * r - q * q * q).sqrt());
        let small = if big != 0.0 { q / big } else { 0.0 };
        big + small - shift
    }
}

/// Appends to `out` the distinct real roots of `coeffs` (at most degree 15) in
/// `[lo, hi]`, ascending.
pub fn roots_in(coeffs: &[f64], lo: f64, hi: f64, out: &mut Vec<f64>) {
    if coeffs.len() > MAX_DEGREE + 1
        || lo.is_nan()
        || hi.is_nan()
        || lo >= hi
        || coeffs.iter().any(|c| !c.is_finite())
    {
        return;
    }
    let mut p = Poly::ZERO;
    p.c[..coeffs.len()].copy_from_slice(coeffs);
    p.len = coeffs.len();
    let scale = p.scale();
    if scale == 0.0 {
        return;
    }
    for c in &mut p.c[..p.len] {
        *c /= scale;
    }
    // A ray grazing a surface can leave a negligible leading coefficient and with it a
    // huge spurious root.
    p.trim(1e-14);
    let mut roots = [0.0; MAX_DEGREE];
    let n = roots_of(&p, lo, hi, 1e-13, &mut roots);
    out.extend_from_slice(&roots[..n]);
}

/// The roots of `p` in `[lo, hi]`, ascending, written to `out`; returns how many. Between
/// consecutive roots of the derivative (found the same way) `p` is monotonic, so each
/// such stretch holds at most one root, bracketed by a change of sign.
///
/// A coarse critical point can land a hair past a double root; the stretch then shows no
/// change of sign and that tangent root is lost, which is what a ray grazing a surface
/// should see anyway.
fn roots_of(p: &Poly, lo: f64, hi: f64, precision: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    match p.len {
        0 | 1 => 0,
        2 => {
            let t = -p.c[0] / p.c[1];
            if (lo..=hi).contains(&t) {
                out[0] = t;
                1
            } else {
                0
            }
        }
        _ => {
            let mut critical = [0.0; MAX_DEGREE];
            let mut dp = p.derivative();
            dp.trim(0.0);
            // The derivative's roots only split the interval: a coarse position will do.
            let m = roots_of(&dp, lo, hi, 1e-7, &mut critical);
            let mut n = 0;
            let mut a = lo;
            let mut fa = p.eval(a);
            for &b in critical[..m].iter().chain(std::iter::once(&hi)) {
                let fb = p.eval(b);
                if fa == 0.0 {
                    if n == 0 || out[n - 1] != a {
                        out[n] = a;
                        n += 1;
                    }
                } else if (fa < 0.0) != (fb < 0.0)
                    && fb != 0.0
                    && let Some(root) = refine(p, a, b, precision)
                {
                    out[n] = root;
                    n += 1;
                }
                a = b;
                fa = fb;
            }
            if fa == 0.0 && (n == 0 || out[n - 1] != a) {
                out[n] = a;
                n += 1;
            }
            n
        }
    }
}

/// The root of `p` in `[lo, hi]` when `p` changes sign there, to a relative `precision`:
/// Newton's method kept inside the shrinking bracket, bisecting whenever a step would
/// leave it or converge too slowly.
fn refine(p: &Poly, mut lo: f64, mut hi: f64, precision: f64) -> Option<f64> {
    let f_lo = p.eval(lo);
    let f_hi = p.eval(hi);
    if f_lo == 0.0 {
        return Some(lo);
    }
    if f_hi == 0.0 {
        return Some(hi);
    }
    if (f_lo < 0.0) == (f_hi < 0.0) {
        return None;
    }
    // Orient the bracket so that p(lo) < 0 < p(hi).
    if f_lo > 0.0 {
        std::mem::swap(&mut lo, &mut hi);
    }
    let tolerance = precision * (lo.abs().max(hi.abs()) + (hi - lo).abs());
    let mut x = 0.5 * (lo + hi);
    let mut last_step = (hi - lo).abs();
    for _ in 0..100 {
        let (f, df) = p.eval_with_derivative(x);
        if f == 0.0 {
            return Some(x);
        }
        if f < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        let newton = x - f / df;
        let inside = (newton - lo) * (newton - hi) < 0.0;
        let step = if inside && (f / df).abs() * 2.0 < last_step {
            let step = (newton - x).abs();
            x = newton;
            step
        } else {
            let mid = 0.5 * (lo + hi);
            let step = (mid - x).abs();
            x = mid;
            step
        };
        last_step = step;
        if step <= tolerance {
            return Some(x);
        }
    }
    Some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn roots(coeffs: &[f64], lo: f64, hi: f64) -> Vec<f64> {
        let mut out = Vec::new();
        roots_in(coeffs, lo, hi, &mut out);
        out
    }

    #[test]
    fn quartic_with_four_roots() {
        // (x - 1)(x - 2)(x - 3)(x - 4) = x⁴ - 10x³ + 35x² - 50x + 24
        let r = roots(&[24.0, -50.0, 35.0, -10.0, 1.0], 0.0, 10.0);
        assert_eq!(r.len(), 4, "{r:?}");
        for (got, want) in r.iter().zip([1.0, 2.0, 3.0, 4.0]) {
            assert!((got - want).abs() < 1e-10, "{r:?}");
        }
        assert_eq!(roots(&[24.0, -50.0, 35.0, -10.0, 1.0], 1.5, 3.5).len(), 2);
    }

    #[test]
    fn closed_form_quartic_agrees_with_the_search() {
        for coeffs in [
            [24.0, -50.0, 35.0, -10.0, 1.0],
            [1.0, 0.0, -5.0, 0.0, 4.0],
            [0.3, -1.2, 0.1, 0.7, 2.0],
            [1.0, 0.0, 0.0, 0.0, 1.0],
        ] {
            let (found, n) = quartic_roots_in(&coeffs, -10.0, 10.0);
            let closed = &found[..n];
            let searched = roots(&coeffs, -10.0, 10.0);
            assert_eq!(
                closed.len(),
                searched.len(),
                "{coeffs:?}: {closed:?} {searched:?}"
            );
            for (a, b) in closed.iter().zip(&searched) {
                assert!((a - b).abs() < 1e-9, "{coeffs:?}: {closed:?} {searched:?}");
            }
        }
    }

    #[test]
    fn the_least_cubic_root_kept_is_the_least_of_all_kept() {
        // Three simple roots, a double and a simple one, a triple one, one real root.
        for coeffs in [
            [6.0, -11.0, 6.0, -1.0],
            [0.5, 0.0, -1.5, 1.0],
            [-1.0, 3.0, -3.0, 1.0],
            [1.0, 1.0, 1.0, 1.0],
            [0.3, -0.2, -0.9, 0.35],
        ] {
            let (all, n) = cubic_roots_in(&coeffs, -10.0, 10.0);
            for above in [-10.0, -0.5, 0.99, 1.5, 2.5, 9.0] {
                let keep = |x: f64| x > above && x < 5.0;
                let want = all[..n].iter().copied().find(|&x| keep(x));
                let got = least_cubic_root(&coeffs, (above, 5.0), keep);
                assert_eq!(got, want, "{coeffs:?} above {above}");
            }
        }
    }

    #[test]
    fn the_largest_cubic_root_is_the_largest_of_all() {
        for (a, b, c) in [
            (-6.0, 11.0, -6.0),
            (0.0, -3.0, 1.0),
            (1.0, 1.0, 1.0),
            (-0.5, -2.0, 0.3),
            (3.0, 3.0, 1.0),
        ] {
            let (all, n) = cubic_roots(a, b, c);
            let want = all[..n].iter().fold(f64::NEG_INFINITY, |m, &x| m.max(x));
            let got = largest_cubic_root(a, b, c);
            assert!((got - want).abs() < 1e-9, "{a} {b} {c}: {got} {want}");
        }
    }

    #[test]
    fn close_roots_and_no_roots() {
        // (x - 1)(x - 1.000001)(x² + 1)
        let a = 1.0;
        let b = 1.000_001;
        let quad = [a * b, -(a + b), 1.0];
        let mut p = [0.0; 5];
        for (i, q) in quad.iter().enumerate() {
            p[i] += q;
            p[i + 2] += q;
        }
        let r = roots(&p, 0.0, 2.0);
        assert_eq!(r.len(), 2, "{r:?}");
        assert!(roots(&[1.0, 0.0, 1.0], -5.0, 5.0).is_empty());
        assert!(roots(&[f64::NAN, 1.0], -5.0, 5.0).is_empty());
    }
}
