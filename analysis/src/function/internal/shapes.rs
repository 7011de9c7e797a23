//! Distance-like shapes and coordinates: spheres, tori, boxes, surfaces of revolution of a
//! polynomial, and the spherical coordinates. Where POV-Ray 3.7 guards a corner case
//! (a floor, an offset, a nudge off a singular axis) the guard was measured and is kept;
//! `a` is `x, y, z, P0, ...`.

/// The distance from the origin.
pub fn r(a: &[f64]) -> f64 {
    (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt()
}

/// The sphere of radius P0 about the origin.
pub fn sphere(a: &[f64]) -> f64 {
    r(a) - a[3]
}

/// The torus about y, major radius P0, minor P1.
pub fn torus(a: &[f64]) -> f64 {
    let ring = (a[0] * a[0] + a[2] * a[2]).sqrt() - a[3];
    (ring * ring + a[1] * a[1]).sqrt() - a[4]
}

/// The longitude about y, in radians, measured from +z towards +x.
pub fn th(a: &[f64]) -> f64 {
    a[0].atan2(a[2])
}

/// The polar angle from +y, in radians (0 at the origin).
pub fn ph(a: &[f64]) -> f64 {
    (a[0] * a[0] + a[2] * a[2]).sqrt().atan2(a[1])
}

/// The ellipsoid's radial function √((P0·x)² + (P1·y)² + (P2·z)²), 1 on its surface.
pub fn ellipsoid(a: &[f64]) -> f64 {
    ((a[3] * a[0]).powi(2) + (a[4] * a[1]).powi(2) + (a[5] * a[2]).powi(2)).sqrt()
}

/// The superellipsoid 1 − ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2), e east-west
/// and n north-south.
pub fn superellipsoid(a: &[f64]) -> f64 {
    let (e, n) = (a[3], a[4]);
    let across = (a[0].abs().powf(2.0 / e) + a[1].abs().powf(2.0 / e)).powf(e / n);
    1.0 - (across + a[2].abs().powf(2.0 / n)).powf(n / 2.0)
}

/// The box ±(P1, P2, P3) with its edges rounded to radius P0: the distance from the box
/// shrunk by P0, less P0 and POV-Ray's 1e-6.
pub fn rounded_box(a: &[f64]) -> f64 {
    let radius = a[3];
    let outside = |c: f64, half: f64| (c.abs() - half + radius).max(0.0);
    let (dx, dy, dz) = (
        outside(a[0], a[4]),
        outside(a[1], a[5]),
        outside(a[2], a[6]),
    );
    (dx * dx + dy * dy + dz * dz).sqrt() - radius - 1e-6
}

/// The polynomial A + By + Cy² + Dy³ + Ey⁴ of `f_poly4` and `f_polytubes`.
fn quartic(y: f64, c: &[f64]) -> f64 {
    c[0] + y * (c[1] + y * (c[2] + y * (c[3] + y * c[4])))
}

/// The surface of revolution about y of x = A + By + Cy² + Dy³ + Ey⁴; POV-Ray floors the
/// radius at -5.
pub fn poly4(a: &[f64]) -> f64 {
    (a[0] * a[0] + a[2] * a[2]).sqrt() - quartic(a[1], &a[3..8]).max(-5.0)
}

/// P0 tubes about y, each at distance A + By + ... + Ey⁴ from the axis and spaced 2π/P0
/// apart from +z: the distance to the nearest, at most 10000. Only whole tubes are made
/// (⌊P0⌋ of them) though the spacing uses P0 itself.
pub fn polytubes(a: &[f64]) -> f64 {
    let (x, z, count) = (a[0], a[2], a[3]);
    let radius = quartic(a[1], &a[4..9]);
    let step = std::f64::consts::TAU / count;
    let whole = if count >= 1.0 {
        count.min(f64::from(u16::MAX)) as u32
    } else {
        0
    };
    (0..whole)
        .map(|k| {
            let (sin, cos) = (step * f64::from(k)).sin_cos();
            (x - radius * sin).hypot(z - radius * cos)
        })
        .fold(10000.0, f64::min)
}

/// A comma of size P0: a ball of radius P0/2 at (P0/2, 0, 0) joined to a tail that follows
/// the upper half of the circle of radius 3P0/4 about (−P0/4, 0, 0) in the xz plane and
/// thins as (P0/2)·cos(φ/2) with the angle φ about y, the tail cut off below z = 0.
/// POV-Ray moves a point on the y axis to x = 0.0001.
pub fn comma(a: &[f64]) -> f64 {
    let (mut x, y, z, size) = (a[0], a[1], a[2], a[3]);
    if x == 0.0 && z == 0.0 {
        x = 0.0001;
    }
    let ball = ((x - 0.5 * size).powi(2) + y * y + z * z).sqrt() - 0.5 * size;
    let from_arc = ((x + 0.25 * size).powi(2) + z * z).sqrt() - 0.75 * size;
    let tail = (from_arc * from_arc + y * y).sqrt() - 0.5 * size * (z.atan2(x) / 2.0).cos();
    ball.min(tail.max(-z))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polytubes_makes_whole_tubes_only() {
        // POV-Ray 3.7 with 2.5 tubes of radius 0.5: tubes at 0° and 144° about y, none at
        // 288°, so a point at 250° is nearest the 144° tube; with no tube at all, 10000.
        let angle = 250f64.to_radians();
        let point = [0.5 * angle.sin(), 0.0, 0.5 * angle.cos()];
        let args = [point[0], point[1], point[2], 2.5, 0.5, 0.0, 0.0, 0.0, 0.0];
        assert!((polytubes(&args) - 2.0 * 0.5 * 53f64.to_radians().sin()).abs() < 1e-12);
        assert_eq!(
            polytubes(&[0.1, 0.0, 0.2, 0.5, 0.5, 0.0, 0.0, 0.0, 0.0]),
            10000.0
        );
    }

    #[test]
    fn poly4_floors_the_radius_at_minus_five() {
        // POV-Ray 3.7: f_poly4(0, 0, 0, -7, 0, 0, 0, 0) = 5.
        assert_eq!(poly4(&[0.0, 0.0, 0.0, -7.0, 0.0, 0.0, 0.0, 0.0]), 5.0);
    }

    #[test]
    fn comma_moves_points_off_the_y_axis() {
        // POV-Ray 3.7: f_comma(0, 0, 0, 1) = -0.0001 and f_comma(0, 1, 0, 2) =
        // 0.414142853462832.
        assert!((comma(&[0.0, 0.0, 0.0, 1.0]) + 0.0001).abs() < 1e-15);
        assert!((comma(&[0.0, 1.0, 0.0, 2.0]) - 0.414142853462832).abs() < 1e-14);
    }

    #[test]
    fn rounded_box_keeps_povrays_offset() {
        // POV-Ray 3.7: f_rounded_box(2, 0, 0, 0.1, 1, 1, 1) = 0.999999.
        assert!((rounded_box(&[2.0, 0.0, 0.0, 0.1, 1.0, 1.0, 1.0]) - 0.999999).abs() < 1e-15);
    }
}
