//! Distribution 3 of `mesh_camera`: an image position names a point of uv space, and the
//! first face whose uv triangle holds it gives the ray, from the point of the face with the
//! same barycentric coordinates. A grid over uv space lists the faces each cell meets, in
//! the faces' order, so that a lookup tests a few faces rather than all.

use analysis::scene::mesh::MeshGeometry;
use glam::{DAffine3, DVec2, DVec3};

/// How far outside a uv triangle (in barycentric weight) a point still counts as on it:
/// POV-Ray counts points on an edge as inside.
const EDGE: f64 = 1e-12;

/// The faces of a mesh camera by their uv coordinates.
#[derive(Debug, Clone)]
pub struct UvMap {
    faces: Vec<UvFace>,
    /// The grid's corner and cell size in uv space, and its cells across and down.
    origin: DVec2,
    cell: DVec2,
    columns: usize,
    rows: usize,
    /// Cell `i`'s faces are `members[starts[i]..starts[i + 1]]`, in ascending order.
    starts: Vec<u32>,
    members: Vec<u32>,
}

/// One camera triangle: its corners in uv space and in the world.
#[derive(Debug, Clone)]
struct UvFace {
    uv: [DVec2; 3],
    /// 1 / the uv triangle's doubled signed area; 0 for a degenerate one, which holds
    /// nothing.
    inverse_area: f64,
    corners: [DVec3; 3],
    /// The rays' direction from a flat face: (c - a) × (b - a), unit, as the other
    /// distributions point it.
    normal: DVec3,
    /// The corners' normals in the world, for `smooth`.
    corner_normals: Option<[DVec3; 3]>,
}

/// Where a ray leaves the camera: a point on a face and the face's direction there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FacePoint {
    pub point: DVec3,
    pub normal: DVec3,
}

impl UvMap {
    /// The faces of `meshes`, in order, with their corners placed in the world.
    pub fn new(meshes: &[(std::sync::Arc<MeshGeometry>, DAffine3)]) -> UvMap {
        let mut faces = Vec::new();
        for (mesh, to_world) in meshes {
            let normal_matrix = to_world.matrix3.inverse().transpose();
            for face in &mesh.faces {
                let Some(uvs) = face.uvs else {
                    // A face without uv_vectors has every corner at uv 0: it holds no point.
                    continue;
                };
                let uv = uvs.map(|i| mesh.uvs[i as usize]);
                let corners = face
                    .vertices
                    .map(|i| to_world.transform_point3(mesh.vertices[i as usize]));
                let area = cross(uv[1] - uv[0], uv[2] - uv[0]);
                faces.push(UvFace {
                    uv,
                    inverse_area: if area.abs() > f64::MIN_POSITIVE {
                        1.0 / area
                    } else {
                        0.0
                    },
                    corners,
                    normal: (corners[2] - corners[0])
                        .cross(corners[1] - corners[0])
                        .normalize_or_zero(),
                    corner_normals: face
                        .normals
                        .map(|ids| ids.map(|i| normal_matrix * mesh.normals[i as usize])),
                });
            }
        }
        UvMap::with_grid(faces)
    }

    fn with_grid(faces: Vec<UvFace>) -> UvMap {
        let (mut low, mut high) = (DVec2::splat(f64::INFINITY), DVec2::splat(f64::NEG_INFINITY));
        for face in faces.iter().filter(|f| f.inverse_area != 0.0) {
            for p in face.uv {
                low = low.min(p);
                high = high.max(p);
            }
        }
        // About one face per cell, at most 1024 cells each way.
        let side = ((faces.len() as f64).sqrt().ceil() as usize).clamp(1, 1024);
        let (columns, rows) = (side, side);
        let extent = if low.x <= high.x && (high - low).is_finite() {
            (high - low).max(DVec2::splat(1e-300))
        } else {
            low = DVec2::ZERO;
            DVec2::ONE
        };
        let cell = extent / DVec2::new(columns as f64, rows as f64);
        let mut lists = vec![Vec::new(); columns * rows];
        for (index, face) in faces.iter().enumerate() {
            if face.inverse_area == 0.0 {
                continue;
            }
            let (mut a, mut b) = (face.uv[0], face.uv[0]);
            for p in &face.uv[1..] {
                a = a.min(*p);
                b = b.max(*p);
            }
            let (c0, r0) = cell_of(a, low, cell, columns, rows);
            let (c1, r1) = cell_of(b, low, cell, columns, rows);
            for r in r0..=r1 {
                for c in c0..=c1 {
                    lists[r * columns + c].push(index as u32);
                }
            }
        }
        let mut starts = Vec::with_capacity(lists.len() + 1);
        let mut members = Vec::new();
        for list in lists {
            starts.push(members.len() as u32);
            members.extend(list);
        }
        starts.push(members.len() as u32);
        UvMap {
            faces,
            origin: low,
            cell,
            columns,
            rows,
            starts,
            members,
        }
    }

    /// The point of the first face whose uv triangle holds `uv`, and the direction there:
    /// the face's own, or with `smooth` its corners' normals blended as a smooth
    /// triangle's are, on the face's side.
    pub fn find(&self, uv: DVec2, smooth: bool) -> Option<FacePoint> {
        let relative = (uv - self.origin) / self.cell;
        let (c, r) = (relative.x.floor(), relative.y.floor());
        // A point on the grid's far edge belongs to the last cell.
        let inside = |i: f64, n: usize| (0.0..=n as f64).contains(&i);
        if !inside(c, self.columns) || !inside(r, self.rows) {
            return None;
        }
        let c = (c as usize).min(self.columns - 1);
        let r = (r as usize).min(self.rows - 1);
        let cell = r * self.columns + c;
        let members = &self.members[self.starts[cell] as usize..self.starts[cell + 1] as usize];
        members.iter().find_map(|&i| {
            let face = &self.faces[i as usize];
            let w = face.weights(uv)?;
            let point = face.corners[0] * w.x + face.corners[1] * w.y + face.corners[2] * w.z;
            let normal = match face.corner_normals {
                Some(n) if smooth => {
                    let blended = (n[0] * w.x + n[1] * w.y + n[2] * w.z).normalize_or_zero();
                    if blended.dot(face.normal) < 0.0 {
                        -blended
                    } else {
                        blended
                    }
                }
                _ => face.normal,
            };
            Some(FacePoint { point, normal })
        })
    }
}

impl UvFace {
    /// The barycentric weights of `p` in the uv triangle, if it holds `p`.
    fn weights(&self, p: DVec2) -> Option<DVec3> {
        if self.inverse_area == 0.0 {
            return None;
        }
        let [a, b, c] = self.uv;
        let wb = cross(p - a, c - a) * self.inverse_area;
        let wc = cross(b - a, p - a) * self.inverse_area;
        let wa = 1.0 - wb - wc;
        (wa >= -EDGE && wb >= -EDGE && wc >= -EDGE).then_some(DVec3::new(wa, wb, wc))
    }
}

fn cross(a: DVec2, b: DVec2) -> f64 {
    a.x * b.y - a.y * b.x
}

fn cell_of(p: DVec2, origin: DVec2, cell: DVec2, columns: usize, rows: usize) -> (usize, usize) {
    let relative = (p - origin) / cell;
    let index = |v: f64, n: usize| (v.max(0.0) as usize).min(n - 1);
    (index(relative.x, columns), index(relative.y, rows))
}

#[cfg(test)]
mod tests {
    use super::*;
    use analysis::scene::mesh::{FaceTexture, MeshFace};
    use std::sync::Arc;

    /// The unit square of uv space as two triangles lying at z = 0, stretched to 2 × 3 in
    /// the world; the second triangle's corners carry normals tilted towards +x.
    fn square() -> Arc<MeshGeometry> {
        let uvs = vec![
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(1.0, 1.0),
            DVec2::new(0.0, 1.0),
        ];
        let face = |vertices: [u32; 3], normals| MeshFace {
            vertices,
            normals,
            uvs: Some(vertices),
            texture: FaceTexture::Object,
        };
        Arc::new(MeshGeometry {
            vertices: uvs
                .iter()
                .map(|uv| (*uv * DVec2::new(2.0, 3.0)).extend(0.0))
                .collect(),
            normals: vec![DVec3::new(1.0, 0.0, -1.0)],
            uvs,
            faces: vec![face([0, 1, 2], None), face([0, 2, 3], Some([0, 0, 0]))],
        })
    }

    #[test]
    fn a_uv_point_finds_the_world_point_with_the_same_barycentric_coordinates() {
        let map = UvMap::new(&[(square(), DAffine3::IDENTITY)]);
        let hit = map.find(DVec2::new(0.75, 0.25), false).unwrap();
        assert!((hit.point - DVec3::new(1.5, 0.75, 0.0)).length() < 1e-12);
        // (c - a) × (b - a) of the first face points down z.
        assert_eq!(hit.normal, DVec3::new(0.0, 0.0, -1.0));
        // Outside every triangle there is no ray.
        assert_eq!(map.find(DVec2::new(1.01, 0.5), false), None);
        assert_eq!(map.find(DVec2::new(-0.5, 0.5), false), None);
    }

    #[test]
    fn edges_belong_to_the_first_face_that_has_them() {
        let map = UvMap::new(&[(square(), DAffine3::IDENTITY)]);
        // The diagonal is shared: the first face, which has no corner normals, answers
        // even with smooth on.
        let on_diagonal = map.find(DVec2::new(0.5, 0.5), true).unwrap();
        assert_eq!(on_diagonal.normal, DVec3::new(0.0, 0.0, -1.0));
        // The square's own edges count as inside.
        assert!(map.find(DVec2::new(1.0, 1.0), false).is_some());
        assert!(map.find(DVec2::new(0.0, 0.0), false).is_some());
    }

    #[test]
    fn smooth_follows_the_corner_normals_on_the_face_side() {
        let map = UvMap::new(&[(square(), DAffine3::IDENTITY)]);
        let hit = map.find(DVec2::new(0.25, 0.75), true).unwrap();
        let expected = DVec3::new(1.0, 0.0, -1.0).normalize();
        assert!((hit.normal - expected).length() < 1e-12);
        let flat = map.find(DVec2::new(0.25, 0.75), false).unwrap();
        assert_eq!(flat.normal, DVec3::new(0.0, 0.0, -1.0));
    }

    #[test]
    fn many_faces_are_found_through_the_grid_as_by_a_search_of_all() {
        // A 20 × 20 grid of squares, each split in two, in uv and in the world alike.
        let n = 20;
        let mut mesh = MeshGeometry {
            vertices: Vec::new(),
            normals: Vec::new(),
            uvs: Vec::new(),
            faces: Vec::new(),
        };
        for j in 0..=n {
            for i in 0..=n {
                let uv = DVec2::new(i as f64, j as f64) / n as f64;
                mesh.uvs.push(uv);
                mesh.vertices.push(uv.extend(1.0));
            }
        }
        let at = |i: u32, j: u32| j * (n + 1) + i;
        for j in 0..n {
            for i in 0..n {
                for vertices in [
                    [at(i, j), at(i + 1, j), at(i + 1, j + 1)],
                    [at(i, j), at(i + 1, j + 1), at(i, j + 1)],
                ] {
                    mesh.faces.push(MeshFace {
                        vertices,
                        normals: None,
                        uvs: Some(vertices),
                        texture: FaceTexture::Object,
                    });
                }
            }
        }
        let map = UvMap::new(&[(Arc::new(mesh), DAffine3::IDENTITY)]);
        for k in 0..500 {
            let uv = DVec2::new((k as f64 * 0.618_034) % 1.0, (k as f64 * 0.414_214) % 1.0);
            let hit = map
                .find(uv, false)
                .expect("every point of the square is on a face");
            assert!((hit.point - uv.extend(1.0)).length() < 1e-12, "{uv}");
        }
    }
}
