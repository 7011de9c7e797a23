//! `text`: glyph outlines extruded along z from 0 to the thickness, intersected exactly. A
//! ray meets the front and back faces where its crossing point lies inside the outline
//! (the contours wind around it), and the side walls where its shadow on the x-y plane
//! crosses an outline curve, a polynomial of degree 1 to 3 in the curve's parameter.
//! Each glyph keeps its own box, so a ray only looks at the glyphs it passes near.

use super::solve_quadratic_half;
use super::{Root, Roots};
use crate::bounds::Aabb;
use crate::polynomial::cubic_roots_in;
use crate::ray::Ray;
use analysis::scene::math_shapes::{self, OutlineSegment};
use glam::{DVec2, DVec3};

/// Parts of the surface, for the normal.
const FRONT: u32 = 0;
const BACK: u32 = 1;
const SIDE: u32 = 2;

#[derive(Debug, Clone, PartialEq)]
pub struct Text {
    glyphs: Vec<Glyph>,
    thickness: f64,
    bounds: Aabb,
}

#[derive(Debug, Clone, PartialEq)]
struct Glyph {
    curves: Vec<Curve>,
    bounds: Aabb,
}

/// An outline segment in power form: the point at s in 0..1 is Σ c[k] sᵏ.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Curve {
    c: [DVec2; 4],
    degree: usize,
    /// The lowest and highest y of its points, to skip it quickly.
    y_range: (f64, f64),
}

impl Curve {
    fn new(segment: &OutlineSegment) -> Curve {
        let (c, degree) = match *segment {
            OutlineSegment::Line(a, b) => ([a, b - a, DVec2::ZERO, DVec2::ZERO], 1),
            OutlineSegment::Quad(a, b, c) => ([a, 2.0 * (b - a), a - 2.0 * b + c, DVec2::ZERO], 2),
            OutlineSegment::Cubic(a, b, c, d) => (
                [
                    a,
                    3.0 * (b - a),
                    3.0 * (a - 2.0 * b + c),
                    d - a + 3.0 * (b - c),
                ],
                3,
            ),
        };
        let points = segment.points();
        let y_range = points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p.y), hi.max(p.y))
            });
        Curve { c, degree, y_range }
    }

    fn at(&self, s: f64) -> DVec2 {
        ((self.c[3] * s + self.c[2]) * s + self.c[1]) * s + self.c[0]
    }

    fn tangent(&self, s: f64) -> DVec2 {
        (self.c[3] * (3.0 * s) + self.c[2] * 2.0) * s + self.c[1]
    }

    /// The parameters in [0, 1] where `coeffs · (x(s), y(s)) = value`.
    fn solve(&self, along: DVec2, value: f64) -> ([f64; 3], usize) {
        let k = |i: usize| self.c[i].dot(along);
        let coeffs = [k(0) - value, k(1), k(2), k(3)];
        let mut found = ([0.0; 3], 0);
        let mut keep = |s: f64| {
            if (0.0..=1.0).contains(&s) && found.1 < 3 {
                found.0[found.1] = s;
                found.1 += 1;
            }
        };
        match self.degree {
            1 => {
                if coeffs[1] != 0.0 {
                    keep(-coeffs[0] / coeffs[1]);
                }
            }
            2 => {
                if let Some((a, b)) = solve_quadratic_half(coeffs[2], 0.5 * coeffs[1], coeffs[0]) {
                    keep(a);
                    if b != a {
                        keep(b);
                    }
                }
            }
            _ => {
                let (roots, n) = cubic_roots_in(&coeffs, 0.0, 1.0);
                for &s in &roots[..n] {
                    keep(s);
                }
            }
        }
        found
    }
}

impl Glyph {
    /// The winding number of the outline around `q`: crossings of the ray from `q`
    /// towards +x, counted by the direction the outline crosses it. The parameter range
    /// is half open so that a crossing at a joint of two curves counts once.
    fn winding(&self, q: DVec2) -> i32 {
        let mut winding = 0;
        for curve in &self.curves {
            if q.y < curve.y_range.0 || q.y > curve.y_range.1 {
                continue;
            }
            let (roots, n) = curve.solve(DVec2::Y, q.y);
            for &s in &roots[..n] {
                if s >= 1.0 {
                    continue;
                }
                let dy = curve.tangent(s).y;
                if dy != 0.0 && curve.at(s).x > q.x {
                    winding += if dy > 0.0 { 1 } else { -1 };
                }
            }
        }
        winding
    }

    fn contains(&self, q: DVec2) -> bool {
        q.x >= self.bounds.min.x
            && q.x <= self.bounds.max.x
            && q.y >= self.bounds.min.y
            && q.y <= self.bounds.max.y
            && self.winding(q) != 0
    }
}

impl Text {
    /// The runtime text; `None` when it has no outline at all (spaces only).
    pub fn new(text: &math_shapes::Text) -> Option<Text> {
        let thickness = text.thickness;
        let glyphs: Vec<Glyph> = text
            .glyphs
            .iter()
            .filter(|segments| !segments.is_empty())
            .map(|segments| {
                let mut lo = DVec2::splat(f64::INFINITY);
                let mut hi = DVec2::splat(f64::NEG_INFINITY);
                for p in segments.iter().flat_map(OutlineSegment::points) {
                    lo = lo.min(p);
                    hi = hi.max(p);
                }
                Glyph {
                    curves: segments.iter().map(Curve::new).collect(),
                    bounds: Aabb::new(lo.extend(thickness.min(0.0)), hi.extend(thickness.max(0.0))),
                }
            })
            .collect();
        if glyphs.is_empty() || thickness == 0.0 {
            return None;
        }
        let bounds = glyphs.iter().fold(Aabb::EMPTY, |b, g| b.union(&g.bounds));
        Some(Text {
            glyphs,
            thickness,
            bounds,
        })
    }

    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    /// Every crossing between `tmin` and `tmax`, unordered, into `found`.
    fn crossings(&self, ray: &Ray, tmin: f64, tmax: f64, found: &mut Vec<Root>) {
        let inverse = ray.direction.recip();
        let (z0, z1) = (self.thickness.min(0.0), self.thickness.max(0.0));
        let flat = ray.direction.truncate();
        let flat_length = flat.length_squared();
        for glyph in &self.glyphs {
            if glyph.bounds.clip(ray, inverse, tmin, tmax).is_none() {
                continue;
            }
            if ray.direction.z != 0.0 {
                for (z, part) in [(0.0, FRONT), (self.thickness, BACK)] {
                    let t = (z - ray.origin.z) / ray.direction.z;
                    if t > tmin
                        && t < tmax
                        && glyph.contains((ray.origin + ray.direction * t).truncate())
                    {
                        found.push(Root { t, part });
                    }
                }
            }
            if flat_length == 0.0 {
                continue;
            }
            // The curve meets the ray's shadow where its offset from the ray's origin is
            // parallel to the ray: zero along the shadow's perpendicular.
            let across = DVec2::new(-flat.y, flat.x);
            let origin = ray.origin.truncate();
            for curve in &glyph.curves {
                let (roots, n) = curve.solve(across, origin.dot(across));
                for &s in &roots[..n] {
                    let t = (curve.at(s) - origin).dot(flat) / flat_length;
                    let z = ray.origin.z + ray.direction.z * t;
                    if t > tmin && t < tmax && z >= z0 && z <= z1 {
                        found.push(Root { t, part: SIDE });
                    }
                }
            }
        }
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let mut found = Vec::new();
        self.crossings(ray, f64::NEG_INFINITY, f64::INFINITY, &mut found);
        found.sort_by(|a, b| a.t.total_cmp(&b.t));
        for root in found {
            roots.push(root.t, root.part);
        }
    }

    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        let mut found = Vec::new();
        self.crossings(ray, tmin, tmax, &mut found);
        found.into_iter().min_by(|a, b| a.t.total_cmp(&b.t))
    }

    pub fn inside(&self, p: DVec3) -> bool {
        let (z0, z1) = (self.thickness.min(0.0), self.thickness.max(0.0));
        p.z >= z0 && p.z <= z1 && self.glyphs.iter().any(|g| g.contains(p.truncate()))
    }

    /// The outward normal: ∓z on the faces; on the walls, across the outline curve that
    /// passes closest to the point.
    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match part {
            FRONT => return DVec3::new(0.0, 0.0, -self.thickness.signum()),
            BACK => return DVec3::new(0.0, 0.0, self.thickness.signum()),
            _ => {}
        }
        let q = p.truncate();
        let mut best = (f64::INFINITY, DVec2::X, 0usize);
        for (g, glyph) in self.glyphs.iter().enumerate() {
            let b = &glyph.bounds;
            let margin = 1e-6;
            if q.x < b.min.x - margin
                || q.x > b.max.x + margin
                || q.y < b.min.y - margin
                || q.y > b.max.y + margin
            {
                continue;
            }
            for curve in &glyph.curves {
                for (along, value) in [(DVec2::X, q.x), (DVec2::Y, q.y)] {
                    let (roots, n) = curve.solve(along, value);
                    for &s in &roots[..n] {
                        let distance = (curve.at(s) - q).length_squared();
                        if distance < best.0 {
                            best = (distance, curve.tangent(s), g);
                        }
                    }
                }
            }
        }
        let (_, tangent, g) = best;
        let mut normal = DVec2::new(tangent.y, -tangent.x).normalize_or_zero();
        // Fonts wind their outer contours either way; outward is where the glyph is not.
        let step = 1e-6 * (1.0 + q.abs().max_element());
        if self.glyphs[g].winding(q + normal * step) != 0 {
            normal = -normal;
        }
        normal.extend(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    /// A unit square with a square hole, the hole wound the other way, and one curved side.
    fn framed_square() -> Text {
        let p = DVec2::new;
        let outer = vec![
            OutlineSegment::Line(p(0.0, 0.0), p(0.0, 1.0)),
            OutlineSegment::Line(p(0.0, 1.0), p(1.0, 1.0)),
            OutlineSegment::Quad(p(1.0, 1.0), p(1.5, 0.5), p(1.0, 0.0)),
            OutlineSegment::Line(p(1.0, 0.0), p(0.0, 0.0)),
        ];
        let hole = vec![
            OutlineSegment::Line(p(0.25, 0.25), p(0.75, 0.25)),
            OutlineSegment::Line(p(0.75, 0.25), p(0.75, 0.75)),
            OutlineSegment::Line(p(0.75, 0.75), p(0.25, 0.75)),
            OutlineSegment::Line(p(0.25, 0.75), p(0.25, 0.25)),
        ];
        Text::new(&math_shapes::Text {
            glyphs: Arc::from(vec![[outer, hole].concat()]),
            thickness: 0.5,
        })
        .unwrap()
    }

    #[test]
    fn rays_hit_the_faces_but_not_the_hole() {
        let text = framed_square();
        let down = |x: f64, y: f64| Ray::new(DVec3::new(x, y, -1.0), DVec3::Z);
        let hit = text.first_hit(&down(0.1, 0.5), 0.0, f64::INFINITY).unwrap();
        assert_eq!((hit.t, hit.part), (1.0, FRONT));
        assert!(
            text.first_hit(&down(0.5, 0.5), 0.0, f64::INFINITY)
                .is_none()
        );
        // The curved side bulges to x = 1.25 at y = 0.5.
        assert!(
            text.first_hit(&down(1.2, 0.5), 0.0, f64::INFINITY)
                .is_some()
        );
        assert!(
            text.first_hit(&down(1.3, 0.5), 0.0, f64::INFINITY)
                .is_none()
        );
        let mut roots = Roots::new();
        text.intersect(&down(0.1, 0.5), &mut roots);
        let ts: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
        assert_eq!(ts, vec![1.0, 1.5]);
    }

    #[test]
    fn side_walls_are_met_exactly_and_face_outwards() {
        let text = framed_square();
        let ray = Ray::new(DVec3::new(3.0, 0.5, 0.25), -DVec3::X);
        let hit = text.first_hit(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 1.75).abs() < 1e-12, "{}", hit.t);
        let n = text.normal(ray.origin + ray.direction * hit.t, hit.part);
        assert!((n - DVec3::X).length() < 1e-9, "{n}");
        // Inside the hole, the wall faces into the hole.
        let ray = Ray::new(DVec3::new(0.5, 0.5, 0.25), DVec3::X);
        let hit = text.first_hit(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - 0.25).abs() < 1e-12);
        let n = text.normal(ray.origin + ray.direction * hit.t, hit.part);
        assert!((n + DVec3::X).length() < 1e-9, "{n}");
        assert!(text.inside(DVec3::new(0.1, 0.5, 0.25)));
        assert!(!text.inside(DVec3::new(0.5, 0.5, 0.25)));
    }
}
