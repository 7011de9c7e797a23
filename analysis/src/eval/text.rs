//! `text { ttf "font" "string" Thickness, Offset }`: the font read through the evaluation's
//! file source and the string laid out into glyph outlines here, so that a corrupt font or
//! a bad string is a located error. A font the caller did not supply, such as POV-Ray's
//! own timrom.ttf, and POV-Ray's built-in `internal` fonts, are drawn with the bundled
//! font, with a warning.

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::font::{self, BUNDLED_FONT, BUNDLED_FONT_NAME};
use crate::scene::Shape;
use crate::scene::math_shapes::Text;
use glam::DVec2;
use std::sync::Arc;
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// The inside of `text { }` up to the object modifiers.
    pub(super) fn text_shape(&mut self, keyword: &Token) -> Result<Shape> {
        let kind = self.next()?;
        let bytes: Arc<[u8]> = match kind.kind {
            TTF_KW => {
                let at = self.next()?;
                self.unget(at.clone());
                let name = self.string()?;
                // POV-Ray takes a comma between the font and the string, as between the
                // other parameters (`ttf "crystal.ttf", "text", 0.1, 0`).
                self.eat(COMMA)?;
                match self.source.read_bytes(&name) {
                    Some(bytes) => bytes,
                    None => {
                        self.warn_at(
                            &at,
                            format!("font '{name}' was not supplied; drawing the text in the bundled font ({BUNDLED_FONT_NAME}) instead"),
                        );
                        Arc::from(BUNDLED_FONT)
                    }
                }
            }
            INTERNAL_KW => {
                self.int()?;
                self.warn_at(
                    &kind,
                    format!("POV-Ray's internal fonts are not included; drawing the text in the bundled font ({BUNDLED_FONT_NAME}) instead"),
                );
                Arc::from(BUNDLED_FONT)
            }
            _ => {
                return Err(self.error_at(
                    &kind,
                    format!("expected ttf or internal, found {}", self.describe(&kind)),
                ));
            }
        };
        let at = self.next()?;
        self.unget(at.clone());
        let string = self.string()?;
        self.eat(COMMA)?;
        let thickness = self.float()?;
        self.eat(COMMA)?;
        let offset = self.vector()?;
        if offset.z != 0.0 {
            return Err(self.unsupported(keyword, "a text offset along z"));
        }
        let glyphs = font::layout(&bytes, &string, DVec2::new(offset.x, offset.y))
            .map_err(|message| self.error_at(&kind, message))?;
        Ok(Shape::Text(Box::new(Text {
            glyphs: glyphs.into(),
            thickness,
        })))
    }
}
