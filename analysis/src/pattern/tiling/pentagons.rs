//! `tiling 25`, Penrose's first tiling, as POV-Ray 3.7 draws it: pentagons of three types
//! (0, 1 and 2), stars (3), boats (4) and diamonds (5), all with edges of length 1. A type 0
//! pentagon is centred on the origin with corners towards 36° + k 72° (from +x towards
//! +z), and the tiling is mirror symmetric about the x axis.
//!
//! It is its own substitution scaled by φ² and turned by 36°, and every tile's children
//! are fixed by its type and by a direction that its shape does not show (a pentagon of
//! type 1 or 2, a diamond) or shows only in part (a boat): measured on POV-Ray's values by
//! cutting them into tiles over a disc of radius 52 and checking that every tile of a
//! type, turned to its own direction, has the same children (the rules below, which hold
//! for all of them). A pentagon's children: a type 0 pentagon turned by 36° at its
//! centre, five pentagons at its corners, and at each edge half a diamond or the point of
//! a star or boat. A star's: a star turned by 36° at its centre, five type 1 pentagons
//! round it, and the middle points of five boats in its points; a boat's: the three of
//! those that its points hold. A diamond's: a type 1 pentagon and the points of a star
//! and a boat. Children astride a parent's edge are whole tiles in its list, so a point
//! finds its tile by descent from a pentagon round the origin big enough to hold it,
//! taking at each level the child that holds it: as many steps as the logarithm of its
//! distance, and no memory.
//!
//! The value follows the other tilings' convention: a tile of type `k` takes `k / 6`
//! inside and rises linearly to `(k + 1) / 6` at its edges over a bevel as wide as the
//! rhombs' of `tiling 27`. For a star the distance is to the line of the edge of its tenth
//! (the triangle from its centre to a point's tip and a neighbouring inner corner) that
//! holds the point; a boat, a star cut by the line through two of its inner corners,
//! takes the lesser of that and the distance to the cut. These match POV-Ray to 1e-6
//! from the origin out to 1e6 (its colours are single precision).

use super::penrose::{PHI, RHOMBS_BEVEL, SPOKES};
use glam::{DVec2, DVec3};
use std::sync::OnceLock;

/// φ², the substitution's scale.
const PHI2: f64 = PHI * PHI;

/// A regular pentagon's circumradius and inradius, edge 1.
const CIRCUMRADIUS: f64 = 0.850_650_808_352_039_9;
const INRADIUS: f64 = 0.688_190_960_235_586_8;

/// How far a star's tips and its inner corners lie from its centre, edge 1.
const TIP: f64 = CIRCUMRADIUS * PHI;
const INNER: f64 = CIRCUMRADIUS / PHI;

/// Half of a diamond's long and short diagonals, edge 1: `cos 18°` and `sin 18°`.
const DIAMOND_LONG: f64 = 0.951_056_516_295_153_5;
const DIAMOND_SHORT: f64 = 0.309_016_994_374_947_4;

/// The bevel width, measured on POV-Ray's values: the same as `tiling 27`'s.
const BEVEL: f64 = RHOMBS_BEVEL;

/// The tile types, numbered as POV-Ray's values band them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Pentagon0,
    Pentagon1,
    Pentagon2,
    Star,
    Boat,
    Diamond,
}

impl Kind {
    const ALL: [Kind; 6] = [
        Kind::Pentagon0,
        Kind::Pentagon1,
        Kind::Pentagon2,
        Kind::Star,
        Kind::Boat,
        Kind::Diamond,
    ];

    fn number(self) -> usize {
        self as usize
    }
}

/// A line that bounds a piece or bevels a tile: `normal . q - offset` is the distance
/// from it, positive on the tile's side.
#[derive(Clone, Copy)]
struct Line {
    normal: DVec2,
    offset: f64,
}

impl Line {
    /// The line from `a` to `b`, the tile on its left (corners counter-clockwise).
    fn through(a: DVec2, b: DVec2) -> Line {
        let normal = (b - a).perp().normalize();
        Line {
            normal,
            offset: normal.dot(a),
        }
    }

    fn distance(self, q: DVec2) -> f64 {
        self.normal.dot(q) - self.offset
    }
}

/// A convex part of a tile, and the lines whose distance makes the bevel in it.
struct Piece {
    sides: Vec<Line>,
    bevels: Vec<Line>,
}

impl Piece {
    /// How far inside the piece `q` is: the least distance to its sides, negative outside.
    fn depth(&self, q: DVec2) -> f64 {
        self.sides
            .iter()
            .fold(f64::INFINITY, |least, side| least.min(side.distance(q)))
    }
}

/// A tile of edge 1 in its own frame, its direction along +x: the pieces it is cut into,
/// the radius of a disc round its centre that holds it and that of one that it holds.
struct Shape {
    radius: f64,
    inner_radius: f64,
    pieces: Vec<Piece>,
}

/// A child of a tile in the tile's own frame, in units where the child's edge is 1 (the
/// parent's is φ²): its kind, centre, and direction in tenths of a turn.
struct Child {
    kind: Kind,
    centre: DVec2,
    turn: usize,
}

/// The shapes and substitution rules of the six kinds, in the order of `Kind::ALL`.
struct Rules {
    shapes: Vec<Shape>,
    children: Vec<Vec<Child>>,
}

fn rules() -> &'static Rules {
    static RULES: OnceLock<Rules> = OnceLock::new();
    RULES.get_or_init(|| Rules {
        shapes: Kind::ALL.iter().map(|&kind| shape(kind)).collect(),
        children: Kind::ALL.iter().map(|&kind| children(kind)).collect(),
    })
}

/// The spoke `k` tenths of a turn from +x (any `k`).
fn spoke(k: usize) -> DVec2 {
    SPOKES[k % 10]
}

/// A convex polygon with corners `corners` (counter-clockwise) whose every side bevels.
fn polygon(corners: &[DVec2]) -> Piece {
    let sides: Vec<Line> = (0..corners.len())
        .map(|k| Line::through(corners[k], corners[(k + 1) % corners.len()]))
        .collect();
    Piece {
        bevels: sides.clone(),
        sides,
    }
}

/// The triangle from the origin to `a` and `b` (counter-clockwise), beveled by its side
/// from `a` to `b` and by `more`.
fn tenth(a: DVec2, b: DVec2, more: &[Line]) -> Piece {
    let outer = Line::through(a, b);
    Piece {
        sides: vec![
            Line::through(DVec2::ZERO, a),
            outer,
            Line::through(b, DVec2::ZERO),
        ],
        bevels: [outer].into_iter().chain(more.iter().copied()).collect(),
    }
}

/// A star's tip `k` (of ten spokes, even) and its inner corners.
fn tip(k: usize) -> DVec2 {
    spoke(k) * TIP
}

fn inner(k: usize) -> DVec2 {
    spoke(k) * INNER
}

/// Each kind's shape: pentagons with corners along the even spokes; a star with tips
/// along them and inner corners along the odd ones, cut into ten triangles from its
/// centre; a boat, the star's points at spokes 8, 0 and 2 and the rest cut off by the
/// line from its inner corner at spoke 3 to the one at spoke 7; a diamond with its long
/// diagonal along +x.
fn shape(kind: Kind) -> Shape {
    match kind {
        Kind::Pentagon0 | Kind::Pentagon1 | Kind::Pentagon2 => {
            let corners: Vec<DVec2> = (0..5).map(|k| spoke(2 * k) * CIRCUMRADIUS).collect();
            Shape {
                radius: CIRCUMRADIUS,
                inner_radius: INRADIUS,
                pieces: vec![polygon(&corners)],
            }
        }
        Kind::Star => Shape {
            radius: TIP,
            inner_radius: INNER,
            pieces: (0..10)
                .map(|k| {
                    let (a, b) = if k % 2 == 0 {
                        (tip(k), inner(k + 1))
                    } else {
                        (inner(k), tip(k + 1))
                    };
                    tenth(a, b, &[])
                })
                .collect(),
        },
        Kind::Boat => {
            let cut = Line::through(inner(3), inner(7));
            let mut pieces: Vec<Piece> = [(tip(8), inner(9)), (inner(9), tip(0))]
                .into_iter()
                .chain([(tip(0), inner(1)), (inner(1), tip(2)), (tip(2), inner(3))])
                .chain([(inner(7), tip(8))])
                .map(|(a, b)| tenth(a, b, &[cut]))
                .collect();
            pieces.push(Piece {
                sides: vec![
                    Line::through(DVec2::ZERO, inner(3)),
                    cut,
                    Line::through(inner(7), DVec2::ZERO),
                ],
                bevels: vec![cut],
            });
            Shape {
                radius: TIP,
                inner_radius: cut.offset.abs(),
                pieces,
            }
        }
        Kind::Diamond => Shape {
            radius: DIAMOND_LONG,
            // The distance from its centre to its sides, `sin 36° / 2`.
            inner_radius: DIAMOND_LONG * DIAMOND_SHORT,
            pieces: vec![polygon(&[
                DVec2::new(DIAMOND_LONG, 0.0),
                DVec2::new(0.0, DIAMOND_SHORT),
                DVec2::new(-DIAMOND_LONG, 0.0),
                DVec2::new(0.0, -DIAMOND_SHORT),
            ])],
        },
    }
}

/// Each kind's children, as measured on POV-Ray's values. Directions are tenths of a turn
/// from the parent's.
fn children(kind: Kind) -> Vec<Child> {
    use Kind::*;
    let child = |kind: Kind, distance: f64, spoke_index: usize, turn: usize| Child {
        kind,
        centre: spoke(spoke_index) * distance,
        turn: turn % 10,
    };
    // A pentagon's children: the turned pentagon at its centre, a pentagon at each corner
    // (spokes 0, 2, ..., 8) and a tile astride each edge (spokes 1, 3, ..., 9), each
    // given as kind and direction; a diamond's centre is on the edge, a star's or boat's
    // an inner radius beyond it.
    let pentagon = |corners: [(Kind, usize); 5], edges: [(Kind, usize); 5]| {
        let mut list = vec![child(Pentagon0, 0.0, 0, 1)];
        for (k, (kind, turn)) in corners.into_iter().enumerate() {
            list.push(child(kind, CIRCUMRADIUS * PHI, 2 * k, turn));
        }
        for (k, (kind, turn)) in edges.into_iter().enumerate() {
            let distance = if kind == Diamond {
                INRADIUS * PHI2
            } else {
                CIRCUMRADIUS * PHI2
            };
            list.push(child(kind, distance, 2 * k + 1, turn));
        }
        list
    };
    // A star's or boat's children round its points along `spokes`: a type 1 pentagon
    // facing in, then a boat facing out.
    let points = |spokes: &[usize]| {
        let mut list = vec![child(Star, 0.0, 0, 1)];
        for &k in spokes {
            list.push(child(Pentagon1, CIRCUMRADIUS * PHI, k, k + 5));
            list.push(child(Boat, CIRCUMRADIUS * PHI2, k, k));
        }
        list
    };
    match kind {
        Pentagon0 => pentagon(
            [
                (Pentagon2, 2),
                (Pentagon2, 4),
                (Pentagon2, 6),
                (Pentagon2, 8),
                (Pentagon2, 0),
            ],
            [
                (Diamond, 1),
                (Diamond, 3),
                (Diamond, 5),
                (Diamond, 7),
                (Diamond, 9),
            ],
        ),
        Pentagon1 => pentagon(
            [
                (Pentagon2, 2),
                (Pentagon1, 0),
                (Pentagon1, 6),
                (Pentagon1, 4),
                (Pentagon1, 0),
            ],
            [(Boat, 4), (Diamond, 8), (Star, 0), (Diamond, 2), (Boat, 6)],
        ),
        Pentagon2 => pentagon(
            [
                (Pentagon2, 2),
                (Pentagon1, 0),
                (Pentagon1, 6),
                (Pentagon2, 8),
                (Pentagon2, 0),
            ],
            [
                (Boat, 4),
                (Diamond, 8),
                (Boat, 2),
                (Diamond, 7),
                (Diamond, 9),
            ],
        ),
        Star => points(&[0, 2, 4, 6, 8]),
        Boat => points(&[8, 0, 2]),
        // The star's tip and the boat's middle tip are the diamond's sharp corners.
        Diamond => vec![
            child(Pentagon1, INNER / 2.0, 5, 0),
            child(Star, DIAMOND_LONG * PHI2 - TIP, 0, 0),
            child(Boat, DIAMOND_LONG * PHI2 - TIP, 5, 5),
        ],
    }
}

/// `q` turned back by `turn` tenths of a turn.
fn unturn(q: DVec2, turn: usize) -> DVec2 {
    let s = spoke(turn);
    DVec2::new(q.x * s.x + q.y * s.y, q.y * s.x - q.x * s.y)
}

/// The value of `tiling 25` at `p` (y is ignored), in 0..=1; points that are not finite,
/// or farther than 1e300, take 0.
pub fn value(p: DVec3) -> f64 {
    let q = DVec2::new(p.x, p.z);
    let distance = q.length();
    if distance.is_nan() || distance > 1e300 {
        return 0.0;
    }
    let rules = rules();
    // The least count of substitutions whose pentagon round the origin holds every point
    // nearer than `distance`. The pentagon of `n` substitutions is `φ^2n` across and
    // turned by `-n 36°` from the first (whose corners point at 36°).
    let mut size = 1.0;
    let mut levels = 0;
    while INRADIUS * size <= distance {
        size *= PHI2;
        levels += 1;
    }
    let mut kind = Kind::Pentagon0;
    // `local` is the point in the frame of the tile it is in, in units of its edge.
    let mut local = unturn(q, (1 + 9 * levels) % 10) / size;
    for _ in 0..levels {
        let (child, in_child) = holding_child(rules, kind, local * PHI2);
        kind = child;
        local = in_child;
    }
    let shape = &rules.shapes[kind.number()];
    let piece = deepest(shape, local).0;
    let edge = piece
        .bevels
        .iter()
        .fold(f64::INFINITY, |least, line| least.min(line.distance(local)));
    let ramp = (edge / BEVEL).clamp(0.0, 1.0);
    (kind.number() as f64 + 1.0 - ramp) / 6.0
}

/// The piece of `shape` that holds `q`, or the one it is least outside of, and how deep
/// inside it `q` is.
fn deepest(shape: &Shape, q: DVec2) -> (&Piece, f64) {
    let mut best = (&shape.pieces[0], f64::NEG_INFINITY);
    for piece in &shape.pieces {
        let depth = piece.depth(q);
        if depth >= 0.0 {
            return (piece, depth);
        }
        if depth > best.1 {
            best = (piece, depth);
        }
    }
    best
}

/// The child of a tile of `kind` that holds `q` (in the tile's frame, in units of the
/// child's edge), and `q` in the child's own frame; where rounding leaves `q` outside
/// every child, the one it is least outside of.
fn holding_child(rules: &Rules, kind: Kind, q: DVec2) -> (Kind, DVec2) {
    let mut best = (Kind::Pentagon0, q, f64::NEG_INFINITY);
    for child in &rules.children[kind.number()] {
        let shape = &rules.shapes[child.kind.number()];
        let offset = q - child.centre;
        // A child whose disc does not reach `q` cannot hold it, and is never the nearest.
        if offset.length_squared() > shape.radius * shape.radius + 1e-9 {
            continue;
        }
        let in_child = unturn(offset, child.turn);
        if offset.length_squared() < shape.inner_radius * shape.inner_radius {
            return (child.kind, in_child);
        }
        let depth = deepest(shape, in_child).1;
        if depth >= 0.0 {
            return (child.kind, in_child);
        }
        if depth > best.2 {
            best = (child.kind, in_child, depth);
        }
    }
    (best.0, best.1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(x: f64, z: f64) -> f64 {
        value(DVec3::new(x, 2.5, z))
    }

    /// Values POV-Ray 3.7 gives (read through a `color_map { [0 rgb 0] [1 rgb 1] }`
    /// pigment function and `#debug`), in tiles of every type, near the origin and far
    /// from it: POV-Ray's colours are single precision.
    #[test]
    fn values_match_povrays() {
        let povray = [
            ((0.45, 0.2), 0.030_497_316),
            ((-1.15, 0.05), 0.974_302_232),
            ((2.3, -1.7), 0.124_952_629),
            ((13.7, -4.2), 0.318_773_955),
            ((-251.3, 97.6), 0.314_255_953),
            ((1000.3, 370.1), 0.333_334_327),
            ((-31415.9, 27182.8), 0.333_334_327),
            ((123456.7, -654321.1), 0.286_266_983),
        ];
        for ((x, z), expected) in povray {
            let ours = at(x, z);
            assert!(
                (ours - expected).abs() < 2e-6,
                "at ({x}, {z}): {ours} is not {expected}"
            );
        }
    }

    /// The type 0 pentagon round the origin, ramping over the bevel from its edges (whose
    /// normals point at k 72°), and its five type 2 neighbours across them.
    #[test]
    fn the_origin_is_the_centre_of_a_type_0_pentagon() {
        assert_eq!(at(0.0, 0.0), 0.0);
        for k in 0..5 {
            let normal = spoke(2 * k);
            let inside = normal * (INRADIUS - 0.1);
            assert!((at(inside.x, inside.y) - (1.0 - 0.1 / BEVEL) / 6.0).abs() < 1e-12);
            let across = normal * (INRADIUS + 0.4);
            assert!((at(across.x, across.y) - 2.0 / 6.0).abs() < 1e-12);
        }
    }

    /// The tiling is mirror symmetric about the x axis, as POV-Ray's is.
    #[test]
    fn the_tiling_mirrors_across_the_x_axis() {
        for i in 0..200 {
            let (x, z) = (
                f64::from(i) * 0.173 - 17.0,
                f64::from(i * 37 % 200) * 0.191 - 19.0,
            );
            assert!((at(x, z) - at(x, -z)).abs() < 1e-9, "at ({x}, {z})");
        }
    }

    /// The children of every kind cover their parent once: points of a parent (on a fine
    /// lattice) lie in exactly one child, away from the children's edges.
    #[test]
    fn children_cover_their_parents_once() {
        let rules = rules();
        for kind in Kind::ALL {
            let parent = &rules.shapes[kind.number()];
            for i in 0..80 {
                for j in 0..80 {
                    let q = DVec2::new(f64::from(i) + 0.37, f64::from(j) + 0.61) / 40.0 - 1.0;
                    let q = q * parent.radius;
                    if deepest(parent, q).1 < 1e-6 {
                        continue;
                    }
                    let scaled = q * PHI2;
                    let holding = rules.children[kind.number()]
                        .iter()
                        .filter(|child| {
                            let shape = &rules.shapes[child.kind.number()];
                            let in_child = unturn(scaled - child.centre, child.turn);
                            deepest(shape, in_child).1 > 1e-9
                        })
                        .count();
                    assert!(holding <= 1, "{kind:?} at {q}: {holding} children");
                    let on_edge = rules.children[kind.number()].iter().any(|child| {
                        let shape = &rules.shapes[child.kind.number()];
                        let in_child = unturn(scaled - child.centre, child.turn);
                        deepest(shape, in_child).1.abs() <= 1e-9
                    });
                    assert!(holding == 1 || on_edge, "{kind:?} at {q}: no child");
                }
            }
        }
    }

    /// Each shape holds the disc of its inner radius and lies within that of its radius,
    /// and touches both circles.
    #[test]
    fn shapes_lie_between_their_discs() {
        for kind in Kind::ALL {
            let shape = &rules().shapes[kind.number()];
            let depths = |radius: f64| {
                (0..3600).map(move |k| {
                    let q = DVec2::from_angle(f64::from(k) * std::f64::consts::TAU / 3600.0);
                    deepest(shape, q * radius).1
                })
            };
            assert!(
                depths(shape.inner_radius * (1.0 - 1e-9)).all(|d| d >= 0.0),
                "{kind:?}"
            );
            assert!(
                depths(shape.inner_radius * 1.001).any(|d| d < 0.0),
                "{kind:?}"
            );
            assert!(
                depths(shape.radius * (1.0 + 1e-9)).all(|d| d < 0.0),
                "{kind:?}"
            );
            assert!(depths(shape.radius * 0.999).any(|d| d >= 0.0), "{kind:?}");
        }
    }

    /// A point as far as a double reaches still answers, and points without a place take 0.
    #[test]
    fn far_and_non_finite_points_answer() {
        assert!((0.0..=1.0).contains(&at(3e299, -4e299)));
        assert_eq!(at(f64::NAN, 0.0), 0.0);
        assert_eq!(at(f64::INFINITY, 0.0), 0.0);
        assert_eq!(at(1e301, 0.0), 0.0);
    }
}
