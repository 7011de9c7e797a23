//! Sine and cosine for inner loops, faster than the standard library's where that matters:
//! in WebAssembly the standard `sin` and `cos` are software routines run by an
//! interpreter, and isosurfaces, polynomial solvers and wave patterns call them millions of
//! times.

use std::f64::consts::FRAC_2_PI;

/// π/2 in three parts, the first two short enough that k·part is exact for |k| < 2¹⁶.
const PIO2_HIGH: f64 = 1.570_796_326_734_125_6;
const PIO2_MID: f64 = 6.077_100_506_506_192e-11;
const PIO2_LOW: f64 = 2.022_266_248_795_950_6e-21;

/// The largest argument reduced here; beyond it the standard functions take over.
const REDUCTION_LIMIT: f64 = 1.0e5;

/// Whether `x` is within the reduction's limit: one comparison that NaN fails too, where a
/// test for NaN and one of the size were two.
#[inline(always)]
fn reducible(x: f64) -> bool {
    x.abs() <= REDUCTION_LIMIT
}

/// sin(x) and cos(x), within a few units in the last place, sharing one range reduction.
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    if !reducible(x) {
        return (x.sin(), x.cos());
    }
    let (quarter, r) = reduce(x);
    let (s, c) = (sine_series(r), cosine_series(r));
    match quarter {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// sin(x) alone, the very value [`sin_cos`] gives, for half the series.
#[inline]
pub fn sin(x: f64) -> f64 {
    if !reducible(x) {
        return x.sin();
    }
    let (quarter, r) = reduce(x);
    let value = if quarter & 1 == 0 {
        sine_series(r)
    } else {
        cosine_series(r)
    };
    if quarter & 2 == 0 { value } else { -value }
}

/// The nearest quarter turn to `x` (modulo 4) and the remainder beyond it. `floor` is one
/// WebAssembly instruction where `f64::round` takes several. Halves may go either way:
/// the remainder stays within π/4, give or take an ulp, where the series are as accurate.
#[inline(always)]
fn reduce(x: f64) -> (i64, f64) {
    let k = (x * FRAC_2_PI + 0.5).floor();
    let r = ((x - k * PIO2_HIGH) - k * PIO2_MID) - k * PIO2_LOW;
    ((k as i64) & 3, r)
}

/// Taylor series to the 15th power: on |r| <= π/4 the first omitted term is below 1e-16
/// of the result.
#[inline(always)]
fn sine_series(r: f64) -> f64 {
    let r2 = r * r;
    r * (1.0
        + r2 * (-1.0 / 6.0
            + r2 * (1.0 / 120.0
                + r2 * (-1.0 / 5040.0
                    + r2 * (1.0 / 362_880.0
                        + r2 * (-1.0 / 39_916_800.0
                            + r2 * (1.0 / 6_227_020_800.0 + r2 * (-1.0 / 1_307_674_368_000.0))))))))
}

/// Taylor series to the 16th power, as accurate as [`sine_series`].
#[inline(always)]
fn cosine_series(r: f64) -> f64 {
    let r2 = r * r;
    1.0 + r2
        * (-0.5
            + r2 * (1.0 / 24.0
                + r2 * (-1.0 / 720.0
                    + r2 * (1.0 / 40_320.0
                        + r2 * (-1.0 / 3_628_800.0
                            + r2 * (1.0 / 479_001_600.0
                                + r2 * (-1.0 / 87_178_291_200.0
                                    + r2 * (1.0 / 20_922_789_888_000.0))))))))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sin_cos_match_the_standard_library() {
        let mut worst: f64 = 0.0;
        let mut x = -2000.0;
        while x < 2000.0 {
            let (s, c) = sin_cos(x);
            worst = worst.max((s - x.sin()).abs()).max((c - x.cos()).abs());
            x += 0.0137;
        }
        assert!(worst < 1e-13, "worst error {worst}");
        for x in [0.0, -0.0, 1e-300, 3e5, -1e9, f64::MAX] {
            let (s, c) = sin_cos(x);
            assert!(
                (s - x.sin()).abs() < 1e-12 && (c - x.cos()).abs() < 1e-12,
                "{x}"
            );
        }
        let mut x = -300.0;
        while x < 300.0 {
            assert_eq!(sin(x), sin_cos(x).0, "{x}");
            x += 0.0731;
        }
        assert_eq!(sin(4e5), 4e5f64.sin());
        let (s, c) = sin_cos(f64::NAN);
        assert!(s.is_nan() && c.is_nan());
        let (s, c) = sin_cos(f64::INFINITY);
        assert!(s.is_nan() && c.is_nan());
    }
}
