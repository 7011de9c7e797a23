//! What surrounds the objects: fogs, rainbows, atmospheric media and the sky sphere, built
//! only when a scene has them.

mod fog;
mod rainbow;
mod sky;

use crate::colour::Sample;
use crate::media::Medium;
use analysis::scene::Scene;
use glam::DVec3;
use std::sync::Arc;

pub use fog::Veil;
pub use sky::Sky;

/// The scene's fogs, rainbows and atmospheric media.
#[derive(Debug, Clone)]
pub struct Atmosphere {
    fogs: Vec<fog::Fog>,
    rainbows: Vec<rainbow::Rainbow>,
    pub media: Vec<Medium>,
}

impl Atmosphere {
    /// `None` when the scene has neither fog, rainbow nor atmospheric media. Without
    /// `with_media` (quality levels below 9) the media are left out.
    pub fn from_scene(scene: &Scene, with_media: bool) -> Result<Option<Arc<Atmosphere>>, String> {
        let media = if with_media { &scene.media[..] } else { &[] };
        if scene.fogs.is_empty() && scene.rainbows.is_empty() && media.is_empty() {
            return Ok(None);
        }
        let media = media
            .iter()
            .map(|m| Medium::from_scene(m))
            .collect::<Result<Vec<_>, String>>()?;
        Ok(Some(Arc::new(Atmosphere {
            fogs: scene.fogs.iter().map(fog::Fog::from_scene).collect(),
            rainbows: scene
                .rainbows
                .iter()
                .map(rainbow::Rainbow::from_scene)
                .collect(),
            media,
        })))
    }

    /// Whether there are fogs or rainbows to lay over rays.
    pub fn has_veils(&self) -> bool {
        !self.fogs.is_empty() || !self.rainbows.is_empty()
    }

    /// The fogs' and rainbows' effect over `depth` (infinite for a ray that meets nothing)
    /// along the ray from `origin` in unit `direction`: what they let through multiplies,
    /// what they add adds, as POV-Ray's renders of several fogs show.
    pub fn veil(&self, origin: DVec3, direction: DVec3, depth: f64) -> Veil {
        let mut total = Veil {
            through: DVec3::ONE,
            added: DVec3::ZERO,
        };
        let veils = self
            .rainbows
            .iter()
            .filter_map(|r| r.veil(direction, depth))
            .chain(self.fogs.iter().map(|f| f.veil(origin, direction, depth)));
        for v in veils {
            total.through *= v.through;
            total.added += v.added;
        }
        total
    }

    /// A sample seen through the fogs and rainbows.
    pub fn apply_veil(&self, origin: DVec3, direction: DVec3, depth: f64, s: Sample) -> Sample {
        let v = self.veil(origin, direction, depth);
        let grey = 0.297 * v.through.x + 0.589 * v.through.y + 0.114 * v.through.z;
        Sample::new(
            s.colour * v.through + v.added,
            s.transmit * grey.clamp(0.0, 1.0),
        )
    }
}
