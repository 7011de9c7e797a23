//! Periodic structures: hexagonal lattices in the xy plane and a woven mesh of threads,
//! each the distance to the nearest cell centre, line or thread, found among the
//! neighbouring cells. The lattices' spacings were measured from POV-Ray 3.7's
//! `functions.inc`; `a` is `x, y, z, P0, ...`.

use std::f64::consts::PI;

const HALF_SQRT_3: f64 = 0.866_025_403_784_438_6;

/// The hexagonal norm whose unit ball is a hexagon with flat sides facing ±x.
fn hexagonal_norm(dx: f64, dy: f64) -> f64 {
    let slant = HALF_SQRT_3 * dy;
    dx.abs()
        .max((0.5 * dx + slant).abs())
        .max((0.5 * dx - slant).abs())
}

/// Hexagonal cylinders along z: the hexagonal distance to the nearest centre of the
/// lattice spanned by (√3, 0) and (√3/2, 1.5), so that neighbours touch at 0.8660254.
pub fn hex_x(a: &[f64]) -> f64 {
    let (x, y) = (a[0], a[1]);
    let width = 2.0 * HALF_SQRT_3;
    let (column, row) = ((x / width).floor(), (y / 3.0).floor());
    let mut nearest = f64::INFINITY;
    for i in -1..=2 {
        for j in -1..=2 {
            let (cx, cy) = ((column + f64::from(i)) * width, (row + f64::from(j)) * 3.0);
            nearest = nearest
                .min(hexagonal_norm(x - cx, y - cy))
                .min(hexagonal_norm(x - cx - HALF_SQRT_3, y - cy - 1.5));
        }
    }
    nearest
}

/// The distance from `value` to the nearest multiple of 1.5.
fn to_lines(value: f64) -> f64 {
    (value - 1.5 * (value / 1.5).round()).abs()
}

/// Triangular cells along z: the distance to the nearest line of the three families
/// y = 1.5k and the lines at ±60° through (√3·m, 0), all 1.5 apart.
pub fn hex_y(a: &[f64]) -> f64 {
    let (x, y) = (a[0], a[1]);
    let rising = HALF_SQRT_3 * x - 0.5 * y;
    let falling = HALF_SQRT_3 * x + 0.5 * y;
    to_lines(y).min(to_lines(rising)).min(to_lines(falling))
}

/// A woven mesh: threads along x at z = j·P1 rising and falling as P3·cos(πx/P0), and
/// threads along z at x = i·P0 as −P3·cos(πz/P1), each family alternating in sign from
/// one thread to the next; the distance to the nearest, its horizontal part scaled by P2
/// and its vertical part by P4.
pub fn mesh1(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (spacing_x, spacing_z, across, amplitude, upright) = (a[3], a[4], a[5], a[6], a[7]);
    let alternate = |k: f64| if k.rem_euclid(2.0) == 0.0 { 1.0 } else { -1.0 };
    let distance = |horizontal: f64, vertical: f64| (across * horizontal).hypot(upright * vertical);
    let mut nearest = f64::INFINITY;
    let (row, column) = ((z / spacing_z).floor(), (x / spacing_x).floor());
    for step in [0.0, 1.0] {
        let j = row + step;
        let height = amplitude * (PI * x / spacing_x).cos() * alternate(j);
        nearest = nearest.min(distance(z - j * spacing_z, y - height));
        let i = column + step;
        let height = -amplitude * (PI * z / spacing_z).cos() * alternate(i);
        nearest = nearest.min(distance(x - i * spacing_x, y - height));
    }
    nearest
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hex_x_measures_the_hexagonal_distance() {
        // POV-Ray 3.7: f_hex_x at (1, 0, 0) is √3 − 1, at (0, 1, 0) is 0.86603.
        assert!((hex_x(&[1.0, 0.0, 0.0, 1.0]) - (3f64.sqrt() - 1.0)).abs() < 1e-12);
        assert!((hex_x(&[0.0, 1.0, 0.0, 1.0]) - HALF_SQRT_3).abs() < 1e-12);
    }

    #[test]
    fn hex_y_is_zero_on_its_lines() {
        // POV-Ray 3.7: f_hex_y is 0 along y = 0 and y = 1.5, and 0.5 at (0, 1, 0).
        assert_eq!(hex_y(&[0.7, 0.0, 0.0, 1.0]), 0.0);
        assert!(hex_y(&[2.3, 1.5, 0.0, 1.0]).abs() < 1e-12);
        assert!((hex_y(&[0.0, 1.0, 0.0, 1.0]) - 0.5).abs() < 1e-12);
    }
}
