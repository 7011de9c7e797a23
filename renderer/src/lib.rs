//! The Povrayst ray tracer: builds runtime shapes, materials, lights and acceleration
//! structures from an [`analysis::scene::Scene`] and traces them into an image.

mod atmosphere;
mod bounds;
mod build;
mod bump_map;
mod bvh;
mod camera;
mod colour;
mod csg_spans;
mod dispersion;
mod fast_math;
mod focal_blur;
mod function_program;
mod geometry;
mod image;
mod interior;
mod light;
mod material;
mod media;
mod mesh_camera;
mod normal;
mod object;
mod options;
mod parallel;
mod photons;
pub mod pipeline;
mod png_output;
mod polynomial;
mod radiosity;
mod ray;
mod refraction;
mod render;
mod sampling;
mod shapes;
mod statistics;
mod sturm;
mod subsurface;
mod texture_point;
mod tracer;

pub use build::BuildError;
pub use geometry::SceneGeometry;
pub use image::Image;
pub use options::{Extent, Gamma, RenderOptions};
pub use png_output::encode_png;
pub use render::render;
pub use statistics::{WorldStatistics, world_statistics};
