//! POT files, Fractint's 16-bit "continuous potential" images: a GIF twice as wide as the
//! picture, whose left half holds each pixel's high byte and right half its low byte, as
//! palette indices. They are read as 16-bit grey, the heights a height field takes.

use super::{Image, ImageError};

pub fn decode(bytes: &[u8]) -> Result<Image, ImageError> {
    let gif = super::gif::decode(bytes)?;
    let indices = gif.indices.as_deref().unwrap_or_default();
    if gif.width % 2 != 0 || indices.len() != gif.width * gif.height {
        return Err(ImageError::Malformed(format!(
            "not a valid POT file: its GIF is {} pixels wide, not an even number",
            gif.width
        )));
    }
    let width = gif.width / 2;
    let values: Vec<f32> = indices
        .chunks_exact(gif.width)
        .flat_map(|row| {
            let (high, low) = row.split_at(width);
            high.iter()
                .zip(low)
                .map(|(&h, &l)| f32::from(u16::from_be_bytes([h, l])) / 65535.0)
        })
        .collect();
    Ok(Image::opaque(width, gif.height, 1, &values))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image::ColourModel;

    #[test]
    fn the_halves_are_high_and_low_bytes() {
        // A 2 by 2 picture stored as a 4 by 2 GIF of palette indices.
        let image = decode(include_bytes!("testdata/heights.pot")).unwrap();
        assert_eq!((image.width, image.height), (2, 2));
        assert_eq!(image.model, ColourModel::Grey);
        let heights: Vec<u32> = (0..2)
            .flat_map(|y| (0..2).map(move |x| (x, y)))
            .map(|(x, y)| (image.pixel(x, y)[0] * 65535.0).round() as u32)
            .collect();
        assert_eq!(heights, [0x0102, 0xff00, 0x7f80, 0x0001]);
    }

    #[test]
    fn an_odd_width_is_an_error() {
        let result = decode(include_bytes!("testdata/odd.pot"));
        assert!(matches!(result, Err(ImageError::Malformed(m)) if m.contains("3 pixels wide")));
    }
}
