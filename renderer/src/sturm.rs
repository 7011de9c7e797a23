//! Real roots of a polynomial in an interval by Sturm's theorem: the number of sign
//! changes along the Sturm sequence (p, p', and the negated remainders of Euclid's
//! algorithm) drops by one at each distinct root, so bisection on that count isolates
//! every root, double roots included, which a change of sign alone would miss. Each
//! isolated root is then refined by bisection kept safe by the count, sped up by Newton
//! steps. Coefficients are given lowest degree first, up to degree 15.

use crate::polynomial::MAX_DEGREE;

/// A polynomial on the stack, lowest degree first.
#[derive(Debug, Clone, Copy)]
struct Poly {
    c: [f64; MAX_DEGREE + 1],
    /// Degree + 1; 0 for the zero polynomial.
    len: usize,
}

impl Poly {
    fn eval(&self, x: f64) -> f64 {
        self.c[..self.len]
            .iter()
            .rev()
            .fold(0.0, |acc, c| acc * x + c)
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

/// The Sturm sequence of a polynomial.
struct Sequence {
    polys: [Poly; MAX_DEGREE + 1],
    len: usize,
}

impl Sequence {
    fn new(p: &Poly) -> Sequence {
        let zero = Poly {
            c: [0.0; MAX_DEGREE + 1],
            len: 0,
        };
        let mut seq = Sequence {
            polys: [zero; MAX_DEGREE + 1],
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
        while seq.len < MAX_DEGREE + 1 && seq.polys[seq.len - 1].len > 1 {
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
fn quotient(a: &Poly, b: &Poly) -> Poly {
    let mut r = *a;
    let mut q = Poly {
        c: [0.0; MAX_DEGREE + 1],
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
fn remainder(a: &Poly, b: &Poly) -> Poly {
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
    let mut p = Poly {
        c: [0.0; MAX_DEGREE + 1],
        len: coeffs.len(),
    };
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
fn isolate(
    p: &Poly,
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
        out[*n] = refine(p, count_at, a, va, b);
        *n += 1;
        return;
    }
    let m = a + 0.5 * width;
    let vm = count_at(m);
    isolate(p, count_at, a, va, m, vm, depth + 1, out, n);
    isolate(p, count_at, m, vm, b, vb, depth + 1, out, n);
}

/// The single root in `(a, b]`: bisection on the sign when the ends differ in sign,
/// otherwise (an even root) on the Sturm count.
fn refine(p: &Poly, count_at: &dyn Fn(f64) -> u32, a: f64, va: u32, b: f64) -> f64 {
    let (mut a, mut b) = (a, b);
    let mut fa = p.eval(a);
    let fb = p.eval(b);
    let sign_change = fa != 0.0 && fb != 0.0 && (fa < 0.0) != (fb < 0.0);
    for _ in 0..200 {
        let width = b - a;
        if width <= 1e-12 * (a.abs().max(b.abs()) + 1e-300) {
            break;
        }
        let m = a + 0.5 * width;
        if sign_change {
            let fm = p.eval(m);
            if fm == 0.0 {
                return m;
            }
            if (fm < 0.0) == (fa < 0.0) {
                a = m;
                fa = fm;
            } else {
                b = m;
            }
        } else if count_at(m) < va {
            b = m;
        } else {
            a = m;
        }
    }
    0.5 * (a + b)
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
