//! Normal perturbation (`normal { }`): bumps that exist only in the lighting. Patterns built
//! for normals (bumps, dents, wrinkles, ripples, waves) push the normal by vectors of their
//! own. Every other pattern is sampled, as POV-Ray describes, at the four corners of a
//! regular tetrahedron of radius `accuracy` around the point, and each corner's direction,
//! weighted by the value there, is added to the normal, scaled by `-5 bump_size` and by
//! `0.02 / accuracy` (POV-Ray's calibration): a gentle tilt along the pattern's slope and a
//! sharp one across its jumps. The push is added in pattern space to the unit normal
//! there, and the sum carried back to the world like a normal, as POV-Ray's bump scaling
//! does: scaling a pattern changes where its bumps are, not how steep they look.

use analysis::noise;
use analysis::pattern::{self, PatternValue};
use analysis::scene::{self, NormalKind, Pattern, PatternKind};
use glam::DVec3;
use std::f64::consts::TAU;

/// Whether the normal can be evaluated; `Err` names what is missing.
pub fn check(normal: &scene::Normal) -> Result<(), String> {
    match &normal.kind {
        NormalKind::Pattern { pattern, .. } => match pattern.kind {
            PatternKind::Ripples | PatternKind::Waves => Ok(()),
            _ => pattern::check(pattern),
        },
        NormalKind::Map { .. } => Err("not supported yet: normal_map".into()),
    }
}

/// The perturbed unit normal at world point `p` for surface normal `n`.
pub fn perturb(normal: &scene::Normal, p: DVec3, n: DVec3) -> DVec3 {
    let NormalKind::Pattern { pattern, bump_size } = &normal.kind else {
        return n;
    };
    if *bump_size == 0.0 {
        return n;
    }
    let to_pattern = &pattern.transform.inverse;
    let local = to_pattern.transform_point3(p);
    // Normals go into pattern space by the transposed forward matrix and back by the
    // transposed inverse.
    let local_normal = (pattern.transform.matrix.matrix3.transpose() * n).normalize_or_zero();
    let push = match pattern.kind {
        PatternKind::Bumps => noise::vector(local) * *bump_size,
        PatternKind::Dents => {
            let depth = noise::noise(local).powi(3);
            noise::vector(local) * (-bump_size * depth)
        }
        PatternKind::Wrinkles => {
            let mut v = DVec3::ZERO;
            let mut scale = 1.0;
            for _ in 0..10 {
                v += (noise::vector(local * scale) / scale).abs();
                scale *= 2.0;
            }
            v * *bump_size
        }
        PatternKind::Ripples | PatternKind::Waves => waves(pattern, local) * *bump_size,
        _ => {
            let accuracy = if normal.accuracy > 0.0 {
                normal.accuracy
            } else {
                0.02
            };
            let amount = -5.0 * bump_size * (0.02 / accuracy);
            pyramid(pattern, local, accuracy) * amount
        }
    };
    let perturbed = (to_pattern.matrix3.transpose() * (local_normal + push)).normalize_or_zero();
    if perturbed == DVec3::ZERO || !perturbed.is_finite() {
        n
    } else {
        perturbed
    }
}

/// The corners of a regular tetrahedron around the origin, one straight up.
const PYRAMID: [DVec3; 4] = [
    DVec3::new(0.942_809_041, -0.333_333_333, 0.0),
    DVec3::new(-0.471_404_521, -0.333_333_333, 0.816_496_581),
    DVec3::new(-0.471_404_521, -0.333_333_333, -0.816_496_581),
    DVec3::new(0.0, 1.0, 0.0),
];

/// The sum of the tetrahedron's corner directions weighted by the pattern's value at each
/// corner, in pattern space.
fn pyramid(pattern: &Pattern, local: DVec3, h: f64) -> DVec3 {
    PYRAMID.iter().fold(DVec3::ZERO, |sum, corner| {
        let value = match pattern::evaluate_local(pattern, local + *corner * h) {
            PatternValue::Blend(v) => v,
            PatternValue::Block(i) => i as f64,
        };
        sum + *corner * value
    })
}

/// The ten wave sources of ripples and waves: fixed points scattered in the unit cube.
fn sources() -> &'static [DVec3; 10] {
    static SOURCES: std::sync::OnceLock<[DVec3; 10]> = std::sync::OnceLock::new();
    SOURCES.get_or_init(|| {
        let mut state: u32 = 0x1234_5678;
        let mut next = move || {
            state = state.wrapping_mul(1_103_515_245).wrapping_add(12_345);
            f64::from((state >> 8) & 0xffff) / 65536.0 - 0.5
        };
        std::array::from_fn(|_| DVec3::new(next(), next(), next()))
    })
}

/// The push of concentric waves around the sources, each a sine of the distance at the
/// pattern's frequency and phase; waves give each source a frequency of its own and weaken
/// the faster ones.
fn waves(pattern: &Pattern, p: DVec3) -> DVec3 {
    let mut push = DVec3::ZERO;
    let n = sources().len() as f64;
    for (i, source) in sources().iter().enumerate() {
        let d = p - *source;
        let len = match d.length() {
            0.0 => 1.0,
            l => l,
        };
        let own = match pattern.kind {
            PatternKind::Waves => 0.5 + (i as f64 * 0.618_034).fract(),
            _ => 1.0,
        };
        let index = len * pattern.frequency * own + pattern.phase;
        push += d * ((index * TAU).sin() / own / (len * n));
    }
    push
}
