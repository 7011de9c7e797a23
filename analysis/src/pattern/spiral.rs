//! `spiral1` and `spiral2`: arms winding around the z axis, and `quilted`, cubes with
//! softened seams. Their raw values are left unwrapped; the wave type folds them.

use glam::DVec3;
use std::f64::consts::{FRAC_PI_2, TAU};

/// The angle around the z axis, from -y (0) anticlockwise seen from +z, in 0..2π.
fn turn(p: DVec3) -> f64 {
    if p.x == 0.0 && p.y == 0.0 {
        0.0
    } else {
        (p.y.atan2(p.x) + FRAC_PI_2).rem_euclid(TAU)
    }
}

/// One period of a triangle wave: 0 at whole numbers, 1 halfway between.
fn triangle(v: f64) -> f64 {
    let f = v - v.floor();
    if f < 0.5 { 2.0 * f } else { 2.0 * (1.0 - f) }
}

/// `spiral1 arms`: the distance from the z axis plus z plus the arm count times the
/// fraction of a turn; `turbulence` adds its scalar value, as for marble.
pub fn spiral1(p: DVec3, arms: f64, turbulence: f64) -> f64 {
    let radius = (p.x * p.x + p.y * p.y).sqrt();
    p.z + radius + arms * turn(p) / TAU + turbulence
}

/// `spiral2 arms`: spiral1 folded by a triangle wave, plus the folded distance from the
/// z axis, so that two spirals cross.
pub fn spiral2(p: DVec3, arms: f64, turbulence: f64) -> f64 {
    let radius = (p.x * p.x + p.y * p.y).sqrt();
    triangle(spiral1(p, arms, turbulence)) + triangle(radius)
}

/// The seam shape of `quilted`: a cubic from 0 to 1 whose slopes at the ends follow the
/// two controls, scaled so that a cube's corner (at distance √3/2) reaches 1.
fn quilt_cubic(t: f64, control0: f64, control1: f64) -> f64 {
    let it = 1.0 - t;
    (t * t * t + 3.0 * t * it * it * control0 + 3.0 * t * t * it * control1) * 1.154_700_538
}

/// The offset of a point from the centre of its unit cube, scaled by the seam shape: what
/// `quilted` shows as a pigment and pushes normals by.
pub fn quilt_offset(p: DVec3, control0: f64, control1: f64) -> DVec3 {
    let offset = p - p.floor() - DVec3::splat(0.5);
    offset * quilt_cubic(offset.length(), control0, control1)
}

/// `quilted` as a pigment: the mean size of the scaled offset's components.
pub fn quilted(p: DVec3, control0: f64, control1: f64) -> f64 {
    let v = quilt_offset(p, control0, control1);
    (v.x.abs() + v.y.abs() + v.z.abs()) / 3.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spiral_arms_advance_with_the_angle() {
        // Along +x a quarter turn from -y: one arm in four.
        assert!((spiral1(DVec3::new(2.0, 0.0, 0.0), 3.0, 0.0) - 2.75).abs() < 1e-12);
        assert!((spiral1(DVec3::new(0.0, 2.0, 0.3), 2.0, 0.0) - 3.3).abs() < 1e-12);
        assert!((spiral2(DVec3::new(0.5, 0.0, 0.0), 2.0, 0.0) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn quilted_is_zero_at_cube_centres() {
        assert_eq!(quilted(DVec3::splat(0.5), 1.0, 1.0), 0.0);
        let corner = quilted(DVec3::splat(1e-9), 0.0, 0.0);
        assert!((corner - 0.375).abs() < 1e-6, "{corner}");
    }
}
