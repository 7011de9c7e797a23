//! The Netpbm formats POV-Ray reads: PGM (grey) and PPM (colour), each as plain text (P2,
//! P3) or binary (P5, P6), with 8- or 16-bit samples. A 16-bit PPM, like a TGA, can carry
//! a height field in its red and green bytes.

use super::{Image, ImageError, check_size};

pub fn decode(bytes: &[u8]) -> Result<Image, ImageError> {
    let malformed = |what: &str| ImageError::Malformed(format!("not a valid PPM/PGM file: {what}"));
    let magic = bytes.get(..2).ok_or_else(|| malformed("too short"))?;
    let (channels, binary) = match magic {
        b"P2" => (1, false),
        b"P3" => (3, false),
        b"P5" => (1, true),
        b"P6" => (3, true),
        b"P1" | b"P4" => {
            return Err(ImageError::Unsupported(
                "PBM (black and white) images".into(),
            ));
        }
        _ => return Err(malformed("it does not start with P2, P3, P5 or P6")),
    };
    let mut pos = 2;
    let mut header = [0usize; 3];
    for value in &mut header {
        *value = number(bytes, &mut pos).ok_or_else(|| malformed("its header is incomplete"))?;
    }
    let [width, height, max] = header;
    check_size(width, height)?;
    if !(1..=65535).contains(&max) {
        return Err(malformed("the maximum sample value must be 1 to 65535"));
    }
    let count = width * height * channels;
    let mut samples = Vec::with_capacity(count);
    if binary {
        // One whitespace byte separates the header from the samples.
        pos += 1;
        let size = if max > 255 { 2 } else { 1 };
        let data = bytes
            .get(pos..pos + count * size)
            .ok_or_else(|| malformed("it has fewer samples than its size says"))?;
        if size == 2 {
            samples.extend(
                data.chunks(2)
                    .map(|p| usize::from(u16::from_be_bytes([p[0], p[1]]))),
            );
        } else {
            samples.extend(data.iter().map(|&b| usize::from(b)));
        }
    } else {
        for _ in 0..count {
            samples.push(
                number(bytes, &mut pos)
                    .ok_or_else(|| malformed("it has fewer samples than its size says"))?,
            );
        }
    }
    let scale = max as f32;
    let values: Vec<f32> = samples.iter().map(|&s| s.min(max) as f32 / scale).collect();
    Ok(Image::opaque(width, height, channels, &values))
}

/// The next decimal number of the header or of a plain file, skipping whitespace and
/// `#` comments.
fn number(bytes: &[u8], pos: &mut usize) -> Option<usize> {
    loop {
        match bytes.get(*pos)? {
            b'#' => {
                while *bytes.get(*pos)? != b'\n' {
                    *pos += 1;
                }
            }
            c if c.is_ascii_whitespace() => *pos += 1,
            _ => break,
        }
    }
    let start = *pos;
    while bytes.get(*pos).is_some_and(u8::is_ascii_digit) {
        *pos += 1;
    }
    std::str::from_utf8(&bytes[start..*pos]).ok()?.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image::ColourModel;

    #[test]
    fn plain_and_binary_files_decode_alike() {
        let plain = decode(b"P2\n# a comment\n2 1\n255\n0 255\n").unwrap();
        let binary = decode(b"P5 2 1 255\n\x00\xff").unwrap();
        assert_eq!(plain.pixels, binary.pixels);
        assert_eq!(plain.pixels[1], [1.0, 1.0, 1.0, 1.0]);
        let colour = decode(b"P6 1 1 65535\n\xff\xff\x00\x00\x80\x00").unwrap();
        assert_eq!(colour.pixels[0][0], 1.0);
        assert_eq!(colour.model, ColourModel::Rgb);
    }

    #[test]
    fn truncated_files_are_errors() {
        assert!(decode(b"P5 4 4 255\n\x00").is_err());
        assert!(decode(b"P3 2").is_err());
        assert!(decode(b"JUNK").is_err());
        assert!(decode(b"P5 0 4 255\n").is_err());
    }
}
