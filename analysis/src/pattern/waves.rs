//! `ripples` and `waves`: concentric waves from ten fixed sources. POV-Ray puts its
//! sources at pseudo-random points of the unit sphere and gives each wave of `waves` a
//! frequency from 0.01 to 1.01 drawn by a linear congruential generator; the frequencies
//! here come from the same generator, the sources from our own. The patterns therefore
//! match POV-Ray's in wavelength and amplitude, not in where the sources sit.

use crate::trig;
use glam::DVec3;
use std::f64::consts::TAU;

/// How many sources the waves come from (POV-Ray's `number_of_waves` default).
const SOURCES: usize = 10;

/// The sources, on the unit sphere, and each one's frequency for `waves`.
fn sources() -> &'static [(DVec3, f64); SOURCES] {
    static TABLE: std::sync::OnceLock<[(DVec3, f64); SOURCES]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let mut place: u32 = 0x1234_5678;
        let mut uniform = move || {
            place = place.wrapping_mul(1_103_515_245).wrapping_add(12_345);
            f64::from((place >> 8) & 0xffff) / 65536.0
        };
        let mut frequency: i32 = -560_851_967;
        std::array::from_fn(|_| {
            // A uniform direction: uniform height and angle around the axis.
            let height = 2.0 * uniform() - 1.0;
            let angle = TAU * uniform();
            let ring = (1.0 - height * height).sqrt();
            let at = DVec3::new(ring * angle.cos(), height, ring * angle.sin());
            frequency = frequency.wrapping_mul(1_812_433_253).wrapping_add(12_345);
            let k = f64::from((frequency >> 16) & 0x7fff) * 0.000_030_518_509_476 + 0.01;
            (at, k)
        })
    })
}

/// The per-source terms: the offset from the source, its distance (1 at the source
/// itself), the sine of the wave there, and the source's weight.
fn each_source(
    p: DVec3,
    frequency: f64,
    phase: f64,
    own: bool,
    mut f: impl FnMut(DVec3, f64, f64, f64),
) {
    for (source, own_frequency) in sources() {
        let d = p - *source;
        let length = match d.length() {
            0.0 => 1.0,
            l => l,
        };
        let k = if own { *own_frequency } else { 1.0 };
        let sine = trig::sin((length * frequency * k + phase) * TAU);
        f(d, length, sine, 1.0 / k);
    }
}

/// `ripples` as a pigment: the mean of the sources' sines, mapped to 0..1.
pub fn ripples(p: DVec3, frequency: f64, phase: f64) -> f64 {
    let mut sum = 0.0;
    each_source(p, frequency, phase, false, |_, _, sine, _| sum += sine);
    0.5 * (1.0 + sum / SOURCES as f64)
}

/// `waves` as a pigment: each source with a frequency of its own, the faster ones weaker.
pub fn waves(p: DVec3, frequency: f64, phase: f64) -> f64 {
    let mut sum = 0.0;
    each_source(p, frequency, phase, true, |_, _, sine, weight| {
        sum += sine * weight
    });
    0.2 * (2.5 + sum / SOURCES as f64)
}

/// The normal push of `ripples` (or, `own_frequencies`, of `waves`) for a bump size of 1:
/// each source tilts the normal along the direction away from it by its wave's sine.
pub fn push(p: DVec3, frequency: f64, phase: f64, own_frequencies: bool) -> DVec3 {
    let mut push = DVec3::ZERO;
    each_source(
        p,
        frequency,
        phase,
        own_frequencies,
        |d, length, sine, weight| {
            push += d * (sine * weight / (length * SOURCES as f64));
        },
    );
    push
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ripples_stay_in_range_and_waves_finite() {
        for i in 0..500 {
            let p = DVec3::new(i as f64 * 0.13, (i % 11) as f64 * 0.7, -(i as f64) * 0.05);
            assert!((0.0..=1.0).contains(&ripples(p, 1.0, 0.0)));
            assert!(waves(p, 1.0, 0.0).is_finite());
        }
    }
}
