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
use super::quadric::Quadric;
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
    Quadric(Quadric),
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
                MathShape::Poly(Poly::new(
                    p.order as usize,
                    terms,
                    p.sturm,
                    bounded_region(object),
                )),
                identity,
            )))
        }
        scene::Shape::Quadric {
            squares,
            mixed,
            linear,
            constant,
        } => Ok(Some((
            MathShape::Quadric(Quadric::new(
                *squares,
                *mixed,
                *linear,
                *constant,
                bounded_region(object),
            )),
            identity,
        ))),
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
            MathShape::Quadric(s) => s.intersect(ray, roots),
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
            MathShape::Quadric(s) => s.first_hit(ray, tmin, tmax),
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
                return roots.nearest_within(tmin, tmax);
            }
        };
        t.map(|t| Root { t, part: 0 })
    }

    pub fn inside(&self, p: DVec3) -> bool {
        match self {
            MathShape::Poly(s) => s.inside(p),
            MathShape::Quadric(s) => s.inside(p),
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
            MathShape::Quadric(s) => s.normal(p),
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
            MathShape::Quadric(s) => s.bounds(),
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
