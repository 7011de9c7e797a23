//! Light sources at run time: where light comes from for a surface point and how strong it
//! is there before shadows, following POV-Ray's attenuation rules: the spotlight's cone
//! (`radius`, `falloff` and `tightness` on the cosine of the angle), the cylinder light's
//! tube, parallel lights' fixed direction, and `fade_distance`/`fade_power`. Area lights
//! carry their grid for the shadow sampler; lights projected through an object carry the
//! object.

use crate::object::Object;
use analysis::scene::{self, LightKind, LightPhotons};
use glam::DVec3;

#[derive(Debug, Clone)]
pub struct Light {
    pub position: DVec3,
    pub colour: DVec3,
    /// Fill lights: no shadows, no highlights.
    pub shadowless: bool,
    /// Whether media scatter this light: not a shadowless one, which POV-Ray 3.7's
    /// renders show leaving media dark (`media_interaction` on or not).
    pub media_interaction: bool,
    /// Whether fog and atmospheric media dim this light on its way.
    pub media_attenuation: bool,
    kind: Kind,
    /// `(fade_distance, fade_power)` when fading is on.
    fade: Option<(f64, f64)>,
    pub area: Option<AreaGrid>,
    /// The object the light shines through (`projected_through`), set by the world's
    /// builder: the light reaches only the points whose rays to it cross the object.
    pub projected_through: Option<Object>,
    /// Which photons the light shoots.
    pub photons: LightPhotons,
    /// Whether its light reaches every point whole, before the surface's lighting: nothing
    /// in the world can shadow, filter or dim it (see [`Light::arrives_whole_in`]).
    pub arrives_whole: bool,
}

#[derive(Debug, Clone, Copy)]
enum Kind {
    Point,
    /// `direction` from the light towards `point_at`; angles as cosines.
    Spot {
        direction: DVec3,
        cos_radius: f64,
        cos_falloff: f64,
        tightness: f64,
    },
    Cylinder {
        direction: DVec3,
        radius: f64,
        falloff: f64,
        tightness: f64,
    },
    /// Light arriving along `-direction` everywhere.
    Parallel {
        direction: DVec3,
    },
}

/// An area light's grid of point lights spread over `axis1` × `axis2`.
#[derive(Debug, Clone, Copy)]
pub struct AreaGrid {
    pub axis1: DVec3,
    pub axis2: DVec3,
    pub size1: u32,
    pub size2: u32,
    pub adaptive: u32,
    pub jitter: bool,
    pub circular: bool,
    pub orient: bool,
}

impl AreaGrid {
    /// The offset of grid point `(u, v)` from the light's centre; `(ju, jv)` is a jitter in
    /// grid units.
    pub fn offset(&self, axis1: DVec3, axis2: DVec3, u: f64, v: f64) -> DVec3 {
        let (s1, s2) = (f64::from(self.size1), f64::from(self.size2));
        if self.circular && self.size1 > 1 && self.size2 > 1 {
            // Squares of the grid mapped onto concentric circles.
            let mut a = u / (s1 - 1.0) - 0.5 + 0.001;
            let mut b = v / (s2 - 1.0) - 0.5 + 0.001;
            let scale = a.abs().max(b.abs()) / (a * a + b * b).sqrt();
            a *= scale;
            b *= scale;
            return axis1 * a + axis2 * b;
        }
        let a = if self.size1 > 1 {
            axis1 * (u / (s1 - 1.0) - 0.5)
        } else {
            DVec3::ZERO
        };
        let b = if self.size2 > 1 {
            axis2 * (v / (s2 - 1.0) - 0.5)
        } else {
            DVec3::ZERO
        };
        a + b
    }
}

/// Light arriving at a point from one source, before shadows.
#[derive(Debug, Clone, Copy)]
pub struct Incoming {
    /// Unit vector from the point towards the light.
    pub direction: DVec3,
    /// How far along `direction` the shadow test must look.
    pub distance: f64,
    pub colour: DVec3,
}

impl Light {
    pub fn from_scene(light: &scene::Light) -> Result<Light, String> {
        let towards = |point_at: DVec3| (point_at - light.position).normalize_or_zero();
        let kind = match light.kind {
            LightKind::Point => Kind::Point,
            LightKind::Spotlight {
                point_at,
                radius,
                falloff,
                tightness,
            } => Kind::Spot {
                direction: towards(point_at),
                cos_radius: radius.to_radians().cos(),
                cos_falloff: falloff.to_radians().cos(),
                tightness,
            },
            LightKind::Cylinder {
                point_at,
                radius,
                falloff,
                tightness,
            } => Kind::Cylinder {
                direction: towards(point_at),
                radius,
                falloff,
                tightness,
            },
            LightKind::Parallel { point_at } => Kind::Parallel {
                direction: towards(point_at),
            },
        };
        Ok(Light {
            position: light.position,
            colour: light.colour.rgb,
            shadowless: light.shadowless,
            media_interaction: light.media_interaction && !light.shadowless,
            media_attenuation: light.media_attenuation,
            kind,
            fade: (light.fade_power > 0.0)
                .then(|| (light.fade_distance.unwrap_or(0.0), light.fade_power)),
            area: light.area.as_ref().map(|a| AreaGrid {
                axis1: a.axis1,
                axis2: a.axis2,
                size1: a.size1.max(1),
                size2: a.size2.max(1),
                adaptive: a.adaptive,
                jitter: a.jitter,
                circular: a.circular,
                orient: a.orient,
            }),
            projected_through: None,
            photons: light.photons,
            arrives_whole: false,
        })
    }

    /// Whether this light's colour reaches every point as it leaves the light, in a world
    /// that traces shadow rays (`shadows`) and area lights' grids (`area_lights`) or not,
    /// where `blockable` says whether anything may stand in a shadow ray's way (an object
    /// shadow rays see, fog or media) and `atmosphere` whether there is one to dim light:
    /// a light without an object to shine through, whose shadow rays are not traced or
    /// can meet nothing.
    pub fn arrives_whole_in(
        &self,
        shadows: bool,
        area_lights: bool,
        blockable: bool,
        atmosphere: bool,
    ) -> bool {
        // An area light's samples would be averaged, which may round.
        let sampled = self.area.is_some() && area_lights;
        let unshadowed = self.shadowless || !shadows || !(blockable || sampled);
        unshadowed && self.projected_through.is_none() && !(self.media_attenuation && atmosphere)
    }

    /// The direction of a parallel or cylinder light's rays; `None` for lights that shine
    /// from a point.
    pub fn parallel_axis(&self) -> Option<DVec3> {
        match self.kind {
            Kind::Parallel { direction } | Kind::Cylinder { direction, .. } => {
                direction.try_normalize()
            }
            Kind::Point | Kind::Spot { .. } => None,
        }
    }

    /// The direction and shadow-ray length from `point` to the light placed at `centre`.
    pub fn ray_to(&self, point: DVec3, centre: DVec3) -> Option<(DVec3, f64)> {
        match self.kind {
            Kind::Cylinder { direction, .. } => {
                // Light travels parallel to the axis: the shadow ray runs back along it.
                let back = -direction;
                let depth = (centre - point).dot(back);
                (back != DVec3::ZERO).then_some((back, depth))
            }
            Kind::Parallel { direction } => {
                let to = centre - point;
                let depth = to.dot(-direction);
                (direction != DVec3::ZERO).then_some((-direction, depth))
            }
            _ => {
                let to = centre - point;
                let distance = to.length();
                (distance > 0.0 && distance.is_finite()).then(|| (to / distance, distance))
            }
        }
    }

    /// The light reaching `point` from the light's centre, before shadows; `None` when none
    /// can (outside a spotlight's cone, at the light itself).
    #[inline]
    pub fn incoming(&self, point: DVec3) -> Option<Incoming> {
        // A plain point light, the common one, is not attenuated: its colour arrives as it
        // is (times 1 it would be the same), without the calls.
        if let (Kind::Point, None) = (self.kind, self.fade) {
            let to = self.position - point;
            let distance = to.length();
            return (distance > 0.0 && distance.is_finite()).then(|| Incoming {
                direction: to / distance,
                distance,
                colour: self.colour,
            });
        }
        self.attenuated(point)
    }

    /// [`Light::incoming`] of a light that may be attenuated: kept out of line, so that
    /// plain point lights pay no call.
    #[inline(never)]
    fn attenuated(&self, point: DVec3) -> Option<Incoming> {
        let (direction, distance) = self.ray_to(point, self.position)?;
        let attenuation = self.attenuation(point, direction, distance);
        (attenuation > 0.0).then(|| Incoming {
            direction,
            distance,
            colour: self.colour * attenuation,
        })
    }

    /// Where `ray` (of unit direction) crosses the edge of this light's beam between `t0`
    /// and `t1`: a spotlight's cone at its falloff angle or a cylinder light's tube at its
    /// falloff radius. Media sampling splits the ray there so that no beam falls between
    /// two samples.
    pub fn beam_crossings(&self, ray: &crate::ray::Ray, (t0, t1): (f64, f64), out: &mut Vec<f64>) {
        let w = ray.origin - self.position;
        let d = ray.direction;
        let (a, b, c) = match self.kind {
            Kind::Spot {
                direction: axis,
                cos_falloff,
                ..
            } => {
                let c2 = cos_falloff * cos_falloff;
                let (da, wa) = (d.dot(axis), w.dot(axis));
                (
                    da * da - c2 * d.dot(d),
                    2.0 * (da * wa - c2 * d.dot(w)),
                    wa * wa - c2 * w.dot(w),
                )
            }
            Kind::Cylinder {
                direction: axis,
                falloff,
                ..
            } => {
                let dp = d - axis * d.dot(axis);
                let wp = w - axis * w.dot(axis);
                (dp.dot(dp), 2.0 * dp.dot(wp), wp.dot(wp) - falloff * falloff)
            }
            Kind::Point | Kind::Parallel { .. } => return,
        };
        let roots = if a.abs() < 1e-12 {
            [(b.abs() > 1e-12).then(|| -c / b), None]
        } else {
            let disc = b * b - 4.0 * a * c;
            if disc < 0.0 {
                return;
            }
            let s = disc.sqrt();
            [Some((-b - s) / (2.0 * a)), Some((-b + s) / (2.0 * a))]
        };
        out.extend(roots.into_iter().flatten().filter(|t| *t > t0 && *t < t1));
    }

    /// Cone, tube and distance attenuation for light reaching `point` along `-direction`
    /// over `distance`.
    pub fn attenuation(&self, point: DVec3, direction: DVec3, distance: f64) -> f64 {
        let mut a = 1.0;
        match self.kind {
            Kind::Spot {
                direction: axis,
                cos_radius,
                cos_falloff,
                tightness,
            } => {
                let cos = -direction.dot(axis);
                if cos <= 0.0 {
                    return 0.0;
                }
                // The common tightnesses 0 and 1 need no power (a library call per
                // shadow ray and media sample), and give the same numbers without it.
                a = if tightness == 0.0 {
                    1.0
                } else if tightness == 1.0 {
                    cos
                } else {
                    cos.powf(tightness)
                };
                if cos_radius > 0.0 && cos < cos_radius {
                    a *= cubic_spline(cos_falloff, cos_radius, cos);
                }
            }
            Kind::Cylinder {
                direction: axis,
                radius,
                falloff,
                tightness,
            } => {
                let v = point - self.position;
                let k = v.dot(axis);
                if k <= 0.0 {
                    return 0.0;
                }
                let len = (v - k * axis).length();
                if len >= falloff {
                    return 0.0;
                }
                let dist = 1.0 - len / falloff;
                a = if tightness == 0.0 {
                    1.0
                } else {
                    dist.powf(tightness)
                };
                if radius > 0.0 && len > radius {
                    a *= cubic_spline(0.0, 1.0 - radius / falloff, dist);
                }
            }
            Kind::Point | Kind::Parallel { .. } => {}
        }
        if let Some((fade_distance, fade_power)) = self.fade {
            a *= if fade_distance.abs() >= 1e-10 {
                2.0 / (1.0 + (distance / fade_distance).powf(fade_power))
            } else {
                distance.powf(-fade_power)
            };
        }
        if a.is_finite() { a } else { 0.0 }
    }
}

/// 0 below `low`, 1 from `high` on, and the smooth cubic step between.
fn cubic_spline(low: f64, high: f64, x: f64) -> f64 {
    if x < low {
        return 0.0;
    }
    if x >= high {
        return 1.0;
    }
    let t = (x - low) / (high - low);
    (3.0 - 2.0 * t) * t * t
}

#[cfg(test)]
mod tests {
    use super::*;
    use analysis::scene::Colour;

    fn spot() -> Light {
        let mut l = scene::Light::point(DVec3::new(0.0, 10.0, 0.0), Colour::gray(1.0));
        l.kind = LightKind::Spotlight {
            point_at: DVec3::ZERO,
            radius: 10.0,
            falloff: 20.0,
            tightness: 0.0,
        };
        Light::from_scene(&l).unwrap()
    }

    #[test]
    fn spotlight_cone() {
        let s = spot();
        // On the axis: full; inside the radius: full; beyond the falloff: dark.
        assert_eq!(s.incoming(DVec3::ZERO).unwrap().colour, DVec3::ONE);
        let inside = DVec3::new(10.0 * 5f64.to_radians().tan(), 0.0, 0.0);
        assert_eq!(s.incoming(inside).unwrap().colour, DVec3::ONE);
        let between = DVec3::new(10.0 * 15f64.to_radians().tan(), 0.0, 0.0);
        let c = s.incoming(between).unwrap().colour.x;
        assert!(c > 0.0 && c < 1.0, "{c}");
        assert!(s.incoming(DVec3::new(10.0, 0.0, 0.0)).is_none());
    }

    #[test]
    fn fading_halves_at_the_fade_distance() {
        let mut l = scene::Light::point(DVec3::ZERO, Colour::gray(1.0));
        l.fade_distance = Some(2.0);
        l.fade_power = 2.0;
        let light = Light::from_scene(&l).unwrap();
        let c = light.incoming(DVec3::new(2.0, 0.0, 0.0)).unwrap().colour.x;
        assert!((c - 1.0).abs() < 1e-12);
        let c = light.incoming(DVec3::new(4.0, 0.0, 0.0)).unwrap().colour.x;
        assert!((c - 0.4).abs() < 1e-12);
    }
}
