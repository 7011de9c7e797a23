//! `media { }`: particles that absorb, emit and scatter light, inside objects (`interior`)
//! or filling the scene (atmospheric media).

use super::Pigment;
use glam::DVec3;

/// One `media { }` block with POV-Ray 3.7's defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct Media {
    /// `method` 1, 2 or 3.
    pub method: u8,
    pub intervals: u32,
    /// `samples min, max`; `None` leaves the renderer its default for the method.
    pub samples: Option<(u32, u32)>,
    pub confidence: f64,
    pub variance: f64,
    pub ratio: f64,
    pub jitter: f64,
    pub aa_level: u32,
    pub aa_threshold: f64,
    pub absorption: DVec3,
    pub emission: DVec3,
    pub scattering: Option<Scattering>,
    /// The `density { }` blocks, each a pigment whose colour at a point is the density
    /// there; several multiply. None means a constant density of 1.
    pub density: Vec<Pigment>,
    /// `collect off`: media photons are neither left in the media nor gathered there.
    pub collect: bool,
}

impl Default for Media {
    fn default() -> Self {
        Media {
            method: 3,
            intervals: 1,
            samples: None,
            confidence: 0.9,
            variance: 1.0 / 128.0,
            ratio: 0.9,
            jitter: 0.0,
            aa_level: 3,
            aa_threshold: 0.1,
            absorption: DVec3::ZERO,
            emission: DVec3::ZERO,
            scattering: None,
            density: Vec::new(),
            collect: true,
        }
    }
}

/// `scattering { type, colour [eccentricity e] [extinction x] }`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scattering {
    pub kind: ScatteringKind,
    pub colour: DVec3,
    pub extinction: f64,
}

/// The phase functions of scattering types 1 to 5.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ScatteringKind {
    Isotropic,
    MieHazy,
    MieMurky,
    Rayleigh,
    /// Henyey-Greenstein with its eccentricity.
    HenyeyGreenstein(f64),
}
