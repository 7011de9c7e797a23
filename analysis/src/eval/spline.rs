//! `spline { }` statements and `Spline(t [, type])` calls.

use super::tokens::Token;
use super::value::{Terms, Value};
use super::{Evaluator, Result};
use crate::spline::{Spline, SplineKind};
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// `{ [type] t1, <p1>, t2, <p2>, ... }` after `spline`.
    pub fn spline_body(&mut self) -> Result<Spline> {
        self.expect(L_BRACE, "'{'")?;
        let mut spline = Spline {
            kind: SplineKind::Linear,
            points: Vec::new(),
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                LINEAR_SPLINE_KW => spline.kind = SplineKind::Linear,
                QUADRATIC_SPLINE_KW => spline.kind = SplineKind::Quadratic,
                CUBIC_SPLINE_KW => spline.kind = SplineKind::Cubic,
                NATURAL_SPLINE_KW => spline.kind = SplineKind::Natural,
                IDENT
                    if token
                        .slot
                        .as_ref()
                        .is_some_and(|s| matches!(&*s.borrow(), Value::Spline(_))) =>
                {
                    if let Some(Value::Spline(other)) =
                        token.slot.as_ref().map(|s| s.borrow().clone())
                    {
                        spline = Spline::clone(&other);
                    }
                }
                _ => {
                    self.unget(token.clone());
                    let key = self.float()?;
                    self.eat(COMMA)?;
                    let value = self.expression()?;
                    let terms = value.terms().ok_or_else(|| {
                        self.error_at(
                            &token,
                            format!("expected a spline point, found {}", value.type_name()),
                        )
                    })?;
                    // A float point is a 2-component one; of two points with the same
                    // parameter the first stays (both measured against POV-Ray 3.7).
                    let terms = if terms.len == 1 {
                        Terms::splat(terms.c[0], 2)
                    } else {
                        terms
                    };
                    if !spline.points.iter().any(|(k, _)| *k == key) {
                        spline.points.push((key, terms));
                    }
                    self.eat(COMMA)?;
                }
            }
        }
        spline.points.sort_by(|a, b| a.0.total_cmp(&b.0));
        Ok(spline)
    }

    /// `Spline(t [, type])`, after the identifier.
    pub fn call_spline(&mut self, at: &Token, spline: &Spline) -> Result<Value> {
        self.expect(L_PAREN, "'('")?;
        let t = self.float_in_parens()?;
        let mut kind = spline.kind;
        if self.eat(COMMA)? {
            let token = self.next()?;
            kind = match token.kind {
                LINEAR_SPLINE_KW => SplineKind::Linear,
                QUADRATIC_SPLINE_KW => SplineKind::Quadratic,
                CUBIC_SPLINE_KW => SplineKind::Cubic,
                NATURAL_SPLINE_KW => SplineKind::Natural,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!("expected a spline type, found {}", self.describe(&token)),
                    ));
                }
            };
        }
        self.expect(R_PAREN, "')'")?;
        if spline.points.is_empty() {
            return Err(self.error_at(at, "the spline has no points"));
        }
        Ok(Value::Vector(spline.at(t, kind)))
    }
}
