//! The block patterns that tile space with a fixed number of entries: brick, hexagon,
//! square and triangular. Each returns the index of the map entry at a point; the layouts
//! follow POV-Ray's renders (tests/reference/scenes/patterns-blocks.pov checks them).

use glam::DVec3;
use std::f64::consts::{FRAC_PI_3, TAU};

const SQRT3: f64 = 1.732_050_807_568_877_2;

/// `brick`: courses of bricks `size.y` high, each course shifted half a brick along x
/// from the one below and half a brick along z from the one above; `mortar` thick joints
/// run along the upper faces of each brick. Entry 0 is the mortar, 1 the brick.
pub fn brick(p: DVec3, size: DVec3, mortar: f64) -> usize {
    let mut q = p;
    if (q.y / size.y).floor().rem_euclid(2.0) == 1.0 {
        q.x += size.x / 2.0;
    } else {
        q.z += size.z / 2.0;
    }
    let within = q.rem_euclid(size);
    let in_mortar =
        within.x >= size.x - mortar || within.y >= size.y - mortar || within.z >= size.z - mortar;
    usize::from(!in_mortar)
}

/// `square`: unit squares in the x-z plane taking four entries, so that no two squares
/// that share an edge show the same one.
pub fn square(p: DVec3) -> usize {
    let odd_x = p.x.floor().rem_euclid(2.0) == 1.0;
    let odd_z = p.z.floor().rem_euclid(2.0) == 1.0;
    match (odd_x, odd_z) {
        (false, false) => 0,
        (false, true) => 1,
        (true, true) => 2,
        (true, false) => 3,
    }
}

/// The centre nearest to `(x, z)` of the hexagons with unit sides, pointed along x, one
/// centred on the origin: lattice coordinates `(i, j)` of the centre
/// `(1.5 i, sqrt(3) (j + i/2))`.
fn hexagon_cell(x: f64, z: f64) -> (i64, i64, f64, f64) {
    let column = (x / 1.5).floor() as i64;
    let mut best = (0, 0, f64::INFINITY, 0.0, 0.0);
    for i in column..=column + 1 {
        let row = (z / SQRT3 - i as f64 / 2.0).round() as i64;
        for j in row - 1..=row + 1 {
            let cx = 1.5 * i as f64;
            let cz = SQRT3 * (j as f64 + i as f64 / 2.0);
            let d = (x - cx).powi(2) + (z - cz).powi(2);
            if d < best.2 {
                best = (i, j, d, cx, cz);
            }
        }
    }
    (best.0, best.1, best.3, best.4)
}

/// `hexagon`: hexagons with unit sides in the x-z plane, entry 0 around the origin, entry 1
/// next along +z and entry 2 beside them.
pub fn hexagon(p: DVec3) -> usize {
    if !(p.x.is_finite() && p.z.is_finite()) {
        return 0;
    }
    let (i, j, _, _) = hexagon_cell(p.x, p.z);
    (j + 2 * i).rem_euclid(3) as usize
}

/// `triangular`: each hexagon of the hexagon pattern cut into six triangles with unit
/// sides, numbered anticlockwise (from +x towards +z) from the one right of the centre.
pub fn triangular(p: DVec3) -> usize {
    if !(p.x.is_finite() && p.z.is_finite()) {
        return 0;
    }
    let (_, _, cx, cz) = hexagon_cell(p.x, p.z);
    let angle = (p.z - cz).atan2(p.x - cx).rem_euclid(TAU);
    ((angle / FRAC_PI_3) as usize).min(5)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bricks_have_mortar_on_their_upper_faces() {
        let size = DVec3::new(8.0, 3.0, 4.5);
        assert_eq!(brick(DVec3::new(1.0, 1.0, 1.0), size, 0.5), 1);
        assert_eq!(brick(DVec3::new(1.0, 2.8, 1.0), size, 0.5), 0);
        // The second course is shifted by half a brick along x.
        assert_eq!(brick(DVec3::new(7.8, 1.0, 1.0), size, 0.5), 0);
        assert_eq!(brick(DVec3::new(7.8, 4.0, 1.0), size, 0.5), 1);
        assert_eq!(brick(DVec3::new(3.8, 4.0, 1.0), size, 0.5), 0);
    }

    #[test]
    fn hexagons_and_triangles_surround_the_origin() {
        assert_eq!(hexagon(DVec3::ZERO), 0);
        assert_eq!(hexagon(DVec3::new(0.0, 0.0, SQRT3)), 1);
        assert_eq!(hexagon(DVec3::new(1.5, 0.0, SQRT3 / 2.0)), 2);
        assert_eq!(hexagon(DVec3::new(-1.5, 0.0, SQRT3 / 2.0)), 2);
        assert_eq!(triangular(DVec3::new(0.5, 0.0, 0.1)), 0);
        assert_eq!(triangular(DVec3::new(-0.5, 0.0, -0.1)), 3);
        assert_eq!(square(DVec3::new(0.5, 0.0, 0.5)), 0);
        assert_eq!(square(DVec3::new(1.5, 0.0, -0.5)), 2);
    }
}
