//! `triangle` and `smooth_triangle`: flat triangles, the smooth kind with normals
//! interpolated from its corners. Triangles have no inside. The crossing test, the corner
//! weights and the normal interpolation serve mesh triangles too.

use super::Roots;
use crate::ray::Ray;
use glam::DVec3;

#[derive(Debug, Clone, PartialEq)]
pub struct Triangle {
    pub corners: [DVec3; 3],
    /// Unit normals at the corners for a smooth triangle, boxed so that the flat kind and
    /// every other shape stay small.
    pub normals: Option<Box<[DVec3; 3]>>,
}

impl Triangle {
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        if let Some(t) = crossing(ray, self.corners) {
            roots.push(t, 0);
        }
    }

    pub fn normal(&self, p: DVec3) -> DVec3 {
        match &self.normals {
            Some(normals) => smooth_normal(self.corners, **normals, p),
            None => flat_normal(self.corners),
        }
    }
}

/// The ray parameter where the ray crosses the triangle (Möller and Trumbore's test),
/// edges included.
pub fn crossing(ray: &Ray, [a, b, c]: [DVec3; 3]) -> Option<f64> {
    let (e1, e2) = (b - a, c - a);
    let pv = ray.direction.cross(e2);
    let det = e1.dot(pv);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let inv = 1.0 / det;
    let tv = ray.origin - a;
    let u = tv.dot(pv) * inv;
    if !(0.0..=1.0).contains(&u) {
        return None;
    }
    let qv = tv.cross(e1);
    let v = ray.direction.dot(qv) * inv;
    if v < 0.0 || u + v > 1.0 {
        return None;
    }
    Some(e2.dot(qv) * inv)
}

/// The normal of the triangle's plane, of no particular length, on the side from which
/// the corners turn anticlockwise.
pub fn flat_normal([a, b, c]: [DVec3; 3]) -> DVec3 {
    (b - a).cross(c - a)
}

/// The weights of the corners at a point of the triangle, from the areas of the
/// sub-triangles opposite them; they sum to 1.
pub fn corner_weights(corners: [DVec3; 3], p: DVec3) -> DVec3 {
    let [a, b, c] = corners;
    let flat = flat_normal(corners);
    let area = flat.length_squared();
    if area == 0.0 {
        return DVec3::new(1.0, 0.0, 0.0);
    }
    let wb = (p - a).cross(c - a).dot(flat) / area;
    let wc = (b - a).cross(p - a).dot(flat) / area;
    DVec3::new(1.0 - wb - wc, wb, wc)
}

/// The corner normals interpolated at `p`, kept on the side of the flat normal as POV-Ray
/// keeps them.
pub fn smooth_normal(corners: [DVec3; 3], normals: [DVec3; 3], p: DVec3) -> DVec3 {
    let flat = flat_normal(corners);
    let w = corner_weights(corners, p);
    let n = normals[0] * w.x + normals[1] * w.y + normals[2] * w.z;
    if n == DVec3::ZERO {
        flat
    } else if n.dot(flat) < 0.0 {
        -n
    } else {
        n
    }
}
