//! Elementary functions the shapes call in their inner loops, faster than the standard
//! library's where that matters (sine and cosine are `analysis::trig`'s). Even
//! `f64::min`, `f64::max` and `f64::round` are calls to libm there (WebAssembly's own
//! `min`, `max` and `nearest` treat NaN and halves differently), and a call costs the
//! interpreter far more than the comparison it wraps; `min`, `max` and `round` below give
//! the same results without one.

/// The smaller of `x` and `y`, or the one that is not NaN: `f64::min` as it is compiled
/// natively, to the bit (of two equal zeros, `x`).
#[inline]
pub fn min(x: f64, y: f64) -> f64 {
    if x.is_nan() || y < x { y } else { x }
}

/// The larger of `x` and `y`, or the one that is not NaN: `f64::max` as it is compiled
/// natively, to the bit.
#[inline]
pub fn max(x: f64, y: f64) -> f64 {
    if x.is_nan() || y > x { y } else { x }
}

/// `x` rounded to the nearest integer, halves away from zero: `f64::round` to the bit.
/// `trunc` and `copysign` are single instructions in WebAssembly, and the fraction
/// `x - trunc(x)` is exact.
#[inline]
pub fn round(x: f64) -> f64 {
    let whole = x.trunc();
    if (x - whole).abs() >= 0.5 {
        whole + 1f64.copysign(x)
    } else {
        whole
    }
}

mod ln_table;

/// ln 2 in two parts, the first with its low bits zero, so that k times it is exact for
/// the exponents of floats.
const LN_2_HI: f64 = 6.931_471_803_691_238e-1;
const LN_2_LO: f64 = 1.908_214_929_270_587_7e-10;

/// The natural logarithm of `x`, within an ulp or two. With x = m·2^e, m between √½ and
/// √2, f = m - 1 and s = f/(2 + f) (|s| < 0.172): ln m = 2 atanh s = 2s + s·R,
/// R = 2s²/3 + 2s⁴/5 + …, summed as f - f²/2 + s(f²/2 + R) so that its large part f is
/// exact; R's terms up to s¹⁸ reach the last bit. ln 2 is split in two so that e times
/// its first part is exact. Inlined by force, as [`series_pow`] is, so that the powers
/// [`pow_inlined`] takes need no call.
#[inline(always)]
pub fn series_ln(x: f64) -> f64 {
    if !(x.is_normal() && x > 0.0) {
        return x.ln();
    }
    normal_series_ln(x)
}

/// The natural logarithm of `x`, finite and at least 1, which the caller knows it to be:
/// in WebAssembly by a table and a short polynomial ([`ln_table::ln_at_least_one`]),
/// inlined, where the standard one is a call into a software routine (julia_fractal's
/// march takes one per step); natively the standard one, which there is the faster.
#[inline]
pub fn ln_at_least_one(x: f64) -> f64 {
    if cfg!(target_arch = "wasm32") {
        ln_table::ln_at_least_one(x)
    } else {
        x.ln()
    }
}

/// [`series_ln`] of a positive normal `x`.
#[inline]
fn normal_series_ln(x: f64) -> f64 {
    let bits = x.to_bits();
    let mut e = (bits >> 52) as i64 - 1023;
    let mut m = f64::from_bits((bits & ((1 << 52) - 1)) | (1023 << 52));
    if m > std::f64::consts::SQRT_2 {
        m *= 0.5;
        e += 1;
    }
    let f = m - 1.0;
    let s = f / (2.0 + f);
    let z = s * s;
    // R by Estrin's scheme, in pairs of terms that the powers z², z⁴ and z⁸ join: short
    // chains of dependent operations, which an interpreter runs much faster than Horner's
    // one long chain. R is a correction below 2 % of ln m, so its order of summing
    // seldom shows in the result: in its last bit, for about one value in 2000.
    let (z2, t) = (z * z, |a: f64, b: f64| a + z * b);
    let z4 = z2 * z2;
    let low = t(2.0 / 3.0, 2.0 / 5.0) + z2 * t(2.0 / 7.0, 2.0 / 9.0);
    let high = t(2.0 / 11.0, 2.0 / 13.0) + z2 * t(2.0 / 15.0, 2.0 / 17.0);
    let r = z * ((low + z4 * high) + (z4 * z4) * (2.0 / 19.0));
    let half_f2 = 0.5 * f * f;
    let e = e as f64;
    e * LN_2_HI - ((half_f2 - (s * (half_f2 + r) + e * LN_2_LO)) - f)
}

/// The cube root of `x`, within an ulp or two: the standard one is correctly rounded,
/// which in WebAssembly costs a software fused multiply-add. A first guess from the
/// exponent bits (a third of them), good to a digit, is refined by three Halley steps,
/// each of which triples the number of correct digits.
#[inline]
pub fn cbrt(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return x;
    }
    let a = x.abs();
    if !a.is_normal() {
        return x.cbrt();
    }
    // The bits of a float are roughly a scaled, shifted logarithm of it: a third of the
    // exponent's distance from the bias gives the cube root to within about 10 %.
    const BIAS: i64 = 1023 << 52;
    let bits = a.to_bits() as i64;
    let mut y = f64::from_bits(((bits - BIAS) / 3 + BIAS) as u64);
    for _ in 0..3 {
        let y3 = y * y * y;
        y *= (y3 + 2.0 * a) / (2.0 * y3 + a);
    }
    y.copysign(x)
}

/// `x` to the power `e`: by repeated squaring when `e` is a whole number from 0 to 256,
/// as phong_size mostly is, within a few ulp of `powf`; otherwise, in WebAssembly,
/// [`series_pow`], inlined (a specular highlight's exponent 1/roughness is seldom whole);
/// natively the standard one, which there is the faster. In WebAssembly `powf` is a long
/// software routine, and highlights call it for every light at every hit.
#[inline]
pub fn pow(x: f64, e: f64) -> f64 {
    pow_inlined(x, e)
}

/// [`pow`] inlined by force, for a caller's one hot power among others: a specular
/// highlight's, which water and glass surfaces take at every hit.
#[inline(always)]
pub fn pow_inlined(x: f64, e: f64) -> f64 {
    if e.trunc() == e && (0.0..=256.0).contains(&e) {
        powi(x, e as u32)
    } else {
        any_pow(x, e)
    }
}

/// `x` to the power `e`, whole or not: in WebAssembly [`series_pow`], inlined, where
/// `powf` is a long software routine (309 wasm instructions a call); natively `powf`,
/// which there is the faster.
#[inline(always)]
pub fn any_pow(x: f64, e: f64) -> f64 {
    if cfg!(target_arch = "wasm32") {
        series_pow(x, e)
    } else {
        x.powf(e)
    }
}

/// `x` to the power `e` as exp(e ln x), by [`series_ln`] and [`series_exp`]: within
/// (|e ln x| + 2) ulp of `powf`, the error of ln x growing with the exponent. Where the
/// result would be near or beyond the range of floats, or is not a real number, the
/// standard one answers.
#[inline(always)]
pub fn series_pow(x: f64, e: f64) -> f64 {
    let y = e * series_ln(x);
    if y.abs() < 700.0 {
        series_exp(y)
    } else {
        x.powf(e)
    }
}

/// 1/n! for n from 0 to 13: the Taylor coefficients of e^r.
const INVERSE_FACTORIALS: [f64; 14] = [
    1.0,
    1.0,
    1.0 / 2.0,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5040.0,
    1.0 / 40_320.0,
    1.0 / 362_880.0,
    1.0 / 3_628_800.0,
    1.0 / 39_916_800.0,
    1.0 / 479_001_600.0,
    1.0 / 6_227_020_800.0,
];

/// e^y for |y| < 700, within an ulp or two: y = k ln 2 + r with |r| <= ln 2 / 2, ln 2 in
/// [`series_ln`]'s two parts so that r is exact to the last bits, then e^r by its Taylor
/// series to the 13th power (the first omitted term is below 1e-17 of it) and 2^k put in
/// the exponent bits.
#[inline(always)]
fn series_exp(y: f64) -> f64 {
    let k = (y * std::f64::consts::LOG2_E + 0.5).floor();
    let r = (y - k * LN_2_HI) - k * LN_2_LO;
    // Horner's rule from the highest power down.
    let mut series = INVERSE_FACTORIALS[13];
    for c in INVERSE_FACTORIALS[..13].iter().rev() {
        series = series * r + c;
    }
    series * f64::from_bits(((k as i64 + 1023) as u64) << 52)
}

/// `x.powi(n)`, inlined: the library's repeated squaring, whose multiplications this
/// makes in the same order, so that the result is the same to the bit; in WebAssembly
/// `powi` is a call, made for every highlight.
#[inline]
fn powi(mut x: f64, mut n: u32) -> f64 {
    let mut r = 1.0;
    loop {
        if n & 1 != 0 {
            r *= x;
        }
        n >>= 1;
        if n == 0 {
            return r;
        }
        x *= x;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn min_max_and_round_match_the_standard_library() {
        let values = [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.5,
            2.5,
            -2.5,
            0.499_999_999_999_999_94,
            4_503_599_627_370_495.5,
            9.007_199_254_740_993e15,
            1e300,
            f64::MIN_POSITIVE,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            3.7,
            -3.7,
        ];
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
        for &x in &values {
            assert!(same(round(x), x.round()), "round({x})");
            for &y in &values {
                assert!(same(min(x, y), x.min(y)), "min({x}, {y})");
                assert!(same(max(x, y), x.max(y)), "max({x}, {y})");
            }
        }
    }

    #[test]
    fn pow_matches_the_standard_library() {
        for x in [0.0f64, 1e-3, 0.31, 0.5, 0.999_999, 1.0, 1.7] {
            for e in [0.0, 1.0, 2.0, 25.0, 40.0, 50.0, 83.333, 256.0, 300.0, 0.5] {
                let (want, got) = (x.powf(e), pow(x, e));
                assert!((want - got).abs() <= 1e-13 * want, "{x}^{e}: {want} {got}");
            }
        }
        assert!(pow(f64::NAN, 2.0).is_nan());
    }

    #[test]
    fn series_pow_matches_the_standard_library() {
        let mut x: f64 = 1e-12;
        while x < 1e6 {
            for v in [x, x * 1.414, 1.0 - x.min(0.5), 1.0 + x.min(1e-3)] {
                for e in [
                    83.333_333_333_333_33,
                    0.5,
                    1.0 / 0.035,
                    2.2,
                    -1.7,
                    300.5,
                    1e-3,
                ] {
                    let (got, want) = (series_pow(v, e), v.powf(e));
                    let y = (e * v.ln()).abs();
                    assert!(
                        got == want || (got - want).abs() <= (y + 2.0) * f64::EPSILON * want,
                        "{v}^{e}: {got} {want}"
                    );
                }
            }
            x *= 1.37;
        }
        for (v, e) in [
            (0.0, 83.3),
            (0.0, -0.5),
            (-0.5, 83.3),
            (1.0, 83.3),
            (1e-300, 83.3),
        ] {
            let (got, want) = (series_pow(v, e), v.powf(e));
            assert!(got == want || (got.is_nan() && want.is_nan()), "{v}^{e}");
        }
        assert!(series_pow(f64::NAN, 83.3).is_nan() && series_pow(0.5, f64::NAN).is_nan());
        assert_eq!(series_pow(f64::INFINITY, 0.5), f64::INFINITY);
    }

    #[test]
    fn powi_is_the_library_s_to_the_bit() {
        for x in [
            0.0f64,
            -0.0,
            1e-3,
            0.31,
            0.5,
            0.999_999,
            1.0,
            1.7,
            -2.3,
            f64::NAN,
        ] {
            for n in 0..=256 {
                let (want, got) = (x.powi(n as i32), powi(x, n));
                assert!(
                    want.to_bits() == got.to_bits() || (want.is_nan() && got.is_nan()),
                    "{x}^{n}: {want} {got}"
                );
            }
        }
    }

    #[test]
    fn series_ln_matches_the_standard_library() {
        let mut x: f64 = 1e-300;
        while x < 1e300 {
            for v in [
                x,
                x * 1.37,
                x * 1.414,
                x * 1.415,
                x * 2.9,
                1.0 + x.min(1e-3),
            ] {
                let (got, want) = (series_ln(v), v.ln());
                assert!(
                    (got - want).abs() <= 2.0 * f64::EPSILON * want.abs().max(1e-300),
                    "{v}: {got} {want}"
                );
            }
            x *= 1.73;
        }
        assert_eq!(series_ln(1.0), 0.0);
        assert_eq!(series_ln(0.0), f64::NEG_INFINITY);
        assert!(series_ln(-1.0).is_nan() && series_ln(f64::NAN).is_nan());
        assert_eq!(series_ln(f64::INFINITY), f64::INFINITY);
        assert_eq!(series_ln(5e-320), 5e-320f64.ln());
    }

    #[test]
    fn cbrt_matches_the_standard_library() {
        let mut x = 1e-300;
        while x < 1e300 {
            for v in [x, -x, x * 1.37, x * 2.9] {
                let (got, want) = (cbrt(v), v.cbrt());
                assert!((got - want).abs() <= 4.0 * f64::EPSILON * want.abs(), "{v}");
            }
            x *= 7.3;
        }
        for v in [
            0.0,
            -0.0,
            f64::INFINITY,
            f64::NEG_INFINITY,
            5e-320,
            27.0,
            -8.0,
        ] {
            assert_eq!(cbrt(v), v.cbrt(), "{v}");
        }
        assert!(cbrt(f64::NAN).is_nan());
    }
}
