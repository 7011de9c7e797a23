//! Plane curves made solid: `f_algbr_cyl1..4` and the `*_2d` functions evaluate a curve
//! f(x, y) either extruded along z or, with the SOR switch on, swept about the y axis after
//! shifting it along x and turning it about z (the last three parameters). The curves are
//! multiplied by the field strength and clamped: the algebraic cylinders to their field
//! limit, the others to -10..10, as POV-Ray 3.7 does.

/// The point of the curve's plane that (x, y, z) maps to: itself when extruded, or, when
/// swept, its distance from the y axis less the offset, turned by `angle` degrees.
fn plane_point(x: f64, y: f64, z: f64, switch: f64, offset: f64, angle: f64) -> (f64, f64) {
    if switch <= 0.0 {
        return (x, y);
    }
    let u = (x * x + z * z).sqrt() - offset;
    let (sin, cos) = angle.to_radians().sin_cos();
    (u * cos - y * sin, u * sin + y * cos)
}

/// A curve with its SOR parameters at `a[sor..sor + 3]`, times the field strength `a[3]`,
/// clamped to -10..10.
fn swept(a: &[f64], sor: usize, curve: impl Fn(f64, f64) -> f64) -> f64 {
    let (u, v) = plane_point(a[0], a[1], a[2], a[sor], a[sor + 1], a[sor + 2]);
    (a[3] * curve(u, v)).clamp(-10.0, 10.0)
}

/// An algebraic cylinder: the curve times the field strength, limited to ±P1. POV-Ray
/// applies the two bounds one after the other, so a negative limit yields +|P1| for the
/// first cylinder (upper bound first) and -|P1| for the others.
fn cylinder(a: &[f64], upper_first: bool, curve: impl Fn(f64, f64) -> f64) -> f64 {
    let (u, v) = plane_point(a[0], a[1], a[2], a[5], a[6], a[7]);
    let limit = a[4];
    let value = a[3] * curve(u, v);
    if upper_first {
        value.min(limit).max(-limit)
    } else {
        value.max(-limit).min(limit)
    }
}

/// The figure-of-eight cylinder: y² + |x|³ − x².
pub fn algbr_cyl1(a: &[f64]) -> f64 {
    cylinder(a, true, |x, y| y * y + x.abs().powi(3) - x * x)
}

/// The second algebraic cylinder: 2y³ + 3x²y − y² − y⁴ − 2x⁴.
pub fn algbr_cyl2(a: &[f64]) -> f64 {
    cylinder(a, false, |x, y| {
        2.0 * y.powi(3) + 3.0 * x * x * y - y * y - y.powi(4) - 2.0 * x.powi(4)
    })
}

/// The third algebraic cylinder: xy² + 2x²y − y² − x²y² − x⁴.
pub fn algbr_cyl3(a: &[f64]) -> f64 {
    cylinder(a, false, |x, y| {
        x * y * y + 2.0 * x * x * y - y * y - x * x * y * y - x.powi(4)
    })
}

/// The trefoil cylinder: y³ − 3x²y − (x² + y²)².
pub fn algbr_cyl4(a: &[f64]) -> f64 {
    cylinder(a, false, |x, y| {
        y.powi(3) - 3.0 * x * x * y - (x * x + y * y).powi(2)
    })
}

/// The devil's curve: a²x² − b²y² − x⁴ + y⁴.
pub fn devils_curve_2d(a: &[f64]) -> f64 {
    let (fx, fy) = (a[4], a[5]);
    swept(a, 6, |x, y| {
        fx * fx * x * x - fy * fy * y * y - x.powi(4) + y.powi(4)
    })
}

/// The folium curve: −(y² + (b − 4a)xy² + (b + 1)x²).
pub fn folium_surface_2d(a: &[f64]) -> f64 {
    let (neck, divergence) = (a[4], a[5]);
    swept(a, 6, |x, y| {
        -(y * y + (divergence - 4.0 * neck) * x * y * y + (divergence + 1.0) * x * x)
    })
}

/// The kampyle of Eudoxus: b²x⁴ − ab³x² − y².
pub fn kampyle_of_eudoxus_2d(a: &[f64]) -> f64 {
    let (dimple, closeness) = (a[4], a[5]);
    swept(a, 6, |x, y| {
        closeness * closeness * x.powi(4) - dimple * closeness.powi(3) * x * x - y * y
    })
}

/// The lemniscate of Gerono: a²b²x² − b²x⁴ − y².
pub fn lemniscate_of_gerono_2d(a: &[f64]) -> f64 {
    let (size, width) = (a[4], a[5]);
    let w2 = width * width;
    swept(a, 6, |x, y| {
        size * size * w2 * x * x - w2 * x.powi(4) - y * y
    })
}

/// The piriform: c²(ax³ + bx⁴) − y².
pub fn piriform_2d(a: &[f64]) -> f64 {
    let (first, second, fatness) = (a[4], a[5], a[6]);
    swept(a, 7, |x, y| {
        fatness * fatness * (first * x.powi(3) + second * x.powi(4)) - y * y
    })
}

/// The strophoid: xy² + c²x³ + ac²x² − by².
pub fn strophoid_2d(a: &[f64]) -> f64 {
    let (size, sharpness, fatness) = (a[4], a[5], a[6]);
    let c2 = fatness * fatness;
    swept(a, 7, |x, y| {
        x * y * y + c2 * x.powi(3) + size * c2 * x * x - sharpness * y * y
    })
}

/// The witch of Agnesi: b − a²y − x²y.
pub fn witch_of_agnesi_2d(a: &[f64]) -> f64 {
    let (size, height) = (a[4], a[5]);
    swept(a, 6, |x, y| height - size * size * y - x * x * y)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_negative_field_limit_sticks_to_one_bound() {
        // POV-Ray 3.7 at (0.5, 0, 0) with field limit -3: f_algbr_cyl1 gives 3 and
        // f_algbr_cyl2 gives -3, whatever the curve's value.
        assert_eq!(algbr_cyl1(&[0.5, 0.0, 0.0, 1.0, -3.0, 0.0, 0.0, 0.0]), 3.0);
        assert_eq!(algbr_cyl2(&[0.5, 0.0, 0.0, 1.0, -3.0, 0.0, 0.0, 0.0]), -3.0);
        assert_eq!(algbr_cyl1(&[3.0, 3.0, 0.0, 1.0, 5.0, 0.0, 0.0, 0.0]), 5.0);
    }

    #[test]
    fn the_sor_switch_sweeps_the_curve_about_y() {
        // Swept with no offset or angle, (x, y, z) reads the curve at (√(x² + z²), y).
        let swept = devils_curve_2d(&[0.3, 0.2, 0.4, 1.0, 1.3, 0.7, 1.0, 0.0, 0.0]);
        let flat = devils_curve_2d(&[0.5, 0.2, 7.0, 1.0, 1.3, 0.7, 0.0, 0.0, 0.0]);
        assert!((swept - flat).abs() < 1e-12);
    }
}
