//! GIF files: the first image of the file, its palette indices kept (for height fields,
//! `use_index` and per-index filter and transmit), LZW-decoded, interlaced rows put in
//! order. POV-Ray reads GIF files as opaque palette images.

use super::{ColourModel, Image, ImageError, check_size};

pub fn decode(bytes: &[u8]) -> Result<Image, ImageError> {
    let malformed = |what: &str| ImageError::Malformed(format!("not a valid GIF file: {what}"));
    let cut = || malformed("it is cut short");
    if bytes.len() < 13 || !(bytes.starts_with(b"GIF87a") || bytes.starts_with(b"GIF89a")) {
        return Err(malformed("it does not start with GIF87a or GIF89a"));
    }
    let flags = bytes[10];
    let mut pos = 13;
    let mut palette = Vec::new();
    if flags & 0x80 != 0 {
        let size = 3 << ((flags & 7) + 1);
        palette = bytes.get(pos..pos + size).ok_or_else(cut)?.to_vec();
        pos += size;
    }
    loop {
        match *bytes.get(pos).ok_or_else(cut)? {
            // An extension: its label, then sub-blocks up to an empty one.
            0x21 => {
                pos += 2;
                pos = skip_sub_blocks(bytes, pos).ok_or_else(cut)?;
            }
            0x2C => break,
            0x3B => return Err(malformed("it holds no image")),
            other => return Err(malformed(&format!("unexpected block 0x{other:02x}"))),
        }
    }
    let descriptor = bytes.get(pos..pos + 10).ok_or_else(cut)?;
    let u16_at = |i: usize| usize::from(u16::from_le_bytes([descriptor[i], descriptor[i + 1]]));
    let (width, height) = (u16_at(5), u16_at(7));
    let image_flags = descriptor[9];
    pos += 10;
    check_size(width, height)?;
    if image_flags & 0x80 != 0 {
        let size = 3 << ((image_flags & 7) + 1);
        palette = bytes.get(pos..pos + size).ok_or_else(cut)?.to_vec();
        pos += size;
    }
    let min_code_size = *bytes.get(pos).ok_or_else(cut)?;
    if !(1..=11).contains(&min_code_size) {
        return Err(malformed("its LZW code size is out of range"));
    }
    pos += 1;
    let mut data = Vec::new();
    loop {
        let len = usize::from(*bytes.get(pos).ok_or_else(cut)?);
        pos += 1;
        if len == 0 {
            break;
        }
        data.extend_from_slice(bytes.get(pos..pos + len).ok_or_else(cut)?);
        pos += len;
    }
    let mut stored = lzw(&data, min_code_size, width * height)
        .ok_or_else(|| malformed("its image data is corrupt"))?;
    stored.resize(width * height, 0);
    let indices = if image_flags & 0x40 != 0 {
        deinterlace(&stored, width, height)
    } else {
        stored
    };
    let palette_len = palette.len() / 3;
    let pixels = indices
        .iter()
        .map(|&i| {
            let i = usize::from(i);
            if i < palette_len {
                let c = |k: usize| f32::from(palette[3 * i + k]) / 255.0;
                [c(0), c(1), c(2), 1.0]
            } else {
                [0.0, 0.0, 0.0, 1.0]
            }
        })
        .collect();
    Ok(Image {
        width,
        height,
        pixels,
        indices: Some(indices),
        palette_len,
        model: ColourModel::Indexed,
        has_alpha: false,
        gamma: None,
    })
}

fn skip_sub_blocks(bytes: &[u8], mut pos: usize) -> Option<usize> {
    loop {
        let len = usize::from(*bytes.get(pos)?);
        pos += 1 + len;
        if len == 0 {
            return Some(pos);
        }
    }
}

/// Decodes GIF's variable-length LZW codes into at most `limit` indices; `None` when a
/// code refers to an entry the table does not have yet.
fn lzw(data: &[u8], min_code_size: u8, limit: usize) -> Option<Vec<u8>> {
    let clear = 1usize << min_code_size;
    let end = clear + 1;
    // Each entry: the previous entry it extends (or none) and its last index.
    let mut prefix: Vec<Option<usize>> = (0..clear).map(|_| None).collect();
    let mut suffix: Vec<u8> = (0..clear).map(|i| i as u8).collect();
    let mut first: Vec<u8> = suffix.clone();
    let reset = |prefix: &mut Vec<Option<usize>>, suffix: &mut Vec<u8>, first: &mut Vec<u8>| {
        prefix.truncate(clear);
        suffix.truncate(clear);
        first.truncate(clear);
        // The clear and end codes take two places in the table.
        prefix.extend([None, None]);
        suffix.extend([0, 0]);
        first.extend([0, 0]);
    };
    reset(&mut prefix, &mut suffix, &mut first);
    let mut size = u32::from(min_code_size) + 1;
    let mut out = Vec::with_capacity(limit);
    let mut previous: Option<usize> = None;
    let (mut bits, mut count) = (0u32, 0u32);
    let mut bytes = data.iter();
    let mut stack = Vec::new();
    while out.len() < limit {
        while count < size {
            let Some(&b) = bytes.next() else {
                return Some(out);
            };
            bits |= u32::from(b) << count;
            count += 8;
        }
        let code = (bits & ((1 << size) - 1)) as usize;
        bits >>= size;
        count -= size;
        if code == clear {
            reset(&mut prefix, &mut suffix, &mut first);
            size = u32::from(min_code_size) + 1;
            previous = None;
            continue;
        }
        if code == end {
            break;
        }
        let table_len = prefix.len();
        let start = if code < table_len {
            first[code]
        } else if code == table_len {
            first[previous?]
        } else {
            return None;
        };
        if let Some(p) = previous
            && table_len < 4096
        {
            prefix.push(Some(p));
            suffix.push(start);
            first.push(first[p]);
            if prefix.len() == 1 << size && size < 12 {
                size += 1;
            }
        }
        stack.clear();
        let mut at = Some(code);
        while let Some(c) = at {
            stack.push(suffix[c]);
            at = prefix[c];
            if stack.len() > 4096 {
                return None;
            }
        }
        out.extend(stack.iter().rev());
        previous = Some(code);
    }
    out.truncate(limit);
    Some(out)
}

/// Rows stored in GIF's four interlace passes, put back in order.
fn deinterlace(stored: &[u8], width: usize, height: usize) -> Vec<u8> {
    let mut rows = Vec::with_capacity(height);
    for (start, step) in [(0, 8), (4, 8), (2, 4), (1, 2)] {
        rows.extend((start..height).step_by(step));
    }
    let mut out = vec![0; width * height];
    for (i, &row) in rows.iter().enumerate() {
        out[row * width..(row + 1) * width].copy_from_slice(&stored[i * width..(i + 1) * width]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn palette_indices_come_back_in_order() {
        // A 5 by 3 image of a four-colour palette, as an image editor writes it.
        let file = [
            71, 73, 70, 56, 55, 97, 5, 0, 3, 0, 129, 0, 0, 0, 0, 0, 255, 0, 0, 0, 255, 0, 0, 0,
            255, 44, 0, 0, 0, 0, 5, 0, 3, 0, 0, 8, 16, 0, 1, 4, 16, 48, 32, 128, 193, 129, 4, 5, 4,
            0, 0, 32, 32, 0, 59,
        ];
        let image = decode(&file).unwrap();
        assert_eq!(
            image.indices.as_deref(),
            Some(&[0, 1, 2, 3, 1, 1, 1, 1, 2, 2, 3, 2, 1, 0, 0][..])
        );
        assert_eq!(image.pixel(1, 0), [1.0, 0.0, 0.0, 1.0]);
        assert!(decode(&file[..30]).is_err());
        assert!(decode(b"GIF89a").is_err());
    }

    #[test]
    fn interlaced_images_with_growing_codes_decode() {
        // 16 by 16, fifty palette entries, interlaced; index (7x + 13y + xy mod 5) mod 50.
        let image = decode(include_bytes!("testdata/interlaced.gif")).unwrap();
        let indices = image.indices.unwrap();
        for y in 0..16 {
            for x in 0..16 {
                let expected = (x * 7 + y * 13 + (x * y) % 5) % 50;
                assert_eq!(usize::from(indices[y * 16 + x]), expected, "({x}, {y})");
            }
        }
    }
}
