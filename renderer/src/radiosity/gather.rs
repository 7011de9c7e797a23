//! Indirect light at a surface point: from the cache when its samples cover the point,
//! otherwise gathered by `count` rays over the hemisphere and, while the cache is being
//! filled, kept as a new sample.

use super::Radiosity;
use super::cache::{self, Cache, Sample};
use super::split::ToAFreeThread;
use crate::colour;
use crate::object::{Hit, Leaf};
use crate::ray::{Ray, RayKind};
use crate::tracer::{Tracer, World, greyscale, hash3};
use analysis::scene::Finish;
use glam::DVec3;
use std::sync::atomic::{AtomicUsize, Ordering};

/// How much looser the error bound may grow with each diffuse bounce.
const LOOSEST_PER_BOUNCE: f64 = 4.0;

/// What a tracer does with the cache.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Phase {
    /// A pretrace pass: a point whose samples cover it less than `nearest_count` times
    /// (under the lowered error bound) gets a new sample.
    Pretrace,
    /// The last pass before the picture, one ray per pixel: a point no sample covers gets
    /// one; with `always_sample` on, as in a pretrace pass but under the full bound.
    Fill,
    /// The picture: the cache is only read. A point no sample covers (one the fill pass
    /// did not reach, between pixels) gathers its light without keeping it.
    Picture,
}

#[derive(Debug)]
enum Caches<'w> {
    Reading(&'w [Cache]),
    /// The pretrace's: the samples of the rounds before, read only, and this unit's own
    /// new ones, kept apart until the round ends; and how many of the round's units have
    /// finished, leaving their threads free to help the others.
    Filling {
        shared: &'w [Cache],
        own: Vec<Cache>,
        finished: &'w AtomicUsize,
    },
}

/// A tracer's radiosity state: the cache, the phase, and how deep in diffuse bounces the
/// ray being traced is.
#[derive(Debug)]
pub struct Walk<'w> {
    radiosity: &'w Radiosity,
    caches: Caches<'w>,
    pub(super) phase: Phase,
    /// How many diffuse bounces lie between the camera and the current ray.
    bounce: u32,
    /// The point now gathering and its distance from the eye along the path.
    gatherer: DVec3,
    gatherer_distance: f64,
    /// The product of the diffuse reflectances of the points gathering above the current
    /// ray: the share of its light that reaches the picture.
    path_weight: f64,
    /// The lowest coverage a camera-path lookup found since the pretrace last reset it,
    /// for the adaptive pretrace.
    pub(super) weakest: f64,
    /// Whether this walk's last gather shared with another thread took no samples deeper
    /// down, so that its next is worth sharing (see `split`).
    pub(super) quiet: bool,
    /// Whether this walk is a copy tracing another walk's share of a gather, whose own
    /// gathers stay on its thread.
    copy: bool,
}

impl<'w> Walk<'w> {
    /// For the picture, reading the samples the pretrace took.
    pub fn rendering(radiosity: &'w Radiosity) -> Walk<'w> {
        Walk::new(
            radiosity,
            Caches::Reading(&radiosity.caches),
            Phase::Picture,
        )
    }

    /// For a unit of the pretrace: reads the samples of `shared` and keeps its own new
    /// ones apart; `finished` counts the round's units that have finished.
    pub(super) fn filling(
        radiosity: &'w Radiosity,
        shared: &'w [Cache],
        finished: &'w AtomicUsize,
    ) -> Walk<'w> {
        let own = radiosity.empty_caches();
        let caches = Caches::Filling {
            shared,
            own,
            finished,
        };
        Walk::new(radiosity, caches, Phase::Pretrace)
    }

    fn new(radiosity: &'w Radiosity, caches: Caches<'w>, phase: Phase) -> Walk<'w> {
        Walk {
            radiosity,
            caches,
            phase,
            bounce: 0,
            gatherer: DVec3::ZERO,
            gatherer_distance: 0.0,
            path_weight: 1.0,
            weakest: f64::INFINITY,
            quiet: true,
            copy: false,
        }
    }

    /// The samples this walk took, one cache per bounce depth; none when it only read.
    pub(super) fn into_own_samples(self) -> Vec<Cache> {
        match self.caches {
            Caches::Filling { own, .. } => own,
            Caches::Reading(_) => Vec::new(),
        }
    }

    /// Whether a unit of the round has finished, so that a thread may be free to share
    /// this walk's gathers.
    fn may_split(&self) -> bool {
        !self.copy
            && matches!(&self.caches, Caches::Filling { finished, .. }
                if finished.load(Ordering::Relaxed) > 0 && crate::parallel::threads() > 1)
    }

    /// A copy of this walk for another thread to go on with the current gather's rays:
    /// it reads the samples this walk reads, and keeps those it takes apart. Only the
    /// depths the rays reach are copied.
    pub(super) fn fork(&self) -> Walk<'w> {
        let caches = match &self.caches {
            Caches::Reading(caches) => Caches::Reading(caches),
            Caches::Filling {
                shared,
                own,
                finished,
            } => {
                let mut copy = self.radiosity.empty_caches();
                for (copy, own) in copy.iter_mut().zip(own).skip(self.bounce as usize) {
                    copy.clone_from(own);
                }
                Caches::Filling {
                    shared,
                    own: copy,
                    finished,
                }
            }
        };
        Walk {
            caches,
            copy: true,
            ..*self
        }
    }

    /// How many samples this walk has taken at each depth.
    pub(super) fn own_lengths(&self) -> Vec<usize> {
        match &self.caches {
            Caches::Filling { own, .. } => own.iter().map(|c| c.samples().len()).collect(),
            Caches::Reading(_) => Vec::new(),
        }
    }

    /// How many samples this walk has taken.
    pub(super) fn own_count(&self) -> usize {
        match &self.caches {
            Caches::Filling { own, .. } => own.iter().map(|c| c.samples().len()).sum(),
            Caches::Reading(_) => 0,
        }
    }

    /// Takes the samples `fork` took past `lengths` (this walk's at the fork), in the
    /// order it took them, as though this walk had.
    pub(super) fn adopt(&mut self, fork: Walk<'w>, lengths: &[usize]) {
        if let (Caches::Filling { own, .. }, Caches::Filling { own: theirs, .. }) =
            (&mut self.caches, fork.caches)
        {
            for ((own, theirs), &length) in own.iter_mut().zip(&theirs).zip(lengths) {
                for sample in theirs.samples().iter().skip(length) {
                    own.insert(*sample);
                }
            }
        }
    }

    /// Calls `f` with the caches of `bounce` that lookups read, as one.
    fn with_layers<T>(&self, bounce: u32, f: impl FnOnce(&[&Cache]) -> T) -> T {
        let b = bounce as usize;
        match &self.caches {
            Caches::Reading(c) => f(&[&c[b]]),
            Caches::Filling { shared, own, .. } => f(&[&shared[b], &own[b]]),
        }
    }

    /// The error bound of this phase at the current bounce, and the coverage a point needs
    /// to do without a new sample. Light gathered deeper reaches the picture only through
    /// the reflectance of the points that gathered it, so its error may be larger in
    /// proportion, up to [`LOOSEST_PER_BOUNCE`] times per bounce.
    fn rule(&self) -> (f64, f64) {
        let s = &self.radiosity.settings;
        let nearest = f64::from(s.nearest_count);
        let (bound, needed) = match self.phase {
            Phase::Pretrace => (self.radiosity.pretrace_bound(), nearest),
            Phase::Fill if s.always_sample => (s.error_bound, nearest),
            Phase::Fill | Phase::Picture => (s.error_bound, f64::MIN_POSITIVE),
        };
        let loosest = LOOSEST_PER_BOUNCE.powi(self.bounce as i32);
        ((bound / self.path_weight).min(bound * loosest), needed)
    }
}

/// The indirect light of one shading point, gathered at most once however many texture
/// layers use it.
#[derive(Debug, Clone, Copy)]
pub struct Indirect {
    point: DVec3,
    /// The surface's own normal, before any normal perturbation.
    normal: DVec3,
    level: u32,
    light: Option<DVec3>,
}

impl Indirect {
    pub fn new(point: DVec3, normal: DVec3, level: u32) -> Indirect {
        Indirect {
            point,
            normal,
            level,
            light: None,
        }
    }
}

impl<'w> Tracer<'w> {
    /// The light a finish layer receives besides the light sources, to be multiplied by
    /// its pigment: `ambient` times `ambient_light` without radiosity; with it, the
    /// gathered light times `diffuse`, plus, in legacy scenes, the ambient glow.
    pub(crate) fn ambient(
        &mut self,
        finish: &Finish,
        pigment: DVec3,
        layer_normal: DVec3,
        opacity: f64,
        indirect: &mut Indirect,
    ) -> DVec3 {
        let classic = finish.ambient * self.world.ambient_light;
        let Some(walk) = &self.radiosity else {
            return classic;
        };
        let radiosity = walk.radiosity;
        let glow = if radiosity.legacy_ambient {
            classic
        } else {
            DVec3::ZERO
        };
        if finish.diffuse == 0.0 || opacity <= 0.0 {
            return glow;
        }
        let light = match indirect.light {
            Some(light) => light,
            None => {
                let normal = if radiosity.settings.normal {
                    layer_normal
                } else {
                    indirect.normal
                };
                let reflectance = finish.diffuse * greyscale(pigment) * opacity;
                let light = self.irradiance(indirect.point, normal, indirect.level, reflectance);
                indirect.light = Some(light);
                light
            }
        };
        glow + light * finish.diffuse
    }

    /// What a gathering ray brings back from `depth` along it, through media and fog when
    /// radiosity's `media` is on (it is off by default: radiosity rays see none).
    /// `light_set` lights the media, as in [`Tracer::participate`].
    fn through_media(
        &mut self,
        ray: &Ray,
        depth: f64,
        light_set: u32,
        sample: colour::Sample,
    ) -> colour::Sample {
        let media = self
            .radiosity
            .as_ref()
            .is_some_and(|w| w.radiosity.settings.media);
        if media && self.world.participating {
            self.participate(ray, depth, light_set, sample)
        } else {
            sample
        }
    }

    /// Whether the current ray belongs to a radiosity gathering that sees no media or fog
    /// (radiosity's `media` off, the default), not even behind the clear surfaces it
    /// passes: POV-Ray's mesh_camera demo room lights its walls through media that its
    /// radiosity leaves out.
    pub(crate) fn gathering_without_media(&self) -> bool {
        self.radiosity
            .as_ref()
            .is_some_and(|w| w.bounce > 0 && !w.radiosity.settings.media)
    }

    /// Whether the current ray is a pretrace camera ray, whose own colour nobody sees.
    pub(crate) fn vain_pretrace(&self) -> bool {
        self.radiosity
            .as_ref()
            .is_some_and(|w| w.phase != Phase::Picture && w.bounce == 0)
    }

    /// Whether the current ray gathers radiosity, and so sees no highlights.
    pub(crate) fn in_radiosity_ray(&self) -> bool {
        self.radiosity.as_ref().is_some_and(|w| w.bounce > 0)
    }

    /// The light arriving at `p` around `n`, from the cache or gathered, for a surface
    /// reflecting `reflectance` of it.
    fn irradiance(&mut self, p: DVec3, n: DVec3, level: u32, reflectance: f64) -> DVec3 {
        let Some(walk) = &mut self.radiosity else {
            return DVec3::ZERO;
        };
        let radiosity = walk.radiosity;
        let bounce = walk.bounce;
        if bounce >= radiosity.settings.recursion_limit {
            return DVec3::ZERO;
        }
        let eye_distance = if bounce == 0 {
            (p - radiosity.eye).length()
        } else {
            walk.gatherer_distance + (p - walk.gatherer).length()
        };
        let (bound, needed) = walk.rule();
        if bounce == 0 && walk.phase != Phase::Picture {
            // A pretrace camera path's own light is unseen (see `vain_pretrace`): only
            // whether samples cover the point matters, for taking a new one and for the
            // adaptive pretrace, so the samples are counted only as far as that needs.
            let adaptive = radiosity
                .settings
                .adaptive_nearest_count
                .map_or(0.0, f64::from);
            let enough = needed.max(adaptive);
            let coverage = walk.with_layers(bounce, |c| cache::coverage(c, p, n, bound, enough));
            walk.weakest = walk.weakest.min(coverage);
            if coverage >= needed {
                return DVec3::ZERO;
            }
        } else {
            let found = walk.with_layers(bounce, |c| cache::lookup(c, p, n, bound));
            if bounce == 0 {
                walk.weakest = walk.weakest.min(found.coverage);
            }
            if found.coverage >= needed {
                return found.irradiance;
            }
        }
        let sample = self.gather(p, n, level, eye_distance, reflectance);
        if let Some(Walk {
            caches: Caches::Filling { own, .. },
            ..
        }) = &mut self.radiosity
        {
            own[bounce as usize].insert(sample);
        }
        sample.irradiance
    }

    /// A new sample at `p`: the mean light of `count` rays over the hemisphere about `n`,
    /// and its reuse distance.
    fn gather(
        &mut self,
        p: DVec3,
        n: DVec3,
        level: u32,
        eye_distance: f64,
        reflectance: f64,
    ) -> Sample {
        let world = self.world;
        let Some(walk) = &mut self.radiosity else {
            unreachable!("gathering needs radiosity");
        };
        let radiosity: &'w Radiosity = walk.radiosity;
        let settings = &radiosity.settings;
        let saved = (walk.gatherer, walk.gatherer_distance, walk.path_weight);
        walk.bounce += 1;
        walk.gatherer = p;
        walk.gatherer_distance = eye_distance;
        walk.path_weight *= reflectance.abs();
        let key = hash3(p, walk.bounce as i32, 0);
        // A gather whose rays meet other surfaces in the order they are shaded, by
        // importance, or whose tracer keeps photons found near its last points, stays on
        // this thread.
        let split = walk.may_split() && !radiosity.uses_importance && world.photons.is_none();
        let rays = GatherRays::new(world, radiosity, p, n, level, walk.bounce);
        let count = radiosity.directions.count();
        let mut sums = Sums::default();
        let mut shares = ObjectShares::default();
        if split {
            let directions: Vec<DVec3> = radiosity.directions.gather(key).collect();
            let mut gathered = Vec::with_capacity(count);
            self.gather_shared::<ToAFreeThread>(&rays, &directions, &mut gathered);
            gathered.into_iter().for_each(|g| sums.add(g));
        } else if radiosity.uses_importance {
            for (i, d) in radiosity.directions.gather(key).enumerate() {
                let ray = rays.ray(d);
                let Some(hit) = self.first_hit(&ray, RayKind::Radiosity) else {
                    sums.total += self.sky_light(&rays, &ray);
                    continue;
                };
                sums.inverse_distances += 1.0 / hit.t;
                let share = hit.leaf.importance * count as f64;
                if let Some(object) = shares.meet(hit.leaf, i, share) {
                    let light = self.hit_light(&rays, &ray, &hit);
                    shares.add(object, light);
                }
            }
        } else {
            for d in radiosity.directions.gather(key) {
                let gathered = self.gather_ray(&rays, d);
                sums.add(gathered);
            }
        }
        let Sums {
            inverse_distances,
            total,
        } = sums;

        if let Some(walk) = &mut self.radiosity {
            walk.bounce -= 1;
            (walk.gatherer, walk.gatherer_distance, walk.path_weight) = saved;
        }
        let mean = (total + shares.total()) / count as f64 * settings.brightness;
        let grey = DVec3::splat(greyscale(mean));
        let irradiance = mean.lerp(grey, settings.gray_threshold);
        // Ward's reuse distance: the harmonic mean of the distances the rays went, within
        // the reuse limits, which are fractions of the distance from the eye.
        let harmonic = if inverse_distances > 0.0 {
            count as f64 / inverse_distances
        } else {
            f64::INFINITY
        };
        let reuse = harmonic.clamp(
            settings.minimum_reuse * eye_distance,
            settings.maximum_reuse * eye_distance,
        );
        Sample {
            position: p,
            normal: n,
            irradiance,
            reuse,
        }
    }
}

/// Where a gather's rays start and how they are followed.
pub(super) struct GatherRays {
    origin: DVec3,
    /// The tangent, the bitangent and the normal: the directions' x, y and z.
    axes: [DVec3; 3],
    /// The trace level of the gathering point.
    level: u32,
    weight: f64,
    max_sample: Option<f64>,
    /// Whether the surfaces the rays meet may take samples of their own (the bounce is
    /// below the recursion limit): then the rays depend on those taken before them.
    pub(super) sampling: bool,
}

impl GatherRays {
    /// The rays of a gather at `p` about the normal `n`, at trace level `level`, by a walk
    /// `bounce` diffuse bounces below the camera.
    pub(super) fn new(
        world: &World,
        radiosity: &Radiosity,
        p: DVec3,
        n: DVec3,
        level: u32,
        bounce: u32,
    ) -> GatherRays {
        let settings = &radiosity.settings;
        let (t, b) = n.any_orthonormal_pair();
        GatherRays {
            origin: p,
            axes: [t, b, n],
            level,
            // Rays below radiosity's own adc_bailout are not followed: the tracer compares
            // weights with the scene's, so the weight starts at the ratio of the two.
            weight: (world.adc_bailout / settings.adc_bailout).min(1.0),
            max_sample: settings.max_sample,
            sampling: bounce < settings.recursion_limit,
        }
    }

    fn ray(&self, d: DVec3) -> Ray {
        let [t, b, n] = self.axes;
        Ray::new(self.origin, t * d.x + b * d.y + n * d.z)
    }
}

/// What one gathering ray brought back: its light, and how far it went when it met a
/// surface.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Gathered {
    light: DVec3,
    distance: Option<f64>,
}

/// A gather's sums over its rays, taken in the rays' order.
#[derive(Default)]
struct Sums {
    inverse_distances: f64,
    total: DVec3,
}

impl Sums {
    fn add(&mut self, gathered: Gathered) {
        if let Some(distance) = gathered.distance {
            self.inverse_distances += 1.0 / distance;
        }
        self.total += gathered.light;
    }
}

impl<'w> Tracer<'w> {
    /// The light the gathering ray in direction `d` brings back.
    #[inline(always)]
    pub(super) fn gather_ray(&mut self, rays: &GatherRays, d: DVec3) -> Gathered {
        let ray = rays.ray(d);
        match self.first_hit(&ray, RayKind::Radiosity) {
            Some(hit) => Gathered {
                light: self.hit_light(rays, &ray, &hit),
                distance: Some(hit.t),
            },
            None => Gathered {
                light: self.sky_light(rays, &ray),
                distance: None,
            },
        }
    }

    /// The light of the sky a gathering ray met.
    fn sky_light(&mut self, rays: &GatherRays, ray: &Ray) -> DVec3 {
        let sky = self.missed(ray, RayKind::Radiosity);
        let sky = self.through_media(ray, f64::INFINITY, 0, sky);
        limit(sky.colour, rays.max_sample)
    }

    /// The light of the surface a gathering ray met.
    fn hit_light(&mut self, rays: &GatherRays, ray: &Ray, hit: &Hit<'w>) -> DVec3 {
        if rays.level >= self.world.max_trace_level {
            return DVec3::ZERO;
        }
        let shaded = self.shade(ray, hit, rays.level + 1, rays.weight);
        let light = self.through_media(ray, hit.t, hit.leaf.light_set, shaded);
        limit(light.colour, rays.max_sample)
    }
}

/// The light of a gather's rays by the object each met, when importance is in play: an
/// object's rays beyond its share of the sequence are not shaded, and those shaded stand
/// in for them.
#[derive(Default)]
struct ObjectShares {
    /// Per object met: its address, its rays, its shaded rays and their light.
    objects: Vec<(usize, u32, u32, DVec3)>,
}

impl ObjectShares {
    /// Counts the `i`-th ray meeting `leaf`; the object's place when the ray is to be
    /// shaded, because it lies within the object's share of the sequence or is the first
    /// to meet it.
    fn meet(&mut self, leaf: &Leaf, i: usize, share: f64) -> Option<usize> {
        let address = std::ptr::from_ref(leaf) as usize;
        let at = match self.objects.iter().position(|o| o.0 == address) {
            Some(at) => at,
            None => {
                self.objects.push((address, 0, 0, DVec3::ZERO));
                self.objects.len() - 1
            }
        };
        let object = &mut self.objects[at];
        object.1 += 1;
        ((i as f64) < share || object.2 == 0).then_some(at)
    }

    fn add(&mut self, at: usize, light: DVec3) {
        self.objects[at].2 += 1;
        self.objects[at].3 += light;
    }

    /// The light of every ray, shaded or stood in for.
    fn total(&self) -> DVec3 {
        self.objects
            .iter()
            .filter(|o| o.2 > 0)
            .map(|o| o.3 * (f64::from(o.1) / f64::from(o.2)))
            .sum()
    }
}

/// `light` dimmed, keeping its hue, so that its brightness is at most `max_sample`.
fn limit(light: DVec3, max_sample: Option<f64>) -> DVec3 {
    match max_sample {
        Some(max) if greyscale(light) > max => light * (max / greyscale(light)),
        _ => light,
    }
}
