//! `poly`, `cubic`, `quartic` and `polynomial`: the surface Σ c·xⁱyʲzᵏ = 0, inside where
//! the sum is negative. Along a ray the sum is a polynomial in t, built around a point of
//! the ray near the shape so that its coefficients stay well scaled; its roots come from
//! the closed forms up to degree 4, or from Sturm sequences with `sturm` and above.

use super::Roots;
use crate::bounds::Aabb;
use crate::polynomial::{self, MAX_DEGREE};
use crate::ray::Ray;
use crate::sturm;
use glam::DVec3;

/// How far along an unbounded ray roots are looked for, as POV-Ray does.
const MAX_DISTANCE: f64 = 1.0e7;

#[derive(Debug, Clone, PartialEq)]
pub struct Poly {
    pub order: usize,
    /// Powers of x, y, z and the coefficient of each term.
    pub terms: Vec<([u8; 3], f64)>,
    pub sturm: bool,
    /// Where the surface is looked for: the `bounded_by` box, in the shape's frame.
    pub region: Option<Aabb>,
}

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
/// the origin), and the t around which its polynomial along the ray is built.
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
        let mut coeffs = self.along(ray.origin + ray.direction * centre, ray.direction);
        // In units of the half-span, so that the solvers, which judge coefficients against
        // the largest, weigh them alike at any scale of the scene.
        let half = (lo - centre).abs().max((hi - centre).abs());
        if !(half > 0.0 && half.is_finite()) {
            return 0;
        }
        let mut power = 1.0;
        for c in &mut coeffs[..=self.order] {
            *c *= power;
            power *= half;
        }
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
        let mut found = [0.0; MAX_DEGREE];
        let n = self.roots(ray, &mut found);
        found[..n]
            .iter()
            .copied()
            .filter(|&t| t > tmin && t < tmax)
            .min_by(f64::total_cmp)
    }

    pub fn value(&self, p: DVec3) -> f64 {
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
        Poly {
            order: 4,
            terms,
            sturm,
            region: Some(Aabb::new(DVec3::splat(-10.0), DVec3::splat(10.0))),
        }
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
