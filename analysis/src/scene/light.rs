use super::{Colour, LightPhotons, Object, Origin};
use glam::DVec3;

#[derive(Debug, Clone, PartialEq)]
pub enum LightKind {
    Point,
    Spotlight {
        point_at: DVec3,
        radius: f64,
        falloff: f64,
        tightness: f64,
    },
    Cylinder {
        point_at: DVec3,
        radius: f64,
        falloff: f64,
        tightness: f64,
    },
    Parallel {
        point_at: DVec3,
    },
}

/// `area_light axis1, axis2, size1, size2` with its options.
#[derive(Debug, Clone, PartialEq)]
pub struct AreaLight {
    pub axis1: DVec3,
    pub axis2: DVec3,
    pub size1: u32,
    pub size2: u32,
    pub adaptive: u32,
    pub jitter: bool,
    pub circular: bool,
    pub orient: bool,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Light {
    pub kind: LightKind,
    pub position: DVec3,
    pub colour: Colour,
    pub shadowless: bool,
    pub area: Option<AreaLight>,
    pub fade_distance: Option<f64>,
    pub fade_power: f64,
    pub media_interaction: bool,
    pub media_attenuation: bool,
    pub looks_like: Option<Box<Object>>,
    pub projected_through: Option<Box<Object>>,
    pub photons: LightPhotons,
    pub origin: Origin,
}

impl Light {
    pub fn point(position: DVec3, colour: Colour) -> Light {
        Light {
            kind: LightKind::Point,
            position,
            colour,
            shadowless: false,
            area: None,
            fade_distance: None,
            fade_power: 0.0,
            media_interaction: true,
            media_attenuation: false,
            looks_like: None,
            projected_through: None,
            photons: LightPhotons::default(),
            origin: None,
        }
    }
}

/// `light_group { }`: objects lit by the group's own lights, and by the scene's other lights
/// only with `global_lights`. It is a union of its objects otherwise.
#[derive(Debug, Clone, PartialEq)]
pub struct LightGroup {
    pub objects: Vec<Object>,
    pub lights: Vec<Light>,
    pub global_lights: bool,
}
