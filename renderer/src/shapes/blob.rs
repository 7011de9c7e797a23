//! `blob { threshold t  sphere { } cylinder { } ... }`: the surface where the summed
//! field of the components equals the threshold, inside where it is larger. A component
//! of radius r and strength s adds s (1 - d²/r²)² within distance d < r of its centre (a
//! sphere) or of its axis segment (a cylinder with hemispherical ends), as the manual
//! gives it. Along a ray d² is a quadratic in t on each stretch (for a cylinder: before,
//! along and past its axis), so the field is a sum of quartics between the points where
//! the ray enters or leaves a component's reach; each stretch's quartic, written about
//! its middle, is solved for the threshold.

use super::OrderedCrossings;
use super::plane_curve;
use crate::bounds::Aabb;
use crate::material::SurfaceWeights;
use crate::ray::Ray;
use analysis::scene::math_shapes::BlobShape;
use glam::{DAffine3, DVec3};
use std::sync::Arc;

/// One component in its own frame, with the frame's placement in the blob.
#[derive(Debug, Clone, PartialEq)]
pub struct Component {
    pub shape: BlobShape,
    pub radius: f64,
    pub strength: f64,
    /// From the blob's coordinates to the component's.
    pub to_local: DAffine3,
    /// Transposed linear part of `to_local`, which carries gradients back.
    gradient_back: glam::DMat3,
    bounds: Aabb,
}

/// A stretch of the ray where one component's d² is the quadratic q[0] + q[1] t + q[2] t².
#[derive(Debug, Clone, Copy)]
struct Span {
    t0: f64,
    t1: f64,
    q: [f64; 3],
    strength: f64,
    inv_r2: f64,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Blob {
    components: Vec<Component>,
    threshold: f64,
    sturm: bool,
    bounds: Aabb,
}

impl Component {
    /// `to_blob`: from the component's coordinates to the blob's.
    pub fn new(shape: BlobShape, radius: f64, strength: f64, to_blob: DAffine3) -> Component {
        let r = radius.abs();
        let local = match shape {
            BlobShape::Sphere { center } => Aabb::new(center - r, center + r),
            BlobShape::Cylinder { end1, end2 } => Aabb::new(end1.min(end2) - r, end1.max(end2) + r),
        };
        let to_local = to_blob.inverse();
        Component {
            shape,
            radius: r,
            strength,
            gradient_back: to_local.matrix3.transpose(),
            to_local,
            bounds: local.transformed(&to_blob),
        }
    }

    /// d² at a point of the component's frame, and the point of the centre or axis
    /// nearest it.
    fn distance2(&self, p: DVec3) -> (f64, DVec3) {
        let nearest = match self.shape {
            BlobShape::Sphere { center } => center,
            BlobShape::Cylinder { end1, end2 } => {
                let w = end2 - end1;
                let l2 = w.length_squared();
                let k = if l2 > 0.0 {
                    ((p - end1).dot(w) / l2).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                end1 + w * k
            }
        };
        ((p - nearest).length_squared(), nearest)
    }

    fn field(&self, p: DVec3) -> f64 {
        let (d2, _) = self.distance2(self.to_local.transform_point3(p));
        let r2 = self.radius * self.radius;
        if d2 >= r2 {
            return 0.0;
        }
        let k = 1.0 - d2 / r2;
        self.strength * k * k
    }

    fn gradient(&self, p: DVec3) -> DVec3 {
        let local = self.to_local.transform_point3(p);
        let (d2, nearest) = self.distance2(local);
        let r2 = self.radius * self.radius;
        if d2 >= r2 {
            return DVec3::ZERO;
        }
        // d/dp of s (1 - d²/r²)² = -4 s (1 - d²/r²) (p - nearest) / r².
        let local_gradient = (local - nearest) * (-4.0 * self.strength * (1.0 - d2 / r2) / r2);
        self.gradient_back * local_gradient
    }

    /// The stretches of the ray within the component's reach.
    fn spans(&self, ray: &Ray, out: &mut Vec<Span>) {
        let o = self.to_local.transform_point3(ray.origin);
        let d = self.to_local.transform_vector3(ray.direction);
        let r2 = self.radius * self.radius;
        let mut push = |q: [f64; 3], lo: f64, hi: f64| {
            // Where q < r² within [lo, hi].
            if let Some((a, b)) = super::solve_quadratic_half(q[2], 0.5 * q[1], q[0] - r2) {
                let (t0, t1) = (a.max(lo), b.min(hi));
                if t0 < t1 && q[2] > 0.0 {
                    out.push(Span {
                        t0,
                        t1,
                        q,
                        strength: self.strength,
                        inv_r2: 1.0 / r2,
                    });
                }
            }
        };
        let around = |c: DVec3| {
            let v = o - c;
            [v.length_squared(), 2.0 * v.dot(d), d.length_squared()]
        };
        match self.shape {
            BlobShape::Sphere { center } => push(around(center), f64::NEG_INFINITY, f64::INFINITY),
            BlobShape::Cylinder { end1, end2 } => {
                let w = end2 - end1;
                let l2 = w.length_squared();
                let (k0, k1) = ((o - end1).dot(w) / l2, d.dot(w) / l2);
                if l2 == 0.0 || !k0.is_finite() {
                    push(around(end1), f64::NEG_INFINITY, f64::INFINITY);
                    return;
                }
                // Where the projection on the axis passes 0 and 1.
                let (mut ta, mut tb) = (f64::NEG_INFINITY, f64::INFINITY);
                if k1 != 0.0 {
                    let (x, y) = (-k0 / k1, (1.0 - k0) / k1);
                    ta = x.min(y);
                    tb = x.max(y);
                } else if !(0.0..=1.0).contains(&k0) {
                    tb = ta;
                }
                // Along the axis: the distance from it, |v|² - (v·w)²/|w|².
                let v = o - end1;
                let (vw, dw) = (v.dot(w), d.dot(w));
                let q = [
                    v.length_squared() - vw * vw / l2,
                    2.0 * (v.dot(d) - vw * dw / l2),
                    d.length_squared() - dw * dw / l2,
                ];
                if ta < tb {
                    push(q, ta, tb);
                }
                // Before and past the axis the ends' hemispheres; which end comes first
                // depends on the ray's direction along the axis.
                let (first, last) = if k1 >= 0.0 {
                    (end1, end2)
                } else {
                    (end2, end1)
                };
                push(around(first), f64::NEG_INFINITY, ta);
                push(around(last), tb, f64::INFINITY);
            }
        }
    }
}

impl Blob {
    pub fn new(components: Vec<Component>, threshold: f64, sturm: bool) -> Option<Blob> {
        let bounds = components
            .iter()
            .filter(|c| c.strength > 0.0)
            .fold(Aabb::EMPTY, |b, c| b.union(&c.bounds));
        // Without a positive component the field never reaches the (positive) threshold.
        if bounds.is_empty() {
            return None;
        }
        Some(Blob {
            components,
            threshold,
            sturm,
            bounds,
        })
    }

    pub fn bounds(&self) -> Aabb {
        self.bounds
    }

    pub fn field(&self, p: DVec3) -> f64 {
        self.components.iter().map(|c| c.field(p)).sum()
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.field(p) > self.threshold
    }

    /// Outward: the field falls away from the inside.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        -self.components.iter().map(|c| c.gradient(p)).sum::<DVec3>()
    }
}

/// The blend of a blob's component textures: each component's share of the (positive)
/// field at the point, the blob's own texture first with no weight of its own.
#[derive(Debug)]
struct ComponentShares {
    blob: Blob,
    to_local: DAffine3,
}

impl SurfaceWeights for ComponentShares {
    fn weights(&self, p: DVec3, out: &mut Vec<f64>) {
        let p = self.to_local.transform_point3(p);
        out.push(0.0);
        out.extend(self.blob.components.iter().map(|c| c.field(p).max(0.0)));
    }
}

impl Blob {
    /// Weights for blending the blob's texture (first) and its components' (then, in
    /// order), given the map from world to the blob's frame.
    pub fn texture_weights(&self, to_local: DAffine3) -> Arc<dyn SurfaceWeights> {
        Arc::new(ComponentShares {
            blob: self.clone(),
            to_local,
        })
    }
}

impl OrderedCrossings for Blob {
    fn crossings(&self, ray: &Ray, tmin: f64, tmax: f64, take: &mut dyn FnMut(f64) -> bool) {
        let inv = ray.direction.recip();
        let Some((lo, hi)) = self.bounds.clip(ray, inv, tmin, tmax) else {
            return;
        };
        let mut spans = Vec::new();
        for c in &self.components {
            if c.bounds.clip(ray, inv, lo, hi).is_some() {
                c.spans(ray, &mut spans);
            }
        }
        if spans.is_empty() {
            return;
        }
        let mut events: Vec<f64> = spans.iter().flat_map(|s| [s.t0, s.t1]).collect();
        events.sort_by(f64::total_cmp);
        events.dedup();
        let mut found = Vec::new();
        for w in events.windows(2) {
            let (a, b) = (w[0].max(lo), w[1].min(hi));
            if a >= b {
                continue;
            }
            let m = 0.5 * (a + b);
            // The field about m, as a quartic in u = t - m, less the threshold.
            let mut quartic = [-self.threshold, 0.0, 0.0, 0.0, 0.0];
            let mut active = false;
            for s in spans.iter().filter(|s| s.t0 <= m && s.t1 >= m) {
                active = true;
                let q = [
                    s.q[0] + (s.q[1] + s.q[2] * m) * m,
                    s.q[1] + 2.0 * s.q[2] * m,
                    s.q[2],
                ];
                // s (1 - Q/r²)² = s (1 - 2Q/r² + Q²/r⁴).
                let k = s.inv_r2;
                let mut q2 = [0.0; 5];
                plane_curve::multiply(&q, &q, &mut q2);
                quartic[0] += s.strength;
                for i in 0..3 {
                    quartic[i] -= 2.0 * s.strength * k * q[i];
                }
                for i in 0..5 {
                    quartic[i] += s.strength * k * k * q2[i];
                }
            }
            if !active {
                continue;
            }
            found.clear();
            plane_curve::solve(&quartic, a - m, b - m, self.sturm, &mut found);
            for &u in &found {
                if take(m + u) {
                    return;
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::Roots;

    fn sphere(center: DVec3, radius: f64, strength: f64) -> Component {
        Component::new(
            BlobShape::Sphere { center },
            radius,
            strength,
            DAffine3::IDENTITY,
        )
    }

    #[test]
    fn one_sphere_is_a_sphere_inside_its_reach() {
        // s (1 - d²/r²)² = t  gives  d = r √(1 - √(t/s)).
        let blob = Blob::new(vec![sphere(DVec3::ZERO, 2.0, 1.0)], 0.25, false).unwrap();
        let radius = 2.0 * (1.0 - 0.5f64).sqrt();
        let ray = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        let t = blob.first_hit(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((t - (5.0 - radius)).abs() < 1e-9, "{t}");
        assert!(blob.normal(ray.at(t)).normalize().x < -0.999);
        let mut roots = Roots::new();
        blob.intersect(&ray, &mut roots);
        assert_eq!(roots.as_slice().len(), 2);
    }

    #[test]
    fn two_spheres_merge_between_them() {
        let blob = Blob::new(
            vec![
                sphere(DVec3::new(-0.75, 0.0, 0.0), 1.0, 1.0),
                sphere(DVec3::new(0.75, 0.0, 0.0), 1.0, 1.0),
            ],
            0.6,
            false,
        )
        .unwrap();
        // Alone each reaches 0.6 at d = 0.47; together the field at the middle is
        // 2 (1 - 0.5625)² = 0.383: a waist, not a bridge, at this threshold.
        assert!(!blob.inside(DVec3::ZERO));
        let lower = Blob::new(blob.components.clone(), 0.3, false).unwrap();
        assert!(lower.inside(DVec3::ZERO));
        let ray = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        let mut roots = Roots::new();
        blob.intersect(&ray, &mut roots);
        assert_eq!(roots.as_slice().len(), 4);
        let mut roots = Roots::new();
        lower.intersect(&ray, &mut roots);
        assert_eq!(roots.as_slice().len(), 2);
    }

    #[test]
    fn a_cylinder_has_round_ends() {
        let c = Component::new(
            BlobShape::Cylinder {
                end1: DVec3::ZERO,
                end2: DVec3::new(0.0, 2.0, 0.0),
            },
            1.0,
            1.0,
            DAffine3::IDENTITY,
        );
        let blob = Blob::new(vec![c], 0.25, false).unwrap();
        let radius = 0.5f64.sqrt();
        // Across the middle, and straight down onto the top end's hemisphere.
        let across = Ray::new(DVec3::new(-3.0, 1.0, 0.0), DVec3::X);
        let t = blob.first_hit(&across, 0.0, f64::INFINITY).unwrap();
        assert!((t - (3.0 - radius)).abs() < 1e-9);
        let down = Ray::new(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y);
        let t = blob.first_hit(&down, 0.0, f64::INFINITY).unwrap();
        assert!((t - (3.0 - radius)).abs() < 1e-9, "{t}");
        // Slantwise, every crossing lies on the surface.
        let slant = Ray::new(DVec3::new(-3.0, -1.0, 0.2), DVec3::new(1.0, 1.1, 0.0));
        let mut roots = Roots::new();
        blob.intersect(&slant, &mut roots);
        assert!(!roots.as_slice().is_empty());
        for r in roots.as_slice() {
            assert!((blob.field(slant.at(r.t)) - 0.25).abs() < 1e-9);
        }
    }
}
