//! `radiosity { }` in global_settings and in objects, and `subsurface { }` in
//! global_settings and in finishes: reading them with the ranges and rules of POV-Ray 3.7's
//! manual (sections 3.4.4.3 and 3.4.6.3.3.4).

use super::tokens::Token;
use super::{Evaluator, Result};
use crate::scene::{Object, Radiosity, Shape};
use glam::DVec3;
use syntax::SyntaxKind::*;

/// The most rays one radiosity sample may gather, and the largest direction pool: a
/// budget that keeps a mistyped count from stalling the render.
const MAX_COUNT: i64 = 100_000;

impl Evaluator<'_> {
    /// `{ ... }` after `radiosity` in global_settings, modifying the scene's settings.
    pub fn global_radiosity(&mut self) -> Result<()> {
        let open = self.expect(L_BRACE, "'{'")?;
        let mut r = self.settings.radiosity.take().unwrap_or_default();
        let (mut minimum_token, mut maximum_token) = (None, None);
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                ADC_BAILOUT_KW => r.adc_bailout = self.at_least(&token, 0.0)?,
                ALWAYS_SAMPLE_KW => r.always_sample = self.optional_bool()?,
                BRIGHTNESS_KW => r.brightness = self.positive(&token, "brightness")?,
                COUNT_KW => {
                    r.count = self.whole(&token, 1, MAX_COUNT)?;
                    r.direction_pool = if self.eat(COMMA)? {
                        let pool = self.whole(&token, 1, MAX_COUNT)?;
                        Some(pool.max(r.count))
                    } else {
                        None
                    };
                }
                ERROR_BOUND_KW => r.error_bound = self.positive(&token, "error_bound")?,
                GRAY_THRESHOLD_KW => {
                    let gray = self.float()?;
                    if !(0.0..=1.0).contains(&gray) {
                        return Err(self.error_at(&token, "gray_threshold must be from 0 to 1"));
                    }
                    r.gray_threshold = gray;
                }
                LOW_ERROR_FACTOR_KW => {
                    r.low_error_factor = self.positive(&token, "low_error_factor")?
                }
                MAX_SAMPLE_KW => {
                    let max = self.float()?;
                    r.max_sample = (max > 0.0).then_some(max);
                }
                MEDIA_KW => r.media = self.optional_bool()?,
                MAXIMUM_REUSE_KW => {
                    r.maximum_reuse = self.positive(&token, "maximum_reuse")?;
                    maximum_token = Some(token);
                }
                MINIMUM_REUSE_KW => {
                    r.minimum_reuse = self.positive(&token, "minimum_reuse")?;
                    minimum_token = Some(token);
                }
                NEAREST_COUNT_KW => {
                    r.nearest_count = self.whole(&token, 1, 20)?;
                    r.adaptive_nearest_count = if self.eat(COMMA)? {
                        let adaptive = self.whole(&token, 1, 20)?;
                        if adaptive >= r.nearest_count {
                            return Err(self.error_at(
                                &token,
                                "nearest_count's second value (adaptive pretrace) must be smaller than the first",
                            ));
                        }
                        Some(adaptive)
                    } else {
                        None
                    };
                }
                NORMAL_KW => r.normal = self.optional_bool()?,
                PRETRACE_START_KW => r.pretrace_start = self.fraction(&token)?,
                PRETRACE_END_KW => r.pretrace_end = self.fraction(&token)?,
                RECURSION_LIMIT_KW => r.recursion_limit = self.whole(&token, 1, 20)?,
                SUBSURFACE_KW => r.subsurface = self.optional_bool()?,
                LOAD_FILE_KW | SAVE_FILE_KW => {
                    self.string()?;
                    self.warn_at(
                        &token,
                        format!(
                            "since POV-Ray 3.7, radiosity data is saved and loaded by command-line options; this {} is ignored",
                            self.text(&token)
                        ),
                    );
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a radiosity setting or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        self.reconcile_reuse(&open, &mut r, minimum_token, maximum_token)?;
        self.settings.radiosity = Some(r);
        Ok(())
    }

    /// The manual's rules for `minimum_reuse` against `maximum_reuse`: a minimum above half
    /// the maximum is a warning, and moves the value the scene did not set; a minimum at or
    /// above the maximum is an error.
    fn reconcile_reuse(
        &mut self,
        block: &Token,
        r: &mut Radiosity,
        minimum: Option<Token>,
        maximum: Option<Token>,
    ) -> Result<()> {
        if r.minimum_reuse <= r.maximum_reuse / 2.0 {
            return Ok(());
        }
        let at = minimum
            .as_ref()
            .or(maximum.as_ref())
            .unwrap_or(block)
            .clone();
        match (&minimum, &maximum) {
            (Some(_), None) => {
                r.maximum_reuse = r.minimum_reuse * 2.0;
                self.warn_at(
                    &at,
                    format!(
                        "minimum_reuse is more than half of maximum_reuse; maximum_reuse raised to {}",
                        r.maximum_reuse
                    ),
                );
            }
            (None, Some(_)) => {
                r.minimum_reuse = r.maximum_reuse / 2.0;
                self.warn_at(
                    &at,
                    format!(
                        "minimum_reuse is more than half of maximum_reuse; minimum_reuse lowered to {}",
                        r.minimum_reuse
                    ),
                );
            }
            _ if r.minimum_reuse >= r.maximum_reuse => {
                return Err(self.error_at(&at, "minimum_reuse must be less than maximum_reuse"));
            }
            _ => self.warn_at(&at, "minimum_reuse is more than half of maximum_reuse"),
        }
        Ok(())
    }

    /// `{ importance F }` after `radiosity` in an object.
    pub fn object_radiosity(&mut self, object: &mut Object) -> Result<()> {
        if let Some(importance) = self.radiosity_importance()? {
            object.radiosity_importance = Some(importance);
            inherit_importance(object, importance);
        }
        Ok(())
    }

    /// `{ importance F }` after `radiosity` in `#default`: the importance of objects placed
    /// from now on that set none themselves.
    pub fn default_radiosity(&mut self) -> Result<()> {
        if let Some(importance) = self.radiosity_importance()? {
            self.default_importance = importance;
        }
        Ok(())
    }

    fn radiosity_importance(&mut self) -> Result<Option<f64>> {
        self.expect(L_BRACE, "'{'")?;
        let mut importance = None;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(importance),
                IMPORTANCE_KW => {
                    let value = self.float()?;
                    if !(value > 0.0 && value <= 1.0) {
                        return Err(self
                            .error_at(&token, "importance must be greater than 0 and at most 1"));
                    }
                    importance = Some(value);
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected importance or '}}' in an object's radiosity, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `{ [samples N, M] [radiosity B] }` after `subsurface` in global_settings.
    pub fn global_subsurface(&mut self) -> Result<()> {
        self.expect(L_BRACE, "'{'")?;
        let mut s = self.settings.subsurface.take().unwrap_or_default();
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                SAMPLES_KW => {
                    let diffuse = self.whole(&token, 1, MAX_COUNT)?;
                    self.eat(COMMA)?;
                    let single = self.whole(&token, 1, MAX_COUNT)?;
                    s.samples = (diffuse, single);
                }
                RADIOSITY_KW => s.radiosity = self.optional_bool()?,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected samples, radiosity or '}}' in subsurface, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        self.settings.subsurface = Some(s);
        Ok(())
    }

    /// `{ translucency COLOUR }` after `subsurface` in a finish.
    pub fn translucency(&mut self) -> Result<DVec3> {
        self.expect(L_BRACE, "'{'")?;
        let mut translucency = DVec3::ZERO;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(translucency),
                TRANSLUCENCY_KW => translucency = self.scene_colour()?.rgb,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected translucency or '}}' in a finish's subsurface, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// A whole number from `min` to `max`, or an error naming the setting.
    fn whole(&mut self, setting: &Token, min: i64, max: i64) -> Result<u32> {
        let value = self.float()?;
        if value.fract() != 0.0 || value < min as f64 || value > max as f64 {
            return Err(self.error_at(
                setting,
                format!(
                    "{} must be a whole number from {min} to {max}",
                    self.text(setting)
                ),
            ));
        }
        Ok(value as u32)
    }

    fn at_least(&mut self, setting: &Token, min: f64) -> Result<f64> {
        let value = self.float()?;
        if value >= min {
            Ok(value)
        } else {
            Err(self.error_at(
                setting,
                format!("{} must be at least {min}", self.text(setting)),
            ))
        }
    }

    /// A share of the image size: greater than 0 and at most 1.
    fn fraction(&mut self, setting: &Token) -> Result<f64> {
        let value = self.float()?;
        if value > 0.0 && value <= 1.0 {
            Ok(value)
        } else {
            Err(self.error_at(
                setting,
                format!(
                    "{} must be greater than 0 and at most 1",
                    self.text(setting)
                ),
            ))
        }
    }
}

/// Gives a CSG's importance to the children that set none, all the way down.
fn inherit_importance(object: &mut Object, importance: f64) {
    if let Shape::Csg { children, .. } = &mut object.shape {
        for child in children {
            if child.radiosity_importance.is_none() {
                child.radiosity_importance = Some(importance);
                inherit_importance(child, importance);
            }
        }
    }
}

/// Gives the default importance to an object placed in the scene and to its parts that
/// set none.
pub fn place_with_importance(object: &mut Object, default: f64) {
    let importance = *object.radiosity_importance.get_or_insert(default);
    inherit_importance(object, importance);
}

#[cfg(test)]
mod tests {
    use crate::eval::tests::{self, evaluate_ok};
    use crate::scene::{Radiosity, Shape};
    use expect_test::{Expect, expect};

    fn radiosity(block: &str) -> Radiosity {
        evaluate_ok(&format!("global_settings {{ radiosity {{ {block} }} }}"))
            .settings
            .radiosity
            .expect("radiosity on")
    }

    /// The error and warnings of a 3.7 scene, rendered as the front ends print them.
    fn check_diagnostics(text: &str, expect: Expect) {
        tests::check_diagnostics(&format!("#version 3.7;\n{text}"), expect);
    }

    #[test]
    fn an_empty_block_turns_radiosity_on_with_the_manuals_defaults() {
        assert_eq!(radiosity(""), Radiosity::default());
        assert!(evaluate_ok("").settings.radiosity.is_none());
    }

    #[test]
    fn every_setting_is_read() {
        let r = radiosity(
            "adc_bailout 0.005 always_sample on brightness 0.9 count 50, 400 error_bound 0.5 \
             gray_threshold 0.25 low_error_factor 0.6 max_sample 2 media on maximum_reuse 0.1 \
             minimum_reuse 0.01 nearest_count 8, 4 normal on pretrace_start 0.1 \
             pretrace_end 0.01 recursion_limit 3 subsurface on",
        );
        let expected = Radiosity {
            count: 50,
            direction_pool: Some(400),
            error_bound: 0.5,
            recursion_limit: 3,
            pretrace_start: 0.1,
            pretrace_end: 0.01,
            nearest_count: 8,
            adaptive_nearest_count: Some(4),
            low_error_factor: 0.6,
            gray_threshold: 0.25,
            brightness: 0.9,
            minimum_reuse: 0.01,
            maximum_reuse: 0.1,
            normal: true,
            media: true,
            subsurface: true,
            always_sample: true,
            adc_bailout: 0.005,
            max_sample: Some(2.0),
        };
        assert_eq!(r, expected);
        // A non-positive max_sample leaves samples unlimited, as the manual says.
        assert_eq!(radiosity("max_sample 0").max_sample, None);
    }

    #[test]
    fn the_reuse_rules_warn_adjust_or_refuse() {
        // Only the minimum given: the maximum follows it.
        let r = radiosity("minimum_reuse 0.15");
        assert_eq!((r.minimum_reuse, r.maximum_reuse), (0.15, 0.3));
        // Only the maximum given: the minimum follows it.
        let r = radiosity("maximum_reuse 0.02");
        assert_eq!((r.minimum_reuse, r.maximum_reuse), (0.01, 0.02));
        // Both given: a warning, and neither moves.
        let r = radiosity("minimum_reuse 0.15 maximum_reuse 0.2");
        assert_eq!((r.minimum_reuse, r.maximum_reuse), (0.15, 0.2));
        check_diagnostics(
            "global_settings { radiosity { minimum_reuse 0.15 maximum_reuse 0.2 } }",
            expect![[r#"
                scene.pov:2:31: warning: minimum_reuse is more than half of maximum_reuse
                    2 | global_settings { radiosity { minimum_reuse 0.15 maximum_reuse 0.2 } }
                      |                               ^~~~~~~~~~~~~
                scene.pov:1:1: warning: assumed_gamma is not set in this POV-Ray 3.7 scene; taking assumed_gamma 1.0
                    1 | #version 3.7;
                      | ^~~~~~~~
                note: add `assumed_gamma 1.0` to global_settings
            "#]],
        );
        check_diagnostics(
            "global_settings { radiosity { maximum_reuse 0.1 minimum_reuse 0.1 } }",
            expect![[r#"
                scene.pov:2:49: error: minimum_reuse must be less than maximum_reuse
                    2 | global_settings { radiosity { maximum_reuse 0.1 minimum_reuse 0.1 } }
                      |                                                 ^~~~~~~~~~~~~
            "#]],
        );
    }

    #[test]
    fn out_of_range_settings_are_located_errors() {
        check_diagnostics(
            "global_settings { radiosity { recursion_limit 21 } }",
            expect![[r#"
                scene.pov:2:31: error: recursion_limit must be a whole number from 1 to 20
                    2 | global_settings { radiosity { recursion_limit 21 } }
                      |                               ^~~~~~~~~~~~~~~
            "#]],
        );
        check_diagnostics(
            "global_settings { radiosity { nearest_count 5, 5 } }",
            expect![[r#"
                scene.pov:2:31: error: nearest_count's second value (adaptive pretrace) must be smaller than the first
                    2 | global_settings { radiosity { nearest_count 5, 5 } }
                      |                               ^~~~~~~~~~~~~
            "#]],
        );
        check_diagnostics(
            "global_settings { radiosity { pretrace_end 0 } }",
            expect![[r#"
                scene.pov:2:31: error: pretrace_end must be greater than 0 and at most 1
                    2 | global_settings { radiosity { pretrace_end 0 } }
                      |                               ^~~~~~~~~~~~
            "#]],
        );
        check_diagnostics(
            "global_settings { radiosity { brightness 0 } }",
            expect![[r#"
                scene.pov:2:31: error: brightness must be positive, not 0
                    2 | global_settings { radiosity { brightness 0 } }
                      |                               ^~~~~~~~~~
            "#]],
        );
        check_diagnostics(
            "global_settings { radiosity { count 1e9 } }",
            expect![[r#"
                scene.pov:2:31: error: count must be a whole number from 1 to 100000
                    2 | global_settings { radiosity { count 1e9 } }
                      |                               ^~~~~
            "#]],
        );
        check_diagnostics(
            "global_settings { radiosity { load_file \"a.rad\" } }",
            expect![[r#"
                scene.pov:2:31: warning: since POV-Ray 3.7, radiosity data is saved and loaded by command-line options; this load_file is ignored
                    2 | global_settings { radiosity { load_file "a.rad" } }
                      |                               ^~~~~~~~~
                scene.pov:1:1: warning: assumed_gamma is not set in this POV-Ray 3.7 scene; taking assumed_gamma 1.0
                    1 | #version 3.7;
                      | ^~~~~~~~
                note: add `assumed_gamma 1.0` to global_settings
            "#]],
        );
        check_diagnostics(
            "global_settings { radiosity { importance 1 } }",
            expect![[r#"
                scene.pov:2:31: error: expected a radiosity setting or '}', found 'importance'
                    2 | global_settings { radiosity { importance 1 } }
                      |                               ^~~~~~~~~~
            "#]],
        );
    }

    #[test]
    fn importance_comes_from_the_object_its_csg_or_the_default() {
        let s = evaluate_ok(
            "sphere { 0, 1 }
             union { sphere { 0, 1 radiosity { importance 0.25 } } sphere { 0, 1 }
                     radiosity { importance 0.5 } }
             #default { radiosity { importance 0.75 } }
             sphere { 0, 1 }
             union { sphere { 0, 1 } }",
        );
        let importance = |o: &crate::scene::Object| o.radiosity_importance;
        assert_eq!(importance(&s.objects[0]), Some(1.0));
        let Shape::Csg { children, .. } = &s.objects[1].shape else {
            panic!("a union")
        };
        assert_eq!(importance(&s.objects[1]), Some(0.5));
        assert_eq!(importance(&children[0]), Some(0.25));
        assert_eq!(importance(&children[1]), Some(0.5));
        assert_eq!(importance(&s.objects[2]), Some(0.75));
        let Shape::Csg { children, .. } = &s.objects[3].shape else {
            panic!("a union")
        };
        assert_eq!(importance(&children[0]), Some(0.75));
        check_diagnostics(
            "sphere { 0, 1 radiosity { importance 0 } }",
            expect![[r#"
                scene.pov:2:27: error: importance must be greater than 0 and at most 1
                    2 | sphere { 0, 1 radiosity { importance 0 } }
                      |                           ^~~~~~~~~~
            "#]],
        );
    }

    #[test]
    fn subsurface_settings_and_translucency_are_read() {
        let s = evaluate_ok(
            "global_settings { subsurface { samples 20, 30 radiosity on } mm_per_unit 25.4 }
             sphere { 0, 1 finish { subsurface { translucency <1, 0.5, 0.25> } } }",
        );
        let sslt = s.settings.subsurface.expect("subsurface on");
        assert_eq!((sslt.samples, sslt.radiosity), ((20, 30), true));
        assert_eq!(s.settings.mm_per_unit, 25.4);
        let Some(texture) = &s.objects[0].texture else {
            panic!("a texture")
        };
        let crate::scene::Texture::Plain { finish, .. } = &**texture else {
            panic!("a plain texture")
        };
        assert_eq!(finish.translucency, Some(glam::DVec3::new(1.0, 0.5, 0.25)));
        assert_eq!(evaluate_ok("").settings.mm_per_unit, 10.0);
    }
}
