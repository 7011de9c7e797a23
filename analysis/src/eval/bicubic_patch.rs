//! `bicubic_patch { type N [flatness F] [u_steps N] [v_steps N] [uv_vectors ...] 16 points }`.

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::scene::Shape;
use crate::scene::mesh::BicubicPatch;
use glam::{DVec2, DVec3};
use syntax::SyntaxKind::*;

/// The most subdivision steps `u_steps` and `v_steps` may ask for together: each step
/// doubles the pieces, and 2^18 pieces are far finer than a picture can show.
const MAX_STEPS: u32 = 18;

impl Evaluator<'_> {
    /// The items and control points of `bicubic_patch`, read from after its opening brace.
    pub fn bicubic_patch(&mut self, keyword: &Token) -> Result<Shape> {
        let mut kind = None;
        let mut flatness = 0.0;
        let (mut u_steps, mut v_steps) = (0, 0);
        let mut uv_corners = BicubicPatch::DEFAULT_UV;
        loop {
            let token = self.next()?;
            match token.kind {
                TYPE_KW => {
                    let value = self.int()?;
                    kind = Some(match value {
                        0 | 1 => value as u8,
                        _ => {
                            self.warn_at(
                                &token,
                                format!(
                                    "bicubic_patch type {value} is not supported; using type 0"
                                ),
                            );
                            0
                        }
                    });
                }
                FLATNESS_KW => flatness = self.float()?.max(0.0),
                U_STEPS_KW => u_steps = self.steps()?,
                V_STEPS_KW => v_steps = self.steps()?,
                UV_VECTORS_KW => {
                    for (i, corner) in uv_corners.iter_mut().enumerate() {
                        if i > 0 {
                            self.eat(COMMA)?;
                        }
                        let v = self.vector_of(2)?;
                        *corner = DVec2::new(v.c[0], v.c[1]);
                    }
                }
                _ => {
                    self.unget(token);
                    break;
                }
            }
        }
        let Some(kind) = kind else {
            return Err(self.error_at(keyword, "a bicubic_patch needs its type: type 0 or type 1"));
        };
        if u_steps + v_steps > MAX_STEPS {
            return Err(self.error_at(
                keyword,
                format!(
                    "u_steps {u_steps} and v_steps {v_steps} ask for 2^{} pieces; the limit \
                     is 2^{MAX_STEPS}",
                    u_steps + v_steps
                ),
            ));
        }
        // POV-Ray allows a comma after the settings (`v_steps 4, <0, 0, 0>, ...`).
        self.eat(COMMA)?;
        let mut points = [[DVec3::ZERO; 4]; 4];
        for (i, p) in points.iter_mut().flatten().enumerate() {
            if i > 0 {
                self.eat(COMMA)?;
            }
            *p = self.vector()?;
        }
        Ok(Shape::BicubicPatch(Box::new(BicubicPatch {
            kind,
            flatness,
            u_steps,
            v_steps,
            uv_corners,
            points,
        })))
    }

    /// The count after `u_steps` or `v_steps`; negative counts mean none.
    fn steps(&mut self) -> Result<u32> {
        Ok(self.int()?.clamp(0, i64::from(MAX_STEPS)) as u32)
    }
}

#[cfg(test)]
mod tests {
    use crate::files::MemoryFiles;
    use crate::scene::Shape;
    use crate::{EvalOptions, Evaluation, evaluate};
    use glam::{DVec2, DVec3};

    const POINTS: &str = "<0,0,2>,<1,0,0>,<2,0,0>,<3,0,-2>,<0,1,0>,<1,1,0>,<2,1,0>,<3,1,0>,
        <0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>,<0,3,2>,<1,3,0>,<2,3,0>,<3,3,-2>";

    fn eval(items: &str) -> Evaluation {
        let text = format!("#version 3.7;\nbicubic_patch {{ {items} {POINTS} }}");
        let files = MemoryFiles::new().with("scene.pov", text);
        evaluate("scene.pov", &files, &EvalOptions::default())
    }

    #[test]
    fn items_come_in_any_order() {
        let evaluation =
            eval("v_steps 2 uv_vectors <0,0>,<2,0>,<2,2>,<0,2> type 1 u_steps 3 flatness 0.1");
        let Shape::BicubicPatch(patch) = &evaluation.scene.unwrap().objects[0].shape else {
            panic!("a patch");
        };
        assert_eq!((patch.kind, patch.u_steps, patch.v_steps), (1, 3, 2));
        assert_eq!(patch.flatness, 0.1);
        assert_eq!(patch.uv_corners[2], DVec2::splat(2.0));
        assert_eq!(patch.points[3][3], DVec3::new(3.0, 3.0, -2.0));
    }

    #[test]
    fn the_type_is_required_and_steps_are_bounded() {
        let message = |items: &str| {
            let evaluation = eval(items);
            let error = evaluation.diagnostics.iter().find(|d| d.is_error());
            error.map(|d| d.message.clone())
        };
        assert_eq!(
            message("u_steps 3").as_deref(),
            Some("a bicubic_patch needs its type: type 0 or type 1")
        );
        assert_eq!(
            message("type 0 u_steps 10 v_steps 10").as_deref(),
            Some("u_steps 10 and v_steps 10 ask for 2^20 pieces; the limit is 2^18")
        );
        assert_eq!(message("type 0 u_steps 9 v_steps 9"), None);
    }
}
