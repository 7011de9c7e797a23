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

/// sin(x) and cos(x), within a few units in the last place, sharing one range reduction.
#[inline]
pub fn sin_cos(x: f64) -> (f64, f64) {
    if x.is_nan() || x.abs() > REDUCTION_LIMIT {
        return (x.sin(), x.cos());
    }
    // The nearest quarter turn; `floor` is one WebAssembly instruction where `f64::round`
    // takes several. Halves may go either way: the remainder stays within π/4,
    // give or take an ulp, where the series below is as accurate.
    let k = (x * FRAC_2_PI + 0.5).floor();
    let r = ((x - k * PIO2_HIGH) - k * PIO2_MID) - k * PIO2_LOW;
    let r2 = r * r;
    // Taylor series to the 15th and 16th powers: on |r| <= π/4 the first omitted terms are
    // below 1e-16 of the result.
    let s = r
        * (1.0
            + r2 * (-1.0 / 6.0
                + r2 * (1.0 / 120.0
                    + r2 * (-1.0 / 5040.0
                        + r2 * (1.0 / 362_880.0
                            + r2 * (-1.0 / 39_916_800.0
                                + r2 * (1.0 / 6_227_020_800.0
                                    + r2 * (-1.0 / 1_307_674_368_000.0))))))));
    let c = 1.0
        + r2 * (-0.5
            + r2 * (1.0 / 24.0
                + r2 * (-1.0 / 720.0
                    + r2 * (1.0 / 40_320.0
                        + r2 * (-1.0 / 3_628_800.0
                            + r2 * (1.0 / 479_001_600.0
                                + r2 * (-1.0 / 87_178_291_200.0
                                    + r2 * (1.0 / 20_922_789_888_000.0))))))));
    match (k as i64) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
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
        let (s, c) = sin_cos(f64::NAN);
        assert!(s.is_nan() && c.is_nan());
        let (s, c) = sin_cos(f64::INFINITY);
        assert!(s.is_nan() && c.is_nan());
    }
}
