//! Shooting photons, as POV-Ray 3.7 documents it: each light that shoots photons aims a
//! spiral of them at each target's bounding sphere, rings of equal angular spacing
//! (`spacing` times the target's multiplier, over the distance to the sphere's centre)
//! from the pole pointing at the centre out to the sphere's rim, each ring holding as
//! many photons as its circumference takes, every direction jittered within its place.
//! `autostop`: once the spiral has passed that fraction of the rim and hit the target at
//! least once, a whole ring that misses the target ends it. Parallel and cylinder lights
//! shoot a planar spiral of parallel photons at the same spacing.
//!
//! Photons travel through `pass_through` objects untouched until they meet a target;
//! they are reflected and refracted by surfaces that reflect or refract photons (with the
//! surface's reflection colour, or its filter and transmit, as the tracer's rays are), and
//! split into the bands of the spectrum by dispersing interiors. The media of the
//! interiors they cross dim them; atmospheric media do not (POV-Ray 3.7's caustics are the
//! same with and without the light's `media_attenuation`, and no dimmer than the camera's
//! view through the atmosphere makes them). Once a photon has been
//! reflected or refracted, every collecting surface it meets keeps it. A photon carries
//! the light of its share of the spiral: the light's colour times the solid angle between
//! neighbours times the square of the distance it has travelled (POV-Ray's lights do not
//! fade with distance unless told to, and photons have to agree with direct light), scaled
//! at its first surface by the light's spotlight cone, cylinder tube and fading there.
//!
//! Jitter comes from a hash of the light, the target and the photon's place in the
//! spiral, so the map is the same on every run, thread count and platform.

use super::in_media::{self, Deposit};
use super::kdtree::Photon;
use super::{PhotonBudget, Target};
use crate::dispersion::Spectra;
use crate::interior::Interior;
use crate::light::Light;
use crate::object::{Hit, Leaf, Query};
use crate::ray::{Ray, RayKind};
use crate::refraction::{self, Inside};
use crate::tracer::{World, reflectivity};
use glam::DVec3;
use std::f64::consts::TAU;

/// How densely and how far photons go.
#[derive(Debug, Clone, Copy)]
pub struct Shooting {
    pub spacing: f64,
    pub jitter: f64,
    pub autostop: f64,
    pub max_trace_level: u32,
    pub adc_bailout: f64,
    /// How photons are left in media; `None` without `media` in the photons block.
    pub media: Option<Deposit>,
}

/// The spiral of one light at one target: where photons leave from and how they spread.
#[derive(Debug, Clone, Copy)]
struct Spiral {
    /// Unit vector at the spiral's centre and two unit vectors across it.
    axis: DVec3,
    across: (DVec3, DVec3),
    /// Angular spacing for a point light, distance for a parallel one.
    step: f64,
    /// The last ring.
    rings: u32,
    parallel: bool,
    /// Where parallel photons start: the plane through the light, across the axis.
    origin: DVec3,
    /// The target's spacing multiplier.
    multiplier: f64,
}

impl Spiral {
    fn new(light: &Light, target: &Target, spacing: f64) -> Option<Spiral> {
        let centre = target.bounds.centre();
        let radius = (target.bounds.max - target.bounds.min).length() * 0.5;
        let step = spacing * target.spacing_multiplier;
        if let Some(axis) = light.parallel_axis() {
            let across = axis.any_orthonormal_pair();
            let origin = centre - axis * (centre - light.position).dot(axis);
            return Some(Spiral {
                axis,
                across,
                step,
                rings: (radius / step).floor() as u32,
                parallel: true,
                origin,
                multiplier: target.spacing_multiplier,
            });
        }
        let to_centre = centre - light.position;
        let distance = to_centre.length();
        let axis = to_centre.try_normalize().unwrap_or(DVec3::Y);
        let (low, high) = (target.bounds.min, target.bounds.max);
        let inside = light.position.cmpge(low).all() && light.position.cmple(high).all();
        let angle = if inside || radius >= distance {
            std::f64::consts::PI
        } else {
            (radius / distance).asin()
        };
        let step = step / distance.max(radius);
        (step > 0.0 && step.is_finite()).then(|| Spiral {
            axis,
            across: axis.any_orthonormal_pair(),
            step,
            rings: (angle / step).floor() as u32,
            parallel: false,
            origin: light.position,
            multiplier: target.spacing_multiplier,
        })
    }

    /// How many photons ring `k` holds.
    fn ring_size(&self, k: u32) -> u32 {
        let circumference = if self.parallel {
            TAU * f64::from(k)
        } else {
            TAU * (f64::from(k) * self.step).sin() / self.step
        };
        (circumference.round() as u32).max(1)
    }

    fn photons(&self) -> u64 {
        (0..=self.rings).map(|k| u64::from(self.ring_size(k))).sum()
    }

    /// The ray of photon `j` of ring `k`, at ring and angle offsets within its place.
    fn ray(&self, k: u32, j: u32, (dk, dj): (f64, f64)) -> Ray {
        let spread = (f64::from(k) + dk).max(0.0) * self.step;
        let turn = (f64::from(j) + dj) * TAU / f64::from(self.ring_size(k));
        let (u, v) = self.across;
        let around = u * turn.cos() + v * turn.sin();
        if self.parallel {
            Ray::new(self.origin + around * spread, self.axis)
        } else {
            let direction = self.axis * spread.cos() + around * spread.sin();
            Ray::new(self.origin, direction)
        }
    }

    /// The share of the light one photon carries: a solid angle, or an area for parallel
    /// light.
    fn share(&self) -> f64 {
        self.step * self.step
    }
}

/// Shoots every light's photons at every target, adding what lands to `stored`.
pub fn shoot_all(
    world: &World,
    targets: &[Target],
    shooting: &Shooting,
    budget: &PhotonBudget,
    stored: &mut Vec<Photon>,
    in_media: &mut Vec<Photon>,
) -> Result<u64, String> {
    let mut shooter = Shooter {
        world,
        shooting,
        stored,
        in_media,
        media_step: 0.0,
        scratch: Vec::new(),
        spectra: Spectra::default(),
        budget,
    };
    let mut shot = 0;
    for (l, light) in world.lights.iter().enumerate() {
        if !light.photons.shoots() {
            continue;
        }
        for (t, target) in targets.iter().enumerate() {
            let Some(spiral) = Spiral::new(light, target, shooting.spacing) else {
                continue;
            };
            budget.check(spiral.photons())?;
            shot += shooter.spiral(light, &spiral, (l as u64) << 32 | t as u64)?;
        }
    }
    Ok(shot)
}

/// How many photons the spirals at `spacing` shoot, each stopped as `autostop` says:
/// for working out the spacing of a `count`.
pub fn count_shots(world: &World, targets: &[Target], shooting: &Shooting) -> u64 {
    let mut scratch = Vec::new();
    let mut total = 0;
    for light in &world.lights {
        if !light.photons.shoots() {
            continue;
        }
        for target in targets {
            let Some(spiral) = Spiral::new(light, target, shooting.spacing) else {
                continue;
            };
            let mut hit_once = false;
            for k in 0..=spiral.rings {
                let size = spiral.ring_size(k);
                total += u64::from(size);
                let ring_hit = (0..size).any(|j| {
                    let ray = spiral.ray(k, j, (0.0, 0.0));
                    first_target(world, &ray, &mut scratch)
                });
                hit_once |= ring_hit;
                if stops(&spiral, shooting.autostop, k, hit_once, ring_hit) {
                    break;
                }
            }
        }
    }
    total
}

/// Whether a photon along `ray` meets a target before anything else that stops it.
fn first_target<'w>(world: &'w World, ray: &Ray, scratch: &mut Vec<Hit<'w>>) -> bool {
    let mut origin = ray.origin;
    for _ in 0..64 {
        let q = Query::new(
            Ray::new(origin, ray.direction),
            RayKind::Primary,
            world.tolerance(origin),
            f64::INFINITY,
        );
        let Some(hit) = world.bvh.nearest(&q, scratch) else {
            return false;
        };
        if hit.leaf.photons.target() {
            return true;
        }
        if !hit.leaf.photons.pass_through() {
            return false;
        }
        origin = q.ray.at(hit.t);
    }
    false
}

/// Whether the spiral ends after ring `k`.
fn stops(spiral: &Spiral, autostop: f64, k: u32, hit_once: bool, ring_hit: bool) -> bool {
    let past = f64::from(k) >= autostop * f64::from(spiral.rings);
    hit_once && !ring_hit && past
}

/// A photon on its way.
#[derive(Debug, Clone, Copy)]
struct Travel {
    power: DVec3,
    /// What is left of the photon's first power, for `adc_bailout`.
    weight: f64,
    /// Distance from the light, for point lights; `None` for parallel light.
    path: Option<f64>,
    level: u32,
    /// Reflected or refracted already: collecting surfaces keep it.
    caustic: bool,
    kind: RayKind,
}

struct Shooter<'w, 's> {
    world: &'w World,
    shooting: &'s Shooting,
    stored: &'s mut Vec<Photon>,
    /// Photons left in media.
    in_media: &'s mut Vec<Photon>,
    /// The distance between media photons for the spiral being shot.
    media_step: f64,
    scratch: Vec<Hit<'w>>,
    spectra: Spectra,
    budget: &'s PhotonBudget,
}

impl<'w> Shooter<'w, '_> {
    /// Shoots one spiral; returns how many photons left the light.
    fn spiral(&mut self, light: &Light, spiral: &Spiral, seed: u64) -> Result<u64, String> {
        let mut shot = 0;
        let mut hit_once = false;
        let colour = light.colour * spiral.share();
        if let Some(deposit) = &self.shooting.media {
            self.media_step = deposit.step * spiral.multiplier;
        }
        for k in 0..=spiral.rings {
            let size = spiral.ring_size(k);
            let mut ring_hit = false;
            for j in 0..size {
                let mut ray = spiral.ray(k, j, self.jitter(seed, k, j));
                ray.origin += area_offset(light, shot, seed);
                shot += 1;
                let start = Travel {
                    power: colour,
                    weight: 1.0,
                    path: (!spiral.parallel).then_some(0.0),
                    level: 1,
                    caustic: false,
                    kind: RayKind::Primary,
                };
                let mut inside = Inside::default();
                ring_hit |= self.follow(light, ray, start, &mut inside)?;
            }
            hit_once |= ring_hit;
            if stops(spiral, self.shooting.autostop, k, hit_once, ring_hit) {
                break;
            }
        }
        Ok(shot)
    }

    /// Offsets within a photon's place in the spiral, as fractions of the spacing.
    fn jitter(&self, seed: u64, k: u32, j: u32) -> (f64, f64) {
        if self.shooting.jitter == 0.0 || k == 0 {
            return (0.0, 0.0);
        }
        let h = mix(seed ^ (u64::from(k) << 32 | u64::from(j)));
        let a = (h >> 11) as f64 / (1u64 << 53) as f64;
        let b = (mix(h) >> 11) as f64 / (1u64 << 53) as f64;
        (
            (a - 0.5) * self.shooting.jitter,
            (b - 0.5) * self.shooting.jitter,
        )
    }

    /// Follows a photon until it is absorbed or stops mattering; returns whether its first
    /// surface was a target.
    fn follow(
        &mut self,
        light: &Light,
        ray: Ray,
        travel: Travel,
        inside: &mut Inside<'w>,
    ) -> Result<bool, String> {
        let world = self.world;
        if travel.level > self.shooting.max_trace_level {
            return Ok(false);
        }
        let mut origin = ray.origin;
        let mut travel = travel;
        let start = travel;
        let (hit, point) = loop {
            let q = Query::new(
                Ray::new(origin, ray.direction),
                travel.kind,
                world.tolerance(origin),
                f64::INFINITY,
            );
            let Some(hit) = world.bvh.nearest(&q, &mut self.scratch) else {
                if start.caustic {
                    self.leave_in_media(&ray, None, &start, inside)?;
                }
                return Ok(false);
            };
            let point = q.ray.at(hit.t);
            if let Some(path) = &mut travel.path {
                *path += hit.t;
            }
            // Photons on their way to a target pass through `pass_through` objects.
            if travel.caustic || !hit.leaf.photons.pass_through() || hit.leaf.photons.target() {
                break (hit, point);
            }
            origin = point;
        };
        if start.caustic {
            self.leave_in_media(&ray, Some(point), &start, inside)?;
        }
        let leaf: &'w Leaf = hit.leaf;
        let mut power = travel.power;
        if !travel.caustic {
            // Straight from the light: its spotlight cone, cylinder tube and fading, as
            // the direct light at this point has them.
            power *= light
                .ray_to(point, light.position)
                .map_or(0.0, |(to_light, distance)| {
                    light.attenuation(point, to_light, distance)
                });
        }
        if inside.is_innermost(&leaf.interior) {
            let depth = point.distance(ray.origin);
            power *= crate::tracer::fade(&leaf.interior, depth);
        }
        // The media of the interiors the photon crosses dim it, as they dim shadow rays.
        for interior in inside.interiors() {
            power *= interior.media_transmittance(ray.origin, point);
        }
        if travel.caustic && leaf.photons.collect() {
            self.store(point, power, ray.direction, travel.path)?;
        }
        let travel = Travel { power, ..travel };
        let refracts = leaf.photons.refracts(&light.photons);
        let reflects = leaf.photons.reflects(&light.photons);
        if refracts || reflects {
            self.scatter(light, &ray, &hit, point, travel, inside, refracts, reflects)?;
        }
        Ok(leaf.photons.target())
    }

    /// Sends the photon on through the surface and off it, as the surface allows.
    #[allow(clippy::too_many_arguments)]
    fn scatter(
        &mut self,
        light: &Light,
        ray: &Ray,
        hit: &Hit<'w>,
        point: DVec3,
        travel: Travel,
        inside: &mut Inside<'w>,
        refracts: bool,
        reflects: bool,
    ) -> Result<(), String> {
        let leaf: &'w Leaf = hit.leaf;
        let surface = Surface::at(self.world, leaf, ray, point, hit.part, inside);
        let next = Travel {
            level: travel.level + 1,
            caustic: true,
            ..travel
        };
        if refracts && surface.filter.max_element() > 0.0 {
            self.refract(light, ray, point, &surface, leaf, next, inside)?;
        }
        if reflects && surface.reflectivity.max_element() > 0.0 {
            let reflected = Ray::new(point, refraction::reflect(ray.direction, surface.normal));
            let mut outside = inside.clone();
            self.send(
                light,
                reflected,
                surface.reflectivity,
                next,
                RayKind::Reflected,
                &mut outside,
            )?;
        }
        Ok(())
    }

    /// The photon through the surface: split into bands at a dispersing interior, bent by
    /// Snell's law, reflected instead where the refraction is total.
    #[allow(clippy::too_many_arguments)]
    fn refract(
        &mut self,
        light: &Light,
        ray: &Ray,
        point: DVec3,
        surface: &Surface,
        leaf: &'w Leaf,
        travel: Travel,
        inside: &mut Inside<'w>,
    ) -> Result<(), String> {
        let interior: &'w Interior = &leaf.interior;
        let bands: Vec<(Option<f64>, DVec3)> =
            if inside.band.is_none() && crate::dispersion::disperses(interior) {
                self.spectra
                    .bands(interior.dispersion_samples)
                    .iter()
                    .map(|b| (Some(b.position), b.colour))
                    .collect()
            } else {
                vec![(inside.band, DVec3::ONE)]
            };
        for (band, colour) in bands {
            let mut through = inside.clone();
            through.band = band;
            let before = through.clone();
            let ior = through.cross(interior);
            match refraction::refract(ray.direction, surface.normal, ior) {
                Some(direction) => {
                    let next = Ray::new(point, direction);
                    self.send(
                        light,
                        next,
                        surface.filter * colour,
                        travel,
                        RayKind::Transmitted,
                        &mut through,
                    )?;
                }
                None => {
                    let mut back = before;
                    let next = Ray::new(point, refraction::reflect(ray.direction, surface.normal));
                    self.send(light, next, colour, travel, RayKind::Reflected, &mut back)?;
                }
            }
        }
        Ok(())
    }

    /// Follows the photon on with its power scaled by `tint`, unless too little is left.
    fn send(
        &mut self,
        light: &Light,
        ray: Ray,
        tint: DVec3,
        travel: Travel,
        kind: RayKind,
        inside: &mut Inside<'w>,
    ) -> Result<(), String> {
        let weight = travel.weight * tint.max_element();
        if weight <= self.shooting.adc_bailout {
            return Ok(());
        }
        let next = Travel {
            power: travel.power * tint,
            weight,
            kind,
            ..travel
        };
        self.follow(light, ray, next, inside).map(|_| ())
    }

    /// Leaves photons in the scattering media along `ray` up to `end` (`None`: a photon
    /// leaving the scene, which crosses `max_steps` steps of atmospheric media), for a
    /// photon setting out as `start`. Each is dimmed by the interiors' media before it,
    /// as the photon is at a surface.
    fn leave_in_media(
        &mut self,
        ray: &Ray,
        end: Option<DVec3>,
        start: &Travel,
        inside: &Inside<'w>,
    ) -> Result<(), String> {
        let Some(deposit) = self.shooting.media else {
            return Ok(());
        };
        let interiors = inside.interiors();
        if !in_media::collecting(in_media::media_within(self.world, interiors)) {
            return Ok(());
        }
        let step = self.media_step;
        let length = match end {
            Some(end) => end.distance(ray.origin),
            None => step * f64::from(deposit.max_steps),
        };
        let direction = ray.direction.normalize_or_zero();
        let seed = crate::media::seed(ray);
        for (at, width) in deposit.places(length, step, seed) {
            let p = ray.origin + direction * at;
            let mut power = start.power * width;
            for interior in interiors {
                power *= interior.media_transmittance(ray.origin, p);
            }
            let spread = start.path.map_or(1.0, |d| media_spread(d, at));
            let power = power * spread;
            if !(power.is_finite() && p.is_finite()) || power.max_element() <= 0.0 {
                continue;
            }
            self.budget
                .check((self.stored.len() + self.in_media.len()) as u64 + 1)?;
            self.in_media
                .push(in_media::media_photon(p, power, direction));
        }
        Ok(())
    }

    fn store(
        &mut self,
        point: DVec3,
        power: DVec3,
        direction: DVec3,
        path: Option<f64>,
    ) -> Result<(), String> {
        let spread = path.map_or(1.0, |d| d * d);
        let power = power * spread;
        if !(power.is_finite() && point.is_finite()) || power.max_element() <= 0.0 {
            return Ok(());
        }
        self.budget
            .check((self.stored.len() + self.in_media.len()) as u64 + 1)?;
        self.stored.push(Photon {
            position: point.as_vec3(),
            power: power.as_vec3(),
            direction: direction.normalize_or_zero().as_vec3(),
        });
        Ok(())
    }
}

/// The factor on the power of a media photon left `at` along a stretch of media that
/// starts `start` from a point light: the square of the distance travelled, as for surface
/// photons, times that distance over the distance at the start of the stretch. The second
/// factor is what POV-Ray 3.7's renders show: its media photons brighten along a beam by
/// the distance from the light, ×1.41 over a box from 17 to 23 units away (×1.35
/// predicted), ×1.19 from 37 to 43 (×1.16), and not at all for parallel light.
fn media_spread(start: f64, at: f64) -> f64 {
    let d = start + at;
    if start > 0.0 {
        d * d * d / start
    } else {
        d * d
    }
}

/// What a photon needs of the surface it meets: the normal it bends at, the colour of
/// what passes through, and the colour of what is reflected, over the texture's layers.
struct Surface {
    normal: DVec3,
    filter: DVec3,
    reflectivity: DVec3,
}

impl Surface {
    fn at(
        world: &World,
        leaf: &Leaf,
        ray: &Ray,
        p: DVec3,
        part: u32,
        inside: &Inside<'_>,
    ) -> Surface {
        let mut raw = leaf.normal(p, part);
        if raw.dot(ray.direction) > 0.0 {
            raw = -raw;
        }
        let relative_ior = inside.relative_ior(&leaf.interior);
        let mut normal = raw;
        let mut heaviest = 0.0;
        let mut reflectivity_sum = DVec3::ZERO;
        let at = leaf.texture_point(p, part, ray);
        leaf.for_each_layers(&at, part, &mut |w, layers, layers_at| {
            let Some(top) = layers.first() else {
                return;
            };
            let mut n = raw;
            if let Some(bumps) = &top.normal
                && world.quality.normals
            {
                n = crate::normal::perturb(bumps, layers_at, raw);
            }
            let colour = top.pigment.colour_at(&layers_at.with_normal(n));
            let cos = -ray.direction.dot(n);
            reflectivity_sum += w * reflectivity(&top.finish, colour.rgb, cos, relative_ior);
            if w > heaviest {
                heaviest = w;
                normal = n;
            }
        });
        Surface {
            normal,
            filter: leaf.transmitted_at(&at, part),
            reflectivity: reflectivity_sum,
        }
    }
}

/// Where on an area light photon number `index` leaves from, when the light's photons
/// block asks for its area (`area_light`): the points of the grid in turn, jittered as the
/// light's shadows are. Other lights shoot from their centre.
fn area_offset(light: &Light, index: u64, seed: u64) -> DVec3 {
    let Some(grid) = light.area.as_ref().filter(|_| light.photons.area_light) else {
        return DVec3::ZERO;
    };
    let cells = u64::from(grid.size1) * u64::from(grid.size2);
    let cell = index % cells.max(1);
    let (mut u, mut v) = (
        (cell % u64::from(grid.size1)) as f64,
        (cell / u64::from(grid.size1)) as f64,
    );
    if grid.jitter {
        let h = mix(seed ^ index.rotate_left(17) ^ 0x9e37_79b9_7f4a_7c15);
        u += ((h & 0xffff) as f64 / 65536.0) - 0.5;
        v += (((h >> 16) & 0xffff) as f64 / 65536.0) - 0.5;
    }
    grid.offset(grid.axis1, grid.axis2, u, v)
}

/// A 64-bit finaliser: spreads every bit of `x` over the result.
fn mix(mut x: u64) -> u64 {
    x ^= x >> 33;
    x = x.wrapping_mul(0xff51_afd7_ed55_8ccd);
    x ^= x >> 33;
    x = x.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
    x ^ (x >> 33)
}
