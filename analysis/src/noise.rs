//! Solid noise for the noise-based patterns: gradient (Perlin) noise on the integer lattice
//! with a fixed permutation, scaled to 0..1 around 0.5 as POV-Ray's noise is, and the
//! turbulence sums built from it. The values are not POV-Ray's bit for bit; they share its
//! range, mean and spatial frequency (one feature per unit), which the fidelity tests
//! check statistically.

use glam::DVec3;
use std::ops::{Add, Mul, Sub};

/// A fixed permutation of 0..256, repeated, generated at compile time by a small linear
/// congruential shuffle so that the noise is the same on every platform and run, and a
/// lookup costs no initialisation check.
static PERMUTATION: [u8; 512] = permutation();

const fn permutation() -> [u8; 512] {
    let mut p = [0u8; 256];
    let mut i = 0;
    while i < 256 {
        p[i] = i as u8;
        i += 1;
    }
    let mut state: u32 = 0x2545_f491;
    let mut i = 255;
    while i > 0 {
        state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        let j = (state >> 8) as usize % (i + 1);
        let swapped = p[i];
        p[i] = p[j];
        p[j] = swapped;
        i -= 1;
    }
    let mut doubled = [0u8; 512];
    let mut i = 0;
    while i < 512 {
        doubled[i] = p[i & 255];
        i += 1;
    }
    doubled
}

fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

/// The gradient of each hash's low four bits: the twelve edge directions of a cube, four of
/// them twice, as in improved noise. A table lookup and a dot product instead of a chain
/// of branches; the zero components add exact zeros, so the values are those of the
/// branching form.
const GRADIENTS: [[f64; 3]; 16] = [
    [1.0, 1.0, 0.0],
    [-1.0, 1.0, 0.0],
    [1.0, -1.0, 0.0],
    [-1.0, -1.0, 0.0],
    [1.0, 0.0, 1.0],
    [-1.0, 0.0, 1.0],
    [1.0, 0.0, -1.0],
    [-1.0, 0.0, -1.0],
    [0.0, 1.0, 1.0],
    [0.0, -1.0, 1.0],
    [0.0, 1.0, -1.0],
    [0.0, -1.0, -1.0],
    [1.0, 1.0, 0.0],
    [0.0, -1.0, 1.0],
    [-1.0, 1.0, 0.0],
    [0.0, -1.0, -1.0],
];

fn dot([gx, gy, gz]: [f64; 3], x: f64, y: f64, z: f64) -> f64 {
    gx * x + gy * y + gz * z
}

/// The gradient that the hash at each index of [`PERMUTATION`] selects: a corner's
/// gradient is one lookup from its index instead of two.
static GRADIENT_AT: [[f64; 3]; 512] = gradient_at();

const fn gradient_at() -> [[f64; 3]; 512] {
    let mut table = [[0.0; 3]; 512];
    let mut i = 0;
    while i < 512 {
        table[i] = GRADIENTS[PERMUTATION[i] as usize & 15];
        i += 1;
    }
    table
}

/// `x.floor()` without a call into the maths library (x86-64's baseline has no rounding
/// instruction): truncation corrected downwards. Beyond 2^52 every float is an integer.
/// WebAssembly has the instruction itself.
fn lattice_floor(x: f64) -> f64 {
    if cfg!(target_arch = "wasm32") {
        x.floor()
    } else if x.abs() < 4.0e15 {
        let t = x as i64 as f64;
        if t > x { t - 1.0 } else { t }
    } else {
        x.floor()
    }
}

/// How near 0 or 1 the fade weight across y must be for [`blend_cell`] to blend one side's
/// corners alone.
const ONE_SIDED: f64 = 1e-12;

/// Signed gradient noise, roughly in -1..1, zero at lattice points.
pub fn signed(p: DVec3) -> f64 {
    // A coordinate that is not finite makes the fractions, and with them the blend, NaN:
    // one test of the result instead of one per coordinate.
    let value = blend_cell(p, |i, x, y, z| dot(GRADIENT_AT[i], x, y, z));
    if value.is_nan() { 0.0 } else { value }
}

/// Gradient noise at `p` from the values `corner(index, offset)` of the corners of its
/// lattice cell, given each corner's index into the gradient tables (at most 511) and the
/// offset of `p` from it: the corners' values blended by the fade weights of the offset.
/// One blend serves one noise ([`signed`]) and three sharing their hashes ([`vector`]).
#[inline(always)]
fn blend_cell<T>(p: DVec3, corner: impl Fn(usize, f64, f64, f64) -> T) -> T
where
    T: Copy + Add<Output = T> + Sub<Output = T> + Mul<f64, Output = T>,
{
    // Every index below is at most 511 (a table entry plus a cell coordinate, plus one):
    // the mask changes none of them and spares a bounds check at each lookup.
    let perm = |i: usize| usize::from(PERMUTATION[i & 511]);
    let corner = |i: usize, x, y, z| corner(i & 511, x, y, z);
    let f = DVec3::new(lattice_floor(p.x), lattice_floor(p.y), lattice_floor(p.z));
    let (xi, yi, zi) = (
        // The cell's coordinates modulo 256 (two's complement wraps negatives as
        // rem_euclid does), without a floating-point remainder.
        (f.x as i64 & 255) as usize,
        (f.y as i64 & 255) as usize,
        (f.z as i64 & 255) as usize,
    );
    let (x, y, z) = (p.x - f.x, p.y - f.y, p.z - f.z);
    let (u, v, w) = (fade(x), fade(y), fade(z));
    let lerp = |t: f64, a: T, b: T| a + (b - a) * t;
    let (a, b) = (perm(xi) + yi, perm(xi + 1) + yi);
    // On a lattice plane across y (a floor at y = 0, a pattern scaled about it) the
    // corners of one side carry all the weight but for a share below 1e-12 of the
    // difference, which no picture shows: only their square is blended.
    if v <= ONE_SIDED || v >= 1.0 - ONE_SIDED {
        let (j, y) = if v <= ONE_SIDED { (0, y) } else { (1, y - 1.0) };
        let (low, high) = (perm(a + j) + zi, perm(b + j) + zi);
        return lerp(
            w,
            lerp(u, corner(low, x, y, z), corner(high, x - 1.0, y, z)),
            lerp(
                u,
                corner(low + 1, x, y, z - 1.0),
                corner(high + 1, x - 1.0, y, z - 1.0),
            ),
        );
    }
    let (aa, ab) = (perm(a) + zi, perm(a + 1) + zi);
    let (ba, bb) = (perm(b) + zi, perm(b + 1) + zi);
    lerp(
        w,
        lerp(
            v,
            lerp(u, corner(aa, x, y, z), corner(ba, x - 1.0, y, z)),
            lerp(
                u,
                corner(ab, x, y - 1.0, z),
                corner(bb, x - 1.0, y - 1.0, z),
            ),
        ),
        lerp(
            v,
            lerp(
                u,
                corner(aa + 1, x, y, z - 1.0),
                corner(ba + 1, x - 1.0, y, z - 1.0),
            ),
            lerp(
                u,
                corner(ab + 1, x, y - 1.0, z - 1.0),
                corner(bb + 1, x - 1.0, y - 1.0, z - 1.0),
            ),
        ),
    )
}

/// POV-Ray's `Noise`: 0..1 with mean 0.5.
pub fn noise(p: DVec3) -> f64 {
    // Measured against POV-Ray's bozo on a plane: its features are about 1.3 times wider
    // and its values spread about as far as plain gradient noise's.
    (0.5 + 0.51 * signed(p * 0.76)).clamp(0.0, 1.0)
}

/// A vector of three decorrelated signed noises, for turbulence displacements: three
/// gradient noises on one lattice, sharing the cell, the fade weights and the corners'
/// hashes, each with a gradient of its own at every corner (see [`VECTOR_GRADIENTS_AT`]).
/// The first is [`signed`] itself. One cell's work, not three, for three values.
pub fn vector(p: DVec3) -> DVec3 {
    let value = blend_cell(p, |i, x, y, z| {
        let [gx, gy, gz] = VECTOR_GRADIENTS_AT[i];
        gx * x + gy * y + gz * z
    });
    if value.is_nan() { DVec3::ZERO } else { value }
}

/// For each index of [`PERMUTATION`], the gradients of the three components of
/// [`vector`] by axis: entry `a` holds the three gradients' components along axis `a`, so
/// that a corner's three values are three products of a vector and an offset. The first
/// gradient is the hash's (that of [`signed`]), the others those of the hash of the hash
/// with some of its bits flipped. Neighbouring corners along z have neighbouring indices,
/// so the 256 hashes' gradients leave the components correlated by some 0.02 to 0.07,
/// depending on the flips; these flips gave the least (0.02 over 200 000 points, against
/// 0.005 for three noises at points apart).
static VECTOR_GRADIENTS_AT: [[DVec3; 3]; 512] = vector_gradients_at();

const fn vector_gradients_at() -> [[DVec3; 3]; 512] {
    let mut table = [[DVec3::ZERO; 3]; 512];
    let mut i = 0;
    while i < 512 {
        let hash = PERMUTATION[i] as usize;
        let first = GRADIENTS[hash & 15];
        let second = GRADIENTS[PERMUTATION[hash ^ 0x2e] as usize & 15];
        let third = GRADIENTS[PERMUTATION[hash ^ 0x7f] as usize & 15];
        let mut axis = 0;
        while axis < 3 {
            table[i][axis] = DVec3::new(first[axis], second[axis], third[axis]);
            axis += 1;
        }
        i += 1;
    }
    table
}

/// The classic turbulence displacement: octaves of vector noise, each `lambda` times finer
/// and `omega` times weaker than the last.
pub fn turbulence(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> DVec3 {
    let mut sum = DVec3::ZERO;
    let (mut scale, mut amplitude) = (1.0, 1.0);
    for _ in 0..octaves.max(1) {
        sum += vector(p * scale) * amplitude;
        scale *= lambda;
        amplitude *= omega;
    }
    sum
}

/// Scalar turbulence: octaves of |noise| as the granite-like patterns sum them.
pub fn scalar_turbulence(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> f64 {
    let mut sum = 0.0;
    let (mut scale, mut amplitude) = (1.0, 1.0);
    for _ in 0..octaves.max(1) {
        sum += signed(p * scale).abs() * amplitude;
        scale *= lambda;
        amplitude *= omega;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Improved noise's gradient selection as branches: the hash picks two of the
    /// coordinates and their signs.
    fn branching_grad(hash: u8, x: f64, y: f64, z: f64) -> f64 {
        let h = hash & 15;
        let u = if h < 8 { x } else { y };
        let v = if h < 4 {
            y
        } else if h == 12 || h == 14 {
            x
        } else {
            z
        };
        (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
    }

    #[test]
    fn signed_noise_keeps_its_values() {
        // The exact values of the lattice noise, pinned so that a faster implementation
        // keeps every picture that uses it unchanged (cells in all octants, far from the
        // origin, across the 256-cell wrap and beyond 2^52).
        let at = |x, y, z| signed(DVec3::new(x, y, z));
        assert_eq!(at(0.3, 0.7, 0.1), 0.04154071107916779);
        assert_eq!(at(-12.25, 3.5, 100.75), 0.25498151779174805);
        assert_eq!(at(1000.123, -0.001, -77.7), 0.00471858620741164);
        assert_eq!(at(255.5, 256.5, -256.5), 0.25);
        assert_eq!(at(-0.5, 1e17, -3.0), 0.0);
        assert_eq!(at(f64::NAN, 0.0, 0.0), 0.0);
    }

    #[test]
    fn points_on_a_lattice_plane_blend_one_side() {
        // Just above, on and just below the plane y = 0: the first two blend only the
        // corners at y = 0, the last only those at y = 0 of the cell below, and all agree.
        for i in 0..200 {
            let (x, z) = (i as f64 * 0.377 - 31.0, i as f64 * 0.191 + 4.0);
            let on = vector(DVec3::new(x, 0.0, z));
            for y in [1e-17, -1e-17] {
                let near = vector(DVec3::new(x, y, z));
                assert!((near - on).abs().max_element() < 1e-11, "{near} {on}");
            }
        }
    }

    #[test]
    fn the_table_is_a_permutation_twice() {
        let mut first = PERMUTATION[..256].to_vec();
        assert_eq!(&PERMUTATION[256..], &first[..]);
        first.sort_unstable();
        assert!(first.iter().enumerate().all(|(i, &p)| usize::from(p) == i));
    }

    #[test]
    fn the_gradient_table_is_improved_noise_selection() {
        let (x, y, z) = (0.3291, -0.727, 0.5521);
        for (i, &hash) in PERMUTATION.iter().enumerate() {
            assert_eq!(
                dot(GRADIENT_AT[i], x, y, z),
                branching_grad(hash, x, y, z),
                "{i}"
            );
        }
    }

    #[test]
    fn noise_has_povray_range_and_mean() {
        let mut sum = 0.0;
        let n = 20_000;
        for i in 0..n {
            let p = DVec3::new(
                i as f64 * 0.173,
                (i % 97) as f64 * 0.311,
                (i % 13) as f64 * 0.71,
            );
            let v = noise(p);
            assert!((0.0..=1.0).contains(&v));
            sum += v;
        }
        let mean = sum / n as f64;
        assert!((mean - 0.5).abs() < 0.02, "{mean}");
        assert_eq!(noise(DVec3::ZERO), 0.5);
    }

    #[test]
    fn the_vector_s_first_component_is_the_signed_noise() {
        for i in 0..2000 {
            let p = DVec3::new(
                i as f64 * 0.137 - 90.0,
                (i % 41) as f64 * 0.29,
                i as f64 * -0.071,
            );
            assert_eq!(vector(p).x, signed(p), "{p}");
        }
    }

    /// Samples of `f` at a fixed scatter of points, and at the same points moved by
    /// `shift`.
    fn samples(f: impl Fn(DVec3) -> f64, shift: DVec3) -> (Vec<f64>, Vec<f64>) {
        let mut state = 0x9e37_79b9u32;
        let mut next = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            f64::from(state >> 8) / f64::from(1u32 << 24)
        };
        (0..40_000)
            .map(|_| {
                let p = DVec3::new(next(), next(), next()) * 200.0 - DVec3::splat(100.0);
                (f(p), f(p + shift))
            })
            .unzip()
    }

    fn correlation(a: &[f64], b: &[f64]) -> f64 {
        let n = a.len() as f64;
        let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
        let cov: f64 = a.iter().zip(b).map(|(x, y)| (x - ma) * (y - mb)).sum();
        let va: f64 = a.iter().map(|x| (x - ma).powi(2)).sum();
        let vb: f64 = b.iter().map(|y| (y - mb).powi(2)).sum();
        cov / (va * vb).sqrt()
    }

    fn deviation(a: &[f64]) -> f64 {
        let n = a.len() as f64;
        let mean = a.iter().sum::<f64>() / n;
        (a.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n).sqrt()
    }

    #[test]
    fn the_vector_s_components_are_alike_and_decorrelated() {
        // Each component has the scalar noise's mean, spread and range, and its features'
        // size (the correlation of values half a cell apart); no two components go
        // together, at one point or half a cell apart (beyond the 0.02 of their shared
        // lattice, see VECTOR_GRADIENTS_AT).
        let half = DVec3::new(0.5, 0.3, -0.2);
        let (scalar, scalar_moved) = samples(signed, half);
        let spread = deviation(&scalar);
        let feature = correlation(&scalar, &scalar_moved);
        let component = |axis: usize| samples(|p| vector(p)[axis], half);
        let components = [component(0), component(1), component(2)];
        for (axis, (values, moved)) in components.iter().enumerate() {
            let mean = values.iter().sum::<f64>() / values.len() as f64;
            assert!(mean.abs() < 0.01, "{axis}: mean {mean}");
            let ratio = deviation(values) / spread;
            assert!((ratio - 1.0).abs() < 0.08, "{axis}: spread {ratio}");
            assert!(values.iter().all(|v| v.abs() <= 1.1), "{axis}");
            let own = correlation(values, moved);
            assert!(
                (own - feature).abs() < 0.05,
                "{axis}: {own} against {feature}"
            );
        }
        for a in 0..3 {
            for b in a + 1..3 {
                let here = correlation(&components[a].0, &components[b].0);
                let apart = correlation(&components[a].0, &components[b].1);
                assert!(
                    here.abs() < 0.04 && apart.abs() < 0.04,
                    "{a} {b}: {here} {apart}"
                );
            }
        }
    }
}
