//! `ripples` and `waves`: concentric waves from ten fixed sources on the unit sphere.
//! `ripples` is the mean of the sources' sines; `waves` gives each source a frequency of
//! its own from 0.01 to 1.01, drawn by a linear congruential generator, and weakens the
//! faster ones. The sources are POV-Ray 3.7's, measured on its values (module tests): far
//! from the origin each source's wave is a sinusoid along any direction whose phase is the
//! source's projection on that direction, so sweeping the frequency gives a sum of ten
//! exponentials per direction, which a matrix pencil splits into the ten projections;
//! projections on ten directions fit together into ten points (to 1e-5), refined by least
//! squares on values near the origin. Which source each `waves` frequency belongs to came
//! from the phases of the ten frequencies along one axis. POV-Ray's `number_of_waves` has
//! no effect on either pattern in 3.7 (measured), and is ignored here too.

use crate::trig;
use glam::DVec3;
use std::f64::consts::TAU;

/// How many sources the waves come from.
const SOURCES: usize = 10;

/// The sources, in the order of the frequencies the generator draws for `waves`.
const POSITIONS: [[f64; 3]; SOURCES] = [
    [-0.604_377_723_5, 0.492_048_796_8, -0.626_590_117_2],
    [-0.552_574_361_4, -0.246_074_832_0, -0.796_310_257_2],
    [-0.444_550_426_1, 0.623_328_795_3, 0.643_298_930_2],
    [0.496_586_441_4, 0.668_947_987_2, 0.553_091_716_9],
    [-0.064_371_458_8, -0.805_951_539_6, -0.588_471_874_1],
    [0.246_189_563_0, -0.914_555_192_0, -0.320_899_520_3],
    [-0.666_088_020_0, -0.591_879_175_3, -0.453_877_567_2],
    [-0.520_489_427_3, -0.386_026_962_6, -0.761_625_913_7],
    [0.137_950_796_3, -0.704_641_984_1, -0.696_024_059_0],
    [0.564_897_156_1, 0.722_039_852_7, -0.399_436_554_3],
];

/// The sources and each one's frequency for `waves`, worked out when the program is built.
/// A constant, not a static: [`each_source`] indexes it source by source, and its entries
/// then become constants in the code, where from a static the plugin loaded each source's
/// position from memory (thirty loads for each point of a ripples normal).
const SOURCE_TABLE: [(DVec3, f64); SOURCES] = sources();

const fn sources() -> [(DVec3, f64); SOURCES] {
    let mut table = [(DVec3::ZERO, 0.0); SOURCES];
    let mut frequency: i32 = -560_851_967;
    let mut i = 0;
    while i < SOURCES {
        frequency = frequency.wrapping_mul(1_812_433_253).wrapping_add(12_345);
        let k = ((frequency >> 16) & 0x7fff) as f64 * 0.000_030_518_509_476 + 0.01;
        let [x, y, z] = POSITIONS[i];
        table[i] = (DVec3::new(x, y, z), k);
        i += 1;
    }
    table
}

/// The per-source terms: the offset from the source, its distance (1 at the source
/// itself), the sine of the wave there, and the source's weight.
#[inline(always)]
fn each_source(
    p: DVec3,
    frequency: f64,
    phase: f64,
    own: bool,
    mut f: impl FnMut(DVec3, f64, f64, f64),
) {
    // Source by source, not a loop: each source's position and frequency are then
    // constants in the code, where the loop loaded them from the table and kept a count.
    const _: () = assert!(SOURCES == 10, "one call below for each source");
    let mut source = |i| one_source(i, p, frequency, phase, own, &mut f);
    source(0);
    source(1);
    source(2);
    source(3);
    source(4);
    source(5);
    source(6);
    source(7);
    source(8);
    source(9);
}

/// The terms of [`each_source`] for source `i`.
#[inline(always)]
fn one_source(
    i: usize,
    p: DVec3,
    frequency: f64,
    phase: f64,
    own: bool,
    f: &mut impl FnMut(DVec3, f64, f64, f64),
) {
    let (source, own_frequency) = SOURCE_TABLE[i];
    let d = p - source;
    let length = match d.length() {
        0.0 => 1.0,
        l => l,
    };
    let k = if own { own_frequency } else { 1.0 };
    let sine = trig::sin((length * frequency * k + phase) * TAU);
    f(d, length, sine, 1.0 / k);
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
/// Inlined into the one place that asks, a bumped normal's: a call costs the interpreted
/// plugin a frame and the vector passed back through memory.
#[inline(always)]
pub fn push(p: DVec3, frequency: f64, phase: f64, own_frequencies: bool) -> DVec3 {
    let mut push = DVec3::ZERO;
    let mut add = |d: DVec3, length: f64, sine: f64, weight: f64| {
        push += d * (sine * weight / (length * SOURCES as f64));
    };
    // `ripples` apart, with its frequencies and weights of 1 known: the multiplications
    // by them vanish, and with them a division per source, giving the very same values.
    if own_frequencies {
        each_source(p, frequency, phase, true, &mut add);
    } else {
        each_source(p, frequency, phase, false, &mut add);
    }
    push
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values of POV-Ray 3.7's patterns at frequency 1 and phase 0 (the `.red` of a
    /// pigment function with `color_map { [0 rgb 0] [1 rgb 1] }`), at random points.
    #[test]
    fn ripples_and_waves_match_povray() {
        type Pattern = fn(DVec3, f64, f64) -> f64;
        type Values = [([f64; 3], f64); 3];
        let measured: [(&str, Pattern, Values); 2] = [
            (
                "ripples",
                ripples,
                [
                    (
                        [0.047_286_498_801, 1.801_854_785_304, -1.423_361_549_121],
                        0.443_040_162_325,
                    ),
                    (
                        [1.794_597_788_549, -0.752_674_191_958, -0.306_694_204_110],
                        0.368_450_582_027,
                    ),
                    (
                        [1.310_810_375_282, -0.363_203_454_523, 0.198_374_750_692],
                        0.708_509_027_958,
                    ),
                ],
            ),
            (
                "waves",
                waves,
                [
                    (
                        [-1.657_403_331_426, -1.052_757_973_616, 1.205_097_860_826],
                        0.381_819_486_618,
                    ),
                    (
                        [0.328_648_144_257, -1.623_485_431_038, -0.267_492_239_054],
                        0.595_723_390_579,
                    ),
                    (
                        [-0.083_794_807_437, -1.361_044_341_452, 0.938_308_605_637],
                        0.598_443_090_916,
                    ),
                ],
            ),
        ];
        for (name, pattern, values) in measured {
            for (p, want) in values {
                let got = pattern(DVec3::from_array(p), 1.0, 0.0);
                assert!(
                    (got - want).abs() < 3e-5,
                    "{name} at {p:?}: {got} for {want}"
                );
            }
        }
    }

    #[test]
    fn ripples_stay_in_range_and_waves_finite() {
        for i in 0..500 {
            let p = DVec3::new(i as f64 * 0.13, (i % 11) as f64 * 0.7, -(i as f64) * 0.05);
            assert!((0.0..=1.0).contains(&ripples(p, 1.0, 0.0)));
            assert!(waves(p, 1.0, 0.0).is_finite());
        }
    }
}
