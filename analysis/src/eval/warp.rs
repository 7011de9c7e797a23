//! `warp { }` blocks of patterns: repeat, black_hole, turbulence, cylindrical, spherical,
//! toroidal and planar, with their options and POV-Ray's defaults.

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::scene::{Pattern, Transform, Turbulence, Warp};
use glam::DVec3;
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// `{ ... }` after `warp`, added to the pattern's warps. Transformations written before
    /// the warp act before it, so they move from the pattern's transform into the list.
    pub(super) fn warp(&mut self, pattern: &mut Pattern) -> Result<()> {
        self.expect(L_BRACE, "'{'")?;
        let kind = self.next()?;
        let warp = match kind.kind {
            REPEAT_KW => self.repeat_warp()?,
            BLACK_HOLE_KW => self.black_hole_warp()?,
            TURBULENCE_KW => self.turbulence_warp()?,
            CYLINDRICAL_KW | SPHERICAL_KW | TOROIDAL_KW => self.mapping_warp(&kind)?,
            PLANAR_KW => {
                let mut orientation = DVec3::Z;
                let mut distance = 0.0;
                if self.peek_kind()? != R_BRACE {
                    orientation = self.vector()?;
                    self.eat(COMMA)?;
                    distance = self.float()?;
                }
                self.expect(R_BRACE, "'}'")?;
                Warp::Planar {
                    orientation,
                    distance,
                }
            }
            CUBIC_KW => return Err(self.unsupported(&kind, "the cubic warp")),
            _ => {
                return Err(self.error_at(
                    &kind,
                    format!(
                        "expected repeat, black_hole, turbulence, cylindrical, spherical, \
                         toroidal or planar in warp, found {}",
                        self.describe(&kind)
                    ),
                ));
            }
        };
        if !pattern.transform.is_identity() {
            pattern.warps.push(Warp::Transform(pattern.transform));
            pattern.transform = Transform::IDENTITY;
        }
        pattern.warps.push(warp);
        Ok(())
    }

    /// `repeat <direction> [offset <v>] [flip <v>] }`.
    fn repeat_warp(&mut self) -> Result<Warp> {
        let direction = self.vector()?;
        let (mut offset, mut flip) = (DVec3::ZERO, DVec3::ZERO);
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                OFFSET_KW => offset = self.vector()?,
                FLIP_KW => flip = self.vector()?,
                _ => return Err(self.unexpected_in_warp(&token, "offset, flip")),
            }
        }
        Ok(Warp::Repeat {
            direction,
            offset,
            flip,
        })
    }

    /// `black_hole <center>, radius [strength s] [falloff f] [inverse] [repeat <v>]
    /// [turbulence <v>] [type t] }`.
    fn black_hole_warp(&mut self) -> Result<Warp> {
        let center = self.vector()?;
        self.eat(COMMA)?;
        let radius = self.float()?;
        let (mut strength, mut falloff, mut inverse) = (1.0, 2.0, false);
        let (mut repeat, mut jitter) = (DVec3::ZERO, DVec3::ZERO);
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                STRENGTH_KW => strength = self.float()?,
                FALLOFF_KW => falloff = self.float()?,
                INVERSE_KW => inverse = true,
                REPEAT_KW => repeat = self.vector()?,
                TURBULENCE_KW => jitter = self.vector()?,
                // POV-Ray knows one type of black hole, type 0.
                TYPE_KW => {
                    self.float()?;
                }
                _ => {
                    return Err(self.unexpected_in_warp(
                        &token,
                        "strength, falloff, inverse, repeat, turbulence",
                    ));
                }
            }
        }
        Ok(Warp::BlackHole {
            center,
            radius,
            strength,
            falloff,
            inverse,
            repeat,
            jitter,
        })
    }

    /// `turbulence <amount> [octaves n] [omega w] [lambda l] }`.
    fn turbulence_warp(&mut self) -> Result<Warp> {
        let mut turbulence = Turbulence {
            amount: self.vector()?,
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                OCTAVES_KW => turbulence.octaves = self.int()?.clamp(1, 10) as u32,
                OMEGA_KW => turbulence.omega = self.float()?,
                LAMBDA_KW => turbulence.lambda = self.float()?,
                _ => return Err(self.unexpected_in_warp(&token, "octaves, omega, lambda")),
            }
        }
        Ok(Warp::Turbulence(turbulence))
    }

    /// `cylindrical`, `spherical` or `toroidal` with `[orientation <v>] [dist_exp f]
    /// [major_radius r] }`.
    fn mapping_warp(&mut self, kind: &Token) -> Result<Warp> {
        let (mut orientation, mut dist_exp, mut major_radius) = (DVec3::Z, 0.0, 1.0);
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                ORIENTATION_KW => orientation = self.vector()?,
                DIST_EXP_KW => dist_exp = self.float()?,
                MAJOR_RADIUS_KW if kind.kind == TOROIDAL_KW => major_radius = self.float()?,
                _ => {
                    return Err(self.unexpected_in_warp(&token, "orientation, dist_exp"));
                }
            }
        }
        Ok(match kind.kind {
            CYLINDRICAL_KW => Warp::Cylindrical {
                orientation,
                dist_exp,
            },
            SPHERICAL_KW => Warp::Spherical {
                orientation,
                dist_exp,
            },
            _ => Warp::Toroidal {
                orientation,
                dist_exp,
                major_radius,
            },
        })
    }

    fn unexpected_in_warp(&self, token: &Token, expected: &str) -> Box<syntax::Diagnostic> {
        self.error_at(
            token,
            format!(
                "expected {expected} or '}}' in warp, found {}",
                self.describe(token)
            ),
        )
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::{EvalOptions, evaluate};
    use crate::files::MemoryFiles;
    use crate::scene::{Pigment, Warp};

    #[test]
    fn warps_keep_their_order_with_transformations() {
        let text = "sphere { 0, 1 pigment { checker scale 2 warp { repeat x*2 flip x } \
                    warp { black_hole <1, 0, 0>, 0.5 falloff 3 inverse } rotate 30*y } }";
        let files = MemoryFiles::new().with("scene.pov", text);
        let evaluation = evaluate("scene.pov", &files, &EvalOptions::default());
        let scene = evaluation.scene.expect("the scene evaluates");
        let Some(texture) = &scene.objects[0].texture else {
            panic!("no texture")
        };
        let crate::scene::Texture::Plain {
            pigment: Pigment::Pattern { pattern, .. },
            ..
        } = &**texture
        else {
            panic!("no pattern")
        };
        assert!(matches!(pattern.warps[0], Warp::Transform(_)));
        assert!(matches!(pattern.warps[1], Warp::Repeat { .. }));
        assert!(matches!(
            pattern.warps[2],
            Warp::BlackHole {
                falloff: 3.0,
                inverse: true,
                ..
            }
        ));
        assert_eq!(pattern.warps.len(), 3);
        assert!(!pattern.transform.is_identity());
    }
}
