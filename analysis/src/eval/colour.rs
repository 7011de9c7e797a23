//! Colours: `rgb`, `rgbf`, `rgbt`, `rgbft`, their `srgb` forms, colour identifiers and
//! expressions, and the component keywords (`red 1 green 0.5 filter 0.2`).

use super::value::{Terms, Value};
use super::{Evaluator, Result};
use crate::scene::Colour;
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// A colour of five terms.
    pub fn colour(&mut self) -> Result<Terms> {
        let mut token = self.next()?;
        if matches!(token.kind, COLOR_KW | COLOUR_KW) {
            token = self.next()?;
        }
        let mut c = match token.kind {
            RGB_KW | SRGB_KW => self.colour_vector(token.kind, 3, &[0, 1, 2])?,
            RGBF_KW | SRGBF_KW => self.colour_vector(token.kind, 4, &[0, 1, 2, 3])?,
            RGBT_KW | SRGBT_KW => self.colour_vector(token.kind, 4, &[0, 1, 2, 4])?,
            RGBFT_KW | SRGBFT_KW => self.colour_vector(token.kind, 5, &[0, 1, 2, 3, 4])?,
            RED_KW | GREEN_KW | BLUE_KW | FILTER_KW | TRANSMIT_KW => {
                self.unget(token);
                Terms::splat(0.0, 5)
            }
            _ => {
                self.unget(token.clone());
                match self.additive()? {
                    Value::Float(v) => Terms::splat(v, 5),
                    Value::Vector(t) | Value::Colour(t) => t.promoted(5),
                    other => {
                        return Err(self.error_at(
                            &token,
                            format!("expected a color, found {}", other.type_name()),
                        ));
                    }
                }
            }
        };
        loop {
            let token = self.next()?;
            let index = match token.kind {
                RED_KW => 0,
                GREEN_KW => 1,
                BLUE_KW => 2,
                FILTER_KW => 3,
                TRANSMIT_KW => 4,
                _ => {
                    self.unget(token);
                    return Ok(c);
                }
            };
            c.c[index] = self.float()?;
        }
    }

    /// A colour as the scene description stores it.
    pub fn scene_colour(&mut self) -> Result<Colour> {
        let t = self.colour()?;
        Ok(Colour::from_array(t.c))
    }

    /// The vector after `rgb`-style keywords, placed into the given components; a float
    /// fills every given component.
    fn colour_vector(
        &mut self,
        keyword: syntax::SyntaxKind,
        len: u8,
        slots: &[usize],
    ) -> Result<Terms> {
        let at = self.next()?;
        self.unget(at.clone());
        let value = self.additive()?;
        let given = match value {
            Value::Float(v) => Terms::splat(v, len),
            Value::Vector(t) | Value::Colour(t) => t.promoted(len.max(t.len)),
            other => {
                return Err(self.error_at(
                    &at,
                    format!("expected a color vector, found {}", other.type_name()),
                ));
            }
        };
        let mut c = Terms::splat(0.0, 5);
        for (i, &slot) in slots.iter().enumerate() {
            c.c[slot] = given.c[i];
        }
        // Measured against POV-Ray 3.7: `rgb <r, g, b, f>` keeps the extra components in
        // their natural places (filter, then transmit).
        if slots.last() == Some(&(slots.len() - 1)) {
            for i in slots.len()..given.len as usize {
                c.c[i] = given.c[i];
            }
        }
        if matches!(keyword, SRGB_KW | SRGBF_KW | SRGBT_KW | SRGBFT_KW) {
            let Some(gamma) = self.settings.assumed_gamma else {
                return Err(self.error_at(
                    &at,
                    "srgb colors need assumed_gamma to be set first in global_settings",
                ));
            };
            for v in &mut c.c[..3] {
                *v = f64::from(srgb_to_linear(*v as f32).powf(1.0 / gamma as f32));
            }
        }
        Ok(c)
    }
}

/// The sRGB transfer function, decoding one component. POV-Ray computes it in single
/// precision, and scenes that print the result see the difference.
fn srgb_to_linear(v: f32) -> f32 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}
