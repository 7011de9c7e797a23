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
            // Cubic splines use their end points as tangent handles only.
            SplineKind::Cubic if n >= 3 => (1, n - 2),
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
        let h = k1 - k0;
        let u = (t - k0) / h;
        let mut out = Terms::splat(0.0, len);
        for c in 0..len as usize {
            out.c[c] = match kind {
                SplineKind::Linear => p0.c[c] + (p1.c[c] - p0.c[c]) * u,
                SplineKind::Quadratic => {
                    // The parabola through the segment's ends and the point before it (the
                    // one after it for the first segment), as measured against POV-Ray 3.7.
                    let base = if i == 0 { 0 } else { i - 1 };
                    let keys: Vec<f64> = (base..(base + 3).min(n)).map(|j| points[j].0).collect();
                    let values: Vec<f64> = (base..(base + 3).min(n))
                        .map(|j| points[j].1.c[c])
                        .collect();
                    lagrange(&keys, &values, t)
                }
                SplineKind::Cubic => {
                    // Hermite segments whose tangents average the slopes of the neighbouring
                    // segments, scaled to this segment's length (measured against POV-Ray 3.7).
                    let slope = |a: usize, b: usize| {
                        (points[b].1.c[c] - points[a].1.c[c]) / (points[b].0 - points[a].0)
                    };
                    let tangent = |j: usize| {
                        let before = if j > 0 {
                            slope(j - 1, j)
                        } else {
                            slope(j, j + 1)
                        };
                        let after = if j + 1 < n {
                            slope(j, j + 1)
                        } else {
                            slope(j - 1, j)
                        };
                        0.5 * (before + after) * h
                    };
                    hermite(p0.c[c], p1.c[c], tangent(i), tangent(i + 1), u)
                }
                SplineKind::Natural => {
                    let keys: Vec<f64> = points.iter().map(|(k, _)| *k).collect();
                    let values: Vec<f64> = points.iter().map(|(_, p)| p.c[c]).collect();
                    natural_cubic(&keys, &values, i, t)
                }
            };
        }
        out
    }
}

/// The polynomial through `(keys[j], values[j])`, at `t`.
fn lagrange(keys: &[f64], values: &[f64], t: f64) -> f64 {
    let mut sum = 0.0;
    for (j, (&kj, &vj)) in keys.iter().zip(values).enumerate() {
        let mut weight = 1.0;
        for (m, &km) in keys.iter().enumerate() {
            if m != j {
                weight *= (t - km) / (kj - km);
            }
        }
        sum += weight * vj;
    }
    sum
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
