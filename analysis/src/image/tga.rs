//! Truevision TGA files: colour-mapped, true-colour and grey images, uncompressed or
//! run-length encoded, 8 to 32 bits a pixel, stored from either the top or the bottom row.

use super::{ColourModel, Image, ImageError, check_size};

pub fn decode(bytes: &[u8]) -> Result<Image, ImageError> {
    let malformed = |what: &str| ImageError::Malformed(format!("not a valid TGA file: {what}"));
    let header = bytes.get(..18).ok_or_else(|| malformed("too short"))?;
    let u16_at = |i: usize| usize::from(u16::from_le_bytes([header[i], header[i + 1]]));
    let id_len = usize::from(header[0]);
    let has_map = header[1] == 1;
    let kind = header[2];
    let (map_first, map_len, map_bits) = (u16_at(3), u16_at(5), header[7]);
    let (width, height) = (u16_at(12), u16_at(14));
    let depth = header[16];
    let descriptor = header[17];
    let (model, rle) = match kind {
        1 => (ColourModel::Indexed, false),
        2 => (ColourModel::Rgb, false),
        3 => (ColourModel::Grey, false),
        9 => (ColourModel::Indexed, true),
        10 => (ColourModel::Rgb, true),
        11 => (ColourModel::Grey, true),
        _ => return Err(malformed(&format!("unknown image type {kind}"))),
    };
    check_size(width, height)?;
    let mut pos = 18 + id_len;
    let mut palette = Vec::new();
    if has_map {
        let entry = usize::from(map_bits).div_ceil(8);
        let data = bytes
            .get(pos..pos + map_len * entry)
            .ok_or_else(|| malformed("its colour map is cut short"))?;
        palette = data
            .chunks(entry)
            .map(|e| colour(e, map_bits))
            .collect::<Result<Vec<_>, _>>()?;
        pos += map_len * entry;
    }
    let size = usize::from(depth).div_ceil(8);
    let depth_fits = match model {
        ColourModel::Grey => size == 1,
        ColourModel::Indexed => size <= 2,
        _ => (2..=4).contains(&size),
    };
    if !depth_fits {
        return Err(malformed(&format!("{depth} bits a pixel")));
    }
    let raw = pixel_bytes(bytes.get(pos..).unwrap_or(&[]), width * height, size, rle)
        .ok_or_else(|| malformed("its pixels are cut short"))?;
    let mut pixels = Vec::with_capacity(width * height);
    let mut indices = (model == ColourModel::Indexed).then(|| Vec::with_capacity(width * height));
    let has_alpha = (model == ColourModel::Rgb && depth == 32)
        || palette.iter().any(|p: &[f32; 4]| p[3] != 1.0);
    let top_down = descriptor & 0x20 != 0;
    let right_to_left = descriptor & 0x10 != 0;
    for row in 0..height {
        let stored_row = if top_down { row } else { height - 1 - row };
        for column in 0..width {
            let stored_column = if right_to_left {
                width - 1 - column
            } else {
                column
            };
            let at = (stored_row * width + stored_column) * size;
            let p = &raw[at..at + size];
            let pixel = match model {
                ColourModel::Indexed => {
                    let index = if size == 2 {
                        usize::from(u16::from_le_bytes([p[0], p[1]]))
                    } else {
                        usize::from(p[0])
                    };
                    let entry = index.checked_sub(map_first).and_then(|i| palette.get(i));
                    if let Some(list) = &mut indices {
                        list.push(index.min(255) as u8);
                    }
                    entry.copied().unwrap_or([0.0, 0.0, 0.0, 1.0])
                }
                ColourModel::Grey => {
                    let v = f32::from(p[0]) / 255.0;
                    [v, v, v, 1.0]
                }
                _ => colour(p, depth)?,
            };
            pixels.push(pixel);
        }
    }
    Ok(Image {
        width,
        height,
        pixels,
        indices,
        palette_len: palette.len(),
        model,
        has_alpha,
        gamma: None,
    })
}

/// A stored colour: 15/16 bits as 5-5-5 (and an alpha bit), 24 as BGR, 32 as BGRA.
fn colour(p: &[u8], bits: u8) -> Result<[f32; 4], ImageError> {
    Ok(match bits {
        15 | 16 => {
            let v = u16::from_le_bytes([p[0], p[1]]);
            let c = |shift: u16| f32::from((v >> shift) & 31) / 31.0;
            // The top bit is not read as alpha: many writers leave it clear in opaque files.
            [c(10), c(5), c(0), 1.0]
        }
        24 => [
            f32::from(p[2]) / 255.0,
            f32::from(p[1]) / 255.0,
            f32::from(p[0]) / 255.0,
            1.0,
        ],
        32 => [
            f32::from(p[2]) / 255.0,
            f32::from(p[1]) / 255.0,
            f32::from(p[0]) / 255.0,
            f32::from(p[3]) / 255.0,
        ],
        other => {
            return Err(ImageError::Malformed(format!(
                "not a valid TGA file: {other}-bit colours"
            )));
        }
    })
}

/// The pixels' bytes, run-length decoded if need be; `None` when the data runs out.
fn pixel_bytes(data: &[u8], count: usize, size: usize, rle: bool) -> Option<Vec<u8>> {
    if !rle {
        return data.get(..count * size).map(<[u8]>::to_vec);
    }
    let mut out = Vec::with_capacity(count * size);
    let mut pos = 0;
    while out.len() < count * size {
        let packet = *data.get(pos)?;
        pos += 1;
        let n = usize::from(packet & 0x7f) + 1;
        if packet & 0x80 != 0 {
            let pixel = data.get(pos..pos + size)?;
            pos += size;
            for _ in 0..n {
                out.extend_from_slice(pixel);
            }
        } else {
            out.extend_from_slice(data.get(pos..pos + n * size)?);
            pos += n * size;
        }
    }
    out.truncate(count * size);
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn header(kind: u8, width: u16, height: u16, depth: u8, descriptor: u8) -> Vec<u8> {
        let mut h = vec![0, 0, kind, 0, 0, 0, 0, 0, 0, 0, 0, 0];
        h.extend(width.to_le_bytes());
        h.extend(height.to_le_bytes());
        h.extend([depth, descriptor]);
        h
    }

    #[test]
    fn rows_are_stored_from_the_bottom_unless_flagged() {
        let mut file = header(2, 1, 2, 24, 0);
        file.extend([0, 0, 255, 255, 0, 0]);
        let image = decode(&file).unwrap();
        // The first stored row (red) is the bottom one.
        assert_eq!(image.pixel(0, 1), [1.0, 0.0, 0.0, 1.0]);
        assert_eq!(image.pixel(0, 0), [0.0, 0.0, 1.0, 1.0]);
    }

    #[test]
    fn run_length_packets_repeat_a_pixel() {
        let mut file = header(11, 3, 1, 8, 0x20);
        file.extend([0x82, 51]);
        let image = decode(&file).unwrap();
        assert!(image.pixels.iter().all(|p| p[0] == 0.2));
        let mut cut = header(11, 3, 1, 8, 0x20);
        cut.push(0x82);
        assert!(decode(&cut).is_err());
    }
}
