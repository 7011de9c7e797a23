//! A floor for the hot paths of noise and patterns.

/// `x.floor()` without a call into the maths library, for the noise lattice and the tiling
/// and pavement patterns. WebAssembly has a rounding instruction; x86-64's baseline does
/// not, and there `f64::floor` is a library call. Adding 2^52 of `x`'s sign and taking it
/// away again rounds `x` to the nearest whole number, exactly (floats of that size are
/// whole, and the difference is exact): fewer instructions than a conversion to an
/// integer and back, which checks for overflow and NaN.
pub(crate) fn floor(x: f64) -> f64 {
    // From 2^52 on every float is whole; NaN goes to `f64::floor` too.
    const WHOLE_FROM: f64 = 4_503_599_627_370_496.0;
    if cfg!(target_arch = "wasm32") {
        x.floor()
    } else if x.abs() < WHOLE_FROM {
        let shift = WHOLE_FROM.copysign(x);
        // The sign keeps -0.0 as it is, and makes the nearest of a small negative `x`
        // -0.0, below which it is not.
        let nearest = ((x + shift) - shift).copysign(x);
        if nearest > x { nearest - 1.0 } else { nearest }
    } else {
        x.floor()
    }
}

/// Below 2^51 in size, `x + ROUNDER` lies in [2^52, 2^53), where floats are the whole
/// numbers: the sum is `x` rounded to a whole number, which its low bits count.
pub(crate) const ROUNDS_BELOW: f64 = 2_251_799_813_685_248.0;
pub(crate) const ROUNDER: f64 = 6_755_399_441_055_744.0;

/// [`floor`] with the floor as an integer too, for the lattices whose cells index tables
/// (the noise's, the pavement's). Natively both come from rounding additions: adding
/// 1.5 * 2^52 to a float under 2^51 in size rounds it to a whole number, and leaves that
/// number in the sum's low bits. Elsewhere, and for larger values and NaN,
/// the floor is converted as `as i64` does (saturating, NaN to 0).
#[inline(always)]
pub(crate) fn floor_whole(x: f64) -> (f64, i64) {
    if !cfg!(target_arch = "wasm32") && x.abs() < ROUNDS_BELOW {
        // Exact; the sign keeps -0.0 as it is and makes the nearest of a small negative
        // `x` -0.0, below which it is not (rounding never turns a sign but to zero).
        let nearest = ((x + ROUNDER) - ROUNDER).copysign(x);
        // A choice between two floats, which compiles to a compare and a mask: whether
        // the nearest lies above `x` is a coin toss on a noise lattice, where a branch on
        // it was mispredicted at every other coordinate.
        let floor = if nearest > x { nearest - 1.0 } else { nearest };
        // Both in one binade, where the bit patterns count whole numbers: the integer is
        // a subtraction of bit patterns instead of a conversion, which checks for
        // overflow and NaN, and needs no choice of its own.
        let whole = (floor + ROUNDER).to_bits().wrapping_sub(ROUNDER.to_bits()) as i64;
        (floor, whole)
    } else {
        let floor = floor(x);
        (floor, floor as i64)
    }
}

/// [`floor_whole`] with the integer as an `i32`, saturating as the floor's `as i32` does
/// (the pavement's cells: a small tile far out on an infinite plane lies past 2^31).
#[inline(always)]
pub(crate) fn floor_whole_i32(x: f64) -> (f64, i32) {
    let (floor, whole) = floor_whole(x);
    (floor, whole.clamp(i32::MIN.into(), i32::MAX.into()) as i32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floor_whole_i32_saturates_as_the_conversion_does() {
        for x in [
            0.5,
            -0.5,
            3e9,
            -3e9,
            2_147_483_647.5,
            -2_147_483_648.5,
            1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            assert_eq!(floor_whole_i32(x).1, x.floor() as i32, "{x}");
        }
    }

    #[test]
    fn floor_whole_is_the_floor_and_its_integer() {
        let mut values = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            2.5,
            -2.5,
            1e-300,
            -1e-300,
            2_251_799_813_685_247.5,
            -2_251_799_813_685_247.5,
            2_251_799_813_685_248.0,
            -2_251_799_813_685_248.0,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        let mut x: f64 = 1e-3;
        while x < 1e17 {
            for y in [x, x.next_up(), x.next_down(), x.round() + 0.5] {
                values.extend([y, -y]);
            }
            x *= 1.37;
        }
        for v in values {
            let (f, whole) = floor_whole(v);
            assert_eq!(f.to_bits(), v.floor().to_bits(), "{v}");
            assert_eq!(whole, v.floor() as i64, "{v}");
        }
    }

    #[test]
    fn floor_is_f64_floor() {
        let whole = 4_503_599_627_370_496.0;
        for x in [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            2.75,
            -2.75,
            1e-300,
            -1e-300,
            1e15 + 0.5,
            -1e15 - 0.5,
            whole - 0.5,
            -whole + 0.5,
            whole,
            -whole,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ] {
            assert_eq!(floor(x).to_bits(), x.floor().to_bits(), "{x}");
        }
        assert!(floor(f64::NAN).is_nan());
        // Halves (where rounding to the nearest goes either way), their neighbours, and
        // values of every size, of both signs.
        let mut x: f64 = 1e-3;
        while x < 1e17 {
            for y in [x, x.next_up(), x.next_down(), x.round() + 0.5] {
                for v in [y, -y] {
                    assert_eq!(floor(v).to_bits(), v.floor().to_bits(), "{v}");
                }
            }
            x *= 1.37;
        }
    }
}
