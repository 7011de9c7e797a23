//! `parametric { function {x(u,v)} function {y(u,v)} function {z(u,v)} <u1,v1>, <u2,v2> }`:
//! the surface the three functions draw over a rectangle of (u, v), seen only inside its
//! container, hollow. As in POV-Ray, max_gradient bounds every partial derivative, so a
//! patch of half-sizes (hu, hv) lies within max_gradient·(hu + hv) of its centre's point
//! along each axis: patches are halved (u and v in turn) while the ray crosses their box,
//! nearest box first, down to the accuracy; holes appear where max_gradient is set too
//! low, as in POV-Ray's pictures. Once a patch is small, Newton's method on
//! S(u, v) = o + t d from its centre settles the crossing to full precision; where it
//! does not settle, the box's entry point is the crossing, as POV-Ray takes it.
//!
//! `precompute D, x, y, z` keeps the boxes of the first D halvings for the listed axes,
//! each the union of its halves' boxes, which is tighter than the gradient's bound.

use super::Roots;
use super::isosurface::FieldFunction;
use crate::bounds::Aabb;
use crate::ray::Ray;
use analysis::scene::math_shapes::Container;
use glam::{DVec2, DVec3};

/// Patches whose box is smaller than this share of the container try Newton's method.
const NEWTON_SHARE: f64 = 1.0 / 64.0;

/// How many halvings apart Newton's method is tried again below the size.
const NEWTON_EVERY: u32 = 6;

/// The deepest halving: past it a patch is a point for any accuracy.
const MAX_DEPTH: u32 = 48;

/// At most this many levels are precomputed, whatever the scene asks (2^D boxes).
const MAX_PRECOMPUTE: u32 = 16;

#[derive(Debug, Clone, PartialEq)]
pub struct Parametric {
    functions: [FieldFunction; 3],
    u: (f64, f64),
    v: (f64, f64),
    container: Container,
    accuracy: f64,
    max_gradient: f64,
    /// Boxes of the first levels of halving, heap-ordered (children of i: 2i+1, 2i+2).
    precomputed: Vec<Aabb>,
    /// Which axes the precomputed boxes bound.
    precomputed_axes: [bool; 3],
    newton_size: f64,
}

/// A rectangle of (u, v) at some depth of the halving.
#[derive(Debug, Clone, Copy)]
struct Patch {
    u0: f64,
    u1: f64,
    v0: f64,
    v1: f64,
    depth: u32,
    /// Its index in the heap order of the precomputed boxes.
    node: usize,
}

impl Patch {
    fn halves(&self) -> [Patch; 2] {
        let (a, b) = (2 * self.node + 1, 2 * self.node + 2);
        let depth = self.depth + 1;
        if self.depth.is_multiple_of(2) {
            let m = 0.5 * (self.u0 + self.u1);
            [
                Patch {
                    u1: m,
                    depth,
                    node: a,
                    ..*self
                },
                Patch {
                    u0: m,
                    depth,
                    node: b,
                    ..*self
                },
            ]
        } else {
            let m = 0.5 * (self.v0 + self.v1);
            [
                Patch {
                    v1: m,
                    depth,
                    node: a,
                    ..*self
                },
                Patch {
                    v0: m,
                    depth,
                    node: b,
                    ..*self
                },
            ]
        }
    }

    fn centre(&self) -> DVec2 {
        DVec2::new(0.5 * (self.u0 + self.u1), 0.5 * (self.v0 + self.v1))
    }
}

/// The scene's parameters of a parametric surface.
pub struct ParametricSpec {
    pub functions: [FieldFunction; 3],
    pub u: (f64, f64),
    pub v: (f64, f64),
    pub container: Container,
    pub accuracy: f64,
    pub max_gradient: f64,
    pub precompute: Option<(u32, [bool; 3])>,
}

impl Parametric {
    pub fn new(spec: ParametricSpec) -> Parametric {
        let container = container_box(&spec.container);
        let mut shape = Parametric {
            functions: spec.functions,
            u: spec.u,
            v: spec.v,
            container: spec.container,
            accuracy: spec.accuracy,
            max_gradient: spec.max_gradient,
            precomputed: Vec::new(),
            precomputed_axes: [false; 3],
            newton_size: (container.max - container.min).max_element() * NEWTON_SHARE,
        };
        if let Some((depth, axes)) = spec.precompute
            && axes.iter().any(|a| *a)
        {
            let depth = depth.min(MAX_PRECOMPUTE);
            shape.precomputed = vec![Aabb::EMPTY; (1 << (depth + 1)) - 1];
            shape.precomputed_axes = axes;
            shape.precompute(shape.root(), depth);
        }
        shape
    }

    fn root(&self) -> Patch {
        Patch {
            u0: self.u.0,
            u1: self.u.1,
            v0: self.v.0,
            v1: self.v.1,
            depth: 0,
            node: 0,
        }
    }

    fn precompute(&mut self, patch: Patch, levels: u32) -> Aabb {
        let b = if levels == 0 {
            self.gradient_box(&patch)
        } else {
            let [a, c] = patch.halves();
            self.precompute(a, levels - 1)
                .union(&self.precompute(c, levels - 1))
        };
        self.precomputed[patch.node] = b;
        b
    }

    pub fn point(&self, uv: DVec2) -> DVec3 {
        let at = DVec3::new(uv.x, uv.y, 0.0);
        DVec3::new(
            self.functions[0].eval(at),
            self.functions[1].eval(at),
            self.functions[2].eval(at),
        )
    }

    /// The partial derivatives by central differences.
    fn partials(&self, uv: DVec2) -> (DVec3, DVec3) {
        let hu = 1e-6 * (self.u.1 - self.u.0);
        let hv = 1e-6 * (self.v.1 - self.v.0);
        let (eu, ev) = (DVec2::new(hu, 0.0), DVec2::new(0.0, hv));
        let su = (self.point(uv + eu) - self.point(uv - eu)) / (2.0 * hu);
        let sv = (self.point(uv + ev) - self.point(uv - ev)) / (2.0 * hv);
        (su, sv)
    }

    /// The box the gradient bound allows around a patch's centre.
    fn gradient_box(&self, p: &Patch) -> Aabb {
        let centre = self.point(p.centre());
        let reach = self.max_gradient * 0.5 * ((p.u1 - p.u0) + (p.v1 - p.v0));
        Aabb::new(centre - reach, centre + reach)
    }

    fn patch_box(&self, p: &Patch) -> Aabb {
        let mut b = self.gradient_box(p);
        if let Some(pre) = self.precomputed.get(p.node) {
            for axis in 0..3 {
                if self.precomputed_axes[axis] {
                    b.min[axis] = b.min[axis].max(pre.min[axis]);
                    b.max[axis] = b.max[axis].min(pre.max[axis]);
                }
            }
        }
        b
    }

    pub fn bounds(&self) -> Aabb {
        let b = container_box(&self.container);
        match self.precomputed.first() {
            Some(all) if self.precomputed_axes.iter().all(|a| *a) => b.intersection(all),
            _ => b,
        }
    }

    /// Where the ray is inside the container.
    fn container_span(&self, ray: &Ray) -> Option<(f64, f64)> {
        match self.container {
            Container::Box { corner1, corner2 } => Aabb::new(corner1, corner2).line_span(ray),
            Container::Sphere { center, radius } => {
                let oc = ray.origin - center;
                super::solve_quadratic_half(
                    ray.direction.length_squared(),
                    oc.dot(ray.direction),
                    oc.length_squared() - radius * radius,
                )
            }
        }
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let mut hits: Vec<(f64, u32)> = Vec::new();
        if let Some((lo, hi)) = self.container_span(ray)
            && let Some(entry) = self.enter(ray, lo, hi)
        {
            self.search(ray, self.root(), entry, (lo, hi), &mut |t, part| {
                hits.push((t, part));
                false
            });
        }
        hits.sort_by(|a, b| a.0.total_cmp(&b.0));
        // Neighbouring patches may settle on one crossing.
        let mut last = f64::NEG_INFINITY;
        for (t, part) in hits {
            if t - last > self.accuracy * 1e-3 {
                roots.push(t, part);
                last = t;
            }
        }
    }

    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<(f64, u32)> {
        let (lo, hi) = self.container_span(ray)?;
        let (lo, hi) = (lo.max(tmin), hi.min(tmax));
        if lo >= hi {
            return None;
        }
        let mut best = None;
        let entry = self.enter(ray, lo, hi)?;
        self.search(ray, self.root(), entry, (lo, hi), &mut |t, part| {
            best = Some((t, part));
            true
        });
        best
    }

    /// Visits the patches whose boxes the ray crosses within `(lo, hi)`, nearest box
    /// first, handing crossings to `take` until it returns true. `t0` is where the ray
    /// enters the patch's box.
    fn search(
        &self,
        ray: &Ray,
        patch: Patch,
        (b, t0): (Aabb, f64),
        (lo, hi): (f64, f64),
        take: &mut dyn FnMut(f64, u32) -> bool,
    ) -> bool {
        let size = (b.max - b.min).max_element();
        let fallback = size < self.accuracy || patch.depth >= MAX_DEPTH;
        // Newton's method is tried on the first patch below the size, then every few
        // halvings (where it failed, the smaller patches inside rarely do better), and
        // before falling back to the box.
        let first_small = size < self.newton_size && 2.0 * size >= self.newton_size;
        let retry = size < self.newton_size && patch.depth.is_multiple_of(NEWTON_EVERY);
        if (first_small || retry || fallback)
            && let Some((t, uv)) = self.newton(ray, &patch, t0)
        {
            // The patch's crossing; outside the interval (a shadow ray leaving the very
            // point it starts from) it is no crossing at all.
            return t > lo && t < hi && take(t, self.encode(uv));
        }
        if fallback {
            // A box the ray starts in is the surface the ray leaves, not one it meets.
            return t0 > lo && take(t0, self.encode(patch.centre()));
        }
        let inv = ray.direction.recip();
        let [a, c] = patch.halves().map(|p| {
            let b = self.patch_box(&p);
            (p, b, b.clip(ray, inv, lo, hi).map(|s| s.0))
        });
        let order = match (a.2, c.2) {
            (Some(x), Some(y)) if y < x => [c, a],
            _ => [a, c],
        };
        order
            .into_iter()
            .any(|(p, b, t)| t.is_some_and(|t| self.search(ray, p, (b, t), (lo, hi), take)))
    }

    /// The root patch's box and where the ray enters it, if it does.
    fn enter(&self, ray: &Ray, lo: f64, hi: f64) -> Option<(Aabb, f64)> {
        let b = self.patch_box(&self.root());
        let (t, _) = b.clip(ray, ray.direction.recip(), lo, hi)?;
        Some((b, t))
    }

    /// Newton's method on S(u, v) - (o + t d) = 0 from the patch's centre; the crossing
    /// when it settles on the patch or next to it.
    fn newton(&self, ray: &Ray, patch: &Patch, t_start: f64) -> Option<(f64, DVec2)> {
        let (du, dv) = (patch.u1 - patch.u0, patch.v1 - patch.v0);
        let mut uv = patch.centre();
        let mut t = t_start;
        let scale = self.newton_size;
        for _ in 0..8 {
            let f = self.point(uv) - ray.at(t);
            if f.length() <= 1e-13 * scale {
                break;
            }
            let (su, sv) = self.partials(uv);
            let m = glam::DMat3::from_cols(su, sv, -ray.direction);
            let det = m.determinant();
            if det == 0.0 || !det.is_finite() {
                return None;
            }
            let step = m.inverse() * -f;
            // A step far beyond the patch is heading for another crossing, which that
            // patch's own search will find.
            if step.x.abs() > 4.0 * du || step.y.abs() > 4.0 * dv {
                return None;
            }
            uv += DVec2::new(step.x, step.y);
            t += step.z;
            if !(uv.is_finite() && t.is_finite()) {
                return None;
            }
        }
        // Settling on the patch or a neighbour of its size counts as this patch's
        // crossing: patches this small hold one crossing, and the neighbour's search
        // would settle on the same one.
        let inside = uv.x >= (patch.u0 - du).max(self.u.0)
            && uv.x <= (patch.u1 + du).min(self.u.1)
            && uv.y >= (patch.v0 - dv).max(self.v.0)
            && uv.y <= (patch.v1 + dv).min(self.v.1);
        let settled = (self.point(uv) - ray.at(t)).length() <= 1e-9 * scale;
        (inside && settled).then_some((t, uv))
    }

    /// (u, v) packed into a root's part, 16 bits each across the ranges; the normal
    /// starts from it.
    fn encode(&self, uv: DVec2) -> u32 {
        let q = |x: f64, (a, b): (f64, f64)| {
            (((x - a) / (b - a)).clamp(0.0, 1.0) * 65535.0).round() as u32
        };
        (q(uv.x, self.u) << 16) | q(uv.y, self.v)
    }

    fn decode(&self, part: u32) -> DVec2 {
        let f = |q: u32, (a, b): (f64, f64)| a + (b - a) * (f64::from(q) / 65535.0);
        DVec2::new(f(part >> 16, self.u), f(part & 0xffff, self.v))
    }

    /// A hollow surface has no inside.
    pub fn inside(&self, _p: DVec3) -> bool {
        false
    }

    /// S_u × S_v at the (u, v) nearest `p`, found by Gauss-Newton from the packed guess.
    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        let mut uv = self.decode(part);
        for _ in 0..6 {
            let (su, sv) = self.partials(uv);
            let r = self.point(uv) - p;
            let (a, b, c) = (su.dot(su), su.dot(sv), sv.dot(sv));
            let det = a * c - b * b;
            if det == 0.0 || !det.is_finite() {
                break;
            }
            let (gu, gv) = (su.dot(r), sv.dot(r));
            let step = DVec2::new((c * gu - b * gv) / det, (a * gv - b * gu) / det);
            if !step.is_finite() {
                break;
            }
            uv -= step;
        }
        let (su, sv) = self.partials(uv);
        let n = su.cross(sv);
        if n.is_finite() && n.length_squared() > 1e-12 * su.length_squared() * sv.length_squared() {
            return n;
        }
        // A pole of the parametrisation (a sphere's, where sin u = 0): the normals around
        // it, turned to agree, point the way the surface faces there.
        let h = DVec2::new(self.u.1 - self.u.0, self.v.1 - self.v.0) * 1e-3;
        let mut sum = DVec3::ZERO;
        for offset in [
            DVec2::new(h.x, 0.0),
            DVec2::new(-h.x, 0.0),
            DVec2::new(0.0, h.y),
            DVec2::new(0.0, -h.y),
        ] {
            let (a, b) = self.partials(uv + offset);
            let m = a.cross(b).normalize_or_zero();
            sum += if m.dot(sum) < 0.0 { -m } else { m };
        }
        if sum.is_finite() && sum != DVec3::ZERO {
            sum
        } else {
            DVec3::Y
        }
    }
}

fn container_box(container: &Container) -> Aabb {
    match *container {
        Container::Box { corner1, corner2 } => Aabb::new(corner1, corner2),
        Container::Sphere { center, radius } => Aabb::new(center - radius, center + radius),
    }
}
