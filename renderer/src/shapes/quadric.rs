//! `quadric`: the surface A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z + J = 0,
//! inside where the sum is negative. Written as pᵀMp + g·p + J with M symmetric, the sum
//! along a ray is a quadratic in t whose coefficients are three dot products, so a ray
//! costs a few multiplications and one square root instead of the general polynomial
//! expansion that `poly` needs.

use super::Roots;
use super::poly::search_span;
use crate::bounds::Aabb;
use crate::ray::Ray;
use glam::{DMat3, DVec3};

#[derive(Debug, Clone, PartialEq)]
pub struct Quadric {
    /// The symmetric matrix of the quadratic part: the squares' coefficients on the
    /// diagonal, half of each mixed term's off it.
    matrix: DMat3,
    linear: DVec3,
    constant: f64,
    /// Where the surface is looked for: the `bounded_by` box or the ellipsoid's own, in
    /// the shape's frame.
    region: Option<Aabb>,
    /// The box around the surface: the region, or a cylinder's box, infinite along its
    /// axis, or the infinite box.
    extent: Aabb,
}

impl Quadric {
    /// The quadric with the coefficients of POV-Ray's four vectors: the squares (A, B,
    /// C), the mixed terms (D, E, F), the linear terms (G, H, I) and the constant J,
    /// looked for inside `bounded` (the `bounded_by` box) if given.
    pub fn new(
        squares: DVec3,
        mixed: DVec3,
        linear: DVec3,
        constant: f64,
        bounded: Option<Aabb>,
    ) -> Quadric {
        let matrix = DMat3::from_cols(
            DVec3::new(squares.x, mixed.x / 2.0, mixed.y / 2.0),
            DVec3::new(mixed.x / 2.0, squares.y, mixed.z / 2.0),
            DVec3::new(mixed.y / 2.0, mixed.z / 2.0, squares.z),
        );
        let region = match (bounded, ellipsoid_box(matrix, linear, constant)) {
            (Some(a), Some(b)) => Some(a.intersection(&b)),
            (a, b) => a.or(b),
        };
        let extent = region
            .or_else(|| cylinder_box(matrix, linear, constant))
            .unwrap_or(Aabb::INFINITE);
        Quadric {
            matrix,
            linear,
            constant,
            region,
            extent,
        }
    }

    pub fn value(&self, p: DVec3) -> f64 {
        p.dot(self.matrix * p) + self.linear.dot(p) + self.constant
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.value(p) < 0.0
    }

    /// The gradient of the sum, 2Mp + g.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        2.0 * (self.matrix * p) + self.linear
    }

    pub fn bounds(&self) -> Aabb {
        self.extent
    }

    /// The crossings of the ray, ascending, at most two. The quadratic is built around a
    /// point of the ray near the shape, so that a far origin costs no precision: at
    /// p = o + c·d it is (dᵀMd) s² + 2 (dᵀMp + g·d/2) s + value(p) in s = t - c.
    fn roots(&self, ray: &Ray) -> ([f64; 2], usize) {
        let mut found = [0.0; 2];
        let Some((lo, hi, centre)) = search_span(self.region.as_ref(), ray) else {
            return (found, 0);
        };
        let d = ray.direction;
        let p = ray.origin + d * centre;
        let md = self.matrix * d;
        let a = d.dot(md);
        let half_b = md.dot(p) + 0.5 * self.linear.dot(d);
        let c = self.value(p);
        let mut n = 0;
        if let Some((s0, s1)) = super::solve_quadratic_half(a, half_b, c) {
            for s in [s0, s1] {
                let t = s + centre;
                if t >= lo && t <= hi && n < 2 {
                    found[n] = t;
                    n += 1;
                }
            }
        }
        (found, n)
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let (found, n) = self.roots(ray);
        for &t in &found[..n] {
            roots.push(t, 0);
        }
    }

    /// The nearest crossing in `(tmin, tmax)`.
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<f64> {
        let (found, n) = self.roots(ray);
        found[..n].iter().copied().find(|&t| t > tmin && t < tmax)
    }
}

/// The box around a quadric that is an ellipsoid (its matrix M positive definite, so that
/// its inside is the bounded one), for the hierarchy and the root search; `None` for the
/// unbounded quadrics. The centre is `-M⁻¹g/2`, and the surface is `yᵀMy = k` around it
/// with `k = x₀ᵀMx₀ - J`, reaching `√(k (M⁻¹)ᵢᵢ)` along axis `i`.
fn ellipsoid_box(m: DMat3, linear: DVec3, constant: f64) -> Option<Aabb> {
    let minor2 = m.x_axis.x * m.y_axis.y - m.x_axis.y * m.x_axis.y;
    if !(m.x_axis.x > 0.0 && minor2 > 0.0 && m.determinant() > 0.0) {
        return None;
    }
    let inverse = m.inverse();
    let centre = -0.5 * (inverse * linear);
    let k = centre.dot(m * centre) - constant;
    if !(k > 0.0 && k.is_finite()) {
        return None;
    }
    let reach = DVec3::new(inverse.x_axis.x, inverse.y_axis.y, inverse.z_axis.z) * k;
    let reach = DVec3::new(reach.x.sqrt(), reach.y.sqrt(), reach.z.sqrt());
    // A hair wider, so that roots on the box's faces are not lost to rounding.
    let reach = reach * (1.0 + 1e-9) + DVec3::splat(1e-12 * reach.max_element());
    Some(Aabb::new(centre - reach, centre + reach))
}

/// The box around a quadric that does not depend on one or two of the axes (no square,
/// mixed or linear term names them) and is an ellipse or a pair of planes across the
/// others: a cylinder along the free axes, whose box is infinite along them. Giving each
/// free axis a square of its own turns it into an ellipsoid with the same extent across
/// them (the free axis decouples, and its centre coordinate is 0), so the ellipsoid's box
/// gives the finite sides. `None` for other quadrics.
fn cylinder_box(m: DMat3, linear: DVec3, constant: f64) -> Option<Aabb> {
    let free = [0, 1, 2].map(|i| m.col(i) == DVec3::ZERO && linear[i] == 0.0);
    if free == [false; 3] || free == [true; 3] {
        return None;
    }
    let mut closed = m;
    for (i, &free) in free.iter().enumerate() {
        if free {
            closed.col_mut(i)[i] = 1.0;
        }
    }
    let mut b = ellipsoid_box(closed, linear, constant)?;
    for (i, &free) in free.iter().enumerate() {
        if free {
            b.min[i] = f64::NEG_INFINITY;
            b.max[i] = f64::INFINITY;
        }
    }
    Some(b)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// x² + 4y² + 2z² - 1: an ellipsoid.
    fn ellipsoid() -> Quadric {
        Quadric::new(
            DVec3::new(1.0, 4.0, 2.0),
            DVec3::ZERO,
            DVec3::ZERO,
            -1.0,
            None,
        )
    }

    #[test]
    fn a_ray_crosses_the_ellipsoid_twice_in_order() {
        let ray = Ray::new(DVec3::new(0.0, -5.0, 0.0), DVec3::Y);
        let mut roots = Roots::new();
        ellipsoid().intersect(&ray, &mut roots);
        let t: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
        assert_eq!(t.len(), 2, "{t:?}");
        assert!(
            (t[0] - 4.5).abs() < 1e-12 && (t[1] - 5.5).abs() < 1e-12,
            "{t:?}"
        );
        assert_eq!(ellipsoid().first_hit(&ray, 4.6, 10.0), Some(t[1]));
    }

    /// The mixed and linear terms enter as in the expanded sum: (x - y)² + z² + 2x - 1
    /// along a ray agrees with the sum evaluated point by point.
    #[test]
    fn crossings_are_zeros_of_the_sum() {
        let q = Quadric::new(
            DVec3::ONE,
            DVec3::new(-2.0, 0.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            -1.0,
            None,
        );
        let ray = Ray::new(DVec3::new(-3.0, 0.4, -2.0), DVec3::new(1.0, 0.1, 0.7));
        let (found, n) = q.roots(&ray);
        assert_eq!(n, 2);
        for &t in &found[..n] {
            assert!(q.value(ray.at(t)).abs() < 1e-10, "{}", q.value(ray.at(t)));
        }
        let p = ray.at(found[0]);
        let expected = DVec3::new(2.0 * (p.x - p.y) + 2.0, -2.0 * (p.x - p.y), 2.0 * p.z);
        assert!((q.normal(p) - expected).length() < 1e-12);
    }

    /// A cylinder, x² + z² = 1, met far away: the roots keep their precision, and a ray
    /// along its axis meets nothing.
    #[test]
    fn far_rays_keep_precision_and_parallel_rays_miss() {
        let q = Quadric::new(
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::ZERO,
            DVec3::ZERO,
            -1.0,
            None,
        );
        let ray = Ray::new(DVec3::new(-1.0e6, 3.0, 0.5), DVec3::X);
        let (found, n) = q.roots(&ray);
        assert_eq!(n, 2);
        let half = 0.75f64.sqrt();
        assert!((found[0] - (1.0e6 - half)).abs() < 1e-8, "{found:?}");
        assert!((found[1] - (1.0e6 + half)).abs() < 1e-8, "{found:?}");
        let along = Ray::new(DVec3::new(0.5, -5.0, 0.0), DVec3::Y);
        assert_eq!(q.roots(&along).1, 0);
    }

    /// A bounding region keeps only the crossings inside it.
    #[test]
    fn the_region_clips_the_crossings() {
        let region = Aabb::new(DVec3::new(0.0, -2.0, -2.0), DVec3::splat(2.0));
        let q = Quadric::new(
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::ZERO,
            DVec3::ZERO,
            -1.0,
            Some(region),
        );
        let ray = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
        let (found, n) = q.roots(&ray);
        assert_eq!(n, 1);
        assert!((found[0] - 6.0).abs() < 1e-12);
    }

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).abs().max_element() < 1e-8
    }

    fn ellipsoid_box(squares: DVec3, mixed: DVec3, linear: DVec3, constant: f64) -> Option<Aabb> {
        super::ellipsoid_box(
            Quadric::new(squares, mixed, linear, constant, None).matrix,
            linear,
            constant,
        )
    }

    #[test]
    fn ellipsoids_have_their_box_and_other_quadrics_none() {
        // x² + 4y² + 2z² = 1.
        let b = ellipsoid_box(DVec3::new(1.0, 4.0, 2.0), DVec3::ZERO, DVec3::ZERO, -1.0).unwrap();
        assert!(close(b.max, DVec3::new(1.0, 0.5, 0.5f64.sqrt())), "{b:?}");
        assert!(close(b.min, -b.max), "{b:?}");
        // (x - 1)² + y² + z² = 1, written out.
        let b = ellipsoid_box(DVec3::ONE, DVec3::ZERO, DVec3::new(-2.0, 0.0, 0.0), 0.0).unwrap();
        assert!(close(b.min, DVec3::new(0.0, -1.0, -1.0)), "{b:?}");
        assert!(close(b.max, DVec3::new(2.0, 1.0, 1.0)), "{b:?}");
        // A tilted ellipse, 2x² + 2xy + 2y² + z² = 1: the box reaches √(k (M⁻¹)ᵢᵢ).
        let b = ellipsoid_box(
            DVec3::new(2.0, 2.0, 1.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::ZERO,
            -1.0,
        )
        .unwrap();
        assert!(
            close(
                b.max,
                DVec3::new((2.0f64 / 3.0).sqrt(), (2.0f64 / 3.0).sqrt(), 1.0)
            ),
            "{b:?}"
        );
        // A hyperboloid, a cylinder, an inside-out sphere and an empty one have no
        // ellipsoid's box.
        for (squares, constant) in [
            (DVec3::new(1.0, -1.0, 1.0), -0.3),
            (DVec3::new(1.0, 0.0, 1.0), -0.25),
            (DVec3::splat(-1.0), 1.0),
            (DVec3::ONE, 1.0),
        ] {
            assert!(ellipsoid_box(squares, DVec3::ZERO, DVec3::ZERO, constant).is_none());
        }
    }

    #[test]
    fn cylinders_are_bounded_across_their_axis() {
        // (x - 1)² + 4z² = 1, along y.
        let q = Quadric::new(
            DVec3::new(1.0, 0.0, 4.0),
            DVec3::ZERO,
            DVec3::new(-2.0, 0.0, 0.0),
            0.0,
            None,
        );
        let b = q.bounds();
        assert!(close(
            DVec3::new(b.min.x, 0.0, b.min.z),
            DVec3::new(0.0, 0.0, -0.5)
        ));
        assert!(close(
            DVec3::new(b.max.x, 0.0, b.max.z),
            DVec3::new(2.0, 0.0, 0.5)
        ));
        assert!(b.min.y == f64::NEG_INFINITY && b.max.y == f64::INFINITY);
        // The crossings are not confined to a region: a ray along the axis far out
        // still meets the surface.
        assert!(q.region.is_none());
        let ray = Ray::new(DVec3::new(-5.0, 1.0e6, 0.0), DVec3::X);
        assert_eq!(q.roots(&ray).1, 2);
        // Two parallel planes, x² = 1, bound x alone; a hyperboloid, an inside-out
        // cylinder and a cylinder tilted off the axes have no such box.
        let slab = Quadric::new(DVec3::X, DVec3::ZERO, DVec3::ZERO, -1.0, None).bounds();
        assert!(close(
            DVec3::new(slab.min.x, slab.max.x, 0.0),
            DVec3::new(-1.0, 1.0, 0.0)
        ));
        assert!(slab.min.y.is_infinite() && slab.max.z.is_infinite());
        for (squares, mixed, constant) in [
            (DVec3::new(1.0, -1.0, 0.0), DVec3::ZERO, -0.3),
            (DVec3::new(-1.0, 0.0, -1.0), DVec3::ZERO, 1.0),
            (DVec3::new(1.0, 1.0, 0.0), DVec3::new(-2.0, 0.0, 0.0), -1.0),
        ] {
            let q = Quadric::new(squares, mixed, DVec3::ZERO, constant, None);
            assert_eq!(q.bounds(), Aabb::INFINITE, "{squares:?}");
        }
    }
}
