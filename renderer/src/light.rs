//! Light sources at run time: where light comes from for a surface point, how strong it is
//! there, and whether its shadows are traced.

use analysis::scene::{self, LightKind};
use glam::DVec3;

#[derive(Debug, Clone)]
pub struct Light {
    pub position: DVec3,
    pub colour: DVec3,
    pub shadowless: bool,
    fade: Option<(f64, f64)>,
}

/// Light arriving at a point from one source, before shadows.
#[derive(Debug, Clone, Copy)]
pub struct Incoming {
    /// Unit vector from the point towards the light.
    pub direction: DVec3,
    pub distance: f64,
    pub colour: DVec3,
}

impl Light {
    pub fn from_scene(light: &scene::Light) -> Result<Light, String> {
        match light.kind {
            LightKind::Point => {}
            LightKind::Spotlight { .. } => return Err("not supported yet: spotlight".into()),
            LightKind::Cylinder { .. } => return Err("not supported yet: cylinder light".into()),
            LightKind::Parallel { .. } => return Err("not supported yet: parallel light".into()),
        }
        if light.area.is_some() {
            return Err("not supported yet: area_light".into());
        }
        if light.looks_like.is_some() {
            return Err("not supported yet: looks_like".into());
        }
        if light.projected_through.is_some() {
            return Err("not supported yet: projected_through".into());
        }
        Ok(Light {
            position: light.position,
            colour: light.colour.rgb,
            shadowless: light.shadowless,
            fade: light
                .fade_distance
                .filter(|d| *d > 0.0 && light.fade_power > 0.0)
                .map(|d| (d, light.fade_power)),
        })
    }

    /// The light reaching `point`, or `None` when none can (the point is at the light).
    pub fn incoming(&self, point: DVec3) -> Option<Incoming> {
        let to_light = self.position - point;
        let distance = to_light.length();
        if !(distance > 0.0 && distance.is_finite()) {
            return None;
        }
        let mut colour = self.colour;
        if let Some((fade_distance, fade_power)) = self.fade {
            // POV-Ray's attenuation: 2 / (1 + (d / fade_distance)^fade_power).
            colour *= 2.0 / (1.0 + (distance / fade_distance).powf(fade_power));
        }
        Some(Incoming {
            direction: to_light / distance,
            distance,
            colour,
        })
    }
}
