//! `torus { major, minor }`: the tube of radius `minor` around the circle of radius `major`
//! in the x-z plane, centred on the origin.

use super::{Root, Roots};
use crate::bounds::Aabb;
use crate::fast_math::{max, min};
use crate::polynomial;
use crate::ray::Ray;
use crate::sturm;
use glam::{DAffine3, DVec3};

/// The arcs [`Torus::arc_boxes`] divides the ring into: a multiple of four.
pub const ARCS: usize = 32;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Torus {
    pub major: f64,
    pub minor: f64,
    /// `sturm`: roots by Sturm sequences, slower than the closed form but sure to find
    /// both of two close roots where a ray grazes the tube.
    pub sturm: bool,
    /// The ball around the torus in the world, when a transform places it there: see
    /// [`Torus::may_meet`].
    pub ball: Option<WorldBall>,
}

/// A ball in the world holding a placed torus's bounding sphere, a little larger so that
/// rounding never makes it the smaller of the two.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WorldBall {
    centre: DVec3,
    /// The square of the radius.
    radius2: f64,
}

impl Torus {
    /// The torus with the ball that holds it once `to_world` places it.
    pub fn placed(self, to_world: &DAffine3) -> Torus {
        // The linear part stretches no vector by more than the square root of the largest
        // row sum of |LᵀL| (Gershgorin's bound on its largest eigenvalue), which is exact
        // for rotations and scalings, the transforms scenes give tori.
        let m = to_world.matrix3;
        let columns = [m.x_axis, m.y_axis, m.z_axis];
        let stretch2 = columns
            .iter()
            .map(|a| columns.iter().map(|b| a.dot(*b).abs()).sum::<f64>())
            .fold(0.0, f64::max);
        let radius = stretch2.sqrt() * (self.major + self.minor) * (1.0 + 1e-6);
        Torus {
            ball: Some(WorldBall {
                centre: to_world.translation,
                radius2: radius * radius,
            }),
            ..self
        }
    }

    /// Whether the world ray may cross the torus that `to_local` moves into its canonical
    /// frame within `(tmin, tmax)`: `false` only when the part of the ray inside the
    /// torus's ball and inside the slab its tube fills lies outside the interval, where
    /// [`Torus::first_hit`] finds nothing either. Moving a ray into the torus's frame costs
    /// more than this test, and most rays a ring's box lets through miss the ring.
    pub fn may_meet(&self, to_local: &DAffine3, ray: &Ray, tmin: f64, tmax: f64) -> bool {
        let Some(ball) = &self.ball else {
            return true;
        };
        let (o, d) = (ray.origin, ray.direction);
        let m = &to_local.matrix3;
        // The ray's height in the torus's frame, computed exactly as the frame change
        // computes it, so that the slab ends are those `crossings` works with.
        let oy = m.x_axis.y * o.x + m.y_axis.y * o.y + m.z_axis.y * o.z + to_local.translation.y;
        let dy = m.x_axis.y * d.x + m.y_axis.y * d.y + m.z_axis.y * d.z;
        let small = self.minor;
        let (mut near, mut far) = (tmin, tmax);
        if dy != 0.0 {
            let (ya, yb) = ((-small - oy) / dy, (small - oy) / dy);
            near = max(near, min(ya, yb));
            far = min(far, max(ya, yb));
        } else if oy.abs() > small {
            return false;
        }
        if near > far {
            return false;
        }
        // The ray meets the ball within that span when its point there nearest the centre
        // is inside the ball: from the unclamped nearest point, this loses no precision
        // however far the ray starts.
        let to_centre = o - ball.centre;
        let nearest = -to_centre.dot(d) / d.length_squared();
        let miss = to_centre + d * max(near, min(far, nearest));
        // A degenerate ray (NaN) is left to the full test.
        let miss2 = miss.length_squared();
        miss2 <= ball.radius2 || miss2.is_nan()
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        self.intersect_within(ray, f64::NEG_INFINITY, f64::INFINITY, roots);
    }

    /// Every crossing when some may lie inside `[tmin, tmax]`, none otherwise: the interval
    /// culls more rays than the tube's bounds do, those whose crossings a nearer hit
    /// already hides above all. The quartic is solved over the span where the ray is in
    /// the tube's bounds whatever the interval, so that a crossing comes out the same for
    /// every query.
    pub fn intersect_within(&self, ray: &Ray, tmin: f64, tmax: f64, roots: &mut Roots) {
        self.crossings(ray, tmin, tmax, |t| roots.push(t, 0));
    }

    /// The nearest crossing inside `(tmin, tmax)`, as [`Torus::intersect_within`] would
    /// list it, without building the list: most rays a torus is asked about never reach
    /// its quartic.
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
        let mut nearest: Option<f64> = None;
        self.crossings(ray, tmin, tmax, |t| {
            if t.is_finite() && t > tmin && t < tmax && nearest.is_none_or(|n| t < n) {
                nearest = Some(t);
            }
        });
        nearest.map(|t| Root { t, part: 0 })
    }

    /// [`Torus::intersect_within`] giving each crossing to `found`.
    fn crossings(&self, ray: &Ray, tmin: f64, tmax: f64, mut found: impl FnMut(f64)) {
        let (big, small) = (self.major, self.minor);
        // Work from where the ray enters the bounding sphere, so that the quartic's
        // coefficients stay of the torus's own size.
        let bound = big + small;
        let a = ray.direction.length_squared();
        let b = ray.origin.dot(ray.direction);
        let c = ray.origin.length_squared() - bound * bound;
        let Some((mut t0, mut t1)) = super::solve_quadratic_half(a, b, c) else {
            return;
        };
        // The tube lies in the slab |y| <= minor and the annulus major ± minor around the
        // y axis; most rays that reach the bounding sphere miss one of them, which costs
        // far less to find out than the quartic.
        let (o, d) = (ray.origin, ray.direction);
        if d.y != 0.0 {
            let (ya, yb) = ((-small - o.y) / d.y, (small - o.y) / d.y);
            t0 = max(t0, min(ya, yb));
            t1 = min(t1, max(ya, yb));
        } else if o.y.abs() > small {
            return;
        }
        let (near, far) = (max(t0, tmin), min(t1, tmax));
        if near > far {
            return;
        }
        let rho2 = |t: f64| {
            let (x, z) = (o.x + t * d.x, o.z + t * d.z);
            x * x + z * z
        };
        let (e, f) = (d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z);
        let apex = if e > 0.0 { -f / e } else { near };
        let nearest = rho2(apex.clamp(near, far));
        let farthest = max(rho2(near), rho2(far));
        // The hole around the axis exists only when the tube is thinner than the ring; a
        // spindle torus (minor above major) reaches the axis.
        let hole = if big > small { big - small } else { 0.0 };
        if nearest > bound * bound || farthest < hole * hole {
            return;
        }
        // In units of the span, so that the solver weighs the coefficients alike at any
        // scale of the scene.
        let span = t1 - t0;
        let mut coeffs = quartic_along(ray.origin + ray.direction * t0, d, big, small);
        let mut power = 1.0;
        for c in &mut coeffs {
            *c *= power;
            power *= span;
        }
        if self.sturm {
            let mut roots = [0.0; polynomial::MAX_DEGREE];
            let n = sturm::roots_in(&coeffs, 0.0, 1.0, &mut roots);
            for &x in &roots[..n] {
                found(t0 + x * span);
            }
        } else {
            let (roots, n) = polynomial::quartic_roots_in(&coeffs, 0.0, 1.0);
            for &x in &roots[..n] {
                found(t0 + x * span);
            }
        }
    }

    /// Boxes in the canonical frame that together hold the tube, one around each of
    /// `ARCS` equal arcs of the ring thickened by the tube's radius: a ring seen at a slant
    /// covers far less of the image than its one box, whose middle is the ring's hole.
    /// The arcs end on the axes, so that each arc's extremes are its ends; the margin,
    /// far beyond rounding, also holds crossings the quartic finds a hair off the tube.
    pub fn arc_boxes(&self) -> [Aabb; ARCS] {
        let (big, small) = (self.major, self.minor);
        let pad = small + 1e-6 * (big + small);
        let end = |k: usize| {
            let (sin, cos) = (std::f64::consts::TAU * k as f64 / ARCS as f64).sin_cos();
            DVec3::new(big * cos, 0.0, big * sin)
        };
        std::array::from_fn(|k| {
            let (a, b) = (end(k), end(k + 1));
            Aabb::new(a.min(b) - DVec3::splat(pad), a.max(b) + DVec3::splat(pad))
        })
    }

    pub fn inside(&self, p: DVec3) -> bool {
        let ring = (p.x * p.x + p.z * p.z).sqrt() - self.major;
        ring * ring + p.y * p.y < self.minor * self.minor
    }

    pub fn normal(&self, p: DVec3) -> DVec3 {
        let radial = DVec3::new(p.x, 0.0, p.z).normalize_or_zero();
        p - radial * self.major
    }
}

/// The torus equation (|p|² + R² - r²)² = 4 R² (x² + z²) along o + s d, as a quartic in s
/// (lowest degree first). It holds on both the outer and the inner branch of a spindle
/// torus (r > R); the lemon keeps the inner one.
pub(crate) fn quartic_along(o: DVec3, d: DVec3, major: f64, minor: f64) -> [f64; 5] {
    let (r2, k2) = (major * major, minor * minor);
    let qa = d.length_squared();
    let qb = 2.0 * o.dot(d);
    let qc = o.length_squared() + r2 - k2;
    let e = d.x * d.x + d.z * d.z;
    let f = 2.0 * (o.x * d.x + o.z * d.z);
    let g = o.x * o.x + o.z * o.z;
    [
        qc * qc - 4.0 * r2 * g,
        2.0 * qb * qc - 4.0 * r2 * f,
        qb * qb + 2.0 * qa * qc - 4.0 * r2 * e,
        2.0 * qa * qb,
        qa * qa,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn crossings(torus: &Torus, ray: &Ray) -> Vec<f64> {
        let mut roots = Roots::new();
        torus.intersect(ray, &mut roots);
        roots.as_slice().iter().map(|r| r.t).collect()
    }

    #[test]
    fn an_interval_keeps_the_crossings_it_may_hold() {
        let torus = Torus {
            major: 2.0,
            minor: 0.5,
            sturm: false,
            ball: None,
        };
        let ray = Ray::new(DVec3::new(-5.0, 0.2, 0.0), DVec3::X);
        let all = crossings(&torus, &ray);
        assert_eq!(all.len(), 4);
        let within = |tmin: f64, tmax: f64| {
            let mut roots = Roots::new();
            torus.intersect_within(&ray, tmin, tmax, &mut roots);
            roots.as_slice().iter().map(|r| r.t).collect::<Vec<f64>>()
        };
        // An interval reaching the tube gives the very same crossings; one ending before
        // it, or lying in the hole, gives none.
        assert_eq!(within(0.0, 3.0), all);
        assert_eq!(within(6.0, 6.5), all);
        assert!(within(0.0, 2.4).is_empty());
        assert!(within(4.0, 6.0).is_empty());
    }

    #[test]
    fn the_world_ball_rejects_only_rays_that_miss() {
        let torus = Torus {
            major: 1.3,
            minor: 0.06,
            sturm: false,
            ball: None,
        };
        // Turned, stretched a little and moved, as a `matrix` in a scene may place it.
        let to_world = DAffine3::from_translation(DVec3::new(0.4, -0.2, 0.7))
            * DAffine3::from_axis_angle(DVec3::new(0.3, 1.0, -0.6).normalize(), 1.1)
            * DAffine3::from_scale(DVec3::new(1.0, 1.2, 0.9));
        let to_local = to_world.inverse();
        let placed = torus.placed(&to_world);
        // Rays from a camera-like grid of origins towards points spread around the ring,
        // many of them grazing the tube; a simple generator keeps the test repeatable.
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        let (mut hits, mut rejected) = (0, 0);
        for _ in 0..20_000 {
            let origin = DVec3::new(next() * 6.0, next() * 6.0, -8.0 + next());
            let target =
                to_world.transform_point3(DVec3::new(next() * 1.5, next() * 0.1, next() * 1.5));
            let ray = Ray::new(origin, target - origin);
            let (tmin, tmax) = (
                1e-9,
                if next() > 0.0 {
                    f64::INFINITY
                } else {
                    1.0 + next().abs()
                },
            );
            let local = Ray::new(
                to_local.transform_point3(ray.origin),
                to_local.transform_vector3(ray.direction),
            );
            let hit = torus.first_hit(&local, tmin, tmax);
            let may = placed.may_meet(&to_local, &ray, tmin, tmax);
            assert!(may || hit.is_none(), "{ray:?} {tmin} {tmax}: {hit:?}");
            hits += usize::from(hit.is_some());
            rejected += usize::from(!may);
        }
        // The test means something only if both kinds of ray occur often.
        assert!(
            hits > 1000 && rejected > 1000,
            "{hits} hits, {rejected} rejected"
        );
    }

    #[test]
    fn sturm_finds_the_same_crossings() {
        let closed = Torus {
            major: 2.0,
            minor: 0.5,
            sturm: false,
            ball: None,
        };
        let sturm = Torus {
            sturm: true,
            ..closed
        };
        // Through both sides of the tube along x, and obliquely through one side.
        for ray in [
            Ray::new(DVec3::new(-5.0, 0.1, 0.0), DVec3::X),
            Ray::new(DVec3::new(-5.0, 0.3, 0.4), DVec3::new(1.0, -0.1, 0.05)),
        ] {
            let (a, b) = (crossings(&closed, &ray), crossings(&sturm, &ray));
            assert_eq!(a.len(), b.len(), "{a:?} {b:?}");
            assert!(!a.is_empty());
            for (x, y) in a.iter().zip(&b) {
                assert!((x - y).abs() < 1e-9, "{a:?} {b:?}");
            }
        }
        // At height 0.2 along x the tube is crossed where (|x| - 2)² = 0.25 - 0.04.
        let along = crossings(&sturm, &Ray::new(DVec3::new(-5.0, 0.2, 0.0), DVec3::X));
        let h = 0.21f64.sqrt();
        let want = [3.0 - h, 3.0 + h, 7.0 - h, 7.0 + h];
        assert_eq!(along.len(), 4, "{along:?}");
        for (x, y) in along.iter().zip(want) {
            assert!((x - y).abs() < 1e-9, "{along:?}");
        }
    }
}
