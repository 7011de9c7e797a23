//! Patterns built on one random point (a nucleus) in each unit cube of space: `cells`
//! (a random value per cube), `crackle` (distances to the nearest nuclei, a Voronoi
//! diagram) and the nuclei `facets` normals turn towards. The random values are our own,
//! not POV-Ray's; they share its distribution (uniform in each cube), which the noise
//! statistics tests compare.

use crate::noise;
use glam::{DVec3, IVec3};

/// A well-mixed 64-bit hash of a cube's integer coordinates and a stream number.
fn hash(cube: IVec3, stream: u32) -> u64 {
    let mut h = (cube.x as u32 as u64)
        ^ ((cube.y as u32 as u64) << 21)
        ^ ((cube.z as u32 as u64) << 42)
        ^ (u64::from(stream) << 58);
    // SplitMix64's finaliser.
    h = h.wrapping_add(0x9e37_79b9_7f4a_7c15);
    h = (h ^ (h >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h = (h ^ (h >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^ (h >> 31)
}

/// A value in 0..1 fixed for each cube and stream.
fn random(cube: IVec3, stream: u32) -> f64 {
    (hash(cube, stream) >> 11) as f64 / (1u64 << 53) as f64
}

/// The integer cube holding a coordinate, saturating far from the origin.
fn cube_of(p: DVec3) -> IVec3 {
    let clamp = |v: f64| v.floor().clamp(-1e9, 1e9) as i32;
    IVec3::new(clamp(p.x), clamp(p.y), clamp(p.z))
}

/// The random point of a cube.
pub fn nucleus(cube: IVec3) -> DVec3 {
    cube.as_dvec3() + DVec3::new(random(cube, 0), random(cube, 1), random(cube, 2))
}

/// `cells`: the random value of the unit cube holding the point.
pub fn cells(p: DVec3) -> f64 {
    if !p.is_finite() {
        return 0.0;
    }
    random(cube_of(p + DVec3::splat(1e-10)), 3)
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
    let mut best = [f64::INFINITY; 3];
    let mut nearest = DVec3::ZERO;
    let mut nearest_place = usize::MAX;
    // The cubes are searched nearest first, and a cube no part of which is nearer than
    // the third nearest nucleus found so far holds no nucleus that changes the answer: its
    // nucleus is not worked out. Of equally near nuclei the one first in the neighbourhood
    // is the nearest, as when every cube was searched in its order, so the answer is the
    // same to the bit. (The bound holds for the metrics whose sums only grow with each
    // coordinate's distance in floating point too, not for the others' powers.)
    let bounded = metric == 2.0 || metric == 1.0;
    for &(offset, place) in search_order() {
        let cube = centre + offset;
        if bounded && metric_sum(distance_to_cube(p, cube), metric) > best[2] {
            continue;
        }
        let n = nucleus(cube);
        let sum = metric_sum(n - p, metric);
        if sum < best[0] {
            best = [sum, best[0], best[1]];
            nearest = n;
            nearest_place = place;
            continue;
        }
        if sum == best[0] && place < nearest_place {
            nearest = n;
            nearest_place = place;
        }
        if sum < best[1] {
            best = [best[0], sum, best[1]];
        } else if sum < best[2] {
            best[2] = sum;
        }
    }
    (best, nearest)
}

/// The cubes of [`neighbourhood`] nearest to the centre first, each with its place there.
fn search_order() -> &'static [(IVec3, usize); 81] {
    static ORDER: std::sync::OnceLock<[(IVec3, usize); 81]> = std::sync::OnceLock::new();
    ORDER.get_or_init(|| {
        let mut order = [(IVec3::ZERO, 0); 81];
        for (place, offset) in neighbourhood().iter().enumerate() {
            order[place] = (*offset, place);
        }
        order.sort_by_key(|(offset, _)| offset.length_squared());
        order
    })
}

/// How far `p` lies from the unit cube `cube` along each axis: a lower bound on each
/// coordinate of the distance to any point of the cube, its nucleus included.
fn distance_to_cube(p: DVec3, cube: IVec3) -> DVec3 {
    let low = cube.as_dvec3();
    DVec3::ZERO.max(low - p).max(p - (low + 1.0))
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
            for i in 0..3000 {
                let f = i as f64;
                let p = DVec3::new(f * 0.731 - 1100.0, (f * 0.377).sin() * 40.0, f * 1e-3 - 0.5);
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
