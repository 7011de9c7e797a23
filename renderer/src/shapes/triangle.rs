//! `triangle` and `smooth_triangle`: flat triangles, the smooth kind with normals
//! interpolated from its corners. Triangles have no inside.

use super::Roots;
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Triangle {
    pub corners: [DVec3; 3],
    /// Unit normals at the corners for a smooth triangle.
    pub normals: Option<[DVec3; 3]>,
}

impl Triangle {
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let [a, b, c] = self.corners;
        let (e1, e2) = (b - a, c - a);
        let pv = ray.direction.cross(e2);
        let det = e1.dot(pv);
        if det == 0.0 || !det.is_finite() {
            return;
        }
        let inv = 1.0 / det;
        let tv = ray.origin - a;
        let u = tv.dot(pv) * inv;
        if !(0.0..=1.0).contains(&u) {
            return;
        }
        let qv = tv.cross(e1);
        let v = ray.direction.dot(qv) * inv;
        if v < 0.0 || u + v > 1.0 {
            return;
        }
        roots.push(e2.dot(qv) * inv, 0);
    }

    pub fn normal(&self, p: DVec3) -> DVec3 {
        let [a, b, c] = self.corners;
        let flat = (b - a).cross(c - a);
        let Some([na, nb, nc]) = self.normals else {
            return flat;
        };
        // Barycentric weights of p from the areas of the opposite sub-triangles.
        let area = flat.length_squared();
        if area == 0.0 {
            return flat;
        }
        let wb = (p - a).cross(c - a).dot(flat) / area;
        let wc = (b - a).cross(p - a).dot(flat) / area;
        let wa = 1.0 - wb - wc;
        let n = na * wa + nb * wb + nc * wc;
        // POV-Ray keeps the interpolated normal on the side of the flat one.
        if n.dot(flat) < 0.0 { -n } else { n }
    }
}
