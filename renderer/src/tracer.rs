//! The tracer: follows a ray into the world and shades what it meets with POV-Ray's classic
//! model: ambient and emission, diffuse with brilliance, Blinn `specular` and Phong `phong`
//! highlights, shadows (filtered by transparent objects, softened by area lights),
//! reflection with its variable and Fresnel forms, and filtered or transmitted light going
//! on through the surface, refracted by the interiors the ray enters and leaves.

mod participating;
mod projection;
mod subsurface;

use crate::atmosphere::{Atmosphere, Sky};
use crate::bvh::Bvh;
use crate::colour::Sample;
use crate::dispersion::Spectra;
use crate::fast_math;
use crate::interior::Interior;
use crate::light::{Incoming, Light};
use crate::material::{Layer, Pigment};
use crate::object::{Hit, Leaf, OpenSides, Query};
use crate::photons::{GatherScratch, PhotonMap};
use crate::ray::{Ray, RayKind};
use crate::refraction::{self, Inside};
use crate::texture_point::TexturePoint;
use analysis::scene::{Finish, LightPhotons};
use glam::DVec3;
use std::sync::Arc;

/// Which computations the `Quality` setting allows (POV-Ray's levels 0 to 11).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Quality {
    /// Levels 0 and 1 show the pigment under full ambient light, nothing else.
    pub lighting: bool,
    pub shadows: bool,
    pub area_lights: bool,
    /// Normal perturbation, with the texture patterns.
    pub normals: bool,
    /// Reflected, refracted and transmitted rays.
    pub secondary_rays: bool,
    /// Radiosity (and, in POV-Ray, media and subsurface scattering).
    pub radiosity: bool,
    /// The photon pass and the caustics it draws.
    pub photons: bool,
}

impl Quality {
    pub fn from_level(level: u8) -> Quality {
        Quality {
            lighting: level >= 2,
            shadows: level >= 4,
            area_lights: level >= 5,
            normals: level >= 6,
            secondary_rays: level >= 8,
            radiosity: level >= 9,
            photons: level >= 6,
        }
    }
}

/// Everything a ray can meet, built from the scene once.
#[derive(Debug, Clone)]
pub struct World {
    pub bvh: Bvh,
    pub lights: Vec<Light>,
    /// Which lights shine on which objects, as indices into `lights`: set 0 holds the
    /// scene's own lights, the others those of light groups (see [`Leaf::light_set`]).
    pub light_sets: Vec<Vec<u32>>,
    /// What a ray that meets nothing returns, for primary and transmitted rays.
    pub background: Sample,
    /// The background seen in reflections, which never show alpha.
    pub reflected_background: DVec3,
    pub ambient_light: DVec3,
    /// `irid_wavelength`: the wavelengths of red, green and blue for iridescence.
    pub irid_wavelength: DVec3,
    pub quality: Quality,
    pub max_trace_level: u32,
    pub adc_bailout: f64,
    /// Scenes before `#version 3.7` weigh a transparent layer's own colour differently.
    pub legacy_opacity: bool,
    /// The size of the scene, from which the self-intersection tolerance follows so that
    /// scenes at any scale trace alike.
    pub scale: f64,
    /// Shapes with something to report after the render (an isosurface's max_gradient).
    pub shape_reports: Vec<crate::shapes::ShapeReport>,
    pub sky: Option<Sky>,
    pub atmosphere: Option<Arc<Atmosphere>>,
    /// Whether any ray may pass through fog, a rainbow or media; when not, rays skip the
    /// check altogether.
    pub participating: bool,
    /// The interiors the camera is in that matter to media: containers of media and, in
    /// scenes with an atmosphere, solid objects, which keep it out.
    pub camera_interiors: Vec<Arc<Interior>>,
    /// Indirect light, when the scene asks for radiosity and the quality allows it.
    pub radiosity: Option<crate::radiosity::Radiosity>,
    /// The photons the lights shot, when the scene uses photons.
    pub photons: Option<PhotonMap>,
    /// Subsurface light transport, when the scene asks for it and the quality allows it.
    pub subsurface: Option<crate::subsurface::Settings>,
}

impl World {
    /// The smallest ray parameter that counts as leaving `p`, relative to the scene's size.
    pub fn tolerance(&self, p: DVec3) -> f64 {
        1e-9 * (p.abs().max_element() + self.scale)
    }

    /// The lights that shine on `leaf`.
    pub fn lights_for(&self, leaf: &Leaf) -> impl Iterator<Item = &Light> {
        self.light_set(leaf.light_set)
    }

    /// [`Self::lights_for`], each with its place in `lights`.
    fn numbered_lights_for(&self, leaf: &Leaf) -> impl Iterator<Item = (usize, &Light)> {
        self.light_sets[leaf.light_set as usize]
            .iter()
            .map(|&i| (i as usize, &self.lights[i as usize]))
    }

    /// The lights of light set `set` (0: the scene's own lights).
    pub fn light_set(&self, set: u32) -> impl Iterator<Item = &Light> {
        self.light_sets[set as usize]
            .iter()
            .map(|&i| &self.lights[i as usize])
    }
}

/// POV-Ray's greyscale weights.
pub(crate) fn greyscale(c: DVec3) -> f64 {
    0.297 * c.x + 0.589 * c.y + 0.114 * c.z
}

/// A tracer for one thread: the world and scratch space reused from ray to ray.
pub struct Tracer<'w> {
    pub(crate) world: &'w World,
    scratch: Vec<Hit<'w>>,
    /// The interiors the current ray is inside and its band of the spectrum.
    inside: Inside<'w>,
    /// The spectral bands of dispersing interiors.
    spectra: Spectra,
    /// The photons lighting the current point, as lights, and the space to gather them.
    photon_lights: Vec<(DVec3, DVec3)>,
    gather_scratch: GatherScratch,
    /// The object that last stopped a shadow ray, opaque or a photon target that stops its
    /// light: neighbouring shadow rays are usually stopped by it too, and one shape test
    /// is cheaper than the search.
    last_blocker: Option<&'w Leaf>,
    /// The surface the current shadow rays leave, if they leave one: [`Self::last_blocker`]
    /// is not tried again when it is that surface, which shadows its own points rarely if
    /// at all (a disc or plane never) while its neighbours' shadow rays keep meeting it.
    shadow_surface: Option<&'w Leaf>,
    /// The shadow samples of an area light's grid for the current point, kept between
    /// points to spare an allocation each time.
    area_samples: Vec<Option<DVec3>>,
    /// The interiors shadow rays start in: those of a media sample's containers.
    shadow_start: Vec<&'w Interior>,
    /// The interiors the current shadow ray is inside, kept between shadow rays to spare
    /// an allocation for each one that passes a transparent object.
    shadow_inside: Vec<&'w Interior>,
    /// Where the current ray stands in the radiosity computation; `None` without it.
    pub(crate) radiosity: Option<crate::radiosity::Walk<'w>>,
    /// Each texture layer's reflectivity, normal and reflection exponent, kept from its
    /// lighting until its reflected ray is traced: a stack, since those rays shade further
    /// surfaces above the entries of the surface that sent them.
    reflections: Vec<(DVec3, DVec3, f64)>,
    /// The light each light source brings to the surface point being shaded, past the
    /// shadows, found when a layer first needs it and kept for the point's other layers
    /// and texture-map entries, as POV-Ray keeps it: one frame of an entry per light (by
    /// its place in the world's lights) for each point, in a stack, since the rays one
    /// layer sends shade further points before the next layer is lit.
    arrivals: Vec<Option<DVec3>>,
    /// The last diffusion profile of a translucent surface.
    profiles: subsurface::ProfileCache,
    /// The nearest hits of a batch of camera rays (see [`Self::trace_primaries`]).
    primary_hits: Vec<Option<Hit<'w>>>,
    /// The batch's surfaces waiting for their refracted and reflected rays, their layers'
    /// reflections meanwhile, and the light the reflected rays bring.
    behind: Vec<Behind<'w>>,
    parked_reflections: Vec<(DVec3, DVec3, f64)>,
    mirrored_light: Vec<DVec3>,
}

impl<'w> Tracer<'w> {
    pub fn new(world: &'w World) -> Tracer<'w> {
        Tracer {
            world,
            scratch: Vec::new(),
            inside: Inside::default(),
            spectra: Spectra::default(),
            photon_lights: Vec::new(),
            gather_scratch: GatherScratch::default(),
            last_blocker: None,
            shadow_surface: None,
            area_samples: Vec::new(),
            shadow_start: Vec::new(),
            shadow_inside: Vec::new(),
            radiosity: world
                .radiosity
                .as_ref()
                .map(crate::radiosity::Walk::rendering),
            reflections: Vec::new(),
            arrivals: Vec::new(),
            profiles: subsurface::ProfileCache::default(),
            primary_hits: Vec::new(),
            behind: Vec::new(),
            parked_reflections: Vec::new(),
            mirrored_light: Vec::new(),
        }
    }

    /// A fresh tracer inside the interiors the current ray is in, walking the radiosity
    /// computation with `walk`: for another thread to trace some of a gather's rays.
    pub(crate) fn copy_with(&self, walk: crate::radiosity::Walk<'w>) -> Tracer<'w> {
        Tracer {
            inside: self.inside.clone(),
            radiosity: Some(walk),
            ..Tracer::new(self.world)
        }
    }

    fn tolerance(&self, p: DVec3) -> f64 {
        self.world.tolerance(p)
    }

    /// The sample a camera ray brings back.
    pub fn trace_primary(&mut self, ray: &Ray) -> Sample {
        self.start_at_camera();
        self.trace(ray, RayKind::Primary, 1, 1.0)
    }

    /// Puts the current ray inside the interiors the camera is in, as a camera ray starts.
    fn start_at_camera(&mut self) {
        let world = self.world;
        self.inside
            .start_in(world.camera_interiors.iter().map(|i| &**i));
    }

    /// The samples camera rays bring back, appended to `out` in order (a missing ray, one
    /// the camera has none for, brings [`Sample::NO_RAY`]): each as [`Self::trace_primary`]
    /// gives it, but step by step for all of them: the nearest hits; the surfaces' shading,
    /// but for their refracted and reflected rays (see [`Self::shade_deferring`]); the
    /// refracted rays; the reflected ones; and what the layers make of their light. The
    /// interpreted plugin runs much faster so: its host's branch predictors learn the
    /// interpreter's jumps for a stretch of code run again and again, but not for a
    /// sample's whole path, which is too long to hold (see docs/plugin-speed.md). Inside Typst, julia.pov took 1.21 s
    /// with each ray traced whole and 0.97 s with the hits first; caustic.pov took 4.80 s
    /// with the hits first and 3.94 s with the rays through the water after the rest.
    pub fn trace_primaries(&mut self, rays: &[Option<Ray>], out: &mut Vec<Sample>) {
        let world = self.world;
        if world.max_trace_level < 1 {
            out.extend(rays.iter().map(|ray| match ray {
                Some(_) => Sample::default(),
                None => Sample::NO_RAY,
            }));
            return;
        }
        let mut hits = std::mem::take(&mut self.primary_hits);
        hits.clear();
        hits.extend(
            rays.iter()
                .map(|ray| self.first_hit(ray.as_ref()?, RayKind::Primary)),
        );
        // The surfaces' shading, but for their refracted and reflected rays, which are
        // traced next for all of them.
        let mut behind = std::mem::take(&mut self.behind);
        let mut parked = std::mem::take(&mut self.parked_reflections);
        behind.clear();
        parked.clear();
        for (ray, hit) in rays.iter().zip(&hits) {
            let Some(ray) = ray else {
                out.push(Sample::NO_RAY);
                continue;
            };
            self.start_at_camera();
            let sample = match hit {
                None => self.missed(ray, RayKind::Primary),
                Some(hit) => {
                    let index = out.len();
                    let Some(sample) =
                        self.shade_deferring(ray, hit, index, &mut behind, &mut parked)
                    else {
                        out.push(Sample::default());
                        continue;
                    };
                    sample
                }
            };
            out.push(self.past_media(ray, hit.as_ref(), sample));
        }
        for later in &mut behind {
            let Some((through, weight)) = later.through else {
                continue;
            };
            self.start_at_camera();
            let leaf: &'w Leaf = later.hit.leaf;
            self.inside.cross(&leaf.interior);
            let light = self.trace_leaving(leaf, &through, RayKind::Transmitted, 2, weight);
            later.light_behind = Some((light, false));
        }
        // Then the reflected rays of all of them, in the order their layers come.
        let mut mirrored_light = std::mem::take(&mut self.mirrored_light);
        mirrored_light.clear();
        for later in &mut behind {
            self.start_at_camera();
            let (from, count) = later.parked;
            let total_reflection = later.light_behind.is_some_and(|(_, tir)| tir);
            let first = mirrored_light.len();
            for &entry in &parked[from..from + count] {
                let (ray, p, top_normal) = (&later.ray, later.p, later.lit.top_normal);
                if let Some((mirror, weight)) =
                    self.mirror_ray(entry, ray, p, top_normal, total_reflection, 1.0)
                {
                    mirrored_light.push(self.reflect(later.hit.leaf, &mirror, 1, weight));
                }
            }
            later.mirrored = (first, mirrored_light.len() - first);
        }
        for later in &behind {
            self.start_at_camera();
            let first = self.reflections.len();
            let (from, count) = later.parked;
            self.reflections
                .extend_from_slice(&parked[from..from + count]);
            let lit = LayersLit {
                reflections: first,
                ..later.lit
            };
            let (from, count) = later.mirrored;
            let s = self.finish_layers(
                &later.ray,
                later.p,
                &later.hit,
                1,
                1.0,
                &lit,
                later.light_behind,
                &mirrored_light[from..from + count],
            );
            // As [`Self::shade_layered`] adds up its one stack.
            let sample = Sample::default() + s * 1.0;
            out[later.index] = self.past_media(&later.ray, Some(&later.hit), sample);
        }
        self.mirrored_light = mirrored_light;
        self.behind = behind;
        self.parked_reflections = parked;
        self.primary_hits = hits;
    }

    fn trace(&mut self, ray: &Ray, kind: RayKind, level: u32, weight: f64) -> Sample {
        if level > self.world.max_trace_level {
            return Sample::default();
        }
        let hit = self.first_hit(ray, kind);
        self.finish_trace(ray, kind, level, weight, hit.as_ref())
    }

    /// [`Self::trace`] once the nearest hit along `ray` is known: the sample it shades, or
    /// the background, through the media on the way.
    fn finish_trace(
        &mut self,
        ray: &Ray,
        kind: RayKind,
        level: u32,
        weight: f64,
        hit: Option<&Hit<'w>>,
    ) -> Sample {
        let sample = match hit {
            None => self.missed(ray, kind),
            Some(hit) => self.shade(ray, hit, level, weight),
        };
        self.past_media(ray, hit, sample)
    }

    /// The `sample` of the surface `hit` along `ray` (or of the background) as it arrives
    /// past the media on the way.
    fn past_media(&mut self, ray: &Ray, hit: Option<&Hit<'w>>, sample: Sample) -> Sample {
        if self.world.participating && !self.gathering_without_media() {
            let (depth, light_set) =
                hit.map_or((f64::INFINITY, 0), |hit| (hit.t, hit.leaf.light_set));
            return self.participate(ray, depth, light_set, sample);
        }
        sample
    }

    /// The nearest surface along `ray` that rays of `kind` see.
    pub(crate) fn first_hit(&mut self, ray: &Ray, kind: RayKind) -> Option<Hit<'w>> {
        let q = Query::new(*ray, kind, self.tolerance(ray.origin), f64::INFINITY);
        self.world.bvh.nearest(&q, &mut self.scratch)
    }

    pub(crate) fn shade(&mut self, ray: &Ray, hit: &Hit<'w>, level: u32, weight: f64) -> Sample {
        let p = ray.at(hit.t);
        let leaf: &'w Leaf = hit.leaf;
        if self.world.quality.lighting
            && let Some(layer) = leaf.opaque_layer()
            && self.shades_plainly()
        {
            let normal = facing_normal(leaf, p, hit.part, ray);
            let pigment = match &layer.pigment {
                // The same everywhere: no texture point to find.
                Pigment::Solid(colour) => *colour,
                pigment => {
                    let at = leaf.texture_point(p, hit.part, ray);
                    match at.facing {
                        Some(_) => pigment.colour_at(&at.with_normal(normal)),
                        None => pigment.colour_at(&at),
                    }
                }
            };
            // The pigment shows as a plain surface's colour wherever it is opaque, which
            // its material says it is everywhere.
            if pigment.filter == 0.0 && pigment.transmit == 0.0 && pigment.rgb.is_finite() {
                return self.shade_plain(ray, p, normal, leaf, pigment.rgb, &layer.finish);
            }
        }
        self.shade_layered(ray, hit, level, weight)
    }

    /// [`Self::shade`] for a camera ray's `hit`; or `None` where the surface is one stack
    /// of layers that lets light through from behind along a refracted ray, or reflects,
    /// having done all but tracing those rays: what is left joins `behind`, with the
    /// refracted ray, the layers' own light, and their reflections parked on `parked`, for
    /// the sample at `index` of the batch. Not with media, radiosity or subsurface light,
    /// whose results depend on the order rays are traced in; dispersed and totally
    /// reflected light is traced at once.
    fn shade_deferring(
        &mut self,
        ray: &Ray,
        hit: &Hit<'w>,
        index: usize,
        behind: &mut Vec<Behind<'w>>,
        parked: &mut Vec<(DVec3, DVec3, f64)>,
    ) -> Option<Sample> {
        let world = self.world;
        let leaf: &'w Leaf = hit.leaf;
        let layers = match leaf.single_stack() {
            Some(layers)
                if leaf.opaque_layer().is_none()
                    && world.quality.lighting
                    && !world.participating
                    && self.radiosity.is_none()
                    && world.subsurface.is_none() =>
            {
                layers
            }
            _ => return Some(self.shade(ray, hit, 1, 1.0)),
        };
        // As `shade_layered` does for its one stack.
        let p = ray.at(hit.t);
        let at = leaf.texture_point(p, hit.part, ray);
        let normal = facing_normal(leaf, p, hit.part, ray);
        let arrivals = self.arrivals.len();
        self.arrivals.resize(arrivals + world.lights.len(), None);
        let stack = Stack {
            layers,
            at: &at,
            arrivals,
        };
        let lit = self.light_layers(ray, at.world, &stack, normal, leaf, 1);
        let weight = self.weight_behind(&lit, 1.0);
        // As `transmitted` and `refracted` trace a ray through the surface.
        let through = weight
            .filter(|&w| w >= world.adc_bailout && !crate::dispersion::disperses(&leaf.interior))
            .and_then(|w| {
                let ior = self.inside.cross(&leaf.interior);
                let direction = refraction::refract(ray.direction, lit.top_normal, ior);
                self.start_at_camera();
                direction.map(|d| (Ray::new(at.world, d), w))
            });
        // The light from behind at once where it takes no refracted ray (none, too weak,
        // dispersed or totally reflected); the surface waits for its rays otherwise, or
        // where its layers reflect.
        let light_behind = match through {
            Some(_) => None,
            None => weight.map(|w| self.transmitted(ray, at.world, lit.top_normal, leaf, 1, w)),
        };
        let shaded = if through.is_some() || self.reflections.len() > lit.reflections {
            let first = parked.len();
            parked.extend(self.reflections.drain(lit.reflections..));
            behind.push(Behind {
                index,
                hit: *hit,
                ray: *ray,
                p: at.world,
                lit,
                through,
                light_behind,
                parked: (first, parked.len() - first),
                mirrored: (0, 0),
            });
            None
        } else {
            let s = self.finish_layers(ray, at.world, hit, 1, 1.0, &lit, light_behind, &[]);
            Some(Sample::default() + s * 1.0)
        };
        self.arrivals.truncate(arrivals);
        shaded
    }

    /// [`Self::shade`] by the layered model, whatever the surface.
    fn shade_layered(&mut self, ray: &Ray, hit: &Hit<'w>, level: u32, weight: f64) -> Sample {
        let p = ray.at(hit.t);
        let leaf: &'w Leaf = hit.leaf;
        // A texture map shades each texture it blends and mixes the results.
        let at = leaf.texture_point(p, hit.part, ray);
        let mut total = Sample::default();
        if !self.world.quality.lighting {
            // Quality levels 0 and 1 show the top pigment under full ambient light: no
            // normal, no light is needed.
            leaf.for_each_layers(&at, hit.part, &mut |w, layers, layers_at| {
                let top = layers
                    .first()
                    .map_or(DVec3::ZERO, |l| l.pigment.colour_at(layers_at).rgb);
                total = total + Sample::new(top, 0.0) * w;
            });
            return total;
        }
        let normal = facing_normal(leaf, p, hit.part, ray);
        let arrivals = self.arrivals.len();
        self.arrivals
            .resize(arrivals + self.world.lights.len(), None);
        leaf.for_each_layers(&at, hit.part, &mut |w, layers, layers_at| {
            let stack = Stack {
                layers,
                at: layers_at,
                arrivals,
            };
            let s = self.shade_layers(ray, &at, &stack, normal, hit, level, weight * w);
            total = total + s * w;
        });
        self.arrivals.truncate(arrivals);
        total
    }

    /// Whether surfaces of one opaque layer may skip the layered model: without radiosity or
    /// subsurface light, which need its bookkeeping, and with the bailout letting the top
    /// layer show and nothing through it.
    fn shades_plainly(&self) -> bool {
        let world = self.world;
        self.radiosity.is_none()
            && world.subsurface.is_none()
            && (0.0..1.0).contains(&world.adc_bailout)
    }

    /// [`Self::shade_layers`] for a point of a surface of one opaque layer without bumps
    /// or reflection (see [`Leaf::opaque_layer`]) whose pigment there is `colour`, as
    /// [`Self::shades_plainly`] allows: its own ambient and emitted light, the light
    /// sources' and the gathered photons' — the layer shows nothing beneath or behind it
    /// and reflects nothing, so there is nothing to stack, filter or trace further.
    fn shade_plain(
        &mut self,
        ray: &Ray,
        p: DVec3,
        normal: DVec3,
        leaf: &'w Leaf,
        colour: DVec3,
        finish: &Finish,
    ) -> Sample {
        let world = self.world;
        let ambient = finish.ambient * world.ambient_light;
        let mut own = colour * (ambient + finish.emission);
        if shows_light(finish) {
            let shading = Shading {
                p,
                normal,
                ray,
                surface: colour,
                finish,
                diffuse: finish.diffuse,
                opacity: 1.0,
                double_illuminate: leaf.double_illuminate,
                leaf,
            };
            for light in world.lights_for(leaf) {
                own += self.direct_light(light, &shading, None);
            }
            let photon_lights = self.gather_photons(leaf, p, normal);
            own += self.photons_lit(&photon_lights, &shading);
            self.keep_photon_lights(photon_lights);
        }
        Sample::new(own, 0.0)
    }

    /// One stack of texture layers, top first, as POV-Ray shades them: each layer adds its
    /// own light scaled by what the layers above let through, then the light from behind
    /// the surface passes all of them, and each layer's reflection is added. The surface
    /// is lit at `at`; its layers' patterns are evaluated at `layers_at`.
    #[allow(clippy::too_many_arguments)]
    fn shade_layers(
        &mut self,
        ray: &Ray,
        at: &TexturePoint,
        stack: &Stack<'_>,
        raw_normal: DVec3,
        hit: &Hit<'w>,
        level: u32,
        weight: f64,
    ) -> Sample {
        let lit = self.light_layers(ray, at.world, stack, raw_normal, hit.leaf, level);
        let behind = self
            .weight_behind(&lit, weight)
            .map(|weight| self.transmitted(ray, at.world, lit.top_normal, hit.leaf, level, weight));
        self.finish_layers(ray, at.world, hit, level, weight, &lit, behind, &[])
    }

    /// The first step of [`Self::shade_layers`]: each layer's own light, what the layers
    /// let through, and their reflections, kept on [`Self::reflections`] from the entry
    /// [`LayersLit::reflections`] on.
    fn light_layers(
        &mut self,
        ray: &Ray,
        p: DVec3,
        stack: &Stack<'_>,
        raw_normal: DVec3,
        leaf: &'w Leaf,
        level: u32,
    ) -> LayersLit {
        let Stack {
            layers,
            at: layers_at,
            arrivals,
        } = *stack;
        let world = self.world;
        let mut indirect = crate::radiosity::Indirect::new(p, raw_normal, level);
        let mut colour = DVec3::ZERO;
        // What the layers so far let through, and how much of it counts.
        let mut filter = DVec3::ONE;
        let mut trans = 1.0;
        let mut top_normal = raw_normal;
        let reflections = self.reflections.len();
        // Gathered photons light a surface as light sources do: not at all where no layer's
        // finish shows light.
        let photon_lights = if layers.iter().any(|layer| shows_light(&layer.finish)) {
            self.gather_photons(leaf, p, raw_normal)
        } else {
            Vec::new()
        };
        for (i, layer) in layers.iter().enumerate() {
            if trans <= world.adc_bailout {
                break;
            }
            let mut normal = raw_normal;
            if let Some(bumps) = &layer.normal
                && world.quality.normals
            {
                normal = crate::normal::perturb(bumps, layers_at, normal);
            }
            if i == 0 {
                top_normal = normal;
            }
            let pigment = match layers_at.facing {
                Some(_) => layer.pigment.colour_at(&layers_at.with_normal(normal)),
                None => layer.pigment.colour_at(layers_at),
            };
            let finish = &*layer.finish;
            let opacity = if world.legacy_opacity {
                1.0 - (pigment.filter * pigment.rgb.max_element() + pigment.transmit)
            } else {
                1.0 - pigment.filter - pigment.transmit
            };
            let cos_incidence = -ray.direction.dot(normal);
            // Only Fresnel reflection looks at the interiors either side.
            let relative_ior = match &finish.reflection {
                Some(r) if r.fresnel => self.inside.relative_ior(&leaf.interior),
                _ => 1.0,
            };
            let reflectivity = reflectivity(finish, pigment.rgb, cos_incidence, relative_ior);
            // A layer that reflects nothing sends no reflected ray.
            if reflectivity != DVec3::ZERO {
                let exponent = finish.reflection.as_ref().map_or(1.0, |r| r.exponent);
                self.reflections.push((reflectivity, normal, exponent));
            }

            let ambient = self.ambient(finish, pigment.rgb, normal, opacity, &mut indirect);
            let mut own = pigment.rgb * (ambient + finish.emission) * opacity;
            // A translucent layer's diffuse light comes from under the surface, not from
            // the light sources shining on the point itself.
            let profile = match world.subsurface {
                Some(_) => self.subsurface_profile(layer, pigment.rgb, leaf),
                None => None,
            };
            let shading = Shading {
                p,
                normal,
                ray,
                surface: pigment.rgb,
                finish,
                diffuse: if profile.is_some() {
                    0.0
                } else {
                    finish.diffuse
                },
                opacity,
                double_illuminate: leaf.double_illuminate,
                leaf,
            };
            // The pretrace wants only the radiosity samples a camera ray's path takes, and a
            // finish that shows no light (`ambient 1 diffuse 0`) needs no shadow rays.
            let unlit = self.vain_pretrace() || !shows_light(finish);
            for (number, light) in world.numbered_lights_for(leaf).filter(|_| !unlit) {
                own += self.direct_light(light, &shading, Some(arrivals + number));
            }
            if let Some(profile) = profile.filter(|_| !unlit && finish.diffuse > 0.0) {
                let under = self.subsurface_light(&profile, leaf, p, raw_normal);
                own += under * finish.diffuse * opacity;
            }
            if !unlit {
                own += self.photons_lit(&photon_lights, &shading);
            }
            colour += own * filter;

            filter *= pigment.rgb * pigment.filter + DVec3::splat(pigment.transmit);
            if finish.conserve_energy {
                filter *= (DVec3::ONE - reflectivity).min(DVec3::ONE);
            }
            trans = fast_math::min(greyscale(filter).abs(), 1.0);
        }
        self.keep_photon_lights(photon_lights);
        LayersLit {
            colour,
            filter,
            trans,
            top_normal,
            reflections,
        }
    }

    /// The weight of the light from behind a surface whose layers show `lit`, if it is to
    /// be traced.
    fn weight_behind(&self, lit: &LayersLit, weight: f64) -> Option<f64> {
        let world = self.world;
        (lit.trans > world.adc_bailout && world.quality.secondary_rays)
            .then(|| weight * lit.filter.abs().max_element())
    }

    /// The last step of [`Self::shade_layers`]: the light from behind the surface, `behind`
    /// (with whether it was totally reflected), passes the layers, and their reflections
    /// are traced and added.
    #[allow(clippy::too_many_arguments)]
    fn finish_layers(
        &mut self,
        ray: &Ray,
        p: DVec3,
        hit: &Hit<'w>,
        level: u32,
        weight: f64,
        lit: &LayersLit,
        behind: Option<(Sample, bool)>,
        mirrored_light: &[DVec3],
    ) -> Sample {
        let world = self.world;
        let leaf: &'w Leaf = hit.leaf;
        let LayersLit {
            mut colour,
            filter,
            trans,
            top_normal,
            reflections,
        } = *lit;
        let mut transmit = 0.0;
        let mut total_reflection = false;
        if let Some((through, tir)) = behind {
            total_reflection = tir;
            let fade = self.fade(&leaf.interior, hit.t);
            if tir {
                colour += fade * through.colour;
            } else {
                colour += fade * through.colour * filter;
                transmit = greyscale(fade) * through.transmit * trans;
            }
        }

        if world.quality.secondary_rays {
            let mut traced = mirrored_light.iter();
            for index in reflections..self.reflections.len() {
                let entry = self.reflections[index];
                let Some((mirror, new_weight)) =
                    self.mirror_ray(entry, ray, p, top_normal, total_reflection, weight)
                else {
                    continue;
                };
                let reflected = match traced.next() {
                    Some(&light) => light,
                    None => self.reflect(leaf, &mirror, level, new_weight),
                };
                let (reflectivity, _, exponent) = entry;
                let reflected = if exponent != 1.0 && exponent > 0.0 {
                    reflected.max(DVec3::ZERO).powf(1.0 / exponent)
                } else {
                    reflected
                };
                colour += reflectivity * reflected;
            }
        }
        self.reflections.truncate(reflections);
        Sample::new(colour, transmit)
    }

    /// The mirrored ray of a layer's reflection (`entry`, from [`Self::reflections`]) at
    /// `p`, where `ray` met the surface, and its weight; `None` where none is traced: the
    /// layer reflects nothing, the light is too weak, or total internal reflection
    /// (`total_reflection`) has already reflected along the top normal.
    fn mirror_ray(
        &self,
        (reflectivity, normal, _): (DVec3, DVec3, f64),
        ray: &Ray,
        p: DVec3,
        top_normal: DVec3,
        total_reflection: bool,
        weight: f64,
    ) -> Option<(Ray, f64)> {
        let same_as_top = (normal - top_normal).abs().max_element() <= 1e-10;
        if reflectivity == DVec3::ZERO || (total_reflection && same_as_top) {
            return None;
        }
        let new_weight = weight * reflectivity.max_element();
        (new_weight > self.world.adc_bailout).then(|| (mirrored(ray, p, normal), new_weight))
    }

    /// The photons lighting the point `p` of `leaf`, whose normal `normal` faces the
    /// viewer, as lights (see [`PhotonMap::lights_at`]): none where the scene has no
    /// photons or the surface collects none. The list comes from [`Self::photon_lights`];
    /// [`Self::keep_photon_lights`] gives it back.
    fn gather_photons(&mut self, leaf: &Leaf, p: DVec3, normal: DVec3) -> Vec<(DVec3, DVec3)> {
        let world = self.world;
        match &world.photons {
            Some(photons) if leaf.photons.collect() => {
                let mut lights = std::mem::take(&mut self.photon_lights);
                photons.lights_at(p, normal, &mut self.gather_scratch, &mut lights);
                lights
            }
            _ => Vec::new(),
        }
    }

    /// Keeps the list of [`Self::gather_photons`] with its allocation, for the next point.
    fn keep_photon_lights(&mut self, lights: Vec<(DVec3, DVec3)>) {
        if lights.capacity() > 0 {
            self.photon_lights = lights;
        }
    }

    /// Diffuse light and highlights from gathered photons, each `(colour, direction)` lit
    /// as a light source without shadows.
    fn photons_lit(&self, lights: &[(DVec3, DVec3)], at: &Shading<'_, '_>) -> DVec3 {
        let mut colour = DVec3::ZERO;
        for &(light, from) in lights {
            let lit = Lit {
                colour: light,
                direction: from,
                highlights: true,
            };
            colour += self.lit(&lit, at);
        }
        colour
    }

    /// Diffuse light and highlights from one light source. A light behind the surface
    /// lights it only through `double_illuminate` (both sides alike) or the finish's
    /// backside diffuse (`diffuse front, back`, without highlights).
    ///
    /// `arrival`: the entry of [`Tracer::arrivals`] that keeps the light's arrival at the
    /// point, where other layers there may need it too.
    fn direct_light(
        &mut self,
        light: &Light,
        at: &Shading<'_, 'w>,
        arrival: Option<usize>,
    ) -> DVec3 {
        let Shading {
            p,
            normal,
            finish,
            double_illuminate,
            leaf,
            ..
        } = *at;
        let Some(incoming) = light.incoming(p) else {
            return DVec3::ZERO;
        };
        if facing(normal, incoming.direction, finish, double_illuminate).is_none() {
            return DVec3::ZERO;
        }
        // One place that finds the arrival, so that its common case is inlined once.
        let light_colour = if light.arrives_whole {
            incoming.colour
        } else {
            let kept = arrival.and_then(|entry| self.arrivals[entry]);
            kept.unwrap_or_else(|| {
                let colour = self.arriving(light, p, &incoming, leaf);
                if let Some(entry) = arrival {
                    self.arrivals[entry] = Some(colour);
                }
                colour
            })
        };
        // Negative lights darken, as in POV-Ray: only a light too weak either way is skipped.
        if light_colour.abs().max_element() < 1e-10 {
            return DVec3::ZERO;
        }
        let lit = Lit {
            colour: light_colour,
            direction: incoming.direction,
            // POV-Ray's shadowless (fill) lights cause no highlights.
            highlights: !light.shadowless,
        };
        self.lit(&lit, at)
    }

    /// The light of `light` that reaches `p`, on the surface of `surface`, past the
    /// shadow-casting objects, through its projection object and the atmosphere. Light
    /// that is sure to meet nothing (see [`Self::unobstructed`]) is answered inlined, as
    /// it is at every point of a surface open to its lights; the rest in
    /// [`Self::arriving_past`].
    #[inline(always)]
    pub(crate) fn arriving(
        &mut self,
        light: &Light,
        p: DVec3,
        incoming: &Incoming,
        surface: &'w Leaf,
    ) -> DVec3 {
        let world = self.world;
        let shadows = !light.shadowless && world.quality.shadows;
        let clear = shadows && self.unobstructed(light, p, incoming, surface);
        if clear && !(light.media_attenuation && world.atmosphere.is_some()) {
            return incoming.colour;
        }
        self.arriving_past(light, p, incoming, surface, shadows, clear)
    }

    /// [`Self::arriving`] for light that casts no shadows (`shadows` false), meets nothing
    /// (`clear`) but goes through the atmosphere, or may meet something.
    #[inline(never)]
    fn arriving_past(
        &mut self,
        light: &Light,
        p: DVec3,
        incoming: &Incoming,
        surface: &'w Leaf,
        shadows: bool,
        clear: bool,
    ) -> DVec3 {
        let world = self.world;
        let mut colour = if !shadows {
            match self.projected_reach(light, p, incoming.direction, incoming.distance) {
                Some(_) => incoming.colour,
                None => DVec3::ZERO,
            }
        } else if clear {
            incoming.colour
        } else {
            // Inside containers of media the shadow ray crosses their media up to where it
            // leaves them, as POV-Ray's renders show (measured: a white ball in a box of
            // `absorption 0.15` lit from above the box shows 0.291, the light dimmed over
            // the 1.17 units to the box's top; 0.177 when it was dimmed over the 5.27 units
            // from there to the light instead). Not the surface's own object: the point lies
            // on its boundary, where the shadow ray may leave it at once.
            if world.participating {
                let shadow_start = &mut self.shadow_start;
                shadow_start.extend(
                    self.inside
                        .interiors()
                        .iter()
                        .filter(|i| !i.media.is_empty() && !std::ptr::eq(**i, &*surface.interior)),
                );
            }
            self.shadow_surface = Some(surface);
            let colour = self.unshadowed(light, p, incoming);
            self.shadow_surface = None;
            self.shadow_start.clear();
            colour
        };
        if light.media_attenuation && world.atmosphere.is_some() {
            colour *= self.atmospheric_attenuation(p, incoming);
        }
        colour
    }

    /// Whether the light of `light` arriving at `p` on `surface` from `incoming`'s
    /// direction is sure to meet nothing on its way: a light without an area, straight and
    /// not through media, that comes from a side of the flat surface's plane no object
    /// reaches (see [`crate::open_sides`]), or across a side of the box of every object that
    /// the surface lies on (see [`crate::bvh::Bvh::left_behind`]). [`Self::unshadowed`]
    /// would search and find nothing. Inlined into [`Self::arriving`], which asks it for
    /// every light at every point shaded.
    #[inline(always)]
    fn unobstructed(
        &mut self,
        light: &Light,
        p: DVec3,
        incoming: &Incoming,
        surface: &'w Leaf,
    ) -> bool {
        let world = self.world;
        let reach = surface.open_sides.reach();
        !world.participating
            && light.projected_through.is_none()
            && (light.area.is_none() || !world.quality.area_lights)
            && (self.leads_nowhere(surface, incoming.direction)
                || (reach != 0
                    && (world.bvh).left_behind(reach, p, incoming.direction, self.tolerance(p))))
    }

    /// Whether a ray leaving a point of the surface of `leaf` along `direction` meets
    /// nothing: the leaf is flat and the ray goes into a side of its plane that no other
    /// object reaches. Inlined: shadow rays and the rays leaving a surface ask at every
    /// point of a flat one, and a call costs the interpreted plugin a frame.
    #[inline]
    fn leads_nowhere(&self, leaf: &Leaf, direction: DVec3) -> bool {
        if leaf.open_sides.flat() == OpenSides::NONE {
            return false;
        }
        leaf.open_sides
            .towards(leaf.normal(DVec3::ZERO, 0).dot(direction))
    }

    /// Diffuse light and highlights from light arriving unshadowed, from a light source or
    /// from photons.
    fn lit(&self, lit: &Lit, at: &Shading<'_, '_>) -> DVec3 {
        let Shading {
            p,
            normal,
            ray,
            surface,
            finish,
            diffuse,
            opacity,
            double_illuminate,
            ..
        } = *at;
        let Some(backside) = facing(normal, lit.direction, finish, double_illuminate) else {
            return DVec3::ZERO;
        };
        let cos_in = normal.dot(lit.direction).abs();
        let mut colour = DVec3::ZERO;
        let diffuse = if backside {
            finish.diffuse_back
        } else {
            diffuse
        };
        if diffuse > 0.0 {
            let mut intensity = if finish.brilliance == 1.0 {
                cos_in
            } else {
                fast_math::pow(cos_in, finish.brilliance)
            } * diffuse
                * opacity;
            if finish.crand > 0.0 {
                // Graininess: a fixed pseudo-random dimming per point.
                intensity -= grain(p) * finish.crand;
            }
            colour += lit.colour * surface * intensity;
        }
        // Backside light causes no highlights, and radiosity rays see none.
        if !lit.highlights || backside || self.in_radiosity_ray() {
            return self.iridescent(colour, finish, p, normal, ray, lit.direction);
        }
        if finish.phong > 0.0 {
            let reflected = ray.direction - 2.0 * ray.direction.dot(normal) * normal;
            let cos = reflected.dot(lit.direction);
            if cos > 0.0 && (finish.phong_size < 60.0 || cos > 0.0008) {
                let intensity = finish.phong * fast_math::pow(cos, finish.phong_size);
                let tint = metallic_tint(finish.metallic, surface, normal.dot(lit.direction));
                colour += lit.colour * tint * intensity;
            }
        }
        if finish.specular > 0.0 {
            let halfway = (lit.direction - ray.direction) * 0.5;
            let len = halfway.length();
            if len > 0.0 {
                let cos = normal.dot(halfway) / len;
                if cos > 0.0 {
                    let intensity =
                        finish.specular * fast_math::pow_inlined(cos, 1.0 / finish.roughness);
                    let ndotl = halfway.dot(lit.direction) / len;
                    let tint = metallic_tint(finish.metallic, surface, ndotl);
                    colour += lit.colour * tint * intensity;
                }
            }
        }
        self.iridescent(colour, finish, p, normal, ray, lit.direction)
    }

    /// A light's contribution through the finish's thin film, if it has one: inlined, so
    /// that the many finishes without one pay no call.
    #[inline]
    fn iridescent(
        &self,
        colour: DVec3,
        finish: &Finish,
        p: DVec3,
        normal: DVec3,
        ray: &Ray,
        to_light: DVec3,
    ) -> DVec3 {
        match finish.irid {
            Some(film) if film.0 > 0.0 => self.interference(colour, film, p, normal, ray, to_light),
            _ => colour,
        }
    }

    /// Thin-film interference (`irid { amount thickness turbulence }`): each channel of a
    /// light's contribution scaled by `1 + amount cos(phase / wavelength)`, the phase
    /// growing with the film's thickness and the angles to the light and the eye.
    fn interference(
        &self,
        colour: DVec3,
        (amount, thickness, turbulence): (f64, f64, f64),
        p: DVec3,
        normal: DVec3,
        ray: &Ray,
        to_light: DVec3,
    ) -> DVec3 {
        let mut film = thickness;
        if turbulence != 0.0 {
            let (mut sum, mut weight, mut scale, mut total) = (0.0, 1.0, 1.0, 0.0);
            for _ in 0..5 {
                sum += analysis::noise::noise(p * scale) * weight;
                total += weight;
                weight *= 0.5;
                scale *= 2.0;
            }
            film *= 1.0 + (2.0 * sum / total - 1.0) * turbulence;
        }
        let phase = std::f64::consts::TAU
            * film
            * (normal.dot(to_light).abs() + normal.dot(ray.direction).abs());
        let waves = self.world.irid_wavelength;
        colour
            * (DVec3::ONE
                + amount
                    * DVec3::new(
                        (phase / waves.x).cos(),
                        (phase / waves.y).cos(),
                        (phase / waves.z).cos(),
                    ))
    }

    /// The light that reaches `p` past every shadow-casting object: none behind an opaque
    /// one, filtered by the colours of transparent ones, averaged over an area light.
    fn unshadowed(&mut self, light: &Light, p: DVec3, incoming: &Incoming) -> DVec3 {
        match (&light.area, self.world.quality.area_lights) {
            (Some(grid), true) => {
                let (axis1, axis2) = if grid.orient {
                    oriented_axes(grid.axis1, incoming.direction)
                } else {
                    (grid.axis1, grid.axis2)
                };
                let mut samples = std::mem::take(&mut self.area_samples);
                samples.clear();
                samples.resize((grid.size1 * grid.size2) as usize, None);
                let area = AreaSampler {
                    light,
                    point: p,
                    axis1,
                    axis2,
                    colour: incoming.colour,
                };
                let (s1, s2) = (grid.size1 as i32 - 1, grid.size2 as i32 - 1);
                let light = area.region(self, &mut samples, (0, 0, s1, s2), 0);
                self.area_samples = samples;
                light
            }
            _ => self.shadowed(
                light,
                p,
                incoming.direction,
                incoming.distance,
                incoming.colour,
            ),
        }
    }

    /// The photons settings of `light` when shadow rays towards it stop at the photon
    /// targets that refract its photons: in scenes with photons.
    fn photons_stop<'l>(&self, light: &'l Light) -> Option<&'l LightPhotons> {
        self.world.photons.is_some().then_some(&light.photons)
    }

    /// `colour` after the shadow ray from `p` along `direction` over `distance`.
    /// `photons_stop`: the targets that refract this light's photons stop the light, whose
    /// photons bring it.
    fn filtered(
        &mut self,
        p: DVec3,
        direction: DVec3,
        distance: f64,
        colour: DVec3,
        photons_stop: Option<&LightPhotons>,
    ) -> DVec3 {
        // Without a shadow-casting object or media to cross, the light arrives whole.
        if !self.world.bvh.seen_by(RayKind::Shadow) && self.shadow_start.is_empty() {
            return colour;
        }
        let mut colour = colour;
        let mut origin = p;
        let mut remaining = distance;
        let segment = |tracer: &Self, origin: DVec3, remaining: f64| {
            let eps = tracer.tolerance(origin);
            Query::new(
                Ray::new(origin, direction),
                RayKind::Shadow,
                eps,
                remaining - eps,
            )
        };
        let mut q = segment(self, origin, remaining);
        if let Some(blocker) = self.last_blocker
            && !self
                .shadow_surface
                .is_some_and(|surface| std::ptr::eq(surface, blocker))
            && blocker.blocks(&q, photons_stop)
        {
            return DVec3::ZERO;
        }
        // The interiors the shadow ray is inside, for distance fading and media; it starts
        // outside everything, as POV-Ray's shadow rays do, unless it leaves a media sample.
        // The list is made at the first transparent occluder: most shadow rays meet none,
        // and are inside `shadow_start`'s interiors all the way.
        let mut inside: Option<Vec<&'w Interior>> = None;
        // Each transparent occluder filters the light and the search goes on beyond it;
        // the bound stops a pathological stack of surfaces.
        let arriving = 'crossing: {
            for _ in 0..64 {
                let Some(hit) = self.world.bvh.occluder(&q, &mut self.scratch) else {
                    let end = origin + direction * remaining;
                    for interior in inside.as_ref().unwrap_or(&self.shadow_start) {
                        colour *= interior.media_transmittance(origin, end);
                    }
                    break 'crossing colour;
                };
                let leaf: &'w Leaf = hit.leaf;
                let stops =
                    photons_stop.is_some_and(|light| leaf.photons.stops_light_for_photons(light));
                if stops || !leaf.transmits {
                    if leaf.standalone {
                        self.last_blocker = Some(leaf);
                    }
                    break 'crossing DVec3::ZERO;
                }
                let point = q.ray.at(hit.t);
                colour *=
                    leaf.transmitted_at(&leaf.texture_point(point, hit.part, &q.ray), hit.part);
                let interior: &'w Interior = &leaf.interior;
                let inside = inside.get_or_insert_with(|| {
                    let mut list = std::mem::take(&mut self.shadow_inside);
                    list.clone_from(&self.shadow_start);
                    list
                });
                match inside.iter().position(|i| std::ptr::eq(*i, interior)) {
                    Some(at) => {
                        colour *= fade(interior, hit.t);
                        colour *= interior.media_transmittance(origin, point);
                        inside.remove(at);
                    }
                    None => inside.push(interior),
                }
                if colour.abs().max_element() < self.world.adc_bailout {
                    break 'crossing DVec3::ZERO;
                }
                origin = point;
                remaining -= hit.t;
                q = segment(self, origin, remaining);
            }
            DVec3::ZERO
        };
        if let Some(list) = inside {
            self.shadow_inside = list;
        }
        arriving
    }

    /// Distance attenuation inside the interior the ray is leaving.
    fn fade(&self, interior: &Interior, depth: f64) -> DVec3 {
        if self.inside.is_innermost(interior) {
            fade(interior, depth)
        } else {
            DVec3::ONE
        }
    }

    /// The light arriving through the surface: transmitted straight on, or refracted;
    /// `true` with the reflected light when the refraction is total internal reflection.
    /// White light crossing into or out of a dispersing interior splits into the bands of
    /// the spectrum, each refracted on its own; a split ray stays split.
    #[allow(clippy::too_many_arguments)]
    fn transmitted(
        &mut self,
        ray: &Ray,
        p: DVec3,
        normal: DVec3,
        leaf: &'w Leaf,
        level: u32,
        weight: f64,
    ) -> (Sample, bool) {
        if weight < self.world.adc_bailout {
            return (Sample::default(), false);
        }
        let interior: &'w Interior = &leaf.interior;
        if self.inside.band.is_some() || !crate::dispersion::disperses(interior) {
            return self.refracted(ray, p, normal, leaf, level, weight);
        }
        let bands = self.spectra.bands(interior.dispersion_samples).to_vec();
        let mut total = Sample::default();
        let mut all_reflected = true;
        for band in bands {
            self.inside.band = Some(band.position);
            let band_weight = weight * band.colour.max_element();
            let (s, reflected) = self.refracted(ray, p, normal, leaf, level, band_weight);
            all_reflected &= reflected;
            total = total
                + Sample::new(
                    s.colour * band.colour,
                    s.transmit * band.colour.element_sum() / 3.0,
                );
        }
        self.inside.band = None;
        (total, all_reflected)
    }

    /// [`Self::transmitted`] for one band, or white light where nothing disperses.
    fn refracted(
        &mut self,
        ray: &Ray,
        p: DVec3,
        normal: DVec3,
        leaf: &'w Leaf,
        level: u32,
        weight: f64,
    ) -> (Sample, bool) {
        let saved = self.inside.clone();
        let ior = self.inside.cross(&leaf.interior);
        let result = match refraction::refract(ray.direction, normal, ior) {
            Some(direction) => {
                let next = Ray::new(p, direction);
                let kind = RayKind::Transmitted;
                (
                    self.trace_leaving(leaf, &next, kind, level + 1, weight),
                    false,
                )
            }
            None => {
                self.inside.restore(&saved);
                let reflected = self.reflect(leaf, &mirrored(ray, p, normal), level, weight);
                (Sample::new(reflected, 0.0), true)
            }
        };
        self.inside.restore(&saved);
        result
    }

    /// The colour seen along `mirrored`, the mirror image of the ray that met `leaf`.
    fn reflect(&mut self, leaf: &'w Leaf, mirrored: &Ray, level: u32, weight: f64) -> DVec3 {
        self.trace_leaving(leaf, mirrored, RayKind::Reflected, level + 1, weight)
            .colour
    }

    /// [`Self::trace`] for a ray leaving the surface of `leaf`: the background at once
    /// when the surface is flat and the ray goes into a side of its plane no object
    /// reaches (see [`crate::open_sides`]), as the search would find, unless fog or media
    /// lie along it. Inlined: a surface that reflects asks at every hit, and a call costs
    /// the interpreted plugin a frame.
    #[inline(always)]
    fn trace_leaving(
        &mut self,
        leaf: &'w Leaf,
        ray: &Ray,
        kind: RayKind,
        level: u32,
        weight: f64,
    ) -> Sample {
        let world = self.world;
        if level <= world.max_trace_level
            && !world.participating
            && self.leads_nowhere(leaf, ray.direction)
        {
            return self.missed(ray, kind);
        }
        self.trace(ray, kind, level, weight)
    }
}

/// A camera ray's surface whose refracted or reflected rays are still to be traced (see
/// [`Tracer::trace_primaries`]).
#[derive(Clone, Copy)]
struct Behind<'w> {
    /// Where the sample goes in the batch's output.
    index: usize,
    hit: Hit<'w>,
    ray: Ray,
    p: DVec3,
    lit: LayersLit,
    /// The refracted ray through the surface still to be traced, and its weight.
    through: Option<(Ray, f64)>,
    /// The light from behind the surface, and whether it was totally reflected: found at
    /// once, or along `through` once traced.
    light_behind: Option<(Sample, bool)>,
    /// The layers' reflections: from where on the parked list, and how many.
    parked: (usize, usize),
    /// The light their mirrored rays bring: from where on the list of it, and how many.
    mirrored: (usize, usize),
}

/// What the layers of a stack show at a point before the light from behind the surface
/// and their reflections are added (see [`Tracer::light_layers`]).
#[derive(Clone, Copy)]
struct LayersLit {
    colour: DVec3,
    /// What the layers let through, and how much of it counts.
    filter: DVec3,
    trans: f64,
    /// The top layer's normal, which the light from behind passes.
    top_normal: DVec3,
    /// The first of the layers' entries on [`Tracer::reflections`].
    reflections: usize,
}

/// One stack of texture layers that shows at a surface point: the layers, top first,
/// where their patterns are evaluated, and the frame of [`Tracer::arrivals`] for the point.
#[derive(Clone, Copy)]
struct Stack<'a> {
    layers: &'a [Layer],
    at: &'a TexturePoint,
    arrivals: usize,
}

/// A surface point as the lighting model sees it: where it is, its (perturbed) normal
/// facing the viewer, the ray that found it, its pigment colour and finish, how opaque the
/// layer is, and whether both sides take light alike.
#[derive(Clone, Copy)]
struct Shading<'a, 'w> {
    p: DVec3,
    normal: DVec3,
    ray: &'a Ray,
    surface: DVec3,
    finish: &'a Finish,
    /// The front diffuse the light sources give the point directly: the finish's, or none
    /// where it comes from under the surface instead.
    diffuse: f64,
    opacity: f64,
    double_illuminate: bool,
    /// The surface the point lies on.
    leaf: &'w Leaf,
}

/// Light arriving at a point, ready for the lighting model.
struct Lit {
    colour: DVec3,
    /// Unit vector towards where the light comes from.
    direction: DVec3,
    highlights: bool,
}

/// Whether light sources can show on a surface with this finish at all: through diffuse
/// (front or back) or a highlight; `Tracer::lit` gives nothing otherwise.
/// The normal of `leaf` at `p` turned to face `ray`: POV-Ray lights the side the ray sees.
fn facing_normal(leaf: &Leaf, p: DVec3, part: u32, ray: &Ray) -> DVec3 {
    let normal = leaf.normal(p, part);
    if normal.dot(ray.direction) > 0.0 {
        -normal
    } else {
        normal
    }
}

fn shows_light(finish: &Finish) -> bool {
    finish.diffuse > 0.0 || finish.diffuse_back > 0.0 || finish.phong > 0.0 || finish.specular > 0.0
}

/// Whether a surface facing `normal` takes light from `direction`: `Some(false)` on its
/// front, `Some(true)` from behind through the finish's backside diffuse, `None` not at
/// all. `double_illuminate` lights both sides alike.
fn facing(
    normal: DVec3,
    direction: DVec3,
    finish: &Finish,
    double_illuminate: bool,
) -> Option<bool> {
    if normal.dot(direction) >= 1e-10 || double_illuminate {
        Some(false)
    } else if finish.diffuse_back != 0.0 {
        Some(true)
    } else {
        None
    }
}

/// The mirror image of `ray` in the surface of normal `normal` at `p`, leaving `p`.
fn mirrored(ray: &Ray, p: DVec3, normal: DVec3) -> Ray {
    Ray::new(p, refraction::reflect(ray.direction, normal))
}

/// How much light is left after `depth` inside an interior with `fade_distance`,
/// `fade_power` and `fade_color`.
pub(crate) fn fade(interior: &Interior, depth: f64) -> DVec3 {
    if interior.fade_distance.abs() <= 1e-10 || interior.fade_power <= 0.0 {
        return DVec3::ONE;
    }
    let colour = interior.fade_colour.rgb;
    if interior.fade_power >= 1000.0 {
        let d = depth / interior.fade_distance;
        return DVec3::new(
            (-(1.0 - colour.x) * d).exp(),
            (-(1.0 - colour.y) * d).exp(),
            (-(1.0 - colour.z) * d).exp(),
        );
    }
    let k = 1.0 + (depth / interior.fade_distance).powf(interior.fade_power);
    colour + (DVec3::ONE - colour) / k
}

/// A pseudo-random value in 0..1 fixed for each point, for `crand`.
fn grain(p: DVec3) -> f64 {
    (hash3(p, 0, 0) >> 11) as f64 / (1u64 << 53) as f64
}

/// Samples an area light's grid adaptively, as POV-Ray does: the corners of a region
/// first, and the region split while `adaptive` asks for more levels or its corners
/// disagree.
struct AreaSampler<'l> {
    light: &'l Light,
    point: DVec3,
    axis1: DVec3,
    axis2: DVec3,
    colour: DVec3,
}

impl AreaSampler<'_> {
    fn sample(&self, tracer: &mut Tracer<'_>, u: i32, v: i32) -> DVec3 {
        let grid = self.light.area.as_ref().expect("an area light");
        let (mut fu, mut fv) = (f64::from(u), f64::from(v));
        if grid.jitter {
            // A fixed pseudo-random offset per point and grid cell, so that renders repeat.
            let h = hash3(self.point, u, v);
            fu += ((h & 0xffff) as f64 / 65536.0) - 0.5;
            fv += (((h >> 16) & 0xffff) as f64 / 65536.0) - 0.5;
        }
        let centre = self.light.position + grid.offset(self.axis1, self.axis2, fu, fv);
        let Some((direction, distance)) = self.light.ray_to(self.point, centre) else {
            return DVec3::ZERO;
        };
        tracer.shadowed(self.light, self.point, direction, distance, self.colour)
    }

    fn region(
        &self,
        tracer: &mut Tracer<'_>,
        cache: &mut [Option<DVec3>],
        (u1, v1, u2, v2): (i32, i32, i32, i32),
        level: u32,
    ) -> DVec3 {
        let grid = self.light.area.as_ref().expect("an area light");
        let size2 = grid.size2 as i32;
        let mut corners = [DVec3::ZERO; 4];
        for (i, (u, v)) in [(u1, v1), (u2, v1), (u1, v2), (u2, v2)]
            .into_iter()
            .enumerate()
        {
            let index = (u * size2 + v) as usize;
            corners[i] = match cache[index] {
                Some(c) => c,
                None => {
                    let c = self.sample(tracer, u, v);
                    cache[index] = Some(c);
                    c
                }
            };
        }
        let differ = |a: DVec3, b: DVec3| (a - b).abs().element_sum() > 0.1;
        if (u2 - u1 > 1 || v2 - v1 > 1)
            && (level < grid.adaptive
                || differ(corners[0], corners[1])
                || differ(corners[1], corners[3])
                || differ(corners[3], corners[2])
                || differ(corners[2], corners[0]))
        {
            let (um, vm) = ((u1 + u2) as f64 / 2.0, (v1 + v2) as f64 / 2.0);
            let (lo_u, hi_u) = (um.floor() as i32, um.ceil() as i32);
            let (lo_v, hi_v) = (vm.floor() as i32, vm.ceil() as i32);
            let mut sum = DVec3::ZERO;
            for sub in [
                (u1, v1, lo_u, lo_v),
                (hi_u, v1, u2, lo_v),
                (u1, hi_v, lo_u, v2),
                (hi_u, hi_v, u2, v2),
            ] {
                sum += self.region(tracer, cache, sub, level + 1);
            }
            return sum * 0.25;
        }
        (corners[0] + corners[1] + corners[2] + corners[3]) * 0.25
    }
}

/// A hash of a point and two grid indices, for pseudo-random choices that repeat.
pub(crate) fn hash3(p: DVec3, u: i32, v: i32) -> u64 {
    let mut h = 0xcbf2_9ce4_8422_2325u64;
    for x in [
        p.x.to_bits(),
        p.y.to_bits(),
        p.z.to_bits(),
        u as u64,
        v as u64,
    ] {
        h ^= x;
        h = h.wrapping_mul(0x100_0000_01b3);
        h ^= h >> 29;
    }
    h
}

/// An area light's axes turned to face the point, keeping the first axis's length.
fn oriented_axes(axis1: DVec3, to_light: DVec3) -> (DVec3, DVec3) {
    let length = axis1.length();
    let helper = if (to_light.z.abs() - 1.0).abs() < 0.01 {
        DVec3::Y
    } else {
        DVec3::Z
    };
    let a1 = to_light.cross(helper).normalize_or_zero();
    let a2 = to_light.cross(a1).normalize_or_zero();
    (a1 * length, a2 * length)
}

/// How much the surface reflects, with POV-Ray's variable, Fresnel and metallic rules.
pub(crate) fn reflectivity(finish: &Finish, surface: DVec3, cos: f64, relative_ior: f64) -> DVec3 {
    let Some(r) = &finish.reflection else {
        return DVec3::ZERO;
    };
    let (min, max) = (r.min.rgb, r.max.rgb);
    let mut value = if r.fresnel {
        let f = fresnel(cos, relative_ior);
        f * max + (1.0 - f) * min
    } else {
        let frac = if (r.falloff - 1.0).abs() > 1e-10 {
            (1.0 - cos).max(0.0).powf(r.falloff)
        } else {
            1.0 - cos
        };
        if frac.abs() < 1e-10 {
            min
        } else if (frac - 1.0).abs() < 1e-10 {
            max
        } else {
            frac * max + (1.0 - frac) * min
        }
    };
    value *= metallic_tint(r.metallic, surface, cos);
    value
}

/// The tint metallic surfaces give reflected light: the surface colour, fading to white at
/// grazing angles by POV-Ray's empirical Fresnel curve.
fn metallic_tint(metallic: f64, surface: DVec3, cos: f64) -> DVec3 {
    if metallic == 0.0 {
        return DVec3::ONE;
    }
    let x = cos.clamp(-1.0, 1.0).acos().abs() / std::f64::consts::FRAC_PI_2;
    let f = (0.014_567_225 / ((x - 1.12) * (x - 1.12)) - 0.011_612_903).clamp(0.0, 1.0);
    DVec3::ONE + (metallic * (1.0 - f)) * (surface - DVec3::ONE)
}

/// Fresnel reflectance of unpolarised light at relative index `n`.
fn fresnel(cos: f64, n: f64) -> f64 {
    let g2 = n * n + cos * cos - 1.0;
    if g2 <= 0.0 {
        return 1.0;
    }
    let g = g2.sqrt();
    let a = (g - cos) / (g + cos);
    let b = (cos * (g + cos) - 1.0) / (cos * (g - cos) + 1.0);
    (0.5 * a * a * (1.0 + b * b)).clamp(0.0, 1.0)
}

/// The colour of the centre pixel of a 40 × 30 image of the `#version 3.7` scene `text`,
/// whose world is `world`, for tests.
#[cfg(test)]
pub(crate) fn centre(world: &World, text: &str) -> DVec3 {
    use analysis::{EvalOptions, MemoryFiles, evaluate};
    let files = MemoryFiles::new().with("scene.pov", format!("#version 3.7;\n{text}"));
    let scene = evaluate("scene.pov", &files, &EvalOptions::default())
        .scene
        .unwrap();
    let camera = crate::camera::Camera::from_scene(&scene.camera).unwrap();
    let ray = camera.ray(20.0, 15.0, 40.0, 30.0).unwrap();
    Tracer::new(world).trace_primary(&ray).colour
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::build::scene_and_world_of_source;
    use crate::camera::Camera;

    /// Surfaces of one opaque layer shade as the layered model shades them, to the bit,
    /// under every kind of finish and light the shortcut keeps: highlights, backside and
    /// double illumination, iridescence, graininess, shadowless, spot and fading lights,
    /// shadows; with solid pigments and patterned ones, blended, in blocks and facing the
    /// ray.
    #[test]
    fn plain_surfaces_shade_as_layers_do() {
        let (scene, world) = scene_and_world_of_source(
            "camera { location <0, 2, -6> look_at <0, 0, 0> right -1.333*x }
            light_source { <4, 6, -6> color rgb 1.2 }
            light_source { <-3, 2, -4> color rgb <0.3, 0.4, 0.9> shadowless }
            light_source { <0, 5, 0> color 1 spotlight point_at <0, -1, 0> radius 10 falloff 20
              fade_distance 3 fade_power 2 }
            global_settings { ambient_light rgb <0.2, 0.3, 0.1> }
            sphere { <-1, 0, 0>, 1 pigment { rgb <0.9, 0.4, 0.15> }
              finish { specular 0.5 roughness 0.02 diffuse 0.7 brilliance 2 } }
            sphere { <1.2, 0, 0.5>, 0.8 pigment { rgb <0.2, 0.6, 0.9> }
              finish { phong 0.8 phong_size 30 metallic 0.5 irid { 0.3 thickness 0.2 } emission 0.1 } }
            box { <-0.5, -1, -2>, <0.5, 0.2, -1.5> pigment { rgb 0.8 }
              finish { diffuse 0.6, 0.4 crand 0.1 ambient 0.3 } }
            disc { <0, 0.5, -2.5>, <0.3, 1, -0.2>, 0.5 pigment { rgb <1, 0.5, 0.5> } double_illuminate }
            sphere { <0, 1.2, 1>, 0.6 pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } }
              finish { specular 0.3 } }
            sphere { <-2, 1, 1>, 0.6 pigment { aoi color_map { [0 rgb 0.1] [1 rgb <0.9, 0.8, 0.1>] } } }
            plane { y, -1 pigment { checker rgb <0.92, 0.92, 0.88> rgb <0.3, 0.4, 0.5> }
              finish { diffuse 0.6 } }",
        );
        let camera = Camera::from_scene(&scene.camera).unwrap();
        let mut tracer = Tracer::new(&world);
        let mut plain = 0;
        for y in 0..30 {
            for x in 0..40 {
                let ray = camera
                    .ray(x as f64 + 0.5, y as f64 + 0.5, 40.0, 30.0)
                    .unwrap();
                let Some(hit) = tracer.first_hit(&ray, RayKind::Primary) else {
                    continue;
                };
                plain += usize::from(hit.leaf.opaque_layer().is_some());
                let shaded = tracer.shade(&ray, &hit, 1, 1.0);
                let layered = tracer.shade_layered(&ray, &hit, 1, 1.0);
                assert_eq!(shaded, layered, "pixel ({x}, {y})");
            }
        }
        assert!(tracer.shades_plainly() && plain > 600, "{plain} plain hits");
    }

    /// Camera rays traced as a batch bring back what each brings traced alone, to the bit:
    /// through glass and off mirrors (whose refracted and reflected rays a batch traces
    /// after all its surfaces are lit), bumpy, layered and dispersing glass, a reflective
    /// floor, from inside water (total internal reflection), inside a fogged atmosphere,
    /// and where the camera has no ray.
    #[test]
    fn camera_rays_in_a_batch_shade_as_alone() {
        let scenes = [
            "camera { fisheye location <0, 2, -6> look_at <0, 0, 0> angle 200 }
            light_source { <4, 6, -6> color rgb 1.2 }
            fog { distance 20 color rgb <0.5, 0.6, 0.7> }
            sphere { <-1, 0, 0>, 1 pigment { rgbf <0.9, 0.9, 1, 0.9> } interior { ior 1.5 } }
            sphere { <1.2, 0, 0.5>, 0.8 pigment { rgb 0.2 } finish { reflection 0.8 } }
            plane { y, -1 pigment { checker rgb 0.9 rgb <0.3, 0.4, 0.5> } }",
            "camera { location <0, 2, -6> look_at <0, 0, 0> }
            light_source { <4, 6, -6> color rgb 1.2 }
            sphere { <-1.2, 0, 0>, 1 pigment { rgbf <0.9, 0.9, 1, 0.9> }
              finish { reflection 0.1 specular 0.5 } normal { bumps 0.5 scale 0.2 }
              interior { ior 1.5 fade_distance 1 fade_power 2 } }
            sphere { <1.2, 0, 0>, 1 texture { pigment { rgbt <1, 0.5, 0.5, 0.6> } }
              texture { pigment { rgbf <0.5, 1, 0.5, 0.5> } finish { reflection 0.2 } }
              interior { ior 1.3 } }
            box { <-0.5, -1, 1.5>, <0.5, 0.5, 2> pigment { rgbf 0.9 }
              interior { ior 1.5 dispersion 1.1 dispersion_samples 5 } }
            sphere { <0, -0.5, -1.5>, 0.5 pigment { rgb 0.1 }
              finish { reflection { 0.2, 0.9 falloff 2 exponent 0.8 metallic } } }
            plane { y, -1 pigment { checker rgb 0.9 rgb <0.3, 0.4, 0.5> }
              finish { reflection 0.3 } }",
            "camera { location <0, 0, 0> look_at <0, -1, 2> angle 120 }
            light_source { <4, 6, -6> color rgb 1.2 }
            sphere { 0, 3 pigment { rgbf <0.8, 0.9, 1, 0.95> } interior { ior 1.33 } hollow }
            plane { y, -4 pigment { checker rgb 0.9 rgb <0.3, 0.4, 0.5> } }",
        ];
        for source in scenes {
            let (scene, world) = scene_and_world_of_source(source);
            let camera = Camera::from_scene(&scene.camera).unwrap();
            let rays: Vec<Option<Ray>> = (0..30)
                .flat_map(|y| (0..40).map(move |x| (f64::from(x) + 0.5, f64::from(y) + 0.5)))
                .map(|(x, y)| camera.ray(x, y, 40.0, 30.0))
                .collect();
            let mut batched = Vec::new();
            Tracer::new(&world).trace_primaries(&rays, &mut batched);
            let mut tracer = Tracer::new(&world);
            for (ray, batched) in rays.iter().zip(&batched) {
                let alone = ray
                    .as_ref()
                    .map_or(Sample::NO_RAY, |ray| tracer.trace_primary(ray));
                assert_eq!(*batched, alone, "{ray:?}");
            }
        }
    }

    /// A negative light takes its share away, through a clear pane too, as in POV-Ray:
    /// with half as much negative light the ball shows half its light.
    #[test]
    fn negative_lights_darken() {
        let scene = |negative: &str| {
            format!(
                "camera {{ location <0, 0, -5> look_at 0 }}\n\
                 light_source {{ <0, 0, -10> rgb 1 }}\n{negative}\n\
                 box {{ <-3, -3, -3>, <3, 3, -2.9> pigment {{ rgbt 1 }} }}\n\
                 sphere {{ 0, 1 pigment {{ rgb 1 }} finish {{ ambient 0 diffuse 1 }} }}"
            )
        };
        let plain = scene("");
        let full = centre(&crate::build::world_of_source(&plain), &plain);
        let dimmed = scene("light_source { <0, 0, -10> rgb -0.5 }");
        let half = centre(&crate::build::world_of_source(&dimmed), &dimmed);
        assert!(full.x > 0.5, "{full}");
        assert!(
            (half - full * 0.5).abs().max_element() < 1e-9,
            "{half} {full}"
        );
    }
}
