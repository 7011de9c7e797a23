//! The mathematical shapes behind one variant of [`super::Shape`]: their runtime forms
//! built from the scene's parameters, and the dispatch of ray queries to them. Unlike the
//! simple shapes they may take many steps to find a crossing, so they also answer "the
//! nearest crossing in an interval" directly, which lets them stop early.

use super::blob::{self, Blob};
use super::height_field::HeightField;
use super::isosurface::{FieldFunction, GradientRecord, Isosurface};
use super::julia::{self, Julia};
use super::lathe::Lathe;
use super::lemon::Lemon;
use super::ovus::Ovus;
use super::parametric::{Parametric, ParametricSpec};
use super::poly::Poly;
use super::prism::Prism;
use super::sor::Sor;
use super::sphere_sweep::SphereSweep;
use super::superellipsoid::Superellipsoid;
use super::text::Text;
use super::{OrderedCrossings, Root, Roots};
use crate::bounds::Aabb;
use crate::ray::Ray;
use analysis::scene::{self, Origin};
use glam::{DAffine3, DVec3};
use std::sync::Arc;

#[derive(Debug, Clone, PartialEq)]
pub enum MathShape {
    Poly(Poly),
    Isosurface(Isosurface),
    Julia(Julia),
    SphereSweep(SphereSweep),
    HeightField(HeightField),
    Text(Text),
    Superellipsoid(Superellipsoid),
    Ovus(Ovus),
    Lemon(Lemon),
    Lathe(Lathe),
    Sor(Sor),
    Prism(Prism),
    Blob(Blob),
    Parametric(Parametric),
}

/// Something a shape found out while rendering that the scene's author should hear, as
/// POV-Ray tells it after the render (an isosurface's max_gradient).
#[derive(Debug, Clone)]
pub struct ShapeReport {
    pub origin: Origin,
    record: Arc<GradientRecord>,
    max_gradient: f64,
    evaluate: bool,
}

impl ShapeReport {
    /// The warning, if the render gave reason for one.
    pub fn message(&self) -> Option<String> {
        super::isosurface::gradient_warning(&self.record, self.max_gradient, self.evaluate)
    }
}

/// The runtime shape of a mathematical scene shape with its frame; `Ok(None)` when the
/// shape has no surface at all.
pub fn build(
    object: &scene::Object,
    reports: &mut Vec<ShapeReport>,
) -> Result<Option<(MathShape, DAffine3)>, String> {
    let identity = DAffine3::IDENTITY;
    let built: Result<Option<(MathShape, DAffine3)>, String> = match &object.shape {
        scene::Shape::Polynomial(p) => {
            let terms = p.terms.iter().map(|t| (t.powers, t.coefficient)).collect();
            Ok(Some((
                MathShape::Poly(Poly {
                    order: p.order as usize,
                    terms,
                    sturm: p.sturm,
                    region: bounded_region(object),
                }),
                identity,
            )))
        }
        scene::Shape::Quadric {
            squares,
            mixed,
            linear,
            constant,
        } => {
            // The second-order polynomial A x² + B y² + C z² + D xy + E xz + F yz + G x +
            // H y + I z + J, inside where it is negative, as POV-Ray's quadric.
            let terms = [
                ([2, 0, 0], squares.x),
                ([0, 2, 0], squares.y),
                ([0, 0, 2], squares.z),
                ([1, 1, 0], mixed.x),
                ([1, 0, 1], mixed.y),
                ([0, 1, 1], mixed.z),
                ([1, 0, 0], linear.x),
                ([0, 1, 0], linear.y),
                ([0, 0, 1], linear.z),
                ([0, 0, 0], *constant),
            ];
            let ellipsoid = ellipsoid_box(*squares, *mixed, *linear, *constant);
            let region = match (bounded_region(object), ellipsoid) {
                (Some(a), Some(b)) => Some(a.intersection(&b)),
                (a, b) => a.or(b),
            };
            Ok(Some((
                MathShape::Poly(Poly {
                    order: 2,
                    terms: terms.into_iter().filter(|&(_, c)| c != 0.0).collect(),
                    sturm: false,
                    region,
                }),
                identity,
            )))
        }
        scene::Shape::Isosurface(iso) => {
            let record = Arc::new(GradientRecord::default());
            reports.push(ShapeReport {
                origin: object.origin.clone(),
                record: record.clone(),
                max_gradient: iso.max_gradient,
                evaluate: iso.evaluate.is_some(),
            });
            let sign = if iso.polarity { -1.0 } else { 1.0 };
            Ok(Some((
                MathShape::Isosurface(Isosurface {
                    function: FieldFunction::new(&iso.function),
                    container: iso.container,
                    threshold: sign * iso.threshold,
                    accuracy: iso.accuracy,
                    max_gradient: iso.max_gradient,
                    evaluate: iso.evaluate,
                    closed: !iso.open,
                    max_trace: iso.max_trace,
                    sign,
                    record,
                }),
                identity,
            )))
        }
        scene::Shape::JuliaFractal(j) => Ok(Some((
            MathShape::Julia(Julia::new(
                j.parameter,
                j.algebra,
                j.function,
                j.max_iteration,
                j.precision,
                j.slice,
                j.slice_distance,
            )),
            identity,
        ))),
        scene::Shape::SphereSweep(s) => Ok(SphereSweep::new(s.kind, &s.spheres, s.tolerance)
            .map(|sweep| (MathShape::SphereSweep(sweep), identity))),
        scene::Shape::HeightField(field) => {
            Ok(HeightField::new(field).map(|f| (MathShape::HeightField(f), identity)))
        }
        scene::Shape::Text(text) => Ok(Text::new(text).map(|t| (MathShape::Text(t), identity))),
        scene::Shape::Superellipsoid { e, n } => Ok(Some((
            MathShape::Superellipsoid(Superellipsoid::new(*e, *n)),
            identity,
        ))),
        scene::Shape::Ovus {
            bottom_radius,
            top_radius,
        } => Ok(Some((
            MathShape::Ovus(Ovus::new(*bottom_radius, *top_radius)),
            identity,
        ))),
        scene::Shape::Lemon(l) => {
            let axis = l.cap - l.base;
            let length = axis.length();
            if !(length > 0.0 && length.is_finite()) {
                return Err("degenerate lemon: base and cap coincide".into());
            }
            let w = axis / length;
            let (u, v) = w.any_orthonormal_pair();
            // The canonical lemon stands on the y axis from 0 to its length.
            let frame = DAffine3::from_mat3_translation(glam::DMat3::from_cols(u, w, v), l.base);
            let lemon = Lemon::new(length, l.base_radius, l.cap_radius, l.inner_radius, l.open)?;
            Ok(Some((MathShape::Lemon(lemon), frame)))
        }
        scene::Shape::Lathe(l) => {
            Ok(Lathe::new(l.kind, &l.points, l.sturm)
                .map(|lathe| (MathShape::Lathe(lathe), identity)))
        }
        scene::Shape::Sor(s) => {
            Ok(Sor::new(&s.points, s.open, s.sturm).map(|sor| (MathShape::Sor(sor), identity)))
        }
        scene::Shape::Prism(p) => Ok(Prism::new(
            p.kind,
            p.sweep,
            (p.height1, p.height2),
            &p.points,
            p.open,
            p.sturm,
        )
        .map(|prism| (MathShape::Prism(prism), identity))),
        scene::Shape::Blob(b) => {
            let components = b
                .components
                .iter()
                .map(|c| blob::Component::new(c.kind, c.radius, c.strength, c.transform.matrix))
                .collect();
            Ok(Blob::new(components, b.threshold, b.sturm)
                .map(|blob| (MathShape::Blob(blob), identity)))
        }
        scene::Shape::Parametric(p) => Ok(Some((
            MathShape::Parametric(Parametric::new(ParametricSpec {
                functions: p.functions.clone().map(|f| FieldFunction::new(&f)),
                u: p.u_range,
                v: p.v_range,
                container: p.container,
                accuracy: p.accuracy,
                max_gradient: p.max_gradient,
                precompute: p.precompute,
            })),
            identity,
        ))),
        other => Err(format!("not supported yet: {}", shape_name(other))),
    };
    built
}

/// The keyword of a shape, for messages.
fn shape_name(shape: &scene::Shape) -> &'static str {
    match shape {
        scene::Shape::HeightField(_) => "height_field",
        scene::Shape::Text(_) => "text",
        _ => "this shape",
    }
}

/// The box around a quadric that is an ellipsoid (its quadratic part positive definite,
/// so that its inside is the bounded one), for the hierarchy and the root search; `None`
/// for the unbounded quadrics. With `A` the symmetric matrix of the quadratic part, `g` the
/// linear part and `J` the constant, the centre is `-A⁻¹g/2`, and the surface is
/// `yᵀAy = k` around it with `k = x₀ᵀAx₀ - J`, reaching `√(k (A⁻¹)ᵢᵢ)` along axis `i`.
fn ellipsoid_box(squares: DVec3, mixed: DVec3, linear: DVec3, constant: f64) -> Option<Aabb> {
    let a = glam::DMat3::from_cols(
        DVec3::new(squares.x, mixed.x / 2.0, mixed.y / 2.0),
        DVec3::new(mixed.x / 2.0, squares.y, mixed.z / 2.0),
        DVec3::new(mixed.y / 2.0, mixed.z / 2.0, squares.z),
    );
    let minor2 = squares.x * squares.y - mixed.x * mixed.x / 4.0;
    if !(squares.x > 0.0 && minor2 > 0.0 && a.determinant() > 0.0) {
        return None;
    }
    let inverse = a.inverse();
    let centre = -0.5 * (inverse * linear);
    let k = centre.dot(a * centre) - constant;
    if !(k > 0.0 && k.is_finite()) {
        return None;
    }
    let reach = DVec3::new(inverse.x_axis.x, inverse.y_axis.y, inverse.z_axis.z) * k;
    let reach = DVec3::new(reach.x.sqrt(), reach.y.sqrt(), reach.z.sqrt());
    // A hair wider, so that roots on the box's faces are not lost to rounding.
    let reach = reach * (1.0 + 1e-9) + DVec3::splat(1e-12 * reach.max_element());
    Some(Aabb::new(centre - reach, centre + reach))
}

/// The box, in the shape's own frame, of a `bounded_by` made of spheres and boxes; the
/// polynomial's roots are only looked for inside it.
fn bounded_region(object: &scene::Object) -> Option<Aabb> {
    if object.bounded_by.is_empty() {
        return None;
    }
    let to_local = object.transform.matrix.inverse();
    let mut region = Aabb::INFINITE;
    for bound in &object.bounded_by {
        let frame = to_local * bound.transform.matrix;
        let b = match &bound.shape {
            scene::Shape::Sphere { center, radius } => {
                let c = frame.transform_point3(*center);
                let m = frame.matrix3;
                let extent = DVec3::new(m.row(0).length(), m.row(1).length(), m.row(2).length())
                    * radius.abs();
                Aabb::new(c - extent, c + extent)
            }
            scene::Shape::Box { corner1, corner2 } => {
                Aabb::new(*corner1, *corner2).transformed(&frame)
            }
            _ => return None,
        };
        region = region.intersection(&b);
    }
    region.is_finite().then_some(region)
}

impl MathShape {
    /// Every crossing, as many as fit.
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        match self {
            MathShape::Poly(s) => s.intersect(ray, roots),
            MathShape::Isosurface(s) => s.intersect(ray, roots),
            MathShape::Julia(s) => {
                let mut t = [0.0; 4];
                let n = s.crossings(ray, f64::NEG_INFINITY, f64::INFINITY, false, &mut t);
                for &t in &t[..n] {
                    roots.push(t, 0);
                }
            }
            MathShape::SphereSweep(s) => s.intersect(ray, roots),
            MathShape::HeightField(s) => s.intersect(ray, roots),
            MathShape::Text(s) => s.intersect(ray, roots),
            MathShape::Superellipsoid(s) => s.intersect(ray, roots),
            MathShape::Ovus(s) => s.intersect(ray, roots),
            MathShape::Lemon(s) => s.intersect(ray, roots),
            MathShape::Lathe(s) => s.intersect(ray, roots),
            MathShape::Sor(s) => s.intersect(ray, roots),
            MathShape::Prism(s) => s.intersect(ray, roots),
            MathShape::Blob(s) => s.intersect(ray, roots),
            MathShape::Parametric(s) => s.intersect(ray, roots),
        }
    }

    /// The nearest crossing in `(tmin, tmax)`.
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        let t = match self {
            MathShape::Poly(s) => s.first_hit(ray, tmin, tmax),
            MathShape::Julia(s) => return julia::first_root(s, ray, tmin, tmax),
            MathShape::SphereSweep(s) => s.first_hit(ray, tmin, tmax),
            MathShape::Superellipsoid(s) => s.first_hit(ray, tmin, tmax),
            MathShape::Blob(s) => s.first_hit(ray, tmin, tmax),
            MathShape::Parametric(s) => {
                return s
                    .first_hit(ray, tmin, tmax)
                    .map(|(t, part)| Root { t, part });
            }
            MathShape::HeightField(s) => return s.first_hit(ray, tmin, tmax),
            MathShape::Text(s) => return s.first_hit(ray, tmin, tmax),
            _ => {
                let mut roots = Roots::new();
                self.intersect(ray, &mut roots);
                return roots
                    .as_slice()
                    .iter()
                    .copied()
                    .filter(|r| r.t > tmin && r.t < tmax)
                    .min_by(|a, b| a.t.total_cmp(&b.t));
            }
        };
        t.map(|t| Root { t, part: 0 })
    }

    pub fn inside(&self, p: DVec3) -> bool {
        match self {
            MathShape::Poly(s) => s.inside(p),
            MathShape::Isosurface(s) => s.inside(p),
            MathShape::Julia(s) => s.inside_point(p),
            MathShape::SphereSweep(s) => s.inside(p),
            MathShape::HeightField(s) => s.inside(p),
            MathShape::Text(s) => s.inside(p),
            MathShape::Superellipsoid(s) => s.inside(p),
            MathShape::Ovus(s) => s.inside(p),
            MathShape::Lemon(s) => s.inside(p),
            MathShape::Lathe(s) => s.inside(p),
            MathShape::Sor(s) => s.inside(p),
            MathShape::Prism(s) => s.inside(p),
            MathShape::Blob(s) => s.inside(p),
            MathShape::Parametric(s) => s.inside(p),
        }
    }

    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match self {
            MathShape::Poly(s) => s.normal(p),
            MathShape::Isosurface(s) => s.normal(p, part),
            MathShape::Julia(s) => s.normal(p),
            MathShape::SphereSweep(s) => s.normal(p),
            MathShape::HeightField(s) => s.normal(p),
            MathShape::Text(s) => s.normal(p, part),
            MathShape::Superellipsoid(s) => s.normal(p),
            MathShape::Ovus(s) => s.normal(p, part),
            MathShape::Lemon(s) => s.normal(p, part),
            MathShape::Lathe(s) => s.normal(p, part),
            MathShape::Sor(s) => s.normal(p, part),
            MathShape::Prism(s) => s.normal(p, part),
            MathShape::Blob(s) => s.normal(p),
            MathShape::Parametric(s) => s.normal(p, part),
        }
    }

    pub fn bounds(&self) -> Aabb {
        match self {
            MathShape::Poly(s) => s.bounds(),
            MathShape::Isosurface(s) => {
                let (a, b) = s.bounds();
                Aabb::new(a, b)
            }
            MathShape::Julia(s) => Aabb::new(DVec3::splat(-s.radius), DVec3::splat(s.radius)),
            MathShape::SphereSweep(s) => s.bounds(),
            MathShape::HeightField(s) => s.bounds(),
            MathShape::Text(s) => s.bounds(),
            MathShape::Superellipsoid(_) => Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0)),
            MathShape::Ovus(s) => s.bounds(),
            MathShape::Lemon(s) => s.bounds(),
            MathShape::Lathe(s) => s.bounds(),
            MathShape::Sor(s) => s.bounds(),
            MathShape::Prism(s) => s.bounds(),
            MathShape::Blob(s) => s.bounds(),
            MathShape::Parametric(s) => s.bounds(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).abs().max_element() < 1e-8
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
        // A tilted ellipse, 2x² + 2xy + 2y² + z² = 1: the box reaches √(k (A⁻¹)ᵢᵢ).
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
        // A hyperboloid, a cylinder, an inside-out sphere and an empty one have no box.
        for (squares, constant) in [
            (DVec3::new(1.0, -1.0, 1.0), -0.3),
            (DVec3::new(1.0, 0.0, 1.0), -0.25),
            (DVec3::splat(-1.0), 1.0),
            (DVec3::ONE, 1.0),
        ] {
            assert!(ellipsoid_box(squares, DVec3::ZERO, DVec3::ZERO, constant).is_none());
        }
    }
}
