//! `tiling N`: periodic tilings of the x-z plane by polygons. Each tile type owns a band
//! of `1 / types` of the value range: a tile of type `k` takes `k / types` inside and
//! rises linearly to `(k + 1) / types` at its edges, over a ramp width set per edge
//! (POV-Ray's bevel). The geometry is data, in `tilings.txt`: it was fitted to the values
//! of POV-Ray 3.7's renders, each offset and width then recognised as a number of the form
//! `(a + b√2)/4`, `(a + b√3)/4` or `(a + b√3)/12`, and so reproduces POV-Ray's values to
//! 1e-5. Here a period's tiles are placed so that every point of one period cell finds its
//! tile among a short list.

use glam::{DVec2, DVec3};
use std::sync::OnceLock;

/// The tilings POV-Ray numbers 1 to 27 that are implemented: 1 to 24.
pub fn supported(number: u8) -> bool {
    (1..=tilings().len()).contains(&usize::from(number))
}

/// An edge's line scaled by its ramp width: the ramp is `normal . p - offset`, 0 on the
/// edge and 1 a ramp width inside.
struct Edge {
    normal: DVec2,
    offset: f64,
}

struct Tile {
    kind: f64,
    edges: Vec<Edge>,
}

/// A tiling ready to evaluate: its period, the dual basis that finds a point's place in
/// the period, and every copy of its tiles that overlaps the period cell spanned by `a`
/// and `b` from the origin.
struct Tiling {
    types: f64,
    a: DVec2,
    b: DVec2,
    dual_a: DVec2,
    dual_b: DVec2,
    tiles: Vec<Tile>,
}

fn tilings() -> &'static [Tiling] {
    static TILINGS: OnceLock<Vec<Tiling>> = OnceLock::new();
    TILINGS.get_or_init(|| {
        layouts(include_str!("tilings.txt"))
            .iter()
            .map(Tiling::new)
            .collect()
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

/// The value of `tiling number` at `p` (y is ignored), in 0..=1. `number` must be
/// `supported`.
pub fn value(number: u8, p: DVec3) -> f64 {
    let tiling = &tilings()[usize::from(number) - 1];
    let q = DVec2::new(p.x, p.z);
    let (u, v) = (tiling.dual_a.dot(q), tiling.dual_b.dot(q));
    let q = tiling.a * (u - u.floor()) + tiling.b * (v - v.floor());
    // The tile that holds the point has every ramp non-negative; a point that rounding
    // leaves just outside every tile takes the one it is least outside of.
    let mut best = (f64::NEG_INFINITY, 0.0);
    for tile in &tiling.tiles {
        let ramp = tile.edges.iter().fold(f64::INFINITY, |least, e| {
            least.min(e.normal.dot(q) - e.offset)
        });
        if ramp > best.0 {
            best = (ramp, tile.kind);
            if ramp >= 0.0 {
                break;
            }
        }
    }
    (best.1 + 1.0 - best.0.clamp(0.0, 1.0)) / tiling.types
}

impl Tiling {
    fn new(layout: &Layout) -> Tiling {
        let (a, b) = (layout.a, layout.b);
        let det = a.perp_dot(b);
        let cell = [DVec2::ZERO, a, a + b, b];
        let mut tiles = Vec::new();
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
        Tiling {
            types: f64::from(layout.types),
            a,
            b,
            dual_a: DVec2::new(b.y, -b.x) / det,
            dual_b: DVec2::new(-a.y, a.x) / det,
            tiles,
        }
    }
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
        for (index, tiling) in tilings().iter().enumerate() {
            for i in 0..40 {
                for j in 0..40 {
                    let q = tiling.a * ((f64::from(i) + 0.37) / 40.0)
                        + tiling.b * ((f64::from(j) + 0.61) / 40.0);
                    let holding = tiling
                        .tiles
                        .iter()
                        .filter(|tile| tile.edges.iter().all(|e| e.normal.dot(q) - e.offset > 1e-9))
                        .count();
                    assert_eq!(holding, 1, "tiling {} at {q}", index + 1);
                }
            }
        }
    }

    #[test]
    fn every_tiling_of_the_table_is_read() {
        let layouts = layouts(include_str!("tilings.txt"));
        assert_eq!(layouts.len(), 24);
        for (index, layout) in layouts.iter().enumerate() {
            assert!(!layout.tiles.is_empty(), "tiling {}", index + 1);
            let kinds = layout.tiles.iter().map(|(kind, _)| *kind).max();
            assert_eq!(kinds, Some(layout.types - 1), "tiling {}", index + 1);
        }
    }

    #[test]
    fn the_pattern_repeats_with_its_period() {
        for number in 1..=24 {
            let tiling = &tilings()[usize::from(number) - 1];
            let p = DVec2::new(0.313, -0.271);
            let q = p + tiling.a * 3.0 - tiling.b * 2.0;
            assert_close(at(number, p.x, p.y), at(number, q.x, q.y));
        }
    }
}
