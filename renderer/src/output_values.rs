//! The conversion of averaged samples to the image's output values: straight alpha,
//! clipping, and POV-Ray 3.7's gamma handling (working values to linear light, then the
//! file's curve), or for legacy scenes the working values as they are.
//!
//! Every pixel of every render goes through it, so the two conversions nearly all renders
//! use, legacy and linear working values to sRGB, have loops of their own: the general
//! conversion asked which curves apply three times per pixel and checked every value for
//! finiteness, about 127 instructions a pixel natively (patterns-map-space: 4.4% of the
//! render).

use crate::colour::{Curve, EncodeTable, Sample};
use crate::image::Image;
use glam::DVec3;

/// How a render's samples become output values.
pub struct Output {
    /// Legacy scenes (before 3.7, without assumed_gamma): POV-Ray 3.7 turns gamma
    /// handling off for them and writes working values as they are.
    pub legacy: bool,
    /// Working values to linear light.
    pub working: Curve,
    /// Linear light to the file's values.
    pub file: Curve,
    /// Whether the image has an alpha channel.
    pub alpha: bool,
}

impl Output {
    /// Writes rows of samples into `image`, the first at column `x0` of row `y0`.
    pub fn write(&self, rows: &[Vec<Sample>], image: &mut Image, (x0, y0): (usize, usize)) {
        match (self.legacy, self.working, self.file) {
            (true, ..) => self.write_with(rows, image, (x0, y0), |c| c),
            // Clipped values stay in the table's range, and its values are finite.
            (false, Curve::Identity, Curve::Srgb) => {
                let table = EncodeTable::srgb();
                self.write_with(rows, image, (x0, y0), |c| table.encode_unit_vec(c))
            }
            // Unusual gammas can take values to infinity or NaN.
            (false, working, Curve::Srgb) => {
                let table = EncodeTable::srgb();
                self.write_with(rows, image, (x0, y0), |c| {
                    table.encode_vec(working.decode_vec(c)).map(finite)
                })
            }
            (false, working, file) => self.write_with(rows, image, (x0, y0), |c| {
                file.encode_vec(working.decode_vec(c)).map(finite)
            }),
        }
    }

    /// [`Output::write`] with `encode` taking clipped colours to output values.
    fn write_with(
        &self,
        rows: &[Vec<Sample>],
        image: &mut Image,
        (x0, y0): (usize, usize),
        encode: impl Fn(DVec3) -> DVec3,
    ) {
        if self.alpha {
            fill(rows, image, (x0, y0), |s| {
                let alpha = (1.0 - s.transmit).clamp(0.0, 1.0);
                // Samples carry colour premultiplied by coverage; PNG wants straight alpha.
                let colour = if alpha > 0.0 {
                    s.colour / alpha
                } else {
                    DVec3::ZERO
                };
                let c = encode(clip(colour));
                [c.x as f32, c.y as f32, c.z as f32, finite(alpha) as f32]
            });
        } else {
            fill(rows, image, (x0, y0), |s| {
                let c = encode(clip(s.colour));
                [c.x as f32, c.y as f32, c.z as f32, 1.0]
            });
        }
    }
}

/// Each sample's output value through the rows of the image rather than pixel by pixel,
/// which computed and checked an index for every pixel.
#[inline(always)]
fn fill(
    rows: &[Vec<Sample>],
    image: &mut Image,
    (x0, y0): (usize, usize),
    pixel: impl Fn(Sample) -> [f32; 4],
) {
    let width = image.width as usize;
    let lines = image.pixels.chunks_exact_mut(width).skip(y0);
    for (row, line) in rows.iter().zip(lines) {
        for (s, out) in row.iter().zip(&mut line[x0..]) {
            *out = pixel(*s);
        }
    }
}

/// A colour clipped to 0..=1; NaN becomes 0.
fn clip(c: DVec3) -> DVec3 {
    c.clamp(DVec3::ZERO, DVec3::ONE)
}

fn finite(v: f64) -> f64 {
    if v.is_finite() { v } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn convert(output: &Output, s: Sample) -> [f32; 4] {
        let mut image = Image::new(1, 1, output.alpha);
        output.write(&[vec![s]], &mut image, (0, 0));
        image.pixel(0, 0)
    }

    #[test]
    fn each_conversion_clips_and_encodes() {
        let output = |legacy, working, alpha| Output {
            legacy,
            working,
            file: Curve::Srgb,
            alpha,
        };
        let s = Sample::new(DVec3::new(0.25, 2.0, -1.0), 0.5);
        // Straight alpha: the colour divided by the coverage, then clipped.
        assert_eq!(
            convert(&output(true, Curve::Identity, true), s),
            [0.5, 1.0, 0.0, 0.5]
        );
        assert_eq!(
            convert(&output(true, Curve::Identity, false), s),
            [0.25, 1.0, 0.0, 1.0]
        );
        let srgb = |v: f64| Curve::Srgb.encode(v) as f32;
        let [r, g, b, a] = convert(&output(false, Curve::Identity, false), s);
        assert!((r - srgb(0.25)).abs() < 1e-5 && g == 1.0 && b == 0.0 && a == 1.0);
        let [r, ..] = convert(&output(false, Curve::Power(2.2), false), s);
        assert!((r - srgb(0.25f64.powf(2.2))).abs() < 1e-5, "{r}");
        // NaN transmittance gives a transparent pixel, a NaN colour black.
        let nan = Sample::new(DVec3::splat(f64::NAN), f64::NAN);
        assert_eq!(
            convert(&output(false, Curve::Identity, true), nan),
            [0.0, 0.0, 0.0, 0.0]
        );
        assert_eq!(
            convert(&output(true, Curve::Identity, false), nan),
            [0.0, 0.0, 0.0, 1.0]
        );
    }

    #[test]
    fn unusual_gammas_give_finite_values() {
        let output = Output {
            legacy: false,
            working: Curve::Power(-1.0),
            file: Curve::Power(2.2),
            alpha: false,
        };
        let [r, ..] = convert(&output, Sample::new(DVec3::ZERO, 0.0));
        assert_eq!(r, 0.0);
    }
}
