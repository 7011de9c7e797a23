//! Noise generator 3, which POV-Ray's manual calls Perlin's improved noise, as POV-Ray 3.7
//! computes it (measured, max error 1.6e-9 over 120 000 points up to ±1e5): a gradient noise
//! whose lattice points sit at n − 0.0231572129 on each axis, each with a gradient and no
//! value, blended by the weights 3t² − 2t³ around 0.4925. A lattice point's gradient comes
//! from its coordinates modulo 2048 through two shifts, see
//! [`improved_tables`](super::improved_tables).

use super::improved_tables::{COLUMN_SHIFT, GRADIENTS, ROW_SHIFT};
use super::s_curve;
use crate::floor::floor_whole;
use glam::DVec3;

/// Where the lattice sits: its points are where the coordinates plus this are integers
/// (a single-precision number: measured to 1e-15, it is 0.0231572129 rounded to a float).
const LATTICE_SHIFT: f64 = 0.023157212883234024;

/// The noise's value at every lattice point, and the middle of its range.
const CENTRE: f64 = 0.4925;

/// The gradient of lattice point (x, y, z) (each modulo 2048): the column through (x, y)
/// is the column through (0, 0) shifted along z by the shift of (0, y + the row shift of
/// x).
fn gradient(x: i64, y: i64, z: i64) -> DVec3 {
    let row = (i64::from(ROW_SHIFT[(x & 2047) as usize]) + y) & 2047;
    let column = (i64::from(COLUMN_SHIFT[row as usize]) + z) & 2047;
    DVec3::from_array(GRADIENTS[column as usize])
}

/// Generator 3's noise at `p` before its clipping to 0..1.
pub(super) fn unclipped(p: DVec3) -> f64 {
    // The tables count the lattice points from the one below (0, 0, 0).
    let q = p + DVec3::splat(LATTICE_SHIFT - 1.0);
    let ((fx, x), (fy, y), (fz, z)) = (floor_whole(q.x), floor_whole(q.y), floor_whole(q.z));
    let t = q - DVec3::new(fx, fy, fz);
    let s = DVec3::new(s_curve(t.x), s_curve(t.y), s_curve(t.z));
    let mut sum = 0.0;
    for i in 0..2 {
        let wx = if i == 0 { 1.0 - s.x } else { s.x };
        for j in 0..2 {
            let wxy = wx * if j == 0 { 1.0 - s.y } else { s.y };
            for k in 0..2 {
                let w = wxy * if k == 0 { 1.0 - s.z } else { s.z };
                let d = t - DVec3::new(i as f64, j as f64, k as f64);
                sum += w * gradient(x.wrapping_add(i), y.wrapping_add(j), z.wrapping_add(k)).dot(d);
            }
        }
    }
    let value = CENTRE + sum;
    if value.is_nan() { CENTRE } else { value }
}
