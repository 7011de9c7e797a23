//! Transformations: `translate`, `rotate`, `scale`, `matrix`, `transform { }` and
//! `inverse`, parsed into [`Transform`]s.

use super::tokens::Token;
use super::value::Value;
use super::{Evaluator, Result};
use crate::scene::Transform;
use glam::{DAffine3, DMat3, DVec3};
use syntax::SyntaxKind::{self, *};

impl Evaluator<'_> {
    /// Whether `kind` starts a transformation.
    pub fn starts_transform(kind: SyntaxKind) -> bool {
        matches!(
            kind,
            TRANSLATE_KW | ROTATE_KW | SCALE_KW | MATRIX_KW | TRANSFORM_KW
        )
    }

    /// The transformation introduced by `keyword` (already read).
    pub fn transformation(&mut self, keyword: &Token) -> Result<Transform> {
        match keyword.kind {
            TRANSLATE_KW => Ok(Transform::translate(self.vector()?)),
            ROTATE_KW => Ok(Transform::rotate_degrees(self.vector()?)),
            SCALE_KW => {
                let mut v = self.vector()?;
                for c in [&mut v.x, &mut v.y, &mut v.z] {
                    if *c == 0.0 {
                        *c = 1.0;
                        self.warn_at(keyword, "scale by 0 is ignored (treated as 1) to keep the transformation invertible");
                    }
                }
                Transform::scale(v)
                    .ok_or_else(|| self.error_at(keyword, "scale by a non-finite value"))
            }
            MATRIX_KW => {
                let m = self.vector_list::<12>(keyword)?;
                // POV-Ray's matrix is row-vector style: rows are the images of x, y, z,
                // then the translation.
                let matrix3 = DMat3::from_cols(
                    DVec3::new(m[0], m[1], m[2]),
                    DVec3::new(m[3], m[4], m[5]),
                    DVec3::new(m[6], m[7], m[8]),
                );
                let affine = DAffine3 {
                    matrix3,
                    translation: DVec3::new(m[9], m[10], m[11]),
                };
                Transform::from_affine(affine)
                    .ok_or_else(|| self.error_at(keyword, "this matrix cannot be inverted"))
            }
            TRANSFORM_KW => {
                let next = self.next()?;
                if next.kind == L_BRACE {
                    self.unget(next);
                    return self.transform_body();
                }
                match next.slot.as_ref().map(|s| s.borrow().clone()) {
                    Some(Value::Transform(t)) => Ok(*t),
                    _ => Err(self.error_at(
                        &next,
                        format!("expected a transform, found {}", self.describe(&next)),
                    )),
                }
            }
            _ => Err(self.error_at(keyword, "expected a transformation")),
        }
    }

    /// `{ [TRANSFORM_IDENT] [translate ...] ... [inverse] }`, after `transform`.
    pub fn transform_body(&mut self) -> Result<Transform> {
        self.expect(L_BRACE, "'{'")?;
        let mut result = Transform::IDENTITY;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(result),
                INVERSE_KW => result = result.inverted(),
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    result = result.then(&t);
                }
                IDENT => match token.slot.as_ref().map(|s| s.borrow().clone()) {
                    Some(Value::Transform(t)) => result = result.then(&t),
                    Some(other) => {
                        return Err(self.error_at(
                            &token,
                            format!("expected a transform, found {}", other.type_name()),
                        ));
                    }
                    None => return Err(self.undeclared(&token)),
                },
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a transformation or '}}' in transform, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `< a, b, ... >` with exactly N floats (commas optional, as POV-Ray allows).
    fn vector_list<const N: usize>(&mut self, at: &Token) -> Result<[f64; N]> {
        self.expect(LT, "'<'")?;
        let mut values = [0.0; N];
        for (i, slot) in values.iter_mut().enumerate() {
            if i > 0 {
                self.eat(COMMA)?;
            }
            *slot = self.float()?;
        }
        if !self.eat(GT)? {
            return Err(self.error_at(at, format!("expected '>' after {N} values")));
        }
        Ok(values)
    }
}
