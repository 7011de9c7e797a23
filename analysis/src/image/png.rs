//! PNG files through the `png` crate, without its expansions: palette images keep their
//! indices (for `use_index`, per-index filter and transmit, and height fields), and the
//! samples are unpacked here from every bit depth.

use super::{ColourModel, FileGamma, Image, ImageError, check_size};
use png::{BitDepth, ColorType};

pub fn decode(bytes: &[u8]) -> Result<Image, ImageError> {
    let malformed =
        |e: png::DecodingError| ImageError::Malformed(format!("not a valid PNG file: {e}"));
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::IDENTITY);
    let mut reader = decoder.read_info().map_err(malformed)?;
    let (width, height) = {
        let info = reader.info();
        (info.width as usize, info.height as usize)
    };
    check_size(width, height)?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| ImageError::Malformed("the PNG image is too large".into()))?;
    let mut buffer = vec![0; size];
    let frame = reader.next_frame(&mut buffer).map_err(malformed)?;
    let info = reader.info();
    let depth = frame.bit_depth;
    let colour = frame.color_type;
    let line = frame.line_size;
    let gamma = if info.srgb.is_some() {
        Some(FileGamma::Srgb)
    } else {
        info.gama_chunk
            .map(|g| g.into_value())
            .filter(|&g| g > 0.0)
            .map(|g| FileGamma::Power(1.0 / f64::from(g)))
    };
    let bits = match depth {
        BitDepth::One => 1,
        BitDepth::Two => 2,
        BitDepth::Four => 4,
        BitDepth::Eight => 8,
        BitDepth::Sixteen => 16,
    };
    let channels = match colour {
        ColorType::Grayscale | ColorType::Indexed => 1,
        ColorType::GrayscaleAlpha => 2,
        ColorType::Rgb => 3,
        ColorType::Rgba => 4,
    };
    let max = ((1u32 << bits) - 1) as f32;
    // The `s`-th sample of row `y`, as an integer.
    let sample = |y: usize, s: usize| -> u32 {
        let row = &buffer[y * line..(y + 1) * line];
        match bits {
            16 => u32::from(u16::from_be_bytes([row[2 * s], row[2 * s + 1]])),
            8 => u32::from(row[s]),
            _ => {
                let bit = s * bits;
                let byte = row[bit / 8];
                let shift = 8 - bits - bit % 8;
                u32::from(byte >> shift) & ((1 << bits) - 1)
            }
        }
    };
    let trns = info.trns.as_deref();
    let mut pixels = Vec::with_capacity(width * height);
    let mut indices = None;
    let mut palette_len = 0;
    let mut has_alpha = matches!(colour, ColorType::GrayscaleAlpha | ColorType::Rgba);
    match colour {
        ColorType::Indexed => {
            let palette = info.palette.as_deref().ok_or_else(|| {
                ImageError::Malformed("the PNG palette image has no palette".into())
            })?;
            palette_len = palette.len() / 3;
            // POV-Ray 3.7 reads palette images as opaque, whatever their tRNS chunk says
            // (measured): scenes make palette entries clear with `filter` and `transmit`.
            let entry = |i: usize| -> [f32; 4] {
                if i >= palette_len {
                    return [0.0, 0.0, 0.0, 1.0];
                }
                let c = |k: usize| f32::from(palette[3 * i + k]) / 255.0;
                [c(0), c(1), c(2), 1.0]
            };
            let mut list = Vec::with_capacity(width * height);
            for y in 0..height {
                for x in 0..width {
                    let i = sample(y, x) as usize;
                    list.push(i as u8);
                    pixels.push(entry(i));
                }
            }
            indices = Some(list);
        }
        _ => {
            // A tRNS chunk on a grey or RGB image names one colour that is transparent.
            let key: Option<Vec<u32>> = trns.map(|t| {
                t.chunks(2)
                    .map(|pair| {
                        u32::from(u16::from_be_bytes([pair[0], *pair.get(1).unwrap_or(&0)]))
                    })
                    .collect()
            });
            has_alpha |= key.is_some();
            for y in 0..height {
                for x in 0..width {
                    let mut s = [0u32; 4];
                    for (c, value) in s.iter_mut().enumerate().take(channels) {
                        *value = sample(y, x * channels + c);
                    }
                    let v = |k: usize| s[k] as f32 / max;
                    let mut p = match colour {
                        ColorType::Grayscale => [v(0), v(0), v(0), 1.0],
                        ColorType::GrayscaleAlpha => [v(0), v(0), v(0), v(1)],
                        ColorType::Rgb => [v(0), v(1), v(2), 1.0],
                        _ => [v(0), v(1), v(2), v(3)],
                    };
                    if key.as_deref() == Some(&s[..channels]) {
                        p[3] = 0.0;
                    }
                    pixels.push(p);
                }
            }
        }
    }
    let model = match colour {
        ColorType::Indexed => ColourModel::Indexed,
        ColorType::Grayscale | ColorType::GrayscaleAlpha => ColourModel::Grey,
        ColorType::Rgb | ColorType::Rgba => ColourModel::Rgb,
    };
    Ok(Image {
        width,
        height,
        pixels,
        indices,
        palette_len,
        model,
        has_alpha,
        gamma,
    })
}
