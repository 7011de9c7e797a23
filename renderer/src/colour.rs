//! Colour arithmetic of the tracer: a traced sample (colour plus transmittance towards the
//! background, which becomes alpha) and the transfer curves of POV-Ray 3.7's gamma handling.

use crate::fast_math;
use crate::options::Gamma;
use glam::DVec3;
use std::ops::{Add, Mul};
use std::sync::OnceLock;

/// What one ray brings back: the colour, premultiplied by coverage, and how much of the
/// background's transparency shows through (1 for a transparent background, 0 for an opaque
/// surface). Averaging samples averages both, as antialiasing needs.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Sample {
    pub colour: DVec3,
    pub transmit: f64,
}

impl Sample {
    /// What a camera position without a ray shows: POV-Ray leaves such pixels fully
    /// transparent.
    pub const NO_RAY: Sample = Sample::new(DVec3::ZERO, 1.0);

    pub const fn new(colour: DVec3, transmit: f64) -> Sample {
        Sample { colour, transmit }
    }

    /// POV-Ray's colour distance for antialiasing: the summed absolute differences of red,
    /// green, blue and transmittance.
    pub fn distance(self, other: Sample) -> f64 {
        let d = (self.colour - other.colour).abs();
        d.x + d.y + d.z + (self.transmit - other.transmit).abs()
    }
}

impl Add for Sample {
    type Output = Sample;
    fn add(self, rhs: Sample) -> Sample {
        Sample::new(self.colour + rhs.colour, self.transmit + rhs.transmit)
    }
}

impl Mul<f64> for Sample {
    type Output = Sample;
    fn mul(self, rhs: f64) -> Sample {
        Sample::new(self.colour * rhs, self.transmit * rhs)
    }
}

/// A transfer curve from linear light to encoded values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Curve {
    Identity,
    /// Encoding raises to `1/gamma`.
    Power(f64),
    Srgb,
}

impl Curve {
    pub fn from_gamma(gamma: Gamma) -> Curve {
        match gamma {
            Gamma::Srgb => Curve::Srgb,
            Gamma::Power(1.0) => Curve::Identity,
            Gamma::Power(g) => Curve::Power(g),
        }
    }

    /// Linear light to an encoded value. Negative values stay negative so that no NaN
    /// appears; the caller clips.
    pub fn encode(&self, v: f64) -> f64 {
        self.encode_by(v, f64::powf)
    }

    /// [`Curve::encode`] with the powers taken by `pow`.
    #[inline(always)]
    fn encode_by(&self, v: f64, pow: impl Fn(f64, f64) -> f64) -> f64 {
        match *self {
            Curve::Identity => v,
            Curve::Power(g) => v.signum() * pow(v.abs(), 1.0 / g),
            Curve::Srgb => {
                let a = v.abs();
                let e = if a <= 0.003_130_8 {
                    a * 12.92
                } else {
                    1.055 * pow(a, 1.0 / 2.4) - 0.055
                };
                e * v.signum()
            }
        }
    }

    /// An encoded value back to linear light.
    pub fn decode(&self, v: f64) -> f64 {
        match *self {
            Curve::Identity => v,
            Curve::Power(g) => v.signum() * v.abs().powf(g),
            Curve::Srgb => {
                let a = v.abs();
                let d = if a <= 0.040_45 {
                    a / 12.92
                } else {
                    ((a + 0.055) / 1.055).powf(2.4)
                };
                d * v.signum()
            }
        }
    }

    pub fn encode_vec(&self, v: DVec3) -> DVec3 {
        match self {
            Curve::Identity => v,
            _ => DVec3::new(self.encode(v.x), self.encode(v.y), self.encode(v.z)),
        }
    }

    pub fn decode_vec(&self, v: DVec3) -> DVec3 {
        match self {
            Curve::Identity => v,
            _ => DVec3::new(self.decode(v.x), self.decode(v.y), self.decode(v.z)),
        }
    }
}

/// A transfer curve's encoding tabulated over 0..=1 and interpolated linearly, for the
/// millions of values a render encodes (antialiasing comparisons, output pixels); values
/// outside the table go through the curve itself.
#[derive(Debug, Clone)]
pub struct EncodeTable {
    curve: Curve,
    /// `None` for the identity, which needs no table. An array rather than a vector, so
    /// that its indices, at most `STEPS`, need no bounds checks.
    table: Option<Box<[f64; EncodeTable::STEPS + 1]>>,
}

impl EncodeTable {
    const STEPS: usize = 8192;

    /// The sRGB table, made once for the process: every render's output goes through it,
    /// and its thousands of powers were a fixed cost of each render.
    pub fn srgb() -> &'static EncodeTable {
        static SRGB: OnceLock<EncodeTable> = OnceLock::new();
        SRGB.get_or_init(|| EncodeTable::new(Curve::Srgb))
    }

    pub fn new(curve: Curve) -> EncodeTable {
        let table = match curve {
            Curve::Identity => None,
            _ => {
                let values: Box<[f64]> = (0..=Self::STEPS)
                    .map(|i| curve.encode_by(i as f64 / Self::STEPS as f64, fast_math::any_pow))
                    .collect();
                Some(values.try_into().expect("STEPS + 1 values"))
            }
        };
        EncodeTable { curve, table }
    }

    // Inlined natively only: in WebAssembly the inlined copies made the output loop
    // dearer to interpret (basic.pov in wasmi: 6.51 G instructions out of line, 6.73 G
    // inlined).
    #[cfg_attr(not(target_arch = "wasm32"), inline)]
    pub fn encode(&self, v: f64) -> f64 {
        match &self.table {
            Some(table) if (0.0..=1.0).contains(&v) => interpolate(table, v),
            // Outside the table: mostly colours brighter than white, such as highlights,
            // which the output clips and the antialiasing test compares by the threshold.
            _ => self.curve.encode_by(v, fast_math::any_pow),
        }
    }

    /// Inlined natively, as `encode` is: every output pixel and every antialiasing
    /// comparison calls it.
    #[cfg_attr(not(target_arch = "wasm32"), inline)]
    pub fn encode_vec(&self, v: DVec3) -> DVec3 {
        DVec3::new(self.encode(v.x), self.encode(v.y), self.encode(v.z))
    }

    /// [`EncodeTable::encode_vec`] for a colour known to lie in 0..=1, without the tests
    /// of the table and the range: the same values.
    #[inline]
    pub fn encode_unit_vec(&self, v: DVec3) -> DVec3 {
        match &self.table {
            Some(table) => DVec3::new(
                interpolate(table, v.x),
                interpolate(table, v.y),
                interpolate(table, v.z),
            ),
            None => self.curve.encode_vec(v),
        }
    }
}

/// The table's value at `v` in 0..=1, interpolated linearly.
#[inline]
fn interpolate(table: &[f64; EncodeTable::STEPS + 1], v: f64) -> f64 {
    let x = v * EncodeTable::STEPS as f64;
    // Through `u32`, whose conversion from a float is a few instructions where `usize`'s,
    // for values up to 2^64, is a dozen more; `x` is at most `STEPS`.
    let i = (x as u32 as usize).min(EncodeTable::STEPS - 1);
    let t = x - i as f64;
    table[i] + (table[i + 1] - table[i]) * t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_round_trip_and_known_values() {
        let c = Curve::Srgb;
        assert!((c.encode(0.5) - 0.735_356_983).abs() < 1e-6);
        for v in [0.0, 0.001, 0.2, 0.5, 1.0] {
            assert!((c.decode(c.encode(v)) - v).abs() < 1e-12);
        }
        assert_eq!(Curve::Power(2.5).encode(1.0), 1.0);
        assert!((Curve::Power(2.0).encode(0.25) - 0.5).abs() < 1e-12);
    }

    #[test]
    fn tabulated_srgb_is_exact_to_16_bits() {
        let table = EncodeTable::new(Curve::Srgb);
        for i in 0..=10_000 {
            let v = i as f64 / 10_000.0;
            let err = (table.encode(v) - Curve::Srgb.encode(v)).abs();
            assert!(err < 0.5 / 65535.0, "{v}: {err}");
        }
        assert_eq!(table.encode(2.0), Curve::Srgb.encode(2.0));
    }

    #[test]
    fn unit_values_encode_as_any_value() {
        let table = EncodeTable::new(Curve::Srgb);
        for i in 0..=100_000 {
            let v = DVec3::splat(i as f64 / 100_000.0);
            assert_eq!(table.encode_unit_vec(v), table.encode_vec(v), "{v}");
        }
        let identity = EncodeTable::new(Curve::Identity);
        assert_eq!(
            identity.encode_unit_vec(DVec3::splat(0.3)),
            DVec3::splat(0.3)
        );
    }

    #[test]
    fn distance_counts_every_channel() {
        let a = Sample::new(DVec3::new(0.1, 0.2, 0.3), 0.0);
        let b = Sample::new(DVec3::new(0.2, 0.0, 0.3), 1.0);
        assert!((a.distance(b) - 1.3).abs() < 1e-12);
    }
}
