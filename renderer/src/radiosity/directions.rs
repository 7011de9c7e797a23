//! The directions radiosity gathers light from: a pool of directions over the hemisphere
//! about +z, spread evenly and denser towards the pole in proportion to the cosine, so
//! that the plain mean of what they see is the irradiance divided by π.
//!
//! As the manual describes, every gather uses the same `count` directions unless `count`'s
//! second argument asks for a larger pool, which successive gathers then draw from in
//! turn. Our pool follows the R2 low-discrepancy sequence (Roberts 2018, built on the
//! plastic number), any run of which is itself evenly spread, mapped to the disc with
//! Shirley and Chiu's concentric map and lifted onto the hemisphere (Malley's method).

use glam::DVec3;

/// The plastic number, the R2 sequence's generator.
const PLASTIC: f64 = 1.324_717_957_244_746;

#[derive(Debug, Clone)]
pub struct Directions {
    pool: Vec<DVec3>,
    count: usize,
}

impl Directions {
    /// `count` directions per gather, from a pool of `pool` (at least `count`).
    pub fn new(count: u32, pool: u32) -> Directions {
        let count = count.max(1) as usize;
        let size = (pool as usize).max(count);
        let (a1, a2) = (1.0 / PLASTIC, 1.0 / (PLASTIC * PLASTIC));
        let pool = (0..size)
            .map(|i| {
                let u = (0.5 + a1 * i as f64).fract();
                let v = (0.5 + a2 * i as f64).fract();
                lift(concentric_disc(u, v))
            })
            .collect();
        Directions { pool, count }
    }

    pub fn count(&self) -> usize {
        self.count
    }

    /// The directions of one gather: `count` of them from the pool, starting at the run
    /// that `key` picks, so that neighbouring gathers of a large pool differ.
    pub fn gather(&self, key: u64) -> impl Iterator<Item = DVec3> + '_ {
        let runs = self.pool.len().div_ceil(self.count);
        let start = if runs > 1 {
            (key % runs as u64) as usize * self.count
        } else {
            0
        };
        (0..self.count).map(move |i| self.pool[(start + i) % self.pool.len()])
    }
}

/// Shirley and Chiu's map from the unit square to the unit disc, which keeps neighbouring
/// points neighbours and areas in proportion.
fn concentric_disc(u: f64, v: f64) -> (f64, f64) {
    let (a, b) = (2.0 * u - 1.0, 2.0 * v - 1.0);
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let quarter = std::f64::consts::FRAC_PI_4;
    let (r, phi) = if a.abs() > b.abs() {
        (a, quarter * (b / a))
    } else {
        (b, 2.0 * quarter - quarter * (a / b))
    };
    (r * phi.cos(), r * phi.sin())
}

/// A point of the unit disc raised onto the hemisphere above it: uniform points on the
/// disc become cosine-distributed directions.
fn lift((x, y): (f64, f64)) -> DVec3 {
    DVec3::new(x, y, (1.0 - x * x - y * y).max(0.0).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directions_are_unit_vectors_above_the_surface() {
        let d = Directions::new(35, 35);
        assert_eq!(d.gather(7).count(), 35);
        for v in d.gather(0) {
            assert!((v.length() - 1.0).abs() < 1e-12 && v.z >= 0.0, "{v}");
        }
    }

    #[test]
    fn their_mean_weighs_directions_by_the_cosine() {
        // Under a cosine distribution the mean of z is 2/3, the mean of z² is 1/2, and
        // the mean of x and y is 0.
        let d = Directions::new(400, 400);
        let n = 400.0;
        let mean = d.gather(0).sum::<DVec3>() / n;
        let z2 = d.gather(0).map(|v| v.z * v.z).sum::<f64>() / n;
        assert!((mean.z - 2.0 / 3.0).abs() < 0.01, "{mean}");
        assert!(mean.x.abs() < 0.01 && mean.y.abs() < 0.01, "{mean}");
        assert!((z2 - 0.5).abs() < 0.01, "{z2}");
    }

    #[test]
    fn a_larger_pool_is_drawn_from_in_runs() {
        let d = Directions::new(10, 40);
        let first: Vec<DVec3> = d.gather(0).collect();
        let second: Vec<DVec3> = d.gather(1).collect();
        assert_ne!(first, second);
        assert_eq!(first, d.gather(4).collect::<Vec<_>>());
        // Each run is spread over the hemisphere, not bunched on one side.
        for run in [first, second] {
            let mean = run.iter().sum::<DVec3>() / 10.0;
            assert!(mean.x.abs() < 0.2 && mean.y.abs() < 0.2, "{mean}");
        }
    }
}
