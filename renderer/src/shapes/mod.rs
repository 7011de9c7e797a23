//! Shapes in their own canonical frames: each knows its bounds, where a ray crosses its
//! surface, whether a point is inside, and its normal; nothing of textures or of where it
//! sits in the world (an object's transform places it, pbrt's split).

pub mod bicubic_patch;
mod blob;
mod cone;
mod cuboid;
mod cylinder;
mod disc;
mod height_field;
mod isosurface;
mod julia;
mod lathe;
mod lemon;
mod math_shape;
pub mod mesh;
mod ovus;
mod parametric;
mod plane;
mod plane_curve;
mod poly;
mod polygon;
mod prism;
mod quadric;
mod sor;
mod span;
mod sphere;
mod sphere_sweep;
mod superellipsoid;
mod text;
mod torus;
mod triangle;

pub use cone::Cone;
pub use cuboid::Cuboid;
pub use cylinder::Cylinder;
pub use disc::Disc;
pub use math_shape::{MathShape, ShapeReport, build as build_math_shape};
pub use mesh::Mesh;
pub use plane::Plane;
pub use polygon::Polygon;
pub use span::Span;
pub use sphere::Sphere;
pub use torus::Torus;
pub use triangle::Triangle;

use crate::bounds::Aabb;
use crate::fast_math;
use crate::ray::Ray;
use glam::{DAffine3, DVec3};

/// Where a ray crosses a shape: the ray parameter and which part of the surface (a box
/// face, a cylinder cap, a mesh triangle), so that the normal can be found later for the
/// one hit that wins.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Root {
    pub t: f64,
    pub part: u32,
}

/// The crossings of one ray with one shape. The first few are kept on the stack, since
/// the array is built for every ray and shape and most shapes cross a ray at most four
/// times (a torus); shapes that may cross it more often (a lathe, a prism, a blob, a mesh)
/// spill the rest onto the heap, so that CSG sees every crossing.
#[derive(Debug, Clone)]
pub struct Roots {
    roots: [Root; Roots::INLINE],
    len: usize,
    spilled: Vec<Root>,
}

impl Roots {
    const INLINE: usize = 4;

    pub fn new() -> Roots {
        Roots {
            roots: [Root { t: 0.0, part: 0 }; Roots::INLINE],
            len: 0,
            spilled: Vec::new(),
        }
    }

    /// The nearest crossing inside `(tmin, tmax)`. Inlined, as the loop it stands for was,
    /// into the tests of shapes that find every crossing.
    #[inline]
    pub fn nearest_within(&self, tmin: f64, tmax: f64) -> Option<Root> {
        self.as_slice()
            .iter()
            .copied()
            .filter(|r| r.t > tmin && r.t < tmax)
            .min_by(|a, b| a.t.total_cmp(&b.t))
    }

    /// Records a crossing; NaN parameters (degenerate rays) are dropped here so that no
    /// caller has to think of them.
    pub fn push(&mut self, t: f64, part: u32) {
        if !t.is_finite() {
            return;
        }
        let root = Root { t, part };
        if self.len < Roots::INLINE {
            self.roots[self.len] = root;
            self.len += 1;
        } else {
            if self.spilled.is_empty() {
                self.spilled.extend_from_slice(&self.roots);
            }
            self.spilled.push(root);
        }
    }

    pub fn as_slice(&self) -> &[Root] {
        if self.spilled.is_empty() {
            &self.roots[..self.len]
        } else {
            &self.spilled
        }
    }
}

impl Default for Roots {
    fn default() -> Self {
        Roots::new()
    }
}

/// The first of `ts`, given in increasing order, that is a finite parameter inside
/// `(tmin, tmax)`: the crossing [`Roots`] would keep and a nearest-hit search would take.
#[inline(always)]
fn nearest_in(ts: &[f64], tmin: f64, tmax: f64) -> Option<f64> {
    ts.iter()
        .copied()
        .find(|&t| t.is_finite() && t > tmin && t < tmax)
}

/// A shape that finds its crossings nearest first and can stop at any of them (a blob, a
/// superellipsoid): every crossing for CSG, or the nearest in an interval for the rest.
pub(crate) trait OrderedCrossings {
    /// Hands the crossings in `(tmin, tmax)` to `take`, nearest first, until it returns
    /// true.
    fn crossings(&self, ray: &Ray, tmin: f64, tmax: f64, take: &mut dyn FnMut(f64) -> bool);

    fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        self.crossings(ray, f64::NEG_INFINITY, f64::INFINITY, &mut |t| {
            roots.push(t, 0);
            false
        });
    }

    fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<f64> {
        let mut found = None;
        self.crossings(ray, tmin, tmax, &mut |t| {
            if t > tmin && t < tmax {
                found = Some(t);
                true
            } else {
                false
            }
        });
        found
    }
}

/// A shape in its canonical frame.
#[derive(Debug, Clone, PartialEq)]
pub enum Shape {
    Sphere(Sphere),
    Cuboid(Cuboid),
    Cylinder(Cylinder),
    Cone(Cone),
    Plane(Plane),
    Disc(Disc),
    Torus(Torus),
    Triangle(Triangle),
    /// `mesh`, `mesh2` and the triangles of a `bicubic_patch`.
    Mesh(Mesh),
    Polygon(Polygon),
    /// Polynomials, isosurfaces, fractals, sweeps and the other mathematical shapes.
    Math(Box<MathShape>),
}

impl Shape {
    /// Every crossing of the ray with the surface, at any parameter.
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        match self {
            Shape::Sphere(s) => s.intersect(ray, roots),
            Shape::Cuboid(s) => s.intersect(ray, roots),
            Shape::Cylinder(s) => s.intersect(ray, roots),
            Shape::Cone(s) => s.intersect(ray, roots),
            Shape::Plane(s) => s.intersect(ray, roots),
            Shape::Disc(s) => s.intersect(ray, roots),
            Shape::Torus(s) => s.intersect(ray, roots),
            Shape::Triangle(s) => s.intersect(ray, roots),
            Shape::Mesh(s) => s.intersect(ray, roots),
            Shape::Polygon(s) => s.intersect(ray, roots),
            Shape::Math(s) => s.intersect(ray, roots),
        }
    }

    /// The nearest crossing in `(tmin, tmax)`. Shapes that search iteratively stop at it
    /// instead of finding every crossing.
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        match self {
            Shape::Sphere(s) => return s.first_hit(ray, tmin, tmax),
            Shape::Plane(s) => return s.first_hit(ray, tmin, tmax),
            Shape::Cuboid(s) => return s.first_hit(ray, tmin, tmax),
            Shape::Math(s) => {
                // A polynomial's, a julia fractal's, a sphere sweep's and an isosurface's
                // tests straight from here: a call or two fewer for the interpreted plugin,
                // whose calls each set up a frame.
                return match &**s {
                    MathShape::Poly(p) => p.first_hit(ray, tmin, tmax).map(|t| Root { t, part: 0 }),
                    MathShape::Julia(j) => julia::first_root(j, ray, tmin, tmax),
                    MathShape::SphereSweep(s) => {
                        s.first_hit(ray, tmin, tmax).map(|t| Root { t, part: 0 })
                    }
                    MathShape::Isosurface(iso) => {
                        let mut roots = Roots::new();
                        iso.intersect(ray, &mut roots);
                        roots.nearest_within(tmin, tmax)
                    }
                    s => s.first_hit(ray, tmin, tmax),
                };
            }
            Shape::Mesh(s) => return s.first_hit(ray, tmin, tmax),
            Shape::Torus(s) => return s.first_hit(ray, tmin, tmax),
            Shape::Disc(s) => return s.first_hit(ray, tmin, tmax),
            _ => {}
        }
        let mut roots = Roots::new();
        self.intersect(ray, &mut roots);
        roots.nearest_within(tmin, tmax)
    }

    pub fn inside(&self, p: DVec3) -> bool {
        match self {
            Shape::Sphere(s) => s.inside(p),
            Shape::Cuboid(s) => s.inside(p),
            Shape::Cylinder(s) => s.inside(p),
            Shape::Cone(s) => s.inside(p),
            Shape::Plane(s) => s.inside(p),
            Shape::Disc(s) => s.inside(p),
            Shape::Torus(s) => s.inside(p),
            Shape::Triangle(_) | Shape::Polygon(_) => false,
            Shape::Mesh(s) => s.inside(p),
            Shape::Math(s) => s.inside(p),
        }
    }

    /// The outward normal at a surface point, not necessarily of unit length.
    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match self {
            Shape::Sphere(_) => p,
            Shape::Cuboid(s) => s.normal(part),
            Shape::Cylinder(s) => s.normal(p, part),
            Shape::Cone(s) => s.normal(p, part),
            Shape::Plane(s) => s.normal,
            Shape::Disc(_) => DVec3::Z,
            Shape::Torus(s) => s.normal(p),
            Shape::Triangle(s) => s.normal(p),
            Shape::Mesh(s) => s.normal(p, part),
            Shape::Polygon(_) => DVec3::Z,
            // A polynomial's, a julia fractal's and a sphere sweep's normals straight from
            // here, as their tests are.
            Shape::Math(s) => match &**s {
                MathShape::Poly(poly) => poly.normal(p),
                MathShape::Julia(julia) => julia.normal(p),
                MathShape::SphereSweep(sweep) => sweep.normal(p),
                s => s.normal(p, part),
            },
        }
    }

    /// Bounds in the canonical frame; infinite for planes.
    pub fn bounds(&self) -> Aabb {
        match self {
            Shape::Sphere(_) => Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0)),
            Shape::Cuboid(s) => Aabb::new(s.min, s.max),
            Shape::Cylinder(_) => Aabb::new(DVec3::new(-1.0, -1.0, 0.0), DVec3::ONE),
            Shape::Cone(s) => {
                let r = s.base_radius.max(s.cap_radius);
                Aabb::new(DVec3::new(-r, -r, 0.0), DVec3::new(r, r, 1.0))
            }
            Shape::Plane(s) => s.bounds(),
            Shape::Disc(s) => Aabb::new(
                DVec3::new(-s.radius, -s.radius, 0.0),
                DVec3::new(s.radius, s.radius, 0.0),
            ),
            Shape::Torus(s) => {
                let r = s.major + s.minor;
                Aabb::new(DVec3::new(-r, -s.minor, -r), DVec3::new(r, s.minor, r))
            }
            Shape::Triangle(s) => {
                let [a, b, c] = s.corners;
                Aabb::new(a.min(b).min(c), a.max(b).max(c))
            }
            Shape::Mesh(s) => s.bounds(),
            Shape::Polygon(s) => s.bounds(),
            Shape::Math(s) => s.bounds(),
        }
    }

    /// Bounds in the world once `to_world` places the shape. A sphere and a torus get the
    /// box of their own surface rather than the box around their transformed canonical
    /// box, which a rotated ring overfills by up to half its width along each axis.
    /// Without a rotation or shear the two boxes are the same, and the canonical one is
    /// exact: it is kept there, so that `min_extent` of a moved sphere reads POV-Ray's
    /// `<-1, 0, 1>` and not the tight box's rounding margin (`-0.000000`).
    pub fn world_bounds(&self, to_world: &DAffine3) -> Aabb {
        let m = to_world.matrix3;
        let axis_aligned = [
            m.x_axis.y, m.x_axis.z, m.y_axis.x, m.y_axis.z, m.z_axis.x, m.z_axis.y,
        ]
        .iter()
        .all(|&v| v == 0.0);
        match self {
            Shape::Sphere(_) if !axis_aligned => ring_bounds(0.0, 1.0, to_world),
            Shape::Torus(s) if !axis_aligned => ring_bounds(s.major, s.minor, to_world),
            _ => self.bounds().transformed(to_world),
        }
    }
}

/// The box around the ring of radius `major` in the canonical x-z plane, thickened by a
/// ball of radius `minor`, after `to_world`. Along each world axis the half extent is the
/// sum of the circle's and the (ellipsoidal) ball's, both exact: the widths of a sum of
/// two sets add.
fn ring_bounds(major: f64, minor: f64, to_world: &DAffine3) -> Aabb {
    let m = to_world.matrix3;
    let (x, y, z) = (m.x_axis, m.y_axis, m.z_axis);
    let circle = (x * x + z * z).map(f64::sqrt) * major;
    let ball = (x * x + y * y + z * z).map(f64::sqrt) * minor;
    let centre = to_world.translation;
    // A margin of a few units in the last place keeps rounding from cutting the surface.
    let half = circle + ball;
    let half = half + (half + centre.abs()) * 1e-12;
    Aabb::new(centre - half, centre + half)
}

/// The roots of `a t² + 2 b t + c = 0`, in the form that loses no precision when `b²` is
/// much larger than `a c`. `None` when there is no real root.
pub(crate) fn solve_quadratic_half(a: f64, b: f64, c: f64) -> Option<(f64, f64)> {
    if a == 0.0 {
        if b == 0.0 {
            return None;
        }
        let t = -c / (2.0 * b);
        return Some((t, t));
    }
    let disc = b * b - a * c;
    if disc < 0.0 || !disc.is_finite() {
        return None;
    }
    let q = -(b + b.signum() * disc.sqrt());
    if q == 0.0 {
        return Some((0.0, 0.0));
    }
    let t1 = q / a;
    let t2 = c / q;
    Some((fast_math::min(t1, t2), fast_math::max(t1, t2)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_placed_torus_is_bounded_by_its_own_box() {
        let torus = Shape::Torus(Torus {
            major: 2.0,
            minor: 0.25,
            sturm: false,
            ball: None,
        });
        // Tilted, stretched along one axis and moved, as a matrix in a scene may.
        let to_world = DAffine3::from_translation(DVec3::new(1.0, -2.0, 3.0))
            * DAffine3::from_axis_angle(DVec3::new(1.0, 2.0, 0.5).normalize(), 0.7)
            * DAffine3::from_scale(DVec3::new(1.0, 1.5, 0.8));
        let tight = torus.world_bounds(&to_world);
        let loose = torus.bounds().transformed(&to_world);
        // Points all over the surface: inside the box, and reaching each of its faces.
        let mut reach = Aabb::EMPTY;
        for i in 0..400 {
            for j in 0..40 {
                let (u, v) = (i as f64 * std::f64::consts::TAU / 400.0, j as f64 * 0.157);
                let ring = DVec3::new(u.cos(), 0.0, u.sin());
                let local = ring * 2.0 + (ring * v.cos() + DVec3::Y * v.sin()) * 0.25;
                let p = to_world.transform_point3(local);
                assert!(
                    tight
                        .clip(&Ray::new(p, DVec3::X), DVec3::X, 0.0, 0.0)
                        .is_some()
                );
                reach = reach.union(&Aabb::new(p, p));
            }
        }
        assert!(
            (reach.min - tight.min).abs().max_element() < 1e-3,
            "{reach:?} {tight:?}"
        );
        assert!(
            (reach.max - tight.max).abs().max_element() < 1e-3,
            "{reach:?} {tight:?}"
        );
        let volume = |b: Aabb| (b.max - b.min).element_product();
        assert!(volume(tight) < 0.8 * volume(loose));
    }

    #[test]
    fn quadratic_is_stable() {
        let (a, b) = solve_quadratic_half(1.0, -1.5, 2.0).unwrap();
        assert_eq!((a, b), (1.0, 2.0));
        // Roots 1e-9 and 1e9: the small one keeps its precision.
        let (small, large) = solve_quadratic_half(1.0, -0.5 * (1e9 + 1e-9), 1.0).unwrap();
        assert!((small - 1e-9).abs() < 1e-20 && (large - 1e9).abs() < 1e-3);
        assert!(solve_quadratic_half(1.0, 0.0, 1.0).is_none());
    }
}
