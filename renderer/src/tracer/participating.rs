//! How fog, rainbows, the sky sphere and media act on the rays the tracer follows. Kept
//! beside the tracer so that scenes without them pay one flag test per ray.

use super::{Tracer, World, greyscale};
use crate::colour::Sample;
use crate::interior::Interior;
use crate::light::Incoming;
use crate::media::{self, Incident, Medium, Passage};
use crate::photons;
use crate::ray::{Ray, RayKind};
use glam::DVec3;

/// How far media reach along a ray that meets nothing. POV-Ray samples them to this
/// distance (its largest), measured on 3.7: atmospheric `emission 1e-11` against the
/// background shows 0.2, and `absorption 1e-11` lets through exp(-0.2) of it.
const MISSED_MEDIA_DEPTH: f64 = 2.0e10;

impl<'w> Tracer<'w> {
    /// What a ray sees when it meets nothing: the sky sphere over the background, or the
    /// background.
    pub(crate) fn missed(&self, ray: &Ray, kind: RayKind) -> Sample {
        let world = self.world;
        // Radiosity rays see the sky as reflections do.
        let reflected = matches!(kind, RayKind::Reflected | RayKind::Radiosity);
        let background = if reflected {
            Sample::new(world.reflected_background, 0.0)
        } else {
            world.background
        };
        match &world.sky {
            Some(sky) if reflected || !sky.reflections_only => {
                sky.sample(ray.direction, background)
            }
            _ => background,
        }
    }

    /// `sample`, seen along `ray` to `depth` (its parameter; infinite for a ray that met
    /// nothing) through the media of the containers the ray is in, the atmospheric media,
    /// rainbows and fogs. Media along a ray that met nothing are sampled to
    /// [`MISSED_MEDIA_DEPTH`], so atmospheric media glow and dim against the background.
    /// Inside a solid (not hollow) object none of them shows, as in POV-Ray, where even a
    /// solid container's own media stay dark.
    ///
    /// Every medium along the stretch is lit by the lights of `light_set`: those of the
    /// object the stretch ends at (the scene's lights where it meets nothing). That is
    /// what POV-Ray's pictures show: a light group's light brightens the media in front
    /// of its objects, its own or the atmosphere's, and no others.
    pub(crate) fn participate(
        &mut self,
        ray: &Ray,
        depth: f64,
        light_set: u32,
        sample: Sample,
    ) -> Sample {
        let world = self.world;
        let length = ray.direction.length();
        if length == 0.0 {
            return sample;
        }
        let unit = Ray::new(ray.origin, ray.direction / length);
        let depth = depth * length;
        if self.inside.interiors().iter().any(|i| !i.hollow) {
            return sample;
        }
        let atmosphere = world.atmosphere.as_deref();
        // Most rays of a foggy scene or one with a rainbow cross no medium: they skip the
        // media's set-up (a copy of the interiors, a seed) along with the media.
        let has_media = atmosphere.is_some_and(|a| !a.media.is_empty())
            || self.inside.interiors().iter().any(|i| !i.media.is_empty());
        let mut passage = Passage::CLEAR;
        if has_media {
            let reach = depth.min(MISSED_MEDIA_DEPTH);
            let inside = self.inside.interiors().to_vec();
            let mut splits = Vec::new();
            // The containers' media and the atmosphere's, sampled together.
            let media: Vec<&Medium> = inside
                .iter()
                .flat_map(|i| &i.media)
                .chain(atmosphere.iter().flat_map(|a| &a.media))
                .collect();
            if media.iter().any(|m| m.scatters()) {
                for light in world.light_set(light_set).filter(|l| l.media_interaction) {
                    light.beam_crossings(&unit, (0.0, reach), &mut splits);
                }
                splits.sort_by(f64::total_cmp);
            }
            let seed = media::seed(&unit);
            // Media photons light every medium of a stretch where one of them collects.
            let photons = world
                .photons
                .as_ref()
                .and_then(|p| p.in_media.as_ref())
                .filter(|_| photons::collecting(photons::media_within(world, &inside)));
            let mut lighting = |p: DVec3, out: &mut Vec<Incident>| {
                let lit_at = within_stretch(world, &unit, reach, p);
                self.media_lights(lit_at, &inside, light_set, out);
                if let Some(photons) = photons {
                    photons.lights_at(p, &mut self.gather_scratch.found, out);
                }
            };
            let seed = seed ^ 0xd6e8_feb8_6659_fd93;
            passage = media::passage(&media, &unit, (0.0, reach), &splits, seed, &mut lighting);
        }
        let mut seen = Sample::new(
            sample.colour * passage.transmittance + passage.added,
            sample.transmit * greyscale(passage.transmittance).clamp(0.0, 1.0),
        );
        if let Some(atmosphere) = atmosphere.filter(|a| a.has_veils()) {
            seen = atmosphere.apply_veil(unit.origin, unit.direction, depth, seen);
        }
        seen
    }

    /// The light of every light source of `light_set` that interacts with media arriving
    /// at `p`, a media sample inside the containers `inside`, after shadows (none of
    /// them is shadowless: those leave media dark).
    fn media_lights(
        &mut self,
        p: DVec3,
        inside: &[&'w Interior],
        light_set: u32,
        out: &mut Vec<Incident>,
    ) {
        let world = self.world;
        for light in world.light_set(light_set).filter(|l| l.media_interaction) {
            let Some(incoming) = light.incoming(p) else {
                continue;
            };
            let mut colour = incoming.colour;
            if world.quality.shadows {
                self.shadow_start.extend_from_slice(inside);
                // As at surfaces, refracting photon targets stop the light (in `shadowed`);
                // without photons in media nothing brings it back there, as in POV-Ray.
                colour = self.shadowed(light, p, incoming.direction, incoming.distance, colour);
                self.shadow_start.clear();
            } else if self
                .projected_reach(light, p, incoming.direction, incoming.distance)
                .is_none()
            {
                continue;
            }
            if light.media_attenuation && world.atmosphere.is_some() {
                colour *= self.atmospheric_attenuation(p, &incoming);
            }
            if colour != DVec3::ZERO {
                out.push((incoming.direction, colour));
            }
        }
    }

    /// What fog and atmospheric media leave of a light on its way to `p`.
    pub(super) fn atmospheric_attenuation(&self, p: DVec3, incoming: &Incoming) -> DVec3 {
        let Some(atmosphere) = &self.world.atmosphere else {
            return DVec3::ONE;
        };
        let end = p + incoming.direction * incoming.distance;
        let mut through = atmosphere
            .media
            .iter()
            .fold(DVec3::ONE, |t, m| t * m.transmittance(p, end));
        if atmosphere.has_veils() {
            through *= atmosphere
                .veil(p, incoming.direction, incoming.distance)
                .through;
        }
        through
    }
}

/// Where the light arriving at the media sample `p` of the stretch of `ray` from its
/// origin to `reach` is measured: a hair inside the stretch. The samples at its ends lie
/// on the surfaces the ray starts from and ends at, and a shadow ray leaving through such
/// a surface crosses it nearer than any hit is found; it would then count the container's
/// media all the way to the light. POV-Ray's renders show those samples lit as the
/// samples next to them are (measured: a box of scattering media whose top lies just
/// above the viewing ray, lit from above, shows 0.1322 there, 4% more than when the
/// entry sample's light crossed the box's media to the light).
fn within_stretch(world: &World, ray: &Ray, reach: f64, p: DVec3) -> DVec3 {
    let margin = 1000.0 * world.tolerance(p);
    if reach <= 2.0 * margin {
        return ray.at(reach * 0.5);
    }
    let t = (p - ray.origin).dot(ray.direction);
    if t < margin || t > reach - margin {
        ray.at(t.clamp(margin, reach - margin))
    } else {
        p
    }
}

#[cfg(test)]
mod tests {
    use crate::build::world_of_source as world;
    use crate::tracer::centre;
    use glam::DVec3;

    /// Asserts that every channel of `seen` lies within `tolerance` of `level`.
    fn assert_grey(seen: DVec3, level: f64, tolerance: f64) {
        assert!(
            (seen - DVec3::splat(level)).abs().max_element() < tolerance,
            "{seen} against {level}"
        );
    }

    #[test]
    fn scenes_without_atmosphere_or_media_skip_the_check() {
        let plain = world("sphere { 0, 1 pigment { rgb 1 } }");
        assert!(!plain.participating && plain.camera_interiors.is_empty());
        assert!(plain.atmosphere.is_none() && plain.sky.is_none());
        let foggy = world("sphere { 0, 1 } fog { distance 3 rgb 1 }");
        assert!(foggy.participating);
        let media = world("sphere { 0, 1 hollow interior { media { emission 1 } } }");
        assert!(media.participating && media.atmosphere.is_none());
    }

    #[test]
    fn media_take_the_lights_of_the_object_their_stretch_ends_at() {
        // A red scene light and a green group light. The group's ball holds a medium; the
        // group's clear ball holds none, but the box's medium around it stretches to it.
        let scene = |ball: &str| {
            format!(
                "camera {{ location <0, 0, -5> look_at 0 }}\n\
                 light_source {{ <-5, 3, -5> rgb <1, 0, 0> }}\n\
                 light_group {{ light_source {{ <5, 3, -5> rgb <0, 1, 0> }}\n\
                 sphere {{ 0, 1 hollow pigment {{ rgbt 1 }} {ball} }} }}"
            )
        };
        let own = scene("interior { media { scattering { 1, 0.5 } } }");
        let lit = centre(&world(&own), &own);
        assert!(lit.x == 0.0 && lit.y > 0.05, "{lit}");
        let clear = format!(
            "{}\nbox {{ -3, 3 hollow pigment {{ rgbt 1 }} \
             interior {{ media {{ scattering {{ 1, 0.2 }} }} }} }}",
            scene("")
        );
        let lit = centre(&world(&clear), &clear);
        // Red only from the box's far stretch, which ends at the box; green from the two
        // stretches that end at the ball, the second inside it (its `hollow` holds).
        assert!(lit.y > 2.0 * lit.x && lit.x > 0.0, "{lit}");
    }

    #[test]
    fn atmospheric_media_reach_far_along_rays_that_meet_nothing() {
        // POV-Ray 3.7 shows 0.2 for this glow against the background: 2e10 units of it.
        let glow = "camera { location <0, 0, -5> look_at 0 } media { emission 1e-11 }";
        let seen = centre(&world(glow), glow);
        assert_grey(seen, 0.2, 1e-9);
        // And as much absorption lets exp(-0.2) of the background through.
        let dim = "camera { location <0, 0, -5> look_at 0 } background { rgb 1 } \
                   media { absorption 1e-11 }";
        let seen = centre(&world(dim), dim);
        assert_grey(seen, (-0.2f64).exp(), 1e-9);
    }

    #[test]
    fn shadowless_lights_leave_media_dark() {
        // POV-Ray 3.7 scatters none of a shadowless light in media (measured: a box of
        // scattering media under a shadowless light stays black), though surfaces see it.
        let scene = |shadowless: &str| {
            format!(
                "camera {{ location <0, 0, -5> look_at 0 }}\n\
                 light_source {{ <-3, 0, -3> rgb 1 {shadowless} }}\n\
                 box {{ -2, 2 hollow pigment {{ rgbt 1 }} \
                 interior {{ media {{ scattering {{ 1, 0.1 }} }} }} }}"
            )
        };
        let lit = scene("");
        assert!(centre(&world(&lit), &lit).x > 0.05);
        let fill = scene("shadowless");
        assert_eq!(centre(&world(&fill), &fill), DVec3::ZERO);
    }

    #[test]
    fn light_crosses_a_containers_media_to_its_edge() {
        // A white disc in the middle of a slab of absorbing media, lit and seen from the
        // same side: the light crosses the 1 unit of media from the slab's face to the
        // disc, and the view ray the same; nothing of the 9 units from there to the light.
        let scene = "camera { location <0, 0, -5> look_at 0 }\n\
             light_source { <0, 0, -10> rgb 1 }\n\
             disc { 0, -z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n\
             box { <-3, -3, -1>, <3, 3, 1> hollow pigment { rgbt 1 } \
             interior { media { absorption 0.5 } } }";
        let seen = centre(&world(scene), scene);
        let expected = (-1f64).exp();
        assert_grey(seen, expected, 1e-6);
    }

    #[test]
    fn light_on_the_face_a_ray_enters_by_is_not_dimmed_beyond_it() {
        // Scattering media lit from behind the camera: the light reaching the sample at
        // depth d crosses d units of media, the sample on the entry face none, however
        // close to the face its shadow ray leaves the box. Method 3's 6 steps of 0.5
        // each add their mean light dimmed from their start.
        let scene = "camera { location <0, 0, -5> look_at 0 }\n\
             light_source { <0, 0, -10> rgb 1 }\n\
             box { <-3, -3, -1.5>, <3, 3, 1.5> hollow pigment { rgbt 1 } \
             interior { media { scattering { 1, 0.1 } } } }";
        let seen = centre(&world(scene), scene);
        let source = |k: i32| 0.1 * (-0.05 * f64::from(k)).exp();
        let expected: f64 = (0..6)
            .map(|k| (-0.05 * f64::from(k)).exp() * 0.5 * (source(k) + source(k + 1)) / 2.0)
            .sum();
        assert_grey(seen, expected, 1e-6);
    }

    #[test]
    fn media_of_a_stretch_are_sampled_together() {
        // Scattering without extinction beside absorbing media in one box shows what one
        // medium with both does (POV-Ray: 0.1092 for both at the centre of such a box):
        // the absorbing medium dims the scattered light on its way to the eye.
        let scene = |media: &str| {
            format!(
                "camera {{ location <0, 0, -6> look_at 0 }}\n\
                 light_source {{ <0, 5, -2> rgb 0.5 }}\n\
                 box {{ <-3, -2, -1.5>, <3, 2, 1.5> hollow pigment {{ rgbt 1 }} \
                 interior {{ {media} }} }}"
            )
        };
        let one = scene("media { scattering { 1, 0.1 } }");
        let two = scene("media { scattering { 1, 0.1 extinction 0 } } media { absorption 0.1 }");
        let one = centre(&world(&one), &one);
        let two = centre(&world(&two), &two);
        assert!((one - two).abs().max_element() < 1e-12, "{one} {two}");
    }

    #[test]
    fn a_camera_in_a_hollow_part_of_a_union_sees_its_media() {
        // The union's first part is solid but far from the camera: only the glowing
        // sphere holds it.
        let scene = "camera { location <0, 0, -1> look_at 0 }\n\
             union { box { 10, 11 } sphere { 0, 5 hollow pigment { rgbt 1 } \
             interior { media { emission 0.1 } } } }";
        let glow = centre(&world(scene), scene);
        assert!(glow.min_element() > 0.1, "{glow}");
    }

    #[test]
    fn solid_objects_keep_media_and_fog_out() {
        // The camera inside a solid box sees neither the fog nor a hollow container's
        // glow, as in POV-Ray; made hollow, the box lets both show.
        let scene = |hollow: &str| {
            format!(
                "camera {{ location <0, 0, -5> look_at 0 }}\n\
                 box {{ -10, 10 {hollow} pigment {{ rgbt 1 }} }}\n\
                 sphere {{ 0, 1 hollow pigment {{ rgbt 1 }} interior {{ media {{ emission 0.5 }} }} }}"
            )
        };
        let solid = scene("");
        assert_eq!(centre(&world(&solid), &solid), DVec3::ZERO);
        let hollow = scene("hollow");
        let glow = centre(&world(&hollow), &hollow);
        assert_grey(glow, 1.0, 1e-9);
    }
}
