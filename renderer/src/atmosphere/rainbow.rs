//! `rainbow { }` at run time: a fog-like ring of colour at a fixed angle around a
//! direction.
//!
//! Measured on POV-Ray 3.7: the colour map's index grows linearly with the angle between
//! the ray and `direction`, from 0 at `angle - width/2` to 1 at `angle + width/2`. An arc
//! narrower than 360 degrees is centred on `up`; between half the `falloff_angle` and
//! half the `arc_angle` from it the bow fades out as `(1 + cos(π t)) / 2`, `t` going from
//! 0 to 1 across the fading part. The colour mixes in as a fog's does.

use super::fog::Veil;
use analysis::pattern::blend_position;
use analysis::scene::{self, Colour};
use glam::DVec3;
use std::f64::consts::PI;

#[derive(Debug, Clone)]
pub struct Rainbow {
    direction: DVec3,
    /// Unit vector across `direction` where the arc is centred.
    up: DVec3,
    inner: f64,
    width: f64,
    distance: f64,
    jitter: f64,
    colours: Vec<(f64, Colour)>,
    half_arc: f64,
    half_falloff: f64,
    /// The lowest and highest cosine of a ray's angle from `direction` at which the bow,
    /// jittered, may show: most rays fall outside and need no arc cosine.
    visible_cosines: (f64, f64),
}

impl Rainbow {
    pub fn from_scene(rainbow: &scene::Rainbow) -> Rainbow {
        let direction = rainbow.direction.normalize_or(DVec3::Z);
        let up = (rainbow.up - direction * rainbow.up.dot(direction)).normalize_or_zero();
        let inner = (rainbow.angle - rainbow.width / 2.0).to_radians();
        let width = rainbow.width.to_radians();
        let mut colours = rainbow.colour_map.entries.clone();
        colours.sort_by(|a, b| a.0.total_cmp(&b.0));
        Rainbow {
            direction,
            up,
            inner,
            width,
            distance: rainbow.distance,
            jitter: rainbow.jitter,
            colours,
            half_arc: (rainbow.arc_angle / 2.0).to_radians(),
            half_falloff: (rainbow.falloff_angle / 2.0).to_radians(),
            visible_cosines: visible_cosines(inner, width, rainbow.jitter),
        }
    }

    /// The bow seen along the unit `direction` over `depth`; `None` off the bow.
    pub fn veil(&self, direction: DVec3, depth: f64) -> Option<Veil> {
        let cosine = direction.dot(self.direction);
        if cosine < self.visible_cosines.0 || cosine > self.visible_cosines.1 {
            return None;
        }
        let angle = cosine.clamp(-1.0, 1.0).acos();
        let mut index = (angle - self.inner) / self.width;
        if self.jitter > 0.0 {
            index += self.jitter * (scatter(direction) - 0.5);
        }
        if !(0.0..=1.0).contains(&index) {
            return None;
        }
        let mut weight = 1.0;
        if self.half_arc < PI && self.up != DVec3::ZERO {
            let across = direction - self.direction * direction.dot(self.direction);
            let around = across
                .normalize_or_zero()
                .dot(self.up)
                .clamp(-1.0, 1.0)
                .acos();
            if around > self.half_arc {
                return None;
            }
            if around > self.half_falloff && self.half_arc > self.half_falloff {
                let t = (around - self.half_falloff) / (self.half_arc - self.half_falloff);
                weight = 0.5 * (1.0 + (PI * t).cos());
            }
        }
        let (a, b, t) = blend_position(self.colours.iter().map(|(at, _)| *at), index);
        let colour = self.colours[a].1.lerp(self.colours[b].1, t);
        let k = if self.distance == 0.0 {
            1.0
        } else {
            (-depth / self.distance).exp()
        };
        let k = k.max(colour.transmit);
        let through =
            DVec3::splat(k) * (DVec3::splat(1.0 - colour.filter) + colour.filter * colour.rgb);
        Some(Veil {
            through: DVec3::ONE + weight * (through - DVec3::ONE),
            added: weight * (1.0 - k) * colour.rgb,
        })
    }
}

/// The lowest and highest cosine of the angles at which a bow from `inner` over `width`
/// (radians) may show, its index jittered by up to half of `jitter` either way; the
/// whole range -1..=1 when the width is not positive. A margin far above the arc cosine's
/// rounding keeps every ray that could show the bow.
fn visible_cosines(inner: f64, width: f64, jitter: f64) -> (f64, f64) {
    const MARGIN: f64 = 1e-9;
    if width.is_nan() || width <= 0.0 {
        return (f64::NEG_INFINITY, f64::INFINITY);
    }
    let reach = 0.5 * jitter.max(0.0) * width;
    let nearest = (inner - reach).clamp(0.0, PI);
    let farthest = (inner + width + reach).clamp(0.0, PI);
    (farthest.cos() - MARGIN, nearest.cos() + MARGIN)
}

/// A number in 0..1 fixed for each direction, for the jitter.
fn scatter(direction: DVec3) -> f64 {
    let mut h = 0x9e37_79b9_7f4a_7c15u64;
    for x in [direction.x, direction.y, direction.z] {
        h ^= x.to_bits();
        h = h.wrapping_mul(0xbf58_476d_1ce4_e5b9);
        h ^= h >> 31;
    }
    (h >> 11) as f64 / (1u64 << 53) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use analysis::scene::BlendMap;

    #[test]
    fn index_and_arc_follow_povray() {
        let rainbow = Rainbow::from_scene(&scene::Rainbow {
            direction: DVec3::Z,
            angle: 20.0,
            width: 10.0,
            distance: 1e-9,
            colour_map: BlendMap {
                entries: vec![
                    (0.0, Colour::rgb(0.0, 0.0, 1.0)),
                    (1.0, Colour::rgb(1.0, 0.0, 1.0)),
                ],
            },
            arc_angle: 120.0,
            falloff_angle: 30.0,
            ..scene::Rainbow::default()
        });
        let towards = |angle: f64, around: f64| {
            let (a, r) = (angle.to_radians(), around.to_radians());
            DVec3::new(a.sin() * r.sin(), a.sin() * r.cos(), a.cos())
        };
        // Straight up the bow: the index is linear in the angle.
        let v = rainbow.veil(towards(17.5, 0.0), 1.0).unwrap();
        assert!((v.added.x - 0.25).abs() < 1e-9 && (v.added.z - 1.0).abs() < 1e-9);
        assert!(rainbow.veil(towards(14.0, 0.0), 1.0).is_none());
        // POV-Ray shows 0.744 of the bow 30 degrees round, where the fading has 1/3 to go.
        let v = rainbow.veil(towards(20.0, 30.0), 1.0).unwrap();
        assert!((v.added.z - 0.75).abs() < 1e-9, "{v:?}");
        assert!(rainbow.veil(towards(20.0, 61.0), 1.0).is_none());
    }

    /// Rays just inside either edge of the bow, jittered or not, pass the cosine test; rays
    /// beyond the jitter's reach do not.
    #[test]
    fn visible_cosines_hold_the_whole_jittered_bow() {
        let (inner, width) = (15f64.to_radians(), 10f64.to_radians());
        let inside = |angle: f64, (lo, hi): (f64, f64)| (lo..=hi).contains(&angle.cos());
        let plain = visible_cosines(inner, width, 0.0);
        assert!(inside(inner + 1e-12, plain) && inside(inner + width - 1e-12, plain));
        assert!(!inside(inner - 1e-3, plain) && !inside(inner + width + 1e-3, plain));
        // A jitter of 0.5 moves the index by up to a quarter of the width either way.
        let jittered = visible_cosines(inner, width, 0.5);
        assert!(inside(inner - 0.24 * width, jittered));
        assert!(inside(inner + 1.24 * width, jittered));
        assert!(!inside(inner - 0.26 * width, jittered));
        assert_eq!(
            visible_cosines(inner, 0.0, 0.0),
            (f64::NEG_INFINITY, f64::INFINITY)
        );
    }
}
