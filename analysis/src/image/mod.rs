//! Bitmaps read from the bytes of image files, for image maps, bump maps, image patterns and
//! height fields. Each decoder keeps what POV-Ray's uses need: the samples normalised to
//! 0..1 as the file stores them (no gamma applied), the palette index of each pixel for
//! palette images, and the gamma the file states. Malformed files are errors, never panics.

mod gif;
mod jpeg;
mod netpbm;
mod png;
mod pot;
mod tga;

use std::fmt;

/// The largest image we decode, in pixels: at 16 bytes a pixel, 256 MiB.
pub const MAX_PIXELS: usize = 1 << 24;

/// The image formats POV-Ray names with a keyword before the file name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ImageFormat {
    Png,
    Gif,
    Tga,
    Ppm,
    Pgm,
    Jpeg,
    Tiff,
    Exr,
    Hdr,
    Iff,
    Sys,
    Pot,
}

impl ImageFormat {
    /// The keyword that names the format.
    pub fn keyword(self) -> &'static str {
        match self {
            ImageFormat::Png => "png",
            ImageFormat::Gif => "gif",
            ImageFormat::Tga => "tga",
            ImageFormat::Ppm => "ppm",
            ImageFormat::Pgm => "pgm",
            ImageFormat::Jpeg => "jpeg",
            ImageFormat::Tiff => "tiff",
            ImageFormat::Exr => "exr",
            ImageFormat::Hdr => "hdr",
            ImageFormat::Iff => "iff",
            ImageFormat::Sys => "sys",
            ImageFormat::Pot => "pot",
        }
    }

    /// The format a file name's extension names (`.jpg`, `.tif`, `.png`, ...), which is
    /// how POV-Ray 3.7 reads a file given without a type keyword.
    pub fn from_extension(name: &str) -> Option<ImageFormat> {
        let extension = std::path::Path::new(name).extension()?.to_str()?;
        Some(match extension.to_ascii_lowercase().as_str() {
            "png" => ImageFormat::Png,
            "gif" => ImageFormat::Gif,
            "tga" => ImageFormat::Tga,
            "ppm" => ImageFormat::Ppm,
            "pgm" => ImageFormat::Pgm,
            "jpg" | "jpeg" => ImageFormat::Jpeg,
            "tif" | "tiff" => ImageFormat::Tiff,
            "exr" => ImageFormat::Exr,
            "hdr" => ImageFormat::Hdr,
            "iff" => ImageFormat::Iff,
            "sys" => ImageFormat::Sys,
            "pot" => ImageFormat::Pot,
            _ => return None,
        })
    }

    /// The usual file name extension, which POV-Ray appends to a name that has none.
    pub fn extension(self) -> &'static str {
        match self {
            ImageFormat::Jpeg => "jpg",
            ImageFormat::Tiff => "tif",
            other => other.keyword(),
        }
    }
}

/// How the file stores colour, which decides what a height field or `use_index` reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColourModel {
    Grey,
    /// Colour without a palette. A height field reads its red and green bytes as the high
    /// and low byte of a 16-bit height, as POV-Ray does for every colour format.
    Rgb,
    /// Palette indices; `Image::indices` holds them.
    Indexed,
}

/// The transfer function a file says its samples are encoded with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FileGamma {
    Srgb,
    /// A power law: the display gamma (2.2 for a PNG whose gAMA is 0.45455).
    Power(f64),
}

/// A decoded image.
#[derive(Debug, Clone, PartialEq)]
pub struct Image {
    pub width: usize,
    pub height: usize,
    /// Red, green, blue and alpha of each pixel, row by row from the top, normalised to 0..1
    /// as stored; alpha is 1 where the file has none.
    pub pixels: Vec<[f32; 4]>,
    /// Each pixel's palette index, for palette images.
    pub indices: Option<Vec<u8>>,
    /// The number of palette entries (0 without a palette).
    pub palette_len: usize,
    pub model: ColourModel,
    /// Whether the file has an alpha channel or transparent palette entries.
    pub has_alpha: bool,
    pub gamma: Option<FileGamma>,
}

impl Image {
    /// The pixel at column `x`, row `y` (row 0 at the top).
    pub fn pixel(&self, x: usize, y: usize) -> [f32; 4] {
        self.pixels[y * self.width + x]
    }

    /// The palette index at column `x`, row `y`, for palette images.
    pub fn index(&self, x: usize, y: usize) -> Option<u8> {
        self.indices.as_ref().map(|i| i[y * self.width + x])
    }

    /// An opaque image without a palette from its samples, normalised to 0..1 and one
    /// (grey) or three (red, green, blue) per pixel, row by row from the top.
    fn opaque(width: usize, height: usize, channels: usize, samples: &[f32]) -> Image {
        let pixels = samples
            .chunks_exact(channels)
            .map(|p| match *p {
                [g] => [g, g, g, 1.0],
                _ => [p[0], p[1], p[2], 1.0],
            })
            .collect();
        Image {
            width,
            height,
            pixels,
            indices: None,
            palette_len: 0,
            model: if channels == 1 {
                ColourModel::Grey
            } else {
                ColourModel::Rgb
            },
            has_alpha: false,
            gamma: None,
        }
    }

    /// A copy whose colour samples (not alpha) went through `decode`, as gamma decoding
    /// does before an image map's colours are used.
    pub fn map_colours(&self, decode: impl Fn(f32) -> f32) -> Image {
        let mut image = self.clone();
        for p in &mut image.pixels {
            for c in &mut p[..3] {
                *c = decode(*c);
            }
        }
        image
    }
}

/// Why an image could not be decoded.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum ImageError {
    /// The bytes are not a valid file of the format.
    Malformed(String),
    /// A valid file using something we do not decode.
    Unsupported(String),
}

impl fmt::Display for ImageError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ImageError::Malformed(m) => f.write_str(m),
            ImageError::Unsupported(m) => write!(f, "not supported yet: {m}"),
        }
    }
}

/// Decodes `bytes` as an image of `format`.
pub fn decode(format: ImageFormat, bytes: &[u8]) -> Result<Image, ImageError> {
    let image = match format {
        ImageFormat::Png => png::decode(bytes)?,
        ImageFormat::Gif => gif::decode(bytes)?,
        ImageFormat::Tga => tga::decode(bytes)?,
        ImageFormat::Jpeg => jpeg::decode(bytes)?,
        ImageFormat::Pot => pot::decode(bytes)?,
        ImageFormat::Ppm | ImageFormat::Pgm => netpbm::decode(bytes)?,
        other => {
            return Err(ImageError::Unsupported(format!(
                "{} images",
                other.keyword()
            )));
        }
    };
    Ok(image)
}

/// Checks an image's size against [`MAX_PIXELS`] before its samples are allocated.
fn check_size(width: usize, height: usize) -> Result<(), ImageError> {
    if width == 0 || height == 0 {
        return Err(ImageError::Malformed(format!(
            "the image is empty ({width} by {height} pixels)"
        )));
    }
    if width.saturating_mul(height) > MAX_PIXELS {
        return Err(ImageError::Malformed(format!(
            "the image is too large ({width} by {height} pixels; the limit is {MAX_PIXELS} pixels)"
        )));
    }
    Ok(())
}
