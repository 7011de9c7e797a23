//! Radiosity: diffuse light bounced between surfaces, with POV-Ray 3.7's semantics.
//!
//! With `global_settings { radiosity { } }` and quality 9 or more, a surface's ambient term
//! is replaced by the light it gathers from around it times its `diffuse`; a finish's
//! `ambient` then counts for nothing (legacy scenes, `#version` below 3.7, keep it as a
//! glow that also lights others), and `emission` is how a surface gives light of its own.
//! What the gathering rays meet is shaded with light sources, emission and, up to
//! `recursion_limit` bounces, radiosity of its own, but no highlights.
//!
//! Gathering at every point would cost `count` rays each, so the light is measured at
//! sample points and interpolated between them (the irradiance cache, [`cache`]). Before
//! the picture, pretrace passes shoot camera rays through a mosaic of blocks that halve from
//! `pretrace_start` to `pretrace_end` of the image size, each taking samples where the
//! cache cannot yet answer under the error bound lowered by `low_error_factor`
//! ([`pretrace`]). The picture then only reads the cache.
//!
//! Everything that decides a sample (its place, its ray directions) follows from positions
//! and a fixed order, never from thread timing, so the picture is the same natively with
//! any number of threads and in the single-threaded Typst plugin.

pub mod cache;
mod directions;
mod gather;
mod pretrace;
mod split;

use crate::tracer::Quality;
use analysis::scene::{self, Scene};
use cache::Cache;
use directions::Directions;
use glam::DVec3;

pub use gather::{Indirect, Walk};
pub use pretrace::{Frame, pretrace};

/// Radiosity as a render runs it: the scene's settings, the gathering directions, and the
/// samples the pretrace took.
#[derive(Debug, Clone)]
pub struct Radiosity {
    pub settings: scene::Radiosity,
    directions: Directions,
    /// The camera's position: reuse limits are fractions of the distance from it.
    eye: DVec3,
    /// Legacy scenes' ambient glows and lights other surfaces, as emission does.
    legacy_ambient: bool,
    /// Whether any object has an importance below 1, which the gathers must then honour.
    uses_importance: bool,
    /// One cache per bounce depth, filled by [`pretrace`].
    caches: Vec<Cache>,
}

impl Radiosity {
    /// Radiosity for `scene`, or `None` when it has none or the quality leaves it out.
    pub fn from_scene(scene: &Scene, quality: &Quality) -> Option<Radiosity> {
        let settings = scene.settings.radiosity.clone()?;
        if !quality.radiosity {
            return None;
        }
        let directions = Directions::new(
            settings.count,
            settings.direction_pool.unwrap_or(settings.count),
        );
        Some(Radiosity {
            directions,
            eye: scene.camera.location,
            legacy_ambient: scene.version.is_none_or(|v| v < 3.7),
            uses_importance: scene.objects.iter().any(lowers_importance),
            caches: Vec::new(),
            settings,
        })
    }

    /// The error bound of the pretrace passes.
    fn pretrace_bound(&self) -> f64 {
        self.settings.error_bound * self.settings.low_error_factor
    }

    /// Empty caches, one per bounce, for the pretrace to fill.
    fn empty_caches(&self) -> Vec<Cache> {
        (0..self.settings.recursion_limit)
            .map(|_| Cache::new(self.settings.error_bound))
            .collect()
    }

    /// How many samples each bounce depth holds.
    #[cfg(test)]
    fn sample_counts(&self) -> Vec<usize> {
        self.caches.iter().map(Cache::len).collect()
    }
}

fn lowers_importance(object: &scene::Object) -> bool {
    object.radiosity_importance.is_some_and(|i| i < 1.0)
        || match &object.shape {
            scene::Shape::Csg { children, .. } => children.iter().any(lowers_importance),
            _ => false,
        }
}

#[cfg(test)]
mod tests;
