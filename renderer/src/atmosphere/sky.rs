//! `sky_sphere { }` at run time: pigments on the sphere at infinity, looked up by the ray's
//! direction, layered as a texture's layers are (measured on POV-Ray 3.7: each layer adds
//! its colour times its opacity times what the layers above let through, and what the
//! bottom layer lets through shows the background), the sky's own light scaled by
//! `emission`.

use crate::colour::Sample;
use crate::material::Pigment;
use crate::texture_point::TexturePoint;
use analysis::scene;
use glam::{DAffine3, DVec3};

#[derive(Debug, Clone)]
pub struct Sky {
    /// The top layer first.
    layers: Vec<Pigment>,
    emission: DVec3,
    to_sky: DAffine3,
    /// Legacy scenes rendered with alpha show the sky in reflections only.
    pub reflections_only: bool,
}

impl Sky {
    pub fn from_scene(sky: &scene::SkySphere) -> Result<Sky, String> {
        let layers = sky
            .pigments
            .iter()
            .rev()
            .map(crate::material::pigment_from_scene)
            .collect::<Result<Vec<_>, String>>()?;
        Ok(Sky {
            layers,
            emission: sky.emission,
            to_sky: sky.transform.inverse,
            reflections_only: false,
        })
    }

    /// The sky seen along `direction`, over `background`.
    pub fn sample(&self, direction: DVec3, background: Sample) -> Sample {
        let p = self
            .to_sky
            .transform_vector3(direction)
            .normalize_or(DVec3::Z);
        let mut own = DVec3::ZERO;
        let mut through = DVec3::ONE;
        for layer in &self.layers {
            let c = layer.colour_at(&TexturePoint::in_space(p));
            own += through * c.rgb * (1.0 - c.filter - c.transmit);
            through *= c.rgb * c.filter + DVec3::splat(c.transmit);
            if through == DVec3::ZERO {
                break;
            }
        }
        let grey = (0.297 * through.x + 0.589 * through.y + 0.114 * through.z).clamp(0.0, 1.0);
        Sample::new(
            own * self.emission + through * background.colour,
            grey * background.transmit,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use analysis::scene::Colour;

    #[test]
    fn layers_and_emission_follow_povray() {
        let colour = |r, g, b, f, t| {
            scene::Pigment::Solid(Colour {
                rgb: DVec3::new(r, g, b),
                filter: f,
                transmit: t,
            })
        };
        let background = Sample::new(DVec3::splat(0.5), 0.0);
        // POV-Ray 3.7 shows <0.675, 0.40751, 0.27625> for these two layers over grey.
        let sky = Sky::from_scene(&scene::SkySphere {
            pigments: vec![
                colour(0.2, 0.4, 0.6, 0.0, 0.5),
                colour(1.0, 0.5, 0.25, 0.3, 0.2),
            ],
            ..scene::SkySphere::default()
        })
        .unwrap();
        let s = sky.sample(DVec3::Z, background);
        assert!(
            (s.colour - DVec3::new(0.675, 0.40751, 0.27625))
                .abs()
                .max_element()
                < 1e-4
        );
        // And <0.1, 0.32, 0.84> with emission <0.5, 1, 2> on one filtering layer.
        let sky = Sky::from_scene(&scene::SkySphere {
            pigments: vec![colour(0.2, 0.4, 0.6, 0.4, 0.0)],
            emission: DVec3::new(0.5, 1.0, 2.0),
            ..scene::SkySphere::default()
        })
        .unwrap();
        let s = sky.sample(DVec3::Z, background);
        assert!((s.colour - DVec3::new(0.1, 0.32, 0.84)).abs().max_element() < 1e-4);
    }
}
