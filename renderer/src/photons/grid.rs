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
//! cells or the lists would take more than a few tens of megabytes. The lists are built
//! from the photons sorted into bins of a few cells, taken nearest first.

use super::kdtree::KdTree;
use crate::parallel::map_indices;
use glam::{DVec3, Vec3};

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
/// caustic.pov a half takes the fewest operations, cells built and photons searched
/// together (a search looks through 11 photons).
const CELL_FRACTION: f32 = 0.5;

/// The most cells, and the most photons listed in all cells together: some 20 MB. Beyond
/// either the cells grow, up to `ATTEMPTS` times, and then the grid gives up.
const MAX_CELLS: usize = 1 << 18;
const MAX_CANDIDATES: usize = 1 << 20;
const ATTEMPTS: usize = 4;

/// How much the bounds of the lists are widened against rounding: far more than the few
/// units in the last place by which a distance the searches compute in single precision
/// can differ from the exact one.
const SLACK: f64 = 1e-4;

/// The most photons a grid gathers: its lists grow with the number gathered and keeping
/// the nearest in order costs more than the tree's heap, so that a grid for POV-Ray's
/// default 100 (or the 60 of the photon fidelity scenes) makes a native render slower
/// (photons-prism 178 -> 352 ms).
pub const MAX_GATHERED: usize = 16;

/// How many photons the typical distance to the `k`-th nearest is measured around.
const SAMPLES: usize = 512;

impl CandidateGrid {
    /// The grid for searches of the `k` nearest photons of `tree` within `radius`; `None`
    /// when the tree is empty, `k` is more than [`MAX_GATHERED`] or the grid would take
    /// too much memory.
    pub fn build(tree: &KdTree, k: usize, radius: f32) -> Option<CandidateGrid> {
        let positions = tree.positions();
        if positions.is_empty()
            || k == 0
            || k > MAX_GATHERED
            || radius <= 0.0
            || !radius.is_finite()
        {
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
        let mut layout = Layout {
            origin: lo,
            sides,
            margin: f64::from(margin),
            counts,
            k,
            radius,
            bins: Bins::default(),
        };
        layout.bins = Bins::new(tree.positions(), &layout, scale);
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
    bins: Bins,
}

/// The photons sorted into bins of two cells along each axis the photons spread along,
/// and the offsets from a bin to the bins around it, nearest first: the photons near a
/// cell's centre are gathered from the bins around it, cheaper than from the tree. The
/// bins are laid out with a border of empty ones as wide as the offsets reach, so that
/// an offset never leaves them.
#[derive(Default)]
struct Bins {
    photons: Vec<(Vec3, u32)>,
    /// Where each bin's photons start, and where the last one's end, border included.
    starts: Vec<u32>,
    /// The cells along each axis of a bin.
    bin: [u32; 3],
    /// The bins along x and y, border included.
    padded: [usize; 2],
    /// The width of the border along each axis.
    border: [u32; 3],
    /// For each place of a cell in its bin, offsets to the bins around as steps in
    /// `starts`, each with the least distance from the cell's centre to a point of the
    /// bin (widened by the margin), in that order.
    offsets: Vec<Vec<(isize, f64)>>,
    /// How far from a cell's centre the offsets cover every point.
    reach: f64,
}

/// The most offsets to the bins around a bin, and the most bins with the border: cells
/// whose lists reach farther are built from the tree.
const MAX_OFFSETS: usize = 1 << 14;
const MAX_PADDED: usize = 1 << 20;

impl Bins {
    fn new(positions: &[Vec3], layout: &Layout, scale: Vec3) -> Bins {
        let bin = layout.counts.map(|c| if c > 1 { 2 } else { 1 });
        let counts = [0, 1, 2].map(|i| layout.counts[i].div_ceil(bin[i]));
        // Every cell the lists may need: within the radius plus a cell's half diagonal,
        // as far as the limits allow.
        let sides = layout.sides.as_dvec3();
        let bin_sides = sides * DVec3::new(bin[0].into(), bin[1].into(), bin[2].into());
        let mut reach = f64::from(layout.radius) + sides.length();
        let borders = |reach: f64| {
            [bin_sides.x, bin_sides.y, bin_sides.z].map(|side| {
                if side > 0.0 {
                    ((reach + layout.margin) / side).floor() as u32 + 1
                } else {
                    0
                }
            })
        };
        let size = |border: [u32; 3], base: [u32; 3]| {
            (0..3)
                .map(|i| (base[i] + 2 * border[i]) as usize)
                .product::<usize>()
        };
        let mut border = borders(reach);
        while size(border, [1; 3]) > MAX_OFFSETS || size(border, counts) > MAX_PADDED {
            reach *= 0.8;
            border = borders(reach);
        }
        let padded = [0, 1, 2].map(|i| (counts[i] + 2 * border[i]) as usize);
        let last = layout.counts.map(|c| c - 1);
        let bin_of = |p: Vec3| {
            let f = (p - layout.origin) * scale;
            let [x, y, z] = [f.x, f.y, f.z].map(|f| f as u32);
            let at = [x.min(last[0]), y.min(last[1]), z.min(last[2])];
            let [x, y, z] = [0, 1, 2].map(|i| (at[i] / bin[i] + border[i]) as usize);
            x + padded[0] * (y + padded[1] * z)
        };
        let bins = padded.iter().product::<usize>();
        let mut starts = vec![0u32; bins + 1];
        for p in positions {
            starts[bin_of(*p) + 1] += 1;
        }
        for i in 0..bins {
            starts[i + 1] += starts[i];
        }
        let mut next = starts.clone();
        let mut photons = vec![(Vec3::ZERO, 0); positions.len()];
        for (index, p) in (0..).zip(positions) {
            let bin = bin_of(*p);
            photons[next[bin] as usize] = (*p, index);
            next[bin] += 1;
        }
        let span = border.map(|b| b as i32);
        // Places along an axis whose bins hold one cell are never asked for.
        let offsets = (0..8)
            .map(|place| {
                // The cell's centre from its bin's lower corner.
                let at = [place % 2, place / 2 % 2, place / 4].map(|a| a as f64 + 0.5);
                let centre = DVec3::from(at) * sides;
                let mut offsets = Vec::new();
                for dz in -span[2]..=span[2] {
                    for dy in -span[1]..=span[1] {
                        for dx in -span[0]..=span[0] {
                            let d = DVec3::new(dx.into(), dy.into(), dz.into());
                            let (low, high) = (d * bin_sides, (d + 1.0) * bin_sides);
                            let gap = ((low - centre).max(centre - high) - layout.margin)
                                .max(DVec3::ZERO)
                                .length();
                            if gap <= reach {
                                let step = dx as isize
                                    + padded[0] as isize
                                        * (dy as isize + padded[1] as isize * dz as isize);
                                offsets.push((step, gap));
                            }
                        }
                    }
                }
                offsets.sort_by(|a, b| a.1.total_cmp(&b.1).then(a.0.cmp(&b.0)));
                offsets
            })
            .collect();
        Bins {
            photons,
            starts,
            bin,
            padded: [padded[0], padded[1]],
            border,
            offsets,
            reach,
        }
    }

    /// The photons that can be among the `k` nearest within the radius of a point of
    /// cell `cell`, whose centre is `centre` and whose half diagonal is `h`, appended to
    /// `out` as keys (the bits of their distance from the centre, then their index)
    /// sorted; `false` when the cells around it do not reach far enough. The cells are
    /// taken nearest first, so that the `k`-th nearest photon of the centre, and with
    /// it how far the list reaches, is known before most are taken.
    fn gather(
        &self,
        layout: &Layout,
        cell: [u32; 3],
        (centre, h): (Vec3, f64),
        nearest: &mut Vec<f32>,
        out: &mut Vec<u64>,
    ) -> bool {
        let k = layout.k;
        let radius = f64::from(layout.radius);
        let [x, y, z] = [0, 1, 2].map(|i| (cell[i] / self.bin[i] + self.border[i]) as usize);
        let base = (x + self.padded[0] * (y + self.padded[1] * z)) as isize;
        // The cell's place in its bin, counted as the offsets' places are.
        let place = [0, 1, 2].map(|i| cell[i] % self.bin[i]);
        let offsets = &self.offsets[(place[0] + 2 * place[1] + 4 * place[2]) as usize];
        // The `k` nearest distances so far, in order.
        nearest.clear();
        let mut reach = list_reach(None, h, radius);
        for &(step, gap) in offsets {
            if gap > reach {
                break;
            }
            let bin = (base + step) as usize;
            let (start, end) = (self.starts[bin] as usize, self.starts[bin + 1] as usize);
            for &(position, index) in &self.photons[start..end] {
                let distance = position.distance(centre);
                if f64::from(distance) > reach {
                    continue;
                }
                out.push(key(distance, index));
                if nearest.len() < k || distance < nearest[k - 1] {
                    let i = nearest.partition_point(|d| *d <= distance);
                    nearest.insert(i, distance);
                    nearest.truncate(k);
                    if nearest.len() == k {
                        // Single precision distances are off by a rounding at most.
                        let kth = f64::from(nearest[k - 1]) * (1.0 + SLACK);
                        reach = list_reach(Some(kth), h, radius);
                    }
                }
            }
        }
        if reach > self.reach {
            out.clear();
            return false;
        }
        out.retain(|&key| f64::from(distance_of(key)) <= reach);
        out.sort_unstable();
        true
    }
}

impl Layout {
    /// The lists of the cells of one row along x (`row` counting rows along y, then
    /// z), one after the other, and the cells with their starts in it.
    fn row(&self, tree: &KdTree, row: u32) -> (Vec<Candidate>, Vec<Cell>) {
        let (y, z) = (row % self.counts[1], row / self.counts[1]);
        let (mut list, mut cells) = (Vec::new(), Vec::new());
        let (mut found, mut within, mut nearest, mut keys) =
            (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        let positions = tree.positions();
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
            keys.clear();
            let cell = [x, y, z];
            if !self
                .bins
                .gather(self, cell, (centre, h), &mut nearest, &mut keys)
            {
                // Too far for the cells around: the tree's photons within the reach.
                let kth = tree.nearest(centre, self.k, r2, None, &mut found);
                let kth = (found.len() == self.k).then(|| f64::from(kth).sqrt() * (1.0 + SLACK));
                let reach = list_reach(kth, h, radius);
                within.clear();
                tree.within(centre, (reach * reach) as f32, &mut within);
                keys.extend(
                    within
                        .iter()
                        .map(|&(p, index)| key(p.distance(centre), index)),
                );
                keys.sort_unstable();
            }
            let start = list.len();
            list.extend(keys.iter().map(|&key| {
                let (distance, index) = (distance_of(key), index_of(key));
                Candidate {
                    position: positions[index as usize],
                    from_centre: (f64::from(distance) * (1.0 - SLACK)) as f32,
                    index,
                }
            }));
            cells.push(Cell {
                start: start as u32,
                centre,
            });
        }
        (list, cells)
    }
}

/// How far from a cell's centre its list reaches, for a cell whose centre is `h` from its
/// farthest point: the `k`-th nearest photon of the centre, at `kth` (`None` when fewer lie
/// within `radius`), bounds the `k`-th nearest of any point of the cell by `kth + h`, never
/// more than the radius, and those photons lie within that plus `h` of the centre; widened
/// against rounding.
fn list_reach(kth: Option<f64>, h: f64, radius: f64) -> f64 {
    (kth.map_or(radius, |kth| (kth + h).min(radius)) + h) * (1.0 + 2.0 * SLACK)
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

/// A photon as one number: the bits of its distance (a search's squared distance from its
/// point, a list's distance from its cell's centre) above its index. Distances are never
/// negative or NaN, so that these order as the photons do by distance and then by index,
/// and the nearest are kept in order by one comparison each and moved by one load and
/// one store.
pub type Key = u64;

/// The key of a photon at distance (or squared distance) `d` with index `index`.
#[inline(always)]
pub fn key(d: f32, index: u32) -> Key {
    u64::from(d.to_bits()) << 32 | u64::from(index)
}

/// The index of the photon of `key`.
#[inline(always)]
pub fn index_of(key: Key) -> u32 {
    key as u32
}

/// The distance (or squared distance) `key` was made with.
#[inline(always)]
pub fn distance_of(key: Key) -> f32 {
    f32::from_bits((key >> 32) as u32)
}

/// The up to `k` (at least one) photons nearest `p` within squared distance `max_d2`
/// among `candidates` (the list of the cell holding `p`, whose centre is `centre`), into
/// `keep` as keys in order: by squared distance and then by index; returns the squared
/// distance of the farthest one kept when `k` were found, else `max_d2`. These are the
/// photons [`KdTree::nearest`] finds, a tie at the farthest going to the lower index.
#[inline(always)]
pub fn nearest(
    (candidates, centre): (&[Candidate], Vec3),
    p: Vec3,
    k: usize,
    max_d2: f32,
    keep: &mut Vec<Key>,
) -> f32 {
    keep.resize(k, 0);
    let mut rest = candidates.iter();
    let slots = &mut keep[..k];
    // Until `k` are kept every photon within `max_d2` is: a key below this one's. The
    // photons are not cut off by their distance from the centre here: the list's
    // photons beyond `max_d2` are few, those from the centre to the cell's edge and
    // back, and their distances from `p` leave them out as surely.
    let within = key(max_d2, 0);
    let mut count = 0;
    // The farthest kept so far, 0 while none are: the photons come nearly in order, and
    // most go after it without reading it back. Keys are never equal (indices differ).
    let mut farthest = 0;
    while count < k {
        let Some(candidate) = rest.next() else {
            break;
        };
        let offered = key(candidate.position.distance_squared(p), candidate.index);
        if offered >= within {
            continue;
        }
        if offered > farthest {
            slots[count] = offered;
            farthest = offered;
        } else {
            let mut i = count;
            while i > 0 && offered < slots[i - 1] {
                slots[i] = slots[i - 1];
                i -= 1;
            }
            slots[i] = offered;
        }
        count += 1;
    }
    if count < k {
        keep.truncate(count);
        return max_d2;
    }
    // Then a photon must come before the farthest kept, which it replaces; one farther
    // than `stop` from the centre is farther than that from `p`, and so are the rest.
    let mut limit = slots[k - 1];
    let off_centre = p.distance(centre);
    let mut stop = off_centre + distance_of(limit).sqrt();
    for candidate in rest {
        if candidate.from_centre > stop {
            break;
        }
        let offered = key(candidate.position.distance_squared(p), candidate.index);
        if offered >= limit {
            continue;
        }
        let mut i = k - 1;
        while i > 0 && offered < slots[i - 1] {
            slots[i] = slots[i - 1];
            i -= 1;
        }
        slots[i] = offered;
        limit = slots[k - 1];
        stop = off_centre + distance_of(limit).sqrt();
    }
    distance_of(limit)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::photons::kdtree::{Found, Photon};

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
        let mut keys = Vec::new();
        let mut served = 0;
        for p in queries(&grid, &mut next) {
            let Some(candidates) = grid.candidates(p) else {
                continue;
            };
            served += 1;
            let area = nearest(candidates, p, k, radius * radius, &mut keys);
            let (expected, expected_area) = brute_force(&tree, p, k, radius * radius);
            let found: Vec<Found> = keys
                .iter()
                .map(|key| (distance_of(*key), index_of(*key)))
                .collect();
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
        for (k, radius) in [(8, 0.3), (1, 0.05), (16, 0.2), (8, 0.02)] {
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
        for (k, radius) in [(8, 0.55), (3, 0.1), (16, 1.0)] {
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
        check(&lattice, 16, 0.4, 11);
    }

    #[test]
    fn cells_far_from_the_photons_find_what_all_photons_give() {
        // A dense cluster and a sparse one far away: the cells between them reach beyond
        // the bins around them, and their lists come from the tree.
        let mut positions = cloud(1500, 5, |next: &mut dyn FnMut() -> f32| {
            Vec3::new(next(), next(), next()) * 0.1
        });
        positions.extend(cloud(10, 6, |next: &mut dyn FnMut() -> f32| {
            Vec3::new(4.0, 0.0, 0.0) + Vec3::new(next(), next(), next()) * 0.1
        }));
        check(&positions, 8, 10.0, 14);
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
    fn no_grid_without_photons_or_for_many_gathered() {
        assert!(CandidateGrid::build(&tree(&[]), 8, 1.0).is_none());
        let positions = cloud(100, 7, |next: &mut dyn FnMut() -> f32| {
            Vec3::new(next(), 0.0, next())
        });
        assert!(CandidateGrid::build(&tree(&positions), MAX_GATHERED, 1.0).is_some());
        assert!(CandidateGrid::build(&tree(&positions), MAX_GATHERED + 1, 1.0).is_none());
    }
}
