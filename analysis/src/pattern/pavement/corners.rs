//! The looks of a pavement tile's corners other than POV-Ray's default sharp ones:
//! `form` for the corners where a tile turns (slow convex corners), `exterior` for the
//! corners of a tile's pointed ends (quick convex ones) and `interior` for its notches
//! (concave corners); 0 is sharp, 1 cut and 2 round.
//!
//! Measured on POV-Ray 3.7 (its values read through 16-bit renders of a grey ramp, which
//! these rules reproduce to 1e-4 on every layout tried with looks drawn at random: all
//! 56 of squares, all 22 of triangles, and hexagons'): a look is a norm, whose unit disc
//! is the sharp corner's polygon, that polygon turned to cut the corner, or a circle,
//! and a corner's ramp is a distance in that norm.
//!
//! Square cells (`square_distance`), with the norms max(|a|, |b|), |a| + |b| and the
//! Euclidean one:
//! - A cell whose tile turns in it (two adjacent tile edges, and a notch at the opposite
//!   corner `c`) is drawn whole from `c`: the distance is the lesser of `|p - c|` and
//!   `1 - |p - c|` in the `form`'s norm, so that the turn is a quarter ring round the
//!   notch.
//! - Elsewhere, the quarter of a cell at a corner where two of its edges are tile edges
//!   takes `1/2 - |p - m|` in the `exterior`'s norm, `m` the cell's centre: a tile's end
//!   is half a disc, a lone cell a whole one.
//! - A notch, a corner where the tile's edges leave away from the cell, counts `|p - v|`
//!   in the `interior`'s norm, `v` the corner.
//! - `form 3` draws a turning cell as any other (by `exterior` and `interior`).
//!
//! Hexagon cells (`hexagon_distance`) have corners of 120 degrees, drawn by `form`, and
//! notches of 240, drawn by `interior`; they have no pointed ends, and POV-Ray ignores
//! their `exterior`. Triangle cells (`triangle_distance`) have points of 60 degrees,
//! drawn by `exterior`, corners of 120, drawn by `form`, and notches, drawn by
//! `interior`. Both measure in the triangle lattice's norms: a hexagon's gauge with its
//! faces across the lattice directions (sharp) or along them (cut), or the Euclidean one.

use super::{Lattice, Layout, ROOT3_2};
use crate::floor::floor_whole_i32;
use crate::scene::Pavement;
use glam::DVec2;

/// How a corner is drawn: the unit disc of the norm its ramp measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Look {
    Sharp,
    Cut,
    Round,
}

impl Look {
    fn new(look: u8) -> Look {
        match look {
            0 => Look::Sharp,
            1 => Look::Cut,
            _ => Look::Round,
        }
    }

    /// The norm of `(a, b)`.
    fn norm(self, a: f64, b: f64) -> f64 {
        let (a, b) = (a.abs(), b.abs());
        match self {
            Look::Sharp => a.max(b),
            Look::Cut => a + b,
            Look::Round => a.hypot(b),
        }
    }
}

impl Look {
    /// The norm of `p` by which a hexagon's turning corner is drawn: a regular hexagon's
    /// gauge, its faces across the lattice directions (sharp) or along them and scaled
    /// to agree with the Euclidean norm across them (cut), or the Euclidean norm.
    fn hexagon_turn_norm(self, p: DVec2) -> f64 {
        match self {
            Look::Sharp => across_lattice(p),
            Look::Cut => along_lattice(p) / ROOT3_2,
            Look::Round => p.length(),
        }
    }

    /// The norm of `p` by which a hexagon tile's notch is drawn: as for a turning corner,
    /// but the cut and round norms agree with the sharp one along the notch's bisector.
    fn hexagon_notch_norm(self, p: DVec2) -> f64 {
        match self {
            Look::Sharp => across_lattice(p),
            Look::Cut => along_lattice(p) * ROOT3_2,
            Look::Round => p.length() * ROOT3_2,
        }
    }
}

/// The largest distance of `p` to the triangle lattice's three lines through the origin.
fn across_lattice(p: DVec2) -> f64 {
    let (a, b) = (0.5 * p.y, ROOT3_2 * p.x);
    p.y.abs().max((a - b).abs()).max((a + b).abs())
}

/// The largest length of `p` along the triangle lattice's three directions.
fn along_lattice(p: DVec2) -> f64 {
    let (a, b) = (0.5 * p.x, ROOT3_2 * p.y);
    p.x.abs().max((a + b).abs()).max((a - b).abs())
}

/// Bits of a square lattice vertex's mask: tile edges towards +x, +z, -x and -z.
const PLUS_X: u8 = 1;
const PLUS_Z: u8 = 2;
const MINUS_X: u8 = 4;
const MINUS_Z: u8 = 8;

/// The distance of `q` from the tile's edges as the ramp counts it (at most 1/2, where
/// the ramp ends), for square cells with the corner looks of `pavement`.
pub(super) fn square_distance(layout: &Layout, pavement: &Pavement, q: DVec2) -> f64 {
    let ((x, whole_x), (z, whole_z)) = (floor_whole_i32(q.x), floor_whole_i32(q.y));
    let (u, w) = (q.x - x, q.y - z);
    let lower_left = layout.in_period((whole_x, whole_z));
    // The masks of the cell's corners, by (cx, cz) offset from its lower left one.
    let mask = |offset: (i32, i32)| layout.mask_near(lower_left, offset);
    let masks = [[mask((0, 0)), mask((0, 1))], [mask((1, 0)), mask((1, 1))]];
    // The cell's own tile edges: along x at z = 0 and 1, along z at x = 0 and 1.
    let along_x = [masks[0][0] & PLUS_X != 0, masks[0][1] & PLUS_X != 0];
    let along_z = [masks[0][0] & PLUS_Z != 0, masks[1][0] & PLUS_Z != 0];
    let edges = along_x.iter().chain(&along_z).filter(|&&e| e).count();

    let interior = Look::new(pavement.interior);
    let exterior = Look::new(pavement.exterior);
    if pavement.form < 3 && edges == 2 && along_x.contains(&true) && along_z.contains(&true) {
        // The corner opposite the tile's corner in the cell.
        let cx = usize::from(!along_z[1]);
        let cz = usize::from(!along_x[1]);
        if outward(masks[cx][cz], cx, cz) == (true, true) {
            let form = Look::new(pavement.form);
            let from_notch = form.norm(u - cx as f64, w - cz as f64);
            return from_notch.min(1.0 - from_notch).clamp(0.0, 0.5);
        }
    }

    let mut nearest: f64 = 0.5;
    for (edge, distance) in along_x.iter().zip([w, 1.0 - w]) {
        if *edge {
            nearest = nearest.min(distance);
        }
    }
    for (edge, distance) in along_z.iter().zip([u, 1.0 - u]) {
        if *edge {
            nearest = nearest.min(distance);
        }
    }
    for cx in 0..2 {
        for cz in 0..2 {
            // The distances from the corner along x and along z.
            let a = (u - cx as f64).abs();
            let b = (w - cz as f64).abs();
            let edge_x = along_x[cz];
            let edge_z = along_z[cx];
            if edge_x && edge_z {
                // A tile's corner in this cell: its quarter of the cell is a quarter of a
                // disc round the cell's centre.
                if a <= 0.5 && b <= 0.5 {
                    nearest = nearest.min(0.5 - exterior.norm(0.5 - a, 0.5 - b));
                }
            } else if !edge_x && !edge_z {
                nearest = nearest.min(match outward(masks[cx][cz], cx, cz) {
                    (true, true) => interior.norm(a, b),
                    (true, false) => b,
                    (false, true) => a,
                    (false, false) => continue,
                });
            }
        }
    }
    nearest.max(0.0)
}

/// The distance of `q` from the tile's edges as the ramp counts it (at most `ramp`),
/// for hexagon cells with the corner looks of `pavement`: the tile's edges; where two
/// edges of the cell meet at a tile corner (of 120 degrees), in the kite between that
/// corner and the cell's centre `c`, `√3/2 - |q - c|` in the `form`'s norm; and at a
/// notch (a corner where one edge of the cell and the edge leaving it outward are tile
/// edges) `|q - v|` in the `interior`'s norm, `v` the corner.
pub(super) fn hexagon_distance(layout: &Layout, pavement: &Pavement, q: DVec2, ramp: f64) -> f64 {
    let lattice = Lattice::Hexagon;
    // The cell's centre is the corner of the triangle holding `q` whose i - k is 1
    // modulo 3.
    let triangle = triangle_holding(q);
    let centre = triangle
        .into_iter()
        .find(|(i, k)| (i - k).rem_euclid(3) == 1)
        .unwrap_or(triangle[0]);
    let from_centre = q - lattice.position(centre);
    let steps = lattice.steps();
    // The corner whose kite holds `q`: the direction from the centre nearest to q's (the
    // last of equals, as `max_by` keeps), each direction's projection found once.
    let along: [f64; 6] = std::array::from_fn(|d| {
        (lattice.position(steps[d]) - lattice.position((0, 0))).dot(from_centre)
    });
    let kite = (0..6)
        .max_by(|&a, &b| along[a].total_cmp(&along[b]))
        .unwrap_or(0);
    let form = Look::new(pavement.form);
    let interior = Look::new(pavement.interior);
    let mut nearest = ramp;
    let centre_in_period = layout.in_period(centre);
    for (j, &(di, dk)) in steps.iter().enumerate() {
        let corner = (centre.0 + di, centre.1 + dk);
        let mask = layout.mask_near(centre_in_period, (di, dk));
        // The cell's edges from this corner to the next and to the previous one, and
        // the lattice edge leaving it away from the cell.
        let (next, previous, outward) = ((j + 2) % 6, (j + 4) % 6, j);
        let edge = |d: usize| mask >> d & 1 != 0;
        let from_corner = q - lattice.position(corner);
        if edge(next) {
            nearest = nearest.min(lattice.across(from_corner)[next % 3].abs());
        }
        if edge(next) && edge(previous) {
            if j == kite && form != Look::Sharp {
                nearest = nearest.min(ROOT3_2 - form.hexagon_turn_norm(from_centre));
            }
        } else if edge(outward) && (edge(next) || edge(previous)) {
            nearest = nearest.min(interior.hexagon_notch_norm(from_corner));
        }
    }
    nearest.max(0.0)
}

/// The distance of `q` from the tile's edges as the ramp counts it (at most `ramp`, the
/// triangles' inradius), for triangle cells with the corner looks of `pavement`. At each
/// corner `v` of the cell that holds `q`, by the tile's angle there:
/// - where neither of the cell's edges at `v` is a tile edge but others are (a notch, or
///   a straight edge across the corner), `|q - v|` in the `interior`'s norm;
/// - at a point of 60 degrees, the cell's own tip, in the kite between `v` and the
///   cell's centre `m`, `ramp - |q - m|` in the `exterior`'s norm (a hexagon for cut, a
///   circle for round);
/// - at a corner of 120 degrees, over the two cells either side of the lattice edge from
///   `v` to `w`, in the kite at `v`, `√3/2 - |q - w|` in the `form`'s norm;
/// - otherwise the tile's edges round the angle, as by default.
pub(super) fn triangle_distance(layout: &Layout, pavement: &Pavement, q: DVec2, ramp: f64) -> f64 {
    let lattice = Lattice::Triangle;
    let corners = triangle_holding(q);
    let places = corners.map(|c| lattice.position(c));
    let centre = (places[0] + places[1] + places[2]) / 3.0;
    let steps = lattice.steps();
    let (form, exterior, interior) = (
        Look::new(pavement.form),
        Look::new(pavement.exterior),
        Look::new(pavement.interior),
    );
    // The corner whose kite holds `q`: the nearest (the first of equals, as `min_by`
    // keeps), each distance found once.
    let distances = places.map(|place| q.distance(place));
    let kite = (0..3)
        .min_by(|&a, &b| distances[a].total_cmp(&distances[b]))
        .unwrap_or(0);
    let mut nearest = ramp;
    let first_in_period = layout.in_period(corners[0]);
    for (n, (&corner, &place)) in corners.iter().zip(&places).enumerate() {
        let offset = (corner.0 - corners[0].0, corner.1 - corners[0].1);
        let mask = layout.mask_near(first_in_period, offset);
        let from_corner = q - place;
        let across = lattice.across(from_corner).map(f64::abs);
        // The cell's own edge from this corner to the next.
        let next = corners[(n + 1) % 3];
        let step = (next.0 - corner.0, next.1 - corner.1);
        if let Some(d) = steps.iter().position(|&s| s == step)
            && mask >> d & 1 != 0
        {
            nearest = nearest.min(across[d % 3]);
        }
        if mask == 0 {
            continue;
        }
        let edge = |d: usize| mask >> (d % 6) & 1 != 0;
        // The cell lies between directions `sector` and `sector + 1` from the corner.
        let sector = lattice.sector(lattice.across(centre - place));
        if !edge(sector) && !edge(sector + 1) {
            nearest = nearest.min(interior.hexagon_notch_norm(from_corner));
            continue;
        }
        // The tile edges either side of the cell, `up` and `down` sectors away.
        let up = (1..=6).find(|&m| edge(sector + m)).unwrap_or(6);
        let down = (0..6).find(|&m| edge(sector + 6 - m)).unwrap_or(0);
        let (a, b) = ((sector + up) % 3, (sector + 6 - down) % 3);
        nearest = match up + down {
            1 | 2 => nearest.min(across[a]).min(across[b]),
            3 => nearest.min(across[a]),
            _ => nearest.min(interior.hexagon_notch_norm(from_corner)),
        };
        if n != kite {
            continue;
        }
        if up + down == 1 && exterior != Look::Sharp {
            let from_centre = q - centre;
            let norm = match exterior {
                Look::Round => from_centre.length(),
                _ => across_lattice(from_centre),
            };
            nearest = nearest.min(ramp - norm);
        } else if up + down == 2 && form != Look::Sharp {
            // The lattice edge inside the corner, between the tile's two cells there.
            let inside = if up == 2 { sector + 1 } else { sector } % 6;
            let (di, dk) = steps[inside];
            let far = lattice.position((corner.0 + di, corner.1 + dk));
            nearest = nearest.min(ROOT3_2 - form.hexagon_turn_norm(q - far));
        }
    }
    nearest.max(0.0)
}

/// The corners of the triangle of the lattice that holds `q`, counterclockwise.
fn triangle_holding(q: DVec2) -> [(i32, i32); 3] {
    let ((i, k), down) = Lattice::Triangle.locate(q);
    if down {
        [(i + 1, k), (i + 1, k + 1), (i, k + 1)]
    } else {
        [(i, k), (i + 1, k), (i, k + 1)]
    }
}

/// Whether tile edges leave the cell's corner `(cx, cz)` away from the cell, along x and
/// along z, given the corner's mask.
fn outward(mask: u8, cx: usize, cz: usize) -> (bool, bool) {
    let x = if cx == 1 { PLUS_X } else { MINUS_X };
    let z = if cz == 1 { PLUS_Z } else { MINUS_Z };
    (mask & x != 0, mask & z != 0)
}

#[cfg(test)]
mod tests {
    use super::super::tests::{pavement, random_numbers};
    use super::super::{check, layout, pattern_count, value};
    use super::*;
    use glam::DVec3;

    /// `number_of_sides`, `number_of_tiles` and `pattern`; `form`, `exterior` and
    /// `interior`; points' x and z and POV-Ray's values there.
    type Case = ((u8, u8, u8), (u8, u8, u8), [(f64, f64, f64); 4]);

    /// Values POV-Ray 3.7 gives at points of layouts with every look, read from 16-bit
    /// renders of a `color_map { [0 rgb 0] [1 rgb 1] }` (so to 1e-4) at pixel centres.
    #[test]
    fn values_match_povrays() {
        #[rustfmt::skip]
        let cases: [Case; 28] = [
            ((4, 3, 2), (1, 0, 0), [(5.025, 3.925, 0.95000), (1.825, 3.475, 0.65000), (5.525, 5.675, 0.35000), (2.575, 0.725, 0.70001)]),
            ((4, 3, 2), (2, 0, 0), [(5.625, 2.275, 0.91441), (5.775, 4.625, 0.72192), (3.225, 5.425, 0.76777), (5.575, 3.325, 0.15000)]),
            ((4, 6, 5), (3, 0, 1), [(0.725, 5.625, 0.45000), (5.225, 2.375, 0.25000), (1.975, 4.575, 0.15000), (2.275, 1.975, 0.95000)]),
            ((4, 6, 5), (3, 2, 2), [(2.325, 5.625, 0.25000), (4.575, 5.675, 0.38079), (2.425, 5.725, 0.45000), (5.125, 0.525, 0.05000)]),
            ((4, 4, 4), (0, 1, 0), [(3.325, 4.125, 0.75000), (2.325, 5.225, 0.35000), (1.625, 0.775, 0.25000), (2.325, 2.275, 0.80000)]),
            ((4, 1, 1), (0, 2, 0), [(5.375, 3.625, 0.35355), (1.425, 2.475, 0.15811), (2.375, 5.575, 0.29155), (2.825, 4.675, 0.73825)]),
            ((4, 5, 3), (1, 1, 1), [(2.575, 1.625, 0.40000), (3.025, 3.975, 0.95000), (4.425, 4.075, 0.85000), (4.825, 0.925, 0.50001)]),
            ((4, 6, 17), (2, 2, 2), [(1.025, 1.525, 0.95131), (4.075, 2.325, 0.85000), (2.825, 2.625, 0.69642), (3.825, 0.375, 0.69642)]),
            ((4, 4, 5), (3, 2, 1), [(3.125, 1.325, 0.10001), (2.125, 4.175, 0.65000), (5.225, 5.525, 0.05000), (3.325, 2.725, 0.45000)]),
            ((4, 6, 34), (0, 0, 2), [(1.175, 4.925, 0.85000), (5.025, 3.825, 0.65000), (2.875, 0.025, 0.95000), (5.725, 3.325, 0.35000)]),
            ((6, 1, 1), (1, 0, 0), [(0.475, 3.125, 0.22469), (3.125, 3.025, 0.72891), (4.775, 2.225, 0.90001), (4.825, 0.925, 0.70001)]),
            ((6, 1, 1), (2, 0, 0), [(2.575, 5.425, 0.22249), (0.325, 0.825, 0.86142), (1.825, 2.075, 0.95818), (2.025, 4.975, 0.77450)]),
            ((6, 3, 2), (0, 0, 1), [(0.675, 5.925, 0.52480), (0.375, 4.775, 0.60446), (1.025, 5.825, 0.17839), (4.725, 0.625, 0.03630)]),
            ((6, 3, 2), (0, 0, 2), [(5.475, 1.775, 0.85122), (1.825, 3.075, 0.85106), (3.375, 4.225, 0.80708), (5.325, 3.425, 0.86455)]),
            ((6, 5, 22), (1, 0, 1), [(4.125, 0.575, 0.24186), (0.575, 5.875, 0.45080), (2.975, 5.675, 0.09561), (3.325, 3.475, 0.70001)]),
            ((6, 5, 22), (2, 0, 2), [(4.725, 1.975, 0.59580), (1.675, 1.025, 0.91046), (5.925, 3.875, 0.06331), (5.225, 0.075, 0.90106)]),
            ((6, 4, 5), (1, 0, 2), [(5.375, 1.475, 0.10954), (4.875, 2.875, 0.50001), (3.125, 4.775, 0.64555), (4.775, 2.725, 0.90001)]),
            ((6, 2, 1), (2, 0, 1), [(3.325, 5.175, 0.33942), (4.275, 5.975, 0.86125), (5.875, 0.325, 0.28035), (1.875, 2.125, 0.71534)]),
            ((3, 1, 1), (0, 1, 0), [(4.375, 2.025, 0.38241), (3.725, 1.275, 0.96663), (1.275, 0.625, 0.90753), (5.825, 2.625, 0.97836)]),
            ((3, 1, 1), (0, 2, 0), [(3.025, 0.625, 0.18640), (5.675, 1.825, 0.90951), (3.625, 5.275, 0.84607), (0.425, 2.975, 0.74131)]),
            ((3, 6, 12), (1, 0, 0), [(4.425, 2.325, 0.90404), (4.825, 4.225, 0.70001), (0.425, 0.125, 0.30001), (0.425, 4.925, 0.30001)]),
            ((3, 6, 12), (2, 0, 0), [(4.725, 3.975, 0.95311), (4.825, 4.675, 0.62579), (4.725, 1.575, 0.56973), (3.325, 3.675, 0.44974)]),
            ((3, 4, 2), (1, 2, 1), [(4.325, 5.075, 0.93031), (0.775, 4.075, 0.56622), (1.475, 1.675, 0.10001), (5.575, 3.825, 0.40018)]),
            ((3, 4, 3), (0, 0, 2), [(3.725, 4.025, 0.85350), (1.525, 2.925, 0.50875), (4.875, 1.475, 0.92978), (1.225, 5.875, 0.49920)]),
            ((3, 5, 4), (0, 2, 1), [(0.575, 3.725, 0.09622), (0.975, 2.475, 0.57365), (3.675, 3.325, 0.26593), (5.725, 3.125, 0.79876)]),
            ((3, 6, 11), (2, 1, 1), [(4.725, 2.025, 0.68240), (1.175, 5.225, 0.90007), (0.075, 4.425, 0.67135), (3.025, 0.775, 0.68467)]),
            ((3, 6, 5), (2, 1, 2), [(2.725, 3.775, 0.07497), (0.275, 3.725, 0.72311), (4.375, 2.625, 0.90674), (1.025, 1.225, 0.06249)]),
            ((3, 3, 1), (1, 2, 2), [(3.225, 5.775, 0.77945), (4.675, 5.425, 0.64067), (2.725, 3.825, 0.19982), (1.525, 0.075, 0.74524)]),
        ];
        for (combination, looks, points) in cases {
            let pavement = pavement(combination, looks);
            assert!(check(&pavement).is_ok());
            for (x, z, povray) in points {
                let ours = value(&pavement, DVec3::new(x, -1.0, z));
                assert!(
                    (ours - povray).abs() < 1e-4,
                    "{combination:?} {looks:?} at ({x}, {z}): {ours} is not {povray}"
                );
            }
        }
    }

    /// With every look sharp the rules here are the default ramp's, which the layouts'
    /// corner terms compute faster: the two agree everywhere.
    #[test]
    fn sharp_looks_give_the_default_ramp() {
        let mut random = random_numbers(0x9e37_79b9_7f4a_7c15);
        for (sides, ramp) in [(3, ROOT3_2 / 3.0), (4, 0.5), (6, ROOT3_2 / 3.0)] {
            for tiles in 1..=6 {
                for pattern in 1..=pattern_count(sides, tiles) {
                    let sharp = pavement((sides, tiles, pattern), (0, 0, 0));
                    let layout = layout(&sharp);
                    for _ in 0..200 {
                        let q = DVec2::new(random() * 24.0 - 12.0, random() * 24.0 - 12.0);
                        let ours = match sides {
                            3 => triangle_distance(layout, &sharp, q, ramp),
                            4 => square_distance(layout, &sharp, q),
                            _ => hexagon_distance(layout, &sharp, q, ramp),
                        };
                        let default = layout.distance(q, ramp);
                        assert!(
                            (ours - default).abs() < 1e-12,
                            "{sides} {tiles} {pattern} at {q}: {ours} is not {default}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn form_3_is_for_squares_only() {
        assert!(check(&pavement((3, 4, 2), (3, 0, 0))).is_err());
        assert!(check(&pavement((6, 3, 2), (3, 0, 0))).is_err());
        assert!(check(&pavement((4, 6, 35), (3, 2, 2))).is_ok());
        // Hexagons have no pointed ends: their exterior is ignored, as by POV-Ray.
        assert!(check(&pavement((6, 3, 2), (0, 2, 0))).is_ok());
        assert!(check(&pavement((3, 4, 2), (2, 1, 1))).is_ok());
    }
}
