//! The scene description: what the evaluator produces and the renderer consumes. It holds
//! parameters and source locations only; the renderer builds its runtime objects (bounds,
//! acceleration structures, precomputed transforms) from it. Anything the scene does not
//! use is absent, so the renderer never pays for it.

mod atmosphere;
pub mod bitmap;
mod camera;
mod colour;
mod light;
pub mod math_shapes;
mod media;
pub mod mesh;
mod object;
mod photons;
mod settings;
mod texture;
mod transform;

pub use atmosphere::{Fog, GroundFog, Rainbow, SkySphere};
pub use camera::{Camera, CameraKind, FocalBlur, MeshCamera};
pub use colour::Colour;
pub use light::{AreaLight, Light, LightGroup, LightKind};
pub use media::{Media, Scattering, ScatteringKind};
pub use object::{CsgOp, Interior, Object, ObjectFlags, Shape};
pub use photons::{
    LightPhotons, MediaPhotons, ObjectPhotons, PhotonDensity, Photons, photons_interact,
};
pub use settings::{GlobalSettings, Radiosity, Subsurface};
pub use texture::{
    Altitude, BlendMap, Finish, Fractal, FractalKind, Normal, NormalKind, Pattern, PatternKind,
    Pavement, Pigment, Reflection, Slope, SlopeTarget, Texture, Turbulence, Warp, WaveType,
};
pub use transform::Transform;

use syntax::Span;

/// Everything a scene file describes, after evaluation.
#[derive(Debug, Clone)]
pub struct Scene {
    pub camera: Camera,
    pub lights: Vec<Light>,
    pub objects: Vec<Object>,
    /// `background { }`; `None` draws transparent black, as POV-Ray does.
    pub background: Option<Colour>,
    pub fogs: Vec<Fog>,
    pub rainbows: Vec<Rainbow>,
    /// The last `sky_sphere { }`: a scene has one at most.
    pub sky_sphere: Option<SkySphere>,
    /// Atmospheric `media { }`, filling the space outside non-hollow objects.
    pub media: Vec<std::sync::Arc<Media>>,
    pub settings: GlobalSettings,
    /// The `#version` in force at the end of parsing, if the scene gave one.
    pub version: Option<f64>,
}

/// The assumed_gamma a scene that sets none works at, by its `#version`: 1.0 from 3.7 on,
/// as POV-Ray 3.7 takes it (with a warning; measured: such a plane of rgb 0.5 lit head-on
/// is written as 187, not 127); older scenes and those without `#version` get no gamma
/// handling (`None`).
pub fn default_assumed_gamma(version: Option<f64>) -> Option<f64> {
    version.filter(|v| *v >= 3.7).map(|_| 1.0)
}

/// Where an entity was written, so that the renderer can report problems at the source.
pub type Origin = Option<Span>;
