//! `mesh_camera`: rays that leave the faces of meshes. Each pixel has its faces, by the
//! pixel's number `width * row + column`: distribution 0 takes ray `r` of a pixel from
//! mesh `r`, 1 counts the faces of all meshes as one list (ray `r` from face
//! `r * width * height + pixel`), 2 sets the meshes side by side, one per band of columns.
//! The rays start at the face's centroid and follow its normal. The camera's `location` z
//! moves the origins along the normals; a negative `direction` z reverses the rays. (Both
//! at once do not give POV-Ray's picture yet: its reversed rays with an offset origin miss
//! what these meet.) Distribution 3 maps image positions to uv space ([`uv_map`]), so its
//! rays depend on where in a pixel a sample lies and antialiasing refines them.

mod uv_map;

use crate::ray::Ray;
use analysis::scene::{self, mesh::MeshGeometry};
use glam::{DAffine3, DVec2, DVec3};
use uv_map::UvMap;

/// The faces of a mesh camera in the world, ready to give rays.
#[derive(Debug, Clone)]
pub struct MeshRays {
    pub rays_per_pixel: u32,
    distribution: u8,
    meshes: Vec<Vec<Face>>,
    /// Distribution 3's faces by their uv coordinates, and whether its rays follow the
    /// corners' normals.
    uv_map: Option<UvMap>,
    smooth: bool,
    /// How far along its normal each ray starts from the face.
    offset: f64,
    /// Whether the rays run against the normals.
    reversed: bool,
}

/// One triangle of a camera mesh, in the world.
#[derive(Debug, Clone)]
struct Face {
    centroid: DVec3,
    /// The unit normal, by the corners' order: (c - a) × (b - a), as POV-Ray's mesh camera
    /// points it.
    normal: DVec3,
}

impl MeshRays {
    pub fn new(camera: &scene::MeshCamera, location: DVec3, direction: DVec3) -> MeshRays {
        let uv_mapped = camera.distribution == 3;
        MeshRays {
            rays_per_pixel: camera.rays_per_pixel,
            distribution: camera.distribution,
            meshes: if uv_mapped {
                Vec::new()
            } else {
                camera
                    .meshes
                    .iter()
                    .map(|(mesh, to_world)| faces(mesh, to_world))
                    .collect()
            },
            uv_map: uv_mapped.then(|| UvMap::new(&camera.meshes)),
            smooth: camera.smooth,
            offset: location.z,
            reversed: direction.z < -1e-10,
        }
    }

    /// Whether each pixel's rays come from its own faces whatever the position in the
    /// pixel (distributions 0 to 2), rather than from the image position (3).
    pub fn by_pixel(&self) -> bool {
        self.uv_map.is_none()
    }

    /// Distribution 3's ray at image position `(x, y)` of a `width` × `height` image; `None`
    /// where no face's uv triangle holds it. POV-Ray 3.7 looks up (x - 1/2, y - 1/2), but
    /// never right of x = width - 3/2 nor above y = 1/2 (measured: the last column of pixels
    /// shows the uv half a pixel left of the column before, and the samples of the first
    /// row all show the uv of y = 1/2); u runs across and v up, both 0 to 1 over the image.
    pub fn uv_ray(&self, x: f64, y: f64, (width, height): (f64, f64)) -> Option<Ray> {
        let map = self.uv_map.as_ref()?;
        let across = (x - 0.5).min(width - 1.5);
        let down = (y - 0.5).max(0.5);
        let hit = map.find(DVec2::new(across / width, 1.0 - down / height), self.smooth)?;
        self.ray(hit.point, hit.normal)
    }

    /// The pixel whose faces give the rays at image position `(x, y)` of a `width` ×
    /// `height` image. POV-Ray 3.7 takes them from half a pixel above the pixel's centre,
    /// rounded towards zero (measured): the top two rows of the image show the first row of
    /// faces, and every row below the row of faces above its own.
    pub fn pixel_at(x: f64, y: f64, (width, height): (u32, u32)) -> (u32, u32) {
        let index = |p: f64, size: u32| (p.max(0.0) as u32).min(size - 1);
        (index(x, width), index(y - 1.0, height))
    }

    /// Ray `r` of pixel `(column, row)` of a `width` × `height` image (distributions 0 to
    /// 2); `None` where there is no face for it (and always through distribution 3).
    pub fn pixel_ray(
        &self,
        r: u32,
        (column, row): (u32, u32),
        (width, height): (u32, u32),
    ) -> Option<Ray> {
        let pixel = row as usize * width as usize + column as usize;
        let face = match self.distribution {
            0 => self.meshes.get(r as usize)?.get(pixel)?,
            1 => {
                let mut index = r as usize * width as usize * height as usize + pixel;
                let mut found = None;
                for faces in &self.meshes {
                    if index < faces.len() {
                        found = Some(&faces[index]);
                        break;
                    }
                    index -= faces.len();
                }
                found?
            }
            2 => {
                // The image split into as many bands of columns as there are meshes.
                let band = (width as usize / self.meshes.len()).max(1);
                let mesh = (column as usize / band).min(self.meshes.len() - 1);
                let x = column as usize - mesh * band;
                self.meshes[mesh].get(row as usize * band + x)?
            }
            _ => return None,
        };
        self.ray(face.centroid, face.normal)
    }

    fn ray(&self, on_face: DVec3, normal: DVec3) -> Option<Ray> {
        if normal == DVec3::ZERO {
            return None;
        }
        let direction = if self.reversed { -normal } else { normal };
        Some(Ray::new(on_face + normal * self.offset, direction))
    }
}

/// The mesh's triangles placed in the world.
fn faces(mesh: &MeshGeometry, to_world: &DAffine3) -> Vec<Face> {
    mesh.faces
        .iter()
        .map(|face| {
            let corners = face
                .vertices
                .map(|i| to_world.transform_point3(mesh.vertices[i as usize]));
            let normal = (corners[2] - corners[0])
                .cross(corners[1] - corners[0])
                .normalize_or_zero();
            Face {
                centroid: (corners[0] + corners[1] + corners[2]) / 3.0,
                normal,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use analysis::scene::mesh::{FaceTexture, MeshFace};
    use std::sync::Arc;

    /// A row of `n` unit triangles along x, face `i` at x = i, facing +z by POV-Ray's
    /// mesh camera's order.
    fn row(n: usize) -> Arc<MeshGeometry> {
        let mut mesh = MeshGeometry {
            vertices: Vec::new(),
            normals: Vec::new(),
            uvs: Vec::new(),
            faces: Vec::new(),
        };
        for i in 0..n {
            let x = i as f64;
            let first = mesh.vertices.len() as u32;
            mesh.vertices.extend([
                DVec3::new(x, 0.0, 0.0),
                DVec3::new(x, 1.0, 0.0),
                DVec3::new(x + 1.0, 0.0, 0.0),
            ]);
            mesh.faces.push(MeshFace {
                vertices: [first, first + 1, first + 2],
                normals: None,
                uvs: None,
                texture: FaceTexture::Object,
            });
        }
        Arc::new(mesh)
    }

    fn camera(rays: u32, distribution: u8, meshes: &[(usize, f64)]) -> MeshRays {
        let camera = scene::MeshCamera {
            rays_per_pixel: rays,
            distribution,
            meshes: meshes
                .iter()
                .map(|&(n, y)| (row(n), DAffine3::from_translation(DVec3::new(0.0, y, 0.0))))
                .collect(),
            smooth: false,
        };
        MeshRays::new(&camera, DVec3::ZERO, DVec3::Z)
    }

    /// Where the ray of a pixel starts: the centroid of its face.
    fn start(mesh: &MeshRays, r: u32, at: (u32, u32), size: (u32, u32)) -> Option<DVec3> {
        mesh.pixel_ray(r, at, size).map(|ray| ray.origin)
    }

    #[test]
    fn faces_follow_pixels_row_by_row_and_ray_by_ray() {
        let centroid = |x: f64, y: f64| DVec3::new(x + 1.0 / 3.0, y + 1.0 / 3.0, 0.0);
        // Distribution 0: ray r from mesh r; pixel (1, 1) of a 2 x 2 image is face 3.
        let zero = camera(2, 0, &[(4, 0.0), (3, 10.0)]);
        assert_eq!(start(&zero, 0, (1, 1), (2, 2)), Some(centroid(3.0, 0.0)));
        assert_eq!(start(&zero, 1, (1, 1), (2, 2)), None);
        assert_eq!(start(&zero, 1, (0, 1), (2, 2)), Some(centroid(2.0, 10.0)));
        // Distribution 1: the meshes' faces as one list, ray r from face r * 4 + pixel.
        let one = camera(2, 1, &[(5, 0.0), (5, 10.0)]);
        assert_eq!(start(&one, 0, (0, 1), (2, 2)), Some(centroid(2.0, 0.0)));
        assert_eq!(start(&one, 1, (0, 1), (2, 2)), Some(centroid(1.0, 10.0)));
        // Past the last face of the last mesh, no ray.
        assert_eq!(start(&one, 1, (0, 0), (4, 4)), None);
        // Distribution 2: one band of columns per mesh.
        let two = camera(1, 2, &[(4, 0.0), (4, 10.0)]);
        assert_eq!(start(&two, 0, (1, 1), (4, 2)), Some(centroid(3.0, 0.0)));
        assert_eq!(start(&two, 0, (2, 0), (4, 2)), Some(centroid(0.0, 10.0)));
        let ray = zero.pixel_ray(0, (0, 0), (2, 2)).unwrap();
        assert_eq!(ray.direction, DVec3::Z);
    }

    #[test]
    fn uv_mapped_rays_follow_image_positions_as_pov_ray_clamps_them() {
        // One face covering uv 0..1 and the world square 0..1 alike, uv (0,0) at the
        // bottom left.
        let mesh = Arc::new(MeshGeometry {
            vertices: vec![DVec3::ZERO, DVec3::X, DVec3::new(1.0, 1.0, 0.0), DVec3::Y],
            normals: Vec::new(),
            uvs: vec![
                glam::DVec2::ZERO,
                glam::DVec2::X,
                glam::DVec2::ONE,
                glam::DVec2::Y,
            ],
            faces: [[0, 1, 2], [0, 2, 3]]
                .map(|vertices| MeshFace {
                    vertices,
                    normals: None,
                    uvs: Some(vertices),
                    texture: FaceTexture::Object,
                })
                .to_vec(),
        });
        let camera = scene::MeshCamera {
            rays_per_pixel: 1,
            distribution: 3,
            meshes: vec![(mesh, DAffine3::IDENTITY)],
            smooth: false,
        };
        let rays = MeshRays::new(&camera, DVec3::ZERO, DVec3::Z);
        assert!(!rays.by_pixel());
        let start = |x: f64, y: f64| rays.uv_ray(x, y, (4.0, 4.0)).unwrap().origin;
        // A pixel centre (column + 1/2, row + 1/2) looks up (column, row).
        assert!((start(1.5, 2.5) - DVec3::new(0.25, 0.5, 0.0)).length() < 1e-12);
        // The last column looks half a pixel further left; the first row, half a pixel down.
        assert!((start(3.5, 2.5) - DVec3::new(0.625, 0.5, 0.0)).length() < 1e-12);
        assert!((start(1.5, 0.25) - DVec3::new(0.25, 0.875, 0.0)).length() < 1e-12);
        // Left of u = 0 there is no face.
        assert!(rays.uv_ray(0.25, 2.5, (4.0, 4.0)).is_none());
        // The pixel-indexed lookup has nothing for distribution 3.
        assert!(rays.pixel_ray(0, (1, 1), (4, 4)).is_none());
    }
}
