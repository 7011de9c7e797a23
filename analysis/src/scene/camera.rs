use super::mesh::MeshGeometry;
use super::{Normal, Origin};
use glam::{DAffine3, DVec3};
use std::sync::Arc;

/// The projection a camera uses.
#[derive(Debug, Clone, PartialEq)]
pub enum CameraKind {
    Perspective,
    Orthographic,
    Fisheye,
    UltraWideAngle,
    Omnimax,
    Panoramic,
    /// `cylinder 1` to `cylinder 4`.
    Cylinder(u8),
    Spherical {
        h_angle: f64,
        v_angle: f64,
    },
    /// `mesh_camera { }`: rays from the faces of meshes.
    Mesh(Arc<MeshCamera>),
}

/// `mesh_camera { rays distribution [max_distance] mesh { } ... [smooth] }`: POV-Ray 3.7's
/// camera whose rays leave the faces of meshes along their normals (distributions 0 to 2:
/// one face per pixel) or from the point of a face that a pixel's uv coordinates name
/// (distribution 3). The camera's `location` z moves each ray's origin along the normal, and
/// a negative `direction` z turns the rays around.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshCamera {
    pub rays_per_pixel: u32,
    pub distribution: u8,
    /// The meshes, each with its transformation to the world.
    pub meshes: Vec<(Arc<MeshGeometry>, DAffine3)>,
    /// `smooth`: distribution 3 interpolates the normals of smooth triangles.
    pub smooth: bool,
}

/// Focal blur: `aperture`, `blur_samples`, `focal_point`, `confidence`, `variance`. As in
/// POV-Ray, nothing is blurred unless both the aperture and the maximum number of samples
/// are above zero.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FocalBlur {
    pub aperture: f64,
    pub min_samples: u32,
    pub max_samples: u32,
    /// In world space: the camera's transformations have moved it with the camera.
    pub focal_point: DVec3,
    pub confidence: f64,
    pub variance: f64,
}

/// A camera with its final vectors: the evaluator has already applied `look_at`, `angle`,
/// `sky` and transformations in POV-Ray's order, so `right` and `up` may be mirrored or of
/// any length, and the renderer follows them literally.
#[derive(Debug, Clone, PartialEq)]
pub struct Camera {
    pub kind: CameraKind,
    pub location: DVec3,
    pub direction: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    pub sky: DVec3,
    /// The field of view in degrees, for the projections that take it directly.
    pub angle: Option<f64>,
    pub focal_blur: Option<FocalBlur>,
    /// `normal { }`: bumps that perturb every camera ray, as if seen through bumpy glass.
    pub normal: Option<Normal>,
    pub origin: Origin,
}

impl Default for Camera {
    /// POV-Ray's default camera: at the origin, looking along +z, with a 4:3 `right`.
    fn default() -> Self {
        Camera {
            kind: CameraKind::Perspective,
            location: DVec3::ZERO,
            direction: DVec3::Z,
            right: DVec3::new(1.33, 0.0, 0.0),
            up: DVec3::Y,
            sky: DVec3::Y,
            angle: None,
            focal_blur: None,
            normal: None,
            origin: None,
        }
    }
}
