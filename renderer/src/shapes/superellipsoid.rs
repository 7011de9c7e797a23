//! `superellipsoid { <e, n> }`: the points where (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n)
//! equals 1, inside the box from -1 to 1. The left side raised to n/2 is a nested p-norm,
//! h = ‖(‖(x, y)‖_{2/e}, z)‖_{2/n}, which grows linearly with distance from the origin and
//! so is well scaled for root finding: the surface is h = 1.
//!
//! With both exponents at most 2 the norms are convex, and so is h along every ray:
//! Newton's method on h - 1 started outside the shape never overshoots (each tangent
//! meets 1 before h does) and converges to the nearest crossing in a few steps, or shows
//! that there is none when h stops falling; started from the far end it finds the last
//! crossing the same way.
//!
//! With either exponent above 2 the shape is pinched: the ray is first cut where it
//! crosses the coordinate planes and the diagonal planes x = ±y, between which h has at
//! most one extremum, bracketed by a golden-section search that stops as soon as it finds
//! a point on the other side. Pinched shapes search on the surface's power form
//! F = h^(2/n) - 1, which has the sign and the extrema of h - 1 but needs no root of a
//! sum: with the usual exponents (e and n of 1, 0.5, 0.25, 0.2, ...) it is products alone,
//! where h costs four calls of pow.

use super::OrderedCrossings;
use crate::ray::Ray;
use glam::DVec3;

/// Golden-section steps at most per stretch of the ray.
const MAX_SEARCH: usize = 60;

/// Root refinement steps at most (each narrows a bracket by secant or bisection).
const MAX_REFINE: usize = 80;

/// Newton steps at most toward a crossing of a convex shape: convergence is quadratic,
/// and even at a grazing ray's double root, where it is linear, a step halves the gap.
const MAX_NEWTON: usize = 80;

/// The Newton step, in the shape's own units, below which a crossing is taken as found.
const NEWTON_TOLERANCE: f64 = 1e-12;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Superellipsoid {
    /// 2/e: the exponent across x and y.
    p_xy: f64,
    /// 2/n: the exponent between the x-y norm and z.
    p_z: f64,
    /// The powers of the power form: 2/e, e/n (of the x-y sum), 2/n; and n/2, which turns
    /// F + 1 back into h.
    xy: Power,
    nest: Power,
    z: Power,
    root: Power,
}

/// x^p for x >= 0, an exponent fixed per shape. Integer exponents, the common case, are
/// repeated multiplication instead of pow.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Power {
    One,
    Half,
    Integer(i32),
    Real(f64),
}

impl Power {
    fn new(p: f64) -> Power {
        let rounded = p.round();
        if p == 0.5 {
            Power::Half
        } else if (p - rounded).abs() > 1e-12 * p.abs() || rounded.abs() > 64.0 {
            Power::Real(p)
        } else if rounded == 1.0 {
            Power::One
        } else {
            Power::Integer(rounded as i32)
        }
    }

    fn of(self, x: f64) -> f64 {
        match self {
            Power::One => x,
            Power::Half => x.sqrt(),
            Power::Integer(n) => x.powi(n),
            Power::Real(p) => x.powf(p),
        }
    }
}

/// ‖(a, b)‖_p for non-negative a and b, factored by the larger so that large exponents
/// neither overflow nor lose the smaller term.
fn p_norm(a: f64, b: f64, p: f64) -> f64 {
    let (big, small) = if a >= b { (a, b) } else { (b, a) };
    if big == 0.0 {
        return 0.0;
    }
    big * (1.0 + (small / big).powf(p)).powf(1.0 / p)
}

impl Superellipsoid {
    /// The shape with POV-Ray's exponents; they must be positive (the evaluator checks).
    pub fn new(e: f64, n: f64) -> Superellipsoid {
        Superellipsoid {
            p_xy: 2.0 / e,
            p_z: 2.0 / n,
            xy: Power::new(2.0 / e),
            nest: Power::new(e / n),
            z: Power::new(2.0 / n),
            root: Power::new(n / 2.0),
        }
    }

    /// F = h^(2/n) - 1 = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) - 1.
    fn power_form(&self, p: DVec3) -> f64 {
        let across = self.xy.of(p.x.abs()) + self.xy.of(p.y.abs());
        self.nest.of(across) + self.z.of(p.z.abs()) - 1.0
    }

    fn convex(&self) -> bool {
        self.p_xy >= 1.0 && self.p_z >= 1.0
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.power_form(p) < 0.0
    }

    /// The gradient of h: for a p-norm N of (a, b), ∂N/∂a = (a/N)^(p-1).
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let (ax, ay, az) = (p.x.abs(), p.y.abs(), p.z.abs());
        let across = p_norm(ax, ay, self.p_xy);
        let h = p_norm(across, az, self.p_z);
        if h == 0.0 {
            return DVec3::Y;
        }
        // Ratios are floored so that a negative power (a pinched shape's edges) stays
        // finite; the normal there is a crease's anyway.
        let ratio = |a: f64, b: f64, q: f64| {
            if b == 0.0 {
                0.0
            } else {
                (a / b).max(1e-150).powf(q - 1.0)
            }
        };
        let d_across = ratio(across, h, self.p_z);
        let n = DVec3::new(
            d_across * ratio(ax, across, self.p_xy) * p.x.signum(),
            d_across * ratio(ay, across, self.p_xy) * p.y.signum(),
            ratio(az, h, self.p_z) * p.z.signum(),
        );
        if n.is_finite() { n } else { p }
    }

    /// h at `p` and its rate of change along `d`. With X = |x|^(2/e), S = X + Y,
    /// G = S^(e/n) + Z = h^(2/n): ∂h/∂x = (h/G)·(S^(e/n)/S)·(X/|x|)·sign x, and alike for y;
    /// ∂h/∂z = (h/G)·(Z/|z|)·sign z. Where a coordinate is zero the partial is taken as
    /// zero, a subgradient of the convex gauge there.
    fn gauge_and_slope(&self, p: DVec3, d: DVec3) -> (f64, f64) {
        let (ax, ay, az) = (p.x.abs(), p.y.abs(), p.z.abs());
        let (px, py, pz) = (self.xy.of(ax), self.xy.of(ay), self.z.of(az));
        let across = px + py;
        let nested = self.nest.of(across);
        let g = nested + pz;
        if g == 0.0 {
            return (0.0, 0.0);
        }
        let h = self.root.of(g);
        let per_unit = |power: f64, a: f64| if a > 0.0 { power / a } else { 0.0 };
        let outer = per_unit(nested, across);
        let grad = DVec3::new(
            outer * per_unit(px, ax) * p.x.signum(),
            outer * per_unit(py, ay) * p.y.signum(),
            per_unit(pz, az) * p.z.signum(),
        );
        (h, h / g * grad.dot(d))
    }

    /// The crossing of a convex shape nearest `from` on the way to `to`, by Newton's method
    /// on h - 1; h at `from` is at least 1. None when h grows toward `to` or the tangent
    /// passes `to` before reaching 1, for then h cannot reach 1 before `to` either.
    fn newton(&self, ray: &Ray, from: f64, to: f64) -> Option<f64> {
        let toward = to - from;
        let speed = ray.direction.length();
        let mut t = from;
        for _ in 0..MAX_NEWTON {
            let (h, slope) = self.gauge_and_slope(ray.at(t), ray.direction);
            let excess = h - 1.0;
            if excess <= 0.0 {
                return Some(t);
            }
            let step = -excess / slope;
            // A step away from `to`, or none (a NaN slope included), means h does not
            // fall toward it.
            if step * toward <= 0.0 || step.is_nan() {
                return None;
            }
            let next = t + step;
            if (next - to) * toward > 0.0 {
                return None;
            }
            if step.abs() * speed <= NEWTON_TOLERANCE || next == t {
                return Some(next);
            }
            t = next;
        }
        None
    }

    /// The crossings of a convex shape in `[t0, t1]`, nearest first: h along the ray is
    /// convex, so there are at most two, the entry found from `t0` and the exit from `t1`.
    fn convex_crossings(&self, ray: &Ray, t0: f64, t1: f64, take: &mut dyn FnMut(f64) -> bool) {
        let outside = |t: f64| self.gauge_and_slope(ray.at(t), ray.direction).0 >= 1.0;
        let exit_outside = outside(t1);
        if outside(t0) {
            let Some(entry) = self.newton(ray, t0, t1) else {
                return;
            };
            if take(entry) || !exit_outside {
                return;
            }
            if let Some(exit) = self.newton(ray, t1, entry)
                && exit > entry
            {
                take(exit);
            }
        } else if exit_outside && let Some(exit) = self.newton(ray, t1, t0) {
            take(exit);
        }
    }

    /// The crossings in one stretch where φ, the power form along the ray, has at most one
    /// interior extremum; true when `take` has had enough.
    #[allow(clippy::too_many_arguments)]
    fn stretch(
        &self,
        ray: &Ray,
        phi: &dyn Fn(f64) -> f64,
        a: f64,
        fa: f64,
        b: f64,
        fb: f64,
        take: &mut dyn FnMut(f64) -> bool,
    ) -> bool {
        if (fa < 0.0) != (fb < 0.0) {
            return take(refine(phi, a, fa, b, fb));
        }
        // Both ends on one side: look for an extremum on the other side. Outside, the
        // minimum; inside, the maximum.
        let sign = if fa < 0.0 { -1.0 } else { 1.0 };
        let g = |t: f64| sign * phi(t);
        // No coordinate changes sign within the stretch, so each |coordinate| is affine
        // along it and the power form, rising in each, is least (or most) over [lo, hi]
        // at the point made of the smaller (larger) |coordinate| of the two ends: a bound
        // of g that ends the search as soon as it shows that g stays positive.
        let g_floor = |lo: f64, hi: f64| {
            let (p, q) = (ray.at(lo).abs(), ray.at(hi).abs());
            let corner = if sign > 0.0 { p.min(q) } else { p.max(q) };
            sign * self.power_form(corner)
        };
        if g_floor(a, b) > 0.0 {
            return false;
        }
        let ratio = 0.5 * (5f64.sqrt() - 1.0);
        let (mut lo, mut hi) = (a, b);
        let mut x1 = hi - ratio * (hi - lo);
        let mut x2 = lo + ratio * (hi - lo);
        let (mut g1, mut g2) = (g(x1), g(x2));
        for _ in 0..MAX_SEARCH {
            let (best_t, best) = if g1 < g2 { (x1, g1) } else { (x2, g2) };
            if best < 0.0 {
                let fm = phi(best_t);
                return take(refine(phi, a, fa, best_t, fm))
                    || take(refine(phi, best_t, fm, b, fb));
            }
            if hi - lo <= 1e-13 * (b - a).max(f64::MIN_POSITIVE) || g_floor(lo, hi) > 0.0 {
                return false;
            }
            if g1 < g2 {
                hi = x2;
                x2 = x1;
                g2 = g1;
                x1 = hi - ratio * (hi - lo);
                g1 = g(x1);
            } else {
                lo = x1;
                x1 = x2;
                g1 = g2;
                x2 = lo + ratio * (hi - lo);
                g2 = g(x2);
            }
        }
        false
    }
}

impl OrderedCrossings for Superellipsoid {
    fn crossings(&self, ray: &Ray, tmin: f64, tmax: f64, take: &mut dyn FnMut(f64) -> bool) {
        let Some((t0, t1)) = unit_box_span(ray) else {
            return;
        };
        let (t0, t1) = (t0.max(tmin), t1.min(tmax));
        if t0 >= t1 {
            return;
        }
        if self.convex() {
            self.convex_crossings(ray, t0, t1, take);
            return;
        }
        let phi = |t: f64| self.power_form(ray.at(t));
        // Where the ray changes octant or crosses a diagonal plane, for pinched shapes.
        let mut cuts = [0.0; 7];
        let mut n = 0;
        cuts[n] = t0;
        n += 1;
        if !self.convex() {
            let (o, d) = (ray.origin, ray.direction);
            for (num, den) in [
                (o.x, d.x),
                (o.y, d.y),
                (o.z, d.z),
                (o.x - o.y, d.x - d.y),
                (o.x + o.y, d.x + d.y),
            ] {
                let t = -num / den;
                if t > t0 && t < t1 {
                    cuts[n] = t;
                    n += 1;
                }
            }
        }
        cuts[n] = t1;
        n += 1;
        cuts[..n].sort_by(f64::total_cmp);
        let mut f_lo = phi(cuts[0]);
        for w in 1..n {
            let (a, b) = (cuts[w - 1], cuts[w]);
            let f_hi = phi(b);
            if b - a > 0.0 && self.stretch(ray, &phi, a, f_lo, b, f_hi, take) {
                return;
            }
            f_lo = f_hi;
        }
    }
}

/// Where the ray is inside the box from -1 to 1.
fn unit_box_span(ray: &Ray) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (f64::NEG_INFINITY, f64::INFINITY);
    for axis in 0..3 {
        let (o, d) = (ray.origin[axis], ray.direction[axis]);
        if d == 0.0 {
            if o.abs() > 1.0 {
                return None;
            }
            continue;
        }
        let (a, b) = ((-1.0 - o) / d, (1.0 - o) / d);
        t0 = t0.max(a.min(b));
        t1 = t1.min(a.max(b));
    }
    (t0 <= t1).then_some((t0, t1))
}

/// The root of φ between `a` and `b`, whose values differ in sign: the Illinois variant of
/// regula falsi, which keeps the bracket and converges superlinearly, down to the last
/// representable step.
pub(crate) fn refine(phi: &dyn Fn(f64) -> f64, a: f64, fa: f64, b: f64, fb: f64) -> f64 {
    let (mut a, mut fa, mut b, mut fb) = (a, fa, b, fb);
    let mut side = 0i8;
    for _ in 0..MAX_REFINE {
        let mut m = if fa != fb {
            (a * fb - b * fa) / (fb - fa)
        } else {
            0.5 * (a + b)
        };
        if !(m > a.min(b) && m < a.max(b)) {
            m = 0.5 * (a + b);
        }
        if m == a || m == b {
            break;
        }
        let fm = phi(m);
        if fm == 0.0 {
            return m;
        }
        if (fm < 0.0) == (fa < 0.0) {
            a = m;
            fa = fm;
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        } else {
            b = m;
            fb = fm;
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        }
        if (b - a).abs() <= 1e-14 * (a.abs() + b.abs()) {
            break;
        }
    }
    // The end whose value is smaller is the better estimate.
    if fa.abs() < fb.abs() { a } else { b }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::Roots;

    #[test]
    fn unit_exponents_make_the_unit_sphere() {
        let s = Superellipsoid::new(1.0, 1.0);
        let ray = Ray::new(DVec3::new(0.3, 0.2, -5.0), DVec3::Z);
        let t = s.first_hit(&ray, 0.0, f64::INFINITY).unwrap();
        let expected = 5.0 - (1.0f64 - 0.09 - 0.04).sqrt();
        assert!((t - expected).abs() < 1e-12, "{t} against {expected}");
        let p = ray.at(t);
        assert!((s.normal(p).normalize() - p).length() < 1e-9);
    }

    #[test]
    fn small_exponents_approach_the_box() {
        let s = Superellipsoid::new(0.1, 0.1);
        let ray = Ray::new(DVec3::new(0.5, 0.5, -5.0), DVec3::Z);
        let t = s.first_hit(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((t - 4.0).abs() < 1e-3, "{t}");
        assert!(s.normal(ray.at(t)).normalize().z < -0.99);
    }

    #[test]
    fn pinched_shapes_find_both_sides_of_a_waist() {
        // e = n = 3: a star whose arms run along the axes; a ray along x at height 0.05
        // crosses the arm, leaves it and meets the opposite arm.
        let s = Superellipsoid::new(3.0, 3.0);
        let ray = Ray::new(DVec3::new(-2.0, 0.02, 0.02), DVec3::X);
        let mut roots = Roots::new();
        s.intersect(&ray, &mut roots);
        let ts: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
        assert_eq!(ts.len(), 2, "{ts:?}");
        for t in ts {
            assert!(s.power_form(ray.at(t)).abs() < 1e-9);
        }
        assert!(s.inside(DVec3::new(0.9, 0.0, 0.0)));
        assert!(!s.inside(DVec3::new(0.5, 0.5, 0.5)));
    }

    /// The power form is the nested norm raised to 2/n, less one, for integer and
    /// fractional exponents alike.
    #[test]
    fn the_power_form_is_a_power_of_the_nested_norm() {
        let points = [
            DVec3::new(0.3, -0.5, 0.7),
            DVec3::new(0.9, 0.1, -0.05),
            DVec3::new(-0.2, 0.0, 0.95),
        ];
        for (e, n) in [(1.0, 1.0), (0.2, 0.2), (1.0, 0.3), (2.5, 2.5), (0.5, 3.0)] {
            let s = Superellipsoid::new(e, n);
            for p in points {
                let across = p_norm(p.x.abs(), p.y.abs(), 2.0 / e);
                let h = p_norm(across, p.z.abs(), 2.0 / n);
                let expected = h.powf(2.0 / n) - 1.0;
                let got = s.power_form(p);
                assert!(
                    (got - expected).abs() < 1e-12,
                    "<{e}, {n}> at {p}: {got} against {expected}"
                );
            }
        }
    }

    #[test]
    fn grazing_rays_give_no_nan() {
        let s = Superellipsoid::new(0.25, 0.5);
        for k in 0..200 {
            let y = 0.99 + k as f64 * 1e-4;
            let ray = Ray::new(DVec3::new(-3.0, y, 0.0), DVec3::X);
            if let Some(t) = s.first_hit(&ray, 0.0, f64::INFINITY) {
                assert!(t.is_finite());
                assert!(s.normal(ray.at(t)).is_finite());
            }
        }
    }

    /// Shapes box-like, diamond-like (exponent 1, with its kinks) and pinched are crossed
    /// where a dense walk along the ray changes sides, and a ray starting inside a convex
    /// one finds its exit alone.
    #[test]
    fn crossings_match_a_dense_walk() {
        for (e, n) in [
            (0.2, 0.2),
            (1.0, 0.3),
            (1.0, 1.0),
            (2.0, 2.0),
            (0.5, 1.5),
            (2.5, 2.5),
            (0.5, 3.0),
        ] {
            let s = Superellipsoid::new(e, n);
            for k in 0..40 {
                let a = k as f64 * 0.37;
                let origin = DVec3::new(3.0 * a.cos(), 1.3 * (2.0 * a).sin(), -3.0);
                let target = DVec3::new(0.4 * (3.0 * a).sin(), 0.3 * a.cos(), 0.2);
                let ray = Ray::new(origin, target - origin);
                let mut roots = Roots::new();
                s.intersect(&ray, &mut roots);
                let found: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
                let steps = 20_000;
                let mut changes = Vec::new();
                for i in 0..steps {
                    let (t0, t1) = (
                        i as f64 * 2.0 / steps as f64,
                        (i + 1) as f64 * 2.0 / steps as f64,
                    );
                    if s.inside(ray.at(t0)) != s.inside(ray.at(t1)) {
                        changes.push(t1);
                    }
                }
                assert_eq!(
                    found.len(),
                    changes.len(),
                    "<{e}, {n}> ray {k}: {found:?} against {changes:?}"
                );
                for (t, c) in found.iter().zip(&changes) {
                    assert!(
                        (t - c).abs() <= 2.0 / steps as f64,
                        "<{e}, {n}> ray {k}: {t} against {c}"
                    );
                    assert!(s.power_form(ray.at(*t)).abs() < 1e-9);
                }
                if let Some(&entry) = found.first()
                    && s.convex()
                {
                    let middle = 0.5 * (entry + found[found.len() - 1]);
                    let inner = Ray::new(ray.at(middle), ray.direction);
                    let exit = s.first_hit(&inner, 0.0, f64::INFINITY).unwrap();
                    let last = found[found.len() - 1] - middle;
                    assert!(
                        (exit - last).abs() < 1e-9,
                        "<{e}, {n}> ray {k}: {exit} against {last}"
                    );
                }
            }
        }
    }
}
