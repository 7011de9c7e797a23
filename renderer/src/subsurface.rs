//! Subsurface light transport (`finish { subsurface { translucency } }`): the dipole
//! diffusion model of Jensen, Marschner, Levoy and Hanrahan, "A Practical Model for
//! Subsurface Light Transport" (SIGGRAPH 2001). Light entering a translucent object at one
//! point leaves it at others, spread by the diffuse reflectance profile `R_d(r)` of a
//! semi-infinite medium: a real source one reduced mean free path under the surface and a
//! virtual one mirrored above it, placed so that the boundary condition of the refractive
//! interface holds.
//!
//! The material is described as POV-Ray's documentation does: the pigment is the total
//! diffuse reflectance `R_d` of a large flat piece (so that a big object looks as it would
//! with plain diffuse shading), `translucency` is the reduced scattering mean free path
//! `1/σ's` in millimetres (the marble of the paper, `σ's` = 2.19, 2.62, 3.00 /mm, is
//! `translucency <0.4566, 0.3817, 0.3333>`), `mm_per_unit` converts millimetres into scene
//! units, and the interior's `ior` sets the boundary. The reduced albedo `α'` follows from
//! the reflectance by inverting the paper's total diffuse reflectance
//! `R_d = α'/2 (1 + e^(-4/3 A √(3(1-α')))) e^(-√(3(1-α')))`, for a share of the pigment
//! calibrated against POV-Ray's pictures (see [`Boundary`]).
//!
//! Only the diffusion term is modelled: the paper's single-scattering term, which
//! POV-Ray's second `samples` count tunes, changes POV-Ray's pictures of back-lit slabs by
//! less than can be measured (the same to 1/255 with 1 or 50 samples).
//!
//! This module is the model alone: the profile, and the densities the tracer samples points
//! around a surface point by (see `tracer/subsurface.rs`).

use glam::DVec3;
use std::f64::consts::PI;

/// The most probe rays one shaded point may spend (`samples` of `global_settings`), so that
/// a scene asking for millions does not hang the render.
pub const MAX_SAMPLES: u32 = 4096;

/// `global_settings { subsurface { } }` as the tracer uses it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Probe rays per shaded point for the diffusion term.
    pub samples: u32,
    pub mm_per_unit: f64,
}

/// The dipole of one colour channel.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Dipole {
    /// The reduced albedo `α' = σ's / σ't`.
    albedo: f64,
    /// The effective transport coefficient `σtr = √(3 σa σ't)`, per scene unit.
    sigma_tr: f64,
    /// Depth of the real source, `1/σ't`.
    z_real: f64,
    /// Height of the virtual source above the surface.
    z_virtual: f64,
    /// The factor bringing the profile's total to the pigment (see [`Profile::new`]).
    scale: f64,
}

impl Dipole {
    fn new(reflectance: f64, free_path: f64, boundary: &Boundary) -> Dipole {
        let albedo = reduced_albedo(reflectance * boundary.share, boundary.a);
        let sigma_s = 1.0 / free_path;
        let sigma_t = sigma_s / albedo;
        let sigma_a = sigma_t - sigma_s;
        let z_real = 1.0 / sigma_t;
        Dipole {
            albedo,
            sigma_tr: (3.0 * sigma_a * sigma_t).sqrt(),
            z_real,
            z_virtual: z_real * (1.0 + 4.0 / 3.0 * boundary.a),
            scale: 1.0 / boundary.share,
        }
    }

    /// `R_d(r)`: the share of light entering at one point that leaves at distance `r`,
    /// per unit area.
    fn reflectance(&self, r2: f64) -> f64 {
        let pole = |z: f64| {
            let d = (r2 + z * z).sqrt();
            let sd = self.sigma_tr * d;
            z * (sd + 1.0) * (-sd).exp() / (d * d * d)
        };
        self.scale * self.albedo / (4.0 * PI) * (pole(self.z_real) + pole(self.z_virtual))
    }

    /// The density per unit area, around the point, of the two ways radii are drawn for
    /// this channel (each half of the time): `σtr² e^(-σtr r) / 2π`, the far falloff, and
    /// `z / (2π (r² + z²)^(3/2))`, the real source's peak near the point.
    fn area_density(&self, r2: f64) -> f64 {
        let r = r2.sqrt();
        let far = self.sigma_tr * self.sigma_tr * (-self.sigma_tr * r).exp();
        let z = self.z_real;
        let d2 = r2 + z * z;
        let near = z / (d2 * d2.sqrt());
        (far + near) / (4.0 * PI)
    }

    /// A radius drawn from [`Self::area_density`] by three numbers in 0..1.
    fn sample_radius(&self, pick: f64, u1: f64, u2: f64) -> f64 {
        if pick < 0.5 {
            // The radius of `σtr² r e^(-σtr r)`, a gamma distribution of shape 2: the sum of
            // two exponential distances.
            -((1.0 - u1) * (1.0 - u2)).ln() / self.sigma_tr
        } else {
            // The radius whose share within it is `1 - z/√(r² + z²)`.
            let s = 1.0 - u1;
            self.z_real * (1.0 / (s * s) - 1.0).max(0.0).sqrt()
        }
    }
}

/// The total diffuse reflectance of a semi-infinite medium of reduced albedo `α'` under
/// the boundary term `A` (equation 6 of Jensen et al. 2001 integrated over the plane).
fn total_reflectance(albedo: f64, boundary: f64) -> f64 {
    let s = (3.0 * (1.0 - albedo)).max(0.0).sqrt();
    0.5 * albedo * (1.0 + (-4.0 / 3.0 * boundary * s).exp()) * (-s).exp()
}

/// The reduced albedo whose total diffuse reflectance is `reflectance`, by bisection: the
/// reflectance grows with the albedo from 0 to 1.
fn reduced_albedo(reflectance: f64, boundary: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 1.0);
    for _ in 0..52 {
        let mid = 0.5 * (lo + hi);
        if total_reflectance(mid, boundary) < reflectance {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// What the interface between the medium and the air does to diffuse light.
struct Boundary {
    /// The boundary term `A = (1 + Fdr) / (1 - Fdr)`, with the diffuse Fresnel
    /// reflectance `Fdr` by the paper's fit for a relative index `η ≥ 1`.
    a: f64,
    /// `1 - Fdr/2`: the share of the pigment the dipole's albedo is found for; the profile
    /// is then scaled back up to the pigment. This calibration matches POV-Ray's pictures
    /// of slabs lit from behind, whose light falls off with their thickness faster than
    /// the plain inversion predicts, and faster the higher the index (measured at indices
    /// 1, 1.5 and 2, pigments 0.2 to 0.95 and slabs 0.5 to 8 free paths thick).
    share: f64,
}

impl Boundary {
    fn new(ior: f64) -> Boundary {
        let eta = ior.max(1.0);
        let fdr = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
        Boundary {
            a: (1.0 + fdr) / (1.0 - fdr),
            share: 1.0 - 0.5 * fdr,
        }
    }
}

/// The diffusion profile of a material in red, green and blue.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Profile {
    channels: [Dipole; 3],
    /// The distance beyond which the profile is taken as nothing: where even the longest
    /// channel's far falloff keeps only 0.1 % of its share.
    pub reach: f64,
}

/// The smallest and largest reflectance a channel is given: a black channel would need an
/// albedo of 0 and a white one an endless reach.
const REFLECTANCE_RANGE: (f64, f64) = (1e-3, 0.995);

impl Profile {
    /// The profile of a pigment colour (the total diffuse reflectance), a `translucency`
    /// (the reduced mean free path in millimetres) and an index of refraction, or `None`
    /// where some channel's free path is not positive: such a material shows plain diffuse
    /// light.
    pub fn new(
        pigment: DVec3,
        translucency: DVec3,
        ior: f64,
        settings: &Settings,
    ) -> Option<Profile> {
        let boundary = Boundary::new(ior);
        let mut channels = [Dipole {
            albedo: 0.0,
            sigma_tr: 0.0,
            z_real: 0.0,
            z_virtual: 0.0,
            scale: 1.0,
        }; 3];
        for (i, channel) in channels.iter_mut().enumerate() {
            let free_path = translucency[i] / settings.mm_per_unit;
            if !(free_path > 0.0 && free_path.is_finite()) {
                return None;
            }
            let reflectance = pigment[i].clamp(REFLECTANCE_RANGE.0, REFLECTANCE_RANGE.1);
            *channel = Dipole::new(reflectance, free_path, &boundary);
        }
        let slowest = channels
            .iter()
            .map(|c| c.sigma_tr)
            .fold(f64::INFINITY, f64::min);
        Some(Profile {
            channels,
            reach: 9.233 / slowest,
        })
    }

    /// `R_d` of each channel at squared distance `r2`.
    pub fn reflectance(&self, r2: f64) -> DVec3 {
        let [r, g, b] = self.channels.map(|c| c.reflectance(r2));
        DVec3::new(r, g, b)
    }

    /// The density per unit area at squared distance `r2` from the point of the radii
    /// [`Self::sample_radius`] draws: the mean of the channels' densities.
    pub fn area_density(&self, r2: f64) -> f64 {
        self.channels
            .iter()
            .map(|c| c.area_density(r2))
            .sum::<f64>()
            / 3.0
    }

    /// A radius: `pick` in 0..1 chooses the channel and its near or far way, `u1` and `u2`
    /// place it.
    pub fn sample_radius(&self, pick: f64, u1: f64, u2: f64) -> f64 {
        let scaled = (pick * 3.0).min(2.999_999);
        let channel = scaled as usize;
        self.channels[channel].sample_radius(scaled - channel as f64, u1, u2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const SETTINGS: Settings = Settings {
        samples: 50,
        mm_per_unit: 10.0,
    };

    /// `∫ f(r) 2πr dr` from 0 to `end` by the midpoint rule on a grid fine near 0.
    fn over_plane(f: impl Fn(f64) -> f64, end: f64) -> f64 {
        let n = 200_000;
        (0..n)
            .map(|i| {
                let (a, b) = (
                    end * (i as f64 / n as f64).powi(3),
                    end * ((i + 1) as f64 / n as f64).powi(3),
                );
                let r = 0.5 * (a + b);
                f(r) * 2.0 * PI * r * (b - a)
            })
            .sum()
    }

    #[test]
    fn the_paper_marble_reflects_its_measured_colour() {
        // Jensen et al.'s marble: σ's = 2.19, 2.62, 3.00 /mm and σa = 0.0021, 0.0041,
        // 0.0071 /mm, whose diffuse reflectance they give as 0.83, 0.79, 0.75.
        let boundary = Boundary::new(1.5).a;
        for (sigma_s, sigma_a, measured) in [
            (2.19, 0.0021, 0.83),
            (2.62, 0.0041, 0.79),
            (3.00, 0.0071, 0.75),
        ] {
            let albedo = sigma_s / (sigma_s + sigma_a);
            let r = total_reflectance(albedo, boundary);
            assert!((r - measured).abs() < 0.01, "{r} against {measured}");
            assert!((reduced_albedo(r, boundary) - albedo).abs() < 1e-9);
        }
    }

    #[test]
    fn the_profile_over_the_plane_is_the_pigment() {
        let pigment = DVec3::new(0.8, 0.5, 0.2);
        let profile = Profile::new(pigment, DVec3::new(1.0, 2.0, 0.5), 1.3, &SETTINGS).unwrap();
        for i in 0..3 {
            let total = over_plane(|r| profile.reflectance(r * r)[i], 4.0 * profile.reach);
            assert!((total - pigment[i]).abs() < 2e-3, "channel {i}: {total}");
        }
    }

    #[test]
    fn the_profile_keeps_nearly_everything_within_its_reach() {
        let pigment = DVec3::new(0.9, 0.6, 0.3);
        let profile = Profile::new(pigment, DVec3::splat(1.0), 1.5, &SETTINGS).unwrap();
        for i in 0..3 {
            let within = over_plane(|r| profile.reflectance(r * r)[i], profile.reach);
            assert!(within > 0.99 * pigment[i], "channel {i}: {within}");
        }
    }

    #[test]
    fn sampled_radii_follow_the_stated_density() {
        let profile =
            Profile::new(DVec3::new(0.8, 0.5, 0.3), DVec3::splat(1.0), 1.5, &SETTINGS).unwrap();
        let total = over_plane(|r| profile.area_density(r * r), 100.0 * profile.reach);
        assert!((total - 1.0).abs() < 1e-3, "{total}");
        // The share of radii drawn below a radius matches the density's.
        let limit = 0.1;
        let n = 60_000;
        let below = (0..n)
            .filter(|&i| {
                let u = |k: u64| {
                    let mut h = (i as u64) << 2 | k;
                    for _ in 0..2 {
                        h = (h ^ (h >> 31)).wrapping_mul(0x9e37_79b9_7f4a_7c15);
                    }
                    (h >> 11) as f64 / (1u64 << 53) as f64
                };
                let pick = (i as f64 + 0.5) / n as f64;
                profile.sample_radius(pick, u(1), u(2)) < limit
            })
            .count();
        let expected = over_plane(|r| profile.area_density(r * r), limit);
        let share = below as f64 / n as f64;
        assert!(
            (share - expected).abs() < 0.01,
            "{share} against {expected}"
        );
    }

    #[test]
    fn no_free_path_means_no_profile() {
        let pigment = DVec3::splat(0.5);
        assert!(Profile::new(pigment, DVec3::new(1.0, 0.0, 1.0), 1.5, &SETTINGS).is_none());
    }
}
