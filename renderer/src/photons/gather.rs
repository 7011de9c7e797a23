//! Gathering photons at a surface point, as POV-Ray 3.7 documents it: the nearest
//! photons up to `gather max` within the gather radius, their power spread over the disc
//! they cover (of the radius to the farthest one when the search filled up, else of the
//! whole search radius). When fewer than `gather min` turn up, the search widens once, to
//! three times the radius; the wider estimate replaces the first unless it found at least
//! `expand_min` photons and raised the density by more than `expand_increase`
//! (`expand_thresholds`). The factor three and the rule are what POV-Ray's renders show at
//! the edge of a caustic.
//!
//! Without a `radius`, the radius is estimated from the spacing, the number of photons
//! stored and `gather max`: 16 spacing √max / N^¼, the radius POV-Ray's own estimate gives
//! on evenly lit surfaces (measured over spacings, counts and gather settings), so that
//! caustics come out as sharp and as smooth as POV-Ray draws them.

use super::kdtree::{Found, KdTree};
use analysis::scene::Photons;
use glam::Vec3;

/// How photons are gathered.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gather {
    pub min: usize,
    pub max: usize,
    /// The first search radius.
    pub radius: f32,
    pub expand_increase: f32,
    pub expand_min: usize,
}

/// Scratch space for gathering, one per tracer, with what the last search found: the
/// next one, usually a neighbour, starts from it.
#[derive(Debug, Clone, Default)]
pub struct GatherScratch {
    pub found: Vec<Found>,
    wide: Vec<Found>,
    /// The squared distance of the farthest photon of the last full search.
    last: Option<f32>,
}

/// What a search found: the photons (in the scratch space) and the disc they share.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// The squared radius of the disc the photons' power spreads over.
    pub area_radius2: f32,
}

impl Gather {
    pub fn new(settings: &Photons, spacing: f64, stored: usize) -> Gather {
        let max = settings.gather_max.max(1) as usize;
        let estimated = || 16.0 * spacing * (max as f64).sqrt() / (stored.max(1) as f64).powf(0.25);
        let radius = settings.radius.unwrap_or_else(estimated) * settings.radius_multiplier;
        Gather {
            min: (settings.gather_min as usize).min(max),
            max,
            radius: radius as f32,
            expand_increase: settings.expand_increase as f32,
            expand_min: settings.expand_min as usize,
        }
    }

    /// Gathers around `p` into `scratch.found`; `None` when no photon counts.
    pub fn gather(&self, tree: &KdTree, p: Vec3, scratch: &mut GatherScratch) -> Option<Estimate> {
        let r2 = self.radius * self.radius;
        // A neighbour's disc, a little widened, usually holds as many photons.
        let hint = scratch.last.map(|d2| 2.0 * d2);
        let found = &mut scratch.found;
        let area = tree.nearest(p, self.max, r2, hint, found);
        scratch.last = (found.len() == self.max).then_some(area);
        if found.len() >= self.min {
            return estimate(found, area);
        }
        let wide = &mut scratch.wide;
        let wide_area = tree.nearest(p, self.max, 9.0 * r2, None, wide);
        let density = found.len() as f32 / area;
        let wide_density = wide.len() as f32 / wide_area;
        if wide.len() >= self.expand_min && wide_density > density * (1.0 + self.expand_increase) {
            return estimate(found, area);
        }
        std::mem::swap(found, wide);
        estimate(found, wide_area)
    }
}

fn estimate(found: &[Found], area_radius2: f32) -> Option<Estimate> {
    (!found.is_empty() && area_radius2 > 0.0).then_some(Estimate { area_radius2 })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::photons::kdtree::Photon;

    /// Photons on a grid of spacing 0.1 over the half plane x < 0 of the plane y = 0.
    fn half_plane() -> KdTree {
        let mut photons = Vec::new();
        for i in -40..0 {
            for j in -40..40 {
                photons.push(Photon {
                    position: Vec3::new(i as f32 * 0.1 + 0.05, 0.0, j as f32 * 0.1 + 0.05),
                    power: Vec3::ONE,
                    direction: Vec3::NEG_Y,
                });
            }
        }
        KdTree::build(photons)
    }

    fn gather(radius: f32) -> Gather {
        Gather {
            min: 20,
            max: 100,
            radius,
            expand_increase: 0.2,
            expand_min: 40,
        }
    }

    #[test]
    fn inside_the_lit_part_the_nearest_photons_set_the_disc() {
        let tree = half_plane();
        let mut scratch = GatherScratch::default();
        let e = gather(1.0)
            .gather(&tree, Vec3::new(-2.0, 0.0, 0.0), &mut scratch)
            .unwrap();
        assert_eq!(scratch.found.len(), 100);
        // A hundred photons at 0.01 each fill a disc of area about 1.
        let density = 100.0 / (std::f32::consts::PI * e.area_radius2);
        assert!((density - 100.0).abs() < 12.0, "{density}");
    }

    #[test]
    fn beyond_the_edge_the_search_widens_only_when_it_finds_little() {
        let tree = half_plane();
        let mut scratch = GatherScratch::default();
        let g = gather(0.5);
        // Just outside the edge: a few photons within 0.5; widening to 1.5 finds many
        // more at a much higher density, so the narrow estimate stands.
        let e = g.gather(&tree, Vec3::new(0.4, 0.0, 0.0), &mut scratch);
        assert_eq!(e.unwrap().area_radius2, 0.25);
        assert!(scratch.found.len() < 20);
        // Farther out nothing lies within 0.5; the wide search finds fewer than 40 and
        // is kept.
        let e = g.gather(&tree, Vec3::new(1.3, 0.0, 0.0), &mut scratch);
        assert_eq!(e.unwrap().area_radius2, 2.25);
        assert!(!scratch.found.is_empty() && scratch.found.len() < 40);
        // Beyond three radii there is nothing.
        assert!(
            g.gather(&tree, Vec3::new(1.6, 0.0, 0.0), &mut scratch)
                .is_none()
        );
    }
}
