//! The escape-time fractal patterns `mandel`, `julia` and `magnet` in the x-y plane, with
//! the interior and exterior colourings of POV-Ray's reference (section 3.4.7.1.11).

use crate::scene::{Fractal, FractalKind};
use glam::DVec3;

/// A complex number as (real, imaginary).
type Complex = (f64, f64);

fn mul(a: Complex, b: Complex) -> Complex {
    (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0)
}

fn div(a: Complex, b: Complex) -> Complex {
    let d = b.0 * b.0 + b.1 * b.1;
    ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
}

fn power(z: Complex, exponent: u32) -> Complex {
    match exponent {
        2 => mul(z, z),
        _ => (1..exponent).fold(z, |acc, _| mul(acc, z)),
    }
}

/// One step of the magnet maps: `((z² + c - 1) / (2z + c - 2))²` for type 1, and for type
/// 2 `((z³ + 3(c-1)z + (c-1)(c-2)) / (3z² + 3(c-2)z + (c-1)(c-2) + 1))²`.
fn magnet_step(variant: u8, z: Complex, c: Complex) -> Complex {
    let c1 = (c.0 - 1.0, c.1);
    let c2 = (c.0 - 2.0, c.1);
    let q = if variant == 1 {
        let top = (z.0 * z.0 - z.1 * z.1 + c1.0, 2.0 * z.0 * z.1 + c1.1);
        let bottom = (2.0 * z.0 + c2.0, 2.0 * z.1 + c2.1);
        div(top, bottom)
    } else {
        let c12 = mul(c1, c2);
        let z2 = mul(z, z);
        let z3 = mul(z2, z);
        let a = mul((3.0, 0.0), mul(c1, z));
        let top = (z3.0 + a.0 + c12.0, z3.1 + a.1 + c12.1);
        let b = mul((3.0, 0.0), mul(c2, z));
        let bottom = (3.0 * z2.0 + b.0 + c12.0 + 1.0, 3.0 * z2.1 + b.1 + c12.1);
        div(top, bottom)
    };
    mul(q, q)
}

/// The fractal's value at the point's x and y.
pub fn value(fractal: &Fractal, p: DVec3) -> f64 {
    let point = (p.x, p.y);
    let max = fractal.max_iteration;
    let magnet = matches!(fractal.kind, FractalKind::Magnet { .. });
    let (mut z, c) = match fractal.kind {
        FractalKind::Mandel => (point, point),
        FractalKind::Julia { c } => (point, c),
        FractalKind::Magnet { julia: None, .. } => ((0.0, 0.0), point),
        FractalKind::Magnet { julia: Some(c), .. } => (point, c),
    };
    let mut smallest = if matches!(fractal.kind, FractalKind::Magnet { julia: None, .. }) {
        10_000.0
    } else {
        z.0 * z.0 + z.1 * z.1
    };
    for iteration in 0..max {
        z = match fractal.kind {
            FractalKind::Magnet { variant, .. } => magnet_step(variant, z, c),
            _ => {
                let zp = power(z, fractal.exponent.max(2));
                (zp.0 + c.0, zp.1 + c.1)
            }
        };
        let size = z.0 * z.0 + z.1 * z.1;
        smallest = smallest.min(size);
        let escaped = if magnet {
            // Magnets stop when they run away or settle on their fixed point 1.
            size > 10_000.0 || (z.0 - 1.0).powi(2) + z.1 * z.1 < 1e-4
        } else {
            size > 4.0
        };
        if escaped {
            return exterior(fractal, iteration, z);
        }
        if !size.is_finite() {
            break;
        }
    }
    interior(fractal, z, smallest)
}

fn exterior(fractal: &Fractal, iteration: u32, z: Complex) -> f64 {
    let (kind, factor) = fractal.exterior;
    let (a, b) = z;
    match kind {
        0 => factor,
        1 => f64::from(iteration) / f64::from(fractal.max_iteration),
        2 => a * factor,
        3 => b * factor,
        4 => a * a * factor,
        5 => b * b * factor,
        6 => (a * a + b * b).sqrt() * factor,
        7 if factor >= 1.0 => f64::from(iteration % factor as u32) / factor,
        8 if factor >= 0.0 => f64::from(iteration % (1.0 + factor) as u32) / factor,
        _ => 0.0,
    }
}

fn interior(fractal: &Fractal, z: Complex, smallest: f64) -> f64 {
    let (kind, factor) = fractal.interior;
    let (a, b) = z;
    match kind {
        0 => factor,
        1 => smallest.sqrt() * factor,
        2 => a * factor,
        3 => b * factor,
        4 => a * a * factor,
        5 => b * b * factor,
        // POV-Ray scales only the imaginary part's square here; its pictures show it.
        6 => a * a + b * b * factor,
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mandel(iterations: u32) -> Fractal {
        Fractal {
            kind: FractalKind::Mandel,
            max_iteration: iterations,
            exponent: 2,
            interior: (0, 1.0),
            exterior: (1, 1.0),
        }
    }

    #[test]
    fn mandel_counts_iterations_outside_and_is_flat_inside() {
        let m = mandel(10);
        assert_eq!(value(&m, DVec3::ZERO), 1.0);
        // c = 0.5: 0.75, 1.06, 1.63, 3.15 escapes at the fourth step (index 3).
        assert_eq!(value(&m, DVec3::X * 0.5), 0.3);
        let cubic = Fractal { exponent: 3, ..m };
        // With z³ + c: 0.625, 0.744, 0.912, 1.258, 2.49 escapes at index 4.
        assert_eq!(value(&cubic, DVec3::X * 0.5), 0.4);
    }

    #[test]
    fn magnets_and_julias_stay_finite() {
        for kind in [
            FractalKind::Magnet {
                variant: 1,
                julia: None,
            },
            FractalKind::Magnet {
                variant: 2,
                julia: Some((0.3, 0.2)),
            },
            FractalKind::Julia { c: (0.353, 0.288) },
        ] {
            let f = Fractal { kind, ..mandel(30) };
            for i in 0..200 {
                let p = DVec3::new(i as f64 * 0.03 - 3.0, (i % 17) as f64 * 0.2 - 1.6, 0.0);
                assert!(value(&f, p).is_finite());
            }
        }
    }
}
