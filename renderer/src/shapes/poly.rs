//! `poly`, `cubic`, `quartic` and `polynomial`: the surface Σ c·xⁱyʲzᵏ = 0, inside where
//! the sum is negative. Along a ray the sum is a polynomial in t, built around a point of
//! the ray near the shape so that its coefficients stay well scaled; its roots come from
//! the closed forms up to degree 4, or from Sturm sequences with `sturm` and above.

use super::Roots;
use crate::bounds::Aabb;
use crate::fast_math;
use crate::polynomial::{self, MAX_DEGREE};
use crate::ray::Ray;
use crate::sturm;
use glam::DVec3;

/// How far along an unbounded ray roots are looked for, as POV-Ray does.
const MAX_DISTANCE: f64 = 1.0e7;

/// The highest order whose polynomial along a ray is built from values (see `Dense`).
const DENSE_ORDER: usize = 4;

/// How many coefficients a polynomial of order `DENSE_ORDER` has at most.
const DENSE_LEN: usize = (DENSE_ORDER + 1) * (DENSE_ORDER + 2) * (DENSE_ORDER + 3) / 6;

#[derive(Debug, Clone, PartialEq)]
pub struct Poly {
    pub order: usize,
    /// Powers of x, y, z and the coefficient of each term.
    pub terms: Vec<([u8; 3], f64)>,
    pub sturm: bool,
    /// Where the surface is looked for: the `bounded_by` box, in the shape's frame.
    pub region: Option<Aabb>,
    /// Orders 2 to 4 (quadrics, `cubic`, `quartic`) also keep every coefficient.
    dense: Option<Dense>,
}

/// Every coefficient of a polynomial of order `ORDER` <= 4, in the order nested Horner
/// evaluation reads them: powers of x descending, within them powers of y descending,
/// within those powers of z descending. Straight-line evaluation without power tables
/// costs about one multiply-add per coefficient, and the polynomial along a ray follows
/// from a few such values, which in the WebAssembly interpreter costs a small part of
/// expanding every term binomially.
#[derive(Debug, Clone, PartialEq)]
struct Dense([f64; DENSE_LEN]);

impl Dense {
    fn new(order: usize, terms: &[([u8; 3], f64)]) -> Dense {
        let mut c = [0.0; DENSE_LEN];
        let mut at = 0;
        for i in (0..=order).rev() {
            for j in (0..=order - i).rev() {
                for k in (0..=order - i - j).rev() {
                    let powers = [i, j, k].map(|p| p as u8);
                    c[at] = terms
                        .iter()
                        .filter(|(p, _)| *p == powers)
                        .map(|(_, value)| value)
                        .sum();
                    at += 1;
                }
            }
        }
        Dense(c)
    }

    /// The polynomial's value at `p`.
    #[inline(always)]
    fn value<const ORDER: usize>(&self, p: DVec3) -> f64 {
        if ORDER == 3 {
            return self.cubic_value(p);
        }
        self.nested_value::<ORDER>(p)
    }

    /// [`Dense::value`] by the loops over the powers, for every order.
    #[inline(always)]
    fn nested_value<const ORDER: usize>(&self, p: DVec3) -> f64 {
        let c = &self.0;
        let mut at = 0;
        let mut sx = 0.0;
        for i in (0..=ORDER).rev() {
            let mut sy = 0.0;
            for j in (0..=ORDER - i).rev() {
                let mut sz = 0.0;
                for _ in 0..=ORDER - i - j {
                    sz = sz * p.z + c[at];
                    at += 1;
                }
                sy = sy * p.y + sz;
            }
            sx = sx * p.x + sy;
        }
        sx
    }

    /// The gradient at `p`: the same nested Horner evaluation, each level carrying its
    /// derivatives along.
    #[inline(always)]
    fn gradient<const ORDER: usize>(&self, p: DVec3) -> DVec3 {
        if ORDER == 3 {
            return self.cubic_gradient(p);
        }
        self.nested_gradient::<ORDER>(p)
    }

    /// A cubic's gradient at `p`: [`Dense::nested_gradient`] for order 3 written out, the
    /// same bits (sums that start from 0 times a variable start from what is added to it).
    #[inline(always)]
    fn cubic_gradient(&self, p: DVec3) -> DVec3 {
        let c = &self.0;
        let (x, y, z) = (p.x, p.y, p.z);
        // A group of coefficients of descending powers of z, by Horner's rule: its value
        // and its derivative in z.
        let chain3 = |a: f64, b: f64, e: f64| {
            let s = a * z + b;
            (s * z + e, a * z + s)
        };
        // Each power of x: its sum over y and z, and that sum's derivatives in y and z.
        let sy2 = c[1] * y + (c[2] * z + c[3]);
        let (s9, d9) = chain3(c[7], c[8], c[9]);
        let a1 = c[4] * y + (c[5] * z + c[6]);
        let (sy1, gy1, gz1) = (a1 * y + s9, c[4] * y + a1, c[5] * y + d9);
        let (s15, d15) = chain3(c[13], c[14], c[15]);
        // Of the terms without x only the derivatives are needed: the group of z alone
        // (c[16] to c[19]) enters by its derivative in z.
        let (s18, d18) = chain3(c[16], c[17], c[18]);
        let d19 = d18 * z + s18;
        let a0 = c[10] * y + (c[11] * z + c[12]);
        let b0 = a0 * y + s15;
        let (gy0, gz0) = ((c[10] * y + a0) * y + b0, (c[11] * y + d15) * y + d19);
        let sx2 = c[0] * x + sy2;
        let sx1 = sx2 * x + sy1;
        DVec3::new(
            (c[0] * x + sx2) * x + sx1,
            (c[1] * x + gy1) * x + gy0,
            (c[2] * x + gz1) * x + gz0,
        )
    }

    /// [`Dense::gradient`] by the loops over the powers, for every order.
    #[inline(always)]
    fn nested_gradient<const ORDER: usize>(&self, p: DVec3) -> DVec3 {
        let c = &self.0;
        let mut at = 0;
        let (mut sx, mut gx) = (0.0, DVec3::ZERO);
        for i in (0..=ORDER).rev() {
            let (mut sy, mut gy) = (0.0, DVec3::ZERO);
            for j in (0..=ORDER - i).rev() {
                let (mut sz, mut dz) = (0.0, 0.0);
                for _ in 0..=ORDER - i - j {
                    dz = dz * p.z + sz;
                    sz = sz * p.z + c[at];
                    at += 1;
                }
                gy = DVec3::new(0.0, gy.y * p.y + sy, gy.z * p.y + dz);
                sy = sy * p.y + sz;
            }
            gx = DVec3::new(gx.x * p.x + sx, gx.y * p.x + gy.y, gx.z * p.x + gy.z);
            sx = sx * p.x + sy;
        }
        gx
    }

    /// A cubic's value at `p`: [`Dense::nested_value`] for order 3 written out, the same
    /// operations in the same order (a group's sum starts from its first coefficient
    /// instead of from 0 times the variable plus it, which is the same number), so the
    /// same bits. The loops' zero starts, index arithmetic and bounds checks cost the
    /// interpreted plugin about as much again as the 19 multiply-adds themselves.
    #[inline(always)]
    fn cubic_value(&self, p: DVec3) -> f64 {
        let c = &self.0;
        let (x, y, z) = (p.x, p.y, p.z);
        let x2 = c[1] * y + (c[2] * z + c[3]);
        let x1 = (c[4] * y + (c[5] * z + c[6])) * y + ((c[7] * z + c[8]) * z + c[9]);
        let x0 = ((c[10] * y + (c[11] * z + c[12])) * y + ((c[13] * z + c[14]) * z + c[15])) * y
            + (((c[16] * z + c[17]) * z + c[18]) * z + c[19]);
        ((c[0] * x + x2) * x + x1) * x + x0
    }

    /// A cubic's terms of order 3 at `d`: [`Dense::nested_top`] for order 3 written out,
    /// the same bits.
    #[inline(always)]
    fn cubic_top(&self, d: DVec3) -> f64 {
        let c = &self.0;
        let (z2, y) = (d.z * d.z, d.y);
        let z3 = z2 * d.z;
        let x2 = c[1] * y + c[2] * d.z;
        let x1 = (c[4] * y + c[5] * d.z) * y + c[7] * z2;
        let x0 = ((c[10] * y + c[11] * d.z) * y + c[13] * z2) * y + c[16] * z3;
        ((c[0] * d.x + x2) * d.x + x1) * d.x + x0
    }

    /// The terms of the highest order alone, at `d`: the leading coefficient along a ray
    /// of direction `d`.
    #[inline(always)]
    fn top<const ORDER: usize>(&self, d: DVec3) -> f64 {
        if ORDER == 3 {
            return self.cubic_top(d);
        }
        self.nested_top::<ORDER>(d)
    }

    /// [`Dense::top`] by the loops over the powers, for every order.
    #[inline(always)]
    fn nested_top<const ORDER: usize>(&self, d: DVec3) -> f64 {
        let c = &self.0;
        let mut zpow = [1.0; DENSE_ORDER + 1];
        for m in 1..=ORDER {
            zpow[m] = zpow[m - 1] * d.z;
        }
        let mut at = 0;
        let mut sx = 0.0;
        for i in (0..=ORDER).rev() {
            let mut sy = 0.0;
            for j in (0..=ORDER - i).rev() {
                // The group of x^i y^j starts with its highest power of z.
                sy = sy * d.y + c[at] * zpow[ORDER - i - j];
                at += ORDER - i - j + 1;
            }
            sx = sx * d.x + sy;
        }
        sx
    }

    /// The polynomial in s of the sum at `o + s·d`, from its values at s = 0, ±1 (and
    /// ±1/2 for a quartic) and its leading coefficient. `d` spans the searched interval,
    /// so the values are those over it and the coefficients come out as well scaled as
    /// the values the root finder judges them by.
    #[inline(always)]
    fn along<const ORDER: usize>(&self, o: DVec3, d: DVec3) -> [f64; ORDER_MAX] {
        let mut out = [0.0; ORDER_MAX];
        let c0 = self.value::<ORDER>(o);
        let top = self.top::<ORDER>(d);
        let (plus, minus) = (self.value::<ORDER>(o + d), self.value::<ORDER>(o - d));
        let (even, odd) = (0.5 * (plus + minus) - c0, 0.5 * (plus - minus));
        out[0] = c0;
        out[ORDER] = top;
        match ORDER {
            2 => out[1] = odd,
            3 => {
                out[1] = odd - top;
                out[2] = even;
            }
            _ => {
                // Odd part c1 s + c3 s³ at s = 1 and 1/2.
                let half = 0.5 * d;
                let (plus, minus) = (self.value::<ORDER>(o + half), self.value::<ORDER>(o - half));
                let odd_half = 0.5 * (plus - minus);
                let c3 = (odd - 2.0 * odd_half) * (4.0 / 3.0);
                out[1] = odd - c3;
                out[2] = even - top;
                out[3] = c3;
            }
        }
        out
    }
}

/// Room for the coefficients of a dense polynomial along a ray.
const ORDER_MAX: usize = DENSE_ORDER + 1;

/// A polynomial in t, lowest degree first.
type Coeffs = [f64; MAX_DEGREE + 1];

/// Rows 0..=MAX_DEGREE of Pascal's triangle, packed.
const TRIANGLE: usize = (MAX_DEGREE + 1) * (MAX_DEGREE + 2) / 2;

fn binomials() -> &'static [f64; TRIANGLE] {
    static TABLE: std::sync::OnceLock<[f64; TRIANGLE]> = std::sync::OnceLock::new();
    TABLE.get_or_init(|| {
        let mut t = [0.0; TRIANGLE];
        for k in 0..=MAX_DEGREE {
            let row = k * (k + 1) / 2;
            t[row] = 1.0;
            t[row + k] = 1.0;
            for m in 1..k {
                let above = (k - 1) * k / 2;
                t[row + m] = t[above + m - 1] + t[above + m];
            }
        }
        t
    })
}

/// x⁰..xⁿ.
fn powers(x: f64, n: usize) -> [f64; MAX_DEGREE + 1] {
    let mut p = [1.0; MAX_DEGREE + 1];
    for k in 1..=n {
        p[k] = p[k - 1] * x;
    }
    p
}

/// The interval of t in which a polynomial shape's roots are looked for (inside the
/// `region` if it has one, else within [`MAX_DISTANCE`] of the ray's nearest approach to
/// the origin), and the t around which its polynomial along the ray is built. Inlined, as
/// the span returned through memory costs about as much as finding it.
#[inline(always)]
pub(super) fn search_span(region: Option<&Aabb>, ray: &Ray) -> Option<(f64, f64, f64)> {
    match region {
        Some(region) => {
            let (lo, hi) =
                region.clip(ray, ray.direction.recip(), f64::NEG_INFINITY, f64::INFINITY)?;
            Some((lo, hi, 0.5 * (lo + hi)))
        }
        None => {
            let d2 = ray.direction.length_squared();
            if d2 == 0.0 {
                return None;
            }
            let centre = -ray.origin.dot(ray.direction) / d2;
            let reach = MAX_DISTANCE / d2.sqrt();
            Some((centre - reach, centre + reach, centre))
        }
    }
}

impl Poly {
    pub fn new(
        order: usize,
        terms: Vec<([u8; 3], f64)>,
        sturm: bool,
        region: Option<Aabb>,
    ) -> Poly {
        let dense = (2..=DENSE_ORDER)
            .contains(&order)
            .then(|| Dense::new(order, &terms));
        Poly {
            order,
            terms,
            sturm,
            region,
            dense,
        }
    }

    /// The polynomial in s of the sum at `o + s·d`: each term's factors expand by the
    /// binomial theorem, (o + s d)ᵏ = Σ C(k, m) oᵏ⁻ᵐ dᵐ sᵐ.
    fn along(&self, o: DVec3, d: DVec3) -> Coeffs {
        let n = self.order;
        let binomial = binomials();
        // Per axis, the coefficients of (o + s d)^k for every k, packed row after row.
        let mut expansions = [[0.0; TRIANGLE]; 3];
        for axis in 0..3 {
            let (oa, da) = (o[axis], d[axis]);
            let mut opow = [1.0; MAX_DEGREE + 1];
            let mut dpow = [1.0; MAX_DEGREE + 1];
            for k in 1..=n {
                opow[k] = opow[k - 1] * oa;
                dpow[k] = dpow[k - 1] * da;
            }
            for k in 0..=n {
                let row = k * (k + 1) / 2;
                for m in 0..=k {
                    expansions[axis][row + m] = binomial[row + m] * opow[k - m] * dpow[m];
                }
            }
        }
        let mut out = [0.0; MAX_DEGREE + 1];
        for &([i, j, k], c) in &self.terms {
            let (i, j, k) = (usize::from(i), usize::from(j), usize::from(k));
            let x = &expansions[0][i * (i + 1) / 2..][..=i];
            let y = &expansions[1][j * (j + 1) / 2..][..=j];
            let z = &expansions[2][k * (k + 1) / 2..][..=k];
            for (a, xa) in x.iter().enumerate() {
                let cx = c * xa;
                for (b, yb) in y.iter().enumerate() {
                    let cxy = cx * yb;
                    for (e, ze) in z.iter().enumerate() {
                        out[a + b + e] += cxy * ze;
                    }
                }
            }
        }
        out
    }

    /// The crossings of the ray in `[lo, hi]`, ascending.
    fn roots(&self, ray: &Ray, out: &mut [f64; MAX_DEGREE]) -> usize {
        let Some((lo, hi, centre)) = search_span(self.region.as_ref(), ray) else {
            return 0;
        };
        // In units of the half-span, so that the solvers, which judge coefficients against
        // the largest, weigh them alike at any scale of the scene.
        let half = (lo - centre).abs().max((hi - centre).abs());
        if !(half > 0.0 && half.is_finite()) {
            return 0;
        }
        let o = ray.origin + ray.direction * centre;
        let coeffs = match &self.dense {
            Some(dense) => {
                let d = ray.direction * half;
                let mut c = [0.0; MAX_DEGREE + 1];
                let small = match self.order {
                    2 => dense.along::<2>(o, d),
                    3 => dense.along::<3>(o, d),
                    _ => dense.along::<4>(o, d),
                };
                c[..ORDER_MAX].copy_from_slice(&small);
                c
            }
            None => {
                let mut coeffs = self.along(o, ray.direction);
                let mut power = 1.0;
                for c in &mut coeffs[..=self.order] {
                    *c *= power;
                    power *= half;
                }
                coeffs
            }
        };
        let (a, b) = ((lo - centre) / half, (hi - centre) / half);
        let mut n = 0;
        let mut put = |x: f64| {
            if n < out.len() {
                out[n] = x * half + centre;
                n += 1;
            }
        };
        let degree = self.order;
        if !self.sturm && degree == 3 {
            let c: [f64; 4] = [coeffs[0], coeffs[1], coeffs[2], coeffs[3]];
            let (r, k) = polynomial::cubic_roots_in(&c, a, b);
            r[..k].iter().for_each(|&x| put(x));
        } else if !self.sturm && degree == 4 {
            let c: [f64; 5] = [coeffs[0], coeffs[1], coeffs[2], coeffs[3], coeffs[4]];
            let (r, k) = polynomial::quartic_roots_in(&c, a, b);
            r[..k].iter().for_each(|&x| put(x));
        } else if !self.sturm && degree == 2 {
            if let Some((x0, x1)) =
                super::solve_quadratic_half(coeffs[2], 0.5 * coeffs[1], coeffs[0])
            {
                for x in [x0, x1] {
                    if x >= a && x <= b {
                        put(x);
                    }
                }
            }
        } else {
            let mut r = [0.0; MAX_DEGREE];
            let k = sturm::roots_in(&coeffs[..=degree], a, b, &mut r);
            r[..k].iter().for_each(|&x| put(x));
        }
        n
    }

    pub fn intersect(&self, ray: &Ray, roots: &mut Roots) {
        let mut found = [0.0; MAX_DEGREE];
        let n = self.roots(ray, &mut found);
        for &t in &found[..n] {
            roots.push(t, 0);
        }
    }

    /// The nearest crossing in `(tmin, tmax)`.
    pub fn first_hit(&self, ray: &Ray, tmin: f64, tmax: f64) -> Option<f64> {
        if let (3, false, Some(dense)) = (self.order, self.sturm, &self.dense) {
            return self.first_cubic_hit(dense, ray, tmin, tmax);
        }
        let mut found = [0.0; MAX_DEGREE];
        let n = self.roots(ray, &mut found);
        found[..n]
            .iter()
            .copied()
            .filter(|&t| t > tmin && t < tmax)
            .min_by(f64::total_cmp)
    }

    /// [`Poly::first_hit`] of a `cubic` without `sturm`, the roots found as
    /// [`Poly::roots`] finds them (the same numbers) but without a sort or a list of
    /// every root: the least one kept is all a camera ray asks of the shape.
    fn first_cubic_hit(&self, dense: &Dense, ray: &Ray, tmin: f64, tmax: f64) -> Option<f64> {
        let (lo, hi, centre) = search_span(self.region.as_ref(), ray)?;
        let half = fast_math::max((lo - centre).abs(), (hi - centre).abs());
        if !(half > 0.0 && half.is_finite()) {
            return None;
        }
        let o = ray.origin + ray.direction * centre;
        let c = dense.along::<3>(o, ray.direction * half);
        let (a, b) = ((lo - centre) / half, (hi - centre) / half);
        // Where the query's interval lies in the polynomial's variable: only roots there
        // need polishing.
        let near = (
            fast_math::max(a, (tmin - centre) / half),
            fast_math::min(b, (tmax - centre) / half),
        );
        let x = polynomial::least_cubic_root(&[c[0], c[1], c[2], c[3]], near, |x| {
            let t = x * half + centre;
            x >= a && x <= b && t > tmin && t < tmax
        })?;
        Some(x * half + centre)
    }

    pub fn value(&self, p: DVec3) -> f64 {
        match (&self.dense, self.order) {
            (Some(dense), 2) => return dense.value::<2>(p),
            (Some(dense), 3) => return dense.value::<3>(p),
            (Some(dense), 4) => return dense.value::<4>(p),
            _ => {}
        }
        let (px, py, pz) = (
            powers(p.x, self.order),
            powers(p.y, self.order),
            powers(p.z, self.order),
        );
        self.terms
            .iter()
            .map(|&([i, j, k], c)| c * px[usize::from(i)] * py[usize::from(j)] * pz[usize::from(k)])
            .sum()
    }

    pub fn inside(&self, p: DVec3) -> bool {
        self.value(p) < 0.0
    }

    /// The gradient of the sum.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        match (&self.dense, self.order) {
            (Some(dense), 2) => return dense.gradient::<2>(p),
            (Some(dense), 3) => return dense.gradient::<3>(p),
            (Some(dense), 4) => return dense.gradient::<4>(p),
            _ => {}
        }
        let (px, py, pz) = (
            powers(p.x, self.order),
            powers(p.y, self.order),
            powers(p.z, self.order),
        );
        let mut g = DVec3::ZERO;
        for &([i, j, k], c) in &self.terms {
            let (i, j, k) = (usize::from(i), usize::from(j), usize::from(k));
            let (xi, yj, zk) = (px[i], py[j], pz[k]);
            if i > 0 {
                g.x += c * i as f64 * px[i - 1] * yj * zk;
            }
            if j > 0 {
                g.y += c * j as f64 * xi * py[j - 1] * zk;
            }
            if k > 0 {
                g.z += c * k as f64 * xi * yj * pz[k - 1];
            }
        }
        g
    }

    pub fn bounds(&self) -> Aabb {
        self.region.unwrap_or(Aabb::INFINITE)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The torus x⁴ + y⁴ + z⁴ + 2x²y² + 2x²z² + 2y²z² - 104x² + 56y² - 104z² + 784 of the
    /// manual's polynomial example: major radius √40, minor √12.
    fn torus(sturm: bool) -> Poly {
        let terms = vec![
            ([4, 0, 0], 1.0),
            ([2, 2, 0], 2.0),
            ([2, 0, 2], 2.0),
            ([2, 0, 0], -104.0),
            ([0, 4, 0], 1.0),
            ([0, 2, 2], 2.0),
            ([0, 2, 0], 56.0),
            ([0, 0, 4], 1.0),
            ([0, 0, 2], -104.0),
            ([0, 0, 0], 784.0),
        ];
        Poly::new(
            4,
            terms,
            sturm,
            Some(Aabb::new(DVec3::splat(-10.0), DVec3::splat(10.0))),
        )
    }

    #[test]
    fn torus_crossings_agree_with_and_without_sturm() {
        let (big, small) = (40f64.sqrt(), 12f64.sqrt());
        let ray = Ray::new(DVec3::new(-20.0, 0.0, 0.0), DVec3::X);
        for sturm in [false, true] {
            let mut roots = Roots::new();
            torus(sturm).intersect(&ray, &mut roots);
            let t: Vec<f64> = roots.as_slice().iter().map(|r| r.t).collect();
            let want = [
                20.0 - big - small,
                20.0 - big + small,
                20.0 + big - small,
                20.0 + big + small,
            ];
            assert_eq!(t.len(), 4, "{t:?}");
            for (got, want) in t.iter().zip(want) {
                assert!((got - want).abs() < 1e-8, "sturm {sturm}: {t:?}");
            }
        }
    }

    #[test]
    fn the_polynomial_along_a_ray_from_values_matches_the_binomial_expansion() {
        // Every term of orders 2 to 4, with unequal coefficients.
        for order in 2..=DENSE_ORDER {
            let mut terms = Vec::new();
            for i in 0..=order {
                for j in 0..=order - i {
                    for k in 0..=order - i - j {
                        let c = 1.0 + (i * 7 + j * 3 + k) as f64 * 0.37 - (i * j) as f64;
                        terms.push(([i as u8, j as u8, k as u8], c));
                    }
                }
            }
            let poly = Poly::new(order, terms, false, None);
            let dense = poly.dense.as_ref().expect("dense coefficients");
            let (o, d, half) = (DVec3::new(0.3, -1.2, 0.7), DVec3::new(-0.4, 0.9, 0.25), 1.7);
            let mut want = poly.along(o, d);
            let mut power = 1.0;
            for c in &mut want[..=order] {
                *c *= power;
                power *= half;
            }
            let got = match order {
                2 => dense.along::<2>(o, d * half),
                3 => dense.along::<3>(o, d * half),
                _ => dense.along::<4>(o, d * half),
            };
            let scale = want.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            for m in 0..=order {
                assert!(
                    (got[m] - want[m]).abs() < 1e-12 * scale,
                    "order {order}: {got:?} {want:?}"
                );
            }
            let p = DVec3::new(0.5, 0.25, -0.75);
            let by_terms: f64 = poly
                .terms
                .iter()
                .map(|&([i, j, k], c)| {
                    c * p.x.powi(i.into()) * p.y.powi(j.into()) * p.z.powi(k.into())
                })
                .sum();
            assert!((poly.value(p) - by_terms).abs() < 1e-12 * by_terms.abs().max(1.0));
            let h = 1e-6;
            let slope =
                |axis: DVec3| (poly.value(p + axis * h) - poly.value(p - axis * h)) / (2.0 * h);
            let want = DVec3::new(slope(DVec3::X), slope(DVec3::Y), slope(DVec3::Z));
            assert!(
                (poly.normal(p) - want).length() < 1e-6 * want.length(),
                "{want}"
            );
        }
    }

    /// Every cubic term, with unequal coefficients.
    fn full_cubic() -> Poly {
        let mut terms = Vec::new();
        for i in 0..=3u8 {
            for j in 0..=3 - i {
                for k in 0..=3 - i - j {
                    let c = 1.3 - f64::from(i * 5 + j * 3 + k) * 0.41 + f64::from(i * k);
                    terms.push(([i, j, k], c));
                }
            }
        }
        Poly::new(
            3,
            terms,
            false,
            Some(Aabb::new(DVec3::splat(-2.0), DVec3::splat(2.0))),
        )
    }

    #[test]
    fn the_written_out_cubic_gives_the_loops_bits() {
        let poly = full_cubic();
        let dense = poly.dense.as_ref().expect("dense coefficients");
        for p in [
            DVec3::new(0.3, -1.2, 0.7),
            DVec3::new(-1.7, 0.05, 1.9),
            DVec3::new(1e-3, 2.5e2, -3.0),
            DVec3::ZERO,
        ] {
            assert_eq!(
                dense.cubic_value(p).to_bits(),
                dense.nested_value::<3>(p).to_bits()
            );
            assert_eq!(
                dense.cubic_top(p).to_bits(),
                dense.nested_top::<3>(p).to_bits()
            );
            let (got, want) = (dense.cubic_gradient(p), dense.nested_gradient::<3>(p));
            assert_eq!(
                got.to_array().map(f64::to_bits),
                want.to_array().map(f64::to_bits)
            );
        }
    }

    #[test]
    fn a_cubics_first_hit_is_its_least_root_inside_the_interval() {
        let poly = full_cubic();
        let mut hits = 0;
        for (origin, direction) in [
            (DVec3::new(-3.0, 0.2, 0.1), DVec3::new(1.0, 0.1, -0.05)),
            (DVec3::new(0.5, 3.0, -0.4), DVec3::new(-0.2, -1.0, 0.3)),
            (DVec3::new(0.1, 0.1, 0.1), DVec3::new(0.3, 0.4, 1.0)),
        ] {
            let ray = Ray::new(origin, direction);
            let mut found = [0.0; MAX_DEGREE];
            let n = poly.roots(&ray, &mut found);
            for (tmin, tmax) in [(0.0, f64::INFINITY), (1e-6, 2.0), (1.0, 4.0)] {
                let want = found[..n]
                    .iter()
                    .copied()
                    .filter(|&t| t > tmin && t < tmax)
                    .min_by(f64::total_cmp);
                assert_eq!(poly.first_hit(&ray, tmin, tmax), want, "{origin} {tmin}");
                hits += usize::from(want.is_some());
            }
        }
        assert!(hits >= 4, "{hits}");
    }

    #[test]
    fn normals_point_out_of_the_negative_side() {
        let p = torus(false);
        let surface = DVec3::new(40f64.sqrt() + 12f64.sqrt(), 0.0, 0.0);
        assert!(p.value(surface).abs() < 1e-9);
        assert!(p.normal(surface).x > 0.0);
        assert!(p.inside(DVec3::new(40f64.sqrt(), 0.0, 0.0)));
    }

    #[test]
    fn grazing_rays_find_the_double_root_or_nothing() {
        // A ray tangent to the top of the tube, y = minor radius.
        let p = torus(true);
        let ray = Ray::new(DVec3::new(-20.0, 12f64.sqrt(), 0.0), DVec3::X);
        let mut roots = Roots::new();
        p.intersect(&ray, &mut roots);
        for r in roots.as_slice() {
            assert!(r.t.is_finite());
            assert!(
                p.value(ray.at(r.t)).abs() < 1e-3,
                "{}",
                p.value(ray.at(r.t))
            );
        }
    }
}
