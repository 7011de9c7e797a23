//! The tracer: follows one ray into the world and shades what it meets with POV-Ray's
//! classic lighting model (ambient, emission, diffuse with brilliance, Blinn `specular`,
//! Phong `phong`), shadows included.

use crate::bvh::Bvh;
use crate::colour::Sample;
use crate::light::Light;
use crate::object::{Hit, Query};
use crate::ray::{Ray, RayKind};
use glam::DVec3;

/// Which computations the `Quality` setting allows (POV-Ray's levels 0 to 11).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Quality {
    /// Levels 0 and 1 show the pigment under full ambient light, nothing else.
    pub lighting: bool,
    pub shadows: bool,
}

impl Quality {
    pub fn from_level(level: u8) -> Quality {
        Quality {
            lighting: level >= 2,
            shadows: level >= 4,
        }
    }
}

/// Everything a ray can meet, built from the scene once.
#[derive(Debug, Clone)]
pub struct World {
    pub bvh: Bvh,
    pub lights: Vec<Light>,
    /// What a ray that meets nothing returns.
    pub background: Sample,
    pub ambient_light: DVec3,
    pub quality: Quality,
    /// The size of the scene, from which the self-intersection tolerance follows so that
    /// scenes at any scale trace alike.
    pub scale: f64,
}

/// A tracer for one thread: the world and scratch space reused from ray to ray.
pub struct Tracer<'w> {
    world: &'w World,
    scratch: Vec<Hit<'w>>,
}

impl<'w> Tracer<'w> {
    pub fn new(world: &'w World) -> Tracer<'w> {
        Tracer {
            world,
            scratch: Vec::new(),
        }
    }

    /// The smallest ray parameter that counts as leaving `p`, relative to the scene's size.
    fn tolerance(&self, p: DVec3) -> f64 {
        1e-9 * (p.abs().max_element() + self.world.scale)
    }

    /// The sample a camera ray brings back.
    pub fn trace_primary(&mut self, ray: &Ray) -> Sample {
        let q = Query::new(
            *ray,
            RayKind::Primary,
            self.tolerance(ray.origin),
            f64::INFINITY,
        );
        match self.world.bvh.nearest(&q, &mut self.scratch) {
            None => self.world.background,
            Some(hit) => Sample::new(self.shade(ray, &hit), 0.0),
        }
    }

    fn shade(&mut self, ray: &Ray, hit: &Hit<'w>) -> DVec3 {
        let p = ray.at(hit.t);
        let leaf = hit.leaf;
        let mut normal = leaf.normal(p, hit.part);
        // POV-Ray lights the side the ray sees.
        if normal.dot(ray.direction) > 0.0 {
            normal = -normal;
        }
        let material = &leaf.material;
        let pigment = material.pigment.colour_at(p);
        let finish = &*material.finish;
        if !self.world.quality.lighting {
            return pigment.rgb;
        }
        let opacity = (1.0 - pigment.filter - pigment.transmit).clamp(0.0, 1.0);
        let mut colour =
            pigment.rgb * (finish.ambient * self.world.ambient_light + finish.emission) * opacity;
        let world = self.world;
        for light in &world.lights {
            let Some(incoming) = light.incoming(p) else {
                continue;
            };
            let cos_in = normal.dot(incoming.direction);
            if cos_in <= 0.0 {
                continue;
            }
            if !light.shadowless && world.quality.shadows && self.blocked(p, &incoming) {
                continue;
            }
            if finish.diffuse > 0.0 {
                let intensity = if finish.brilliance == 1.0 {
                    cos_in
                } else {
                    cos_in.powf(finish.brilliance)
                };
                colour += incoming.colour * pigment.rgb * (finish.diffuse * intensity * opacity);
            }
            // POV-Ray's shadowless (fill) lights cause no highlights.
            if light.shadowless {
                continue;
            }
            if finish.specular > 0.0 {
                let halfway = incoming.direction - ray.direction;
                let len = halfway.length();
                if len > 0.0 {
                    let cos = normal.dot(halfway) / len;
                    if cos > 0.0 {
                        let intensity = finish.specular * cos.powf(1.0 / finish.roughness);
                        colour +=
                            highlight(incoming.colour, pigment.rgb, finish.metallic) * intensity;
                    }
                }
            }
            if finish.phong > 0.0 {
                let reflected = ray.direction - 2.0 * ray.direction.dot(normal) * normal;
                let cos = reflected.dot(incoming.direction);
                if cos > 0.0 {
                    let intensity = finish.phong * cos.powf(finish.phong_size);
                    colour += highlight(incoming.colour, pigment.rgb, finish.metallic) * intensity;
                }
            }
        }
        colour
    }

    /// Whether an object casting shadows stands between `p` and the light.
    fn blocked(&mut self, p: DVec3, incoming: &crate::light::Incoming) -> bool {
        let eps = self.tolerance(p);
        let q = Query::new(
            Ray::new(p, incoming.direction),
            RayKind::Shadow,
            eps,
            incoming.distance - eps,
        );
        self.world.bvh.nearest(&q, &mut self.scratch).is_some()
    }
}

/// The colour of a highlight: the light's, tinted towards the surface's by `metallic`.
fn highlight(light: DVec3, surface: DVec3, metallic: f64) -> DVec3 {
    if metallic > 0.0 {
        light * (DVec3::ONE + metallic * (surface - DVec3::ONE))
    } else {
        light
    }
}
