//! Real roots of polynomials inside an interval, for the shapes whose surfaces are
//! algebraic (torus, later cubic, quartic and poly). The roots are isolated with a Sturm
//! sequence, which counts the distinct real roots in any interval, and then refined by
//! bisection safeguarded regula falsi. Coefficients are given lowest degree first.

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
        self.coeffs().iter().fold(0.0f64, |m, c| m.max(c.abs()))
    }

    /// Drops leading coefficients at or below `tolerance`.
    fn trim(&mut self, tolerance: f64) {
        while self.len > 0 && self.c[self.len - 1].abs() <= tolerance {
            self.len -= 1;
        }
    }

    fn derivative(&self) -> Poly {
        let mut d = Poly::ZERO;
        for i in 1..self.len {
            d.c[i - 1] = self.c[i] * i as f64;
        }
        d.len = self.len.saturating_sub(1);
        d
    }

    /// The negated remainder of `self / b`, the next member of a Sturm chain.
    fn negated_remainder(&self, b: &Poly) -> Poly {
        let mut r = *self;
        let lead = b.c[b.len - 1];
        while r.len >= b.len {
            let factor = r.c[r.len - 1] / lead;
            let shift = r.len - b.len;
            for i in 0..b.len {
                r.c[shift + i] -= factor * b.c[i];
            }
            r.len -= 1;
        }
        // Coefficients that are rounding noise relative to the dividend are zero.
        r.trim(1e-14 * self.scale());
        for c in &mut r.c[..r.len] {
            *c = -*c;
        }
        r
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
    if p.len < 2 {
        return;
    }
    let mut chain = [Poly::ZERO; MAX_DEGREE + 1];
    chain[0] = p;
    chain[1] = p.derivative();
    let mut n = 2;
    while n < chain.len() && chain[n - 1].len > 1 {
        let r = chain[n - 2].negated_remainder(&chain[n - 1]);
        if r.len == 0 {
            break;
        }
        chain[n] = r;
        n += 1;
    }
    let chain = &chain[..n];
    let count = |x: f64| sign_changes(chain, x);
    isolate(&p, &count, lo, hi, count(lo), count(hi), 0, out);
}

fn sign_changes(chain: &[Poly], x: f64) -> usize {
    let mut changes = 0;
    let mut last = 0.0;
    for q in chain {
        let v = q.eval(x);
        if v != 0.0 {
            if last != 0.0 && (v < 0.0) != (last < 0.0) {
                changes += 1;
            }
            last = v;
        }
    }
    changes
}

#[allow(clippy::too_many_arguments)]
fn isolate(
    p: &Poly,
    count: &dyn Fn(f64) -> usize,
    lo: f64,
    hi: f64,
    c_lo: usize,
    c_hi: usize,
    depth: u32,
    out: &mut Vec<f64>,
) {
    let n = c_lo.saturating_sub(c_hi);
    if n == 0 {
        return;
    }
    if n == 1 || depth > 60 || hi - lo <= 1e-15 * (lo.abs() + hi.abs()) {
        if let Some(root) = refine(p, lo, hi) {
            out.push(root);
        } else if n > 1 || depth > 60 {
            // A cluster of roots too close to tell apart: one crossing stands for them.
            out.push(0.5 * (lo + hi));
        }
        return;
    }
    let mid = 0.5 * (lo + hi);
    let c_mid = count(mid);
    isolate(p, count, lo, mid, c_lo, c_mid, depth + 1, out);
    isolate(p, count, mid, hi, c_mid, c_hi, depth + 1, out);
}

/// The root of `p` in `[lo, hi]` when `p` changes sign there.
fn refine(p: &Poly, mut lo: f64, mut hi: f64) -> Option<f64> {
    let mut f_lo = p.eval(lo);
    let mut f_hi = p.eval(hi);
    if f_lo == 0.0 {
        return Some(lo);
    }
    if f_hi == 0.0 {
        return Some(hi);
    }
    if (f_lo < 0.0) == (f_hi < 0.0) {
        return None;
    }
    let mut side = 0;
    for _ in 0..100 {
        // Regula falsi with the Illinois correction, falling back to bisection when the
        // secant leaves the bracket.
        let mut x = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if !(x > lo && x < hi) {
            x = 0.5 * (lo + hi);
        }
        let f = p.eval(x);
        if f == 0.0 || hi - lo <= 1e-14 * (lo.abs() + hi.abs()) {
            return Some(x);
        }
        if (f < 0.0) == (f_lo < 0.0) {
            lo = x;
            f_lo = f;
            if side == -1 {
                f_hi *= 0.5;
            }
            side = -1;
        } else {
            hi = x;
            f_hi = f;
            if side == 1 {
                f_lo *= 0.5;
            }
            side = 1;
        }
    }
    Some(0.5 * (lo + hi))
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
