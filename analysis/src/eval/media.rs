//! `media { }` with its `scattering { }` and `density { }` blocks, and `density_map`.
//! A density is kept as a pigment whose colour at a point is the density there, so the
//! renderer evaluates it with the pigment machinery.

use super::expr::is_colour_keyword;
use super::value::Value;
use super::{Evaluator, Result};
use crate::scene::{
    BlendMap, Colour, Interior, Media, PatternKind, Pigment, Scattering, ScatteringKind, Transform,
};
use std::sync::Arc;
use syntax::SyntaxKind::{self, *};

impl Evaluator<'_> {
    /// `{ ... }` after `media`.
    pub fn media_body(&mut self) -> Result<Media> {
        self.expect(L_BRACE, "'{'")?;
        let first = self.next()?;
        let mut media = match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Media(m)) => Media::clone(&m),
            _ => {
                self.unget(first);
                Media::default()
            }
        };
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => return Ok(media),
                METHOD_KW => {
                    let method = self.int()?;
                    if !(1..=3).contains(&method) {
                        return Err(self.error_at(&token, "media method must be 1, 2 or 3"));
                    }
                    media.method = method as u8;
                }
                INTERVALS_KW => {
                    let intervals = self.int()?;
                    if intervals < 1 {
                        return Err(self.error_at(&token, "media needs at least one interval"));
                    }
                    media.intervals = intervals.min(10_000) as u32;
                }
                SAMPLES_KW => {
                    let min = self.int()?;
                    let max = if self.eat(COMMA)? { self.int()? } else { min };
                    if min < 1 || max < min {
                        return Err(self.error_at(
                            &token,
                            "media samples must be at least 1, and the maximum at least the minimum",
                        ));
                    }
                    // The budget keeps a typing slip from hanging a render.
                    media.samples = Some((min.min(10_000) as u32, max.min(10_000) as u32));
                }
                CONFIDENCE_KW => {
                    let confidence = self.float()?;
                    if !(0.0..1.0).contains(&confidence) {
                        return Err(
                            self.error_at(&token, "media confidence must be between 0 and 1")
                        );
                    }
                    media.confidence = confidence;
                }
                VARIANCE_KW => media.variance = self.float()?.max(0.0),
                RATIO_KW => media.ratio = self.float()?.clamp(0.0, 1.0),
                JITTER_KW => media.jitter = self.float()?.clamp(0.0, 1.0),
                AA_LEVEL_KW => media.aa_level = self.int()?.clamp(0, 16) as u32,
                AA_THRESHOLD_KW => media.aa_threshold = self.float()?.max(0.0),
                ABSORPTION_KW => media.absorption = self.scene_colour()?.rgb,
                EMISSION_KW => media.emission = self.scene_colour()?.rgb,
                SCATTERING_KW => media.scattering = Some(self.scattering()?),
                DENSITY_KW => media.density.push(self.density_body()?),
                COLLECT_KW => media.collect = self.optional_bool()?,
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    transform_media(&mut media, &t);
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a media item or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `{ type, colour [eccentricity e] [extinction x] }` after `scattering`.
    fn scattering(&mut self) -> Result<Scattering> {
        let open = self.expect(L_BRACE, "'{'")?;
        let at = self.next()?;
        self.unget(at.clone());
        let kind = self.int()?;
        self.eat(COMMA)?;
        let colour = self.scene_colour()?.rgb;
        let mut eccentricity = None;
        let mut extinction = 1.0;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => break,
                ECCENTRICITY_KW => eccentricity = Some((token.clone(), self.float()?)),
                EXTINCTION_KW => extinction = self.float()?,
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected eccentricity, extinction or '}}' in scattering, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
        let kind = match kind {
            1 => ScatteringKind::Isotropic,
            2 => ScatteringKind::MieHazy,
            3 => ScatteringKind::MieMurky,
            4 => ScatteringKind::Rayleigh,
            5 => {
                let e = eccentricity.take().map_or(0.0, |(_, e)| e);
                if e.abs() >= 1.0 {
                    return Err(
                        self.error_at(&open, "eccentricity must lie strictly between -1 and 1")
                    );
                }
                ScatteringKind::HenyeyGreenstein(e)
            }
            _ => {
                return Err(self.error_at(&at, "scattering type must be 1, 2, 3, 4 or 5"));
            }
        };
        if let Some((token, _)) = eccentricity {
            return Err(self.error_at(
                &token,
                "eccentricity only applies to scattering type 5 (Henyey-Greenstein)",
            ));
        }
        Ok(Scattering {
            kind,
            colour,
            extinction,
        })
    }

    /// `{ ... }` after `density`.
    pub fn density_body(&mut self) -> Result<Pigment> {
        self.expect(L_BRACE, "'{'")?;
        let density = self.density_inner(R_BRACE)?;
        self.expect(R_BRACE, "'}'")?;
        Ok(density)
    }

    /// The inside of a density up to (not including) `end`: `}` for `density { }`, `]` for
    /// a density map entry. Without a pattern the density is a constant 1.
    fn density_inner(&mut self, end: SyntaxKind) -> Result<Pigment> {
        let first = self.next()?;
        let mut density = match first.kind {
            IDENT => match first.slot.as_ref().map(|s| s.borrow().clone()) {
                Some(Value::Density(d)) => Pigment::clone(&d),
                Some(Value::Colour(_) | Value::Vector(_) | Value::Float(_)) => {
                    self.unget(first);
                    Pigment::Solid(self.scene_colour()?)
                }
                Some(other) => {
                    return Err(self.error_at(
                        &first,
                        format!("expected a density or color, found {}", other.type_name()),
                    ));
                }
                None => return Err(self.undeclared(&first)),
            },
            kind if starts_colour(kind) => {
                self.unget(first);
                Pigment::Solid(self.scene_colour()?)
            }
            IMAGE_MAP_KW => {
                return Err(self.unsupported(&first, self.text(&first)));
            }
            kind if super::texture::pattern_keyword(kind) => {
                let pattern = self.pattern(&first)?;
                let map = match super::texture::block_entries(&pattern.kind) {
                    Some(n) => self.block_densities(n)?,
                    None => grey_ramp(),
                };
                if matches!(pattern.kind, PatternKind::Object(_)) {
                    self.expect(R_BRACE, "'}'")?;
                }
                Pigment::Pattern {
                    pattern: Box::new(pattern),
                    map,
                }
            }
            _ => {
                self.unget(first);
                Pigment::Solid(Colour::gray(1.0))
            }
        };
        loop {
            let token = self.next()?;
            if token.kind == end {
                self.unget(token);
                return Ok(density);
            }
            if Self::starts_transform(token.kind) {
                let t = self.transformation(&token)?;
                super::texture::transform_pigment(&mut density, &t);
                continue;
            }
            if let Pigment::Pattern { pattern, map } = &mut density {
                match token.kind {
                    COLOR_MAP_KW | COLOUR_MAP_KW => {
                        *map = solid_entries(self.colour_map_body()?);
                        continue;
                    }
                    DENSITY_MAP_KW => {
                        *map = self.density_map_body()?;
                        super::texture::into_pattern_space(
                            map,
                            pattern,
                            super::texture::transform_pigment,
                        );
                        continue;
                    }
                    _ => {
                        if self.pattern_modifier(pattern, &token)? {
                            continue;
                        }
                    }
                }
            }
            return Err(self.error_at(
                &token,
                format!(
                    "expected a density modifier or '}}', found {}",
                    self.describe(&token)
                ),
            ));
        }
    }

    /// The densities or colours listed after a block pattern (`checker density {A}
    /// density {B}`).
    fn block_densities(&mut self, count: usize) -> Result<BlendMap<Pigment>> {
        let mut entries = Vec::new();
        while entries.len() < count {
            let token = self.next()?;
            let density = match token.kind {
                DENSITY_KW => self.density_body()?,
                kind if starts_colour(kind) => {
                    self.unget(token);
                    Pigment::Solid(self.scene_colour()?)
                }
                _ => {
                    self.unget(token);
                    break;
                }
            };
            entries.push((entries.len() as f64, density));
            self.eat(COMMA)?;
        }
        // Entries left out are POV-Ray's black and white.
        for i in entries.len()..count {
            let grey = if i == 0 { 1.0 } else { 0.0 };
            entries.push((i as f64, Pigment::Solid(Colour::gray(grey))));
        }
        Ok(BlendMap { entries })
    }

    /// `{ [value density_body] ... }` after `density_map`, or a density map identifier.
    pub fn density_map_body(&mut self) -> Result<BlendMap<Pigment>> {
        let declared = |value: &Value| match value {
            Value::DensityMap(map) => Some(BlendMap::clone(map)),
            _ => None,
        };
        self.blend_map_body("density_map", declared, |ev| {
            let value = ev.float()?;
            ev.eat(COMMA)?;
            let density = if ev.eat(DENSITY_KW)? {
                ev.density_body()?
            } else {
                ev.density_inner(R_BRACK)?
            };
            Ok((value, density))
        })
    }

    /// `media { }` inside `interior { }`.
    pub fn interior_media(&mut self, interior: &mut Interior) -> Result<()> {
        let media = self.media_body()?;
        interior.media.push(Arc::new(media));
        Ok(())
    }

    /// A `media { }` at the top level of a scene: atmospheric media.
    pub fn atmospheric_media(&mut self) -> Result<()> {
        let media = self.media_body()?;
        self.media.push(Arc::new(media));
        Ok(())
    }
}

/// Whether `kind` starts a colour: a colour keyword, a vector or a number.
fn starts_colour(kind: SyntaxKind) -> bool {
    is_colour_keyword(kind) || matches!(kind, LT | NUMBER)
}

/// A density pattern without a map gives its value as a grey density.
fn grey_ramp() -> BlendMap<Pigment> {
    BlendMap {
        entries: vec![
            (0.0, Pigment::Solid(Colour::BLACK)),
            (1.0, Pigment::Solid(Colour::gray(1.0))),
        ],
    }
}

fn solid_entries(map: BlendMap<Colour>) -> BlendMap<Pigment> {
    BlendMap {
        entries: map
            .entries
            .into_iter()
            .map(|(at, c)| (at, Pigment::Solid(c)))
            .collect(),
    }
}

/// Moves a media's densities (those given so far) by `t`.
pub fn transform_media(media: &mut Media, t: &Transform) {
    for density in &mut media.density {
        super::texture::transform_pigment(density, t);
    }
}

/// Moves an interior's media with its object.
pub fn transform_interior(interior: &mut Interior, t: &Transform) {
    for media in &mut interior.media {
        transform_media(Arc::make_mut(media), t);
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::tests::evaluate_ok;
    use crate::scene::{Pigment, ScatteringKind};
    use glam::DVec3;

    #[test]
    fn media_items_and_defaults() {
        let scene = evaluate_ok(
            "sphere { 0, 1 hollow pigment { rgbt 1 } interior { media { \
             emission 0.5 absorption <0.1, 0.2, 0.3> scattering { 5, 0.3 eccentricity 0.4 extinction 0.5 } \
             method 2 samples 4, 8 jitter 0.5 density { spherical } } } }",
        );
        let interior = scene.objects[0].interior.as_ref().unwrap();
        let media = &interior.media[0];
        assert_eq!(media.emission, DVec3::splat(0.5));
        assert_eq!(media.absorption, DVec3::new(0.1, 0.2, 0.3));
        let scattering = media.scattering.unwrap();
        assert_eq!(scattering.kind, ScatteringKind::HenyeyGreenstein(0.4));
        assert_eq!(scattering.extinction, 0.5);
        assert_eq!(
            (media.method, media.samples, media.jitter),
            (2, Some((4, 8)), 0.5)
        );
        assert!(matches!(media.density[0], Pigment::Pattern { .. }));
        let default = crate::scene::Media::default();
        assert_eq!(
            (default.method, default.intervals, default.aa_level),
            (3, 1, 3)
        );
    }

    #[test]
    fn declared_media_density_and_maps() {
        let scene = evaluate_ok(
            "#declare D = density { bozo density_map { [0 rgb 0] [1 density { rgb 1 }] } }\n\
             #declare M = media { emission 1 density { D scale 2 } }\n\
             media { M }",
        );
        assert_eq!(scene.media.len(), 1);
        let Pigment::Pattern { map, pattern } = &scene.media[0].density[0] else {
            panic!("a patterned density");
        };
        assert_eq!(map.entries.len(), 2);
        assert!(!pattern.transform.is_identity());
    }

    #[test]
    fn media_moves_with_its_object() {
        let scene = evaluate_ok(
            "sphere { 0, 1 hollow interior { media { density { spherical } } } translate x }",
        );
        let media = &scene.objects[0].interior.as_ref().unwrap().media[0];
        let Pigment::Pattern { pattern, .. } = &media.density[0] else {
            panic!("a patterned density");
        };
        assert_eq!(pattern.transform.point(DVec3::ZERO), DVec3::X);
    }

    #[test]
    fn bad_media_items_are_located_errors() {
        for (source, message) in [
            ("media { method 4 }", "media method must be 1, 2 or 3"),
            ("media { scattering { 6, 1 } }", "scattering type must be"),
            (
                "media { scattering { 1, 1 eccentricity 0.5 } }",
                "eccentricity only applies",
            ),
            ("media { samples 0 }", "media samples must be at least 1"),
        ] {
            let error = crate::eval::tests::evaluate_err(source);
            assert!(error.contains(message), "{source}: {error}");
        }
    }
}
