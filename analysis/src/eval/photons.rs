//! The three `photons { }` blocks: in `global_settings` (how many photons and how they are
//! gathered), in an object (target, refraction, reflection, collect, pass_through,
//! split_union) and in a light source (which photons it shoots).

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::scene::{
    LightPhotons, MediaPhotons, Object, ObjectPhotons, PhotonDensity, Photons, Shape,
};
use syntax::SyntaxKind::{self, *};

/// The most photons one stretch of media gets from one photon: a memory budget, far
/// above the 100 POV-Ray's documentation suggests.
const MAX_MEDIA_STEPS: u32 = 10_000;

/// The keywords of an object's photons block, which end `target`'s optional multiplier.
const OBJECT_ITEMS: &[SyntaxKind] = &[
    R_BRACE,
    TARGET_KW,
    REFRACTION_KW,
    REFLECTION_KW,
    COLLECT_KW,
    PASS_THROUGH_KW,
    SPLIT_UNION_KW,
];

impl Evaluator<'_> {
    /// `photons { spacing 0.1 gather 20, 100 ... }` in global_settings, after `photons`.
    pub(super) fn global_photons(&mut self, keyword: &Token) -> Result<Photons> {
        self.expect(L_BRACE, "'{'")?;
        let mut photons = Photons {
            origin: Some(self.span(keyword)),
            ..Photons::default()
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(photons),
                SPACING_KW => {
                    let spacing = self.float()?;
                    if !(spacing > 0.0 && spacing.is_finite()) {
                        return Err(self.error_at(&token, "photon spacing must be positive"));
                    }
                    photons.density = PhotonDensity::Spacing(spacing);
                }
                COUNT_KW => {
                    let count = self.int()?;
                    if count < 1 {
                        return Err(self.error_at(&token, "photon count must be at least 1"));
                    }
                    photons.density = PhotonDensity::Count(count.min(i64::from(u32::MAX)) as u32);
                }
                GATHER_KW => {
                    let min = self.int()?;
                    self.eat(COMMA)?;
                    let max = self.int()?;
                    if min < 1 || max < min {
                        return Err(self.error_at(&token, "gather needs 1 <= min <= max photons"));
                    }
                    photons.gather_min = min.min(i64::from(u32::MAX)) as u32;
                    photons.gather_max = max.min(i64::from(u32::MAX)) as u32;
                }
                JITTER_KW => photons.jitter = self.float()?.clamp(0.0, 1.0),
                MAX_TRACE_LEVEL_KW => {
                    photons.max_trace_level = Some(self.int()?.clamp(1, 256) as u32)
                }
                ADC_BAILOUT_KW => photons.adc_bailout = Some(self.float()?),
                AUTOSTOP_KW => photons.autostop = self.float()?.clamp(0.0, 1.0),
                EXPAND_THRESHOLDS_KW => {
                    photons.expand_increase = self.float()?.max(0.0);
                    self.eat(COMMA)?;
                    photons.expand_min = self.int()?.max(0) as u32;
                }
                RADIUS_KW => self.photon_radius(&mut photons)?,
                MEDIA_KW => {
                    let max_steps = self.int()?;
                    let factor = if self.eat(COMMA)? { self.float()? } else { 1.0 };
                    if !(factor > 0.0 && factor.is_finite()) {
                        return Err(
                            self.error_at(&token, "the media photon factor must be positive")
                        );
                    }
                    photons.media = (max_steps > 0).then_some(MediaPhotons {
                        max_steps: max_steps.min(i64::from(MAX_MEDIA_STEPS)) as u32,
                        factor,
                    });
                }
                SAVE_FILE_KW | LOAD_FILE_KW => {
                    return Err(self.unsupported(
                        &token,
                        &format!("photon map files ({})", self.text(&token)),
                    ));
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a photons setting or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `radius [gather_radius] [, multiplier [, media_radius [, media_multiplier]]]`, every
    /// part optional: `radius , 0.5` only scales the estimated radius.
    fn photon_radius(&mut self, photons: &mut Photons) -> Result<()> {
        let [radius, multiplier, media_radius, media_multiplier] = self.sparse_floats()?;
        let positive = |v: Option<f64>| v.filter(|v| *v > 0.0);
        if let Some(radius) = radius {
            photons.radius = positive(Some(radius));
        }
        if let Some(radius) = media_radius {
            photons.media_radius = positive(Some(radius));
        }
        if let Some(m) = positive(multiplier) {
            photons.radius_multiplier = m;
        }
        if let Some(m) = positive(media_multiplier) {
            photons.media_radius_multiplier = m;
        }
        Ok(())
    }

    /// Up to `N` comma-separated numbers, any of which may be left out before its comma
    /// (`, 0.5`): `None` for each left out or not reached.
    fn sparse_floats<const N: usize>(&mut self) -> Result<[Option<f64>; N]> {
        let mut values = [None; N];
        for (i, value) in values.iter_mut().enumerate() {
            if i > 0 && !self.eat(COMMA)? {
                break;
            }
            let next = self.next()?;
            let left_out = next.kind == COMMA;
            self.unget(next);
            if !left_out {
                *value = Some(self.float()?);
            }
        }
        Ok(values)
    }

    /// `photons { target refraction on collect off ... }` in an object, after `photons`.
    pub(super) fn object_photons(&mut self, photons: &mut ObjectPhotons) -> Result<()> {
        self.expect(L_BRACE, "'{'")?;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(()),
                TARGET_KW => {
                    let next = self.next()?;
                    let has_value = !OBJECT_ITEMS.contains(&next.kind);
                    self.unget(next);
                    let multiplier = if has_value { self.float()? } else { 1.0 };
                    photons.target = (multiplier > 0.0).then_some(multiplier);
                }
                REFRACTION_KW => photons.refraction = Some(self.optional_bool()?),
                REFLECTION_KW => photons.reflection = Some(self.optional_bool()?),
                COLLECT_KW => photons.collect = self.optional_bool()?,
                PASS_THROUGH_KW => photons.pass_through = Some(self.optional_bool()?),
                SPLIT_UNION_KW => photons.split_union = self.optional_bool()?,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected target, refraction, reflection, collect, pass_through, split_union or '}}' in photons, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `photons { refraction on reflection off area_light }` in a light, after `photons`.
    pub(super) fn light_photons(&mut self, photons: &mut LightPhotons) -> Result<()> {
        self.expect(L_BRACE, "'{'")?;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(()),
                REFRACTION_KW => photons.refraction = Some(self.optional_bool()?),
                REFLECTION_KW => photons.reflection = Some(self.optional_bool()?),
                AREA_LIGHT_KW => photons.area_light = self.optional_bool()?,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected refraction, reflection, area_light or '}}' in photons, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }
}

/// Gives the parts of a CSG object its photons block, as POV-Ray does: the renderer meets
/// photons at the parts' surfaces.
pub(super) fn spread_to_parts(object: &mut Object) {
    let photons = object.photons;
    if let Shape::Csg { children, .. } = &mut object.shape {
        for child in children {
            child.photons = photons;
            spread_to_parts(child);
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::tests::{evaluate_err, evaluate_ok};
    use crate::scene::{LightPhotons, MediaPhotons, ObjectPhotons, PhotonDensity, Photons, Shape};

    #[test]
    fn global_block_takes_every_setting() {
        let s = evaluate_ok(
            "global_settings { photons { count 20000 gather 3, 8 jitter 0.2 max_trace_level 4
               adc_bailout 0.01 autostop 0.5 expand_thresholds 0.3, 25 radius 0.7, 2, 0.3, 1.5
               media 100, 2 } }",
        );
        let p = s.settings.photons.unwrap();
        assert_eq!(p.density, PhotonDensity::Count(20000));
        assert_eq!((p.gather_min, p.gather_max), (3, 8));
        assert_eq!(
            (p.jitter, p.max_trace_level, p.adc_bailout),
            (0.2, Some(4), Some(0.01))
        );
        assert_eq!(
            (p.autostop, p.expand_increase, p.expand_min),
            (0.5, 0.3, 25)
        );
        assert_eq!((p.radius, p.radius_multiplier), (Some(0.7), 2.0));
        assert_eq!(
            (p.media_radius, p.media_radius_multiplier),
            (Some(0.3), 1.5)
        );
        let media = MediaPhotons {
            max_steps: 100,
            factor: 2.0,
        };
        assert_eq!(p.media, Some(media));
    }

    #[test]
    fn global_block_defaults_follow_povray() {
        let s = evaluate_ok("global_settings { photons { spacing 0.1 radius , 0.5 } }");
        let p = s.settings.photons.unwrap();
        assert_eq!(p.density, PhotonDensity::Spacing(0.1));
        assert_eq!((p.radius, p.radius_multiplier), (None, 0.5));
        assert_eq!((p.media, p.media_radius), (None, None));
        let defaults = Photons::default();
        assert_eq!((p.gather_min, p.gather_max, p.jitter), (20, 100, 0.4));
        assert_eq!(p.expand_min, defaults.expand_min);
        assert!(evaluate_ok("sphere { 0, 1 }").settings.photons.is_none());
    }

    #[test]
    fn unsupported_and_bad_settings_are_located_errors() {
        for (text, message) in [
            (
                r#"photons { spacing 0.1 save_file "a.ph" }"#,
                "not supported yet: photon map files (save_file)",
            ),
            (
                "photons { spacing 0.1 media 100, 0 }",
                "the media photon factor must be positive",
            ),
            ("photons { spacing 0 }", "photon spacing must be positive"),
            (
                "photons { gather 8, 3 }",
                "gather needs 1 <= min <= max photons",
            ),
        ] {
            let error = evaluate_err(&format!("global_settings {{ {text} }}"));
            assert_eq!(error, message, "{text}");
        }
    }

    #[test]
    fn object_block_reaches_the_parts_of_a_csg() {
        let s = evaluate_ok(
            "union { sphere { 0, 1 } sphere { x, 1 } photons { target 0.5 refraction on collect off } }
             sphere { 0, 1 photons { target reflection on pass_through } no_shadow }
             sphere { 0, 1 split_union off }",
        );
        let expected = ObjectPhotons {
            target: Some(0.5),
            refraction: Some(true),
            collect: false,
            ..ObjectPhotons::default()
        };
        assert_eq!(s.objects[0].photons, expected);
        let Shape::Csg { children, .. } = &s.objects[0].shape else {
            panic!("a union");
        };
        assert!(children.iter().all(|c| c.photons == expected));
        let second = s.objects[1].photons;
        assert_eq!(second.target, Some(1.0));
        assert_eq!((second.reflection, second.refraction), (Some(true), None));
        assert_eq!(second.pass_through, Some(true));
        assert!(!s.objects[2].photons.split_union);
    }

    #[test]
    fn lights_leave_unsaid_kinds_to_the_objects() {
        let s = evaluate_ok(
            "light_source { 0, 1 }
             light_source { 0, 1 photons { refraction off area_light } }",
        );
        assert_eq!(s.lights[0].photons, LightPhotons::default());
        assert!(s.lights[0].photons.shoots());
        let second = s.lights[1].photons;
        assert_eq!((second.refraction, second.reflection), (Some(false), None));
        assert!(second.area_light && second.shoots());
    }
}
