//! Triangle meshes (`mesh`, `mesh2`, and the triangles a `bicubic_patch` is cut into): the
//! corners, normals and uv vectors the triangles index, with a bounding volume hierarchy
//! over the triangles. The data is shared by every copy of a mesh; a copy adds only its
//! placement and its inside direction.

use super::triangle::{corner_weights, crossing, flat_normal, smooth_normal};
use super::{Root, Roots};
use crate::bounds::Aabb;
use crate::bvh::tree::Tree;
use crate::ray::Ray;
use analysis::scene::mesh::{FaceTexture, MeshFace};
use glam::{DVec2, DVec3};
use std::sync::Arc;

/// Triangles in one leaf of the hierarchy at most.
const LEAF_SIZE: usize = 4;

/// The shared part of a mesh.
#[derive(Debug)]
pub struct MeshData {
    vertices: Vec<DVec3>,
    /// Unit normals.
    normals: Vec<DVec3>,
    uvs: Vec<DVec2>,
    /// In the order of the hierarchy's leaves.
    faces: Vec<MeshFace>,
    tree: Tree,
}

/// Whether the triangles get a hierarchy (`hierarchy on`, the default) or are all tested
/// for every ray.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Hierarchy {
    On,
    Off,
}

impl MeshData {
    /// The mesh over `faces`, whose indices must be within the lists.
    pub fn new(
        vertices: Vec<DVec3>,
        normals: Vec<DVec3>,
        uvs: Vec<DVec2>,
        faces: Vec<MeshFace>,
        hierarchy: Hierarchy,
    ) -> MeshData {
        let corners = |f: &MeshFace| f.vertices.map(|i| vertices[i as usize]);
        let boxes: Vec<Aabb> = faces
            .iter()
            .map(|f| {
                let [a, b, c] = corners(f);
                Aabb::new(a.min(b).min(c), a.max(b).max(c))
            })
            .collect();
        let (tree, order) = match hierarchy {
            Hierarchy::On => Tree::build(&boxes, LEAF_SIZE),
            Hierarchy::Off => Tree::build(&boxes, boxes.len()),
        };
        let faces = order.iter().map(|&i| faces[i as usize]).collect();
        MeshData {
            normals: normals.into_iter().map(DVec3::normalize_or_zero).collect(),
            vertices,
            uvs,
            faces,
            tree,
        }
    }

    /// The bytes the mesh takes: its lists and its hierarchy.
    pub fn memory(&self) -> usize {
        use std::mem::size_of;
        self.vertices.len() * size_of::<DVec3>()
            + self.normals.len() * size_of::<DVec3>()
            + self.uvs.len() * size_of::<DVec2>()
            + self.faces.len() * size_of::<MeshFace>()
            + self.tree.memory()
    }

    pub fn face_count(&self) -> usize {
        self.faces.len()
    }

    fn corners(&self, face: &MeshFace) -> [DVec3; 3] {
        face.vertices.map(|i| self.vertices[i as usize])
    }

    /// Calls `hit` with every crossing of the ray with a triangle in `[tmin, tmax]`, as
    /// (parameter, face index); `hit` returns the interval's new end.
    fn crossings(&self, ray: &Ray, tmin: f64, tmax: f64, mut hit: impl FnMut(f64, u32) -> f64) {
        self.tree.traverse(
            ray,
            ray.direction.recip(),
            tmin,
            tmax,
            u8::MAX,
            |range, mut end| {
                for i in range {
                    if let Some(t) = crossing(ray, self.corners(&self.faces[i]))
                        && t >= tmin
                        && t <= end
                    {
                        end = hit(t, i as u32);
                    }
                }
                end
            },
        );
    }
}

/// A mesh as one object uses it.
#[derive(Debug, Clone)]
pub struct Mesh {
    pub data: Arc<MeshData>,
    /// The direction whose crossings tell inside from outside (`inside_vector`); `None`
    /// gives the mesh no inside.
    pub inside_vector: Option<DVec3>,
}

impl PartialEq for Mesh {
    /// Copies of one mesh are equal: they share their data.
    fn eq(&self, other: &Mesh) -> bool {
        Arc::ptr_eq(&self.data, &other.data) && self.inside_vector == other.inside_vector
    }
}

impl Mesh {
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        self.data
            .crossings(ray, f64::NEG_INFINITY, f64::INFINITY, |t, face| {
                roots.push(t, face);
                f64::INFINITY
            });
    }

    /// The nearest crossing in `(tmin, tmax)`, with the triangle it crosses as its part.
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        let mut best = None;
        self.data.crossings(ray, tmin, tmax, |t, face| {
            if t > tmin && t < tmax && best.is_none_or(|b: Root| t < b.t) {
                best = Some(Root { t, part: face });
            }
            best.map_or(tmax, |b| b.t)
        });
        best
    }

    /// POV-Ray's test: a point is inside when the ray from it along the inside vector
    /// crosses the triangles an odd number of times.
    pub fn inside(&self, p: DVec3) -> bool {
        let Some(direction) = self.inside_vector else {
            return false;
        };
        let ray = Ray::new(p, direction);
        let mut odd = false;
        self.data.crossings(&ray, 0.0, f64::INFINITY, |t, _| {
            if t > 0.0 {
                odd = !odd;
            }
            f64::INFINITY
        });
        odd
    }

    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        let face = &self.data.faces[part as usize];
        let corners = self.data.corners(face);
        match face.normals {
            Some(ids) => smooth_normal(corners, ids.map(|i| self.data.normals[i as usize]), p),
            None => flat_normal(corners),
        }
    }

    /// The uv coordinates at a point of triangle `part`.
    pub fn uv(&self, p: DVec3, part: u32) -> DVec2 {
        let face = &self.data.faces[part as usize];
        let Some(ids) = face.uvs else {
            return DVec2::ZERO;
        };
        let w = corner_weights(self.data.corners(face), p);
        let [a, b, c] = ids.map(|i| self.data.uvs[i as usize]);
        a * w.x + b * w.y + c * w.z
    }

    /// Which texture colours triangle `part`, and the weights of its corners at `p` for
    /// the textures blended across it.
    pub fn texture(&self, p: DVec3, part: u32) -> (FaceTexture, DVec3) {
        let face = &self.data.faces[part as usize];
        let weights = match face.texture {
            FaceTexture::Corners(_) => corner_weights(self.data.corners(face), p),
            _ => DVec3::X,
        };
        (face.texture, weights)
    }

    pub fn bounds(&self) -> Aabb {
        self.data.tree.bounds()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A closed cube of twelve triangles, corners from -1 to 1, facing out.
    fn cube(hierarchy: Hierarchy) -> Mesh {
        let vertices: Vec<DVec3> = (0..8)
            .map(|i| {
                DVec3::new(
                    if i & 1 == 0 { -1.0 } else { 1.0 },
                    if i & 2 == 0 { -1.0 } else { 1.0 },
                    if i & 4 == 0 { -1.0 } else { 1.0 },
                )
            })
            .collect();
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let faces = quads
            .iter()
            .flat_map(|[a, b, c, d]| [[*a, *b, *c], [*a, *c, *d]])
            .map(|vertices| MeshFace {
                vertices,
                normals: None,
                uvs: None,
                texture: FaceTexture::Object,
            })
            .collect();
        Mesh {
            data: Arc::new(MeshData::new(
                vertices,
                Vec::new(),
                Vec::new(),
                faces,
                hierarchy,
            )),
            inside_vector: Some(DVec3::new(0.1, 0.2, 1.0)),
        }
    }

    #[test]
    fn rays_cross_a_closed_mesh_twice() {
        for hierarchy in [Hierarchy::On, Hierarchy::Off] {
            let mesh = cube(hierarchy);
            let ray = Ray::new(DVec3::new(0.3, 0.2, -5.0), DVec3::Z);
            let mut roots = Roots::new();
            mesh.intersect(&ray, &mut roots);
            let mut ts: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
            ts.sort_by(f64::total_cmp);
            assert_eq!(ts, vec![4.0, 6.0]);
            let first = mesh.first_hit(&ray, 0.0, f64::INFINITY).unwrap();
            assert_eq!(first.t, 4.0);
            let n = mesh.normal(ray.at(first.t), first.part);
            assert!(n.normalize().abs_diff_eq(-DVec3::Z, 1e-12), "{n}");
            assert!(mesh.first_hit(&ray, 4.0, 5.0).is_none());
            assert!(mesh.inside(DVec3::new(0.2, -0.3, 0.5)));
            assert!(!mesh.inside(DVec3::new(0.2, -0.3, 1.5)));
            assert!(!mesh.inside(DVec3::new(3.0, 0.0, 0.0)));
        }
    }

    #[test]
    fn uv_and_corner_weights_interpolate() {
        let face = MeshFace {
            vertices: [0, 1, 2],
            normals: Some([0, 1, 2]),
            uvs: Some([0, 1, 2]),
            texture: FaceTexture::Corners([0, 1, 2]),
        };
        let data = MeshData::new(
            vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            vec![DVec3::Z, DVec3::new(1.0, 0.0, 1.0), DVec3::Z * 2.0],
            vec![
                DVec2::new(0.5, 0.5),
                DVec2::new(1.0, 0.5),
                DVec2::new(0.5, 1.0),
            ],
            vec![face],
            Hierarchy::On,
        );
        let mesh = Mesh {
            data: Arc::new(data),
            inside_vector: None,
        };
        let p = DVec3::new(0.25, 0.5, 0.0);
        assert!(mesh.uv(p, 0).abs_diff_eq(DVec2::new(0.625, 0.75), 1e-12));
        let (texture, weights) = mesh.texture(p, 0);
        assert_eq!(texture, FaceTexture::Corners([0, 1, 2]));
        assert!(weights.abs_diff_eq(DVec3::new(0.25, 0.25, 0.5), 1e-12));
        // The normals are made unit before they are blended.
        let n = mesh.normal(p, 0);
        let expected = DVec3::Z * 0.75 + DVec3::new(1.0, 0.0, 1.0).normalize() * 0.25;
        assert!(n.abs_diff_eq(expected, 1e-12), "{n}");
        assert!(!mesh.inside(DVec3::ZERO));
    }
}
