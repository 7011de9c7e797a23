//! `tiling N`: periodic tilings of the x-z plane by polygons. Each tile type owns a band
//! of `1 / types` of the value range: a tile of type `k` takes `k / types` inside and
//! rises linearly to `(k + 1) / types` at its edges, over a ramp width set per edge
//! (POV-Ray's bevel). The geometry is data, in `tilings.txt`: it was fitted to the values
//! of POV-Ray 3.7's renders, each offset and width then recognised as a number of the form
//! `(a + b√2)/4`, `(a + b√3)/4` or `(a + b√3)/12`, and so reproduces POV-Ray's values to
//! 1e-5. Here a period's tiles are placed so that every point of one period cell finds its
//! tile among a short list: the cell is cut into a grid, and each grid square lists the
//! few tiles that reach into it. Tilings 25 to 27 are Penrose's, aperiodic, and built by
//! their own substitution rules: 25, his first tiling of pentagons, stars, boats and
//! diamonds, in `pentagons`; 26 and 27, his kites and darts and his rhombs, in `penrose`.

mod penrose;
mod pentagons;

use super::floor;
use glam::{DVec2, DVec3};
use penrose::Penrose;
use std::ops::Range;
use std::sync::OnceLock;

/// How many tilings `tilings.txt` holds: POV-Ray's periodic tilings, 1 to 24.
const TILINGS: usize = 24;

/// Which of the Penrose tilings built from Robinson triangles POV-Ray's tiling `number`
/// is, if it is one of them.
fn penrose(number: u8) -> Option<Penrose> {
    match number {
        26 => Some(Penrose::KitesAndDarts),
        27 => Some(Penrose::Rhombs),
        _ => None,
    }
}

/// An edge's line scaled by its ramp width: the ramp is `normal . p - offset`, 0 on the
/// edge and 1 a ramp width inside.
#[derive(Clone)]
struct Edge {
    normal: DVec2,
    offset: f64,
}

/// A tile: its type, and its edges.
struct Tile {
    kind: f64,
    edges: Vec<Edge>,
}

/// The least of the ramps of `edges` at `q` (NaN ramps left out).
fn ramp(edges: &[Edge], q: DVec2) -> f64 {
    edges.iter().fold(f64::INFINITY, |least, e| {
        least.min(e.normal.dot(q) - e.offset)
    })
}

/// [`ramp`] when it is not negative (the tile holds `q`); `None` from the first negative
/// ramp on.
fn ramp_if_holding(edges: &[Edge], q: DVec2) -> Option<f64> {
    let mut least = f64::INFINITY;
    for e in edges {
        let ramp = e.normal.dot(q) - e.offset;
        if ramp < 0.0 {
            return None;
        }
        // As `least.min(ramp)`: a NaN ramp is left out, and `least` is never NaN.
        if ramp < least {
            least = ramp;
        }
    }
    Some(least)
}

/// A tile listed for a grid square: its type and the range of [`Tiling::edges`] that
/// holds its edges there. Every square's tiles share one list of edges, so that a search
/// reads them in a row rather than through a list of its own for each tile.
struct Candidate {
    kind: f64,
    edges: Range<u32>,
}

/// How many grid squares the period cell is cut into along each of its sides.
const GRID: usize = 16;

/// A tiling ready to evaluate: its period, the dual basis that finds a point's place in
/// the period cell spanned by `a` and `b` from the origin, and for each square of the
/// cell's grid (row by row in the `b` direction) the range of `candidates` that lists the
/// copies of its tiles reaching into it, each with only those of its edges that matter
/// there (in `edges`).
struct Tiling {
    types: f64,
    a: DVec2,
    b: DVec2,
    dual_a: DVec2,
    dual_b: DVec2,
    squares: Vec<Range<u32>>,
    candidates: Vec<Candidate>,
    edges: Vec<Edge>,
}

/// Periodic tiling `number` (1 to 24), made ready the first time a scene uses
/// it: a scene uses few of them.
fn tiling(number: u8) -> &'static Tiling {
    static READY: [OnceLock<Tiling>; TILINGS] = [const { OnceLock::new() }; TILINGS];
    static LAYOUTS: OnceLock<Vec<Layout>> = OnceLock::new();
    let index = usize::from(number) - 1;
    READY[index].get_or_init(|| {
        Tiling::new(&LAYOUTS.get_or_init(|| layouts(include_str!("tilings.txt")))[index])
    })
}

/// An edge as `tilings.txt` gives it: inward normal angle in degrees, offset, ramp width.
type EdgeLine = (f64, f64, f64);

/// One tiling's period as `tilings.txt` gives it.
struct Layout {
    types: u8,
    a: DVec2,
    b: DVec2,
    /// Each tile's type and edges.
    tiles: Vec<(u8, Vec<EdgeLine>)>,
}

/// The layouts in `text`, in the order it gives them. The text is ours and fixed (a test
/// reads it all), so a malformed line is a bug, not an input error.
fn layouts(text: &str) -> Vec<Layout> {
    let numbers = |words: &str| -> Vec<f64> {
        words
            .split_whitespace()
            .map(|w| w.parse().expect("tilings.txt holds numbers"))
            .collect()
    };
    let mut layouts: Vec<Layout> = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        if let Some(head) = line.strip_prefix("tiling ") {
            // `N types T period AX AZ BX BZ`, without the words.
            let head = head.replace("types", "").replace("period", "");
            let n = numbers(&head);
            layouts.push(Layout {
                types: n[1] as u8,
                a: DVec2::new(n[2], n[3]),
                b: DVec2::new(n[4], n[5]),
                tiles: Vec::new(),
            });
        } else if let (Some((kind, edges)), Some(layout)) =
            (line.split_once(':'), layouts.last_mut())
        {
            let edges = edges
                .split('|')
                .map(|edge| match numbers(edge)[..] {
                    [angle, offset, width] => (angle, offset, width),
                    _ => panic!("tilings.txt: an edge is three numbers: {edge}"),
                })
                .collect();
            layout.tiles.push((
                kind.trim().parse().expect("tilings.txt: a tile type"),
                edges,
            ));
        }
    }
    layouts
}

/// The value of `tiling number` at `p` (y is ignored), in 0..=1. `number` must be one
/// of POV-Ray's, 1 to 27.
pub fn value(number: u8, p: DVec3) -> f64 {
    let [value] = values(number, [p]);
    value
}

/// [`value`] at each of `points`, the tiling found once for them all: a bumped normal
/// asks for four values at a time, where finding the tiling and a call for each value
/// cost as much as a periodic tiling's own search.
pub fn values<const N: usize>(number: u8, points: [DVec3; N]) -> [f64; N] {
    if number == 25 {
        return points.map(pentagons::value);
    }
    if let Some(penrose) = penrose(number) {
        return points.map(|p| penrose::value(penrose, p));
    }
    let tiling = tiling(number);
    // A loop rather than `map`, whose closure calls are not all inlined.
    let mut values = [0.0; N];
    for (value, p) in values.iter_mut().zip(points) {
        let q = DVec2::new(p.x, p.z);
        let (u, v) = (tiling.dual_a.dot(q), tiling.dual_b.dot(q));
        *value = tiling.value_in_cell(u - floor(u), v - floor(v));
    }
    values
}

/// The grid square along one side of the period cell that holds the fraction `t` of it
/// (`t` in 0..=1, where rounding can give 1; NaN goes to the first square). Through
/// `u32`, whose conversion from a float is a few instructions where `usize`'s, for values
/// up to 2^64, is a dozen more.
fn grid_index(t: f64) -> usize {
    ((t * GRID as f64) as u32 as usize).min(GRID - 1)
}

impl Tiling {
    /// The value at the point `u a + v b` of the period cell (`u`, `v` in 0..=1). The grid
    /// square's candidates keep the tiles' order, so the tile found is the one a search of
    /// every tile would find. Inlined into [`values`]' loop, as it was into a single
    /// value's search before: a call costs a tenth of a search.
    #[inline(always)]
    fn value_in_cell(&self, u: f64, v: f64) -> f64 {
        let Range { start, end } = self.squares[grid_index(v) * GRID + grid_index(u)].clone();
        let tiles = self.candidates[start as usize..end as usize]
            .iter()
            .map(|c| {
                (
                    c.kind,
                    &self.edges[c.edges.start as usize..c.edges.end as usize],
                )
            });
        self.value_among(tiles, self.a * u + self.b * v)
    }

    /// The value at `q` of the first of `tiles` that holds it. The tile that holds a point
    /// has every ramp non-negative, and the search leaves every other tile at its first
    /// negative ramp; a point that rounding leaves just outside every tile takes the first
    /// one it is least outside of.
    fn value_among<'a>(
        &self,
        tiles: impl Iterator<Item = (f64, &'a [Edge])> + Clone,
        q: DVec2,
    ) -> f64 {
        let value = |kind: f64, ramp: f64| (kind + 1.0 - ramp.clamp(0.0, 1.0)) / self.types;
        for (kind, edges) in tiles.clone() {
            if let Some(ramp) = ramp_if_holding(edges, q) {
                return value(kind, ramp);
            }
        }
        let mut best = (f64::NEG_INFINITY, 0.0);
        for (kind, edges) in tiles {
            let least = ramp(edges, q);
            if least > best.0 {
                best = (least, kind);
            }
        }
        value(best.1, best.0)
    }

    fn new(layout: &Layout) -> Tiling {
        let (a, b) = (layout.a, layout.b);
        let det = a.perp_dot(b);
        let dual_a = DVec2::new(b.y, -b.x) / det;
        let dual_b = DVec2::new(-a.y, a.x) / det;
        let (tiles, extents) = copies(layout, dual_a, dual_b);
        let (squares, candidates, edges) = grid_candidates(&extents, &tiles, a, b);
        Tiling {
            types: f64::from(layout.types),
            a,
            b,
            dual_a,
            dual_b,
            squares,
            candidates,
            edges,
        }
    }
}

/// Every copy of the layout's tiles that overlaps the period cell spanned by its `a` and
/// `b` from the origin, and each one's extent in the cell's own coordinates (fractions of
/// `a` and `b`, as the dual basis gives them).
fn copies(layout: &Layout, dual_a: DVec2, dual_b: DVec2) -> (Vec<Tile>, Vec<(DVec2, DVec2)>) {
    let (a, b) = (layout.a, layout.b);
    let cell = [DVec2::ZERO, a, a + b, b];
    let mut tiles = Vec::new();
    // Each tile's extent in the cell's own coordinates (fractions of `a` and `b`),
    // where the grid squares it may reach are a rectangle.
    let mut extents = Vec::new();
    for (kind, edges) in &layout.tiles {
        let lines: Vec<(DVec2, f64, f64)> = edges
            .iter()
            .map(|&(angle, offset, width)| {
                let (sin, cos) = angle.to_radians().sin_cos();
                (DVec2::new(cos, sin), offset, width)
            })
            .collect();
        let corners = corners(&lines);
        for i in -2..=2 {
            for j in -2..=2 {
                let shift = a * f64::from(i) + b * f64::from(j);
                let moved: Vec<DVec2> = corners.iter().map(|c| *c + shift).collect();
                if !overlaps(&moved, &cell) {
                    continue;
                }
                extents.push(moved.iter().fold(
                    (DVec2::INFINITY, DVec2::NEG_INFINITY),
                    |(lo, hi), c| {
                        let uv = DVec2::new(dual_a.dot(*c), dual_b.dot(*c));
                        (lo.min(uv), hi.max(uv))
                    },
                ));
                tiles.push(Tile {
                    kind: f64::from(*kind),
                    edges: lines
                        .iter()
                        .map(|&(normal, offset, width)| Edge {
                            normal: normal / width,
                            offset: (offset + normal.dot(shift)) / width,
                        })
                        .collect(),
                });
            }
        }
    }
    (tiles, extents)
}

/// For each grid square of the period cell (row by row in `v`), the range of the returned
/// candidates that names, in order, the tiles whose `extents` (lowest and highest `u`,
/// `v`) reach into it, and the list of edges the candidates' ranges point into. Extents are widened by a margin far above rounding, so a point that
/// rounding moves across a square's side still finds its tile.
///
/// Each listed tile keeps only the edges whose ramp falls below 1 somewhere in the square
/// (the grid square is the parallelogram `u a + v b` over its range of `u` and `v`, and a
/// ramp, linear, is least at one of its corners): an edge whose ramp is 1 or more all
/// over it neither leaves a point outside the tile nor lowers the value, which takes the
/// least ramp up to 1.
fn grid_candidates(
    extents: &[(DVec2, DVec2)],
    tiles: &[Tile],
    a: DVec2,
    b: DVec2,
) -> (Vec<Range<u32>>, Vec<Candidate>, Vec<Edge>) {
    const MARGIN: f64 = 1e-6;
    let squares_of = |lo: f64, hi: f64| {
        let first = ((lo - MARGIN) * GRID as f64).floor().max(0.0) as usize;
        let last = ((hi + MARGIN) * GRID as f64).floor().max(0.0) as usize;
        first..=last.min(GRID - 1)
    };
    let mut lists = vec![Vec::new(); GRID * GRID];
    for (index, (lo, hi)) in extents.iter().enumerate() {
        for j in squares_of(lo.y, hi.y) {
            for i in squares_of(lo.x, hi.x) {
                lists[j * GRID + i].push(index as u16);
            }
        }
    }
    let mut candidates = Vec::new();
    let mut kept = Vec::new();
    let squares = lists
        .into_iter()
        .enumerate()
        .map(|(square, list)| {
            let (i, j) = (square % GRID, square / GRID);
            let corners = [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)]
                .map(|(i, j)| a * (i as f64 / GRID as f64) + b * (j as f64 / GRID as f64));
            let start = candidates.len() as u32;
            for index in list {
                let tile = &tiles[usize::from(index)];
                let first = kept.len() as u32;
                kept.extend(
                    tile.edges
                        .iter()
                        .filter(|e| {
                            let least = corners.iter().map(|c| e.normal.dot(*c) - e.offset);
                            least.fold(f64::INFINITY, f64::min) < 1.0 + MARGIN
                        })
                        .cloned(),
                );
                candidates.push(Candidate {
                    kind: tile.kind,
                    edges: first..kept.len() as u32,
                });
            }
            start..candidates.len() as u32
        })
        .collect();
    (squares, candidates, kept)
}

/// The corners of the convex polygon bounded by `lines` (normal, offset, width), whose
/// normals go round in order: each where one edge's line meets the next one's.
fn corners(lines: &[(DVec2, f64, f64)]) -> Vec<DVec2> {
    (0..lines.len())
        .map(|k| {
            let (n1, c1, _) = lines[k];
            let (n2, c2, _) = lines[(k + 1) % lines.len()];
            let det = n1.perp_dot(n2);
            DVec2::new(c1 * n2.y - c2 * n1.y, n1.x * c2 - n2.x * c1) / det
        })
        .collect()
}

/// Whether two convex polygons share some area (touching is not overlapping), by the
/// separating axis test over both polygons' edge normals.
fn overlaps(p: &[DVec2], q: &[DVec2]) -> bool {
    let normals = |poly: &[DVec2]| {
        (0..poly.len())
            .map(|k| (poly[(k + 1) % poly.len()] - poly[k]).perp())
            .collect::<Vec<_>>()
    };
    let span = |poly: &[DVec2], axis: DVec2| {
        poly.iter()
            .map(|v| v.dot(axis))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), d| {
                (lo.min(d), hi.max(d))
            })
    };
    normals(p).into_iter().chain(normals(q)).all(|axis| {
        let (lo1, hi1) = span(p, axis);
        let (lo2, hi2) = span(q, axis);
        let slack = 1e-9 * axis.length();
        hi1 > lo2 + slack && hi2 > lo1 + slack
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(number: u8, x: f64, z: f64) -> f64 {
        value(number, DVec3::new(x, 7.0, z))
    }

    /// Every copy of tiling `number`'s tiles that overlaps its period cell, with all its
    /// edges.
    fn all_tiles(number: u8) -> Vec<Tile> {
        let tiling = tiling(number);
        let layout = &layouts(include_str!("tilings.txt"))[usize::from(number) - 1];
        copies(layout, tiling.dual_a, tiling.dual_b).0
    }

    fn assert_close(ours: f64, povray: f64) {
        assert!((ours - povray).abs() < 1e-6, "{ours} is not {povray}");
    }

    /// Values POV-Ray 3.7 gives (read through a `color_map { [0 rgb 0] [1 rgb 1] }`
    /// pigment function and `#debug`).
    #[test]
    fn values_match_povrays() {
        // Unit squares ramping over half a unit from their edges.
        assert_close(at(1, 0.1, 0.5), 0.8);
        assert_close(at(1, 0.5, 0.3), 0.4);
        // Hexagons of side 1, one centred at (2, 0).
        assert_close(at(2, 2.0, 0.0), 0.0);
        assert_close(at(2, 1.5, 0.0), 0.5);
        assert_close(at(2, 0.0, 0.3), 0.826_794_9);
        // Octagons (type 1 of 2) round the origin, squares between them.
        assert_close(at(7, 0.0, 0.0), 0.5);
        assert_close(at(7, 1.0, 0.0), 0.792_893_2);
        assert_close(at(7, 0.9, 0.1), 0.692_893_2);
    }

    /// Every period's copies of its tiles cover the cell exactly once: the tile areas
    /// that fall inside add up to the cell's area (checked on a grid of points, each of
    /// which must lie inside exactly one tile).
    #[test]
    fn tiles_cover_each_period_once() {
        for number in 1..=TILINGS as u8 {
            let (tiling, tiles) = (tiling(number), all_tiles(number));
            for i in 0..40 {
                for j in 0..40 {
                    let q = tiling.a * ((f64::from(i) + 0.37) / 40.0)
                        + tiling.b * ((f64::from(j) + 0.61) / 40.0);
                    let holding = tiles
                        .iter()
                        .filter(|tile| ramp(&tile.edges, q) > 1e-9)
                        .count();
                    assert_eq!(holding, 1, "tiling {number} at {q}");
                }
            }
        }
    }

    /// Each grid square's candidates include every tile that holds a point of the square,
    /// with every edge that matters there: points on a fine lattice, the squares' own
    /// sides among them, get exactly the value a search of every tile with all its edges
    /// gives.
    #[test]
    fn grid_squares_list_every_tile_that_reaches_them() {
        let steps = GRID * 12;
        for number in 1..=TILINGS as u8 {
            let (tiling, tiles) = (tiling(number), all_tiles(number));
            for i in 0..=steps {
                for j in 0..=steps {
                    let (u, v) = (i as f64 / steps as f64, j as f64 / steps as f64);
                    let q = tiling.a * u + tiling.b * v;
                    let everywhere =
                        tiling.value_among(tiles.iter().map(|t| (t.kind, t.edges.as_slice())), q);
                    assert_eq!(tiling.value_in_cell(u, v), everywhere, "at {q}");
                }
            }
        }
    }

    #[test]
    fn every_tiling_of_the_table_is_read() {
        let layouts = layouts(include_str!("tilings.txt"));
        assert_eq!(layouts.len(), TILINGS);
        for (index, layout) in layouts.iter().enumerate() {
            assert!(!layout.tiles.is_empty(), "tiling {}", index + 1);
            let kinds = layout.tiles.iter().map(|(kind, _)| *kind).max();
            assert_eq!(kinds, Some(layout.types - 1), "tiling {}", index + 1);
        }
    }

    #[test]
    fn the_pattern_repeats_with_its_period() {
        for number in 1..=24 {
            let tiling = tiling(number);
            let p = DVec2::new(0.313, -0.271);
            let q = p + tiling.a * 3.0 - tiling.b * 2.0;
            assert_close(at(number, p.x, p.y), at(number, q.x, q.y));
        }
    }
}
