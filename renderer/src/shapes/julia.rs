//! `julia_fractal`: the points h₀ of a 3-D slice of 4-space whose orbit h ← f(h) + p stays
//! bounded for `max_iteration` steps. Rays march as POV-Ray's do, so that the same thin
//! filaments show: from the bounding sphere in steps of the distance estimate, never
//! shorter than 1/precision, until a step crosses the set's boundary, which bisection then
//! pins down to 1e-7. The normal is the gradient of |h_n|² with respect to the point.

use super::Root;
use crate::fast_math::{ln_at_least_one, max, min, round};
use crate::ray::Ray;
use analysis::scene::math_shapes::{JuliaAlgebra, JuliaFunction};
use glam::{DVec2, DVec3, DVec4};

/// How finely a crossing is pinned down, in the fractal's own units.
const TOLERANCE: f64 = 1e-7;

/// The longest orbit traced; longer `max_iteration`s are clamped here.
pub const MAX_ITERATIONS: u32 = 4096;

#[derive(Debug, Clone, PartialEq)]
pub struct Julia {
    pub parameter: DVec4,
    pub algebra: JuliaAlgebra,
    pub function: JuliaFunction,
    pub iterations: u32,
    /// The shortest march step: 1/precision.
    pub min_step: f64,
    /// (min_step · n)² (1 - 1e-9) for quaternion powers n: what a distance estimate's
    /// terms are compared with to show it shorter than the shortest step (see
    /// [`Julia::quaternion_orbit`]).
    pub short_bound: f64,
    pub slice: DVec4,
    pub slice_distance: f64,
    /// The bounding sphere's radius, and the squared norm past which an orbit escapes.
    pub radius: f64,
    pub exit: f64,
    /// The unit vector along the parameter's vector part (any unit vector when that part
    /// is zero), and that part's length: see [`Julia::quaternion_orbit`].
    pub axis: DVec3,
    pub vector_length: f64,
    /// Two unit vectors perpendicular to the axis and to each other: the vector part's
    /// components along them are those across the axis.
    pub across_axes: (DVec3, DVec3),
}

impl Julia {
    pub fn new(
        parameter: DVec4,
        algebra: JuliaAlgebra,
        function: JuliaFunction,
        max_iteration: u32,
        precision: f64,
        slice: DVec4,
        slice_distance: f64,
    ) -> Julia {
        // POV-Ray's bounds: quaternion sets lie within 1 + |p| (at most 2), hypercomplex
        // ones within 4.
        let (radius, exit) = match algebra {
            JuliaAlgebra::Quaternion => {
                let r = (1.0 + parameter.length() + TOLERANCE).min(2.0);
                (r, r * r + TOLERANCE)
            }
            JuliaAlgebra::Hypercomplex => (4.0, 16.0),
        };
        let min_step = 1.0 / precision.max(1.0);
        let vector = DVec3::new(parameter.y, parameter.z, parameter.w);
        let vector_length = vector.length();
        let axis = if vector_length > 0.0 {
            vector / vector_length
        } else {
            DVec3::X
        };
        Julia {
            parameter,
            algebra,
            function,
            iterations: max_iteration.clamp(1, MAX_ITERATIONS),
            min_step,
            short_bound: {
                let power = if function == JuliaFunction::Cube {
                    3.0
                } else {
                    2.0
                };
                (min_step * power) * (min_step * power) * (1.0 - 1e-9)
            },
            slice,
            slice_distance,
            radius,
            exit,
            axis,
            vector_length,
            across_axes: axis.any_orthonormal_pair(),
        }
    }

    /// The components of the vector part `v` across the axis (see [`Julia::across_axes`]).
    fn across(&self, v: DVec3) -> DVec2 {
        DVec2::new(v.dot(self.across_axes.0), v.dot(self.across_axes.1))
    }

    /// The 4-D point of the slice above `p`.
    fn lift(&self, p: DVec3) -> DVec4 {
        let w = (self.slice_distance - self.slice.truncate().dot(p)) / self.slice.w;
        DVec4::new(p.x, p.y, p.z, w)
    }

    /// Whether the orbit of `p` stays bounded.
    pub fn inside_point(&self, p: DVec3) -> bool {
        match self.kind() {
            QUATERNION_SQUARE => self.orbit::<QUATERNION_SQUARE, false>(self.lift(p)).inside,
            QUATERNION_CUBE => self.orbit::<QUATERNION_CUBE, false>(self.lift(p)).inside,
            _ => self.orbit::<HYPERCOMPLEX, false>(self.lift(p)).inside,
        }
    }

    /// Which of the three iterations the set is made by, as the `KIND` of [`Julia::orbit`].
    fn kind(&self) -> u8 {
        match (self.algebra, self.function) {
            (JuliaAlgebra::Quaternion, JuliaFunction::Cube) => QUATERNION_CUBE,
            (JuliaAlgebra::Quaternion, _) => QUATERNION_SQUARE,
            (JuliaAlgebra::Hypercomplex, _) => HYPERCOMPLEX,
        }
    }

    /// The orbit of `h`: whether it stays bounded, how far past the escape norm it went,
    /// and with `DISTANCE` a lower bound of the distance to the set when it escapes (the
    /// step a march may take). Without it the logarithms of the estimate are skipped: a
    /// refinement only asks for the side and the value. Inlined, so that the orbit's
    /// answer stays in locals rather than going through memory, as a returned structure
    /// does in WebAssembly; `KIND`, the iteration, is fixed when compiling, so that a
    /// quaternion march holds no call to the hypercomplex orbit, which would keep the
    /// point and the answer of every step in memory.
    #[inline(always)]
    fn orbit<const KIND: u8, const DISTANCE: bool>(&self, h: DVec4) -> Orbit {
        match KIND {
            QUATERNION_CUBE => self.quaternion_orbit::<DISTANCE>(self.plane_point(h), 3.0),
            QUATERNION_SQUARE => self.quaternion_orbit::<DISTANCE>(self.plane_point(h), 2.0),
            _ => self.hypercomplex_orbit::<DISTANCE>(h),
        }
    }

    /// [`Julia::orbit`] of the point at `depth` along `line`.
    #[inline(always)]
    fn orbit_on<const KIND: u8, const DISTANCE: bool>(
        &self,
        line: &PlaneLine,
        depth: f64,
    ) -> Orbit {
        match KIND {
            QUATERNION_CUBE => self.quaternion_orbit::<DISTANCE>(line.at(depth), 3.0),
            QUATERNION_SQUARE => self.quaternion_orbit::<DISTANCE>(line.at(depth), 2.0),
            _ => self.hypercomplex_orbit::<DISTANCE>(self.lift(line.origin + line.dir * depth)),
        }
    }

    /// The point `h` of 4-space in the coordinates of its quaternion orbit's plane (see
    /// [`Julia::quaternion_orbit`]).
    #[inline(always)]
    fn plane_point(&self, h: DVec4) -> PlanePoint {
        let v = DVec3::new(h.y, h.z, h.w);
        PlanePoint {
            real: h.x,
            along: v.dot(self.axis),
            // The components across keep that part accurate where v nearly lies along
            // the axis, as |v|² - along² would not.
            across: self.across(v).length_squared(),
        }
    }

    /// Quaternion squares or cubes. Quaternion norms multiply, so the derivative's norm
    /// for the distance estimate is the power times the product of the orbit's norms.
    ///
    /// Both powers scale the vector part v of h = (a, v) by a real number,
    /// (a, v)² = (a² - |v|², 2a·v) and (a, v)³ = (a³ - 3a|v|², (3a² - |v|²)·v), before the
    /// parameter's vector part is added; so the orbit's vector parts stay in the plane of
    /// the first one and the parameter's, and three reals follow the orbit there: a, the
    /// component `along` the parameter's vector part, and the squared component `across`
    /// it, which the scaling multiplies by the scale's square. That is a quarter of the
    /// arithmetic of a step in four coordinates; the norms, all a march asks for, are
    /// the same but for rounding.
    #[inline(always)]
    fn quaternion_orbit<const DISTANCE: bool>(&self, start: PlanePoint, power: f64) -> Orbit {
        let (c, vector_length) = (self.parameter.x, self.vector_length);
        let PlanePoint {
            real: mut a,
            mut along,
            mut across,
        } = start;
        let mut product: f64 = 1.0;
        // Cubes multiply the scale by 3 at each step; squares find 2^k when they need it,
        // from its bits, which saves the interpreter a multiplication at every step.
        let mut scale = 1.0;
        // The norm of the last point checked, whose excess over the escape norm is the
        // value, bounded or not.
        let mut norm = 1.0;
        for steps in 0..self.iterations {
            let a2 = a * a;
            let vector = along * along + across;
            norm = a2 + vector;
            if norm > self.exit {
                let scale = if power == 2.0 {
                    power_of_two(steps)
                } else {
                    scale
                };
                let value = norm - self.exit;
                let stretch = stretch(scale, product, power);
                if !DISTANCE {
                    return Orbit::escaped(value, 0.0, stretch);
                }
                // POV-Ray's estimate over the k points of the orbit so far, the escaping
                // one included: |h|·ln|h|² / (n^k · Π|h_j|). The march never steps
                // less than min_step, so an estimate shorter than that need not be taken:
                // ln x ≤ (x - 1)/√x for x ≥ 1 (the escape norm is at least 1) shows it
                // shorter without the logarithm, as it does at about four in five of the
                // steps that are. For squares the stretch is the scale² · product this
                // asks for.
                let reach = if power == 2.0 {
                    stretch
                } else {
                    scale * scale * product
                };
                let excess = norm - 1.0;
                if excess * excess < norm * reach * self.short_bound {
                    return Orbit::escaped(value, 0.0, stretch);
                }
                // The escape norm is above 1, and finite: the point before was within the
                // escape norm, at most 4 and a little.
                let dist = ln_at_least_one(norm) / (product.sqrt() * scale * power);
                return Orbit::escaped(value, dist, stretch);
            }
            product *= norm;
            if power != 2.0 {
                scale *= power;
            }
            if power == 2.0 {
                across *= 4.0 * a2;
                along = 2.0 * a * along + vector_length;
                a = a2 - vector + c;
            } else {
                let t = 3.0 * a2 - vector;
                a = a * (a2 - 3.0 * vector) + c;
                along = along * t + vector_length;
                across *= t * t;
            }
        }
        let scale = if power == 2.0 {
            power_of_two(self.iterations - 1)
        } else {
            scale / power
        };
        // A point past the escape norm (that of 1 + |c|) squares or cubes to one further
        // out than c can bring back, so a bounded orbit's points before the last stay
        // clear of the escape norm, and the set's boundary is where the last norm checked
        // reaches it: that norm less the escape norm is a value continuous across the
        // boundary, as the escaping orbits' is. The march gets it for nothing, where the
        // largest norm would cost a comparison at every step.
        Orbit {
            inside: true,
            dist: self.min_step,
            value: norm - self.exit,
            stretch: stretch(scale, product / norm, power),
        }
    }

    /// Hypercomplex iteration: the algebra splits into two complex planes,
    /// (x - w) + i(y + z) and (x + w) + i(y - z), where f acts on each.
    #[inline(never)]
    fn hypercomplex_orbit<const DISTANCE: bool>(&self, h: DVec4) -> Orbit {
        let (mut a, mut b) = split(h);
        let (pa, pb) = split(self.parameter);
        let mut da = Complex::ONE;
        let mut db = Complex::ONE;
        let mut peak: f64 = 0.0;
        for _ in 0..self.iterations {
            let norm = merged_norm(a, b);
            if norm > self.exit || !norm.is_finite() {
                // An orbit lost to overflow has gone past any norm.
                let value = if norm.is_finite() {
                    norm - self.exit
                } else {
                    f64::MAX
                };
                if !DISTANCE {
                    return Orbit::escaped(value, 0.0, f64::INFINITY);
                }
                let derivative = 0.5 * (da.norm() + db.norm());
                let dist = if derivative > 0.0 {
                    0.5 * norm.sqrt() * norm.ln() / derivative
                } else {
                    self.min_step
                };
                return Orbit::escaped(value, max(dist, 0.0), f64::INFINITY);
            }
            if !DISTANCE {
                peak = max(peak, norm);
            }
            let (fa, fda) = apply(self.function, a);
            let (fb, fdb) = apply(self.function, b);
            da = fda.mul(da);
            db = fdb.mul(db);
            a = fa.add(pa);
            b = fb.add(pb);
        }
        // How the orbit stretches is not tracked here: refining a crossing halves.
        self.bounded::<DISTANCE>(peak, f64::INFINITY)
    }

    /// A bounded hypercomplex orbit whose largest squared norm was `peak`. A march, which
    /// asks for distances, leaves the peak untracked: refining a hypercomplex crossing
    /// halves, and asks for no value.
    fn bounded<const DISTANCE: bool>(&self, peak: f64, stretch: f64) -> Orbit {
        Orbit {
            inside: true,
            dist: self.min_step,
            value: if DISTANCE { f64::NAN } else { peak - self.exit },
            stretch,
        }
    }

    /// The nearest crossing in `(tmin, tmax)` when `first` is set, or up to `out.len()`
    /// crossings from the start; returns how many were found.
    pub fn crossings(
        &self,
        ray: &Ray,
        tmin: f64,
        tmax: f64,
        first: bool,
        out: &mut [f64],
    ) -> usize {
        let len = ray.direction.length();
        if !len.is_finite() || len <= 0.0 {
            return 0;
        }
        let dir = ray.direction / len;
        // The bounding sphere, in unit steps along the normalised direction.
        let b = ray.origin.dot(dir);
        let c = ray.origin.length_squared() - self.radius * self.radius;
        let disc = b * b - c;
        if disc.is_nan() || disc < 0.0 {
            return 0;
        }
        let root = disc.sqrt();
        let (near, far) = (-b - root, -b + root);
        let end = min(far, tmax * len);
        if end < TOLERANCE {
            return 0;
        }
        let depth = max(max(near, TOLERANCE), tmin * len);
        if depth > end {
            return 0;
        }
        let (origin, span) = (ray.origin, (depth, end));
        match self.kind() {
            QUATERNION_SQUARE => {
                self.march::<QUATERNION_SQUARE>(origin, dir, span, len, first, out)
            }
            QUATERNION_CUBE => self.march::<QUATERNION_CUBE>(origin, dir, span, len, first, out),
            _ => self.march::<HYPERCOMPLEX>(origin, dir, span, len, first, out),
        }
    }

    /// [`Julia::crossings`] for the iteration `KIND`: the march from `origin` along the
    /// unit vector `dir` over the depths `span` (within the bounding sphere), whose
    /// crossings are given as depths divided by `len`, the ray direction's length.
    fn march<const KIND: u8>(
        &self,
        origin: DVec3,
        dir: DVec3,
        span: (f64, f64),
        len: f64,
        first: bool,
        out: &mut [f64],
    ) -> usize {
        let (mut depth, end) = span;
        // Each orbit starts afresh from the ray's point at its depth, not from a sum of
        // steps.
        let line = PlaneLine::new(self, origin, dir);
        let mut here = self.orbit_on::<KIND, true>(&line, depth);
        if here.inside {
            // A ray starting inside (a shadow ray from the surface) moves off first.
            depth += 2.0 * TOLERANCE;
            if depth > end {
                return 0;
            }
            here = self.orbit_on::<KIND, true>(&line, depth);
        }
        let mut found = 0;
        'march: while depth < end && found < out.len() {
            // March until a step lands on the other side of the boundary.
            let (before, step, next) = loop {
                // A plain comparison, without `max`'s test for NaN: a NaN estimate
                // compares false, and the shortest step is taken, as `max` would.
                let step = if here.dist > self.min_step {
                    here.dist
                } else {
                    self.min_step
                };
                let before = depth;
                depth += step;
                if depth > end {
                    break 'march;
                }
                let next = self.orbit_on::<KIND, true>(&line, depth);
                if next.inside != here.inside {
                    break (before, step, next);
                }
                here = next;
            };
            depth = before + self.refine::<KIND>(&line, before, step, &here, &next);
            if depth > end {
                break;
            }
            out[found] = depth / len;
            found += 1;
            if first {
                break;
            }
            here = next;
        }
        found
    }

    /// Where the boundary crosses the step along `line` from the depth `start` (whose
    /// orbit was `from`) to `start + step` (whose orbit was `to`, on the other side),
    /// each orbit started from its depth as the march's are: the offset of the
    /// inside end of the cell of the grid, the step halved down to the tolerance, that
    /// halving finds. Halving is what POV-Ray does, and where the boundary crosses the
    /// bracket many times (a fractal of many iterations) its choice shows. But once the
    /// bracket is shorter than the distance over which the orbit's value (the last norm it
    /// checked less the escape norm, which changes sign at the boundary) bends, the value
    /// is nearly linear there and crosses once: interpolation then finds halving's cell in
    /// two or three orbits where halving takes ten or more. Each trial is the grid point
    /// next to [`crossing_estimate`]'s crossing on the side away from the end the last
    /// trial moved, so that, the estimate being good, the next trial closes the bracket
    /// from the other side rather than creeping up on the crossing from one; should two
    /// trials fail to halve the bracket, the next halves it.
    fn refine<const KIND: u8>(
        &self,
        line: &PlaneLine,
        start: f64,
        step: f64,
        from: &Orbit,
        to: &Orbit,
    ) -> f64 {
        let mut cell = step;
        let mut cells: u64 = 1;
        while cell > TOLERANCE {
            cell *= 0.5;
            cells *= 2;
        }
        let (mut a, mut fa, mut sa) = (0, from.value, from.stretch);
        let (mut b, mut fb, mut sb) = (cells, to.value, to.stretch);
        // The end the last trial replaced, with its value: a third point for the
        // interpolation; and whether that end was `a`.
        let mut replaced: Option<(u64, f64)> = None;
        let mut moved_a = None;
        let (mut earlier, mut last) = (u64::MAX, u64::MAX);
        while b - a > 1 {
            let width = b - a;
            let length = width as f64 * cell;
            let straight = length * length * max(sa, sb) < 1.0;
            let trial = if straight && width < earlier / 2 {
                let third = replaced.map(|(at, value)| (at as f64 - a as f64, value));
                let x = crossing_estimate(width as f64, fa, fb, third);
                let next = match moved_a {
                    Some(true) => x.ceil(),
                    Some(false) => x.floor(),
                    None => round(x),
                };
                // On the grid, strictly inside the bracket (NaN goes to its start).
                a + (next as u64).clamp(1, width - 1)
            } else {
                a + width / 2
            };
            (earlier, last) = (last, width);
            let orbit = self.orbit_on::<KIND, false>(line, start + trial as f64 * cell);
            if orbit.inside == from.inside {
                replaced = Some((a, fa));
                moved_a = Some(true);
                (a, fa, sa) = (trial, orbit.value, orbit.stretch);
            } else {
                replaced = Some((b, fb));
                moved_a = Some(false);
                (b, fb, sb) = (trial, orbit.value, orbit.stretch);
            }
        }
        (if from.inside { a } else { b }) as f64 * cell
    }

    /// The gradient of |h_n|² at `p`: outward where orbits escape.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        if self.kind() == QUATERNION_SQUARE {
            return self.square_gradient(p);
        }
        // The orbit is kept for the backward pass; short ones, the usual, on the stack.
        let steps = self.iterations as usize;
        if steps <= SHORT_ORBIT {
            self.gradient(p, &mut [DVec4::ZERO; SHORT_ORBIT + 1][..=steps])
        } else {
            self.gradient(p, &mut vec![DVec4::ZERO; steps + 1])
        }
    }

    /// [`Julia::gradient`] for quaternion squares (half of it, which points the same way),
    /// carried forwards in the plane the orbit stays in (see [`Julia::quaternion_orbit`]):
    /// the gradients of its three reals with respect to the point, three vectors per step
    /// where the pass backwards through four coordinates needs the orbit kept in memory.
    /// With the real part a, the component u along the axis and the squared component
    /// across it Y, a step (a² - u² - Y + c₀, 2au + |c|, 4a²Y) moves the gradients as
    /// (2a·da - 2u·du - dY, 2u·da + 2a·du, 8aY·da + 4a²·dY), and |h|²/2 = (a² + u² + Y)/2
    /// has the gradient a·da + u·du + dY/2.
    fn square_gradient(&self, p: DVec3) -> DVec3 {
        let h = self.lift(p);
        let v = DVec3::new(h.y, h.z, h.w);
        let across = v.cross(self.axis);
        let (mut a, mut u, mut y) = (h.x, v.dot(self.axis), across.length_squared());
        // The point's x, y and z are the real part and the vector part's first two
        // components; its w is held fixed.
        let mut da = DVec3::X;
        let mut du = DVec3::new(0.0, self.axis.x, self.axis.y);
        let mut dy = 2.0
            * DVec3::new(
                0.0,
                across.dot(DVec3::X.cross(self.axis)),
                across.dot(DVec3::Y.cross(self.axis)),
            );
        let (c, vector_length) = (self.parameter.x, self.vector_length);
        for _ in 0..self.iterations {
            let a2 = a * a;
            (da, du, dy) = (
                2.0 * a * da - 2.0 * u * du - dy,
                2.0 * u * da + 2.0 * a * du,
                8.0 * a * y * da + 4.0 * a2 * dy,
            );
            (a, u, y) = (
                a2 - u * u - y + c,
                2.0 * a * u + vector_length,
                4.0 * a2 * y,
            );
            // The squared norm alone tells an overflowing orbit: it is infinite or NaN.
            let norm = a * a + u * u + y;
            if norm > 1e100 || norm.is_nan() {
                break;
            }
        }
        let n = a * da + u * du + 0.5 * dy;
        if n.is_finite() && n != DVec3::ZERO {
            n
        } else {
            p
        }
    }

    /// The gradient of |h_n|² at `p`, with room for the orbit in `orbit` (one more point
    /// than steps). Finite differences of the escape-time potential would be noisy;
    /// instead the orbit's derivative is taken exactly, as POV-Ray does (with w held
    /// fixed, as POV-Ray holds it). It is carried backwards, from h_n through each step's
    /// transposed derivative to the start: one vector per step, where carrying the three
    /// tangents of x, y and z forwards would take three.
    fn gradient(&self, p: DVec3, orbit: &mut [DVec4]) -> DVec3 {
        orbit[0] = self.lift(p);
        let mut last = 0;
        while last + 1 < orbit.len() {
            let q = self.step(orbit[last]);
            last += 1;
            orbit[last] = q;
            // The squared norm alone tells an overflowing orbit: it is infinite or NaN.
            let norm = q.length_squared();
            if norm > 1e100 || norm.is_nan() {
                break;
            }
        }
        let mut g = orbit[last];
        for &q in orbit[..last].iter().rev() {
            g = self.pullback(q, g);
        }
        let n = g.truncate();
        if n.is_finite() && n != DVec3::ZERO {
            n
        } else {
            p
        }
    }

    /// One step of the orbit from `q`.
    fn step(&self, q: DVec4) -> DVec4 {
        let p = self.parameter;
        match (self.algebra, self.function) {
            (JuliaAlgebra::Quaternion, JuliaFunction::Cube) => {
                let d = q.y * q.y + q.z * q.z + q.w * q.w;
                let x2 = q.x * q.x;
                let t = 3.0 * x2 - d;
                DVec4::new(q.x * (x2 - 3.0 * d), q.y * t, q.z * t, q.w * t) + p
            }
            (JuliaAlgebra::Quaternion, _) => {
                let d = q.y * q.y + q.z * q.z + q.w * q.w;
                DVec4::new(
                    q.x * q.x - d,
                    2.0 * q.x * q.y,
                    2.0 * q.x * q.z,
                    2.0 * q.x * q.w,
                ) + p
            }
            (JuliaAlgebra::Hypercomplex, f) => {
                let (a, b) = split(q);
                let (pa, pb) = split(p);
                merge(apply(f, a).0.add(pa), apply(f, b).0.add(pb))
            }
        }
    }

    /// The transposed derivative of the step at `q`, applied to `g`: the gradient with
    /// respect to `q` of a quantity whose gradient with respect to the next point is `g`.
    fn pullback(&self, q: DVec4, g: DVec4) -> DVec4 {
        match (self.algebra, self.function) {
            (JuliaAlgebra::Quaternion, JuliaFunction::Cube) => {
                // d(h³) = h² dh + h dh h + dh h²; the transpose of a product by a
                // quaternion is the product by its conjugate.
                let c = qconj(q);
                let c2 = qmul(c, c);
                qmul(c2, g) + qmul(qmul(c, g), c) + qmul(g, c2)
            }
            // d(h²) = h dh + dh h, whose cross products cancel.
            (JuliaAlgebra::Quaternion, _) => {
                let real = q.x * g.x + (q.y * g.y + q.z * g.z + q.w * g.w);
                2.0 * DVec4::new(
                    real,
                    q.x * g.y - g.x * q.y,
                    q.x * g.z - g.x * q.z,
                    q.x * g.w - g.x * q.w,
                )
            }
            // The split is a scaled rotation (its transpose is twice the merge), and the
            // transpose of a product by a complex number is the product by its conjugate.
            (JuliaAlgebra::Hypercomplex, f) => {
                let (a, b) = split(q);
                let (ga, gb) = split(g);
                merge(apply(f, a).1.conj().mul(ga), apply(f, b).1.conj().mul(gb))
            }
        }
    }
}

/// The squared norm of a quaternion orbit's derivative after k steps of `power` (2 or 3),
/// from the power to the k and the product of the orbit's squared norms: each square
/// stretches by 2|h|, each cube by 3|h|².
fn stretch(scale: f64, product: f64, power: f64) -> f64 {
    if power == 2.0 {
        scale * scale * product
    } else {
        let d = scale * product;
        d * d
    }
}

/// Where a value that is `fa` at 0 and `fb` at `width` (of opposite signs) crosses zero:
/// where the inverse quadratic through those and the `third` point (its position and
/// value) does, when that lies strictly inside the bracket, and otherwise where the chord
/// does. Near a simple crossing the quadratic is the better guess by far (its error
/// shrinks with the product of the three points' distances from the crossing, the
/// chord's with that of two), and where it strays outside the bracket the chord is safe.
fn crossing_estimate(width: f64, fa: f64, fb: f64, third: Option<(f64, f64)>) -> f64 {
    if let Some((c, fc)) = third {
        let quadratic =
            width * fa * fc / ((fb - fa) * (fb - fc)) + c * fa * fb / ((fc - fa) * (fc - fb));
        // False for NaN: a third point without a value, or two equal values.
        if quadratic > 0.0 && quadratic < width {
            return quadratic;
        }
    }
    width * (fa / (fa - fb))
}

/// 2^k, exactly, as repeated doubling gives it: infinite past 2^1023. The exponent field
/// of 2^1024 would be all ones, the bits of infinity.
fn power_of_two(k: u32) -> f64 {
    f64::from_bits(u64::from(1023 + k.min(1024)) << 52)
}

/// The iterations a set may be made by, as the `KIND` of [`Julia::orbit`].
const QUATERNION_SQUARE: u8 = 0;
const QUATERNION_CUBE: u8 = 1;
const HYPERCOMPLEX: u8 = 2;

/// What an orbit tells of its starting point.
#[derive(Debug, Clone, Copy)]
struct Orbit {
    inside: bool,
    /// How far a march may step from the point; 0 where that is less than the
    /// shortest step, which the march takes instead.
    dist: f64,
    /// The squared norm of the last point of the orbit checked less the escape norm:
    /// positive outside, negative or zero inside, and continuous across the boundary.
    /// For bounded hypercomplex orbits the largest squared norm is taken instead, and
    /// NaN in a march, which does not track it.
    value: f64,
    /// The square of how far the last point of the orbit whose norm was checked (the
    /// escaping one, or a bounded orbit's point before its last step) moves per unit the
    /// start moves (a bound, for quaternions, the norm of the derivative; infinite when
    /// not known): the value bends over distances of about its inverse root.
    stretch: f64,
}

impl Orbit {
    fn escaped(value: f64, dist: f64, stretch: f64) -> Orbit {
        Orbit {
            inside: false,
            dist,
            value,
            stretch,
        }
    }
}

/// A point of 4-space as the three reals its quaternion orbit follows (see
/// [`Julia::quaternion_orbit`]): the real part, and the components of the vector part
/// along the parameter's vector part and (squared) across it.
#[derive(Debug, Clone, Copy)]
struct PlanePoint {
    real: f64,
    along: f64,
    across: f64,
}

/// A ray through the slice from `origin` along the unit vector `dir`, and its points in
/// the coordinates of [`PlanePoint`]: the real part and the along component are linear in
/// the depth, and the across component is the squared length of a vector that is linear
/// in it: the vector part's components across the axis.
struct PlaneLine {
    origin: DVec3,
    dir: DVec3,
    real: (f64, f64),
    along: (f64, f64),
    across: (DVec2, DVec2),
}

impl PlaneLine {
    /// The ray from `origin` along the unit vector `dir`, each pair the value at depth 0
    /// and the change per unit depth.
    fn new(julia: &Julia, origin: DVec3, dir: DVec3) -> PlaneLine {
        let start = julia.lift(origin);
        let tilt = -julia.slice.truncate().dot(dir) / julia.slice.w;
        let (v, dv) = (
            DVec3::new(start.y, start.z, start.w),
            DVec3::new(dir.y, dir.z, tilt),
        );
        PlaneLine {
            origin,
            dir,
            real: (start.x, dir.x),
            along: (v.dot(julia.axis), dv.dot(julia.axis)),
            across: (julia.across(v), julia.across(dv)),
        }
    }

    #[inline(always)]
    fn at(&self, depth: f64) -> PlanePoint {
        PlanePoint {
            real: self.real.0 + self.real.1 * depth,
            along: self.along.0 + self.along.1 * depth,
            across: (self.across.0 + self.across.1 * depth).length_squared(),
        }
    }
}

/// The longest orbit whose normal keeps it on the stack.
const SHORT_ORBIT: usize = 32;

/// The quaternion conjugate.
fn qconj(a: DVec4) -> DVec4 {
    DVec4::new(a.x, -a.y, -a.z, -a.w)
}

/// The quaternion product.
fn qmul(a: DVec4, b: DVec4) -> DVec4 {
    DVec4::new(
        a.x * b.x - a.y * b.y - a.z * b.z - a.w * b.w,
        a.x * b.y + a.y * b.x + a.z * b.w - a.w * b.z,
        a.x * b.z - a.y * b.w + a.z * b.x + a.w * b.y,
        a.x * b.w + a.y * b.z - a.z * b.y + a.w * b.x,
    )
}

/// A complex number.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Complex {
    re: f64,
    im: f64,
}

impl Complex {
    const ONE: Complex = Complex { re: 1.0, im: 0.0 };

    fn new(re: f64, im: f64) -> Complex {
        Complex { re, im }
    }

    fn add(self, o: Complex) -> Complex {
        Complex::new(self.re + o.re, self.im + o.im)
    }

    fn sub(self, o: Complex) -> Complex {
        Complex::new(self.re - o.re, self.im - o.im)
    }

    fn mul(self, o: Complex) -> Complex {
        Complex::new(
            self.re * o.re - self.im * o.im,
            self.re * o.im + self.im * o.re,
        )
    }

    fn div(self, o: Complex) -> Complex {
        let d = o.re * o.re + o.im * o.im;
        Complex::new(
            (self.re * o.re + self.im * o.im) / d,
            (self.im * o.re - self.re * o.im) / d,
        )
    }

    fn conj(self) -> Complex {
        Complex::new(self.re, -self.im)
    }

    fn scale(self, s: f64) -> Complex {
        Complex::new(self.re * s, self.im * s)
    }

    fn norm(self) -> f64 {
        self.re.hypot(self.im)
    }

    fn exp(self) -> Complex {
        let m = self.re.exp();
        Complex::new(m * self.im.cos(), m * self.im.sin())
    }

    fn ln(self) -> Complex {
        Complex::new(self.norm().ln(), self.im.atan2(self.re))
    }

    fn sqrt(self) -> Complex {
        let m = self.norm();
        let re = max((m + self.re) * 0.5, 0.0).sqrt();
        let im = max((m - self.re) * 0.5, 0.0).sqrt();
        Complex::new(re, if self.im < 0.0 { -im } else { im })
    }

    fn sin(self) -> Complex {
        Complex::new(
            self.re.sin() * self.im.cosh(),
            self.re.cos() * self.im.sinh(),
        )
    }

    fn cos(self) -> Complex {
        Complex::new(
            self.re.cos() * self.im.cosh(),
            -self.re.sin() * self.im.sinh(),
        )
    }

    fn sinh(self) -> Complex {
        Complex::new(
            self.re.sinh() * self.im.cos(),
            self.re.cosh() * self.im.sin(),
        )
    }

    fn cosh(self) -> Complex {
        Complex::new(
            self.re.cosh() * self.im.cos(),
            self.re.sinh() * self.im.sin(),
        )
    }
}

const I: Complex = Complex { re: 0.0, im: 1.0 };

/// f(z) and f'(z) for one complex plane of the hypercomplex algebra.
fn apply(f: JuliaFunction, z: Complex) -> (Complex, Complex) {
    let one = Complex::ONE;
    match f {
        JuliaFunction::Sqr => (z.mul(z), z.scale(2.0)),
        JuliaFunction::Cube => (z.mul(z).mul(z), z.mul(z).scale(3.0)),
        JuliaFunction::Reciprocal => {
            let r = one.div(z);
            (r, r.mul(r).scale(-1.0))
        }
        JuliaFunction::Exp => {
            let e = z.exp();
            (e, e)
        }
        JuliaFunction::Ln => (z.ln(), one.div(z)),
        JuliaFunction::Sin => (z.sin(), z.cos()),
        JuliaFunction::Cos => (z.cos(), z.sin().scale(-1.0)),
        JuliaFunction::Tan => {
            let c = z.cos();
            (z.sin().div(c), one.div(c.mul(c)))
        }
        JuliaFunction::Sinh => (z.sinh(), z.cosh()),
        JuliaFunction::Cosh => (z.cosh(), z.sinh()),
        JuliaFunction::Tanh => {
            let c = z.cosh();
            (z.sinh().div(c), one.div(c.mul(c)))
        }
        JuliaFunction::Asin => {
            // asin z = -i ln(iz + √(1 - z²)).
            let root = one.sub(z.mul(z)).sqrt();
            let v = I.mul(z).add(root).ln().mul(Complex::new(0.0, -1.0));
            (v, one.div(root))
        }
        JuliaFunction::Acos => {
            // acos z = -i ln(z + i√(1 - z²)).
            let root = one.sub(z.mul(z)).sqrt();
            let v = z.add(I.mul(root)).ln().mul(Complex::new(0.0, -1.0));
            (v, one.div(root).scale(-1.0))
        }
        JuliaFunction::Atan => {
            // atan z = (i/2) ln((i + z)/(i - z)).
            let v = I.add(z).div(I.sub(z)).ln().mul(Complex::new(0.0, 0.5));
            (v, one.div(one.add(z.mul(z))))
        }
        JuliaFunction::Asinh => {
            let root = z.mul(z).add(one).sqrt();
            (z.add(root).ln(), one.div(root))
        }
        JuliaFunction::Acosh => {
            let root = z.add(one).sqrt().mul(z.sub(one).sqrt());
            (z.add(root).ln(), one.div(root))
        }
        JuliaFunction::Atanh => {
            let v = one.add(z).div(one.sub(z)).ln().scale(0.5);
            (v, one.div(one.sub(z.mul(z))))
        }
        JuliaFunction::Pwr(re, im) => {
            // z^w = exp(w ln z); its derivative w z^w / z.
            let w = Complex::new(re, im);
            let v = w.mul(z.ln()).exp();
            (v, w.mul(v).div(z))
        }
    }
}

/// The two complex planes of a hypercomplex number.
fn split(h: DVec4) -> (Complex, Complex) {
    (
        Complex::new(h.x - h.w, h.y + h.z),
        Complex::new(h.x + h.w, h.y - h.z),
    )
}

/// The hypercomplex number with the complex planes `a` and `b`.
fn merge(a: Complex, b: Complex) -> DVec4 {
    DVec4::new(
        0.5 * (a.re + b.re),
        0.5 * (a.im + b.im),
        0.5 * (a.im - b.im),
        0.5 * (b.re - a.re),
    )
}

/// The squared 4-D norm of the number with complex planes `a` and `b`.
fn merged_norm(a: Complex, b: Complex) -> f64 {
    merge(a, b).length_squared()
}

/// The nearest crossing of a julia fractal as a root.
pub fn first_root(julia: &Julia, ray: &Ray, tmin: f64, tmax: f64) -> Option<Root> {
    let mut t = [0.0];
    (julia.crossings(ray, tmin, tmax, true, &mut t) == 1).then_some(Root { t: t[0], part: 0 })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gallery_julia(iterations: u32) -> Julia {
        Julia::new(
            DVec4::new(-0.083, 0.0, -0.83, -0.025),
            JuliaAlgebra::Quaternion,
            JuliaFunction::Sqr,
            iterations,
            50.0,
            DVec4::new(0.0, 0.0, 0.0, 1.0),
            0.15,
        )
    }

    #[test]
    fn a_ray_through_the_middle_hits_and_the_normal_faces_it() {
        let julia = gallery_julia(8);
        let ray = Ray::new(DVec3::new(0.0, 0.0, -3.0), DVec3::Z);
        let hit = first_root(&julia, &ray, 0.0, f64::INFINITY).expect("a hit");
        let p = ray.at(hit.t);
        assert!(julia.inside_point(p + DVec3::Z * 1e-6), "{p}");
        assert!(!julia.inside_point(p - DVec3::Z * 1e-3), "{p}");
        assert!(julia.normal(p).dot(ray.direction) < 0.0);
        // A ray past the bounding sphere misses.
        let away = Ray::new(DVec3::new(3.0, 0.0, -3.0), DVec3::Z);
        assert!(first_root(&julia, &away, 0.0, f64::INFINITY).is_none());
    }

    #[test]
    fn the_pullback_is_the_transposed_derivative_of_the_step() {
        // ⟨D v, g⟩ = ⟨v, Dᵀ g⟩, with D v by central differences of the step.
        let (q, v, g) = (
            DVec4::new(0.3, -0.7, 0.2, 0.9),
            DVec4::new(-0.4, 0.1, 0.8, 0.25),
            DVec4::new(0.6, 0.35, -0.2, -0.5),
        );
        let algebras = [
            (JuliaAlgebra::Quaternion, JuliaFunction::Sqr),
            (JuliaAlgebra::Quaternion, JuliaFunction::Cube),
            (JuliaAlgebra::Hypercomplex, JuliaFunction::Sqr),
            (JuliaAlgebra::Hypercomplex, JuliaFunction::Sin),
            (JuliaAlgebra::Hypercomplex, JuliaFunction::Pwr(2.0, 0.5)),
        ];
        for (algebra, function) in algebras {
            let julia = Julia::new(
                DVec4::new(0.4, 0.2, 0.1, 0.0),
                algebra,
                function,
                8,
                20.0,
                DVec4::new(0.0, 0.0, 0.0, 1.0),
                0.0,
            );
            let h = 1e-6;
            let dv = (julia.step(q + v * h) - julia.step(q - v * h)) / (2.0 * h);
            let (want, got) = (dv.dot(g), v.dot(julia.pullback(q, g)));
            assert!(
                (want - got).abs() < 1e-8,
                "{algebra:?} {function:?}: {want} {got}"
            );
        }
    }

    #[test]
    fn the_plane_orbit_follows_the_orbit_in_four_dimensions() {
        // Squares and cubes, with a parameter whose vector part is zero too: the orbit
        // followed in its plane escapes at the same step, with the same norm but for
        // rounding, as the one stepped in four coordinates.
        let cases = [
            (DVec4::new(-0.083, 0.0, -0.83, -0.025), JuliaFunction::Sqr),
            (DVec4::new(-0.2, 0.6, 0.2, 0.2), JuliaFunction::Cube),
            (DVec4::new(-0.75, 0.0, 0.0, 0.0), JuliaFunction::Sqr),
        ];
        for (parameter, function) in cases {
            let julia = Julia::new(
                parameter,
                JuliaAlgebra::Quaternion,
                function,
                12,
                50.0,
                DVec4::new(0.0, 0.0, 0.0, 1.0),
                0.0,
            );
            for k in 0..400 {
                let t = f64::from(k);
                let h = 1.2
                    * DVec4::new(
                        (0.7 * t).sin(),
                        (1.3 * t).cos(),
                        (2.1 * t).sin(),
                        (0.3 * t).cos(),
                    );
                let got = if function == JuliaFunction::Cube {
                    julia.orbit::<QUATERNION_CUBE, false>(h)
                } else {
                    julia.orbit::<QUATERNION_SQUARE, false>(h)
                };
                let (mut q, mut last) = (h, 0.0);
                let mut escaped = false;
                for _ in 0..julia.iterations {
                    last = q.length_squared();
                    if last > julia.exit {
                        escaped = true;
                        break;
                    }
                    q = julia.step(q);
                }
                let want = last - julia.exit;
                assert_eq!(got.inside, !escaped, "{function:?} {h}");
                assert!(
                    (got.value - want).abs() <= 1e-9 * (1.0 + want.abs()),
                    "{function:?} {h}: {} {want}",
                    got.value
                );
            }
        }
    }

    #[test]
    fn the_stretch_bounds_the_derivative_at_the_last_point_checked() {
        // n² |h|² (squares) or n² |h|⁴ (cubes) for each point the value depends on: up to
        // the escaping point, or to a bounded orbit's point before its last step.
        for (function, power) in [(JuliaFunction::Sqr, 2.0), (JuliaFunction::Cube, 3.0)] {
            let julia = Julia::new(
                DVec4::new(-0.083, 0.0, -0.83, -0.025),
                JuliaAlgebra::Quaternion,
                function,
                8,
                50.0,
                DVec4::new(0.0, 0.0, 0.0, 1.0),
                0.0,
            );
            let (mut inside, mut outside) = (0, 0);
            for k in 0..200 {
                let t = f64::from(k);
                let h = 0.9 * DVec4::new((0.7 * t).sin(), (1.3 * t).cos(), (2.1 * t).sin(), 0.0);
                let got = if power == 2.0 {
                    julia.orbit::<QUATERNION_SQUARE, false>(h)
                } else {
                    julia.orbit::<QUATERNION_CUBE, false>(h)
                };
                let (mut q, mut want) = (h, 1.0);
                for step in 0..julia.iterations {
                    let norm = q.length_squared();
                    if norm > julia.exit || step + 1 == julia.iterations {
                        break;
                    }
                    want *= power * power * norm.powf(power - 1.0);
                    q = julia.step(q);
                }
                assert!(
                    (got.stretch - want).abs() <= 1e-9 * want,
                    "{function:?} {h}: {} {want}",
                    got.stretch
                );
                if got.inside {
                    inside += 1;
                } else {
                    outside += 1;
                }
            }
            assert!(inside > 10 && outside > 10, "{inside} {outside}");
        }
    }

    /// The gallery's fractal with a parameter of every component, on a tilted slice.
    fn tilted_julia() -> Julia {
        Julia::new(
            DVec4::new(-0.083, 0.3, -0.83, -0.025),
            JuliaAlgebra::Quaternion,
            JuliaFunction::Sqr,
            8,
            50.0,
            DVec4::new(0.2, -0.1, 0.3, 0.9),
            0.15,
        )
    }

    #[test]
    fn the_square_gradient_in_the_plane_is_the_one_through_four_coordinates() {
        // Points inside, near and outside the set: the same direction but for rounding.
        let julia = tilted_julia();
        let mut orbit = [DVec4::ZERO; 9];
        for k in 0..400 {
            let t = f64::from(k);
            let p = 1.1 * DVec3::new((0.7 * t).sin(), (1.3 * t).cos(), (2.1 * t).sin());
            let (got, want) = (julia.square_gradient(p), julia.gradient(p, &mut orbit));
            assert!(
                (got.normalize() - want.normalize()).length() < 1e-9,
                "{p}: {got} {want}"
            );
        }
    }

    #[test]
    fn a_power_of_two_is_repeated_doubling() {
        let mut doubled = 1.0_f64;
        for k in 0..=MAX_ITERATIONS {
            assert_eq!(power_of_two(k).to_bits(), doubled.to_bits(), "2^{k}");
            doubled *= 2.0;
        }
    }

    #[test]
    fn a_plane_line_is_the_ray_lifted_into_the_plane() {
        let julia = tilted_julia();
        let (origin, dir) = (
            DVec3::new(0.3, -1.0, -2.5),
            DVec3::new(0.1, 0.4, 1.0).normalize(),
        );
        let line = PlaneLine::new(&julia, origin, dir);
        for depth in [0.0, 0.7, 2.2, 4.0] {
            let got = line.at(depth);
            let want = julia.plane_point(julia.lift(origin + dir * depth));
            let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
            assert!(
                close(got.real, want.real)
                    && close(got.along, want.along)
                    && close(got.across, want.across),
                "{depth}: {got:?} {want:?}"
            );
        }
    }

    #[test]
    fn the_normal_is_the_gradient_of_the_orbit_norm() {
        // Past the stack's room for the orbit too.
        for iterations in [3, 40] {
            let julia = gallery_julia(iterations);
            let norm = |p: DVec3| {
                let mut q = julia.lift(p);
                for _ in 0..iterations {
                    q = julia.step(q);
                }
                0.5 * q.length_squared()
            };
            let p = DVec3::new(0.1, -0.2, 0.05);
            let h = 1e-7;
            let slope = |axis: DVec3| (norm(p + axis * h) - norm(p - axis * h)) / (2.0 * h);
            let want = DVec3::new(slope(DVec3::X), slope(DVec3::Y), slope(DVec3::Z));
            let got = julia.normal(p);
            assert!(
                (got - want).length() < 1e-5 * want.length(),
                "{iterations}: {got} {want}"
            );
        }
    }

    /// Where halving the march's step from the depth `start` along `line` down to the
    /// tolerance, as POV-Ray does, puts the crossing: the inside end of the last cell.
    fn halving<const KIND: u8>(
        julia: &Julia,
        line: &PlaneLine,
        start: f64,
        step: f64,
        inside: bool,
    ) -> f64 {
        let (mut depth, mut dist) = (0.0, step);
        while dist > TOLERANCE {
            dist *= 0.5;
            if julia
                .orbit_on::<KIND, false>(line, start + (depth + dist))
                .inside
                == inside
            {
                depth += dist;
            }
        }
        if inside { depth } else { depth + dist }
    }

    #[test]
    fn refining_finds_the_cell_halving_finds() {
        // Rays across the gallery's fractal (8 iterations), a rougher one (20) and a cube:
        // every march step that crosses the boundary is refined to halving's cell.
        let cube = Julia::new(
            DVec4::new(-0.083, 0.0, -0.83, -0.025),
            JuliaAlgebra::Quaternion,
            JuliaFunction::Cube,
            6,
            50.0,
            DVec4::new(0.0, 0.0, 0.0, 1.0),
            0.15,
        );
        let refined = [
            refinements_match_halving::<QUATERNION_SQUARE>(&gallery_julia(8)),
            refinements_match_halving::<QUATERNION_SQUARE>(&gallery_julia(20)),
            refinements_match_halving::<QUATERNION_CUBE>(&cube),
        ];
        assert!(refined.iter().all(|&n| n > 100), "{refined:?}");
    }

    /// How many march steps across the boundary, on 400 rays across `julia` (made by the
    /// iteration `KIND`), were refined, each to halving's cell.
    fn refinements_match_halving<const KIND: u8>(julia: &Julia) -> usize {
        let mut refined = 0;
        for k in 0..400 {
            let (x, y) = (-1.0 + 0.005 * f64::from(k), 0.3 - 0.0015 * f64::from(k));
            let dir = DVec3::new(0.05, -0.02, 1.0).normalize();
            let line = PlaneLine::new(julia, DVec3::new(x, y, -2.0), dir);
            let mut start = 0.0;
            let mut here = julia.orbit_on::<KIND, true>(&line, start);
            for _ in 0..400 {
                let step = max(here.dist, julia.min_step);
                let next = julia.orbit_on::<KIND, true>(&line, start + step);
                if next.inside != here.inside {
                    let want = halving::<KIND>(julia, &line, start, step, here.inside);
                    let got = julia.refine::<KIND>(&line, start, step, &here, &next);
                    assert!(
                        (got - want).abs() <= 1e-12,
                        "{} iterations, ray {k}: {got} {want}",
                        julia.iterations
                    );
                    refined += 1;
                }
                (start, here) = (start + step, next);
            }
        }
        refined
    }

    #[test]
    fn the_crossing_estimate_is_exact_for_lines_and_inverse_quadratics() {
        // A straight value, with or without a third point: the chord's crossing.
        let line = |x: f64| 0.3 - 0.1 * x;
        for third in [None, Some((11.0, line(11.0)))] {
            let got = crossing_estimate(8.0, line(0.0), line(8.0), third);
            assert!((got - 3.0).abs() < 1e-12, "{third:?}: {got}");
        }
        // A value whose inverse is quadratic, x = 2 + f + f², crossing at 2: found
        // exactly from three points, where the chord misses.
        let points = [-0.5_f64, 1.0, 2.0].map(|f| (2.0 + f + f * f, f));
        let [(a, fa), (b, fb), (c, fc)] = points;
        let got = a + crossing_estimate(b - a, fa, fb, Some((c - a, fc)));
        assert!((got - 2.0).abs() < 1e-12, "{got}");
        assert!((a + crossing_estimate(b - a, fa, fb, None) - 2.0).abs() > 0.1);
        // A third point that would put the crossing outside the bracket, or that has no
        // value, leaves the chord.
        let chord = crossing_estimate(4.0, 1.0, -1.0, None);
        assert_eq!(
            crossing_estimate(4.0, 1.0, -1.0, Some((5.0, f64::NAN))),
            chord
        );
        assert_eq!(crossing_estimate(4.0, 1.0, -1.0, Some((5.0, -1.0))), chord);
        let outside = crossing_estimate(4.0, 1.0, -1.0, Some((-1.0, 0.01)));
        assert_eq!(outside, chord);
    }

    #[test]
    fn extremes_of_iteration_give_finite_answers() {
        for iterations in [1, 200] {
            let julia = gallery_julia(iterations);
            for k in 0..50 {
                let y = -1.5 + 0.06 * f64::from(k);
                let ray = Ray::new(DVec3::new(0.1, y, -3.0), DVec3::new(0.01, 0.0, 1.0));
                if let Some(hit) = first_root(&julia, &ray, 0.0, f64::INFINITY) {
                    assert!(hit.t.is_finite());
                    assert!(julia.normal(ray.at(hit.t)).is_finite());
                }
            }
        }
    }

    #[test]
    fn hypercomplex_functions_stay_finite() {
        use JuliaFunction::*;
        for f in [
            Sqr,
            Cube,
            Reciprocal,
            Exp,
            Ln,
            Sin,
            Asin,
            Cos,
            Acos,
            Tan,
            Atan,
            Sinh,
            Asinh,
            Cosh,
            Acosh,
            Tanh,
            Atanh,
            Pwr(2.0, 0.5),
        ] {
            let julia = Julia::new(
                DVec4::new(0.4, 0.2, 0.1, 0.0),
                JuliaAlgebra::Hypercomplex,
                f,
                20,
                20.0,
                DVec4::new(0.0, 0.0, 0.0, 1.0),
                0.0,
            );
            let ray = Ray::new(DVec3::new(0.05, 0.02, -5.0), DVec3::Z);
            let mut t = [0.0; 4];
            let n = julia.crossings(&ray, 0.0, f64::INFINITY, false, &mut t);
            for &t in &t[..n] {
                assert!(t.is_finite(), "{f:?}");
                assert!(!julia.normal(ray.at(t)).is_nan(), "{f:?}");
            }
        }
    }
}
