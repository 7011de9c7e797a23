//! A grid over the stored photons whose cells each list, in advance, every photon that can
//! be among the `k` nearest within the gather radius of any point in the cell: a search
//! from a point in the grid looks through its cell's short list and nothing else.
//!
//! The `k` photons nearest a cell's centre lie within their distance from it plus `h`,
//! the distance from the centre to the cell's farthest point, of every point of the cell;
//! so the `k` nearest of such a point lie within that distance plus `h` again of the
//! centre, and those within the radius within the radius plus `h`. A cell lists the
//! photons that pass both, sorted by their distance from its centre. A search from a
//! point `t` from the centre stops at the first photon farther from the centre than `t`
//! plus the distance to the `k`-th nearest photon kept so far: it and the rest are
//! farther from the point than that photon. The photons come out sorted by distance and
//! then by index, an order that does not depend on how they were visited.
//!
//! The cells are small next to the typical distance to the `k`-th nearest photon, which
//! keeps the lists short; the grid gives up (and the searches go to the tree) when the
//! cells or the lists would take more than a few tens of megabytes.

use super::kdtree::{Found, KdTree};
use crate::parallel::map_indices;
use glam::Vec3;

/// A photon in a cell's list: its position, a lower bound on its distance from the
/// cell's centre, and its index in the tree.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Candidate {
    position: Vec3,
    from_centre: f32,
    index: u32,
}

/// A cell: where its list starts (the next cell's start ends it) and its centre.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Cell {
    start: u32,
    centre: Vec3,
}

#[derive(Debug, Clone)]
pub struct CandidateGrid {
    /// The corners of the box whose points the lists serve: the photons' bounds widened
    /// by a margin.
    min: Vec3,
    max: Vec3,
    /// The photons' lower corner, from which cells are counted.
    origin: Vec3,
    /// Cells per unit along each axis, 0 along an axis the photons do not spread along.
    scale: Vec3,
    /// The index of the last cell along each axis.
    last: [u32; 3],
    /// The cells per step along y and along z.
    strides: [u32; 2],
    /// The cells along x, then y, then z, and one more that ends the last list.
    cells: Vec<Cell>,
    candidates: Vec<Candidate>,
}

/// The cell size as a fraction of the distance to the `k`-th nearest photon, typical over
/// the photons: smaller cells have shorter lists, but take longer to build. On
/// caustic.pov cells as wide as that distance look through the fewest photons, cells
/// built and photons searched together.
const CELL_FRACTION: f32 = 1.0;

/// The most cells, and the most photons listed in all cells together: some 20 MB. Beyond
/// either the cells grow, up to `ATTEMPTS` times, and then the grid gives up.
const MAX_CELLS: usize = 1 << 18;
const MAX_CANDIDATES: usize = 1 << 20;
const ATTEMPTS: usize = 4;

/// How much the bounds of the lists are widened against rounding: far more than the few
/// units in the last place by which a distance the searches compute in single precision
/// can differ from the exact one.
const SLACK: f64 = 1e-4;

/// How many photons the typical distance to the `k`-th nearest is measured around.
const SAMPLES: usize = 512;

impl CandidateGrid {
    /// The grid for searches of the `k` nearest photons of `tree` within `radius`; `None`
    /// when the tree is empty or the grid would take too much memory.
    pub fn build(tree: &KdTree, k: usize, radius: f32) -> Option<CandidateGrid> {
        let positions = tree.positions();
        if positions.is_empty() || k == 0 || radius <= 0.0 || !radius.is_finite() {
            return None;
        }
        let (lo, hi) = positions.iter().fold(
            (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
            |(lo, hi), p| (lo.min(*p), hi.max(*p)),
        );
        if !(lo.is_finite() && hi.is_finite()) {
            return None;
        }
        let mut size = typical_kth_distance(tree, k, radius) * CELL_FRACTION;
        if size.is_nan() || size <= 0.0 {
            size = radius * CELL_FRACTION;
        }
        let mut attempts = 0;
        loop {
            let counts = ((hi - lo) / size).ceil().max(Vec3::ONE);
            if counts.x * counts.y * counts.z > MAX_CELLS as f32 {
                size *= 2.0;
                continue;
            }
            let counts = [counts.x as u32, counts.y as u32, counts.z as u32];
            if let Some(grid) = Self::with_counts(tree, k, radius, lo, hi, counts) {
                return Some(grid);
            }
            attempts += 1;
            if attempts == ATTEMPTS {
                return None;
            }
            size *= 2.0;
        }
    }

    /// The grid of `counts` cells along the axes over the photons' bounds `lo`, `hi`;
    /// `None` when its lists would be too long.
    fn with_counts(
        tree: &KdTree,
        k: usize,
        radius: f32,
        lo: Vec3,
        hi: Vec3,
        counts: [u32; 3],
    ) -> Option<CandidateGrid> {
        let extent = hi - lo;
        let sides = extent / Vec3::new(counts[0] as f32, counts[1] as f32, counts[2] as f32);
        // Each list also serves the points a little outside its cell: the cell a search
        // computes for a point can be off by a rounding, by at most a few 2^-24 of the
        // cells along the axis.
        let most = counts.into_iter().max().unwrap_or(1) as f32;
        let margin = sides.max_element() * (1.0 / 256.0f32).max(most / (1 << 20) as f32);
        let scale = Vec3::select(extent.cmpgt(Vec3::ZERO), 1.0 / sides, Vec3::ZERO);
        let layout = Layout {
            origin: lo,
            sides,
            margin: f64::from(margin),
            counts,
            k,
            radius,
        };
        // Rows of cells along x, built in parallel natively and in order in the plugin.
        let rows = map_indices((counts[1] * counts[2]) as usize, |row| {
            layout.row(tree, row as u32)
        });
        let total: usize = rows.iter().map(|(list, _)| list.len()).sum();
        if total > MAX_CANDIDATES {
            return None;
        }
        let mut cells = Vec::with_capacity((counts[0] * counts[1] * counts[2]) as usize + 1);
        let mut candidates = Vec::with_capacity(total);
        for (list, row) in rows {
            let base = candidates.len() as u32;
            cells.extend(row.into_iter().map(|cell| Cell {
                start: base + cell.start,
                ..cell
            }));
            candidates.extend(list);
        }
        cells.push(Cell {
            start: candidates.len() as u32,
            centre: Vec3::ZERO,
        });
        Some(CandidateGrid {
            min: lo - Vec3::splat(margin),
            max: hi + Vec3::splat(margin),
            origin: lo,
            scale,
            last: counts.map(|c| c - 1),
            strides: [counts[0], counts[0] * counts[1]],
            cells,
            candidates,
        })
    }

    /// The list of the cell holding `p` and the cell's centre; `None` when `p` lies
    /// outside the grid.
    #[inline(always)]
    pub fn candidates(&self, p: Vec3) -> Option<(&[Candidate], Vec3)> {
        let inside = p.x >= self.min.x
            && p.x <= self.max.x
            && p.y >= self.min.y
            && p.y <= self.max.y
            && p.z >= self.min.z
            && p.z <= self.max.z;
        if !inside {
            return None;
        }
        // The conversions saturate: a point just below the origin falls in the first
        // cell.
        let f = (p - self.origin) * self.scale;
        let x = (f.x as u32).min(self.last[0]);
        let y = (f.y as u32).min(self.last[1]);
        let z = (f.z as u32).min(self.last[2]);
        let cell = (x + y * self.strides[0] + z * self.strides[1]) as usize;
        let (start, end) = (self.cells[cell].start, self.cells[cell + 1].start);
        Some((
            &self.candidates[start as usize..end as usize],
            self.cells[cell].centre,
        ))
    }
}

/// The grid's cells as the build sees them.
struct Layout {
    origin: Vec3,
    sides: Vec3,
    margin: f64,
    counts: [u32; 3],
    k: usize,
    radius: f32,
}

impl Layout {
    /// The lists of the cells of one row along x (`row` counting rows along y, then
    /// z), one after the other, and the cells with their starts in it.
    fn row(&self, tree: &KdTree, row: u32) -> (Vec<Candidate>, Vec<Cell>) {
        let (y, z) = (row % self.counts[1], row / self.counts[1]);
        let (mut list, mut cells) = (Vec::new(), Vec::new());
        let (mut found, mut within) = (Vec::new(), Vec::new());
        // The distance from the last cell's centre to its `k`-th nearest photon, which
        // bounds the next one's: a first guess that spares the search the photons beyond.
        let mut last: Option<(Vec3, f64)> = None;
        let radius = f64::from(self.radius);
        let r2 = self.radius * self.radius;
        for x in 0..self.counts[0] {
            let index = Vec3::new(x as f32, y as f32, z as f32);
            let corner = self.origin + index * self.sides;
            let centre = corner + 0.5 * self.sides;
            let (min, max) = (
                corner.as_dvec3() - self.margin,
                (corner + self.sides).as_dvec3() + self.margin,
            );
            let c = centre.as_dvec3();
            let h = (c - min).abs().max((max - c).abs()).length();
            let hint = last.map(|(previous, kth)| {
                let bound = (kth + previous.as_dvec3().distance(c)) * (1.0 + SLACK);
                (bound * bound) as f32
            });
            let kth = tree.nearest(centre, self.k, r2, hint, &mut found);
            let kth = (found.len() == self.k).then(|| f64::from(kth).sqrt());
            last = kth.map(|kth| (centre, kth));
            let reach = (kth.map_or(radius, |kth| (kth + h).min(radius)) + h) * (1.0 + 2.0 * SLACK);
            within.clear();
            tree.within(centre, (reach * reach) as f32, &mut within);
            let start = list.len();
            list.extend(within.iter().map(|&(position, index)| Candidate {
                position,
                from_centre: (position.as_dvec3().distance(c) * (1.0 - SLACK)) as f32,
                index,
            }));
            list[start..].sort_unstable_by(|a, b| {
                (a.from_centre.total_cmp(&b.from_centre)).then(a.index.cmp(&b.index))
            });
            cells.push(Cell {
                start: start as u32,
                centre,
            });
        }
        (list, cells)
    }
}

/// The median distance from a photon to its `k`-th nearest other photon within
/// `radius` (the radius when fewer lie within it), over a sample of the photons.
fn typical_kth_distance(tree: &KdTree, k: usize, radius: f32) -> f32 {
    let positions = tree.positions();
    let step = positions.len().div_ceil(SAMPLES);
    let mut found = Vec::new();
    let mut distances: Vec<f32> = positions
        .iter()
        .step_by(step)
        .map(|p| {
            // The photon itself is the nearest.
            let d2 = tree.nearest(*p, k + 1, radius * radius, None, &mut found);
            if found.len() == k + 1 {
                d2.sqrt()
            } else {
                radius
            }
        })
        .collect();
    let middle = distances.len() / 2;
    let (_, median, _) = distances.select_nth_unstable_by(middle, f32::total_cmp);
    *median
}

/// The up to `k` photons nearest `p` within squared distance `max_d2` among `candidates`
/// (the list of the cell holding `p`, whose centre is `centre`), into `found` sorted by
/// squared distance and then by index; returns the squared distance of the farthest one
/// kept when `k` were found, else `max_d2`. These are the photons [`KdTree::nearest`]
/// finds, a tie at the farthest going to the lower index.
#[inline(always)]
pub fn nearest(
    (candidates, centre): (&[Candidate], Vec3),
    p: Vec3,
    k: usize,
    max_d2: f32,
    found: &mut Vec<Found>,
) -> f32 {
    if found.len() < k {
        found.resize(k, (0.0, 0));
    }
    let keep = &mut found[..k];
    let mut count = 0;
    // The farthest photon kept once `k` are: a photon must come before it.
    let mut limit = (max_d2, 0);
    // A photon farther than this from the centre is farther than the limit from `p`.
    let off_centre = p.distance(centre);
    let mut stop = off_centre + max_d2.sqrt();
    for candidate in candidates {
        if candidate.from_centre > stop {
            break;
        }
        let offered = (candidate.position.distance_squared(p), candidate.index);
        if !before(offered, limit) {
            continue;
        }
        let mut i = count;
        if count < k {
            count += 1;
        } else {
            i = k - 1;
        }
        while i > 0 && before(offered, keep[i - 1]) {
            keep[i] = keep[i - 1];
            i -= 1;
        }
        keep[i] = offered;
        if count == k {
            limit = keep[k - 1];
            stop = off_centre + limit.0.sqrt();
        }
    }
    found.truncate(count);
    if count == k { limit.0 } else { max_d2 }
}

/// Whether `a` is nearer than `b`, or as near with a lower index.
#[inline(always)]
fn before(a: Found, b: Found) -> bool {
    a.0 < b.0 || (a.0 == b.0 && a.1 < b.1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::photons::kdtree::Photon;

    /// A small linear congruential sequence of numbers in [0, 1).
    fn sequence(seed: u32) -> impl FnMut() -> f32 {
        let mut state = seed;
        move || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1u32 << 24) as f32
        }
    }

    fn tree(positions: &[Vec3]) -> KdTree {
        KdTree::build(
            positions
                .iter()
                .map(|&position| Photon {
                    position,
                    power: Vec3::ONE,
                    direction: Vec3::NEG_Y,
                })
                .collect(),
        )
    }

    /// The `k` nearest within `max_d2` by looking at every photon, sorted by distance
    /// and then by index, and the squared radius of their disc.
    fn brute_force(tree: &KdTree, p: Vec3, k: usize, max_d2: f32) -> (Vec<Found>, f32) {
        let mut all: Vec<Found> = (0..)
            .zip(tree.positions())
            .map(|(index, q)| (q.distance_squared(p), index))
            .filter(|(d2, _)| *d2 < max_d2)
            .collect();
        all.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        all.truncate(k);
        let area = if all.len() == k { all[k - 1].0 } else { max_d2 };
        (all, area)
    }

    /// Points spread over the grid's box and a little beyond it, and points on and
    /// about the borders of its cells.
    fn queries(grid: &CandidateGrid, next: &mut impl FnMut() -> f32) -> Vec<Vec3> {
        let (min, max) = (grid.min, grid.max);
        let span = max - min;
        let mut points: Vec<Vec3> = (0..400)
            .map(|_| min - 0.1 * span + 1.2 * span * Vec3::new(next(), next(), next()))
            .collect();
        let sides = Vec3::select(grid.scale.cmpgt(Vec3::ZERO), 1.0 / grid.scale, Vec3::ZERO);
        for _ in 0..400 {
            let cell =
                Vec3::new(next(), next(), next()) * (Vec3::from(grid.last.map(|l| l as f32)) + 1.0);
            let corner = grid.origin + cell.floor() * sides;
            // On a border, or a rounding or a margin off it.
            let offset = match (next() * 4.0) as u32 {
                0 => 0.0,
                1 => 1e-6,
                2 => -1e-6,
                _ => (next() - 0.5) * 0.02,
            };
            let along = Vec3::new(next(), next(), next());
            let mut p = corner + along * sides;
            let axis = (next() * 3.0) as usize;
            p[axis] = corner[axis] + offset * sides.max_element();
            points.push(p);
        }
        // The corners of the box.
        points.extend([
            min,
            max,
            Vec3::new(min.x, max.y, min.z),
            Vec3::new(max.x, min.y, max.z),
        ]);
        points
    }

    /// Checks every query inside the grid against the brute force, and that some were.
    fn check(positions: &[Vec3], k: usize, radius: f32, seed: u32) {
        let tree = tree(positions);
        let grid = CandidateGrid::build(&tree, k, radius).expect("the grid is built");
        let mut next = sequence(seed);
        let mut found = Vec::new();
        let mut served = 0;
        for p in queries(&grid, &mut next) {
            let Some(candidates) = grid.candidates(p) else {
                continue;
            };
            served += 1;
            let area = nearest(candidates, p, k, radius * radius, &mut found);
            let (expected, expected_area) = brute_force(&tree, p, k, radius * radius);
            assert_eq!(found, expected, "{p} k {k} radius {radius}");
            assert_eq!(area, expected_area, "{p}");
        }
        assert!(served > 400, "{served}");
    }

    fn cloud(n: usize, seed: u32, shape: impl Fn(&mut dyn FnMut() -> f32) -> Vec3) -> Vec<Vec3> {
        let mut next = sequence(seed);
        (0..n).map(|_| shape(&mut next)).collect()
    }

    #[test]
    fn a_cell_finds_what_all_photons_give_in_a_volume() {
        let positions = cloud(3000, 1, |next: &mut dyn FnMut() -> f32| {
            Vec3::new(next(), next(), next()) * Vec3::new(2.0, 1.0, 0.5)
        });
        for (k, radius) in [(8, 0.3), (1, 0.05), (20, 0.2), (8, 0.02)] {
            check(&positions, k, radius, 7);
        }
    }

    #[test]
    fn a_cell_finds_what_all_photons_give_on_a_plane() {
        // A caustic's photons on a floor: dense in the middle, sparse around.
        let positions = cloud(4000, 2, |next: &mut dyn FnMut() -> f32| {
            let (r, a) = (next() * next() * 4.0, next() * std::f32::consts::TAU);
            Vec3::new(r * a.cos() - 1.0, -2.0, r * a.sin() + 0.5)
        });
        for (k, radius) in [(8, 0.55), (3, 0.1), (50, 1.0)] {
            check(&positions, k, radius, 8);
        }
    }

    #[test]
    fn a_cell_finds_what_all_photons_give_on_a_line_and_with_ties() {
        let line = cloud(500, 3, |next: &mut dyn FnMut() -> f32| {
            Vec3::new(1.0, next() * 5.0, 3.0)
        });
        check(&line, 8, 0.5, 9);
        // Photons on a lattice, many at the same distance from a point, and some on top
        // of each other: ties go to the lower index.
        let mut lattice: Vec<Vec3> = (0..900)
            .map(|i| Vec3::new((i % 30) as f32 * 0.1, 0.0, (i / 30) as f32 * 0.1))
            .collect();
        lattice.extend_from_within(100..200);
        check(&lattice, 8, 0.25, 10);
        check(&lattice, 30, 0.4, 11);
    }

    #[test]
    fn more_photons_wanted_than_there_are() {
        let positions = cloud(5, 4, |next: &mut dyn FnMut() -> f32| {
            Vec3::new(next(), next(), 0.0)
        });
        check(&positions, 8, 10.0, 12);
        check(&positions, 8, 0.3, 13);
    }

    #[test]
    fn no_grid_without_photons() {
        assert!(CandidateGrid::build(&tree(&[]), 8, 1.0).is_none());
    }
}
