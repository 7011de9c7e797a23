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
//!
//! The points a tracer gathers at follow each other across a surface, so each search
//! first looks among the photons around a recent point (a `Neighbourhood`), which settles
//! it with the very photons the tree would give whenever they are near enough.

use super::grid::{self, CandidateGrid, Key};
use super::kdtree::{self, Found, KdTree};
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

/// Scratch space for gathering, one per tracer, with what the last searches found: the
/// next one, usually a neighbour, starts from them.
#[derive(Debug, Clone, Default)]
pub struct GatherScratch {
    /// The photons the last gathering found, as keys (see [`grid::key`]).
    pub photons: Vec<Key>,
    /// The photons a search of the tree finds.
    pub found: Vec<Found>,
    wide: Vec<Found>,
    /// The squared distance of the farthest photon of the last full search.
    last: Option<f32>,
    near: Neighbourhood,
}

/// The photons around a recent gathering point: consecutive points of a surface lie close
/// together, and a search among these few settles most of them without the tree.
#[derive(Debug, Clone, Default)]
struct Neighbourhood {
    centre: Vec3,
    /// Every photon within this distance of the centre is held; 0 when none is.
    radius: f32,
    photons: Vec<(Vec3, u32)>,
}

/// How much wider than the last search's radius a neighbourhood is taken: the points of
/// the next searches may move by the difference before it has to be taken anew. Wider
/// holds more photons to look through at every search, narrower is taken anew more
/// often; on caustic.pov 1.4 looks through the fewest photons per search (23, a tenth of
/// the searches taking the neighbourhood anew), against some 70 for a search of the tree.
const NEIGHBOURHOOD_WIDTH: f32 = 1.4;

/// How much wider (in area) than the last search's disc the next one is tried first: the
/// photons beyond it are not taken into the selection of the nearest only to leave it
/// again. On caustic.pov (`gather 3, 8`, some 19 photons in reach of a search) 1.5 takes
/// 12.0 photons into the selection per search, against 14.3 without it, the searches
/// it is too narrow for included.
const NEIGHBOUR_DISC_WIDENING: f32 = 1.5;

impl Neighbourhood {
    /// [`KdTree::nearest`] for `gather` among the photons held, when they settle it: when
    /// every photon it keeps, or its whole radius if it keeps fewer than `gather.max`, lies
    /// within the part of the neighbourhood that surrounds `p`. The margin covers the
    /// rounding of distances. `hint` as for [`KdTree::nearest`]. Inlined into the one
    /// place that asks, at every gathering: a call costs the interpreted plugin a frame.
    #[inline(always)]
    fn nearest(
        &self,
        p: Vec3,
        gather: &Gather,
        hint: Option<f32>,
        found: &mut Vec<Found>,
    ) -> Option<f32> {
        let reach = self.radius * (1.0 - 1e-4) - self.centre.distance(p);
        if reach <= 0.0 {
            return None;
        }
        let (k, max_d2) = (gather.max, gather.radius * gather.radius);
        let d2 = kdtree::nearest_among(&self.photons, p, k, max_d2, hint, found);
        (d2 <= reach * reach).then_some(d2)
    }

    /// Takes the photons within `radius` of `centre` from the tree.
    fn take(&mut self, tree: &KdTree, centre: Vec3, radius: f32) {
        self.photons.clear();
        tree.within(centre, radius * radius, &mut self.photons);
        self.centre = centre;
        self.radius = radius;
    }
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

    /// Gathers around `p` into `scratch.photons`; `None` when no photon counts. `grid`,
    /// the tree's [`CandidateGrid`] for this gathering if it has one, serves the points
    /// inside it; with a grid the photons come sorted by distance and then by index
    /// wherever they were found.
    pub fn gather(
        &self,
        tree: &KdTree,
        grid: Option<&CandidateGrid>,
        p: Vec3,
        scratch: &mut GatherScratch,
    ) -> Option<Estimate> {
        let r2 = self.radius * self.radius;
        let area = match grid.and_then(|grid| grid.candidates(p)) {
            Some(candidates) => grid::nearest(candidates, p, self.max, r2, &mut scratch.photons),
            None => {
                let area = self.nearest_without_grid(tree, p, scratch);
                keys_of(&scratch.found, grid.is_some(), &mut scratch.photons);
                area
            }
        };
        let photons = &mut scratch.photons;
        if photons.len() >= self.min {
            return estimate(photons, area);
        }
        let wide = &mut scratch.wide;
        let wide_area = tree.nearest(p, self.max, 9.0 * r2, None, wide);
        let density = photons.len() as f32 / area;
        let wide_density = wide.len() as f32 / wide_area;
        if wide.len() >= self.expand_min && wide_density > density * (1.0 + self.expand_increase) {
            return estimate(photons, area);
        }
        keys_of(wide, grid.is_some(), photons);
        estimate(photons, wide_area)
    }

    /// The nearest photons within the first radius, found among a recent point's or
    /// else in the tree, into `scratch.found` in no particular order; returns the
    /// squared radius of their disc.
    fn nearest_without_grid(&self, tree: &KdTree, p: Vec3, scratch: &mut GatherScratch) -> f32 {
        let r2 = self.radius * self.radius;
        let found = &mut scratch.found;
        let near = &mut scratch.near;
        // A neighbour's disc, a little widened, usually holds as many photons.
        let hint = scratch.last.map(|d2| NEIGHBOUR_DISC_WIDENING * d2);
        // The neighbourhood as it is, then, when it does not settle the search, taken
        // anew: one place that asks it, so that its search is inlined once.
        let mut taken = false;
        let area = loop {
            let area = near.nearest(p, self, hint, found);
            if area.is_some() || taken {
                break area;
            }
            // The neighbourhood is taken anew around `p`, as wide as the last disc allows.
            // A comparison rather than `f32::min`, a call into libm in WebAssembly; the
            // same value (`last` is never NaN).
            let last = scratch.last.filter(|last| *last < r2).unwrap_or(r2);
            near.take(tree, p, NEIGHBOURHOOD_WIDTH * last.sqrt());
            taken = true;
        };
        let area = area.unwrap_or_else(|| tree.nearest(p, self.max, r2, hint, found));
        scratch.last = (found.len() == self.max).then_some(area);
        area
    }
}

/// The keys of the photons a search of the tree found, into `keys`: in the order a grid
/// finds them, by distance and then by index, when `canonical`, else in the order found.
/// With a grid the order in which the photons are summed fixes the rounding of the sums,
/// which must then depend on the point alone, not on the points a tracer gathered at
/// before (which the neighbourhood's order does).
fn keys_of(found: &[Found], canonical: bool, keys: &mut Vec<Key>) {
    keys.clear();
    keys.extend(found.iter().map(|&(d2, index)| grid::key(d2, index)));
    if canonical {
        keys.sort_unstable();
    }
}

fn estimate(found: &[Key], area_radius2: f32) -> Option<Estimate> {
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

    /// Photons scattered unevenly over the plane y = 0 by a small linear congruential
    /// sequence: a dense stripe and a sparse rest.
    fn uneven() -> KdTree {
        let mut state = 987_654_321u32;
        let mut next = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1u32 << 24) as f32
        };
        let photons = (0..6000)
            .map(|i| {
                let x = if i % 3 == 0 {
                    next() * 0.5
                } else {
                    next() * 4.0
                };
                Photon {
                    position: Vec3::new(x, 0.0, next() * 4.0),
                    power: Vec3::ONE,
                    direction: Vec3::NEG_Y,
                }
            })
            .collect();
        KdTree::build(photons)
    }

    #[test]
    fn consecutive_gatherings_find_what_the_tree_finds() {
        let tree = uneven();
        let g = Gather {
            min: 3,
            max: 8,
            radius: 0.4,
            expand_increase: 0.2,
            expand_min: 40,
        };
        let grid = CandidateGrid::build(&tree, g.max, g.radius);
        assert!(grid.is_some());
        for grid in [None, grid.as_ref()] {
            walk_across(&tree, grid, &g);
        }
    }

    /// Gathers along a walk across the stripe of [`uneven`] and out beyond the photons,
    /// in steps of all sizes, and checks what each finds against the tree.
    fn walk_across(tree: &KdTree, grid: Option<&CandidateGrid>, g: &Gather) {
        let mut scratch = GatherScratch::default();
        let mut expected = Vec::new();
        let mut p = Vec3::new(-0.6, 0.0, 1.0);
        for i in 0..3000 {
            p += Vec3::new(0.002 * (i % 7) as f32, 0.0, 0.001 * (i % 5) as f32 - 0.0015);
            let estimate = g.gather(tree, grid, p, &mut scratch);
            let area = tree.nearest(p, g.max, g.radius * g.radius, None, &mut expected);
            if expected.len() >= g.min {
                assert_eq!(estimate.map(|e| e.area_radius2), Some(area), "{p}");
                // With a grid, found in the canonical order, by distance and then by
                // index; without one in no particular order.
                let mut found = scratch.photons.clone();
                if grid.is_none() {
                    found.sort_unstable();
                }
                let mut expected: Vec<Key> =
                    expected.iter().map(|&(d2, i)| grid::key(d2, i)).collect();
                expected.sort_unstable();
                assert_eq!(found, expected, "{p}");
            }
        }
        // The neighbourhood settles searches without a grid or outside it.
        assert!(scratch.near.radius > 0.0);
    }

    #[test]
    fn inside_the_lit_part_the_nearest_photons_set_the_disc() {
        let tree = half_plane();
        let mut scratch = GatherScratch::default();
        let e = gather(1.0)
            .gather(&tree, None, Vec3::new(-2.0, 0.0, 0.0), &mut scratch)
            .unwrap();
        assert_eq!(scratch.photons.len(), 100);
        // A hundred photons at 0.01 each fill a disc of area about 1.
        let density = 100.0 / (std::f32::consts::PI * e.area_radius2);
        assert!((density - 100.0).abs() < 12.0, "{density}");
    }

    #[test]
    fn beyond_the_edge_the_search_widens_only_when_it_finds_little() {
        let (tree, g) = (half_plane(), gather(0.5));
        let mut scratch = GatherScratch::default();
        // Just outside the edge: a few photons within 0.5; widening to 1.5 finds many
        // more at a much higher density, so the narrow estimate stands.
        let e = g.gather(&tree, None, Vec3::new(0.4, 0.0, 0.0), &mut scratch);
        assert_eq!(e.unwrap().area_radius2, 0.25);
        assert!(scratch.photons.len() < 20);
        // Farther out nothing lies within 0.5; the wide search finds fewer than 40 and
        // is kept.
        let e = g.gather(&tree, None, Vec3::new(1.3, 0.0, 0.0), &mut scratch);
        assert_eq!(e.unwrap().area_radius2, 2.25);
        assert!(!scratch.photons.is_empty() && scratch.photons.len() < 40);
        // Beyond three radii there is nothing.
        assert!(
            g.gather(&tree, None, Vec3::new(1.6, 0.0, 0.0), &mut scratch)
                .is_none()
        );
    }
}
