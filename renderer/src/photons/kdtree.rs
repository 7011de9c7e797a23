//! The stored photons in a balanced kd-tree: the photons themselves are the nodes, laid
//! out so that the node of a range of the array is its middle element (the median along
//! the range's widest axis), the lower half before it and the upper half after; ranges of
//! a few photons are leaves, searched straight through. No pointers, no padding, and the
//! positions apart from the rest so that a search reads only them; a k-nearest search
//! keeps its candidates in a max-heap so that the search radius shrinks as closer photons
//! turn up.

use glam::Vec3;

/// A photon where it landed: the light it brings and the way it was going. Single
/// precision halves the memory and the cache traffic of a search; a photon's position
/// only needs to be as exact as the gather radius is small.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Photon {
    pub position: Vec3,
    pub power: Vec3,
    /// Unit direction of travel.
    pub direction: Vec3,
}

/// A found photon: its squared distance and its index in the tree.
pub type Found = (f32, u32);

/// The most photons of a leaf.
const LEAF: u32 = 8;

#[derive(Debug, Clone)]
pub struct KdTree {
    photons: Vec<Photon>,
    /// The photons' positions, in the same order.
    positions: Vec<Vec3>,
    /// The split axis of the node at each index.
    axes: Vec<u8>,
}

impl KdTree {
    pub fn build(mut photons: Vec<Photon>) -> KdTree {
        let mut axes = vec![0; photons.len()];
        split(&mut photons, &mut axes);
        KdTree {
            positions: photons.iter().map(|p| p.position).collect(),
            photons,
            axes,
        }
    }

    pub fn photon(&self, index: u32) -> &Photon {
        &self.photons[index as usize]
    }

    /// The photons' positions, by index.
    pub fn positions(&self) -> &[Vec3] {
        &self.positions
    }

    /// The up to `k` photons nearest `p` within squared distance `max_d2`, into `found`
    /// (in no particular order); returns the squared distance of the farthest one kept
    /// when `k` were found, else `max_d2`. `hint` is a squared distance that probably
    /// holds `k` photons (a neighbouring search's): the search tries it first, which
    /// spares it most of the photons between the hint and `max_d2`.
    pub fn nearest(
        &self,
        p: Vec3,
        k: usize,
        max_d2: f32,
        hint: Option<f32>,
        found: &mut Vec<Found>,
    ) -> f32 {
        hinted(k, max_d2, hint, found, |limit, found| {
            self.search(p, k, limit, found)
        })
    }

    /// [`Self::nearest`] within `max_d2`; returns the squared distance of the farthest
    /// photon kept when `k` were found.
    fn search(&self, p: Vec3, k: usize, max_d2: f32, found: &mut Vec<Found>) -> f32 {
        let mut best = Best::new(found, k, max_d2);
        self.visit(p, max_d2, |d2, index| {
            best.offer(d2, index);
            best.limit
        });
        best.limit
    }

    /// Every photon nearer `p` than the square root of `max_d2`, appended to `out` with
    /// its index.
    pub fn within(&self, p: Vec3, max_d2: f32, out: &mut Vec<(Vec3, u32)>) {
        self.visit(p, max_d2, |d2, index| {
            if d2 < max_d2 {
                out.push((self.positions[index as usize], index));
            }
            max_d2
        });
    }

    /// Hands `offer` the squared distance from `p` and the index of every photon that may
    /// lie nearer than the limit, the near side of each split first; `offer` returns the
    /// limit from then on (`limit` at first), which only shrinks.
    #[inline(always)]
    fn visit(&self, p: Vec3, limit: f32, mut offer: impl FnMut(f32, u32) -> f32) {
        let mut limit = limit;
        // Ranges still to visit with the squared distance from `p` to their side of the
        // splitting plane; 64 levels hold any tree that fits in memory.
        let mut stack = [(0u32, 0u32, 0f32); 64];
        stack[0] = (0, self.positions.len() as u32, 0.0);
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let (mut lo, mut hi, plane_d2) = stack[top];
            if plane_d2 >= limit {
                continue;
            }
            while hi - lo > LEAF {
                let mid = (lo + hi) / 2;
                let node = self.positions[mid as usize];
                limit = offer(node.distance_squared(p), mid);
                let axis = self.axes[mid as usize] as usize;
                let delta = p[axis] - node[axis];
                let (near, far) = if delta < 0.0 {
                    ((lo, mid), (mid + 1, hi))
                } else {
                    ((mid + 1, hi), (lo, mid))
                };
                let delta2 = delta * delta;
                if far.0 < far.1 && delta2 < limit && top < stack.len() {
                    stack[top] = (far.0, far.1, delta2);
                    top += 1;
                }
                (lo, hi) = near;
            }
            for (index, position) in (lo..hi).zip(&self.positions[lo as usize..hi as usize]) {
                limit = offer(position.distance_squared(p), index);
            }
        }
    }
}

/// [`KdTree::nearest`] among `candidates` alone (photons with their indices).
pub fn nearest_among(
    candidates: &[(Vec3, u32)],
    p: Vec3,
    k: usize,
    max_d2: f32,
    hint: Option<f32>,
    found: &mut Vec<Found>,
) -> f32 {
    hinted(k, max_d2, hint, found, |limit, found| {
        let mut best = Best::new(found, k, limit);
        for &(position, index) in candidates {
            best.offer(position.distance_squared(p), index);
        }
        best.limit
    })
}

/// A search for the `k` nearest within `max_d2` by `search(limit, found)` (which returns
/// the squared distance of the farthest photon kept when it keeps `k`), tried within
/// `hint` first when that is nearer: when the hint holds `k` photons they are the nearest,
/// found without taking in and throwing out the farther ones. Returns the squared
/// distance of the farthest photon kept when `k` were found, else `max_d2`. Both tries
/// go through one call of `search`, so that it is inlined here rather than kept out of
/// line as a closure called from two places, a call per gathering in the plugin.
#[inline(always)]
fn hinted(
    k: usize,
    max_d2: f32,
    hint: Option<f32>,
    found: &mut Vec<Found>,
    mut search: impl FnMut(f32, &mut Vec<Found>) -> f32,
) -> f32 {
    let hint = hint.filter(|h| *h < max_d2);
    let mut limit = hint.unwrap_or(max_d2);
    let mut widest = hint.is_none();
    loop {
        let d2 = search(limit, found);
        if found.len() == k {
            return d2;
        }
        if widest {
            return max_d2;
        }
        (limit, widest) = (max_d2, true);
    }
}

/// The nearest photons found so far: gathered as they come until there are `k`, then a
/// max-heap whose top, the farthest kept, is the distance a photon must beat.
struct Best<'a> {
    found: &'a mut Vec<Found>,
    k: usize,
    limit: f32,
}

impl<'a> Best<'a> {
    /// None found yet, within `max_d2`.
    fn new(found: &'a mut Vec<Found>, k: usize, max_d2: f32) -> Best<'a> {
        found.clear();
        Best {
            found,
            k,
            limit: max_d2,
        }
    }

    /// Keeps the photon if it is nearer than the farthest kept: a comparison, inlined
    /// into the searches, for the many that are not.
    #[inline(always)]
    fn offer(&mut self, d2: f32, index: u32) {
        if d2 < self.limit {
            self.keep(d2, index);
        }
    }

    /// Inlined as well: a search keeps a dozen photons, each a call the interpreted plugin
    /// sets up a frame for.
    #[inline(always)]
    fn keep(&mut self, d2: f32, index: u32) {
        let heap = &mut *self.found;
        if heap.len() < self.k {
            heap.push((d2, index));
            if heap.len() == self.k {
                for i in (0..self.k / 2).rev() {
                    sift_down(heap, i);
                }
                self.limit = heap[0].0;
            }
            return;
        }
        // A selection of no photons has no top and keeps none.
        let Some(top) = heap.first_mut() else {
            return;
        };
        *top = (d2, index);
        sift_down(heap, 0);
        self.limit = heap[0].0;
    }
}

/// Restores the max-heap order below `i`. Inlined into the searches: a gathering keeps
/// a dozen photons, each a call the interpreted plugin sets up a frame for.
#[inline(always)]
fn sift_down(heap: &mut [Found], mut i: usize) {
    loop {
        let (left, right) = (2 * i + 1, 2 * i + 2);
        let mut largest = i;
        if left < heap.len() && heap[left].0 > heap[largest].0 {
            largest = left;
        }
        if right < heap.len() && heap[right].0 > heap[largest].0 {
            largest = right;
        }
        if largest == i {
            return;
        }
        heap.swap(i, largest);
        i = largest;
    }
}

/// Puts the median of `photons` along their widest axis in the middle, the smaller ones
/// before it and the larger after, and does the same for both halves.
fn split(photons: &mut [Photon], axes: &mut [u8]) {
    if photons.len() <= LEAF as usize {
        return;
    }
    let (min, max) = photons.iter().fold(
        (Vec3::splat(f32::INFINITY), Vec3::splat(f32::NEG_INFINITY)),
        |(lo, hi), ph| (lo.min(ph.position), hi.max(ph.position)),
    );
    let extent = max - min;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mid = photons.len() / 2;
    photons.select_nth_unstable_by(mid, |a, b| a.position[axis].total_cmp(&b.position[axis]));
    axes[mid] = axis as u8;
    let (lower, rest) = photons.split_at_mut(mid);
    let (lower_axes, rest_axes) = axes.split_at_mut(mid);
    split(lower, lower_axes);
    split(&mut rest[1..], &mut rest_axes[1..]);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn photon(x: f32, y: f32, z: f32) -> Photon {
        Photon {
            position: Vec3::new(x, y, z),
            power: Vec3::ONE,
            direction: Vec3::NEG_Y,
        }
    }

    /// A fixed scatter of points from a small linear congruential sequence.
    fn scatter(n: usize) -> Vec<Photon> {
        let mut state = 12345u32;
        let mut next = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1u32 << 24) as f32
        };
        (0..n)
            .map(|_| photon(next(), next() * 0.2, next()))
            .collect()
    }

    #[test]
    fn nearest_agrees_with_a_linear_search() {
        let photons = scatter(2000);
        let tree = KdTree::build(photons.clone());
        let mut found = Vec::new();
        for q in scatter(50) {
            for (k, max_d2) in [(1, 1.0), (8, 1.0), (100, 0.01), (5000, 0.02)] {
                let hint = (k == 8).then_some(0.001);
                let radius = tree.nearest(q.position, k, max_d2, hint, &mut found);
                let mut got: Vec<f32> = found.iter().map(|f| f.0).collect();
                got.sort_by(f32::total_cmp);
                let mut all: Vec<f32> = photons
                    .iter()
                    .map(|p| p.position.distance_squared(q.position))
                    .filter(|d| *d < max_d2)
                    .collect();
                all.sort_by(f32::total_cmp);
                all.truncate(k);
                assert_eq!(got, all, "k {k}");
                let expected = if all.len() == k { all[k - 1] } else { max_d2 };
                assert_eq!(radius, expected);
                for (d2, index) in &found {
                    assert_eq!(
                        *d2,
                        tree.photon(*index).position.distance_squared(q.position)
                    );
                }
            }
        }
    }

    #[test]
    fn empty_and_single_trees() {
        let mut found = vec![(0.0, 0)];
        assert_eq!(
            KdTree::build(Vec::new()).nearest(Vec3::ZERO, 4, 1.0, None, &mut found),
            1.0
        );
        assert!(found.is_empty());
        let one = KdTree::build(vec![photon(0.5, 0.0, 0.0)]);
        assert_eq!(one.nearest(Vec3::ZERO, 4, 1.0, None, &mut found), 1.0);
        assert_eq!(found, vec![(0.25, 0)]);
    }
}
