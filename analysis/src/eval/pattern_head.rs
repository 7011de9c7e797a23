//! Patterns whose heads carry more than a keyword and a few numbers: `object { }` (an
//! object and, after it, the two entries), `facets` and its parameters.

use super::tokens::Token;
use super::value::Value;
use super::{Evaluator, Result};
use crate::scene::{Pattern, PatternKind};
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// The pattern a keyword starts, for the patterns kept here; `None` for any other.
    pub(super) fn pattern_head(&mut self, keyword: &Token) -> Result<Option<PatternKind>> {
        Ok(Some(match keyword.kind {
            OBJECT_KW => {
                // `object { OBJECT A, B }`: the entries and the closing brace are read by
                // the caller, as for any block pattern.
                self.expect(L_BRACE, "'{'")?;
                let token = self.next()?;
                let object = if Self::starts_object(token.kind) {
                    self.unget(token);
                    self.object()?
                } else {
                    match token.slot.as_ref().map(|s| s.borrow().clone()) {
                        Some(Value::Object(object)) => crate::scene::Object::clone(&object),
                        None if token.kind == IDENT => return Err(self.undeclared(&token)),
                        _ => {
                            return Err(self.error_at(
                                &token,
                                format!("expected an object, found {}", self.describe(&token)),
                            ));
                        }
                    }
                };
                let test = self
                    .geometry
                    .inside_test(&object)
                    .map_err(|m| self.error_at(keyword, m))?;
                PatternKind::Object(test)
            }
            PIGMENT_PATTERN_KW => PatternKind::PigmentPattern(Box::new(self.pigment_body()?)),
            FACETS_KW => PatternKind::Facets {
                coords: 0.0,
                size: 0.1,
                metric: 2.0,
            },
            _ => return Ok(None),
        }))
    }

    /// A parameter of a pattern kept here, after the pattern's head; false when `token` is
    /// not one for this pattern.
    pub(super) fn pattern_parameter(
        &mut self,
        pattern: &mut Pattern,
        token: &Token,
    ) -> Result<bool> {
        if let PatternKind::Facets {
            coords,
            size,
            metric,
        } = &mut pattern.kind
        {
            match token.kind {
                COORDS_KW => *coords = self.float()?,
                SIZE_KW => *size = self.float()?,
                METRIC_KW => *metric = self.float()?,
                _ => return Ok(false),
            }
            return Ok(true);
        }
        Ok(false)
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::tests::SpheresOnly;
    use crate::eval::{EvalOptions, evaluate, evaluate_with};
    use crate::files::MemoryFiles;
    use crate::pattern;
    use expect_test::expect;
    use glam::DVec3;

    #[test]
    fn object_patterns_tell_inside_from_outside() {
        let text = "#declare Ball = sphere { 0, 1 }\n\
                    #declare P = function { pattern { object { Ball } } }\n\
                    #debug concat(str(P(0, 0, 0), 0, 0), str(P(2, 0, 0), 0, 0), \"\\n\")\n\
                    plane { y, 0 pigment { object { Ball rgb 1, rgb 0 } scale 2 } }";
        let files = MemoryFiles::new().with("scene.pov", text);
        let evaluation = evaluate_with("scene.pov", &files, &EvalOptions::default(), &SpheresOnly);
        assert_eq!(evaluation.debug_text(), "10\n");
        let scene = evaluation.scene.expect("the scene evaluates");
        let texture = scene.objects[0].texture.clone().expect("a texture");
        let crate::scene::Texture::Plain { pigment, .. } = &*texture else {
            panic!("not plain")
        };
        let at = |x: f64| {
            pattern::pigment_colour(pigment, DVec3::new(x, 0.0, 0.0))
                .rgb
                .x
        };
        assert_eq!((at(1.5), at(2.5)), (0.0, 1.0));
    }

    #[test]
    fn object_patterns_need_a_renderer() {
        let text = "plane { y, 0 pigment { object { sphere { 0, 1 } rgb 1, rgb 0 } } }";
        let files = MemoryFiles::new().with("scene.pov", text);
        let evaluation = evaluate("scene.pov", &files, &EvalOptions::default());
        let errors: Vec<_> = evaluation
            .diagnostics
            .into_iter()
            .filter(|d| d.is_error())
            .collect();
        expect![[r#"
            scene.pov:1:24: error: this front end cannot answer geometric queries (trace, inside, extents, object pattern)
                1 | plane { y, 0 pigment { object { sphere { 0, 1 } rgb 1, rgb 0 } } }
                  |                        ^~~~~~
        "#]]
        .assert_eq(&syntax::diagnostic::render_human(&errors, &evaluation.sources));
    }
}
