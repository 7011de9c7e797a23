//! What fills the space around the objects and lies beyond them: `fog`, `rainbow` and
//! `sky_sphere`. Atmospheric `media` is described with the other media in [`super::Media`].

use super::{BlendMap, Colour, Pigment, Transform, Turbulence};
use glam::DVec3;

/// `fog { }`, with POV-Ray's defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct Fog {
    /// `fog_type 2`: a fog thinning out above `fog_offset`.
    pub ground: Option<GroundFog>,
    /// The depth at which 63 % of the fog's colour shows; 0 turns the fog off.
    pub distance: f64,
    pub colour: Colour,
    pub turbulence: Option<Turbulence>,
    pub turb_depth: f64,
    /// Rotates the `up` vector and places the turbulence.
    pub transform: Transform,
}

impl Default for Fog {
    fn default() -> Self {
        Fog {
            ground: None,
            distance: 0.0,
            colour: Colour::BLACK,
            turbulence: None,
            turb_depth: 0.5,
            transform: Transform::IDENTITY,
        }
    }
}

/// The extra parameters of `fog_type 2`.
#[derive(Debug, Clone, PartialEq)]
pub struct GroundFog {
    pub offset: f64,
    pub alt: f64,
    /// The direction heights are measured along, before the fog's transform.
    pub up: DVec3,
}

/// `rainbow { }`: a fog-like coloured arc around `direction`.
#[derive(Debug, Clone, PartialEq)]
pub struct Rainbow {
    pub direction: DVec3,
    /// The angle in degrees between `direction` and the middle of the bow.
    pub angle: f64,
    /// The bow's width in degrees.
    pub width: f64,
    pub distance: f64,
    pub jitter: f64,
    pub colour_map: BlendMap<Colour>,
    /// Where the arc's angle is zero.
    pub up: DVec3,
    /// Degrees of the arc shown, and of its part shown at full strength.
    pub arc_angle: f64,
    pub falloff_angle: f64,
}

impl Default for Rainbow {
    fn default() -> Self {
        Rainbow {
            direction: DVec3::Z,
            angle: 0.0,
            width: 0.0,
            distance: 1e7,
            jitter: 0.0,
            colour_map: BlendMap {
                entries: Vec::new(),
            },
            up: DVec3::Y,
            arc_angle: 180.0,
            falloff_angle: 180.0,
        }
    }
}

/// `sky_sphere { }`: pigments layered on the sphere at infinity, the first at the bottom.
#[derive(Debug, Clone, PartialEq)]
pub struct SkySphere {
    pub pigments: Vec<Pigment>,
    /// Scales the sky's own colour (3.7's `emission`).
    pub emission: DVec3,
    pub transform: Transform,
}

impl Default for SkySphere {
    fn default() -> Self {
        SkySphere {
            pigments: Vec::new(),
            emission: DVec3::ONE,
            transform: Transform::IDENTITY,
        }
    }
}
