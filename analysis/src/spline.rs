//! Splines: points with parameter values, evaluated by linear, quadratic, cubic or natural
//! interpolation and clamped at the ends. Scenes call them at parse time and from
//! `function { spline }`.

use crate::eval::value::Terms;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SplineKind {
    Linear,
    Quadratic,
    Cubic,
    Natural,
}

/// A spline: its kind and its points sorted by parameter.
#[derive(Debug, Clone, PartialEq)]
pub struct Spline {
    pub kind: SplineKind,
    pub points: Vec<(f64, Terms)>,
}

impl Spline {
    /// The point at parameter `t`, interpolated as `kind`.
    pub fn at(&self, t: f64, kind: SplineKind) -> Terms {
        let len = self.points.iter().map(|(_, p)| p.len).max().unwrap_or(3);
        let points: Vec<(f64, Terms)> = self
            .points
            .iter()
            .map(|(k, p)| (*k, p.promoted(len)))
            .collect();
        let n = points.len();
        if n == 0 {
            return Terms::splat(0.0, len);
        }
        if n == 1 {
            return points[0].1;
        }
        let (first, last) = match kind {
            SplineKind::Cubic if n >= 4 => (1, n - 2),
            _ => (0, n - 1),
        };
        if t <= points[first].0 {
            return points[first].1;
        }
        if t >= points[last].0 {
            return points[last].1;
        }
        let i = (first..last)
            .find(|&i| t < points[i + 1].0)
            .unwrap_or(last - 1);
        let (k0, p0) = points[i];
        let (k1, p1) = points[i + 1];
        let u = (t - k0) / (k1 - k0);
        let mut out = Terms::splat(0.0, len);
        match kind {
            SplineKind::Linear => {
                for c in 0..len as usize {
                    out.c[c] = p0.c[c] + (p1.c[c] - p0.c[c]) * u;
                }
            }
            SplineKind::Quadratic | SplineKind::Cubic => {
                // Catmull-Rom with one-sided tangents at the ends of the valid range.
                let prev = if i > 0 {
                    points[i - 1]
                } else {
                    (k0 - (k1 - k0), p0)
                };
                let next = if i + 2 < n {
                    points[i + 2]
                } else {
                    (k1 + (k1 - k0), p1)
                };
                for c in 0..len as usize {
                    let m0 = (p1.c[c] - prev.1.c[c]) / (k1 - prev.0) * (k1 - k0);
                    let m1 = (next.1.c[c] - p0.c[c]) / (next.0 - k0) * (k1 - k0);
                    out.c[c] = hermite(p0.c[c], p1.c[c], m0, m1, u);
                }
            }
            SplineKind::Natural => {
                for c in 0..len as usize {
                    let keys: Vec<f64> = points.iter().map(|(k, _)| *k).collect();
                    let values: Vec<f64> = points.iter().map(|(_, p)| p.c[c]).collect();
                    out.c[c] = natural_cubic(&keys, &values, i, t);
                }
            }
        }
        out
    }
}

fn hermite(p0: f64, p1: f64, m0: f64, m1: f64, u: f64) -> f64 {
    let u2 = u * u;
    let u3 = u2 * u;
    (2.0 * u3 - 3.0 * u2 + 1.0) * p0
        + (u3 - 2.0 * u2 + u) * m0
        + (-2.0 * u3 + 3.0 * u2) * p1
        + (u3 - u2) * m1
}

/// The natural cubic spline through (keys, values) at `t`, which lies in segment `i`.
fn natural_cubic(keys: &[f64], values: &[f64], i: usize, t: f64) -> f64 {
    let n = keys.len();
    let mut second = vec![0.0; n];
    let mut u = vec![0.0; n];
    for j in 1..n - 1 {
        let sig = (keys[j] - keys[j - 1]) / (keys[j + 1] - keys[j - 1]);
        let p = sig * second[j - 1] + 2.0;
        second[j] = (sig - 1.0) / p;
        let slope = (values[j + 1] - values[j]) / (keys[j + 1] - keys[j])
            - (values[j] - values[j - 1]) / (keys[j] - keys[j - 1]);
        u[j] = (6.0 * slope / (keys[j + 1] - keys[j - 1]) - sig * u[j - 1]) / p;
    }
    second[n - 1] = 0.0;
    for j in (0..n - 1).rev() {
        second[j] = second[j] * second[j + 1] + u[j];
    }
    let h = keys[i + 1] - keys[i];
    let a = (keys[i + 1] - t) / h;
    let b = (t - keys[i]) / h;
    a * values[i]
        + b * values[i + 1]
        + ((a * a * a - a) * second[i] + (b * b * b - b) * second[i + 1]) * h * h / 6.0
}
