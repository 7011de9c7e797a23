//! Photon mapping settings, with POV-Ray 3.7's defaults: the `photons { }` block of
//! `global_settings` (how densely photons are shot and how they are gathered), of an
//! object (whether photons are aimed at it, and what it does with photons that reach it)
//! and of a light source (which photons it shoots).

use super::Origin;

/// How many photons to shoot: a distance between photons on the targets, or a total
/// from which that distance is worked out.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PhotonDensity {
    Spacing(f64),
    Count(u32),
}

/// `photons { }` in `global_settings`.
#[derive(Debug, Clone, PartialEq)]
pub struct Photons {
    pub density: PhotonDensity,
    /// `gather min, max`: the fewest photons an estimate wants before widening its search,
    /// and the most it uses.
    pub gather_min: u32,
    pub gather_max: u32,
    /// `jitter`: how far each photon's direction strays from its place in the spiral, as a
    /// fraction of the spacing.
    pub jitter: f64,
    /// `max_trace_level` and `adc_bailout` of the photon pass; `None` takes the scene's.
    pub max_trace_level: Option<u32>,
    pub adc_bailout: Option<f64>,
    /// `autostop`: the fraction of a target's bounding circle the spiral covers before a
    /// whole turn without hitting the target stops it.
    pub autostop: f64,
    /// `expand_thresholds`: a widened search is discarded when it raises the density by
    /// more than `expand_increase`, unless it found fewer than `expand_min` photons.
    pub expand_increase: f64,
    pub expand_min: u32,
    /// `radius`: the gather radius (`None` lets the renderer estimate it from the map) and
    /// the factor applied to it.
    pub radius: Option<f64>,
    pub radius_multiplier: f64,
    /// `media max_steps [, factor]`: photons are also left in scattering media.
    pub media: Option<MediaPhotons>,
    /// The gather radius in media (`None` takes the surfaces' radius) and its factor.
    pub media_radius: Option<f64>,
    pub media_radius_multiplier: f64,
    pub origin: Origin,
}

/// `media max_steps, factor` in the global photons block: photons that cross scattering
/// media after a reflection or refraction leave photons along the way, `factor` times the
/// surface spacing apart, at most `max_steps` per stretch of media.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MediaPhotons {
    pub max_steps: u32,
    pub factor: f64,
}

impl Default for Photons {
    fn default() -> Self {
        Photons {
            // POV-Ray shoots at spacing 1 when the block gives neither spacing nor count.
            density: PhotonDensity::Spacing(1.0),
            gather_min: 20,
            gather_max: 100,
            jitter: 0.4,
            max_trace_level: None,
            adc_bailout: None,
            autostop: 0.0,
            expand_increase: 0.2,
            expand_min: 40,
            radius: None,
            radius_multiplier: 1.0,
            media: None,
            media_radius: None,
            media_radius_multiplier: 1.0,
            origin: None,
        }
    }
}

/// `photons { }` in an object.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObjectPhotons {
    /// `target [multiplier]`: photons are aimed at the object, at the global spacing times
    /// the multiplier.
    pub target: Option<f64>,
    /// Whether photons go on through the surface, and off it: `None` when the block does
    /// not say, which leaves it to the light (see [`photons_interact`]).
    pub refraction: Option<bool>,
    pub reflection: Option<bool>,
    /// Whether photons that reach the surface after a reflection or refraction are kept
    /// there and light it.
    pub collect: bool,
    /// Photons on their way to a target go through the object untouched; `None` follows
    /// `no_shadow`, as POV-Ray does.
    pub pass_through: Option<bool>,
    /// A union target is shot at part by part.
    pub split_union: bool,
}

impl Default for ObjectPhotons {
    fn default() -> Self {
        ObjectPhotons {
            target: None,
            refraction: None,
            reflection: None,
            collect: true,
            pass_through: None,
            split_union: true,
        }
    }
}

/// `photons { }` in a light source: which photons it shoots. `None` when the block does
/// not say, which leaves it to each object (see [`photons_interact`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LightPhotons {
    pub refraction: Option<bool>,
    pub reflection: Option<bool>,
    /// Photons leave from the points of the area light's grid instead of its centre.
    pub area_light: bool,
}

impl LightPhotons {
    /// Whether the light may shoot photons at all: not both kinds turned off.
    pub fn shoots(&self) -> bool {
        self.refraction != Some(false) || self.reflection != Some(false)
    }
}

/// Whether photons from a light refract (or reflect) at an object, from the object's and
/// the light's settings for that kind: an `off` on either side stops them, otherwise an
/// `on` on either side lets them, and nothing said means no. POV-Ray 3.7's renders show
/// this: a target without `refraction` refracts the photons of a light with
/// `refraction on`, and a mirror with no photons block reflects a `reflection on` light's.
pub fn photons_interact(object: Option<bool>, light: Option<bool>) -> bool {
    match (object, light) {
        (Some(false), _) | (_, Some(false)) => false,
        (object, light) => object == Some(true) || light == Some(true),
    }
}
