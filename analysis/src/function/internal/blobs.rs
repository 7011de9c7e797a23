//! Field functions: sums of blob-like falloffs around points and axes, which make smooth
//! surfaces at a threshold. The falloffs and their combinations were pinned down by sampling
//! POV-Ray 3.7's `functions.inc`; `a` is `x, y, z, P0, ...`.

/// Two blob components, at x = ∓P0/2, each `strength·(1 − (k·d)²)²` inside its radius 1/k
/// and zero outside, negated so that the inside is below the threshold.
pub fn blob(a: &[f64]) -> f64 {
    let (x, y, z, separation) = (a[0], a[1], a[2], a[3]);
    let component = |centre: f64, strength: f64, inverse_radius: f64| {
        let d2 = ((x - centre).powi(2) + y * y + z * z) * inverse_radius * inverse_radius;
        if d2 < 1.0 {
            strength * (1.0 - d2).powi(2)
        } else {
            0.0
        }
    };
    -(component(-separation / 2.0, a[4], a[5]) + component(separation / 2.0, a[6], a[7]))
}

/// Two Gaussian blobs, at the origin and at x = P0: P3 − P2·(e^(−P1·d₁²) + e^(−P1·d₂²)).
pub fn blob2(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (separation, inverse_size, strength, threshold) = (a[3], a[4], a[5], a[6]);
    let near = x * x + y * y + z * z;
    let far = (x - separation).powi(2) + y * y + z * z;
    threshold - strength * ((-inverse_size * near).exp() + (-inverse_size * far).exp())
}

/// The quadratic form of the ellipsoid along each axis: the coordinate along the axis
/// squared plus `eccentricity` times the squared distance from the axis.
fn axial_forms(x: f64, y: f64, z: f64, eccentricity: f64) -> [f64; 3] {
    let (x2, y2, z2) = (x * x, y * y, z * z);
    [
        x2 + eccentricity * (y2 + z2),
        y2 + eccentricity * (x2 + z2),
        z2 + eccentricity * (x2 + y2),
    ]
}

/// The three axial Gaussian ellipsoids' values at inverse size `k`.
fn axial_gaussians(x: f64, y: f64, z: f64, eccentricity: f64, k: f64) -> [f64; 3] {
    axial_forms(x, y, z, eccentricity).map(|form| (-k * form).exp())
}

/// The union of three crossed Gaussian ellipsoids: P3 − P2·(the largest Gaussian).
pub fn cross_ellipsoids(a: &[f64]) -> f64 {
    let [gx, gy, gz] = axial_gaussians(a[0], a[1], a[2], a[3], a[4]);
    a[6] - a[5] * gx.max(gy).max(gz)
}

/// The intersection of three crossed Gaussian ellipsoids: P3 − P2·(the smallest Gaussian).
pub fn isect_ellipsoids(a: &[f64]) -> f64 {
    let [gx, gy, gz] = axial_gaussians(a[0], a[1], a[2], a[3], a[4]);
    a[6] - a[5] * gx.min(gy).min(gz)
}

/// The sum of the three axial Gaussian ellipsoids at inverse size `k`.
fn axial_sum(x: f64, y: f64, z: f64, eccentricity: f64, k: f64) -> f64 {
    axial_gaussians(x, y, z, eccentricity, k).iter().sum()
}

/// The flange cover: three crossed Gaussian ellipsoids summed, P3 − P2·Σ e^(−P1·form).
pub fn flange_cover(a: &[f64]) -> f64 {
    a[6] - a[5] * axial_sum(a[0], a[1], a[2], a[3], a[4])
}

/// Spikes: the three axial Gaussians less a central one, P2·(Σ e^(−P1·form) −
/// P4·e^(−P3·r²)).
pub fn spikes(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let r2 = x * x + y * y + z * z;
    a[5] * (axial_sum(x, y, z, a[3], a[4]) - a[7] * (-a[6] * r2).exp())
}

/// A field of spikes over the xz plane: y − h·cos(fx·x)·cos(fz·z)·e^(−rate·(x² + z²)).
pub fn spikes_2d(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let (height, fx, fz, rate) = (a[3], a[4], a[5], a[6]);
    y - height * (fx * x).cos() * (fz * z).cos() * (-rate * (x * x + z * z)).exp()
}

/// A d orbital's density cloud: 1.2 − 1.6·(3y² − r²)²·e^(−1.33333332·r). The decay constant
/// is POV-Ray's, 4/3 to eight places.
pub fn quantum(a: &[f64]) -> f64 {
    let (x, y, z) = (a[0], a[1], a[2]);
    let r2 = x * x + y * y + z * z;
    1.2 - 1.6 * (3.0 * y * y - r2).powi(2) * (-1.333_333_32 * r2.sqrt()).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn blob_is_negative_zero_outside_both_components() {
        // POV-Ray 3.7 prints -0.000000000 there.
        let value = blob(&[1.5, -0.6, -0.25, 1.0, 0.5, 0.8, 0.3, 1.2]);
        assert_eq!(value, 0.0);
        assert!(value.is_sign_negative());
    }

    #[test]
    fn the_axial_falloffs_are_povrays() {
        // POV-Ray 3.7 at (1, 0, 0): f_flange_cover(0.5, 1, 1, 0) = -1.58094 (e^-1 + 2e^-0.5)
        // and f_spikes(1, 1, 1, 1, 1) = 0.73576 (2e^-1).
        let flange = flange_cover(&[1.0, 0.0, 0.0, 0.5, 1.0, 1.0, 0.0]);
        assert!((flange + (-1.0f64).exp() + 2.0 * (-0.5f64).exp()).abs() < 1e-12);
        let spike = spikes(&[1.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0]);
        assert!((spike - 2.0 * (-1.0f64).exp()).abs() < 1e-12);
    }

    #[test]
    fn crossed_ellipsoids_pick_among_the_gaussians() {
        // Sampled from POV-Ray 3.7 with a negative inverse size, where the largest
        // Gaussian belongs to the largest quadratic form.
        let args = [
            2.528892281023219,
            -1.209515792974764,
            -0.22076504600039648,
            -2.624078085713907,
            -1.0,
            2.23776224100979,
            -2.0,
        ];
        assert!((cross_ellipsoids(&args) + 27.382090002995223).abs() < 1e-9);
    }
}
