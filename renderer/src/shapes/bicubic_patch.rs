//! `bicubic_patch`: the Bézier surface cut into pieces as POV-Ray cuts it (halved
//! `u_steps` times from row to row of control points and `v_steps` times along the rows,
//! fewer where `flatness` finds a piece flat enough), each piece two smooth triangles whose
//! corner normals are the surface's own and whose uv coordinates follow the patch's
//! parameters.

use super::mesh::{Hierarchy, MeshData};
use analysis::scene::mesh::{BicubicPatch, FaceTexture, MeshFace};
use glam::{DVec2, DVec3};
use std::collections::HashMap;

/// The triangles of a patch; `None` when none of them has an area.
pub fn tessellate(patch: &BicubicPatch) -> Option<MeshData> {
    let mut pieces = Pieces {
        patch,
        ids: HashMap::new(),
        vertices: Vec::new(),
        normals: Vec::new(),
        uvs: Vec::new(),
        faces: Vec::new(),
    };
    pieces.split(
        &patch.points,
        [0.0, 0.0, 1.0, 1.0],
        patch.v_steps,
        patch.u_steps,
    );
    if pieces.faces.is_empty() {
        return None;
    }
    Some(MeshData::new(
        pieces.vertices,
        pieces.normals,
        pieces.uvs,
        pieces.faces,
        Hierarchy::On,
    ))
}

/// The Bernstein weights of the four control points of a cubic at `t`, and of their
/// derivative.
fn bernstein(t: f64) -> ([f64; 4], [f64; 4]) {
    let s = 1.0 - t;
    (
        [s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t],
        [
            -3.0 * s * s,
            3.0 * s * (s - 2.0 * t),
            3.0 * t * (2.0 * s - t),
            3.0 * t * t,
        ],
    )
}

/// The point of the patch at parameters (u, v) and its derivatives along u and v. `u` runs
/// along each row of control points, `v` from row to row.
fn evaluate(points: &[[DVec3; 4]; 4], u: f64, v: f64) -> (DVec3, DVec3, DVec3) {
    let (bu, du) = bernstein(u);
    let (bv, dv) = bernstein(v);
    let (mut p, mut pu, mut pv) = (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO);
    for (j, row) in points.iter().enumerate() {
        for (i, point) in row.iter().enumerate() {
            p += *point * (bu[i] * bv[j]);
            pu += *point * (du[i] * bv[j]);
            pv += *point * (bu[i] * dv[j]);
        }
    }
    (p, pu, pv)
}

/// The surface normal at (u, v). Where the derivatives vanish or align (a corner whose
/// edge collapses to a point) the normal is taken a little way into the patch.
fn surface_normal(points: &[[DVec3; 4]; 4], u: f64, v: f64) -> DVec3 {
    let (_, pu, pv) = evaluate(points, u, v);
    if let Some(n) = pu.cross(pv).try_normalize() {
        return n;
    }
    let inset = |t: f64| t + (0.5 - t) * 1e-4;
    let (_, pu, pv) = evaluate(points, inset(u), inset(v));
    pu.cross(pv).normalize_or_zero()
}

struct Pieces<'a> {
    patch: &'a BicubicPatch,
    /// Vertices by the bits of their parameters, so that pieces share corners.
    ids: HashMap<[u64; 2], u32>,
    vertices: Vec<DVec3>,
    normals: Vec<DVec3>,
    uvs: Vec<DVec2>,
    faces: Vec<MeshFace>,
}

/// The control points of a row or column cut in half at its middle (de Casteljau's
/// construction): the points of the first half and of the second.
fn halve(p: [DVec3; 4]) -> ([DVec3; 4], [DVec3; 4]) {
    let ab = (p[0] + p[1]) * 0.5;
    let bc = (p[1] + p[2]) * 0.5;
    let cd = (p[2] + p[3]) * 0.5;
    let abc = (ab + bc) * 0.5;
    let bcd = (bc + cd) * 0.5;
    let middle = (abc + bcd) * 0.5;
    ([p[0], ab, abc, middle], [middle, bcd, cd, p[3]])
}

/// A net of control points cut in half across u (along each row).
fn halve_u(net: &Net) -> (Net, Net) {
    let (mut low, mut high) = ([[DVec3::ZERO; 4]; 4], [[DVec3::ZERO; 4]; 4]);
    for j in 0..4 {
        (low[j], high[j]) = halve(net[j]);
    }
    (low, high)
}

/// A net of control points cut in half across v (along each column).
fn halve_v(net: &Net) -> (Net, Net) {
    let (mut low, mut high) = ([[DVec3::ZERO; 4]; 4], [[DVec3::ZERO; 4]; 4]);
    for i in 0..4 {
        let (a, b) = halve([net[0][i], net[1][i], net[2][i], net[3][i]]);
        for j in 0..4 {
            low[j][i] = a[j];
            high[j][i] = b[j];
        }
    }
    (low, high)
}

/// Control points in rows: `net[v][u]`.
type Net = [[DVec3; 4]; 4];

impl Pieces<'_> {
    /// Cuts the piece with control points `net` over the parameter rectangle
    /// `[u0, v0, u1, v1]` while steps remain and it is not flat enough, then adds its
    /// triangles. `u_steps` halves u, along the rows; POV-Ray's own `u_steps` keyword
    /// counts the other way, from row to row.
    fn split(&mut self, net: &Net, [u0, v0, u1, v1]: [f64; 4], u_steps: u32, v_steps: u32) {
        if (u_steps > 0 || v_steps > 0) && !self.flat(net) {
            let (um, vm) = ((u0 + u1) * 0.5, (v0 + v1) * 0.5);
            let rows: Vec<(Net, f64, f64)> = if v_steps > 0 {
                let (low, high) = halve_v(net);
                vec![(low, v0, vm), (high, vm, v1)]
            } else {
                vec![(*net, v0, v1)]
            };
            let (u_next, v_next) = (u_steps.saturating_sub(1), v_steps.saturating_sub(1));
            for (row, a, b) in rows {
                if u_steps > 0 {
                    let (low, high) = halve_u(&row);
                    self.split(&low, [u0, a, um, b], u_next, v_next);
                    self.split(&high, [um, a, u1, b], u_next, v_next);
                } else {
                    self.split(&row, [u0, a, u1, b], u_next, v_next);
                }
            }
            return;
        }
        let a = self.vertex(u0, v0);
        let b = self.vertex(u1, v0);
        let c = self.vertex(u1, v1);
        let d = self.vertex(u0, v1);
        for vertices in [[a, b, c], [a, c, d]] {
            let [p, q, r] = vertices.map(|i| self.vertices[i as usize]);
            if (q - p).cross(r - p).length_squared() == 0.0 {
                continue;
            }
            self.faces.push(MeshFace {
                vertices,
                normals: Some(vertices),
                uvs: Some(vertices),
                texture: FaceTexture::Object,
            });
        }
    }

    /// Whether a piece is flat enough to stop, as POV-Ray judges it: with a positive
    /// `flatness`, every control point lies within that distance of the plane through the
    /// corners at the start of the first row, its end and the start of the last row.
    fn flat(&self, net: &Net) -> bool {
        let flatness = self.patch.flatness;
        if flatness <= 0.0 {
            return false;
        }
        let origin = net[0][0];
        let Some(normal) = (net[0][3] - origin)
            .cross(net[3][0] - origin)
            .try_normalize()
        else {
            return false;
        };
        net.iter()
            .flatten()
            .all(|p| (*p - origin).dot(normal).abs() <= flatness)
    }

    /// The vertex at parameters (u, v), made once.
    fn vertex(&mut self, u: f64, v: f64) -> u32 {
        if let Some(id) = self.ids.get(&[u.to_bits(), v.to_bits()]) {
            return *id;
        }
        let points = &self.patch.points;
        let [c0, c1, c2, c3] = self.patch.uv_corners;
        let id = self.vertices.len() as u32;
        self.vertices.push(evaluate(points, u, v).0);
        self.normals.push(surface_normal(points, u, v));
        self.uvs.push(
            c0 * ((1.0 - u) * (1.0 - v))
                + c1 * (u * (1.0 - v))
                + c2 * (u * v)
                + c3 * ((1.0 - u) * v),
        );
        self.ids.insert([u.to_bits(), v.to_bits()], id);
        id
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn saddle(u_steps: u32, v_steps: u32, flatness: f64) -> BicubicPatch {
        let mut points = [[DVec3::ZERO; 4]; 4];
        for (j, row) in points.iter_mut().enumerate() {
            for (i, p) in row.iter_mut().enumerate() {
                let (x, y) = (i as f64, j as f64);
                *p = DVec3::new(x, y, (x - 1.5) * (y - 1.5) * 0.5);
            }
        }
        BicubicPatch {
            kind: 1,
            flatness,
            u_steps,
            v_steps,
            uv_corners: BicubicPatch::DEFAULT_UV,
            points,
        }
    }

    #[test]
    fn steps_halve_the_patch() {
        let mesh = tessellate(&saddle(3, 2, 0.0)).unwrap();
        assert_eq!(mesh.face_count(), 2 * 8 * 4);
        assert_eq!(tessellate(&saddle(0, 0, 0.0)).unwrap().face_count(), 2);
    }

    #[test]
    fn flatness_stops_where_the_surface_is_flat() {
        let mut flat = saddle(4, 4, 0.1);
        for row in &mut flat.points {
            for p in row {
                p.z = 0.0;
            }
        }
        assert_eq!(tessellate(&flat).unwrap().face_count(), 2);
        let curved = tessellate(&saddle(4, 4, 0.05)).unwrap().face_count();
        assert!(curved > 2 && curved < 2 * 256, "{curved}");
    }

    #[test]
    fn halving_keeps_the_surface() {
        let patch = saddle(0, 0, 0.0);
        let (low, high) = halve_u(&patch.points);
        let (_, high_v) = halve_v(&high);
        // The corner of the quarter at u, v >= 0.5 is the surface point at (0.5, 0.5).
        let (p, _, _) = evaluate(&patch.points, 0.5, 0.5);
        assert!(high_v[0][0].abs_diff_eq(p, 1e-12));
        let (q, _, _) = evaluate(&low, 1.0, 0.25);
        let (r, _, _) = evaluate(&patch.points, 0.5, 0.25);
        assert!(q.abs_diff_eq(r, 1e-12));
    }

    #[test]
    fn the_surface_interpolates_its_corners() {
        let patch = saddle(0, 0, 0.0);
        let (p, pu, pv) = evaluate(&patch.points, 1.0, 1.0);
        assert!(p.abs_diff_eq(patch.points[3][3], 1e-12));
        // The derivative along u at a corner points at the neighbouring control point.
        assert!(
            pu.normalize()
                .abs_diff_eq((patch.points[3][3] - patch.points[3][2]).normalize(), 1e-12)
        );
        assert!(
            pv.normalize()
                .abs_diff_eq((patch.points[3][3] - patch.points[2][3]).normalize(), 1e-12)
        );
    }
}
