//! Patterns whose heads carry more than a keyword and a few numbers: `object { }` (an
//! object and, after it, the two entries), `facets` and its parameters, `slope { }`,
//! `pavement` and its parameters.

use super::tokens::Token;
use super::value::Value;
use super::{Evaluator, Result};
use crate::scene::{Altitude, Pattern, PatternKind, Pavement, Slope, SlopeTarget};
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
            SLOPE_KW => PatternKind::Slope(Box::new(self.slope(keyword)?)),
            AOI_KW => PatternKind::Aoi,
            PAVEMENT_KW => PatternKind::Pavement(Pavement {
                sides: 3,
                tiles: 1,
                pattern: 1,
                form: 0,
                exterior: 0,
                interior: 0,
            }),
            FACETS_KW => PatternKind::Facets {
                coords: 0.0,
                size: 0.1,
                metric: 2.0,
            },
            _ => return Ok(None),
        }))
    }

    /// A parameter of `pavement`; false when `token` is not one. Whether the pattern
    /// number exists for the cells and tiles is known only once all are read, and is
    /// checked with the pattern (`pattern::check`).
    fn pavement_parameter(&mut self, pavement: &mut Pavement, token: &Token) -> Result<bool> {
        let (low, high, what) = match token.kind {
            NUMBER_OF_SIDES_KW => (3, 6, "number_of_sides of pavement must be 3, 4 or 6"),
            NUMBER_OF_TILES_KW => (1, 6, "number_of_tiles of pavement must be from 1 to 6"),
            PATTERN_KW => (1, 35, "pattern of pavement must be from 1 to 35"),
            // Whether form 3 fits the cells is checked with the pattern.
            FORM_KW => (0, 3, "form of pavement must be from 0 to 3"),
            EXTERIOR_KW => (0, 2, "exterior of pavement must be 0, 1 or 2"),
            INTERIOR_KW => (0, 2, "interior of pavement must be 0, 1 or 2"),
            _ => return Ok(false),
        };
        let value = self.int()?;
        if !(low..=high).contains(&value) || (token.kind == NUMBER_OF_SIDES_KW && value == 5) {
            return Err(self.error_at(token, what));
        }
        let value = value as u8;
        match token.kind {
            NUMBER_OF_SIDES_KW => pavement.sides = value,
            NUMBER_OF_TILES_KW => pavement.tiles = value,
            FORM_KW => pavement.form = value,
            EXTERIOR_KW => pavement.exterior = value,
            INTERIOR_KW => pavement.interior = value,
            _ => pavement.pattern = value,
        }
        Ok(true)
    }

    /// The rest of `slope <Direction>`, `slope { <Direction> [, Lo, Hi] [altitude
    /// <Altitude> [, Lo, Hi]] }` or `slope { point_at <Point> [, Lo, Hi] }`.
    fn slope(&mut self, keyword: &Token) -> Result<Slope> {
        if !self.eat(L_BRACE)? {
            let direction = self.vector()?;
            return self.slope_towards(keyword, direction, None, None);
        }
        let first = self.next()?;
        if first.kind == POINT_AT_KW {
            let at = self.vector()?;
            let range = self.opt_slope_range()?;
            let token = self.next()?;
            if token.kind == ALTITUDE_KW {
                return Err(self.error_at(
                    &token,
                    "altitude cannot be used with point_at in a slope pattern",
                ));
            }
            self.unget(token);
            self.expect(R_BRACE, "'}'")?;
            return Ok(Slope {
                towards: SlopeTarget::Point(at),
                weight: 1.0,
                range,
                altitude: None,
            });
        }
        self.unget(first);
        let direction = self.vector()?;
        let range = self.opt_slope_range()?;
        let altitude = if self.eat(ALTITUDE_KW)? {
            let axis = self.vector()?;
            Some((axis, self.opt_slope_range()?))
        } else {
            None
        };
        self.expect(R_BRACE, "'}'")?;
        self.slope_towards(keyword, direction, range, altitude)
    }

    /// `, Lo, Hi` after a slope's direction or altitude, if it is there; two equal values
    /// count as none, as in POV-Ray.
    fn opt_slope_range(&mut self) -> Result<Option<(f64, f64)>> {
        if !self.eat(COMMA)? {
            return Ok(None);
        }
        let lo = self.float()?;
        self.expect(COMMA, "','")?;
        let hi = self.float()?;
        Ok((lo != hi).then_some((lo, hi)))
    }

    fn slope_towards(
        &mut self,
        keyword: &Token,
        direction: glam::DVec3,
        range: Option<(f64, f64)>,
        altitude: Option<(glam::DVec3, Option<(f64, f64)>)>,
    ) -> Result<Slope> {
        let altitude = altitude
            .filter(|(axis, _)| axis.length() > 0.0)
            .map(|(axis, range)| Altitude {
                axis: axis.normalize(),
                weight: axis.length(),
                range: range.unwrap_or((0.0, 1.0)),
            });
        let weight = direction.length();
        if weight == 0.0 && altitude.is_none() {
            return Err(self.error_at(
                keyword,
                "a slope pattern needs a direction or an altitude that is not zero",
            ));
        }
        Ok(Slope {
            towards: SlopeTarget::Direction(direction.normalize_or_zero()),
            weight,
            range,
            altitude,
        })
    }

    /// A parameter of a pattern kept here, after the pattern's head; false when `token` is
    /// not one for this pattern.
    pub(super) fn pattern_parameter(
        &mut self,
        pattern: &mut Pattern,
        token: &Token,
    ) -> Result<bool> {
        if let PatternKind::Pavement(pavement) = &mut pattern.kind {
            return self.pavement_parameter(pavement, token);
        }
        if let PatternKind::DensityFile { trilinear, .. } = &mut pattern.kind
            && token.kind == INTERPOLATE_KW
        {
            let at = self.next()?;
            self.unget(at.clone());
            *trilinear = match self.int()? {
                0 => false,
                1 => true,
                2 => {
                    return Err(self
                        .unsupported(&at, "tricubic density_file interpolation (interpolate 2)"));
                }
                other => {
                    return Err(self.error_at(
                        &at,
                        format!("interpolate must be 0, 1 or 2 for a density_file, not {other}"),
                    ));
                }
            };
            return Ok(true);
        }
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
        let evaluation = evaluate_with(
            "scene.pov",
            &files,
            &EvalOptions::default(),
            &SpheresOnly::default(),
        );
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

    /// The pattern of the first object's plain pigment in `text`.
    fn first_pattern(text: &str) -> crate::scene::Pattern {
        let files = MemoryFiles::new().with("scene.pov", text);
        let scene = evaluate("scene.pov", &files, &EvalOptions::default())
            .scene
            .expect("the scene evaluates");
        let texture = scene.objects[0].texture.clone().expect("a texture");
        let crate::scene::Texture::Plain { pigment, .. } = &*texture else {
            panic!("not plain")
        };
        let crate::scene::Pigment::Pattern { pattern, .. } = pigment else {
            panic!("not a pattern")
        };
        crate::scene::Pattern::clone(pattern)
    }

    #[test]
    fn slope_reads_its_direction_ranges_and_altitude() {
        use crate::scene::{Altitude, PatternKind, Slope, SlopeTarget};
        let slope = |body: &str| match first_pattern(&format!(
            "plane {{ y, 0 pigment {{ slope {body} }} }}"
        ))
        .kind
        {
            PatternKind::Slope(s) => *s,
            other => panic!("{other:?}"),
        };
        assert_eq!(
            slope("{ 2*y, 0.2, 0.7 altitude 3*x, -1, 1 }"),
            Slope {
                towards: SlopeTarget::Direction(DVec3::Y),
                weight: 2.0,
                range: Some((0.2, 0.7)),
                altitude: Some(Altitude {
                    axis: DVec3::X,
                    weight: 3.0,
                    range: (-1.0, 1.0),
                }),
            }
        );
        // Without braces, a direction alone; equal ends and a zero altitude count as none.
        let plain = slope("<0, 0, 3>");
        assert_eq!(plain.towards, SlopeTarget::Direction(DVec3::Z));
        assert_eq!(slope("{ 3*z, 0.5, 0.5 altitude 0 }"), plain);
        let at = slope("{ point_at <1, 2, 3>, 0, 0.5 }");
        assert_eq!(at.towards, SlopeTarget::Point(DVec3::new(1.0, 2.0, 3.0)));
        assert_eq!(at.range, Some((0.0, 0.5)));
    }
}
