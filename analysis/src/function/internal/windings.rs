//! Tubes wound along curves: helices about y, a spiral in the xz plane and a torus with a
//! helical winding. Each measures a point's offset from the curve in two cross-section
//! coordinates and applies a cross-section norm; the parametrisations (phases, the
//! directions angles run in) were pinned down by sampling POV-Ray 3.7's `functions.inc`.
//! `a` is `x, y, z, P0, ...`.

use std::f64::consts::{PI, TAU};

/// The cross-section norm of type `t`: (|u|^(2/t) + |v|^(2/t))^(t/2), so 1 is a circle, 2 a
/// diamond, 0 a square and larger values concave stars.
fn section_norm(u: f64, v: f64, t: f64) -> f64 {
    if t == 0.0 {
        return u.abs().max(v.abs());
    }
    let p = 2.0 / t;
    (u.abs().powf(p) + v.abs().powf(p)).powf(1.0 / p)
}

/// `angle` reduced by whole periods to the period centred on zero.
fn centred(angle: f64, period: f64) -> f64 {
    let shifted = angle + period / 2.0;
    shifted - period * (shifted / period).floor() - period / 2.0
}

/// P0 helices about y at radius P3, turning P1 radians per unit of y: the offset from the
/// radius and the height to the nearest turn (in units of 1/P1, stretched 1/P4 along y),
/// turned by P6 degrees, in the P5 norm, less the tube radius P2. The value is capped at
/// the distance ρ + P3 to the far side of the axis.
pub fn helix1(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (count, frequency, minor, major, shape, section, angle) =
        (a[3], a[4], a[5], a[6], a[7], a[8], a[9]);
    let rho = (x * x + z * z).sqrt();
    let turn = centred(z.atan2(x) - PI / count + frequency * y, TAU / count);
    let (u, v) = (rho - major, turn / frequency / shape);
    let (sin, cos) = angle.to_radians().sin_cos();
    let norm = section_norm(u * cos - v * sin, u * sin + v * cos, section);
    norm.min(rho + major) - minor
}

/// A single helix about y at radius P3, turning P1 radians per unit of y, measured in the
/// horizontal plane: the point turned back by P1·y, its offset from (P3, 0) in the P5 norm,
/// less the tube radius P2.
pub fn helix2(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (frequency, minor, major, section) = (a[4], a[5], a[6], a[8]);
    let (sin, cos) = (frequency * y).sin_cos();
    let along = x * cos + z * sin;
    let across = z * cos - x * sin;
    section_norm(along - major, across, section) - minor
}

/// A flat Archimedean spiral in the xz plane with windings P0 apart, thickness P1 in the P5
/// norm, inside the sphere of radius P2.
pub fn spiral(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (spacing, thickness, outer, section) = (a[3], a[4], a[5], a[8]);
    let rho = (x * x + z * z).sqrt();
    let along = rho + spacing * (-z).atan2(-x) / TAU;
    let offset = along - spacing * (along / spacing).round();
    let tube = section_norm(offset, y, section) - thickness;
    tube.max((x * x + y * y + z * z).sqrt() - outer)
}

/// A torus about y (major radius P0) carrying a winding of P1 loops that twist P2 turns
/// around the tube per loop: the nearer of the central tube (minor radius grown as P5
/// falls) and the winding centred P5 from the tube's axis (width set by P6), grooved
/// across by P7 grooves of depth P3, amplitude P8 and twist P9 per radian about y, the
/// whole capped by ρ + P0 − P5 and less the threshold P4.
pub fn helical_torus(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (major, loops, twist, depth, threshold, centre, width) =
        (a[3], a[4], a[5], a[6], a[7], a[8], a[9]);
    let (grooves, amplitude, groove_twist) = (a[10], a[11], a[12]);
    let rho = (x * x + z * z).sqrt();
    let u = rho - major;
    let d = (u * u + y * y).sqrt();
    let longitude = x.atan2(z);
    let phase = centred(loops * longitude + twist * u.atan2(y) + PI, TAU);
    let winding = ((d - centre).powi(2) + width * phase * phase).sqrt();
    let across = (amplitude * phase).atan2(d - centre);
    let groove = depth * (grooves * across + groove_twist * longitude).cos();
    ((d + centre).min(winding) - groove).min(rho + major - centre) - threshold
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn section_norms_are_povrays() {
        // POV-Ray 3.7 near an f_helix1 tube, 0.1 off in both directions: 0.1 for type 0,
        // 0.1414 for 1, 0.2 for 2, 0.2828 for 3.
        assert_eq!(section_norm(0.1, -0.1, 0.0), 0.1);
        assert!((section_norm(0.1, 0.1, 1.0) - 0.1 * 2f64.sqrt()).abs() < 1e-15);
        assert!((section_norm(0.1, 0.1, 2.0) - 0.2).abs() < 1e-15);
        assert!((section_norm(0.1, 0.1, 3.0) - 0.28284).abs() < 1e-5);
    }

    #[test]
    fn a_helix_without_frequency_is_capped_by_the_far_side() {
        // POV-Ray 3.7: f_helix1(-1, 0, 0, 1, 0, 0.1, 1, 1, 1, 0) = 1.9.
        let value = helix1(&[-1.0, 0.0, 0.0, 1.0, 0.0, 0.1, 1.0, 1.0, 1.0, 0.0]);
        assert!((value - 1.9).abs() < 1e-15);
    }
}
