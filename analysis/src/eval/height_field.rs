//! `height_field { }`: heights sampled from a function, or read from an image file as
//! POV-Ray 3.7 reads each kind: grey images by their grey level, palette images by the
//! index, colour images by their red and green bytes as the high and low byte of a 16-bit
//! height. The image's top row lies at z = 1, its left column at x = 0.

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::image::{ColourModel, Image};
use crate::scene::Shape;
use crate::scene::math_shapes::HeightField;
use syntax::SyntaxKind::*;

/// The largest grid a function height field may ask for.
const MAX_FIELD_SAMPLES: i64 = 1 << 24;

impl Evaluator<'_> {
    /// The inside of `height_field { }` up to the object modifiers: `function ResX, ResY
    /// { f }` or an image file, then `smooth`, `water_level` and `hierarchy`.
    pub(super) fn height_field(&mut self, keyword: &Token) -> Result<Shape> {
        let token = self.next()?;
        let (columns, rows, heights) = if token.kind == FUNCTION_KW {
            self.function_heights(&token)?
        } else {
            self.unget(token.clone());
            let file = self.bitmap_file()?;
            let image = Self::data_values(&file);
            if image.width < 2 || image.height < 2 {
                return Err(self.error_at(
                    &token,
                    format!(
                        "a height field needs an image at least 2 pixels each way, not {} by {}",
                        image.width, image.height
                    ),
                ));
            }
            (image.width, image.height, image_heights(&image))
        };
        let mut field = HeightField {
            columns,
            rows,
            heights: heights.into(),
            smooth: false,
            water_level: 0.0,
            hierarchy: true,
        };
        self.height_field_modifiers(keyword, &mut field)?;
        Ok(Shape::HeightField(Box::new(field)))
    }

    /// `ResX, ResY { f }` after `function`: f(x, y, 0) sampled over the unit square and
    /// clamped to 0..1, x across, and y down the rows of an image, so that y = 0 lies at
    /// z = 1 as an image's top row does.
    fn function_heights(&mut self, token: &Token) -> Result<(usize, usize, Vec<f32>)> {
        let columns = self.int()?;
        self.eat(COMMA)?;
        let rows = self.int()?;
        if columns < 2 || rows < 2 || columns.saturating_mul(rows) > MAX_FIELD_SAMPLES {
            return Err(self.error_at(
                token,
                format!("a function height field needs 2 to {MAX_FIELD_SAMPLES} samples, at least 2 each way, not {columns} by {rows}"),
            ));
        }
        let function = self.function_body_after_keyword(token)?;
        let (columns, rows) = (columns as usize, rows as usize);
        let mut heights = Vec::with_capacity(columns * rows);
        for row in 0..rows {
            for column in 0..columns {
                let x = column as f64 / (columns - 1) as f64;
                let y = 1.0 - row as f64 / (rows - 1) as f64;
                let v = function.eval(&[x, y, 0.0]);
                heights.push(if v.is_finite() {
                    v.clamp(0.0, 1.0) as f32
                } else {
                    0.0
                });
            }
        }
        Ok((columns, rows, heights))
    }

    fn height_field_modifiers(&mut self, _keyword: &Token, field: &mut HeightField) -> Result<()> {
        loop {
            let token = self.next()?;
            match token.kind {
                SMOOTH_KW => field.smooth = self.optional_bool()?,
                WATER_LEVEL_KW => field.water_level = self.float()?,
                HIERARCHY_KW => field.hierarchy = self.optional_bool()?,
                _ => {
                    self.unget(token);
                    return Ok(());
                }
            }
        }
    }
}

/// The heights of an image, rows from z = 0 (the image's bottom row) up.
fn image_heights(image: &Image) -> Vec<f32> {
    let mut heights = Vec::with_capacity(image.width * image.height);
    for row in (0..image.height).rev() {
        for column in 0..image.width {
            let [r, g, _, _] = image.pixel(column, row);
            let h = match image.model {
                ColourModel::Indexed => {
                    f32::from(image.index(column, row).unwrap_or(0)) * 256.0 / 65535.0
                }
                ColourModel::Grey => r,
                ColourModel::Rgb => {
                    let byte = |v: f32| (v * 255.0).round();
                    (byte(r) * 256.0 + byte(g)) / 65535.0
                }
            };
            heights.push(h.clamp(0.0, 1.0));
        }
    }
    heights
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image::ColourModel;

    fn image(model: ColourModel, pixels: Vec<[f32; 4]>, indices: Option<Vec<u8>>) -> Image {
        Image {
            width: 2,
            height: 1,
            pixels,
            indices,
            palette_len: 256,
            model,
            has_alpha: false,
            gamma: None,
        }
    }

    #[test]
    fn each_kind_of_image_gives_heights_as_povray_reads_it() {
        // Measured with POV-Ray 3.7's trace(): palette index 255 is 0.99805 * 2 at a
        // cell's middle, pure red 0.9961, pure green 255 / 65535.
        let palette = image(
            ColourModel::Indexed,
            vec![[0.0; 4], [1.0; 4]],
            Some(vec![0, 255]),
        );
        assert_eq!(image_heights(&palette), vec![0.0, 255.0 * 256.0 / 65535.0]);
        let colour = image(
            ColourModel::Rgb,
            vec![[1.0, 0.0, 0.0, 1.0], [0.0, 1.0, 0.0, 1.0]],
            None,
        );
        assert_eq!(
            image_heights(&colour),
            vec![255.0 * 256.0 / 65535.0, 255.0 / 65535.0]
        );
    }
}
