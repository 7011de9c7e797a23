//! `light_group { objects... light_source {...}... [global_lights on] transformations }`.

use super::light::transform_light;
use super::object::{collect_lights, transform_object};
use super::value::Value;
use super::{Evaluator, Result};
use crate::scene::{LightGroup, Object, Origin, Shape};
use syntax::SyntaxKind::*;

impl Evaluator<'_> {
    /// The items of `light_group`, read from after its opening brace up to its closing one.
    /// A light group takes no object modifiers besides transformations.
    pub fn light_group(&mut self, origin: Origin) -> Result<Object> {
        let first = self.next()?;
        let declared = match first.slot.as_ref().map(|s| s.borrow().clone()) {
            Some(Value::Object(object)) => match &object.shape {
                Shape::LightGroup(group) => Some(LightGroup::clone(group)),
                _ => None,
            },
            _ => None,
        };
        let mut group = declared.unwrap_or_else(|| {
            self.unget(first);
            LightGroup {
                objects: Vec::new(),
                lights: Vec::new(),
                global_lights: false,
            }
        });
        loop {
            let token = self.next()?;
            match token.kind {
                R_BRACE => {
                    self.unget(token);
                    return Ok(Object::new(Shape::LightGroup(Box::new(group)), origin));
                }
                LIGHT_SOURCE_KW => {
                    self.unget(token);
                    group.lights.push(self.light_source()?);
                }
                GLOBAL_LIGHTS_KW => group.global_lights = self.optional_bool()?,
                kind if Self::starts_transform(kind) => {
                    let t = self.transformation(&token)?;
                    for object in &mut group.objects {
                        transform_object(object, &t);
                    }
                    for light in &mut group.lights {
                        transform_light(light, &t);
                    }
                }
                kind if Self::starts_object(kind) => {
                    self.unget(token);
                    let mut object = self.object()?;
                    // Lights inside the group's CSG objects belong to the group.
                    collect_lights(&mut object, &mut group.lights);
                    group.objects.push(object);
                }
                _ => {
                    return Err(self.error_at(
                        &token,
                        format!(
                            "expected an object, light_source, global_lights, a \
                             transformation or '}}' in light_group, found {}",
                            self.describe(&token)
                        ),
                    ));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::eval::tests::{evaluate_err, evaluate_ok};
    use crate::scene::{LightGroup, Scene, Shape};

    fn group(scene: &Scene, i: usize) -> &LightGroup {
        match &scene.objects[i].shape {
            Shape::LightGroup(group) => group,
            other => panic!("not a light group: {other:?}"),
        }
    }

    #[test]
    fn group_lights_stay_in_their_group() {
        let scene = evaluate_ok(
            "light_source { <0, 10, 0> rgb 1 }
             #declare G = light_group {
               light_source { <1, 0, 0> rgb 1 }
               union { sphere { 0, 1 } sphere { x, 1 } light_source { <2, 0, 0> rgb 1 } }
             }
             light_group { G global_lights translate 5*y }",
        );
        assert_eq!(
            scene.lights.len(),
            1,
            "only the scene's own light is global"
        );
        let g = group(&scene, 0);
        assert!(g.global_lights);
        assert_eq!(g.objects.len(), 1);
        let positions: Vec<_> = g.lights.iter().map(|l| l.position.to_array()).collect();
        assert_eq!(positions, vec![[1.0, 5.0, 0.0], [2.0, 5.0, 0.0]]);
    }

    #[test]
    fn light_groups_take_no_other_modifiers() {
        let error = evaluate_err("light_group { sphere { 0, 1 } pigment { rgb 1 } }");
        assert!(
            error.starts_with("expected an object, light_source, global_lights"),
            "{error}"
        );
    }
}
