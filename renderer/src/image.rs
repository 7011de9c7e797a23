//! The rendered picture: output-encoded colour (after the file gamma) with straight alpha,
//! kept as floats so that 8- and 16-bit PNG files quantise the same values.

/// A rendered image, row by row from the top.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    /// Whether the alpha channel carries information (`Output_Alpha`); when it does not,
    /// every alpha is 1 and PNG output is RGB.
    pub has_alpha: bool,
    /// Red, green, blue, alpha in 0..=1 for each pixel.
    pub pixels: Vec<[f32; 4]>,
}

impl Image {
    /// A black image, transparent when `has_alpha`.
    pub fn new(width: u32, height: u32, has_alpha: bool) -> Image {
        let alpha = if has_alpha { 0.0 } else { 1.0 };
        Image {
            width,
            height,
            has_alpha,
            pixels: vec![[0.0, 0.0, 0.0, alpha]; width as usize * height as usize],
        }
    }

    pub fn pixel(&self, x: u32, y: u32) -> [f32; 4] {
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    pub fn set_pixel(&mut self, x: u32, y: u32, value: [f32; 4]) {
        let w = self.width as usize;
        self.pixels[y as usize * w + x as usize] = value;
    }

    /// The samples at 8 bits, red, green, blue and (when it carries information) alpha
    /// of each pixel, row by row: what an 8-bit PNG file and the Typst plugin hold.
    pub fn samples8(&self) -> Vec<u8> {
        if self.has_alpha {
            self.quantised::<4>()
        } else {
            self.quantised::<3>()
        }
    }

    /// The first `N` channels of each pixel at 8 bits. The channel count is a constant so
    /// that the loop over a pixel's channels unrolls: in WebAssembly, a loop of three or
    /// four turns cost as much as the quantising.
    fn quantised<const N: usize>(&self) -> Vec<u8> {
        // Written into place rather than pushed: a push checks the capacity, which in
        // WebAssembly costs as much as the quantising.
        let mut samples = vec![0; self.pixels.len() * N];
        let (pixels, _) = samples.as_chunks_mut::<N>();
        for (out, pixel) in pixels.iter_mut().zip(&self.pixels) {
            for (o, &value) in out.iter_mut().zip(pixel) {
                *o = quantise8(value);
            }
        }
        samples
    }
}

/// A sample in 0..=1 (clipped) to the nearest of 256 levels, halves rounded up. Written
/// out rather than with `f32::round`, which is a call to libm in WebAssembly, made for
/// every sample of every image the plugin returns. `x + 0.5` in f64 is exact for every
/// `x` of at least 2^-22 (24 significant bits, none below 2^-45, and the sum below 2^9);
/// smaller ones stay below 1 however the sum rounds. So its truncation is `x` rounded,
/// and a NaN truncates to 0 as before. Truncated to `u32` and then to `u8` rather than
/// straight to `u8`: the value is known to be at most 255, and the saturating conversion
/// to `u8` costs two more comparisons per sample.
fn quantise8(value: f32) -> u8 {
    let x = value.clamp(0.0, 1.0) * 255.0;
    (f64::from(x) + 0.5) as u32 as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantise8_rounds_as_f32_round_does() {
        let mut value = -0.01f32;
        while value <= 1.01 {
            let expected = (value.clamp(0.0, 1.0) * 255.0).round() as u8;
            assert_eq!(quantise8(value), expected, "{value}");
            value += 1.0 / 65536.0;
        }
        // Around every halfway point between levels, a few ulps either side.
        for level in 0..255 {
            let mut value = (level as f32 + 0.5) / 255.0;
            for _ in 0..4 {
                value = f32::from_bits(value.to_bits() - 1);
            }
            for _ in 0..9 {
                let expected = (value.clamp(0.0, 1.0) * 255.0).round() as u8;
                assert_eq!(quantise8(value), expected, "{value}");
                value = f32::from_bits(value.to_bits() + 1);
            }
        }
        for value in [
            0.5 / 255.0,
            1.5 / 255.0,
            0.499_999_97 / 255.0,
            1e-30,
            f32::MIN_POSITIVE,
            -0.0,
            f32::NAN,
        ] {
            let expected = (value.clamp(0.0, 1.0) * 255.0).round() as u8;
            assert_eq!(quantise8(value), expected, "{value}");
        }
    }
}
