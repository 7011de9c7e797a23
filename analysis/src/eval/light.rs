//! `light_source { }` in all its forms.

use super::object::transform_object;
use super::value::Value;
use super::{Evaluator, Result};
use crate::scene::{AreaLight, Light, LightKind, Object, Transform};
use glam::DVec3;
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// A light source statement.
    pub fn light_source(&mut self) -> Result<Light> {
        let keyword = self.expect(LIGHT_SOURCE_KW, "'light_source'")?;
        self.expect(L_BRACE, "'{'")?;
        let first = self.next()?;
        let mut light = match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Light(light)) => Light::clone(&light),
            _ => {
                self.unget(first);
                let position = self.vector()?;
                self.eat(COMMA)?;
                let colour = self.scene_colour()?;
                let mut light = Light::point(position, colour);
                light.origin = Some(self.span(&keyword));
                light
            }
        };
        // `area_illumination on`, which shades with each point of an area light's grid.
        let mut area_illumination = None;
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => {
                    if let (Some(at), Some(_)) = (&area_illumination, &light.area) {
                        return Err(self.unsupported(at, "area_illumination"));
                    }
                    return Ok(light);
                }
                SPOTLIGHT_KW => {
                    light.kind = LightKind::Spotlight {
                        point_at: DVec3::Z,
                        radius: 30.0,
                        falloff: 45.0,
                        tightness: 0.0,
                    }
                }
                CYLINDER_KW => {
                    light.kind = LightKind::Cylinder {
                        point_at: DVec3::Z,
                        radius: 0.75,
                        falloff: 1.0,
                        tightness: 0.0,
                    }
                }
                PARALLEL_KW => {
                    light.kind = LightKind::Parallel {
                        point_at: DVec3::ZERO,
                    }
                }
                POINT_AT_KW => {
                    let target = self.vector()?;
                    match &mut light.kind {
                        LightKind::Spotlight { point_at, .. }
                        | LightKind::Cylinder { point_at, .. }
                        | LightKind::Parallel { point_at } => *point_at = target,
                        LightKind::Point => {}
                    }
                }
                RADIUS_KW | FALLOFF_KW | TIGHTNESS_KW => {
                    let value = self.float()?;
                    if let LightKind::Spotlight {
                        radius,
                        falloff,
                        tightness,
                        ..
                    }
                    | LightKind::Cylinder {
                        radius,
                        falloff,
                        tightness,
                        ..
                    } = &mut light.kind
                    {
                        match token.kind {
                            RADIUS_KW => *radius = value,
                            FALLOFF_KW => *falloff = value,
                            _ => *tightness = value,
                        }
                    }
                }
                AREA_LIGHT_KW => {
                    let axis1 = self.vector()?;
                    self.eat(COMMA)?;
                    let axis2 = self.vector()?;
                    self.eat(COMMA)?;
                    let size1 = self.int()?.max(1) as u32;
                    self.eat(COMMA)?;
                    let size2 = self.int()?.max(1) as u32;
                    light.area = Some(AreaLight {
                        axis1,
                        axis2,
                        size1,
                        size2,
                        adaptive: 0,
                        jitter: false,
                        circular: false,
                        orient: false,
                    });
                }
                ADAPTIVE_KW | JITTER_KW | CIRCULAR_KW | ORIENT_KW => {
                    let adaptive = if token.kind == ADAPTIVE_KW {
                        self.int()?.max(0) as u32
                    } else {
                        0
                    };
                    let on = if token.kind == ADAPTIVE_KW {
                        true
                    } else {
                        self.optional_bool()?
                    };
                    // Without an area light these change nothing, as in POV-Ray.
                    let Some(area) = &mut light.area else {
                        continue;
                    };
                    match token.kind {
                        ADAPTIVE_KW => area.adaptive = adaptive,
                        JITTER_KW => area.jitter = on,
                        CIRCULAR_KW => area.circular = on,
                        _ => area.orient = on,
                    }
                }
                FADE_DISTANCE_KW => light.fade_distance = Some(self.float()?),
                FADE_POWER_KW => light.fade_power = self.float()?,
                SHADOWLESS_KW => light.shadowless = true,
                MEDIA_INTERACTION_KW => light.media_interaction = self.optional_bool()?,
                MEDIA_ATTENUATION_KW => light.media_attenuation = self.optional_bool()?,
                AREA_ILLUMINATION_KW => {
                    if self.optional_bool()? {
                        area_illumination = Some(token.clone());
                    }
                }
                LOOKS_LIKE_KW => {
                    let mut object = self.braced_object()?;
                    // POV-Ray moves the object to where the light is now (the light's
                    // later transformations move both) and lets the light out of it.
                    transform_object(&mut object, &Transform::translate(light.position));
                    object.flags.no_shadow = true;
                    light.looks_like = Some(Box::new(object));
                }
                PROJECTED_THROUGH_KW => {
                    light.projected_through = Some(Box::new(self.braced_object()?));
                }
                PHOTONS_KW => self.light_photons(&mut light.photons)?,
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    transform_light(&mut light, &t);
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected a light_source item or '}}', found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }

    /// `{ OBJECT }` after `looks_like` or `projected_through`.
    fn braced_object(&mut self) -> Result<Object> {
        self.expect(L_BRACE, "'{'")?;
        let object = self.object_or_identifier()?;
        self.expect(R_BRACE, "'}'")?;
        Ok(object)
    }
}

/// Moves a light with a transformation.
pub fn transform_light(light: &mut Light, t: &Transform) {
    light.position = t.point(light.position);
    match &mut light.kind {
        LightKind::Spotlight { point_at, .. }
        | LightKind::Cylinder { point_at, .. }
        | LightKind::Parallel { point_at } => {
            *point_at = t.point(*point_at);
        }
        LightKind::Point => {}
    }
    if let Some(area) = &mut light.area {
        area.axis1 = t.vector(area.axis1);
        area.axis2 = t.vector(area.axis2);
    }
    for object in light
        .looks_like
        .iter_mut()
        .chain(light.projected_through.iter_mut())
    {
        transform_object(object, t);
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::tests::{evaluate_err, evaluate_ok};
    use crate::scene::Shape;
    use glam::DVec3;

    /// As in POV-Ray's renders: the looks_like object moves to where the light is when
    /// it is given, and the light's later transformations move both; it casts no shadow.
    #[test]
    fn looks_like_objects_sit_at_the_light() {
        let scene = evaluate_ok(
            "light_source { <2, 1, 0> rgb 1 translate <-3, 0, 0>
               looks_like { sphere { <1, 0, 0>, 0.5 } } rotate z*90 }",
        );
        let light = &scene.lights[0];
        let shape = light.looks_like.as_ref().expect("a looks_like object");
        assert!(shape.flags.no_shadow);
        let centre = match &shape.shape {
            Shape::Sphere { center, .. } => shape.transform.point(*center),
            other => panic!("{other:?}"),
        };
        assert!((light.position - DVec3::new(-1.0, -1.0, 0.0)).length() < 1e-12);
        assert!(
            (centre - DVec3::new(-1.0, 0.0, 0.0)).length() < 1e-12,
            "{centre}"
        );
    }

    #[test]
    fn projection_objects_may_be_identifiers() {
        let scene = evaluate_ok(
            "#declare S = box { -1, 1 }
             light_source { <0, 5, 0> rgb 1 projected_through { S } }",
        );
        assert!(scene.lights[0].projected_through.is_some());
        assert_eq!(
            evaluate_err("light_source { 0, 1 projected_through { 3 } }"),
            "expected an object, found '3'"
        );
    }

    #[test]
    fn area_illumination_is_refused_on_area_lights_only() {
        evaluate_ok("light_source { 0, 1 area_illumination on }");
        assert_eq!(
            evaluate_err("light_source { 0, 1 area_light x, y, 2, 2 area_illumination on }"),
            "not supported yet: area_illumination"
        );
    }
}
