//! The irradiance cache: indirect light measured at sample points, and its interpolation
//! at points near them (Ward, Rubinstein and Clear 1988, "A ray tracing solution for
//! diffuse interreflection").
//!
//! A sample may stand in for a point `x` with normal `n` while its estimated error
//! `εᵢ = |x - xᵢ| / Rᵢ + √(1 - n·nᵢ)` stays below the error bound, `Rᵢ` being the
//! sample's reuse distance (the harmonic mean of the distances its rays went, within the
//! reuse limits). Samples are blended with weights `(1 - εᵢ/bound)²`, which fall smoothly
//! to zero at the edge of each sample's reach: the blend has no seams where a sample drops
//! out, and no single noisy sample dominates the points around it.
//!
//! Samples live in a loose octree: each in the smallest cell that holds its position and
//! is at least as wide as its reach, so a lookup visits only the cells whose doubled
//! extent holds the point.
//!
//! Lookups may read several caches as one (the pretrace's units read the samples of the
//! rounds before theirs and their own, kept apart until the round ends).

use glam::DVec3;

/// One measurement of indirect light.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    pub position: DVec3,
    pub normal: DVec3,
    pub irradiance: DVec3,
    /// The reuse distance `R`.
    pub reuse: f64,
}

/// What a lookup found: the blended light and how well the samples cover the point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Blend {
    pub irradiance: DVec3,
    /// The number of samples found, each weighed by how close it is: a sample at the edge
    /// of its reach counts a half, one very close counts up to four, after the manual's
    /// description of `nearest_count`.
    pub coverage: f64,
}

#[derive(Debug, Clone)]
struct Cell {
    centre: DVec3,
    half: f64,
    children: [u32; 8],
    spots: Spots,
}

/// Where a cell's samples are and how far they reach, in single precision relative to the
/// cell's centre, [`LANES`] side by side, so that a lookup turns most of them away with a
/// few vector instructions before looking at a sample itself.
#[derive(Debug, Clone, Default)]
struct Spots {
    chunks: Vec<SpotChunk>,
    len: usize,
}

/// How many spots the prefilter tests at once: a fixed count, so that the test of a chunk
/// compiles to vector instructions with no bounds checks.
const LANES: usize = 8;

/// The spots of one chunk; lanes past the last sample sit infinitely far away.
#[derive(Debug, Clone, Copy)]
struct SpotChunk {
    x: [f32; LANES],
    y: [f32; LANES],
    z: [f32; LANES],
    reuse: [f32; LANES],
    sample: [u32; LANES],
}

const EMPTY_CHUNK: SpotChunk = SpotChunk {
    x: [f32::INFINITY; LANES],
    y: [f32::INFINITY; LANES],
    z: [f32::INFINITY; LANES],
    reuse: [0.0; LANES],
    sample: [NONE; LANES],
};

impl Spots {
    fn push(&mut self, offset: DVec3, reuse: f64, sample: u32) {
        let lane = self.len % LANES;
        if lane == 0 {
            self.chunks.push(EMPTY_CHUNK);
        }
        let chunk = self
            .chunks
            .last_mut()
            .expect("a chunk was pushed for lane 0");
        chunk.x[lane] = offset.x as f32;
        chunk.y[lane] = offset.y as f32;
        chunk.z[lane] = offset.z as f32;
        chunk.reuse[lane] = reuse as f32;
        chunk.sample[lane] = sample;
        self.len += 1;
    }

    /// Calls `f` with each sample that may lie within `bound` reuse distances of the
    /// point at `offset` from the cell's centre (`slack` covers single precision), in the
    /// order they were pushed, until `f` returns `true`; returns whether it did.
    fn near(&self, offset: DVec3, bound: f64, slack: f64, mut f: impl FnMut(u32) -> bool) -> bool {
        let (qx, qy, qz) = (offset.x as f32, offset.y as f32, offset.z as f32);
        let (b, slack) = (bound as f32 * 1.001, slack as f32);
        for chunk in &self.chunks {
            // The squared distance less the squared reach, whose sign bit marks a spot
            // within reach: a form the compiler turns into a vector mask.
            let mut beyond = [0f32; LANES];
            for (k, beyond) in beyond.iter_mut().enumerate() {
                let (dx, dy, dz) = (chunk.x[k] - qx, chunk.y[k] - qy, chunk.z[k] - qz);
                let reach = b * chunk.reuse[k] + slack;
                *beyond = dx * dx + dy * dy + dz * dz - reach * reach;
            }
            let mut near = 0u32;
            for (k, beyond) in beyond.iter().enumerate() {
                near |= (beyond.to_bits() >> 31) << k;
            }
            while near != 0 {
                let k = near.trailing_zeros() as usize;
                near &= near - 1;
                if f(chunk.sample[k]) {
                    return true;
                }
            }
        }
        false
    }
}

impl Cell {
    fn new(centre: DVec3, half: f64) -> Cell {
        Cell {
            centre,
            half,
            children: [NONE; 8],
            spots: Spots::default(),
        }
    }

    /// Whether a sample of this cell may reach `p` when reaches are `stretch` times those
    /// the cell was chosen for: the cell holds its samples' positions, and their reaches
    /// are at most its half-size.
    fn may_reach(&self, p: DVec3, stretch: f64) -> bool {
        (p - self.centre).abs().max_element() <= self.half * (1.0 + stretch)
    }

    fn octant(&self, p: DVec3) -> usize {
        usize::from(p.x > self.centre.x)
            | usize::from(p.y > self.centre.y) << 1
            | usize::from(p.z > self.centre.z) << 2
    }
}

const NONE: u32 = u32::MAX;

/// The samples of one bounce depth.
#[derive(Debug, Clone, Default)]
pub struct Cache {
    cells: Vec<Cell>,
    samples: Vec<Sample>,
    root: u32,
    /// A sample's cell is chosen for a reach of its reuse distance times this bound;
    /// lookups under larger bounds search further.
    reference_bound: f64,
}

impl Cache {
    pub fn new(reference_bound: f64) -> Cache {
        Cache {
            cells: Vec::new(),
            samples: Vec::new(),
            root: NONE,
            reference_bound,
        }
    }

    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.samples.len()
    }

    pub fn insert(&mut self, sample: Sample) {
        let reach = sample.reuse * self.reference_bound;
        let index = self.samples.len() as u32;
        self.samples.push(sample);
        if self.root == NONE {
            self.root = self.cells.len() as u32;
            let half = if reach > 0.0 { reach } else { 1.0 };
            self.cells.push(Cell::new(sample.position, half));
        }
        self.grow_to(sample.position, reach);
        let mut at = self.root as usize;
        // Down to the smallest cell still as wide as the sample's reach; the limit stops
        // degenerate reaches from building towers of cells.
        for _ in 0..64 {
            let (centre, half) = (self.cells[at].centre, self.cells[at].half / 2.0);
            if half < reach {
                break;
            }
            let octant = self.cells[at].octant(sample.position);
            at = match self.cells[at].children[octant] {
                NONE => {
                    let offset = DVec3::new(
                        if octant & 1 != 0 { half } else { -half },
                        if octant & 2 != 0 { half } else { -half },
                        if octant & 4 != 0 { half } else { -half },
                    );
                    let new = self.cells.len() as u32;
                    self.cells.push(Cell::new(centre + offset, half));
                    self.cells[at].children[octant] = new;
                    new as usize
                }
                child => child as usize,
            };
        }
        let offset = sample.position - self.cells[at].centre;
        self.cells[at].spots.push(offset, sample.reuse, index);
    }

    /// Enlarges the root until it holds `p` and is at least as wide as `reach`.
    fn grow_to(&mut self, p: DVec3, reach: f64) {
        loop {
            let root = &self.cells[self.root as usize];
            let inside = (p - root.centre).abs().max_element() <= root.half;
            if inside && root.half >= reach {
                return;
            }
            // The new root doubles the old one towards `p`; the old root is the octant of
            // it on the other side.
            let towards = DVec3::select(p.cmpge(root.centre), DVec3::ONE, -DVec3::ONE);
            let centre = root.centre + towards * root.half;
            let mut grown = Cell::new(centre, root.half * 2.0);
            let old_octant = grown.octant(root.centre);
            grown.children[old_octant] = self.root;
            self.root = self.cells.len() as u32;
            self.cells.push(grown);
        }
    }

    /// The samples in the order they were inserted.
    pub fn samples(&self) -> &[Sample] {
        &self.samples
    }

    /// Adds the samples of cell `at` and its descendants that fit the search to `sums`;
    /// returns whether the coverage reached the search's `enough`, which stops it.
    fn visit(&self, at: u32, search: &Search, sums: &mut Sums) -> bool {
        let cell = &self.cells[at as usize];
        if !cell.may_reach(search.p, search.stretch) {
            return false;
        }
        let slack = 1e-5 * cell.half;
        let enough = cell
            .spots
            .near(search.p - cell.centre, search.bound, slack, |i| {
                let s = &self.samples[i as usize];
                if let Some((weight, quality)) = fit(s, search.p, search.n, search.bound) {
                    sums.light += s.irradiance * weight;
                    sums.weights += weight;
                    sums.coverage += (quality / 2.0).min(4.0);
                }
                sums.coverage >= search.enough
            });
        enough
            || cell
                .children
                .iter()
                .any(|&child| child != NONE && self.visit(child, search, sums))
    }
}

/// The samples of `layers`, read as one cache, that may stand in for `(p, n)` under
/// `bound`, blended.
pub fn lookup(layers: &[&Cache], p: DVec3, n: DVec3, bound: f64) -> Blend {
    let sums = sums(layers, p, n, bound, f64::INFINITY);
    Blend {
        irradiance: if sums.weights > 0.0 {
            sums.light / sums.weights
        } else {
            DVec3::ZERO
        },
        coverage: sums.coverage,
    }
}

/// How well the samples of `layers` cover `(p, n)` under `bound`, as [`Blend::coverage`],
/// counted only until it reaches `enough`: for points whose light nobody sees, where only
/// whether the coverage reaches a threshold matters, most of the search is saved. The
/// samples are met in the order `lookup` meets them, so the coverage is exactly
/// `lookup`'s whenever it is below `enough`.
pub fn coverage(layers: &[&Cache], p: DVec3, n: DVec3, bound: f64, enough: f64) -> f64 {
    sums(layers, p, n, bound, enough).coverage
}

fn sums(layers: &[&Cache], p: DVec3, n: DVec3, bound: f64, enough: f64) -> Sums {
    let mut sums = Sums::default();
    for cache in layers {
        if cache.root == NONE {
            continue;
        }
        let search = Search {
            p,
            n,
            bound,
            stretch: bound / cache.reference_bound,
            enough,
        };
        if cache.visit(cache.root, &search, &mut sums) {
            break;
        }
    }
    sums
}

/// What a lookup looks for.
struct Search {
    p: DVec3,
    n: DVec3,
    bound: f64,
    /// How much further than their cells were chosen for the samples reach under `bound`.
    stretch: f64,
    /// The coverage at which the search may stop.
    enough: f64,
}

#[derive(Default)]
struct Sums {
    light: DVec3,
    weights: f64,
    coverage: f64,
}

/// The blending weight of sample `s` at `(p, n)` and the ratio of the bound to its error,
/// or `None` when it may not stand in for the point.
fn fit(s: &Sample, p: DVec3, n: DVec3, bound: f64) -> Option<(f64, f64)> {
    let offset = p - s.position;
    let reach = bound * s.reuse;
    if offset.length_squared() >= reach * reach {
        return None;
    }
    let distance = offset.length();
    let error = distance / s.reuse + (1.0 - n.dot(s.normal)).max(0.0).sqrt();
    if error >= bound {
        return None;
    }
    // A sample in front of the point's tangent plane saw light the point may not see.
    if offset.dot(n + s.normal) < -0.1 * s.reuse {
        return None;
    }
    let falloff = 1.0 - error / bound;
    Some((falloff * falloff, bound / error.max(1e-9)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(x: f64, light: f64) -> Sample {
        Sample {
            position: DVec3::new(x, 0.0, 0.0),
            normal: DVec3::Y,
            irradiance: DVec3::splat(light),
            reuse: 1.0,
        }
    }

    #[test]
    fn a_point_between_two_samples_blends_them_by_closeness() {
        let mut cache = Cache::new(1.0);
        cache.insert(sample(0.0, 1.0));
        cache.insert(sample(1.0, 3.0));
        let halfway = lookup(&[&cache], DVec3::new(0.5, 0.0, 0.0), DVec3::Y, 1.0);
        assert!((halfway.irradiance.x - 2.0).abs() < 1e-12, "{halfway:?}");
        let near_first = lookup(&[&cache], DVec3::new(0.2, 0.0, 0.0), DVec3::Y, 1.0);
        assert!(near_first.irradiance.x < 1.2, "{near_first:?}");
        assert!(near_first.coverage > halfway.coverage / 2.0);
    }

    #[test]
    fn samples_out_of_reach_turned_away_or_in_front_are_not_used() {
        let mut cache = Cache::new(1.0);
        cache.insert(sample(0.0, 1.0));
        let far = lookup(&[&cache], DVec3::new(1.5, 0.0, 0.0), DVec3::Y, 1.0);
        assert_eq!(far.coverage, 0.0);
        let turned = lookup(&[&cache], DVec3::new(0.1, 0.0, 0.0), DVec3::X, 1.0);
        assert_eq!(turned.coverage, 0.0);
        // A point below the sample's surface, as on a step down from it.
        let below = lookup(&[&cache], DVec3::new(0.0, -0.3, 0.0), DVec3::Y, 1.0);
        assert_eq!(below.coverage, 0.0);
        // A looser bound reaches further.
        assert!(lookup(&[&cache], DVec3::new(1.5, 0.0, 0.0), DVec3::Y, 2.0).coverage > 0.0);
    }

    #[test]
    fn the_octree_finds_samples_of_every_size_anywhere() {
        // Samples of reaches from 0.01 to 100 scattered over a large region, each found
        // from a point near it, and the lookup agrees with a search of every sample.
        let mut cache = Cache::new(1.8);
        let mut all = Vec::new();
        for i in 0..500u32 {
            let f = f64::from(i);
            let s = Sample {
                position: DVec3::new((f * 7.31).sin() * 500.0, (f * 3.17).cos() * 50.0, f),
                normal: DVec3::Y,
                irradiance: DVec3::splat(f),
                reuse: 10f64.powf((f * 0.37).sin() * 2.0),
            };
            cache.insert(s);
            all.push(s);
        }
        for (i, s) in all.iter().enumerate() {
            let p = s.position + DVec3::new(0.3, 0.0, 0.2) * s.reuse;
            let found = lookup(&[&cache], p, DVec3::Y, 1.8);
            let expected: f64 = all
                .iter()
                .filter_map(|s| fit(s, p, DVec3::Y, 1.8))
                .map(|(_, q)| (q / 2.0).min(4.0))
                .sum();
            assert!(found.coverage > 0.0, "sample {i} not found");
            assert!((found.coverage - expected).abs() < 1e-9, "sample {i}");
            // A count up to a threshold agrees with the whole count on either side of it.
            for enough in [0.5, 2.0, expected, expected + 1.0] {
                let counted = coverage(&[&cache], p, DVec3::Y, 1.8, enough);
                assert_eq!(counted >= enough, found.coverage >= enough, "sample {i}");
                if found.coverage < enough {
                    assert_eq!(counted, found.coverage, "sample {i}");
                }
            }
        }
    }

    #[test]
    fn caches_read_as_one_find_what_one_cache_of_all_their_samples_finds() {
        let samples: Vec<Sample> = (0..60)
            .map(|i| {
                let f = f64::from(i);
                Sample {
                    position: DVec3::new((f * 1.7).sin() * 3.0, 0.0, (f * 0.9).cos() * 3.0),
                    normal: DVec3::Y,
                    irradiance: DVec3::splat(f),
                    reuse: 0.5 + (f * 0.3).sin().abs(),
                }
            })
            .collect();
        let mut all = Cache::new(1.0);
        let (mut first, mut second) = (Cache::new(1.0), Cache::new(1.0));
        for (i, s) in samples.iter().enumerate() {
            all.insert(*s);
            if i % 3 == 0 {
                first.insert(*s);
            } else {
                second.insert(*s);
            }
        }
        for j in 0..40 {
            let f = f64::from(j);
            let p = DVec3::new((f * 2.3).cos() * 3.0, 0.0, (f * 1.1).sin() * 3.0);
            let whole = lookup(&[&all], p, DVec3::Y, 1.5);
            let layered = lookup(&[&first, &second], p, DVec3::Y, 1.5);
            assert!((whole.coverage - layered.coverage).abs() < 1e-9, "{p}");
            assert!(
                whole.irradiance.abs_diff_eq(layered.irradiance, 1e-9),
                "{p}"
            );
            // Counting stops at the same threshold across the layers.
            let counted = coverage(&[&first, &second], p, DVec3::Y, 1.5, 2.0);
            assert_eq!(counted >= 2.0, whole.coverage >= 2.0, "{p}");
        }
        assert!(lookup(&[&Cache::new(1.0)], DVec3::ZERO, DVec3::Y, 1.5).coverage == 0.0);
    }
}
