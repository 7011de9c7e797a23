//! Patterns built on one random point (a nucleus) in each unit cube of space: `cells`
//! (a random value per cube), `crackle` (distances to the nearest nuclei, a Voronoi
//! diagram) and the nuclei `facets` normals turn towards. The random numbers are POV-Ray
//! 3.7's, measured: a cube's hash (see [`noise::cube_hash`]) picks its numbers from the
//! outputs of the Mersenne twister.

use crate::noise;
use glam::{DVec3, IVec3};

/// The numbers POV-Ray 3.7 gives its cubes: the first outputs of the Mersenne twister
/// MT19937 from its standard seed 5489, each over 2^32. The cube of hash `h` has value
/// `h` for `cells` and values `h`, `h + 1` and `h + 2` as its nucleus's offsets. Found by
/// probing: cells values, and nuclei solved from crackle distances, over all 4096 hashes.
static CUBE_RANDOMS: [f64; 4098] = mersenne_twister_outputs();

const fn mersenne_twister_outputs() -> [f64; 4098] {
    const N: usize = 624;
    let mut state = [0u32; N];
    state[0] = 5489;
    let mut i = 1;
    while i < N {
        let previous = state[i - 1];
        state[i] = 1_812_433_253u32
            .wrapping_mul(previous ^ (previous >> 30))
            .wrapping_add(i as u32);
        i += 1;
    }
    let mut outputs = [0.0; 4098];
    let mut next = N;
    let mut k = 0;
    while k < outputs.len() {
        if next == N {
            let mut j = 0;
            while j < N {
                let y = (state[j] & 0x8000_0000) | (state[(j + 1) % N] & 0x7fff_ffff);
                let twist = if y & 1 == 1 { 0x9908_b0df } else { 0 };
                state[j] = state[(j + 397) % N] ^ (y >> 1) ^ twist;
                j += 1;
            }
            next = 0;
        }
        let mut y = state[next];
        next += 1;
        y ^= y >> 11;
        y ^= (y << 7) & 0x9d2c_5680;
        y ^= (y << 15) & 0xefc6_0000;
        y ^= y >> 18;
        outputs[k] = y as f64 / 4_294_967_296.0;
        k += 1;
    }
    outputs
}

/// The index of a cube's first number in [`CUBE_RANDOMS`].
fn cube_index(cube: IVec3) -> usize {
    noise::cube_hash(i64::from(cube.x), i64::from(cube.y), i64::from(cube.z))
}

/// The integer cube holding a coordinate, saturating far from the origin.
fn cube_of(p: DVec3) -> IVec3 {
    let clamp = |v: f64| v.floor().clamp(-1e9, 1e9) as i32;
    IVec3::new(clamp(p.x), clamp(p.y), clamp(p.z))
}

/// The random point of a cube.
pub fn nucleus(cube: IVec3) -> DVec3 {
    let i = cube_index(cube);
    cube.as_dvec3() + DVec3::new(CUBE_RANDOMS[i], CUBE_RANDOMS[i + 1], CUBE_RANDOMS[i + 2])
}

/// `cells`: the random value of the unit cube holding the point.
pub fn cells(p: DVec3) -> f64 {
    if !p.is_finite() {
        return 0.0;
    }
    CUBE_RANDOMS[cube_index(cube_of(p + DVec3::splat(1e-10)))]
}

/// The offsets of the 81 cubes that may hold the nucleus nearest to a point of the centre
/// cube: every cube within one step in each axis, and those two steps away along one axis
/// and at most one step along the others.
fn neighbourhood() -> &'static [IVec3; 81] {
    static CUBES: std::sync::OnceLock<[IVec3; 81]> = std::sync::OnceLock::new();
    CUBES.get_or_init(|| {
        let mut cubes = [IVec3::ZERO; 81];
        let mut n = 0;
        for x in -2..=2 {
            for y in -2..=2 {
                for z in -2..=2 {
                    let far = [x, y, z].iter().filter(|c: &&i32| c.abs() == 2).count();
                    if far <= 1 {
                        cubes[n] = IVec3::new(x, y, z);
                        n += 1;
                    }
                }
            }
        }
        cubes
    })
}

/// Distance in the crackle metric, before taking the root.
fn metric_sum(d: DVec3, metric: f64) -> f64 {
    if metric == 2.0 {
        d.length_squared()
    } else if metric == 1.0 {
        d.x.abs() + d.y.abs() + d.z.abs()
    } else {
        d.x.abs().powf(metric) + d.y.abs().powf(metric) + d.z.abs().powf(metric)
    }
}

fn metric_root(sum: f64, metric: f64) -> f64 {
    if metric == 2.0 {
        sum.sqrt()
    } else if metric == 1.0 {
        sum
    } else {
        sum.powf(1.0 / metric)
    }
}

/// The nuclei nearest to `p`: the three smallest metric sums (before roots) and the
/// nearest nucleus itself.
fn nearest_three(p: DVec3, metric: f64) -> ([f64; 3], DVec3) {
    let centre = cube_of(p - DVec3::splat(1e-10));
    let low = centre.as_dvec3();
    let mut best = [f64::INFINITY; 3];
    let mut nearest = DVec3::ZERO;
    let mut nearest_place = u8::MAX;
    // A cube no part of which is nearer than the third nearest nucleus found so far holds
    // no nucleus that changes the answer: its nucleus is not worked out. Of equally near
    // nuclei the one first in the neighbourhood is the nearest, as when every cube was
    // searched in its order, so the answer is the same to the bit whatever the order of
    // the search. (The bound holds for the metrics whose sums only grow with each
    // coordinate's distance in floating point too, not for the others' powers.)
    let bounded = metric == 2.0 || metric == 1.0;
    let gaps = if bounded {
        axis_gaps(p, low, metric)
    } else {
        [[0.0; 5]; 3]
    };
    // The cubes are searched in the order of the least distance any point of `p`'s
    // eighth of the centre cube can have from them, so that in the Euclidean metric the
    // search ends at the first cube that even that distance rules out. Far from the
    // origin, where the centre cube is clamped, the order is kept but not the early end.
    let upper = |axis: usize| usize::from(p[axis] >= low[axis] + 0.5);
    let octant = upper(0) | upper(1) << 1 | upper(2) << 2;
    let ends_early = metric == 2.0 && p.abs().max_element() < 1e8;
    for step in &search_orders()[octant] {
        if ends_early && step.least_sum > best[2] {
            break;
        }
        let [gx, gy, gz] = step.gap;
        if bounded && gaps[0][gx] + gaps[1][gy] + gaps[2][gz] > best[2] {
            continue;
        }
        let n = nucleus(centre + step.offset);
        let sum = metric_sum(n - p, metric);
        if sum < best[0] {
            best = [sum, best[0], best[1]];
            nearest = n;
            nearest_place = step.place;
            continue;
        }
        if sum == best[0] && step.place < nearest_place {
            nearest = n;
            nearest_place = step.place;
        }
        if sum < best[1] {
            best = [best[0], sum, best[1]];
        } else if sum < best[2] {
            best[2] = sum;
        }
    }
    (best, nearest)
}

/// For each axis and each of the five offsets -2..=2 along it, how far `p` lies from the
/// slab of cubes there, as it enters the metric's sum (squared for the Euclidean metric):
/// the terms of the metric sum of `p`'s distance to a cube, computed as for one cube so
/// that their sum is the same to the bit.
fn axis_gaps(p: DVec3, low: DVec3, metric: f64) -> [[f64; 5]; 3] {
    let mut gaps = [[0.0; 5]; 3];
    for (axis, gaps) in gaps.iter_mut().enumerate() {
        for (i, gap) in gaps.iter_mut().enumerate() {
            let start = low[axis] + (i as f64 - 2.0);
            let before = start - p[axis];
            let after = p[axis] - (start + 1.0);
            let below = if 0.0 > before { 0.0 } else { before };
            let d = if below > after { below } else { after };
            *gap = if metric == 2.0 { d * d } else { d.abs() };
        }
    }
    gaps
}

/// One cube of a search: its offset from the centre cube, its place in [`neighbourhood`],
/// the indices of its offsets in [`axis_gaps`], and the least squared distance it can have
/// from a point in the eighth of the centre cube the search is for.
struct SearchStep {
    offset: IVec3,
    place: u8,
    gap: [usize; 3],
    least_sum: f64,
}

/// The cubes of [`neighbourhood`] for a point in each eighth of the centre cube (bit 0 set
/// for the upper half in x, bit 1 in y, bit 2 in z), by the least distance a point there
/// can have from them.
fn search_orders() -> &'static [Vec<SearchStep>; 8] {
    static ORDERS: std::sync::OnceLock<[Vec<SearchStep>; 8]> = std::sync::OnceLock::new();
    ORDERS.get_or_init(|| {
        std::array::from_fn(|octant| {
            let mut order: Vec<SearchStep> = neighbourhood()
                .iter()
                .enumerate()
                .map(|(place, &offset)| {
                    let least =
                        |axis: usize| least_gap(offset[axis], octant >> axis & 1 == 1).powi(2);
                    SearchStep {
                        offset,
                        place: place as u8,
                        gap: [0, 1, 2].map(|axis| (offset[axis] + 2) as usize),
                        least_sum: least(0) + least(1) + least(2),
                    }
                })
                .collect();
            order.sort_by(|a, b| a.least_sum.total_cmp(&b.least_sum));
            order
        })
    })
}

/// The least distance along one axis from a point of the centre cube's lower or upper half
/// to the cubes `offset` steps away. The point lies in the centre cube or (the cube is
/// found 1e-10 below the point) up to 1e-10 past its upper face, and rounding never takes
/// a difference below a bound it exceeds exactly, so these hold in floating point.
fn least_gap(offset: i32, upper: bool) -> f64 {
    match (offset, upper) {
        (0, _) | (1, true) | (-1, false) => 0.0,
        (1, false) | (-1, true) => 0.5,
        (2, true) => 1.0 - 1e-9,
        (-2, false) => 1.0,
        _ => 1.5,
    }
}

/// The nucleus nearest to `p` in the metric.
pub fn nearest_nucleus(p: DVec3, metric: f64) -> DVec3 {
    nearest_three(p, metric).1
}

/// `crackle`: the distances to the nearest, second and third nearest nuclei weighted by
/// `form`, each grown by `offset`; or, `solid`, the noise at the nearest nucleus, which
/// paints each cell one colour. The value is clipped to 0..1.
pub fn crackle(p: DVec3, form: DVec3, metric: f64, offset: f64, solid: bool) -> f64 {
    if !p.is_finite() {
        return 0.0;
    }
    let (mut sums, nearest) = nearest_three(p, metric);
    if solid {
        return noise::noise(nearest).clamp(0.0, 1.0);
    }
    if offset != 0.0 {
        let grow = if metric == 2.0 {
            offset * offset
        } else if metric == 1.0 {
            offset
        } else {
            offset.powf(metric)
        };
        for s in &mut sums {
            *s += grow;
        }
    }
    let value = form.x * metric_root(sums[0], metric)
        + form.y * metric_root(sums[1], metric)
        + form.z * metric_root(sums[2], metric);
    value.clamp(0.0, 1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_neighbourhood_holds_81_cubes() {
        let cubes = neighbourhood();
        assert!(cubes.contains(&IVec3::new(2, 1, -1)));
        assert!(!cubes.contains(&IVec3::new(2, 2, 0)));
    }

    #[test]
    fn cells_and_crackle_are_povrays() {
        // POV-Ray 3.7's values of `function { pattern { cells } }`, `crackle`, `crackle
        // form <1,0,0> metric 1` and `crackle offset 0.3 form <0.5,0.2,0.1>`, to 12 digits.
        for (p, povray) in [
            (
                DVec3::new(-11.0, -20.0, -10.0),
                [
                    0.128211426316,
                    0.788004609609,
                    0.194619984133,
                    0.480901980356,
                ],
            ),
            (
                DVec3::new(-8.69, -7.867975, 15.623051),
                [0.028388349805, 0.119545764788, 1.0, 0.621373568350],
            ),
            (
                DVec3::new(-5.61, 24.974725, -0.212881),
                [
                    0.132996031083,
                    0.068981424314,
                    0.888285151937,
                    0.561192656116,
                ],
            ),
            (
                DVec3::new(-1.76, 28.5281, 2.492204),
                [
                    0.372211341746,
                    0.381424936797,
                    0.673975113524,
                    0.551178190985,
                ],
            ),
        ] {
            let ours = [
                cells(p),
                crackle(p, DVec3::new(-1.0, 1.0, 0.0), 2.0, 0.0, false),
                crackle(p, DVec3::X, 1.0, 0.0, false),
                crackle(p, DVec3::new(0.5, 0.2, 0.1), 2.0, 0.3, false),
            ];
            for (ours, povray) in ours.into_iter().zip(povray) {
                assert!(
                    (ours - povray).abs() < 1e-9,
                    "{p}: ours {ours}, POV-Ray {povray}"
                );
            }
        }
    }

    #[test]
    fn cells_are_uniform_and_constant_in_a_cube() {
        assert_eq!(
            cells(DVec3::new(0.1, 0.2, 0.3)),
            cells(DVec3::new(0.9, 0.8, 0.7))
        );
        let n = 20_000;
        let mean = (0..n)
            .map(|i| cells(DVec3::new(i as f64, (i / 7) as f64, -(i as f64))))
            .sum::<f64>()
            / n as f64;
        assert!((mean - 0.5).abs() < 0.01, "{mean}");
    }

    #[test]
    fn the_nearest_nuclei_are_those_of_a_search_of_every_cube() {
        // Points in cubes of all octants, near their faces and far from the origin, in
        // the metrics that skip cubes and one that does not.
        for metric in [2.0, 1.0, 3.0] {
            // Also points on cube faces and half-way planes, where the search order
            // changes, and points beyond 1e8, where the search does not end early.
            let on_planes = (0..512).map(|i| {
                let f = i as f64;
                DVec3::new(
                    (i % 8) as f64 * 0.5 - 2.0,
                    (i / 8 % 8) as f64 * 0.25,
                    f * 0.5 - 128.0,
                )
            });
            let far = (0..64).map(|i| DVec3::new(1e8 + i as f64 * 0.37, -2e9, i as f64 * 3.1));
            let scattered = (0..3000).map(|i| {
                let f = i as f64;
                DVec3::new(f * 0.731 - 1100.0, (f * 0.377).sin() * 40.0, f * 1e-3 - 0.5)
            });
            for p in scattered.chain(on_planes).chain(far) {
                // Every cube's nucleus, nearest first; of equally near ones, the first
                // visited.
                let centre = cube_of(p - DVec3::splat(1e-10));
                let mut all: Vec<(f64, DVec3)> = neighbourhood()
                    .iter()
                    .map(|offset| {
                        let n = nucleus(centre + *offset);
                        (metric_sum(n - p, metric), n)
                    })
                    .collect();
                all.sort_by(|a, b| a.0.total_cmp(&b.0));
                let (best, nearest) = ([all[0].0, all[1].0, all[2].0], all[0].1);
                assert_eq!(nearest_three(p, metric), (best, nearest), "{p} {metric}");
            }
        }
    }

    #[test]
    fn crackle_stays_in_range() {
        let form = DVec3::new(-1.0, 1.0, 0.0);
        // At a nucleus the nearest distance is zero and the value the next distance.
        let a = nucleus(IVec3::ZERO);
        let (sums, _) = nearest_three(a, 2.0);
        assert_eq!(sums[0], 0.0);
        let v = crackle(a, form, 2.0, 0.0, false);
        assert!(v > 0.0 && v <= 1.0);
        for i in 0..100 {
            let p = DVec3::new(i as f64 * 0.37, 0.5, i as f64 * 0.11);
            assert!((0.0..=1.0).contains(&crackle(p, form, 2.0, 0.0, false)));
        }
    }
}
