//! The Penrose tilings of `tiling 26` (kites and darts) and `tiling 27` (rhombs): the
//! tilings of the whole x-z plane with five-fold symmetry about the origin that POV-Ray 3.7
//! draws, with long edges of length 1 and an edge of a tile along +x from the origin.
//!
//! Both are built from Robinson triangles, the halves of the tiles: an acute one (36° at its
//! apex, legs 1, base 1/φ) and an obtuse one (108° at its apex, base φ times its legs). Two
//! cuts shrink them: cut α splits an acute triangle into an acute and an obtuse one, both
//! with legs 1/φ of its legs; cut β splits an obtuse triangle into an acute one with its
//! legs and an obtuse one with legs 1/φ of them. A deflation of kites and darts is α then
//! β (acute halves of kites with legs 1, obtuse halves of darts with legs 1/φ); one more α
//! turns that into rhombs with edges 1/φ (both halves' legs are the rhomb's edges).
//!
//! A point finds its tile by descent: it starts in one of the ten acute triangles of a
//! wheel round the origin (the sun of five kites) that is `φ^n` across, with `n` the least
//! even count of deflations whose wheel holds it, and follows the cuts `n` times down to
//! tiles of size 1. Two deflations of a wheel give back a wheel of the same size as the one
//! two levels down, mirrored, so the wheel of each even `n` (mirrored every other time) draws
//! the same tiling wherever they overlap: a point far away takes as many steps as the
//! logarithm of its distance, and no memory. Doubles blur the tiles at distances near
//! `2^52`; points that are not finite, or farther than 1e300, have no tile and take 0.
//!
//! The value follows the periodic tilings' convention: a tile of type `k` of 2 takes
//! `k / 2` inside and rises linearly to `(k + 1) / 2` at its edges over a bevel width.
//! The distance to an edge is the distance to the line through the edge of the tile's own
//! Robinson half (which POV-Ray's values show: near a dart's reflex corner the value
//! follows the line, not the corner). These facts were all measured on POV-Ray's values;
//! they match POV-Ray to 2e-7 from the origin out to 1e5 (its colours are single precision).

use glam::{DVec2, DVec3};

/// The golden ratio φ.
pub(super) const PHI: f64 = 1.618_033_988_749_895;

/// The rhombs' bevel width, measured on POV-Ray's values (no closed form found); `tiling
/// 25`'s pentagons, stars, boats and diamonds have the same.
pub(super) const RHOMBS_BEVEL: f64 = 0.291_537_656;

/// The two Penrose tilings.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Penrose {
    /// `tiling 26`: kites (type 0) and darts (type 1).
    KitesAndDarts,
    /// `tiling 27`: thick rhombs (type 0) and thin rhombs (type 1).
    Rhombs,
}

impl Penrose {
    /// The bevel width, measured on POV-Ray's values: for kites and darts `1 / 4.46` to
    /// the nine digits measured, for rhombs 0.29153766 (no closed form found).
    fn bevel(self) -> f64 {
        match self {
            Penrose::KitesAndDarts => 1.0 / 4.46,
            Penrose::Rhombs => RHOMBS_BEVEL,
        }
    }
}

/// A Robinson triangle: `a` is its apex, between its two equal legs `ab` and `ac`. The
/// order of `b` and `c` carries the triangle's handedness, which the cuts pass on.
#[derive(Clone, Copy, Debug)]
struct Triangle {
    obtuse: bool,
    a: DVec2,
    b: DVec2,
    c: DVec2,
}

/// Whether `q` lies on `side`'s side of the line from `from` to `to` (or on the line).
fn same_side(from: DVec2, to: DVec2, side: DVec2, q: DVec2) -> bool {
    let edge = to - from;
    edge.perp_dot(q - from) * edge.perp_dot(side - from) >= 0.0
}

impl Triangle {
    fn new(obtuse: bool, a: DVec2, b: DVec2, c: DVec2) -> Triangle {
        Triangle { obtuse, a, b, c }
    }

    /// Cut α of an acute triangle, the part that holds `q`: the cut runs from `c` to the
    /// point `1/φ` of the way from `a` to `b`.
    fn alpha(self, q: DVec2) -> Triangle {
        let p = self.a + (self.b - self.a) / PHI;
        if same_side(self.c, p, self.b, q) {
            Triangle::new(false, self.c, p, self.b)
        } else {
            Triangle::new(true, p, self.c, self.a)
        }
    }

    /// Cut β of an obtuse triangle, the part that holds `q`: the cut runs from `a` to the
    /// point `1/φ` of the way from `b` to `c`.
    fn beta(self, q: DVec2) -> Triangle {
        let r = self.b + (self.c - self.b) / PHI;
        if same_side(self.a, r, self.b, q) {
            Triangle::new(false, self.b, self.a, r)
        } else {
            Triangle::new(true, r, self.c, self.a)
        }
    }
}

/// The distance from `q` to the line through `from` and `to`.
fn line_distance(from: DVec2, to: DVec2, q: DVec2) -> f64 {
    let edge = to - from;
    edge.perp_dot(q - from).abs() / edge.length()
}

/// The value of `tiling` at `p` (y is ignored), in 0..=1.
pub fn value(tiling: Penrose, p: DVec3) -> f64 {
    let q = DVec2::new(p.x, p.z);
    let Some(triangle) = tile_half(tiling, q) else {
        return 0.0;
    };
    let Triangle { obtuse, a, b, c } = triangle;
    // A kite or dart is two halves mirrored across the leg `ab`, a rhomb two halves
    // mirrored across the base `bc`; the kind of half names the tile type.
    let (kind, edge) = match tiling {
        Penrose::KitesAndDarts => (obtuse, line_distance(a, c, q).min(line_distance(b, c, q))),
        Penrose::Rhombs => (!obtuse, line_distance(a, b, q).min(line_distance(a, c, q))),
    };
    let kind = if kind { 1.0 } else { 0.0 };
    (kind + 1.0 - (edge / tiling.bevel()).min(1.0)) / 2.0
}

/// The Robinson half of the tile of `tiling` that holds `q`, found by descent from the
/// least wheel that holds it; `None` where `q` is not finite or farther than 1e300.
fn tile_half(tiling: Penrose, q: DVec2) -> Option<Triangle> {
    let distance = q.length();
    if distance.is_nan() || distance > 1e300 {
        return None;
    }
    // The least even count of deflations whose wheel holds every point nearer than
    // `distance` to the origin: a wheel holds the points nearer than its inner radius,
    // `cos 18°` of its outer one, its legs (rhombs take one cut more, so their wheel is
    // one size up).
    let mut legs = if tiling == Penrose::Rhombs { PHI } else { 1.0 };
    let mut deflations = 0;
    while legs * COS_18 <= distance {
        legs *= PHI * PHI;
        deflations += 2;
    }
    Some(descend(tiling, deflations, legs, q))
}

/// `cos 18°`, the inner radius of a regular decagon of outer radius 1.
const COS_18: f64 = 0.951_056_516_295_153_5;

/// The Robinson half of the tile of `tiling` that holds `q`, by descent from the wheel of
/// `deflations` (even) deflations, whose triangles' legs are `legs` long and which must
/// hold `q`.
fn descend(tiling: Penrose, deflations: u32, legs: f64, q: DVec2) -> Triangle {
    let mut half = wheel_triangle(legs, deflations.is_multiple_of(4), q);
    for _ in 0..deflations {
        if !half.obtuse {
            half = half.alpha(q);
        }
        if half.obtuse {
            half = half.beta(q);
        }
    }
    if tiling == Penrose::Rhombs && !half.obtuse {
        half = half.alpha(q);
    }
    half
}

/// The directions of the wheel's spokes, `k 36°` from +x towards +z.
pub(super) const SPOKES: [DVec2; 10] = {
    const C36: f64 = 0.809_016_994_374_947_5;
    const S36: f64 = 0.587_785_252_292_473_1;
    const C72: f64 = 0.309_016_994_374_947_45;
    const S72: f64 = 0.951_056_516_295_153_5;
    [
        DVec2::new(1.0, 0.0),
        DVec2::new(C36, S36),
        DVec2::new(C72, S72),
        DVec2::new(-C72, S72),
        DVec2::new(-C36, S36),
        DVec2::new(-1.0, 0.0),
        DVec2::new(-C36, -S36),
        DVec2::new(-C72, -S72),
        DVec2::new(C72, -S72),
        DVec2::new(C36, -S36),
    ]
};

/// The triangle that holds `q` of the wheel of ten acute triangles of legs `legs` round
/// the origin, their apexes there, the first from +x towards +z. Neighbours are mirror
/// images; `mirrored` says which of the two wheels this is.
fn wheel_triangle(legs: f64, mirrored: bool, q: DVec2) -> Triangle {
    // The sector from one spoke (included) to the next; the origin takes the first.
    let index = (0..10)
        .find(|&k| SPOKES[k].perp_dot(q) >= 0.0 && q.perp_dot(SPOKES[(k + 1) % 10]) > 0.0)
        .unwrap_or(0);
    let (mut b, mut c) = (SPOKES[index] * legs, SPOKES[(index + 1) % 10] * legs);
    if (index % 2 == 1) == mirrored {
        std::mem::swap(&mut b, &mut c);
    }
    Triangle::new(false, DVec2::ZERO, b, c)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(tiling: Penrose, x: f64, z: f64) -> f64 {
        value(tiling, DVec3::new(x, -3.0, z))
    }

    /// Values POV-Ray 3.7 gives (read through a `color_map { [0 rgb 0] [1 rgb 1] }`
    /// pigment function and `#write`), near the origin and far from it: POV-Ray's colours
    /// are single precision.
    #[test]
    fn values_match_povrays() {
        let povray = [
            ((0.45, 0.2), 0.270_979_077, 0.156_991_139),
            ((-1.15, 0.05), 0.647_416_174, 0.097_560_346),
            ((2.3, -1.7), 0.225_131_691, 0.288_604_796),
            ((13.7, -4.2), 0.118_090_317, 0.600_106_537),
            ((-251.3, 97.6), 0.273_706_466, 0.212_693_185),
            ((1000.3, 370.1), 0.979_260_504, 0.630_898_893),
            ((-31415.9, 27182.8), 0.686_900_437, 0.049_076_781),
            ((123456.7, -654321.1), 0.772_537_410, 0.325_063_467),
        ];
        for ((x, z), kites_and_darts, rhombs) in povray {
            for (tiling, expected) in [
                (Penrose::KitesAndDarts, kites_and_darts),
                (Penrose::Rhombs, rhombs),
            ] {
                let ours = at(tiling, x, z);
                assert!(
                    (ours - expected).abs() < 2e-6,
                    "{tiling:?} at ({x}, {z}): {ours} is not {expected}"
                );
            }
        }
    }

    /// The sun of five kites round the origin: kite edges from the origin at 36° + k 72°,
    /// their axes at k 72°, the far corner of each at distance 1. Rhombs: five thick
    /// rhombs round the origin with edges along k 72°.
    #[test]
    fn the_origin_is_the_centre_of_a_sun_and_a_star() {
        let polar = |r: f64, degrees: f64| {
            let (sin, cos) = degrees.to_radians().sin_cos();
            (r * cos, r * sin)
        };
        for k in 0..5 {
            let turn = 72.0 * f64::from(k);
            let (x, z) = polar(0.5, turn + 36.0);
            assert!((at(Penrose::KitesAndDarts, x, z) - 0.5).abs() < 1e-9);
            let (x, z) = polar(0.5, turn);
            assert_eq!(at(Penrose::KitesAndDarts, x, z), 0.0);
            let (x, z) = polar(1.5, turn);
            assert!((at(Penrose::KitesAndDarts, x, z) - 0.5).abs() < 1e-9);
            let (x, z) = polar(0.5, turn);
            assert!((at(Penrose::Rhombs, x, z) - 0.5).abs() < 1e-9);
            let (x, z) = polar(0.8, turn + 36.0);
            assert_eq!(at(Penrose::Rhombs, x, z), 0.0);
        }
    }

    /// Wheels of different sizes draw the same tiling: descents from wheels of 12, 14 and
    /// 16 deflations, far bigger than the least that holds these points, find the same
    /// tile.
    #[test]
    fn bigger_wheels_draw_the_same_tiling() {
        for tiling in [Penrose::KitesAndDarts, Penrose::Rhombs] {
            let extra = i32::from(tiling == Penrose::Rhombs);
            for i in 0..50 {
                let q = DVec2::new(
                    f64::from(i) * 0.37 - 9.0,
                    f64::from(i * 7 % 50) * 0.41 - 10.0,
                );
                let least = tile_half(tiling, q).unwrap();
                for deflations in [12, 14, 16] {
                    let legs = PHI.powi(deflations as i32 + extra);
                    let half = descend(tiling, deflations, legs, q);
                    assert_eq!(half.obtuse, least.obtuse, "{tiling:?} at {q}");
                    assert!(half.a.distance(least.a) < 1e-9, "{tiling:?} at {q}");
                }
            }
        }
    }

    /// A point as far as a double reaches still answers (in about 3000 cuts), and points
    /// without a place take 0.
    #[test]
    fn far_and_non_finite_points_answer() {
        let far = at(Penrose::Rhombs, 3e299, -4e299);
        assert!((0.0..=1.0).contains(&far));
        assert_eq!(at(Penrose::KitesAndDarts, f64::NAN, 0.0), 0.0);
        assert_eq!(at(Penrose::Rhombs, f64::INFINITY, 0.0), 0.0);
        assert_eq!(at(Penrose::Rhombs, 1e301, 0.0), 0.0);
    }
}
