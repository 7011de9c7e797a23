//! Pattern functions: the value a pattern takes at a point, in POV-Ray's conventions. A
//! point goes from the world into pattern space (the pattern's transform), through the
//! warps (innermost first: the last written acts first), and through the classic
//! turbulence, which POV-Ray always applies before any transformation. Blend patterns
//! then give a value that frequency, phase and the wave type shape into 0..1; block
//! patterns (checker, hexagon, brick...) name a map entry directly.

pub mod bitmap;
mod blocks;
pub mod cells;
pub mod density_file;
pub mod facing;
mod fractal;
pub mod pavement;
mod spiral;
pub mod tiling;
pub mod warp;
pub mod waves;

use crate::floor::floor;
use crate::noise;
use crate::scene::{Colour, Pattern, PatternKind, Pigment, Transform, Warp, WaveType};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

pub use facing::Facing;
pub use spiral::quilt_offset;

/// What a pattern gives at a point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PatternValue {
    /// A value in 0..1 that indexes a blend map.
    Blend(f64),
    /// The index of a map entry, for block patterns.
    Block(usize),
}

/// Whether the pattern can be evaluated; `Err` names what is missing.
pub fn check(pattern: &Pattern) -> Result<(), String> {
    match &pattern.kind {
        PatternKind::PigmentPattern(pigment) => return check_pigment(pigment),
        PatternKind::Facets { .. } => {
            return Err("the facets pattern can only be used in a normal".into());
        }
        PatternKind::Pavement(pavement) => return pavement::check(pavement),
        _ => {}
    }
    if let PatternKind::Function(f) = &pattern.kind
        && let Some(missing) = f.unsupported()
    {
        return Err(format!(
            "not supported yet: {}",
            missing.trim_start_matches("not supported yet: ")
        ));
    }
    Ok(())
}

/// Whether every pattern of a pigment can be evaluated; `Err` names the first that cannot.
pub fn check_pigment(pigment: &Pigment) -> Result<(), String> {
    match pigment {
        Pigment::Solid(_) | Pigment::Image(_) => Ok(()),
        Pigment::Pattern { pattern, map } => {
            check(pattern)?;
            map.entries.iter().try_for_each(|(_, p)| check_pigment(p))
        }
    }
}

/// The pattern's value at a world point as one float: a block pattern's entry index, or
/// the blend value (what `function { pattern { } }` returns).
pub fn value(pattern: &Pattern, world: DVec3) -> f64 {
    match evaluate(pattern, world) {
        PatternValue::Blend(v) => v,
        PatternValue::Block(i) => i as f64,
    }
}

/// Where `v` falls in a map whose entry values ascend: the two entries to blend and the
/// weight of the second. Below the first entry and above the last, the end entry alone.
pub fn blend_position(
    values: impl ExactSizeIterator<Item = f64> + Clone,
    v: f64,
) -> (usize, usize, f64) {
    let n = values.len();
    let upper = values.clone().take_while(|&at| at <= v).count();
    if upper == 0 {
        return (0, 0, 0.0);
    }
    if upper == n {
        return (n - 1, n - 1, 0.0);
    }
    let mut pair = values.skip(upper - 1);
    let a = pair.next().unwrap_or(v);
    let b = pair.next().unwrap_or(a);
    let t = if b > a { (v - a) / (b - a) } else { 1.0 };
    (upper - 1, upper, t)
}

/// The average pattern's blend of its map: each entry with its share, the weight written
/// in its place (1 when left out) over the total of the weights; no share when the
/// weights add up to zero.
pub fn average_shares<T>(entries: &[(f64, T)]) -> impl Iterator<Item = (f64, &T)> {
    let total: f64 = entries.iter().map(|(weight, _)| weight).sum();
    entries
        .iter()
        .filter(move |_| total != 0.0)
        .map(move |(weight, item)| (weight / total, item))
}

/// The sum of colours each scaled by its share, all five components alike.
pub fn weighted_colour(parts: impl Iterator<Item = (f64, Colour)>) -> Colour {
    parts.fold(Colour::BLACK, |sum, (share, c)| Colour {
        rgb: sum.rgb + c.rgb * share,
        filter: sum.filter + c.filter * share,
        transmit: sum.transmit + c.transmit * share,
    })
}

/// The colour of a scene pigment at a world point, for pigment functions.
pub fn pigment_colour(pigment: &Pigment, world: DVec3) -> Colour {
    match pigment {
        Pigment::Solid(c) => *c,
        Pigment::Image(map) => {
            bitmap::image_map_colour(map, map.transform.inverse.transform_point3(world))
        }
        Pigment::Pattern { pattern, map } => {
            let entries = &map.entries;
            if entries.is_empty() {
                return Colour::BLACK;
            }
            // Where the entries are evaluated costs the pattern's warps and turbulence
            // over again: it is found only for an entry that is not a plain colour (a
            // colour map's never are), and once.
            let entries_at = std::cell::OnceCell::new();
            let entry_colour = |entry: &Pigment| match entry {
                Pigment::Solid(c) => *c,
                entry => pigment_colour(
                    entry,
                    *entries_at.get_or_init(|| entry_point(pattern, world).unwrap_or(world)),
                ),
            };
            if matches!(pattern.kind, PatternKind::Average) {
                return weighted_colour(
                    average_shares(entries).map(|(share, entry)| (share, entry_colour(entry))),
                );
            }
            match evaluate(pattern, world) {
                PatternValue::Block(i) => entry_colour(&entries[i.min(entries.len() - 1)].1),
                PatternValue::Blend(v) => {
                    let (a, b, t) = blend_position(entries.iter().map(|(at, _)| *at), v);
                    let lower = entry_colour(&entries[a].1);
                    if a == b {
                        lower
                    } else {
                        lower.lerp(entry_colour(&entries[b].1), t)
                    }
                }
            }
        }
    }
}

/// The colours a pattern shows without a colour map, as POV-Ray defines them: grey from
/// black to white for most, and colours of their own for the block patterns and a few
/// classics.
pub fn default_colours(kind: &PatternKind) -> Vec<(f64, Colour)> {
    let c = Colour::rgb;
    match kind {
        PatternKind::Checker | PatternKind::Object(_) => {
            vec![(0.0, c(0.0, 0.0, 1.0)), (1.0, c(0.0, 1.0, 0.0))]
        }
        PatternKind::Brick { .. } => vec![(0.0, c(0.5, 0.5, 0.5)), (1.0, c(0.6, 0.15, 0.15))],
        PatternKind::Hexagon => vec![
            (0.0, c(0.0, 0.0, 1.0)),
            (1.0, c(0.0, 1.0, 0.0)),
            (2.0, c(1.0, 0.0, 0.0)),
        ],
        PatternKind::Square | PatternKind::Triangular => {
            let n = if matches!(kind, PatternKind::Square) {
                4
            } else {
                6
            };
            [
                c(1.0, 0.0, 0.0),
                c(0.0, 1.0, 0.0),
                c(0.0, 0.0, 1.0),
                c(1.0, 1.0, 0.0),
                c(0.0, 1.0, 1.0),
                c(1.0, 0.0, 1.0),
            ]
            .into_iter()
            .take(n)
            .enumerate()
            .map(|(i, colour)| (i as f64, colour))
            .collect()
        }
        PatternKind::Agate { .. } => vec![
            (0.0, c(1.0, 1.0, 1.0)),
            (0.5, c(0.95, 0.75, 0.5)),
            (0.5, c(0.9, 0.7, 0.5)),
            (0.6, c(0.9, 0.7, 0.4)),
            (0.6, c(1.0, 0.7, 0.4)),
            (1.0, c(0.6, 0.3, 0.0)),
        ],
        PatternKind::Bozo => vec![
            (0.4, c(1.0, 1.0, 1.0)),
            (0.4, c(0.0, 1.0, 0.0)),
            (0.6, c(0.0, 1.0, 0.0)),
            (0.6, c(0.0, 0.0, 1.0)),
            (0.8, c(0.0, 0.0, 1.0)),
            (0.8, c(1.0, 0.0, 0.0)),
        ],
        PatternKind::Marble => vec![
            (0.0, c(0.9, 0.8, 0.8)),
            (0.9, c(0.9, 0.08, 0.08)),
            (0.9, c(0.0, 0.0, 0.0)),
        ],
        PatternKind::Radial => vec![
            (0.0, c(0.0, 1.0, 1.0)),
            (0.333, c(1.0, 1.0, 0.0)),
            (0.666, c(1.0, 0.0, 1.0)),
            (1.0, c(0.0, 1.0, 1.0)),
        ],
        PatternKind::Wood => vec![(0.6, c(0.666, 0.312, 0.2)), (0.6, c(0.4, 0.1333, 0.066))],
        PatternKind::Fractal(f)
            if f.kind == crate::scene::FractalKind::Mandel && f.exponent == 2 =>
        {
            vec![
                (0.001, c(0.0, 0.0, 0.0)),
                (0.001, c(0.0, 1.0, 1.0)),
                (0.012, c(1.0, 1.0, 0.0)),
                (0.015, c(1.0, 0.0, 1.0)),
                (0.1, c(0.0, 1.0, 1.0)),
            ]
        }
        _ => vec![(0.0, c(0.0, 0.0, 0.0)), (1.0, c(1.0, 1.0, 1.0))],
    }
}

/// Whether the pattern depends on how the surface faces (`slope`, `aoi`), so that its
/// value needs a [`Facing`].
pub fn uses_facing(pattern: &Pattern) -> bool {
    matches!(pattern.kind, PatternKind::Slope(_) | PatternKind::Aoi)
}

/// The pattern's value at a world point off any surface.
pub fn evaluate(pattern: &Pattern, world: DVec3) -> PatternValue {
    evaluate_on(pattern, world, None)
}

/// The pattern's value at a world point, on the surface `facing` describes if there is
/// one (which only `slope` and `aoi` look at). Inlined: a pattern's carriage into its
/// space and a call of [`evaluate_warped`] are all it does, and a patterned pigment asks
/// at every hit.
#[inline(always)]
pub fn evaluate_on(pattern: &Pattern, world: DVec3, facing: Option<&Facing>) -> PatternValue {
    let local = pattern.transform.inverse.transform_point3(world);
    evaluate_warped(pattern, warped(pattern, local), facing)
}

/// Every transformation of a pattern, those before its warps and those after, composed:
/// what a map's entries carry of their pattern's movements (see `entry_point`).
pub fn all_transforms(pattern: &Pattern) -> Transform {
    pattern
        .warps
        .iter()
        .filter_map(|warp| match warp {
            Warp::Transform(t) => Some(t),
            _ => None,
        })
        .fold(Transform::IDENTITY, |sum, t| sum.then(t))
        .then(&pattern.transform)
}

/// The world point at which the entries of `pattern`'s map are evaluated, when it is not
/// `world` itself. POV-Ray hands the entries the point its pattern was evaluated at: after
/// the pattern's transformations, warps and classic turbulence, except that marble and wood
/// add their turbulence to their value and hand on the point before it (measured on
/// pigment, texture and normal maps). The entries carry the pattern's transformations
/// themselves (`all_transforms`), so the point is carried back out through them; without
/// warps or a turbulence that moves it, that is `world` again, and `None` says so.
///
/// That answer, the usual one, is inlined into the callers (every map at every hit).
#[inline]
pub fn entry_point(pattern: &Pattern, world: DVec3) -> Option<DVec3> {
    if pattern.warps.is_empty() && pattern.turbulence.is_none() {
        None
    } else {
        moved_entry_point(pattern, world)
    }
}

/// [`entry_point`] for a pattern with warps or a turbulence.
fn moved_entry_point(pattern: &Pattern, world: DVec3) -> Option<DVec3> {
    let turbulence = pattern
        .turbulence
        .as_ref()
        .filter(|_| !matches!(pattern.kind, PatternKind::Marble | PatternKind::Wood));
    if pattern.warps.is_empty() && turbulence.is_none() {
        return None;
    }
    let inner = warped(pattern, pattern.transform.inverse.transform_point3(world));
    let inner = match turbulence {
        Some(t) => warp::turbulent(t, inner),
        None => inner,
    };
    Some(all_transforms(pattern).point(inner))
}

/// A point of pattern space carried through the pattern's warps, the last written first.
/// Inlined, with the common pattern without warps answered at once: a bumped normal asks
/// at every hit, and the call cost the interpreted plugin more than the empty loop.
#[inline(always)]
pub fn warped(pattern: &Pattern, local: DVec3) -> DVec3 {
    if pattern.warps.is_empty() {
        return local;
    }
    warp::through_all(&pattern.warps, local)
}

/// [`evaluate_warped`] at each of `points`, the pattern's kind looked at once: the bump
/// pyramid asks for four values at a time, and a tiling without turbulence then finds its
/// table once and skips the pattern dispatch of each value (the same values, through the
/// same `shape`).
pub fn evaluate_warped_each<const N: usize>(
    pattern: &Pattern,
    points: [DVec3; N],
    facing: Option<&Facing>,
) -> [PatternValue; N] {
    match pattern.kind {
        PatternKind::Tiling(number) if pattern.turbulence.is_none() => {
            let raw = tiling::values(number, points);
            // Loops rather than `map`, whose closure calls are not all inlined.
            let mut values = [PatternValue::Blend(0.0); N];
            for (value, raw) in values.iter_mut().zip(raw) {
                *value = PatternValue::Blend(shape(pattern, raw));
            }
            values
        }
        _ => {
            let mut values = [PatternValue::Blend(0.0); N];
            for (value, p) in values.iter_mut().zip(points) {
                *value = evaluate_warped(pattern, p, facing);
            }
            values
        }
    }
}

/// The pattern's value at a point that has been through its warps already. Inlined into
/// its two callers, which hand it a point they have just stored: the call passed the point
/// through memory, and natively loading it back stalled on the store.
#[inline(always)]
pub fn evaluate_warped(pattern: &Pattern, p: DVec3, facing: Option<&Facing>) -> PatternValue {
    // The gradient, the commonest pattern, and the checker, the commonest floor, without
    // the frame of the function that knows every pattern: the saved registers and stack of
    // its heavier arms cost a gradient's value twice what the value itself does.
    match (&pattern.kind, &pattern.turbulence) {
        (PatternKind::Gradient(unit), None) => {
            // Along a zero vector 0 everywhere, as `blend_value` gives.
            let raw = if *unit != DVec3::ZERO {
                p.dot(*unit)
            } else {
                0.0
            };
            PatternValue::Blend(shape(pattern, raw))
        }
        (PatternKind::Checker, None) => checker(p),
        _ => evaluate_any(pattern, p, facing),
    }
}

/// [`evaluate_warped`] for every pattern.
#[inline(never)]
fn evaluate_any(pattern: &Pattern, p: DVec3, facing: Option<&Facing>) -> PatternValue {
    let classic = pattern.turbulence.as_ref();
    let generator = pattern.noise_generator;
    let turbulent = |p: DVec3| match classic {
        Some(t) => warp::turbulent(t, p),
        None => p,
    };
    // The scalar turbulence marble and the spirals add to their value.
    let scalar_turbulence = |p: DVec3| match classic {
        Some(t) => {
            noise::scalar_turbulence(p, t.octaves, t.omega, t.lambda, generator) * t.amount.x
        }
        None => 0.0,
    };
    let raw = match &pattern.kind {
        PatternKind::Checker => return checker(turbulent(p)),
        PatternKind::Brick { size, mortar } => {
            return PatternValue::Block(blocks::brick(turbulent(p), *size, *mortar));
        }
        PatternKind::Hexagon => return PatternValue::Block(blocks::hexagon(turbulent(p))),
        PatternKind::Square => return PatternValue::Block(blocks::square(turbulent(p))),
        PatternKind::Triangular => {
            return PatternValue::Block(blocks::triangular(turbulent(p)));
        }
        PatternKind::Object(object) => {
            return PatternValue::Block(usize::from(object.contains(turbulent(p))));
        }
        PatternKind::MaterialMap { image, textures } => {
            // An interpolated index is cut down to a whole one before it chooses. Measured
            // on POV-Ray 3.7: red values count round the list, as its manual says, but
            // palette indices past the list take its last texture.
            let index = (bitmap::image_value(image, p) * 255.0 + 1e-6).floor() as usize;
            let chosen = if image.bitmap.image.indices.is_some() {
                index.min(textures - 1)
            } else {
                index % textures
            };
            return PatternValue::Block(chosen);
        }
        PatternKind::PigmentPattern(pigment) => pigment_colour(pigment, turbulent(p)).grey_value(),
        PatternKind::Marble => p.x + scalar_turbulence(p),
        PatternKind::Spiral1 { arms } => spiral::spiral1(p, *arms, scalar_turbulence(p)),
        PatternKind::Spiral2 { arms } => spiral::spiral2(p, *arms, scalar_turbulence(p)),
        PatternKind::Wood => {
            let q = match classic {
                Some(t) => p + noise::turbulence(p, t.octaves, t.omega, t.lambda) * t.amount * 0.5,
                None => p,
            };
            (q.x * q.x + q.y * q.y).sqrt()
        }
        PatternKind::Agate { turb } => {
            // POV-Ray 3.7's bands, measured: a sine across z at 1.1 per unit, moved by 1.3
            // times `agate_turb` times the pattern's own scalar turbulence (its octaves,
            // omega and lambda; 6, 0.5 and 2 by default), raised to the power 0.77. A
            // `turbulence` warps the point first, as for any pattern.
            let (octaves, omega, lambda) =
                classic.map_or((6, 0.5, 2.0), |t| (t.octaves, t.omega, t.lambda));
            let q = turbulent(p);
            let t = noise::scalar_turbulence(q, octaves, omega, lambda, generator) * turb;
            let v = 0.5 + 0.5 * (TAU * (1.1 * q.z + 1.3 * t)).sin();
            v.clamp(0.0, 1.0).powf(0.77)
        }
        PatternKind::Ripples => waves::ripples(turbulent(p), pattern.frequency, pattern.phase),
        PatternKind::Waves => waves::waves(turbulent(p), pattern.frequency, pattern.phase),
        PatternKind::Slope(slope) => facing::slope(slope, facing, turbulent(p)),
        PatternKind::Aoi => facing::aoi(facing),
        kind => blend_value(kind, turbulent(p), generator),
    };
    PatternValue::Blend(shape(pattern, raw))
}

/// `checker`'s block at `p`: which of the unit cubes, alternating, holds it.
#[inline(always)]
fn checker(p: DVec3) -> PatternValue {
    let q = p + DVec3::splat(1e-9);
    let sum = floor(q.x) + floor(q.y) + floor(q.z);
    PatternValue::Block(usize::from(is_odd(sum)))
}

/// Raw values of the blend patterns that take no special turbulence, the noise patterns'
/// by noise generator `generator`.
fn blend_value(kind: &PatternKind, p: DVec3, generator: u8) -> f64 {
    match kind {
        // A gradient along a zero vector is 0 everywhere, as the last arm gives.
        PatternKind::Gradient(unit) if *unit != DVec3::ZERO => p.dot(*unit),
        PatternKind::Spherical => 1.0 - p.length().min(1.0),
        PatternKind::Cylindrical => 1.0 - (p.x * p.x + p.z * p.z).sqrt().min(1.0),
        PatternKind::Planar => 1.0 - p.y.abs().min(1.0),
        PatternKind::Boxed => 1.0 - p.abs().max_element().min(1.0),
        PatternKind::Onion => p.length(),
        PatternKind::Radial => {
            // 0 at +x, 0.25 at -z, 0.5 at -x, 0.75 at +z, around +y.
            let angle = (-p.z).atan2(p.x);
            angle.rem_euclid(TAU) / TAU
        }
        PatternKind::Leopard => {
            let s = (p.x.sin() + p.y.sin() + p.z.sin()) / 3.0;
            s * s
        }
        PatternKind::Bozo | PatternKind::Bumps => noise::noise_with_generator(p, generator),
        PatternKind::Dents => noise::noise_with_generator(p, generator).powi(3),
        PatternKind::Granite => {
            // Measured: six octaves from four times the point's frequency, each half as
            // strong as the last.
            let mut sum = 0.0;
            let mut scale = 4.0;
            for octave in 0..6 {
                let n = noise::octave_noise(p * scale, generator).clamp(0.0, 1.0);
                sum += (0.5 - n).abs() / f64::from(1 << octave);
                scale *= 2.0;
            }
            sum
        }
        PatternKind::Wrinkles => {
            // Measured: ten octaves from the point's own frequency, the first weighing 1/2.
            let mut sum = 0.0;
            let mut scale = 1.0;
            for octave in 0..10 {
                let n = noise::octave_noise(p * scale, generator).clamp(0.0, 1.0);
                sum += n / f64::from(2 << octave);
                scale *= 2.0;
            }
            sum
        }
        PatternKind::Cells => cells::cells(p),
        PatternKind::Crackle {
            form,
            metric,
            offset,
            solid,
        } => cells::crackle(p, *form, *metric, *offset, *solid),
        PatternKind::Quilted { control0, control1 } => spiral::quilted(p, *control0, *control1),
        PatternKind::Fractal(f) => fractal::value(f, p),
        PatternKind::Function(f) => f.eval(&[p.x, p.y, p.z]),
        PatternKind::Image(image) => bitmap::image_value(image, p),
        PatternKind::DensityFile { grid, trilinear } => grid.value(p, *trilinear),
        PatternKind::Tiling(number) => tiling::value(*number, p),
        PatternKind::Pavement(pavement) => pavement::value(pavement, p),
        _ => 0.0,
    }
}

/// Whether the whole number `x` is odd, as `x.rem_euclid(2.0) == 1.0` says (a library
/// call) but through an integer: from 2^53 on every float is even, and NaN and the
/// infinities are not odd.
fn is_odd(x: f64) -> bool {
    const EXACT_BELOW: f64 = 9_007_199_254_740_992.0;
    x.abs() < EXACT_BELOW && x as i64 & 1 == 1
}

/// `v % modulus` for a finite `v` and a modulus just above 1, bit for bit, without the
/// library's remainder (a call of some eighty instructions) for the values of a few
/// periods that patterns give: the largest multiple of the modulus by a power of two that
/// fits is taken off, then the next smaller one, as long division does. Each subtraction
/// takes at most twice the subtrahend from a value between it and its double, which
/// floats do exactly (Sterbenz), so the remainder is the exact one the library returns.
fn wrap(v: f64, modulus: f64) -> f64 {
    let mut r = v.abs();
    if r >= 1024.0 * modulus {
        return v % modulus;
    }
    let mut d = modulus;
    while d * 2.0 <= r {
        d *= 2.0;
    }
    while d >= modulus {
        if r >= d {
            r -= d;
        }
        d *= 0.5;
    }
    r.copysign(v)
}

/// The modulus POV-Ray 3.7 wraps negative pattern values with, measured: -12.75 gives
/// 0.25012, -2 gives 0.00001 (292 values from -5000 to 60 fit to its single precision).
const NEGATIVE_MODULUS: f64 = 1.000_01;

/// Frequency and phase, then the wave type; the result lies in 0..1.
#[inline(always)]
fn shape(pattern: &Pattern, raw: f64) -> f64 {
    // The evaluator gives marble and wood their triangle wave unless the scene says
    // otherwise.
    let wave = pattern.wave;
    let mut v = raw * pattern.frequency + pattern.phase;
    if !v.is_finite() {
        v = 0.0;
    }
    // POV-Ray's wrap into 0..1: values up to 1 stay (1, the centre of a spherical
    // pattern, keeps the last map entry), larger ones lose their whole part, and negative
    // ones take their remainder by a modulus a hair above 1, raised by 1 (and once more
    // should that leave them negative).
    if v > 1.0 {
        v -= floor(v);
    } else if v < 0.0 {
        v = wrap(v, NEGATIVE_MODULUS) + 1.0;
        if v < 0.0 {
            v += 1.0;
        }
    }
    let v = v.clamp(0.0, 1.0);
    match wave {
        WaveType::Ramp => v,
        WaveType::Triangle => {
            if v < 0.5 {
                2.0 * v
            } else {
                2.0 * (1.0 - v)
            }
        }
        WaveType::Sine => 0.5 + 0.5 * (v * TAU).sin(),
        WaveType::Scallop => (v * PI).sin().abs(),
        WaveType::Cubic => v * v * (3.0 - 2.0 * v),
        WaveType::Poly(e) => v.powf(e),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::{Transform, Turbulence};

    #[test]
    fn is_odd_is_rem_euclid_of_two() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -1.0,
            2.0,
            -3.0,
            1e15 + 1.0,
            -1e15 - 1.0,
            9_007_199_254_740_991.0,
            -9_007_199_254_740_991.0,
            9_007_199_254_740_992.0,
            1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ] {
            assert_eq!(is_odd(x), x.rem_euclid(2.0) == 1.0, "{x}");
        }
    }

    #[test]
    fn values_wrap_as_povray_wraps_them() {
        // POV-Ray 3.7's values of `function { y }` as a pigment, printed to 12 digits
        // (its colours are single precision).
        let pattern = Pattern::new(PatternKind::Gradient(DVec3::Y));
        for (raw, povray) in [
            (-12.75, 0.250120013952),
            (-12.0, 0.000110000001),
            (-2.5, 0.500020027161),
            (-2.0, 0.000010000000),
            (-1.0, 0.0),
            (-1.0000001, 0.999999880791),
            (-100000.5, 0.499989986420),
            (0.0, 0.0),
            (1.0, 1.0),
            (2.0, 0.0),
            (12.75, 0.75),
            (1000.25, 0.25),
        ] {
            let ours = shape(&pattern, raw);
            assert!(
                (ours - povray).abs() < 1e-7,
                "{raw}: ours {ours}, POV-Ray {povray}"
            );
        }
    }

    #[test]
    fn agate_is_povrays() {
        // POV-Ray 3.7's values of `function { pigment { agate ... } }`, printed to 9 digits,
        // with the defaults, with a `turbulence` warp and with fewer octaves.
        let agate = Pattern::new(PatternKind::Agate { turb: 1.0 });
        let mut warped = agate.clone();
        warped.turbulence = Some(Turbulence {
            amount: DVec3::splat(0.3),
            octaves: 6,
            omega: 0.5,
            lambda: 2.0,
        });
        let mut three_octaves = agate.clone();
        three_octaves.turbulence = Some(Turbulence {
            amount: DVec3::ZERO,
            octaves: 3,
            omega: 0.5,
            lambda: 2.0,
        });
        for (pattern, p, povray) in [
            (&agate, DVec3::new(1.0, 1.0, 0.0), 0.433276564),
            (&agate, DVec3::new(2.5, 1.3, 0.0), 0.975494802),
            (&agate, DVec3::new(0.3, 0.2, 0.1), 0.370484173),
            (&agate, DVec3::new(-1.1, 0.3, -0.7), 0.171098500),
            (&agate, DVec3::ZERO, 0.999946654),
            (&agate, DVec3::new(0.0, 0.0, 0.5), 0.427136391),
            (&warped, DVec3::new(0.5, -2.0, -1.0), 0.550599754),
            (&warped, DVec3::new(0.5, 0.0710675, 0.8541017), 0.091824256),
            (&three_octaves, DVec3::new(0.5, -2.0, -1.0), 0.702850044),
            (
                &three_octaves,
                DVec3::new(0.5, 0.0710675, 0.8541017),
                0.949239016,
            ),
        ] {
            let PatternValue::Blend(ours) = evaluate(pattern, p) else {
                panic!("agate is a blend pattern");
            };
            assert!(
                (ours - povray).abs() < 2e-6,
                "{p}: ours {ours}, POV-Ray {povray}"
            );
        }
    }

    #[test]
    fn wrap_is_the_remainder() {
        const MODULUS: f64 = NEGATIVE_MODULUS;
        let mut values = vec![
            MODULUS,
            -MODULUS,
            2.0 * MODULUS,
            -4.0 * MODULUS,
            1023.0 * MODULUS,
            1024.0 * MODULUS,
            1e300,
            -1e-300,
            0.0,
            -0.0,
        ];
        // Values over a few periods, either side of the multiples of the modulus.
        let mut x: f64 = -40.0;
        while x < 40.0 {
            values.extend([x, f64::from_bits(x.to_bits() + 1), x * MODULUS]);
            x += 0.013_7;
        }
        for v in values {
            assert_eq!(wrap(v, MODULUS).to_bits(), (v % MODULUS).to_bits(), "{v}");
        }
    }

    fn value(kind: PatternKind, p: DVec3) -> PatternValue {
        evaluate(&Pattern::new(kind), p)
    }

    #[test]
    fn blend_patterns_follow_the_manual() {
        assert_eq!(
            value(PatternKind::Gradient(DVec3::Y), DVec3::new(0.0, 0.25, 0.0)),
            PatternValue::Blend(0.25)
        );
        // Gradients repeat: 1.25 and -0.75 both give 0.25.
        let PatternValue::Blend(v) =
            value(PatternKind::Gradient(DVec3::Y), DVec3::new(0.0, -0.75, 0.0))
        else {
            panic!()
        };
        assert!((v - 0.25).abs() < 1e-4);
        assert_eq!(
            value(PatternKind::Spherical, DVec3::ZERO),
            PatternValue::Blend(1.0)
        );
        assert_eq!(
            value(PatternKind::Spherical, DVec3::X * 2.0),
            PatternValue::Blend(0.0)
        );
        let PatternValue::Blend(r) = value(PatternKind::Radial, -DVec3::Z) else {
            panic!()
        };
        assert!((r - 0.25).abs() < 1e-9, "{r}");
    }

    #[test]
    fn checker_alternates_and_is_stable_on_integer_planes() {
        assert_eq!(
            value(PatternKind::Checker, DVec3::new(0.5, 0.0, 0.5)),
            PatternValue::Block(0)
        );
        assert_eq!(
            value(PatternKind::Checker, DVec3::new(1.5, -1e-16, 0.5)),
            PatternValue::Block(1)
        );
        assert_eq!(
            value(PatternKind::Checker, DVec3::new(1.5, 1e-16, 0.5)),
            PatternValue::Block(1)
        );
    }

    #[test]
    fn pattern_transforms_move_the_pattern() {
        let mut pattern = Pattern::new(PatternKind::Gradient(DVec3::X));
        pattern.transform = Transform::scale(DVec3::splat(2.0)).unwrap();
        assert_eq!(evaluate(&pattern, DVec3::X), PatternValue::Blend(0.5));
    }
}
