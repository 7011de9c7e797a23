//! Solid noise for the noise-based patterns: gradient (Perlin) noise on the integer lattice
//! with a fixed permutation, scaled to 0..1 around 0.5 as POV-Ray's noise is, and the
//! turbulence sums built from it. The values are not POV-Ray's bit for bit; they share its
//! range, mean and spatial frequency (one feature per unit), which the fidelity tests
//! check statistically.

use glam::DVec3;

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

/// Each component of the gradient that the hash at each index of [`PERMUTATION`] selects,
/// one table per axis: a corner's gradient is one lookup from its index instead of two,
/// and the gradients of two corners with neighbouring indices lie side by side. The entry
/// past the end repeats the first, for the neighbour of the last index.
static GRADIENT_X: [f64; 513] = gradient_component(0);
static GRADIENT_Y: [f64; 513] = gradient_component(1);
static GRADIENT_Z: [f64; 513] = gradient_component(2);

const fn gradient_component(axis: usize) -> [f64; 513] {
    let mut table = [0.0; 513];
    let mut i = 0;
    while i < 513 {
        table[i] = GRADIENTS[PERMUTATION[i & 511] as usize & 15][axis];
        i += 1;
    }
    table
}

/// Adding this rounds any float of magnitude below 2^51 to an integer, which then fills
/// the low bits of the sum's mantissa (1.5 times 2^52 keeps negative ones there too).
const ROUNDING: f64 = 6_755_399_441_055_744.0;

/// The lattice cell a point lies in: its corner, and the corner's coordinates modulo 256
/// as table indices. Below 2^51 in magnitude, one addition rounds a coordinate and its low
/// mantissa bits give the index (two's complement wraps negatives as `rem_euclid` does),
/// without a conversion to an integer or a call into the maths library (x86-64's baseline
/// has no rounding instruction). Beyond, every float is an integer, and NaN stays NaN.
#[inline(always)]
fn lattice_cell(p: DVec3) -> (DVec3, [usize; 3]) {
    if p.abs().max_element() < 2.0e15 {
        let sum = p + ROUNDING;
        let nearest = sum - ROUNDING;
        let cell = |sum: f64, nearest: f64, x: f64| {
            // One less where the rounding went up. The integer's own conversion back,
            // rather than a choice between two floats, leaves no branch on the rounding
            // direction for random points to mispredict.
            let floor = (sum.to_bits() as i64 - ROUNDING.to_bits() as i64) - i64::from(nearest > x);
            (floor as f64, floor as usize & 255)
        };
        let ((fx, xi), (fy, yi), (fz, zi)) = (
            cell(sum.x, nearest.x, p.x),
            cell(sum.y, nearest.y, p.y),
            cell(sum.z, nearest.z, p.z),
        );
        (DVec3::new(fx, fy, fz), [xi, yi, zi])
    } else {
        let floor = p.floor();
        let index = |f: f64| (f as i64 & 255) as usize;
        (floor, [index(floor.x), index(floor.y), index(floor.z)])
    }
}

/// How near 0 or 1 the fade weight across y must be for [`signed`] to blend one side's
/// corners alone.
const ONE_SIDED: f64 = 1e-12;

/// Signed gradient noise, roughly in -1..1, zero at lattice points.
pub fn signed(p: DVec3) -> f64 {
    lattice_noise(p)
}

/// [`signed`], inlined where the turbulence vector evaluates it three times at once.
#[inline(always)]
fn lattice_noise(p: DVec3) -> f64 {
    // A coordinate that is not finite makes the fractions, and with them the blend, NaN:
    // one test of the result instead of one per coordinate.
    let value = finite_lattice_noise(p);
    if value.is_nan() { 0.0 } else { value }
}

#[inline(always)]
fn finite_lattice_noise(p: DVec3) -> f64 {
    // Every index below is at most 511 (a table entry plus a cell coordinate, plus one):
    // the mask changes none of them and spares a bounds check at each lookup.
    let perm = |i: usize| usize::from(PERMUTATION[i & 511]);
    let (floor, [xi, yi, zi]) = lattice_cell(p);
    let (x, y, z) = (p.x - floor.x, p.y - floor.y, p.z - floor.z);
    let (u, v, w) = (fade(x), fade(y), fade(z));
    // The corners come in pairs across z, whose gradients are neighbours in the tables:
    // each pair's two dot products and each blend across x and y are done side by side
    // (two lanes of one vector register where the target has them), in the same order of
    // operations as one corner at a time, so the values are the same.
    let pair = |i: usize, x: f64, y: f64| -> [f64; 2] {
        let i = i & 511;
        [
            GRADIENT_X[i] * x + GRADIENT_Y[i] * y + GRADIENT_Z[i] * z,
            GRADIENT_X[i + 1] * x + GRADIENT_Y[i + 1] * y + GRADIENT_Z[i + 1] * (z - 1.0),
        ]
    };
    let lerp =
        |t: f64, a: [f64; 2], b: [f64; 2]| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
    let (a, b) = (perm(xi) + yi, perm(xi + 1) + yi);
    // On a lattice plane across y (a floor at y = 0, a pattern scaled about it) the
    // corners of one side carry all the weight but for a share below 1e-12 of the
    // difference, which no picture shows: only their square is blended.
    let [near, far] = if v <= ONE_SIDED || v >= 1.0 - ONE_SIDED {
        let (j, y) = if v <= ONE_SIDED { (0, y) } else { (1, y - 1.0) };
        let (low, high) = (perm(a + j) + zi, perm(b + j) + zi);
        lerp(u, pair(low, x, y), pair(high, x - 1.0, y))
    } else {
        let (aa, ab) = (perm(a) + zi, perm(a + 1) + zi);
        let (ba, bb) = (perm(b) + zi, perm(b + 1) + zi);
        lerp(
            v,
            lerp(u, pair(aa, x, y), pair(ba, x - 1.0, y)),
            lerp(u, pair(ab, x, y - 1.0), pair(bb, x - 1.0, y - 1.0)),
        )
    };
    near + w * (far - near)
}

/// POV-Ray's `Noise`: 0..1 with mean 0.5.
pub fn noise(p: DVec3) -> f64 {
    // Measured against POV-Ray's bozo on a plane: its features are about 1.3 times wider
    // and its values spread about as far as plain gradient noise's.
    (0.5 + 0.51 * signed(p * 0.76)).clamp(0.0, 1.0)
}

/// A vector of three decorrelated signed noises, for turbulence displacements: the noise
/// at three points apart. They lie whole cells apart along y, so that all three stay on a
/// lattice plane together and each blends only half its cell's corners there.
pub fn vector(p: DVec3) -> DVec3 {
    DVec3::new(
        lattice_noise(p),
        lattice_noise(p + DVec3::new(31.416, -48.0, 12.793)),
        lattice_noise(p + DVec3::new(-23.172, 19.0, 61.913)),
    )
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

    fn dot([gx, gy, gz]: [f64; 3], x: f64, y: f64, z: f64) -> f64 {
        gx * x + gy * y + gz * z
    }

    /// Gradient noise as the textbook writes it, one corner at a time.
    fn plain_noise(p: DVec3) -> f64 {
        let f = p.floor();
        let cell = |c: f64| (c as i64).rem_euclid(256) as usize;
        let (xi, yi, zi) = (cell(f.x), cell(f.y), cell(f.z));
        let (x, y, z) = (p.x - f.x, p.y - f.y, p.z - f.z);
        let perm = |i: usize| usize::from(PERMUTATION[i]);
        let grad = |i: usize, x: f64, y: f64, z: f64| dot(GRADIENTS[perm(i) & 15], x, y, z);
        let lerp = |t: f64, a: f64, b: f64| a + t * (b - a);
        let (u, v, w) = (fade(x), fade(y), fade(z));
        let (a, b) = (perm(xi) + yi, perm(xi + 1) + yi);
        let (aa, ab, ba, bb) = (
            perm(a) + zi,
            perm(a + 1) + zi,
            perm(b) + zi,
            perm(b + 1) + zi,
        );
        let side = |zi: usize, z: f64| {
            lerp(
                v,
                lerp(u, grad(aa + zi, x, y, z), grad(ba + zi, x - 1.0, y, z)),
                lerp(
                    u,
                    grad(ab + zi, x, y - 1.0, z),
                    grad(bb + zi, x - 1.0, y - 1.0, z),
                ),
            )
        };
        lerp(w, side(0, z), side(1, z - 1.0))
    }

    #[test]
    fn the_fast_noise_is_the_plain_noise() {
        // Points of every size up to the end of the fast cell computation and beyond,
        // some half-way between lattice planes, away from lattice planes across y (where
        // one side is blended alone): the same bits.
        let mut state: u64 = 12345;
        let mut next = move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for k in 0..20_000 {
            let size = [1.0, 10.0, 300.0, 1e5, 1e9, 1e14, 1.9e15, 1e16][k % 8];
            let y = (next() * 20.0).floor() + 0.5 + next() * 0.8;
            let mut coordinate = || {
                let c = next() * 2.0 * size;
                if k % 3 == 0 { c.floor() + 0.5 } else { c }
            };
            let p = DVec3::new(coordinate(), y, coordinate());
            assert_eq!(signed(p).to_bits(), plain_noise(p).to_bits(), "{p}");
        }
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
                dot([GRADIENT_X[i], GRADIENT_Y[i], GRADIENT_Z[i]], x, y, z),
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
}
