//! `sphere_sweep`: the union of the spheres whose centres and radii follow a linear,
//! B-spline or Catmull-Rom (POV-Ray's cubic_spline) curve. Its distance function is
//! exact: min over s of |p - c(s)| - r(s). Each curve segment is cut into pieces short
//! enough to be enclosed in a capsule around their chord (the Bézier control polygon
//! bounds the deviation), a hierarchy of boxes finds the capsules a ray crosses, and
//! sphere tracing on the piece's true distance, with Newton steps along the ray where
//! they are longer and safe, then Newton's method finds the surface to machine
//! precision, so that normals are smooth and silhouettes exact.

use super::Roots;
use crate::bounds::Aabb;
use crate::fast_math::{max, min};
use crate::ray::Ray;
use analysis::scene::math_shapes::SplineKind;
use glam::DVec3;

/// A piece's capsule may be this much wider than its sweep's radius; wider pieces split.
const DEVIATION_SHARE: f64 = 0.25;

/// The deepest a segment is split (2¹² pieces).
const MAX_SPLITS: u32 = 12;

/// The most sphere tracing steps in one capsule.
const MAX_STEPS: usize = 96;

/// Points of a capsule's remaining span probed once sphere tracing has stalled.
const SCAN_SAMPLES: usize = 64;

/// A cubic (or lower) curve segment with its radius, for s in 0..1.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Segment {
    /// c(s) = c[0] + c[1] s + c[2] s² + c[3] s³.
    c: [DVec3; 4],
    r: [f64; 4],
}

impl Segment {
    fn centre(&self, s: f64) -> DVec3 {
        ((self.c[3] * s + self.c[2]) * s + self.c[1]) * s + self.c[0]
    }

    fn radius(&self, s: f64) -> f64 {
        ((self.r[3] * s + self.r[2]) * s + self.r[1]) * s + self.r[0]
    }

    /// c, c', c'', r, r', r'' at s.
    fn derivatives(&self, s: f64) -> (DVec3, DVec3, DVec3, f64, f64, f64) {
        let c = self.centre(s);
        let d1 = (self.c[3] * (3.0 * s) + self.c[2] * 2.0) * s + self.c[1];
        let d2 = self.c[3] * (6.0 * s) + self.c[2] * 2.0;
        let r = self.radius(s);
        let r1 = (self.r[3] * (3.0 * s) + self.r[2] * 2.0) * s + self.r[1];
        let r2 = self.r[3] * (6.0 * s) + self.r[2] * 2.0;
        (c, d1, d2, r, r1, r2)
    }
}

/// A stretch [s0, s1] of one segment and the capsule that encloses its spheres.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Piece {
    segment: u32,
    s0: f64,
    s1: f64,
    a: DVec3,
    b: DVec3,
    /// The capsule's radius: the largest radius plus the curve's deviation from a..b.
    reach: f64,
}

impl Piece {
    fn bounds(&self) -> Aabb {
        let r = DVec3::splat(self.reach);
        Aabb::new(self.a.min(self.b) - r, self.a.max(self.b) + r)
    }

    /// Where the ray is inside the capsule.
    fn span(&self, ray: &Ray) -> Option<(f64, f64)> {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        let r2 = self.reach * self.reach;
        for centre in [self.a, self.b] {
            let o = ray.origin - centre;
            if let Some((t0, t1)) = super::solve_quadratic_half(
                ray.direction.length_squared(),
                o.dot(ray.direction),
                o.length_squared() - r2,
            ) {
                lo = min(lo, t0);
                hi = max(hi, t1);
            }
        }
        // The cylinder between the end spheres.
        let axis = self.b - self.a;
        let len2 = axis.length_squared();
        if len2 > 0.0 {
            let o = ray.origin - self.a;
            let (od, dd) = (o.dot(axis) / len2, ray.direction.dot(axis) / len2);
            let (po, pd) = (o - axis * od, ray.direction - axis * dd);
            if let Some((t0, t1)) = super::solve_quadratic_half(
                pd.length_squared(),
                po.dot(pd),
                po.length_squared() - r2,
            ) {
                // Within the slab 0 <= projection <= 1.
                let (mut s0, mut s1) = (f64::NEG_INFINITY, f64::INFINITY);
                if dd != 0.0 {
                    let (x, y) = (-od / dd, (1.0 - od) / dd);
                    s0 = min(x, y);
                    s1 = max(x, y);
                } else if !(0.0..=1.0).contains(&od) {
                    s1 = s0;
                }
                let (c0, c1) = (max(t0, s0), min(t1, s1));
                if c0 <= c1 {
                    lo = min(lo, c0);
                    hi = max(hi, c1);
                }
            }
        }
        (lo <= hi).then_some((lo, hi))
    }
}

/// A node of the hierarchy over pieces: a box and either two children or a run of pieces.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Node {
    bounds: Aabb,
    /// Leaves: first piece and count; inner nodes: index of the second child, count 0.
    first: u32,
    count: u32,
}

#[derive(Debug, Clone, PartialEq)]
pub struct SphereSweep {
    segments: Vec<Segment>,
    pieces: Vec<Piece>,
    nodes: Vec<Node>,
    /// How close to the surface a hit is refined, in the sweep's units.
    tolerance: f64,
}

/// What a Newton step along the ray found.
enum NewtonStep {
    /// The crossing.
    Hit(f64),
    /// A point still outside and still approaching: its t, distance and nearest s.
    Closer(f64, f64, f64),
    /// The ray passed its nearest approach to the piece within the step.
    Passed,
    /// No step longer than the safe one.
    Short,
}

/// A candidate capsule along a ray.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    piece: u32,
    t0: f64,
    t1: f64,
}

impl SphereSweep {
    /// The sweep through `spheres` with the given interpolation; `None` when it has no
    /// segment (too few spheres).
    pub fn new(kind: SplineKind, spheres: &[(DVec3, f64)], tolerance: f64) -> Option<SphereSweep> {
        let segments = segments(kind, spheres);
        if segments.is_empty() {
            return None;
        }
        let mut pieces = Vec::new();
        for (i, segment) in segments.iter().enumerate() {
            split(segment, i as u32, 0.0, 1.0, 0, &mut pieces);
        }
        let scale = pieces
            .iter()
            .map(|p| p.a.abs().max_element().max(p.reach))
            .fold(0.0f64, f64::max);
        let nodes = build_hierarchy(&mut pieces);
        Some(SphereSweep {
            segments,
            pieces,
            nodes,
            tolerance: tolerance.max(1e-12 * scale),
        })
    }

    pub fn bounds(&self) -> Aabb {
        self.nodes.first().map_or(Aabb::EMPTY, |n| n.bounds)
    }

    /// The capsules the ray crosses within `(tmin, tmax)`, nearest entry first.
    fn candidates(&self, ray: &Ray, tmin: f64, tmax: f64, out: &mut Vec<Candidate>) {
        let inv = ray.direction.recip();
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let i = stack[top] as usize;
            let node = self.nodes[i];
            if node.bounds.clip(ray, inv, tmin, tmax).is_none() {
                continue;
            }
            if node.count > 0 {
                for i in node.first..node.first + node.count {
                    if let Some((t0, t1)) = self.pieces[i as usize].span(ray)
                        && t1 >= tmin
                        && t0 <= tmax
                    {
                        out.push(Candidate {
                            piece: i,
                            t0: max(t0, tmin),
                            t1: min(t1, tmax),
                        });
                    }
                }
            } else if top + 2 <= stack.len() {
                stack[top] = node.first;
                stack[top + 1] = i as u32 + 1;
                top += 2;
            }
        }
        out.sort_by(|a, b| a.t0.total_cmp(&b.t0));
    }

    /// The signed distance from `p` to one piece's spheres and where on the piece it is
    /// nearest, starting the search at `guess`. The nearest sphere minimises
    /// |p - c(s)|² - r(s)², which is smooth where |p - c(s)| - r(s) has a kink; its
    /// derivative's root is bracketed by the piece's ends and found by Newton steps
    /// that fall back to bisection.
    fn piece_distance(&self, piece: &Piece, p: DVec3, guess: f64) -> (f64, f64) {
        let segment = &self.segments[piece.segment as usize];
        let distance = |s: f64| (p - segment.centre(s)).length() - segment.radius(s);
        // Half the derivative of |p - c|² - r², and its own derivative.
        let slope = |s: f64| {
            let (c, d1, d2, r, r1, r2) = segment.derivatives(s);
            let v = c - p;
            (
                v.dot(d1) + r * r1,
                d1.length_squared() + v.dot(d2) + r1 * r1 + r * r2,
            )
        };
        let (mut lo, mut hi) = (piece.s0, piece.s1);
        let (e_lo, _) = slope(lo);
        let (e_hi, _) = slope(hi);
        let s = if e_lo >= 0.0 && e_hi > 0.0 {
            lo
        } else if e_hi <= 0.0 && e_lo < 0.0 {
            hi
        } else if e_lo >= 0.0 {
            // Rising at the start, falling at the end: both ends are candidates.
            let (a, b) = (distance(lo), distance(hi));
            return if a <= b { (a, lo) } else { (b, hi) };
        } else {
            let mut s = if guess > lo && guess < hi {
                guess
            } else {
                0.5 * (lo + hi)
            };
            for _ in 0..30 {
                let (e, de) = slope(s);
                if e == 0.0 {
                    break;
                }
                if e < 0.0 {
                    lo = s;
                } else {
                    hi = s;
                }
                let newton = s - e / de;
                if de > 0.0 && newton >= lo && newton <= hi {
                    // Newton's method converges quadratically, and the distance is
                    // stationary here: once a step is this short, the next could not
                    // change the distance by a bit.
                    let step = (newton - s).abs();
                    s = newton;
                    if step <= 1e-10 * (piece.s1 - piece.s0) {
                        break;
                    }
                } else {
                    s = 0.5 * (lo + hi);
                    if hi - lo <= 1e-13 * (piece.s1 - piece.s0) {
                        break;
                    }
                }
            }
            s
        };
        (distance(s), s)
    }

    /// The first crossing of the piece's surface along the ray within its capsule span
    /// `[t0, t1]`: from outside if `entering`, else the exit walking back from `t1`.
    fn trace_piece(
        &self,
        piece: &Piece,
        ray: &Ray,
        t0: f64,
        t1: f64,
        entering: bool,
    ) -> Option<f64> {
        let speed = ray.direction.length();
        let (start, sign) = if entering { (t0, 1.0) } else { (t1, -1.0) };
        let mut t = start;
        let mut guess = 0.5 * (piece.s0 + piece.s1);
        let (mut d, mut s) = self.piece_distance(piece, ray.at(t), guess);
        // Newton steps are tried until one passes the ray's nearest approach.
        let mut newton = true;
        for _ in 0..MAX_STEPS {
            guess = s;
            if d <= self.tolerance {
                if d < -self.tolerance && t == start {
                    // The span starts inside: no crossing in this direction.
                    return None;
                }
                return Some(self.polish(piece, ray, t, s));
            }
            // d is measured at the sphere that minimises |p - c|² - r², which for a varying
            // radius need not be the nearest: stepping by d could pass the surface. With
            // |p - c|² - r² = d (d + 2r) and the nearest sphere's |p - c| + r at most
            // d + 2·reach, this step stays short of it.
            let segment = &self.segments[piece.segment as usize];
            let safe = d * (d + 2.0 * segment.radius(s)) / (d + 2.0 * piece.reach) / speed;
            if newton {
                match self.newton_step(piece, ray, t, d, s, sign, safe, (t0, t1)) {
                    NewtonStep::Hit(hit) => return Some(hit),
                    NewtonStep::Closer(nt, nd, ns) => {
                        (t, d, s) = (nt, nd, ns);
                        continue;
                    }
                    NewtonStep::Passed => newton = false,
                    NewtonStep::Short => {}
                }
            }
            t += sign * safe;
            if t > t1 || t < t0 {
                return None;
            }
            (d, s) = self.piece_distance(piece, ray.at(t), guess);
        }
        // Sphere tracing crawls beside a grazing ray, in ever shorter steps, and how far it
        // gets would depend on the tolerance. The rest of the span is scanned for a point
        // inside instead, and the crossing bisected between it and the last point outside.
        let end = if entering { t1 } else { t0 };
        let inside = |t: f64| self.piece_distance(piece, ray.at(t), guess).0 < 0.0;
        let mut outside = t;
        for k in 1..=SCAN_SAMPLES {
            let probe = t + (end - t) * (k as f64 / SCAN_SAMPLES as f64);
            if inside(probe) {
                let mut deep = probe;
                for _ in 0..64 {
                    let mid = 0.5 * (outside + deep);
                    if mid == outside || mid == deep {
                        break;
                    }
                    if inside(mid) {
                        deep = mid;
                    } else {
                        outside = mid;
                    }
                }
                let (_, s) = self.piece_distance(piece, ray.at(outside), guess);
                return Some(self.polish(piece, ray, outside, s));
            }
            outside = probe;
        }
        None
    }

    /// Sphere tracing creeps towards a surface the ray meets at a slant, each step
    /// shortening by the cosine of the angle. A Newton step on the distance along the ray
    /// gets there at once where the tube is convex; it is taken when it is longer than
    /// the safe step and stays in the capsule. Landing inside brackets the crossing with
    /// the last point outside; landing outside but moving away means the ray passed its
    /// nearest approach, and the search falls back to safe steps.
    #[allow(clippy::too_many_arguments)]
    fn newton_step(
        &self,
        piece: &Piece,
        ray: &Ray,
        t: f64,
        d: f64,
        s: f64,
        sign: f64,
        safe: f64,
        (t0, t1): (f64, f64),
    ) -> NewtonStep {
        let segment = &self.segments[piece.segment as usize];
        let approach = |p: DVec3, s: f64| {
            sign * (p - segment.centre(s))
                .normalize_or_zero()
                .dot(ray.direction)
        };
        let slope = approach(ray.at(t), s);
        if slope >= 0.0 || d / -slope <= safe {
            return NewtonStep::Short;
        }
        let next = t + sign * d / -slope;
        if next > t1 || next < t0 {
            return NewtonStep::Short;
        }
        let p = ray.at(next);
        let (nd, ns) = self.piece_distance(piece, p, s);
        if nd < -self.tolerance {
            return NewtonStep::Hit(self.bracketed(piece, ray, (t, d), (next, nd), ns));
        }
        if nd <= self.tolerance {
            return NewtonStep::Hit(self.polish(piece, ray, next, ns));
        }
        if approach(p, ns) < 0.0 {
            NewtonStep::Closer(next, nd, ns)
        } else {
            NewtonStep::Passed
        }
    }

    /// The crossing between a point outside and one inside, by regula falsi with the
    /// Illinois correction, then polished.
    fn bracketed(
        &self,
        piece: &Piece,
        ray: &Ray,
        outside: (f64, f64),
        inside: (f64, f64),
        s: f64,
    ) -> f64 {
        let ((mut ta, mut da), (mut tb, mut db)) = (outside, inside);
        let mut s = s;
        let mut side = 0;
        for _ in 0..64 {
            let t = (ta * db - tb * da) / (db - da);
            if !(t > ta.min(tb) && t < ta.max(tb)) {
                break;
            }
            let (d, ns) = self.piece_distance(piece, ray.at(t), s);
            s = ns;
            if d.abs() <= self.tolerance {
                return self.polish(piece, ray, t, s);
            }
            if d > 0.0 {
                (ta, da) = (t, d);
                if side == 1 {
                    db *= 0.5;
                }
                side = 1;
            } else {
                (tb, db) = (t, d);
                if side == -1 {
                    da *= 0.5;
                }
                side = -1;
            }
        }
        self.polish(piece, ray, ta, s)
    }

    /// Newton's method on the distance along the ray, from a point near the surface.
    fn polish(&self, piece: &Piece, ray: &Ray, t: f64, s: f64) -> f64 {
        let segment = &self.segments[piece.segment as usize];
        let mut t = t;
        let mut s = s;
        for _ in 0..4 {
            let p = ray.at(t);
            let (d, ns) = self.piece_distance(piece, p, s);
            s = ns;
            let n = (p - segment.centre(s)).normalize_or_zero();
            let slope = n.dot(ray.direction);
            if slope == 0.0 || d.abs() <= 1e-15 * (1.0 + p.abs().max_element()) {
                break;
            }
            let step = d / slope;
            // Only small corrections: a grazing ray must not be thrown far away.
            if step.abs() * ray.direction.length() > 4.0 * max(self.tolerance, d.abs()) {
                break;
            }
            t -= step;
        }
        t
    }

    /// The nearest crossing in `(tmin, tmax)`.
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<f64> {
        let mut candidates = Vec::new();
        self.candidates(ray, tmin, tmax, &mut candidates);
        if candidates.is_empty() {
            return None;
        }
        if self.inside_near(ray.at(tmin), &candidates, ray, tmin) {
            // Inside (a shadow or refracted ray): the first crossing is a way out.
            let mut all = Roots::new();
            self.crossings(ray, tmin, tmax, &candidates, &mut all);
            return all.as_slice().iter().map(|r| r.t).find(|&t| t > tmin);
        }
        let mut best = f64::INFINITY;
        for c in &candidates {
            if c.t0 >= best {
                break;
            }
            let piece = &self.pieces[c.piece as usize];
            if let Some(t) = self.trace_piece(piece, ray, c.t0, min(c.t1, best), true)
                && t > tmin
                && t < best
            {
                best = t;
            }
        }
        (best < tmax).then_some(best)
    }

    /// Whether `p` (at `t` along the ray) is inside one of the candidates' pieces.
    fn inside_near(&self, p: DVec3, candidates: &[Candidate], _ray: &Ray, t: f64) -> bool {
        candidates
            .iter()
            .filter(|c| c.t0 <= t && c.t1 >= t)
            .any(|c| {
                let piece = &self.pieces[c.piece as usize];
                self.piece_distance(piece, p, 0.5 * (piece.s0 + piece.s1)).0 < -self.tolerance
            })
    }

    /// Every crossing of the union's surface, nearest first.
    fn crossings(
        &self,
        ray: &Ray,
        tmin: f64,
        tmax: f64,
        candidates: &[Candidate],
        roots: &mut Roots,
    ) {
        let mut found: Vec<f64> = Vec::new();
        for c in candidates {
            let piece = &self.pieces[c.piece as usize];
            for entering in [true, false] {
                if let Some(t) = self.trace_piece(piece, ray, c.t0, c.t1, entering)
                    && t > tmin
                    && t < tmax
                {
                    // A crossing inside another piece is not on the union's surface.
                    let p = ray.at(t);
                    let hidden = candidates.iter().any(|o| {
                        o.piece != c.piece && o.t0 <= t && o.t1 >= t && {
                            let other = &self.pieces[o.piece as usize];
                            self.piece_distance(other, p, 0.5 * (other.s0 + other.s1)).0
                                < -self.tolerance
                        }
                    });
                    if !hidden {
                        found.push(t);
                    }
                }
            }
        }
        found.sort_by(f64::total_cmp);
        found.dedup_by(|a, b| (*a - *b).abs() <= 4.0 * self.tolerance / ray.direction.length());
        for t in found {
            roots.push(t, 0);
        }
    }

    /// Every crossing, nearest first (as many as fit).
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let mut candidates = Vec::new();
        self.candidates(ray, f64::NEG_INFINITY, f64::INFINITY, &mut candidates);
        self.crossings(ray, f64::NEG_INFINITY, f64::INFINITY, &candidates, roots);
    }

    /// The signed distance to the sweep and the nearest centre, over the pieces whose
    /// capsules hold `p`.
    fn nearest(&self, p: DVec3) -> Option<(f64, DVec3)> {
        let mut best: Option<(f64, DVec3)> = None;
        let mut stack = [0u32; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let i = stack[top] as usize;
            let node = self.nodes[i];
            if !(p.cmpge(node.bounds.min).all() && p.cmple(node.bounds.max).all()) {
                continue;
            }
            if node.count > 0 {
                for piece in &self.pieces[node.first as usize..(node.first + node.count) as usize] {
                    let (d, s) = self.piece_distance(piece, p, 0.5 * (piece.s0 + piece.s1));
                    if best.is_none_or(|b| d < b.0) {
                        let c = self.segments[piece.segment as usize].centre(s);
                        best = Some((d, c));
                    }
                }
            } else if top + 2 <= stack.len() {
                stack[top] = node.first;
                stack[top + 1] = i as u32 + 1;
                top += 2;
            }
        }
        best
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.nearest(p).is_some_and(|(d, _)| d <= 0.0)
    }

    pub fn normal(&self, p: DVec3) -> DVec3 {
        match self.nearest(p) {
            Some((_, c)) if p != c => p - c,
            _ => DVec3::Y,
        }
    }
}

/// The curve segments of a sweep through `spheres`.
fn segments(kind: SplineKind, spheres: &[(DVec3, f64)]) -> Vec<Segment> {
    let mut out = Vec::new();
    match kind {
        SplineKind::Linear => {
            for w in spheres.windows(2) {
                let ((p0, r0), (p1, r1)) = (w[0], w[1]);
                out.push(Segment {
                    c: [p0, p1 - p0, DVec3::ZERO, DVec3::ZERO],
                    r: [r0, r1 - r0, 0.0, 0.0],
                });
            }
        }
        SplineKind::BSpline => {
            for w in spheres.windows(4) {
                let c = |f: &dyn Fn(usize) -> DVec3| {
                    let (a, b, c, d) = (f(0), f(1), f(2), f(3));
                    [
                        (a + b * 4.0 + c) / 6.0,
                        (c - a) * 0.5,
                        (a - b * 2.0 + c) * 0.5,
                        (-a + b * 3.0 - c * 3.0 + d) / 6.0,
                    ]
                };
                let centres = c(&|i| w[i].0);
                let radii = c(&|i| DVec3::splat(w[i].1)).map(|v| v.x);
                out.push(Segment {
                    c: centres,
                    r: radii,
                });
            }
        }
        _ => {
            // Catmull-Rom through the inner points.
            for w in spheres.windows(4) {
                let c = |f: &dyn Fn(usize) -> DVec3| {
                    let (a, b, c, d) = (f(0), f(1), f(2), f(3));
                    [
                        b,
                        (c - a) * 0.5,
                        (a * 2.0 - b * 5.0 + c * 4.0 - d) * 0.5,
                        (-a + b * 3.0 - c * 3.0 + d) * 0.5,
                    ]
                };
                let centres = c(&|i| w[i].0);
                let radii = c(&|i| DVec3::splat(w[i].1)).map(|v| v.x);
                out.push(Segment {
                    c: centres,
                    r: radii,
                });
            }
        }
    }
    out
}

/// Splits `[s0, s1]` of a segment until each piece's capsule is tight.
fn split(segment: &Segment, index: u32, s0: f64, s1: f64, depth: u32, out: &mut Vec<Piece>) {
    let h = s1 - s0;
    let (a, da, _, ra, dra, _) = segment.derivatives(s0);
    let (b, db, _, rb, drb, _) = segment.derivatives(s1);
    // Bézier control points of the piece: the curve and radius lie in their hulls.
    let p1 = a + da * (h / 3.0);
    let p2 = b - db * (h / 3.0);
    let deviation = distance_to_segment(p1, a, b).max(distance_to_segment(p2, a, b));
    let radius = ra
        .max(rb)
        .max(ra + dra * h / 3.0)
        .max(rb - drb * h / 3.0)
        .max(0.0);
    if depth < MAX_SPLITS && deviation > DEVIATION_SHARE * radius.max(1e-300) {
        let mid = 0.5 * (s0 + s1);
        split(segment, index, s0, mid, depth + 1, out);
        split(segment, index, mid, s1, depth + 1, out);
        return;
    }
    out.push(Piece {
        segment: index,
        s0,
        s1,
        a,
        b,
        reach: radius + deviation,
    });
}

fn distance_to_segment(p: DVec3, a: DVec3, b: DVec3) -> f64 {
    let ab = b - a;
    let len2 = ab.length_squared();
    let t = if len2 > 0.0 {
        ((p - a).dot(ab) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    (p - (a + ab * t)).length()
}

/// A bounding volume hierarchy over the pieces, reordering them so that each leaf holds
/// a run; the root is node 0 and an inner node's children are the next node and `first`.
fn build_hierarchy(pieces: &mut [Piece]) -> Vec<Node> {
    let mut nodes = Vec::with_capacity(2 * pieces.len());
    build_node(pieces, 0, &mut nodes);
    nodes
}

fn build_node(pieces: &mut [Piece], offset: usize, nodes: &mut Vec<Node>) -> u32 {
    let bounds = pieces.iter().fold(Aabb::EMPTY, |b, p| b.union(&p.bounds()));
    let index = nodes.len() as u32;
    if pieces.len() <= 2 {
        nodes.push(Node {
            bounds,
            first: offset as u32,
            count: pieces.len() as u32,
        });
        return index;
    }
    nodes.push(Node {
        bounds,
        first: 0,
        count: 0,
    });
    let extent = bounds.max - bounds.min;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    pieces.sort_by(|a, b| (a.a[axis] + a.b[axis]).total_cmp(&(b.a[axis] + b.b[axis])));
    let mid = pieces.len() / 2;
    let (left, right) = pieces.split_at_mut(mid);
    build_node(left, offset, nodes);
    let second = build_node(right, offset + mid, nodes);
    // The first child directly follows its parent; the parent records where the second is.
    nodes[index as usize].first = second;
    index
}

#[cfg(test)]
mod tests {
    use super::*;

    fn knot() -> SphereSweep {
        let n = 17;
        let spheres: Vec<(DVec3, f64)> = (-1..=n + 1)
            .map(|i| {
                let theta = 2.0 * std::f64::consts::PI * f64::from(i) / f64::from(n);
                (
                    DVec3::new(
                        0.75 * (3.0 * theta + 0.1).cos(),
                        0.75 * (4.0 * theta + 0.7).cos(),
                        0.75 * (7.0 * theta).cos(),
                    ),
                    0.04,
                )
            })
            .collect();
        SphereSweep::new(SplineKind::BSpline, &spheres, 1e-6).unwrap()
    }

    #[test]
    fn hits_lie_on_the_surface_with_normals_facing_the_ray() {
        let sweep = knot();
        let mut hits = 0;
        for i in 0..40 {
            for j in 0..40 {
                let o = DVec3::new(-1.0 + 0.05 * f64::from(i), -1.0 + 0.05 * f64::from(j), -5.0);
                let ray = Ray::new(o, DVec3::new(0.01, 0.02, 1.0));
                if let Some(t) = sweep.first_hit(&ray, 0.0, f64::INFINITY) {
                    hits += 1;
                    let p = ray.at(t);
                    let (d, _) = sweep.nearest(p).unwrap();
                    assert!(d.abs() < 1e-6, "off the surface by {d}");
                    assert!(sweep.normal(p).dot(ray.direction) < 0.0);
                }
            }
        }
        assert!(hits > 40, "{hits}");
    }

    #[test]
    fn a_straight_sweep_is_a_capsule() {
        let spheres = [
            (DVec3::new(-1.0, 0.0, 0.0), 0.5),
            (DVec3::new(1.0, 0.0, 0.0), 0.5),
        ];
        let sweep = SphereSweep::new(SplineKind::Linear, &spheres, 1e-6).unwrap();
        let ray = Ray::new(DVec3::new(0.3, 0.0, -3.0), DVec3::Z);
        let t = sweep.first_hit(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((t - 2.5).abs() < 1e-9, "{t}");
        let end = Ray::new(DVec3::new(1.2, 0.0, -3.0), DVec3::Z);
        let t = sweep.first_hit(&end, 0.0, f64::INFINITY).unwrap();
        assert!((t - (3.0 - (0.25f64 - 0.04).sqrt())).abs() < 1e-9, "{t}");
        let mut roots = Roots::new();
        sweep.intersect(&ray, &mut roots);
        let r: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
        assert_eq!(r.len(), 2, "{r:?}");
        assert!((r[1] - 3.5).abs() < 1e-9, "{r:?}");
        // From inside, the first crossing is the way out.
        let t = sweep
            .first_hit(&Ray::new(DVec3::ZERO, DVec3::Z), 1e-9, f64::INFINITY)
            .unwrap();
        assert!((t - 0.5).abs() < 1e-9, "{t}");
    }

    #[test]
    fn tiny_radii_stay_finite() {
        let spheres: Vec<(DVec3, f64)> = (0..6)
            .map(|i| {
                (
                    DVec3::new(f64::from(i) * 0.2, (f64::from(i)).sin() * 0.3, 0.0),
                    1e-4,
                )
            })
            .collect();
        let sweep = SphereSweep::new(SplineKind::Cubic, &spheres, 1e-6).unwrap();
        for k in 0..200 {
            let y = -0.3 + 0.003 * f64::from(k);
            let ray = Ray::new(DVec3::new(0.5, y, -1.0), DVec3::Z);
            if let Some(t) = sweep.first_hit(&ray, 0.0, f64::INFINITY) {
                assert!(t.is_finite());
                assert!(sweep.normal(ray.at(t)).is_finite());
            }
        }
    }
}
