//! `isosurface`: where a function of x, y, z crosses its threshold, inside a box or sphere.
//! The root search is POV-Ray's, so that the same surface shows, holes included when
//! max_gradient is set too low: the ray's stretch inside the container is halved
//! recursively, nearest half first, and a stretch is dropped when the function's values
//! at its ends are too large for a function of gradient max_gradient to reach the
//! threshold in between. A stretch shorter than the accuracy whose far end lies inside
//! holds the crossing. The largest gradient met is recorded for POV-Ray's warning.

use super::Roots;
use crate::fast_math;
use crate::function_program::{Program, Registers};
use crate::ray::Ray;
use analysis::function::Function;
use analysis::scene::math_shapes::Container;
use glam::DVec3;
use std::cell::Cell;
use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

/// Parts of a hit: the surface itself, or a face of the container.
const PART_SURFACE: u32 = 0;
const PART_SPHERE: u32 = 7;

/// The function, compiled when it is code.
#[derive(Debug, Clone, PartialEq)]
pub enum FieldFunction {
    Program(Program),
    Function(Arc<Function>),
}

impl FieldFunction {
    pub fn new(function: &Arc<Function>) -> FieldFunction {
        match Program::compile(function, 3) {
            Some(p) => FieldFunction::Program(p),
            None => FieldFunction::Function(function.clone()),
        }
    }

    #[inline]
    pub fn eval(&self, p: DVec3) -> f64 {
        match self {
            FieldFunction::Program(program) => program.eval3(p.x, p.y, p.z),
            FieldFunction::Function(f) => f.eval(&[p.x, p.y, p.z]),
        }
    }

    /// The value at `p`, evaluated in registers the caller keeps.
    #[inline]
    fn eval_in(&self, registers: &mut Registers, p: DVec3) -> f64 {
        match self {
            FieldFunction::Program(program) => program.eval3_in(registers, p.x, p.y, p.z),
            FieldFunction::Function(f) => f.eval(&[p.x, p.y, p.z]),
        }
    }
}

/// The largest value seen by any thread, as the bits of a non-negative float (whose order
/// is the order of the bits).
#[derive(Debug, Default)]
pub struct SharedMax(AtomicU64);

impl SharedMax {
    pub fn record(&self, v: f64) {
        if v > 0.0 && v.is_finite() {
            self.0.fetch_max(v.to_bits(), Ordering::Relaxed);
        }
    }

    pub fn get(&self) -> f64 {
        f64::from_bits(self.0.load(Ordering::Relaxed))
    }
}

/// What a render found out about an isosurface, for POV-Ray's warning after the render.
#[derive(Debug, Default)]
pub struct GradientRecord {
    /// The largest gradient met between two evaluations.
    pub found: SharedMax,
    /// With `evaluate`, the largest max_gradient the adaptation reached.
    pub adapted: SharedMax,
}

#[derive(Debug, Clone)]
pub struct Isosurface {
    pub function: FieldFunction,
    pub container: Container,
    pub threshold: f64,
    pub accuracy: f64,
    pub max_gradient: f64,
    pub evaluate: Option<[f64; 3]>,
    pub closed: bool,
    pub max_trace: u32,
    /// -1 when the scene asked for `polarity`: the function's sign is turned around.
    pub sign: f64,
    pub record: Arc<GradientRecord>,
}

impl PartialEq for Isosurface {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.record, &other.record)
    }
}

/// The state of one ray's search.
struct Search<'a> {
    iso: &'a Isosurface,
    origin: DVec3,
    direction: DVec3,
    /// The sign that makes the searched-for side negative.
    side: f64,
    /// Length of the local direction: gradients are per unit of local distance.
    speed: f64,
    gradient: f64,
    max_gradient: f64,
    registers: Registers,
}

impl Search<'_> {
    fn value(&mut self, t: f64) -> f64 {
        let p = self.origin + self.direction * t;
        let f = self.iso.function.eval_in(&mut self.registers, p);
        self.side * (self.iso.sign * f - self.iso.threshold)
    }

    /// POV-Ray's recursive halving over `[t1, t2]` with values `f1`, `f2`; the far end of
    /// the first short stretch that ends inside, and the value there.
    fn halve(&mut self, t1: f64, f1: f64, t2: f64, f2: f64, reach: f64) -> Option<(f64, f64)> {
        let span = t2 - t1;
        let slope = (f2 - f1).abs() / (self.speed * span);
        if slope > self.gradient {
            self.gradient = slope;
        }
        let mut reach = reach;
        if let Some([_, over, _]) = self.iso.evaluate
            && self.max_gradient < slope * over
        {
            self.max_gradient = slope * over * over;
            reach = self.max_gradient * self.speed * span;
        }
        if span * self.speed < self.iso.accuracy {
            return (f2 < 0.0).then_some((t2, f2));
        }
        if f1 + f2 - reach >= 0.0 {
            return None;
        }
        let tm = t1 + 0.5 * span;
        let fm = self.value(tm);
        self.halve(t1, f1, tm, fm, 0.5 * reach)
            .or_else(|| self.halve(tm, fm, t2, f2, 0.5 * reach))
    }

    /// The first crossing in `[t1, t2]`, flipping the searched-for side first when the
    /// search starts inside an open isosurface.
    fn find(&mut self, t1: f64, t2: f64) -> Option<(f64, f64)> {
        let mut f1 = self.value(t1);
        if !self.iso.closed && f1 < 0.0 {
            self.side = -self.side;
            f1 = -f1;
        }
        let f2 = self.value(t2);
        if let Some([least, _, damping]) = self.iso.evaluate
            && self.max_gradient > least
        {
            self.max_gradient *= damping;
        }
        let reach = self.max_gradient * self.speed * (t2 - t1);
        self.halve(t1, f1, t2, f2, reach)
    }
}

impl Isosurface {
    /// The function less the threshold: negative inside.
    #[inline]
    pub fn value(&self, p: DVec3) -> f64 {
        self.sign * self.function.eval(p) - self.threshold
    }

    /// Where the ray enters and leaves the container, with the parts hit.
    fn container_span(&self, ray: &Ray) -> Option<(f64, u32, f64, u32)> {
        match self.container {
            Container::Sphere { center, radius } => {
                let o = ray.origin - center;
                let a = ray.direction.length_squared();
                let b = o.dot(ray.direction);
                let c = o.length_squared() - radius * radius;
                let (t1, t2) = super::solve_quadratic_half(a, b, c)?;
                Some((t1, PART_SPHERE, t2, PART_SPHERE))
            }
            Container::Box { corner1, corner2 } => {
                let mut near = (f64::NEG_INFINITY, 0u32);
                let mut far = (f64::INFINITY, 0u32);
                for axis in 0..3 {
                    let (o, d) = (ray.origin[axis], ray.direction[axis]);
                    let (lo, hi) = (corner1[axis], corner2[axis]);
                    if d == 0.0 {
                        if o < lo || o > hi {
                            return None;
                        }
                        continue;
                    }
                    let (mut ta, mut tb) = ((lo - o) / d, (hi - o) / d);
                    let (mut pa, mut pb) = (1 + 2 * axis as u32, 2 + 2 * axis as u32);
                    if ta > tb {
                        std::mem::swap(&mut ta, &mut tb);
                        std::mem::swap(&mut pa, &mut pb);
                    }
                    if ta > near.0 {
                        near = (ta, pa);
                    }
                    if tb < far.0 {
                        far = (tb, pb);
                    }
                }
                (near.0 <= far.0).then_some((near.0, near.1, far.0, far.1))
            }
        }
    }

    /// POV-Ray's crossings of the ray: the container's surface where it cuts a closed
    /// isosurface, then up to max_trace crossings of the function.
    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let Some((mut t1, side1, t2, side2)) = self.container_span(ray) else {
            return;
        };
        if t2 < 0.0 {
            return;
        }
        t1 = fast_math::max(t1, 0.0);
        let max_gradient = self.max_gradient.max(self.record.adapted.get());
        let mut search = Search {
            iso: self,
            origin: ray.origin,
            direction: ray.direction,
            side: 1.0,
            speed: ray.direction.length(),
            gradient: 0.0,
            max_gradient,
            registers: Registers::default(),
        };
        if !(search.speed > 0.0 && search.speed.is_finite()) {
            return;
        }
        // The accuracy is a distance in the isosurface's own frame; along the ray, whose
        // parameter is the world's, it spans this much of t. Compared with values, it
        // stays a distance.
        let accuracy = self.accuracy / search.speed;
        let reach = max_gradient * self.accuracy * 4.0;
        let mut traced = 0u32;
        // Where the container's surface counts, found before the search but put in order
        // around its crossings: the entry before them, the exit after them.
        let (mut entry, mut exit) = (None, None);
        if self.closed {
            let at_entry = search.value(t1);
            if t1 > accuracy {
                if at_entry < 0.0 {
                    entry = Some((t1, side1));
                    traced += 1;
                    search.side = -search.side;
                }
            } else {
                if at_entry < reach {
                    t1 = accuracy * 5.0;
                    if search.value(t1) < 0.0 {
                        search.side = -1.0;
                    }
                }
                if search.value(t2) < 0.0 {
                    exit = Some((t2, side2));
                }
            }
        }
        let mut tmin = fast_math::min(t1, t2);
        let tmax = t2;
        if tmax - tmin < accuracy {
            return;
        }
        if tmin < accuracy && search.side == 1.0 && search.value(tmin).abs() < reach {
            // Starting on the surface (a shadow ray from it): step off first.
            tmin = accuracy * 5.0;
            if search.value(tmin) < 0.0 {
                search.side = -1.0;
            }
        }
        if let Some((t, part)) = entry {
            roots.push(t, part);
        }
        while traced < self.max_trace {
            let Some((t, value)) = search.find(tmin, tmax) else {
                break;
            };
            if traced == 0 {
                remember_crossing(
                    self,
                    search.origin + search.direction * t,
                    search.side * value,
                );
            }
            roots.push(t, PART_SURFACE);
            traced += 1;
            tmin = t + accuracy * 5.0;
            if tmax - tmin < accuracy {
                break;
            }
            search.side = -search.side;
        }
        self.record.found.record(search.gradient);
        if self.evaluate.is_some() {
            self.record.adapted.record(search.max_gradient);
        }
        if let Some((t, part)) = exit {
            roots.push(t, part);
        }
    }

    pub fn inside(&self, p: DVec3) -> bool {
        let within = match self.container {
            Container::Sphere { center, radius } => {
                (p - center).length_squared() <= radius * radius
            }
            Container::Box { corner1, corner2 } => p.cmpge(corner1).all() && p.cmple(corner2).all(),
        };
        within && self.value(p) <= 0.0
    }

    /// The outward normal: the container's at its faces, else the function's gradient by
    /// forward differences one accuracy long, as POV-Ray takes it.
    pub fn normal(&self, p: DVec3, part: u32) -> DVec3 {
        match part {
            1..=6 => {
                let axis = ((part - 1) / 2) as usize;
                let mut n = DVec3::ZERO;
                n[axis] = if part % 2 == 1 { -1.0 } else { 1.0 };
                n
            }
            PART_SPHERE => match self.container {
                Container::Sphere { center, .. } => p - center,
                Container::Box { .. } => DVec3::Y,
            },
            _ => {
                let h = self.accuracy;
                let f = remembered_value(self, p).unwrap_or_else(|| self.value(p));
                let n = DVec3::new(
                    self.value(p + DVec3::X * h) - f,
                    self.value(p + DVec3::Y * h) - f,
                    self.value(p + DVec3::Z * h) - f,
                );
                if n == DVec3::ZERO || !n.is_finite() {
                    DVec3::X
                } else {
                    n
                }
            }
        }
    }

    pub fn bounds(&self) -> (DVec3, DVec3) {
        match self.container {
            Container::Sphere { center, radius } => {
                (center - DVec3::splat(radius), center + DVec3::splat(radius))
            }
            Container::Box { corner1, corner2 } => (corner1, corner2),
        }
    }
}

thread_local! {
    /// The isosurface (by address), point and value of the nearest crossing this thread
    /// found last: the normal is asked for there next, and its differences start from
    /// that value, which then costs no evaluation. A value is a function of the point
    /// alone, so whether it comes from here or is computed again changes nothing.
    static LAST_CROSSING: Cell<(usize, [u64; 3], f64)> = const { Cell::new((0, [0; 3], 0.0)) };
}

/// The key of a point of an isosurface in [`LAST_CROSSING`]: exact, bit for bit.
fn crossing_key(iso: &Isosurface, p: DVec3) -> (usize, [u64; 3]) {
    (
        std::ptr::from_ref(iso) as usize,
        p.to_array().map(f64::to_bits),
    )
}

fn remember_crossing(iso: &Isosurface, p: DVec3, value: f64) {
    let (address, point) = crossing_key(iso, p);
    LAST_CROSSING.set((address, point, value));
}

/// The value at `p` when it is the crossing found last.
fn remembered_value(iso: &Isosurface, p: DVec3) -> Option<f64> {
    let (address, point, value) = LAST_CROSSING.get();
    (crossing_key(iso, p) == (address, point)).then_some(value)
}

/// POV-Ray's warning about max_gradient after a render, when the gradient found calls for
/// one: too low a max_gradient may leave holes, too high a one costs time.
pub fn gradient_warning(
    record: &GradientRecord,
    max_gradient: f64,
    evaluate: bool,
) -> Option<String> {
    let found = record.found.get();
    let set = max_gradient.max(record.adapted.get());
    if evaluate || found <= 1e-10 || set <= 1e-10 {
        return None;
    }
    let diff = set - found;
    let ratio = (set / found).abs();
    if (ratio <= 0.9 && diff <= -0.5) || ((ratio <= 0.95 || diff <= -0.1) && set < 10.0) {
        Some(format!(
            "The maximum gradient found was {found:.3}, but max_gradient of the isosurface was set to {set:.3}. The isosurface may contain holes! Adjust max_gradient to get a proper rendering of the isosurface."
        ))
    } else if diff >= 10.0 || (ratio >= 1.1 && diff >= 0.5) {
        Some(format!(
            "The maximum gradient found was {found:.3}, but max_gradient of the isosurface was set to {set:.3}. Adjust max_gradient to get a faster rendering of the isosurface."
        ))
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use analysis::function::{Op, Unary};

    fn warning(s: &Isosurface) -> Option<String> {
        gradient_warning(&s.record, s.max_gradient, s.evaluate.is_some())
    }

    fn sphere_function(radius: f64) -> Arc<Function> {
        // sqrt(x² + y² + z²) - radius
        Arc::new(Function::code(
            vec!["x".into(), "y".into(), "z".into()],
            vec![
                Op::Param(0),
                Op::Unary(Unary::Sqr),
                Op::Param(1),
                Op::Unary(Unary::Sqr),
                Op::Add,
                Op::Param(2),
                Op::Unary(Unary::Sqr),
                Op::Add,
                Op::Unary(Unary::Sqrt),
                Op::Const(radius),
                Op::Sub,
            ],
        ))
    }

    fn iso(f: Arc<Function>, max_gradient: f64, closed: bool) -> Isosurface {
        Isosurface {
            function: FieldFunction::new(&f),
            container: Container::Box {
                corner1: DVec3::splat(-2.0),
                corner2: DVec3::splat(2.0),
            },
            threshold: 0.0,
            accuracy: 0.001,
            max_gradient,
            evaluate: None,
            closed,
            max_trace: 1,
            sign: 1.0,
            record: Arc::default(),
        }
    }

    #[test]
    fn finds_a_sphere_within_the_accuracy() {
        let s = iso(sphere_function(1.0), 1.1, true);
        let mut roots = Roots::new();
        s.intersect(&Ray::new(DVec3::new(0.2, 0.1, -5.0), DVec3::Z), &mut roots);
        let r = roots.as_slice();
        assert_eq!(r.len(), 1, "{r:?}");
        let want = 5.0 - (1.0f64 - 0.05).sqrt();
        assert!((r[0].t - want).abs() < 0.001, "{} {want}", r[0].t);
        let n = s.normal(Ray::new(DVec3::new(0.2, 0.1, -5.0), DVec3::Z).at(r[0].t), 0);
        assert!(n.normalize().dot(DVec3::new(0.2, 0.1, -0.97).normalize()) > 0.99);
        assert!(warning(&s).is_none(), "{:?}", warning(&s));
    }

    #[test]
    fn the_normal_at_the_crossing_found_last_reuses_its_value() {
        let s = iso(sphere_function(1.0), 1.1, true);
        let ray = Ray::new(DVec3::new(0.2, 0.1, -5.0), DVec3::Z);
        let mut roots = Roots::new();
        s.intersect(&ray, &mut roots);
        let p = ray.at(roots.as_slice()[0].t);
        assert_eq!(remembered_value(&s, p), Some(s.value(p)));
        let remembered = s.normal(p, 0);
        // Another ray's crossing takes its place: the normal is computed afresh, alike.
        let other = Ray::new(DVec3::new(-0.3, 0.2, -5.0), DVec3::Z);
        s.intersect(&other, &mut Roots::new());
        assert_eq!(remembered_value(&s, p), None);
        assert_eq!(s.normal(p, 0), remembered);
    }

    #[test]
    fn a_low_max_gradient_is_reported() {
        // f = 3·(|p| - 1) has gradient 3.
        let f = sphere_function(1.0);
        let triple = Arc::new(Function::code(
            vec!["x".into(), "y".into(), "z".into()],
            vec![
                Op::Param(0),
                Op::Param(1),
                Op::Param(2),
                Op::Call(f, 3),
                Op::Const(3.0),
                Op::Mul,
            ],
        ));
        let s = iso(triple, 2.0, true);
        let mut roots = Roots::new();
        s.intersect(&Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z), &mut roots);
        let warning = warning(&s).expect("a warning");
        assert!(
            warning.starts_with("The maximum gradient found was 3.000"),
            "{warning}"
        );
    }

    #[test]
    fn a_closed_isosurface_shows_the_container_where_it_cuts() {
        // A sphere of radius 3 fills the box: the ray meets the box's face.
        let s = iso(sphere_function(3.0), 1.1, true);
        let mut roots = Roots::new();
        s.intersect(&Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z), &mut roots);
        assert_eq!(roots.as_slice()[0].t, 3.0);
        assert_eq!(
            s.normal(DVec3::new(0.0, 0.0, -2.0), roots.as_slice()[0].part),
            -DVec3::Z
        );
        let open = iso(sphere_function(3.0), 1.1, false);
        let mut roots = Roots::new();
        open.intersect(&Ray::new(DVec3::new(0.0, 0.0, -5.0), DVec3::Z), &mut roots);
        assert!(roots.as_slice().is_empty(), "{:?}", roots.as_slice());
    }
}
