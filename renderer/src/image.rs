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
}
