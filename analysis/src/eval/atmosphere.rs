//! `fog { }`, `rainbow { }` and `sky_sphere { }`, at the top level or declared.

use super::expr::is_colour_keyword;
use super::value::Value;
use super::{Evaluator, Result};
use crate::scene::{Fog, GroundFog, Rainbow, SkySphere, Turbulence};
use glam::DVec3;
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// `{ ... }` after `fog`.
    pub fn fog_body(&mut self) -> Result<Fog> {
        self.expect(L_BRACE, "'{'")?;
        let first = self.next()?;
        let mut fog = match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Fog(f)) => Fog::clone(&f),
            _ => {
                self.unget(first);
                Fog::default()
            }
        };
        let mut ground = fog.ground.clone().unwrap_or(GroundFog {
            offset: 0.0,
            alt: 0.0,
            up: DVec3::Y,
        });
        let mut fog_type = if fog.ground.is_some() { 2 } else { 1 };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                FOG_TYPE_KW => {
                    fog_type = self.int()?;
                    if !(1..=2).contains(&fog_type) {
                        return Err(self.error_at(&token, "fog_type must be 1 or 2"));
                    }
                }
                DISTANCE_KW => fog.distance = self.float()?,
                FOG_OFFSET_KW => ground.offset = self.float()?,
                FOG_ALT_KW => ground.alt = self.float()?,
                UP_KW => ground.up = self.vector()?,
                TURB_DEPTH_KW => fog.turb_depth = self.float()?,
                TURBULENCE_KW => fog_turbulence(&mut fog).amount = self.vector()?,
                OCTAVES_KW => fog_turbulence(&mut fog).octaves = self.int()?.clamp(1, 10) as u32,
                OMEGA_KW => fog_turbulence(&mut fog).omega = self.float()?,
                LAMBDA_KW => fog_turbulence(&mut fog).lambda = self.float()?,
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    fog.transform = fog.transform.then(&t);
                }
                kind if is_colour_keyword(kind) => {
                    self.unget(token);
                    fog.colour = self.scene_colour()?;
                }
                IDENT
                    if token.slot.as_ref().is_some_and(|s| {
                        matches!(&*s.borrow(), Value::Colour(_) | Value::Vector(_))
                    }) =>
                {
                    self.unget(token);
                    fog.colour = self.scene_colour()?;
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a fog item or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        fog.ground = (fog_type == 2).then_some(ground);
        Ok(fog)
    }

    /// `{ ... }` after `rainbow`.
    pub fn rainbow_body(&mut self) -> Result<Rainbow> {
        let open = self.expect(L_BRACE, "'{'")?;
        let first = self.next()?;
        let mut rainbow = match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Rainbow(r)) => Rainbow::clone(&r),
            _ => {
                self.unget(first);
                Rainbow::default()
            }
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                DIRECTION_KW => rainbow.direction = self.vector()?,
                ANGLE_KW => rainbow.angle = self.float()?,
                WIDTH_KW => rainbow.width = self.float()?,
                DISTANCE_KW => rainbow.distance = self.float()?,
                JITTER_KW => rainbow.jitter = self.float()?,
                UP_KW => rainbow.up = self.vector()?,
                ARC_ANGLE_KW => rainbow.arc_angle = self.float()?.clamp(0.0, 360.0),
                FALLOFF_ANGLE_KW => rainbow.falloff_angle = self.float()?.clamp(0.0, 360.0),
                COLOR_MAP_KW | COLOUR_MAP_KW => rainbow.colour_map = self.colour_map_body()?,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a rainbow item or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        if rainbow.colour_map.entries.is_empty() {
            return Err(self.error_at(&open, "a rainbow needs a color_map"));
        }
        if rainbow.width <= 0.0 {
            return Err(self.error_at(&open, "a rainbow needs a positive width"));
        }
        if rainbow.direction == DVec3::ZERO {
            return Err(self.error_at(&open, "a rainbow needs a non-zero direction"));
        }
        rainbow.falloff_angle = rainbow.falloff_angle.min(rainbow.arc_angle);
        Ok(rainbow)
    }

    /// `{ ... }` after `sky_sphere`.
    pub fn sky_sphere_body(&mut self) -> Result<SkySphere> {
        self.expect(L_BRACE, "'{'")?;
        let first = self.next()?;
        let mut sky = match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::SkySphere(s)) => SkySphere::clone(&s),
            _ => {
                self.unget(first);
                SkySphere::default()
            }
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(sky),
                PIGMENT_KW => sky.pigments.push(self.pigment_body()?),
                EMISSION_KW => sky.emission = self.scene_colour()?.rgb,
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    sky.transform = sky.transform.then(&t);
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected pigment, emission, a transformation or '}}' in sky_sphere, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }
}

fn fog_turbulence(fog: &mut Fog) -> &mut Turbulence {
    fog.turbulence.get_or_insert(Turbulence {
        amount: DVec3::ZERO,
        octaves: 6,
        omega: 0.5,
        lambda: 2.0,
    })
}

#[cfg(test)]
mod tests {
    use crate::eval::tests::{evaluate_err, evaluate_ok};
    use glam::DVec3;

    #[test]
    fn fogs_add_up_and_ground_fog_keeps_its_parameters() {
        let scene = evaluate_ok(
            "fog { distance 10 rgbt <1, 1, 1, 0.2> }\n\
             #declare F = fog { fog_type 2 fog_offset 1 fog_alt 2 distance 5 color rgb 0.5 up z }\n\
             fog { F turbulence 0.5 rotate 90*x }",
        );
        assert_eq!(scene.fogs.len(), 2);
        assert!(scene.fogs[0].ground.is_none());
        assert_eq!(scene.fogs[0].colour.transmit, 0.2);
        let ground = scene.fogs[1].ground.as_ref().unwrap();
        assert_eq!((ground.offset, ground.alt, ground.up), (1.0, 2.0, DVec3::Z));
        assert_eq!(scene.fogs[1].turbulence.unwrap().amount, DVec3::splat(0.5));
        assert!(!scene.fogs[1].transform.is_identity());
    }

    #[test]
    fn rainbow_and_sky_sphere() {
        let scene = evaluate_ok(
            "rainbow { direction <0, 0, 1> angle 42.5 width 5 distance 1000 jitter 0.01 \
             color_map { [0 rgbt 1] [1 rgb x] } arc_angle 120 falloff_angle 130 }\n\
             #declare S = sky_sphere { pigment { gradient y } emission 2 }\n\
             sky_sphere { S pigment { rgbt 1 } rotate 10*y }",
        );
        let rainbow = &scene.rainbows[0];
        assert_eq!((rainbow.angle, rainbow.width), (42.5, 5.0));
        // The falloff cannot exceed the arc.
        assert_eq!(rainbow.falloff_angle, 120.0);
        let sky = scene.sky_sphere.as_ref().unwrap();
        assert_eq!(sky.pigments.len(), 2);
        assert_eq!(sky.emission, DVec3::splat(2.0));
    }

    #[test]
    fn incomplete_atmospheres_are_errors() {
        for (source, message) in [
            (
                "rainbow { angle 40 width 2 }",
                "a rainbow needs a color_map",
            ),
            ("fog { fog_type 3 }", "fog_type must be 1 or 2"),
            ("fog { distance 1 sphere }", "expected a fog item"),
        ] {
            let error = evaluate_err(source);
            assert!(error.contains(message), "{source}: {error}");
        }
    }
}
