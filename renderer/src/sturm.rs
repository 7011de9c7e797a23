//! Real roots of a polynomial in an interval by Sturm's theorem: the number of sign
//! changes along the Sturm sequence (p, p', and the negated remainders of Euclid's
//! algorithm) drops by one at each distinct root, so bisection on that count isolates
//! every root, double roots included, which a change of sign alone would miss. Each
//! isolated root is then refined by Newton steps kept safe by bisection of its bracket
//! (or, for a root of even multiplicity, by bisection on the count). Coefficients are
//! given lowest degree first, up to degree 15.

use crate::polynomial::MAX_DEGREE;

/// A polynomial on the stack, lowest degree first, with room for `N` coefficients. The
/// work is sized by the degree searched: a sequence holds `N` polynomials, and a cubic's
/// would otherwise zero and copy a sextic's or a 15th degree's worth of them.
#[derive(Debug, Clone, Copy)]
struct Poly<const N: usize> {
    c: [f64; N],
    /// Degree + 1; 0 for the zero polynomial.
    len: usize,
}

impl<const N: usize> Poly<N> {
    const ZERO: Poly<N> = Poly {
        c: [0.0; N],
        len: 0,
    };

    fn eval(&self, x: f64) -> f64 {
        self.c[..self.len]
            .iter()
            .rev()
            .fold(0.0, |acc, c| acc * x + c)
    }

    /// The value and the slope at `x`, by one Horner pass.
    fn eval_with_slope(&self, x: f64) -> (f64, f64) {
        self.c[..self.len]
            .iter()
            .rev()
            .fold((0.0, 0.0), |(v, s), c| (v * x + c, s * x + v))
    }

    fn lead(&self) -> f64 {
        if self.len == 0 {
            0.0
        } else {
            self.c[self.len - 1]
        }
    }

    /// Divides by the largest coefficient, keeping signs: Sturm counts need only signs.
    fn normalise(&mut self) {
        let m = self.c[..self.len]
            .iter()
            .fold(0.0f64, |m, c| m.max(c.abs()));
        if m > 0.0 && m.is_finite() {
            for c in &mut self.c[..self.len] {
                *c /= m;
            }
        }
    }

    /// Drops leading coefficients that are negligible against the largest.
    fn trim(&mut self, relative: f64) {
        let m = self.c[..self.len]
            .iter()
            .fold(0.0f64, |m, c| m.max(c.abs()));
        while self.len > 0 && self.c[self.len - 1].abs() <= relative * m {
            self.len -= 1;
        }
    }
}

/// The Sturm sequence of a polynomial: at most as many polynomials as coefficients.
struct Sequence<const N: usize> {
    polys: [Poly<N>; N],
    len: usize,
}

impl<const N: usize> Sequence<N> {
    fn new(p: &Poly<N>) -> Sequence<N> {
        let zero = Poly::ZERO;
        let mut seq = Sequence {
            polys: [zero; N],
            len: 0,
        };
        let mut first = *p;
        first.normalise();
        seq.polys[0] = first;
        let mut d = zero;
        for i in 1..first.len {
            d.c[i - 1] = first.c[i] * i as f64;
        }
        d.len = first.len.saturating_sub(1);
        d.normalise();
        seq.polys[1] = d;
        seq.len = 2;
        while seq.len < N && seq.polys[seq.len - 1].len > 1 {
            // The dividends are normalised to a largest coefficient of 1, so what is left
            // below 1e-12 is rounding: the remainder is zero.
            let mut r = remainder(&seq.polys[seq.len - 2], &seq.polys[seq.len - 1]);
            while r.len > 0 && r.c[r.len - 1].abs() <= 1e-12 {
                r.len -= 1;
            }
            if r.len == 0 {
                break;
            }
            for c in &mut r.c[..r.len] {
                *c = -*c;
            }
            r.normalise();
            seq.polys[seq.len] = r;
            seq.len += 1;
        }
        seq
    }

    /// Sign changes along the sequence at `x`.
    fn changes(&self, x: f64) -> u32 {
        let mut count = 0;
        let mut last = 0.0f64;
        for p in &self.polys[..self.len] {
            let v = p.eval(x);
            if v != 0.0 {
                if last != 0.0 && (v < 0.0) != (last < 0.0) {
                    count += 1;
                }
                last = v;
            }
        }
        count
    }

    /// Sign changes at +∞ or -∞: from the leading coefficients.
    fn changes_at_infinity(&self, positive: bool) -> u32 {
        let mut count = 0;
        let mut last = 0.0f64;
        for p in &self.polys[..self.len] {
            let mut v = p.lead();
            if !positive && p.len % 2 == 0 {
                v = -v;
            }
            if v != 0.0 {
                if last != 0.0 && (v < 0.0) != (last < 0.0) {
                    count += 1;
                }
                last = v;
            }
        }
        count
    }
}

/// The quotient of a divided by b, the remainder dropped.
fn quotient<const N: usize>(a: &Poly<N>, b: &Poly<N>) -> Poly<N> {
    let mut r = *a;
    let mut q = Poly {
        c: [0.0; N],
        len: a.len + 1 - b.len,
    };
    let lead = b.lead();
    while r.len >= b.len && r.len > 0 {
        let factor = r.lead() / lead;
        let shift = r.len - b.len;
        q.c[shift] = factor;
        for i in 0..b.len {
            r.c[shift + i] -= factor * b.c[i];
        }
        r.c[r.len - 1] = 0.0;
        r.len -= 1;
    }
    q
}

/// The remainder of a divided by b.
fn remainder<const N: usize>(a: &Poly<N>, b: &Poly<N>) -> Poly<N> {
    let mut r = *a;
    if b.len == 0 {
        return r;
    }
    let lead = b.lead();
    while r.len >= b.len && r.len > 0 {
        let factor = r.lead() / lead;
        let shift = r.len - b.len;
        for i in 0..b.len {
            r.c[shift + i] -= factor * b.c[i];
        }
        r.c[r.len - 1] = 0.0;
        r.len -= 1;
    }
    r
}

/// Appends the distinct real roots of `coeffs` in `(lo, hi]` to `out`, ascending, each to
/// a relative precision of about 1e-12; returns how many were written.
pub fn roots_in(coeffs: &[f64], lo: f64, hi: f64, out: &mut [f64; MAX_DEGREE]) -> usize {
    if coeffs.len() > MAX_DEGREE + 1
        || lo.is_nan()
        || hi.is_nan()
        || lo >= hi
        || coeffs.iter().any(|c| !c.is_finite())
    {
        return 0;
    }
    match coeffs.len() {
        0..=4 => roots_with::<4>(coeffs, lo, hi, out),
        5..=7 => roots_with::<7>(coeffs, lo, hi, out),
        _ => roots_with::<{ MAX_DEGREE + 1 }>(coeffs, lo, hi, out),
    }
}

/// [`roots_in`] with room for `N >= coeffs.len()` coefficients.
fn roots_with<const N: usize>(
    coeffs: &[f64],
    lo: f64,
    hi: f64,
    out: &mut [f64; MAX_DEGREE],
) -> usize {
    let mut p = Poly::<N>::ZERO;
    p.len = coeffs.len();
    p.c[..coeffs.len()].copy_from_slice(coeffs);
    p.trim(1e-14);
    if p.len < 2 {
        return 0;
    }
    let mut seq = Sequence::new(&p);
    // A common factor of p and p' means multiple roots, where counts taken near the root
    // are at the mercy of rounding: p divided by that factor has the same roots, simple.
    let gcd = seq.polys[seq.len - 1];
    if gcd.len > 1 {
        p = quotient(&seq.polys[0], &gcd);
        p.trim(1e-14);
        if p.len < 2 {
            return 0;
        }
        seq = Sequence::new(&p);
    }
    let count_at = |x: f64| -> u32 {
        if x == f64::INFINITY {
            seq.changes_at_infinity(true)
        } else if x == f64::NEG_INFINITY {
            seq.changes_at_infinity(false)
        } else {
            seq.changes(x)
        }
    };
    // Infinite ends are replaced by a bound on the roots' size (Cauchy's).
    let lead = p.lead().abs();
    let bound = 1.0
        + p.c[..p.len - 1]
            .iter()
            .fold(0.0f64, |m, c| m.max(c.abs() / lead));
    let (lo, hi) = (lo.max(-bound), hi.min(bound));
    if lo >= hi {
        return 0;
    }
    let mut n = 0;
    isolate(
        &p,
        &count_at,
        lo,
        count_at(lo),
        hi,
        count_at(hi),
        0,
        out,
        &mut n,
    );
    n
}

/// Splits `(a, b]` until each part holds one root, and refines those.
#[allow(clippy::too_many_arguments)]
fn isolate<const N: usize>(
    p: &Poly<N>,
    count_at: &dyn Fn(f64) -> u32,
    a: f64,
    va: u32,
    b: f64,
    vb: u32,
    depth: u32,
    out: &mut [f64; MAX_DEGREE],
    n: &mut usize,
) {
    let roots = va.saturating_sub(vb);
    if roots == 0 || *n >= out.len() {
        return;
    }
    let width = b - a;
    if roots == 1 || depth > 60 || width <= 1e-14 * (a.abs() + b.abs()) {
        out[*n] = refine(p, count_at, (a, b), va);
        *n += 1;
        return;
    }
    let m = a + 0.5 * width;
    let vm = count_at(m);
    isolate(p, count_at, a, va, m, vm, depth + 1, out, n);
    isolate(p, count_at, m, vm, b, vb, depth + 1, out, n);
}

/// The single root in `(a, b]`: Newton's method kept inside the bracket by bisection
/// when the ends differ in sign, otherwise (an even root) bisection on the Sturm count.
fn refine<const N: usize>(
    p: &Poly<N>,
    count_at: &dyn Fn(f64) -> u32,
    (a, b): (f64, f64),
    va: u32,
) -> f64 {
    let (mut a, mut b) = (a, b);
    let fa = p.eval(a);
    let fb = p.eval(b);
    if fa != 0.0 && fb != 0.0 && (fa < 0.0) != (fb < 0.0) {
        return newton_in_bracket(p, a, fa < 0.0, b);
    }
    for _ in 0..200 {
        let width = b - a;
        if width <= 1e-12 * (a.abs().max(b.abs()) + 1e-300) {
            break;
        }
        let m = a + 0.5 * width;
        if count_at(m) < va {
            b = m;
        } else {
            a = m;
        }
    }
    0.5 * (a + b)
}

/// The root of `p` between `a` and `b`, where it changes sign (negative at `a` when
/// `negative_at_a`), to a relative precision of about 1e-12. Each step is Newton's unless
/// it would leave the bracket or shrink it less than a bisection would have two steps
/// before, so it converges at least as surely as bisection and, near a simple root, in a
/// handful of steps instead of some forty.
fn newton_in_bracket<const N: usize>(p: &Poly<N>, a: f64, negative_at_a: bool, b: f64) -> f64 {
    let (mut a, mut b) = (a, b);
    let mut x = a + 0.5 * (b - a);
    let mut step = b - a;
    let mut previous = step;
    for _ in 0..200 {
        let (f, slope) = p.eval_with_slope(x);
        if f == 0.0 {
            return x;
        }
        if (f < 0.0) == negative_at_a {
            a = x;
        } else {
            b = x;
        }
        let newton = x - f / slope;
        let fast = newton > a && newton < b && (2.0 * f).abs() <= (previous * slope).abs();
        previous = step;
        let next = if fast { newton } else { a + 0.5 * (b - a) };
        step = next - x;
        x = next;
        let tolerance = 1e-12 * (x.abs() + 1e-300);
        if step.abs() <= tolerance || b - a <= tolerance {
            break;
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn roots(coeffs: &[f64], lo: f64, hi: f64) -> Vec<f64> {
        let mut out = [0.0; MAX_DEGREE];
        let n = roots_in(coeffs, lo, hi, &mut out);
        out[..n].to_vec()
    }

    #[test]
    fn finds_simple_and_double_roots() {
        // (x - 1)(x - 2)(x - 3)(x - 4)
        let r = roots(&[24.0, -50.0, 35.0, -10.0, 1.0], 0.0, 10.0);
        assert_eq!(r.len(), 4, "{r:?}");
        for (got, want) in r.iter().zip([1.0, 2.0, 3.0, 4.0]) {
            assert!((got - want).abs() < 1e-10, "{r:?}");
        }
        // (x - 1)² (x + 2): the double root has no sign change.
        let r = roots(&[2.0, -3.0, 0.0, 1.0], -5.0, 5.0);
        assert_eq!(r.len(), 2, "{r:?}");
        assert!(
            (r[0] + 2.0).abs() < 1e-10 && (r[1] - 1.0).abs() < 1e-6,
            "{r:?}"
        );
    }

    /// Refined roots are good to about 1e-12 relative, at the interval's end as well as
    /// inside it.
    #[test]
    fn roots_are_refined_to_full_precision() {
        let r = roots(&[-2.0, 0.0, 1.0], 0.0, 3.0);
        assert_eq!(r.len(), 1);
        assert!((r[0] - 2f64.sqrt()).abs() < 1e-12 * 2f64.sqrt(), "{r:?}");
        // (x - 1e-3)(x - 5)(x + 7), scaled.
        let r = roots(&[3.5e-2, -35.002, 1.999, 1.0], -10.0, 10.0);
        assert_eq!(r.len(), 3, "{r:?}");
        for (got, want) in r.iter().zip([-7.0, 1e-3, 5.0]) {
            assert!((got - want).abs() <= 1e-11 * want.abs(), "{r:?}");
        }
        let end = roots(&[-1.0, 1.0], 0.0, 1.0);
        assert!(end.len() == 1 && (end[0] - 1.0).abs() < 1e-12, "{end:?}");
    }

    #[test]
    fn high_degree_and_infinite_ranges() {
        // Roots 1..7 of a 7th-degree polynomial, searched over the whole line.
        let mut p = vec![1.0];
        for k in 1..=7 {
            let mut next = vec![0.0; p.len() + 1];
            for (i, c) in p.iter().enumerate() {
                next[i + 1] += c;
                next[i] -= c * f64::from(k);
            }
            p = next;
        }
        let r = roots(&p, f64::NEG_INFINITY, f64::INFINITY);
        assert_eq!(r.len(), 7, "{r:?}");
        for (i, got) in r.iter().enumerate() {
            assert!((got - (i + 1) as f64).abs() < 1e-8, "{r:?}");
        }
        assert!(roots(&[1.0, 0.0, 1.0], f64::NEG_INFINITY, f64::INFINITY).is_empty());
        assert!(roots(&[f64::NAN, 1.0], -1.0, 1.0).is_empty());
    }
}
