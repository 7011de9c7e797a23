//! An object's interior at run time: what refraction and attenuation need, whether the
//! object is hollow (fog and atmospheric media fill only hollow objects and the space
//! outside all objects), and its media ready to sample.

use crate::media::Medium;
use analysis::scene::{self, Colour};
use glam::DVec3;

#[derive(Debug, Clone)]
pub struct Interior {
    pub ior: f64,
    /// The ratio of the violet index of refraction to the red one; 1 when the interior
    /// does not disperse light, as for an interior without `ior`, which POV-Ray does not
    /// disperse.
    pub dispersion: f64,
    pub dispersion_samples: u32,
    pub fade_distance: f64,
    pub fade_power: f64,
    pub fade_colour: Colour,
    pub hollow: bool,
    pub media: Vec<Medium>,
}

impl Interior {
    /// `Err` names a feature of the interior's media not drawn yet. Without `with_media`
    /// (quality levels below 9) the media are left out.
    pub fn from_scene(
        interior: &scene::Interior,
        hollow: bool,
        with_media: bool,
    ) -> Result<Interior, String> {
        let media = interior
            .media
            .iter()
            .filter(|_| with_media)
            .map(|m| Medium::from_scene(m))
            .collect::<Result<Vec<_>, String>>()?;
        Ok(Interior {
            ior: interior.ior,
            dispersion: if interior.ior_given {
                interior.dispersion
            } else {
                1.0
            },
            dispersion_samples: interior.dispersion_samples,
            fade_distance: interior.fade_distance,
            fade_power: interior.fade_power,
            fade_colour: interior.fade_colour,
            hollow,
            media,
        })
    }

    /// The share of light the media of this interior let through from `a` to `b`.
    pub fn media_transmittance(&self, a: DVec3, b: DVec3) -> DVec3 {
        self.media
            .iter()
            .fold(DVec3::ONE, |t, m| t * m.transmittance(a, b))
    }
}

impl Default for Interior {
    fn default() -> Self {
        Interior::from_scene(&scene::Interior::default(), false, false)
            .expect("the default interior has no media")
    }
}
