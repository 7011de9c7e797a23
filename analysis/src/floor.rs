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

#[cfg(test)]
mod tests {
    use super::*;

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
