//! The classic algebraic surfaces of `functions.inc`: a polynomial in x, y and z, multiplied
//! by the field strength (the first parameter) and clamped to -10..10, which keeps the
//! gradient an isosurface sees bounded far from the surface. The polynomials are the
//! surfaces' published implicit equations, in the orientation, scale and sign POV-Ray 3.7
//! evaluates them (pinned down by sampling its `functions.inc`); `a` is `x, y, z, P0, ...`.

/// The field strength times a polynomial's value, clamped as POV-Ray clamps these surfaces.
fn field(strength: f64, value: f64) -> f64 {
    (strength * value).clamp(-10.0, 10.0)
}

fn sq(v: f64) -> f64 {
    v * v
}

/// The bicorn, revolved about y: y²(a² − r²) − (r² + 2ay − a²)² with r² = x² + z².
pub fn bicorn(a: &[f64]) -> f64 {
    let (y, s) = (a[1], a[4]);
    let r2 = a[0] * a[0] + a[2] * a[2];
    field(a[3], y * y * (s * s - r2) - sq(r2 + 2.0 * s * y - s * s))
}

/// The bifolia surface: a·y·(x² + z²) − (x² + y² + z²)².
pub fn bifolia(a: &[f64]) -> f64 {
    let (x, y, z, s) = (a[0], a[1], a[2], a[4]);
    field(a[3], s * y * (x * x + z * z) - sq(x * x + y * y + z * z))
}

/// Boy's surface, the degree-six immersion of the projective plane, its value times the
/// scale parameter.
pub fn boy_surface(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let r2 = x * x + y * y;
    let s2 = std::f64::consts::SQRT_2;
    let w = 1.0 - z;
    let value = 64.0 * w.powi(3) * z.powi(3) - 48.0 * w * w * z * z * (3.0 * r2 + 2.0 * z * z)
        + 12.0
            * w
            * z
            * (27.0 * r2 * r2 - 24.0 * z * z * r2
                + 36.0 * s2 * y * z * (y * y - 3.0 * x * x)
                + 4.0 * z.powi(4))
        + (9.0 * r2 - 2.0 * z * z)
            * (-81.0 * r2 * r2 - 72.0 * z * z * r2
                + 108.0 * s2 * x * z * (x * x - 3.0 * y * y)
                + 4.0 * z.powi(4));
    field(a[3], a[4] * value)
}

/// The crossed trough: x²z² − y.
pub fn crossed_trough(a: &[f64]) -> f64 {
    field(a[3], a[0] * a[0] * a[2] * a[2] - a[1])
}

/// The cubic saddle: z + y³ − x³.
pub fn cubic_saddle(a: &[f64]) -> f64 {
    field(a[3], a[2] + a[1].powi(3) - a[0].powi(3))
}

/// The cushion: z²x² − z⁴ − 2zx² + 2z³ + x² − z² − (x² − z)² − y⁴ − 2x²y² − y²z² + 2y²z + y².
/// `f_odd` evaluates the same polynomial in POV-Ray 3.7.
pub fn cushion(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (x2, y2, z2) = (x * x, y * y, z * z);
    let value = z2 * x2 - z2 * z2 - 2.0 * z * x2 + 2.0 * z2 * z + x2
        - z2
        - sq(x2 - z)
        - y2 * y2
        - 2.0 * x2 * y2
        - y2 * z2
        + 2.0 * y2 * z
        + y2;
    field(a[3], value)
}

/// The devil's curve swept along z: y⁴ − 0.25y² − (x² + z²)² + 0.36x².
pub fn devils_curve(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    field(
        a[3],
        y.powi(4) - 0.25 * y * y - sq(x * x + z * z) + 0.36 * x * x,
    )
}

/// The Dupin cyclid: the torus (major radius P1, minor P2, displaced by P3 along x and P4
/// along y) inverted in the sphere of radius P5, cleared of denominators. POV-Ray's
/// expansion gives the y displacement the opposite sign in the torus's middle term, which
/// is kept so that the surface is POV-Ray's.
pub fn dupin_cyclid(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (major, minor, dx, dy, k) = (a[4], a[5], a[6], a[7], a[8]);
    let s = x * x + y * y + z * z;
    let c = major * major - minor * minor;
    let k2 = k * k;
    let d2 = dx * dx + dy * dy;
    let inverted = k2 * k2 - 2.0 * k2 * (dx * x + dy * y) + d2 * s;
    let middle = k2 * k2 - 2.0 * k2 * (dx * x - dy * y) + d2 * s;
    let (px, pz) = (k2 * x - dx * s, k2 * z);
    let value = -(inverted * inverted + 2.0 * c * s * middle + c * c * s * s)
        + 4.0 * major * major * (px * px + pz * pz);
    field(a[3], value)
}

/// Enneper's minimal surface in its implicit form −(A³ − 6B²) with A = (y² − x²)/2z +
/// 2z²/9 and B = (y² − x²)/4z; POV-Ray keeps |z| at least 0.2 in the denominators.
pub fn enneper(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let denominator = if z.abs() < 0.2 { 0.2 } else { z };
    let d = y * y - x * x;
    let big_a = d / (2.0 * denominator) + 2.0 / 9.0 * z * z;
    let big_b = d / (4.0 * denominator);
    field(a[3], -(big_a.powi(3) - 6.0 * big_b * big_b))
}

/// The folium surface about x: (y² + z²)(1 + (b − 4a)x) + (b + 1)x², a the neck width and
/// b the divergence.
pub fn folium_surface(a: &[f64]) -> f64 {
    let (x, neck, divergence) = (a[0], a[4], a[5]);
    let r2 = a[1] * a[1] + a[2] * a[2];
    field(
        a[3],
        r2 * (1.0 + (divergence - 4.0 * neck) * x) + (divergence + 1.0) * x * x,
    )
}

/// The glob: 0.5x⁵ + 0.5x⁴ − y² − z².
pub fn glob(a: &[f64]) -> f64 {
    let x = a[0];
    field(
        a[3],
        0.5 * x.powi(5) + 0.5 * x.powi(4) - a[1] * a[1] - a[2] * a[2],
    )
}

/// The heart: y²z³ + 0.1x²z³ − (2x² + y² + z² − 1)³.
pub fn heart(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let z3 = z.powi(3);
    field(
        a[3],
        y * y * z3 + 0.1 * x * x * z3 - (2.0 * x * x + y * y + z * z - 1.0).powi(3),
    )
}

/// Hunt's surface: −(4(x² + y² + z² − 13)³ + 27(3x² + y² − 4z² − 12)²).
pub fn hunt_surface(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let value = 4.0 * (x * x + y * y + z * z - 13.0).powi(3)
        + 27.0 * sq(3.0 * x * x + y * y - 4.0 * z * z - 12.0);
    field(a[3], -value)
}

/// The hyperbolic torus: −((x² + y² − z² + R² − r²)² − 4R²(x² − z²)).
pub fn hyperbolic_torus(a: &[f64]) -> f64 {
    let (x, y, z, major, minor) = (a[0], a[1], a[2], a[4], a[5]);
    let q = x * x + y * y - z * z + major * major - minor * minor;
    field(a[3], -(q * q - 4.0 * major * major * (x * x - z * z)))
}

/// The kampyle of Eudoxus about x: b²x⁴ − a²b²x² − y² − z², a the dimple and b the
/// closeness.
pub fn kampyle_of_eudoxus(a: &[f64]) -> f64 {
    let (x, dimple, closeness) = (a[0], a[4], a[5]);
    let b2 = closeness * closeness;
    field(
        a[3],
        b2 * x.powi(4) - dimple * dimple * b2 * x * x - a[1] * a[1] - a[2] * a[2],
    )
}

/// The figure-eight Klein bottle: −((S + 2y − 1)((S − 2y − 1)² − 8z²) + 16xz(S − 2y − 1))
/// with S = x² + y² + z².
pub fn klein_bottle(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let s = x * x + y * y + z * z;
    let value = (s + 2.0 * y - 1.0) * (sq(s - 2.0 * y - 1.0) - 8.0 * z * z)
        + 16.0 * x * z * (s - 2.0 * y - 1.0);
    field(a[3], -value)
}

/// A Kummer-type quartic of radiating rods: S − 1 − (x⁴ + y⁴ + z⁴) + x²y² + x²z² + y²z².
pub fn kummer_surface_v1(a: &[f64]) -> f64 {
    let (x2, y2, z2) = (a[0] * a[0], a[1] * a[1], a[2] * a[2]);
    let value = x2 + y2 + z2 - 1.0 - (x2 * x2 + y2 * y2 + z2 * z2) + x2 * y2 + x2 * z2 + y2 * z2;
    field(a[3], value)
}

/// The second Kummer-type quartic: 1 − aS − c·xyz − (x⁴ + y⁴ + z⁴) − b(x²y² + x²z² + y²z²).
pub fn kummer_surface_v2(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (rod, divergence, length) = (a[4], a[5], a[6]);
    let (x2, y2, z2) = (x * x, y * y, z * z);
    let value = 1.0
        - rod * (x2 + y2 + z2)
        - length * x * y * z
        - (x2 * x2 + y2 * y2 + z2 * z2)
        - divergence * (x2 * y2 + x2 * z2 + y2 * z2);
    field(a[3], value)
}

/// The lemniscate of Gerono revolved about x: x² − x⁴ − y² − z².
pub fn lemniscate_of_gerono(a: &[f64]) -> f64 {
    let x = a[0];
    field(a[3], x * x - x.powi(4) - a[1] * a[1] - a[2] * a[2])
}

/// The mitre: y² − y²z² − y⁴ − 4x²(x² + y² + z²).
pub fn mitre(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let y2 = y * y;
    field(
        a[3],
        y2 - y2 * z * z - y2 * y2 - 4.0 * x * x * (x * x + y2 + z * z),
    )
}

/// The nodal cubic: 6yz − y³ − z³.
pub fn nodal_cubic(a: &[f64]) -> f64 {
    let (y, z) = (a[1], a[2]);
    field(a[3], 6.0 * y * z - y.powi(3) - z.powi(3))
}

/// The ovals of Cassini revolved about y: −((S + a²)² − c·a²(x² + z²) − b²), a the major
/// radius, b the filling and c the thickness.
pub fn ovals_of_cassini(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (major, filling, thickness) = (a[4], a[5], a[6]);
    let m2 = major * major;
    let s = x * x + y * y + z * z;
    field(
        a[3],
        -(sq(s + m2) - thickness * m2 * (x * x + z * z) - filling * filling),
    )
}

/// The paraboloid about y: y − x² − z².
pub fn paraboloid(a: &[f64]) -> f64 {
    field(a[3], a[1] - a[0] * a[0] - a[2] * a[2])
}

/// The parabolic torus: a torus whose x² + y² is tilted by −z, in POV-Ray's expansion
/// −(q² + c(x² + y²) − 2R²x² + (R² + r²)z + c²) with q = x² + y² − z and c = R² − r².
pub fn parabolic_torus(a: &[f64]) -> f64 {
    let (x, y, z, major, minor) = (a[0], a[1], a[2], a[4], a[5]);
    let (big, small) = (major * major, minor * minor);
    let c = big - small;
    let q = x * x + y * y - z;
    field(
        a[3],
        -(q * q + c * (x * x + y * y) - 2.0 * big * x * x + (big + small) * z + c * c),
    )
}

/// The pillow: x⁴ + y⁴ + z⁴ − x² − y² − z².
pub fn pillow(a: &[f64]) -> f64 {
    let (x2, y2, z2) = (a[0] * a[0], a[1] * a[1], a[2] * a[2]);
    field(a[3], x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2)
}

/// The piriform revolved about x: x⁴ − x³ + y² + z².
pub fn piriform(a: &[f64]) -> f64 {
    let x = a[0];
    field(a[3], x.powi(4) - x.powi(3) + a[1] * a[1] + a[2] * a[2])
}

/// The quartic paraboloid: y − x⁴ − z⁴.
pub fn quartic_paraboloid(a: &[f64]) -> f64 {
    field(a[3], a[1] - a[0].powi(4) - a[2].powi(4))
}

/// The quartic saddle: y + z⁴ − x⁴.
pub fn quartic_saddle(a: &[f64]) -> f64 {
    field(a[3], a[1] + a[2].powi(4) - a[0].powi(4))
}

/// The quartic cylinder about y: a²b² − (b² + y²)(x² + z²), a the egg's diameter and b the
/// tube's width.
pub fn quartic_cylinder(a: &[f64]) -> f64 {
    let (y, diameter, width) = (a[1], a[4], a[5]);
    let w2 = width * width;
    let r2 = a[0] * a[0] + a[2] * a[2];
    field(a[3], diameter * diameter * w2 - (w2 + y * y) * r2)
}

/// Steiner's Roman surface: −(x²y² + x²z² + y²z² + xyz).
pub fn steiners_roman(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (x2, y2, z2) = (x * x, y * y, z * z);
    field(a[3], -(x2 * y2 + x2 * z2 + y2 * z2 + x * y * z))
}

/// The strophoid revolved about x: x(y² + z²) + c²x³ + a·c²x² − b(y² + z²), a the bulb's
/// size, b the sharpness and c the flatness.
pub fn strophoid(a: &[f64]) -> f64 {
    let x = a[0];
    let (size, sharpness, flatness) = (a[4], a[5], a[6]);
    let r2 = a[1] * a[1] + a[2] * a[2];
    let c2 = flatness * flatness;
    field(
        a[3],
        x * r2 + c2 * x.powi(3) + size * c2 * x * x - sharpness * r2,
    )
}

/// The torus about y as a quartic: −((S + R² − r²)² − 4R²(x² + z²)).
pub fn torus2(a: &[f64]) -> f64 {
    let (x, y, z, major, minor) = (a[0], a[1], a[2], a[4], a[5]);
    let s = x * x + y * y + z * z;
    field(
        a[3],
        -(sq(s + major * major - minor * minor) - 4.0 * major * major * (x * x + z * z)),
    )
}

/// The torus gumdrop: 20S − 17 − 4(x⁴ + y⁴ + z⁴ + 2y²z²) − 17x²(y² + z²).
pub fn torus_gumdrop(a: &[f64]) -> f64 {
    let (x2, y2, z2) = (a[0] * a[0], a[1] * a[1], a[2] * a[2]);
    let value = 20.0 * (x2 + y2 + z2)
        - 17.0
        - 4.0 * (x2 * x2 + y2 * y2 + z2 * z2 + 2.0 * y2 * z2)
        - 17.0 * x2 * (y2 + z2);
    field(a[3], value)
}

/// The umbrella (Whitney's umbrella): yz² − x².
pub fn umbrella(a: &[f64]) -> f64 {
    field(a[3], a[1] * a[2] * a[2] - a[0] * a[0])
}

/// The witch of Agnesi revolved about y: a(1 − y) − y(x² + z²).
pub fn witch_of_agnesi(a: &[f64]) -> f64 {
    let (y, width) = (a[1], a[4]);
    field(a[3], width * (1.0 - y) - y * (a[0] * a[0] + a[2] * a[2]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn field_strength_scales_then_clamps_to_ten() {
        // POV-Ray 3.7: f_bicorn(0, -2, 0, P0, 1) is -2.1 for P0 = 0.1 and -10 for 0.5 and
        // 100 (the polynomial is -21 there).
        assert!((bicorn(&[0.0, -2.0, 0.0, 0.1, 1.0]) + 2.1).abs() < 1e-12);
        assert_eq!(bicorn(&[0.0, -2.0, 0.0, 0.5, 1.0]), -10.0);
        assert_eq!(bicorn(&[0.0, -2.0, 0.0, -100.0, 1.0]), 10.0);
    }

    #[test]
    fn enneper_keeps_small_z_out_of_the_denominator() {
        // POV-Ray 3.7 at (0.3, 0.1, z): 0.068 at z = 0, 0.067075430684433 at z = -0.19
        // (both divide by 0.2) and 0.050885223593964 at z = -0.2.
        assert!((enneper(&[0.3, 0.1, 0.0, 1.0]) - 0.068).abs() < 1e-15);
        assert!((enneper(&[0.3, 0.1, -0.19, 1.0]) - 0.067075430684433).abs() < 1e-14);
        assert!((enneper(&[0.3, 0.1, -0.2, 1.0]) - 0.050885223593964).abs() < 1e-14);
    }

    #[test]
    fn dupin_cyclid_matches_povray_with_both_displacements() {
        // Sampled from POV-Ray 3.7: f_dupin_cyclid(x, y, z, 1, 1, 0.5, 0.3, 0.2, 1.5).
        let point = [0.7606349359997449, 0.03394253197726971, -1.0067936815511849];
        let args = [point[0], point[1], point[2], 1.0, 1.0, 0.5, 0.3, 0.2, 1.5];
        assert!((dupin_cyclid(&args) + 2.7728945446880324).abs() < 1e-12);
    }
}
