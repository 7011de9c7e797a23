//! JPEG files through the `zune-jpeg` crate: greyscale files stay grey (a height field
//! reads their one sample), everything else (YCbCr, CMYK, ...) comes out as RGB. JPEG has
//! no alpha and no palette.

use super::{Image, ImageError, MAX_PIXELS, check_size};
use zune_core::bytestream::ZCursor;
use zune_core::colorspace::ColorSpace;
use zune_core::options::DecoderOptions;
use zune_jpeg::JpegDecoder;

pub fn decode(bytes: &[u8]) -> Result<Image, ImageError> {
    let malformed =
        |e: &dyn std::fmt::Display| ImageError::Malformed(format!("not a valid JPEG file: {e}"));
    // The decoder refuses sides past these before it allocates; `check_size` then holds
    // the area to MAX_PIXELS.
    let options = DecoderOptions::new_safe()
        .set_strict_mode(true)
        .set_max_width(MAX_PIXELS)
        .set_max_height(MAX_PIXELS);
    let mut decoder = JpegDecoder::new_with_options(ZCursor::new(bytes), options);
    decoder.decode_headers().map_err(|e| malformed(&e))?;
    let info = decoder
        .info()
        .ok_or_else(|| ImageError::Malformed("not a valid JPEG file: no frame header".into()))?;
    let (width, height) = (usize::from(info.width), usize::from(info.height));
    check_size(width, height)?;
    let out = if decoder.input_colorspace() == Some(ColorSpace::Luma) {
        ColorSpace::Luma
    } else {
        ColorSpace::RGB
    };
    decoder.set_options(options.jpeg_set_out_colorspace(out));
    let samples = decoder.decode().map_err(|e| malformed(&e))?;
    let channels = out.num_components();
    if samples.len() < width * height * channels {
        return Err(ImageError::Malformed(
            "not a valid JPEG file: it is cut short".into(),
        ));
    }
    let values: Vec<f32> = samples[..width * height * channels]
        .iter()
        .map(|&s| f32::from(s) / 255.0)
        .collect();
    Ok(Image::opaque(width, height, channels, &values))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image::ColourModel;

    /// Within JPEG's loss of the colour the test file was saved from.
    fn near(got: [f32; 4], want: [u8; 3]) -> bool {
        got[3] == 1.0 && (0..3).all(|k| (got[k] * 255.0 - f32::from(want[k])).abs() <= 4.0)
    }

    #[test]
    fn colour_files_decode_to_rgb() {
        let image = decode(include_bytes!("testdata/colour.jpg")).unwrap();
        assert_eq!((image.width, image.height), (16, 8));
        assert_eq!(image.model, ColourModel::Rgb);
        assert!(!image.has_alpha);
        assert!(
            near(image.pixel(0, 0), [200, 40, 30]),
            "{:?}",
            image.pixel(0, 0)
        );
        assert!(
            near(image.pixel(15, 0), [20, 60, 220]),
            "{:?}",
            image.pixel(15, 0)
        );
        assert!(
            near(image.pixel(3, 7), [128, 128, 128]),
            "{:?}",
            image.pixel(3, 7)
        );
    }

    #[test]
    fn grey_files_stay_grey() {
        let image = decode(include_bytes!("testdata/grey.jpg")).unwrap();
        assert_eq!((image.width, image.height), (8, 4));
        assert_eq!(image.model, ColourModel::Grey);
        for x in 0..8 {
            let g = (30 * x) as u8;
            assert!(
                near(image.pixel(x, 2), [g, g, g]),
                "{x}: {:?}",
                image.pixel(x, 2)
            );
        }
    }

    #[test]
    fn damaged_files_are_errors() {
        let bytes = include_bytes!("testdata/colour.jpg");
        for cut in [0, 2, 20, 200, bytes.len() - 40] {
            let result = decode(&bytes[..cut]);
            assert!(
                matches!(result, Err(ImageError::Malformed(_))),
                "cut at {cut}: {:?}",
                result.map(|i| (i.width, i.height))
            );
        }
        assert!(matches!(
            decode(b"GIF89a not a jpeg"),
            Err(ImageError::Malformed(_))
        ));
    }
}
