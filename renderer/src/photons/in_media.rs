//! Media photons (`photons { media max_steps, factor }`), as POV-Ray 3.7 documents them: a
//! photon that crosses scattering media after a reflection or refraction leaves photons
//! along the way, about the surface spacing times `factor` apart but at most `max_steps`
//! in one stretch of media, spread evenly over it (POV-Ray's renders with `media 3` show
//! three evenly placed blobs across a box of media). Each carries the photon's power times
//! the length it stands for. While tracing, a media sample gathers the nearest of them
//! within the media radius and takes each as light arriving from where it came, so the
//! media's phase function weighs it as it weighs a light: the power per volume of the
//! gathered sphere is the light's fluence, exact for a beam of evenly spaced photons.
//!
//! Media with `collect off` and media that do not scatter neither keep nor gather
//! photons; where several media share a stretch and one of them collects, all of them
//! gather, as the documentation says.

use super::kdtree::{Found, KdTree, Photon};
use crate::interior::Interior;
use crate::media::{self, Incident, Medium};
use crate::tracer::World;
use glam::DVec3;

/// How photons are left in media during the photon pass.
#[derive(Debug, Clone, Copy)]
pub struct Deposit {
    /// The distance between media photons, before the target's spacing multiplier.
    pub step: f64,
    pub max_steps: u32,
    /// How far each photon strays from the middle of its share of the stretch, as a
    /// fraction of the share: the photons block's `jitter`.
    pub jitter: f64,
}

impl Deposit {
    /// The places along a stretch of `length` where photons go, at `step` apart at most
    /// `max_steps` of them, each moved within its share by the jitter (fixed by `seed`):
    /// `(distance from the start, length each stands for)`.
    pub fn places(&self, length: f64, step: f64, seed: u64) -> impl Iterator<Item = (f64, f64)> {
        let count = if length > 0.0 && length.is_finite() && step > 0.0 {
            (length / step).ceil().clamp(1.0, f64::from(self.max_steps)) as u32
        } else {
            0
        };
        let width = length / f64::from(count.max(1));
        let jitter = self.jitter;
        (0..count).map(move |i| {
            let offset = 0.5 + jitter * (media::unit(seed, i) - 0.5);
            ((f64::from(i) + offset) * width, width)
        })
    }
}

/// Whether any of these media keep photons.
pub fn collecting<'a>(mut media: impl Iterator<Item = &'a Medium>) -> bool {
    media.any(Medium::collects_photons)
}

/// The media a photon or a viewing ray crosses inside `interiors` (outermost first): the
/// containers' media and the atmosphere's, none inside a solid object, which keeps them
/// out as it does for viewing rays.
pub fn media_within<'w>(
    world: &'w World,
    interiors: &[&'w Interior],
) -> impl Iterator<Item = &'w Medium> {
    let open = !interiors.iter().any(|i| !i.hollow);
    let inner = interiors
        .iter()
        .filter(move |_| open)
        .flat_map(|i| &i.media);
    let atmospheric = world
        .atmosphere
        .iter()
        .filter(move |_| open)
        .flat_map(|a| &a.media);
    inner.chain(atmospheric)
}

/// The photons left in media, ready to gather.
#[derive(Debug, Clone)]
pub struct MediaMap {
    tree: KdTree,
    radius2: f32,
    max: usize,
}

impl MediaMap {
    pub fn new(photons: Vec<Photon>, radius: f64, max: usize) -> MediaMap {
        MediaMap {
            tree: KdTree::build(photons),
            radius2: (radius * radius) as f32,
            max: max.max(1),
        }
    }

    /// Adds the gathered photons around `p` to `out` as light arriving at `p`: the unit
    /// direction back to where each came from and its power per volume of the sphere they
    /// were gathered from (of the farthest one's distance when the search filled up).
    pub fn lights_at(&self, p: DVec3, found: &mut Vec<Found>, out: &mut Vec<Incident>) {
        let r2 = self
            .tree
            .nearest(p.as_vec3(), self.max, self.radius2, None, found);
        if found.is_empty() || r2 <= 0.0 {
            return;
        }
        // r³ by one square root: powf is a software routine in WebAssembly.
        let r2 = f64::from(r2);
        let volume = 4.0 / 3.0 * std::f64::consts::PI * r2 * r2.sqrt();
        for &(_, index) in found.iter() {
            let photon = self.tree.photon(index);
            let back = -photon.direction.as_dvec3();
            out.push((back, photon.power.as_dvec3() / volume));
        }
    }
}

/// A media photon at `position` travelling along `direction` with `power` (already times
/// the length it stands for).
pub fn media_photon(position: DVec3, power: DVec3, direction: DVec3) -> Photon {
    Photon {
        position: position.as_vec3(),
        power: power.as_vec3(),
        direction: direction.normalize_or_zero().as_vec3(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_stretches_spread_their_few_photons_evenly() {
        let mut deposit = Deposit {
            step: 0.1,
            max_steps: 3,
            jitter: 0.0,
        };
        let places: Vec<_> = deposit.places(6.0, 0.1, 7).collect();
        assert_eq!(places, vec![(1.0, 2.0), (3.0, 2.0), (5.0, 2.0)]);
        let places: Vec<_> = deposit.places(0.25, 0.1, 7).collect();
        assert_eq!(places.len(), 3);
        assert!(places.iter().all(|(_, w)| (w - 0.25 / 3.0).abs() < 1e-12));
        assert_eq!(deposit.places(0.05, 0.1, 7).count(), 1);
        assert_eq!(deposit.places(0.0, 0.1, 7).count(), 0);
        assert_eq!(deposit.places(f64::INFINITY, 0.1, 7).count(), 0);
        // Jitter moves each photon within its share, the same way for the same seed.
        deposit.jitter = 0.4;
        let a: Vec<_> = deposit.places(6.0, 0.1, 7).collect();
        assert_eq!(a, deposit.places(6.0, 0.1, 7).collect::<Vec<_>>());
        for ((at, width), i) in a.iter().zip(0..) {
            let middle = (f64::from(i) + 0.5) * width;
            assert!((at - middle).abs() <= 0.2 * width && *at != middle, "{at}");
        }
    }

    /// A beam of parallel photons on a square grid of side `s`, each left every `s` along
    /// the beam with power `s² × s` (light 1 through each area `s²`, times its length),
    /// gathers to light 1: the fluence of the beam.
    #[test]
    fn a_uniform_beam_gathers_to_its_light() {
        let s = 0.05;
        let mut photons = Vec::new();
        for i in -30..30 {
            for j in -30..30 {
                for k in -30..30 {
                    let p = DVec3::new(f64::from(i), f64::from(j), f64::from(k)) * s;
                    photons.push(media_photon(p, DVec3::splat(s * s * s), DVec3::X));
                }
            }
        }
        let map = MediaMap::new(photons, 0.5, 100);
        let (mut found, mut out) = (Vec::new(), Vec::new());
        map.lights_at(DVec3::ZERO, &mut found, &mut out);
        assert_eq!(out.len(), 100);
        let total: DVec3 = out.iter().map(|(_, c)| *c).sum();
        assert!((total.x - 1.0).abs() < 0.15, "{total}");
        assert!(out.iter().all(|(d, _)| *d == -DVec3::X));
    }
}
