//! `fog { }` at run time: constant and ground fog, stirred by turbulence.
//!
//! The rules were measured on POV-Ray 3.7 renders. A fog lets `k = exp(-depth / distance)`
//! of the light through, raised to its colour's transmit when that is larger, and adds
//! `(1 - k)` of its colour; its filter tints the light it lets through:
//! `k (1 - filter + filter × colour)`. Several fogs multiply what they let through and add
//! what they add. Ground fog has density 1 up to `fog_offset` and
//! `1 / (1 + ((h - fog_offset) / fog_alt)²)` above, averaged along the ray by the heights
//! it spans. Turbulence thins the fog at random: with `X` the sum of `octaves` noise values
//! (each `omega` times weaker and `lambda` times finer) at the point `turb_depth` of the
//! way along the ray, the optical depth shrinks by `k × min(1, turb_depth × X)`.

use analysis::noise;
use analysis::scene::{self, Turbulence};
use glam::{DAffine3, DVec3};

/// How far a ray that meets nothing runs through a fog: far enough that constant fog hides
/// the background and that ground fog has thinned to nothing.
const ENDLESS: f64 = 1e12;

/// What one fog does to a ray: the factor on the light behind it and the colour it adds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Veil {
    pub through: DVec3,
    pub added: DVec3,
}

#[derive(Debug, Clone)]
pub struct Fog {
    distance: f64,
    colour: DVec3,
    filter: f64,
    transmit: f64,
    ground: Option<Ground>,
    turbulence: Option<Turbulence>,
    turb_depth: f64,
    to_fog: DAffine3,
}

#[derive(Debug, Clone, Copy)]
struct Ground {
    offset: f64,
    alt: f64,
    up: DVec3,
}

impl Fog {
    pub fn from_scene(fog: &scene::Fog) -> Fog {
        Fog {
            distance: fog.distance,
            colour: fog.colour.rgb,
            filter: fog.colour.filter,
            transmit: fog.colour.transmit,
            ground: fog.ground.as_ref().map(|g| Ground {
                offset: g.offset,
                alt: g.alt,
                up: fog.transform.vector(g.up).normalize_or(DVec3::Y),
            }),
            turbulence: fog.turbulence.filter(|t| t.amount != DVec3::ZERO),
            turb_depth: fog.turb_depth,
            to_fog: fog.transform.inverse,
        }
    }

    /// The fog over `depth` along the ray from `origin` in unit direction `direction`.
    pub fn veil(&self, origin: DVec3, direction: DVec3, depth: f64) -> Veil {
        if self.distance == 0.0 {
            return Veil {
                through: DVec3::ONE,
                added: DVec3::ZERO,
            };
        }
        let depth = depth.min(ENDLESS);
        let mut optical = depth / self.distance;
        if let Some(ground) = &self.ground {
            optical *= ground.mean_density(origin, direction, depth);
        }
        if let Some(t) = &self.turbulence {
            let k = (-optical).exp();
            let at = self
                .to_fog
                .transform_point3(origin + direction * (depth * self.turb_depth));
            optical *= 1.0 - k * (self.turb_depth * stir(t, at)).min(1.0);
        }
        let k = (-optical).exp().max(self.transmit);
        Veil {
            through: DVec3::splat(k)
                * (DVec3::splat(1.0 - self.filter) + self.filter * self.colour),
            added: (1.0 - k) * self.colour,
        }
    }
}

impl Ground {
    fn density(&self, h: f64) -> f64 {
        if h <= self.offset {
            return 1.0;
        }
        let x = (h - self.offset) / self.alt;
        1.0 / (1.0 + x * x)
    }

    /// The integral of the density over heights up to `h`, from the offset.
    fn integral(&self, h: f64) -> f64 {
        if h <= self.offset {
            h - self.offset
        } else {
            self.alt * ((h - self.offset) / self.alt).atan()
        }
    }

    fn mean_density(&self, origin: DVec3, direction: DVec3, depth: f64) -> f64 {
        if self.alt <= 0.0 {
            // Without a height to thin over, the fog stops at the offset.
            let h = origin.dot(self.up);
            return if h <= self.offset { 1.0 } else { 0.0 };
        }
        let h0 = origin.dot(self.up);
        let rise = direction.dot(self.up);
        let h1 = h0 + rise * depth;
        if (h1 - h0).abs() < 1e-9 * (1.0 + h0.abs()) {
            return self.density(h0);
        }
        (self.integral(h1) - self.integral(h0)) / (h1 - h0)
    }
}

/// The sum of noise values the fog's turbulence thins it by, about 1 on average.
fn stir(t: &Turbulence, p: DVec3) -> f64 {
    let mut sum = 0.0;
    let (mut scale, mut weight) = (1.0, 1.0);
    let p = p * t.amount;
    for _ in 0..t.octaves.max(1) {
        sum += weight * noise::noise(p * scale);
        scale *= t.lambda;
        weight *= t.omega;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;
    use analysis::scene::{Colour, GroundFog};

    fn fog(colour: Colour) -> scene::Fog {
        scene::Fog {
            distance: 100.0,
            colour,
            ..scene::Fog::default()
        }
    }

    #[test]
    fn constant_fog_follows_povray() {
        // Measured on POV-Ray 3.7 at depth 100 = distance, colour <0.2, 0.4, 0.6>: a
        // white object shows 0.49430 red, a black one 0.12642; with filter 0.5 the white
        // one shows 0.34716; with transmit 0.5 it shows 0.6 and the black one 0.1.
        let c = |f, t| Colour {
            rgb: DVec3::new(0.2, 0.4, 0.6),
            filter: f,
            transmit: t,
        };
        let shown = |fog: &Fog, object: f64| {
            let v = fog.veil(DVec3::ZERO, DVec3::Z, 100.0);
            v.through.x * object + v.added.x
        };
        let plain = Fog::from_scene(&fog(c(0.0, 0.0)));
        assert!((shown(&plain, 1.0) - 0.49430).abs() < 1e-4);
        assert!((shown(&plain, 0.0) - 0.12642).abs() < 1e-4);
        let filtered = Fog::from_scene(&fog(c(0.5, 0.0)));
        assert!((shown(&filtered, 1.0) - 0.34716).abs() < 1e-4);
        let clear = Fog::from_scene(&fog(c(0.0, 0.5)));
        assert!((shown(&clear, 1.0) - 0.6).abs() < 1e-4);
        assert!((shown(&clear, 0.0) - 0.1).abs() < 1e-4);
    }

    #[test]
    fn ground_fog_thins_with_height() {
        // POV-Ray: a horizontal ray 100 long at height 1.95 through fog_offset 0.5,
        // fog_alt 1, distance 100, white: 0.27553 of the fog's colour.
        let mut scene_fog = fog(Colour::gray(1.0));
        scene_fog.ground = Some(GroundFog {
            offset: 0.5,
            alt: 1.0,
            up: DVec3::Y,
        });
        let f = Fog::from_scene(&scene_fog);
        let v = f.veil(DVec3::new(0.0, 1.95, 0.0), DVec3::Z, 100.0);
        assert!((v.added.x - 0.27553).abs() < 1e-4, "{v:?}");
        // A ray rising at 30 degrees from far below the offset to 2.25: 0.63111.
        let dir = DVec3::new(0.0, 0.5, 0.75f64.sqrt());
        let v = f.veil(DVec3::new(0.0, 2.25 - 50.56, 0.0), dir, 101.12);
        assert!((v.added.x - 0.63111).abs() < 2e-3, "{v:?}");
    }
}
