//! Noise and the fractal sums built from it (Musgrave's heterogeneous and ridged
//! multifractals and POV-Ray's ridge function). The way each sums its octaves was pinned
//! down against POV-Ray 3.7 by feeding its own `f_noise_generator` values through each
//! candidate; the noise itself is POV-Ray's (`crate::noise`), so the values are too. `a`
//! is `x, y, z, P0, ...`.

use glam::DVec3;

/// The most octaves one call sums, so that a huge octave count cannot hang an isosurface;
/// beyond it the octaves' frequencies are far finer than any ray resolves.
const MAX_OCTAVES: f64 = 64.0;

fn point(a: &[f64]) -> DVec3 {
    DVec3::new(a[0], a[1], a[2])
}

/// The noise generator a function's parameter selects: POV-Ray 3.7 takes the truncated
/// number's two low bits, 2 and 3 naming generators 2 and 3 and 0 and 1 the original one
/// (measured: -1 and 7 give generator 3, -2 and 258 generator 2, 0, 4 and 5 generator 1).
fn generator(parameter: f64) -> u8 {
    match (parameter as i64) & 3 {
        2 => 2,
        3 => 3,
        _ => 1,
    }
}

/// Solid noise in 0..1.
fn noise(p: DVec3, generator: u8) -> f64 {
    crate::noise::noise_with_generator(p, generator)
}

/// Solid noise stretched to -1..1.
fn signed(p: DVec3, generator: u8) -> f64 {
    2.0 * noise(p, generator) - 1.0
}

/// Solid noise, 0..1, by the default generator.
pub fn noise3d(a: &[f64]) -> f64 {
    crate::noise::noise(point(a))
}

/// Solid noise, 0..1, by the generator of parameter `P0`.
pub fn noise_generator(a: &[f64]) -> f64 {
    noise(point(a), generator(a[3]))
}

/// The heterogeneous multifractal: offset + noise, then each octave i (frequency
/// lacunarity^i, weight lacunarity^(−H·i)) adds (noise + offset)·weight multiplied ⌊T⌋ times
/// by the running value; a fractional octave count adds that fraction of the next octave
/// times the value. Parameters H, lacunarity, octaves, offset, T, generator.
pub fn hetero_mf(a: &[f64]) -> f64 {
    let (h, lacunarity, octaves, offset, t) = (a[3], a[4], a[5], a[6], a[7]);
    let signed = |p| signed(p, generator(a[8]));
    let octaves = octaves.min(MAX_OCTAVES);
    let heterogeneity = if t >= 1.0 {
        t.min(MAX_OCTAVES) as u32
    } else {
        0
    };
    let mut p = point(a);
    let mut value = offset + signed(p);
    let mut i = 1.0;
    while i < octaves {
        p *= lacunarity;
        let mut increment = (signed(p) + offset) * lacunarity.powf(-h * i);
        for _ in 0..heterogeneity {
            increment *= value;
        }
        value += increment;
        i += 1.0;
    }
    let fraction = octaves - octaves.trunc();
    if fraction != 0.0 {
        p *= lacunarity;
        let increment = (signed(p) + offset) * lacunarity.powf(-h * i);
        value += fraction * increment * value;
    }
    value
}

/// POV-Ray's ridge: the weighted mean over the octaves (frequency lambda^i, weight omega^i,
/// at least one whole octave, a fractional count weighting the next octave by the
/// fraction) of |ridge − noise|/ridge, then (mean − offset)/offset; a zero ridge or offset
/// skips its division. Parameters lambda, octaves, omega, offset, ridge, generator.
pub fn ridge(a: &[f64]) -> f64 {
    let (lambda, octaves, omega, offset, crest) = (a[3], a[4], a[5], a[6], a[7]);
    let noise = |p| noise(p, generator(a[8]));
    let octaves = octaves.min(MAX_OCTAVES);
    let term = |p: DVec3| {
        let distance = (crest - noise(p)).abs();
        if crest == 0.0 {
            distance
        } else {
            distance / crest
        }
    };
    let mut p = point(a);
    let (mut total, mut weights, mut weight) = (0.0, 0.0, 1.0);
    for _ in 0..(octaves.trunc().max(1.0) as u32) {
        total += weight * term(p);
        weights += weight;
        weight *= omega;
        p *= lambda;
    }
    let fraction = octaves - octaves.trunc();
    if fraction != 0.0 {
        total += fraction * weight * term(p);
        weights += fraction * weight;
    }
    let mean = total / weights;
    if offset == 0.0 {
        mean
    } else {
        (mean - offset) / offset
    }
}

/// The ridged multifractal: the signal (offset − |noise|)² summed over the octaves
/// (frequency lacunarity^i, weight lacunarity^(−H·i)), each octave's signal scaled by the
/// previous one times the gain, clamped to 0..1. Parameters H, lacunarity, octaves,
/// offset, gain, generator.
pub fn ridged_mf(a: &[f64]) -> f64 {
    let (h, lacunarity, octaves, offset, gain) = (a[3], a[4], a[5], a[6], a[7]);
    let signed = |p| signed(p, generator(a[8]));
    let octaves = octaves.min(MAX_OCTAVES);
    let mut p = point(a);
    let mut signal = (offset - signed(p).abs()).powi(2);
    let mut value = signal;
    let mut i = 1.0;
    while i < octaves {
        p *= lacunarity;
        let weight = (signal * gain).clamp(0.0, 1.0);
        signal = (offset - signed(p).abs()).powi(2) * weight;
        value += signal * lacunarity.powf(-h * i);
        i += 1.0;
    }
    value
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_octave_reduces_to_the_noise() {
        // POV-Ray 3.7 with one octave: f_hetero_mf = offset + snoise, f_ridged_mf =
        // (offset − |snoise|)², f_ridge(…, offset 1, ridge 1) = −noise.
        let p = [0.3, -1.7, 2.2];
        let n = noise(DVec3::from_array(p), 2);
        let s = 2.0 * n - 1.0;
        let hetero = hetero_mf(&[p[0], p[1], p[2], 0.5, 2.0, 1.0, 1.0, 0.5, 2.0]);
        assert!((hetero - (1.0 + s)).abs() < 1e-12);
        let ridged = ridged_mf(&[p[0], p[1], p[2], 0.5, 2.0, 1.0, 1.0, 2.0, 2.0]);
        assert!((ridged - (1.0 - s.abs()).powi(2)).abs() < 1e-12);
        let ridge = ridge(&[p[0], p[1], p[2], 0.5, 1.0, 0.5, 1.0, 1.0, 2.0]);
        assert!((ridge + n).abs() < 1e-12);
    }

    #[test]
    fn huge_octave_counts_are_bounded() {
        let value = hetero_mf(&[0.3, 0.4, 0.5, 0.5, 2.0, 1e12, 1.0, 0.0, 2.0]);
        assert!(value.is_finite());
        assert!(ridge(&[0.3, 0.4, 0.5, 2.0, 1e12, 0.5, 1.0, 1.0, 2.0]).is_finite());
    }
}
