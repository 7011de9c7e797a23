//! `pavement`: the x-z plane paved with copies of one polyform, a tile made of equal
//! cells (unit triangles, unit squares or hexagons of side 1), valued 1 on the tile's
//! edges and falling linearly to 0 a ramp width inside (half a unit for squares, the
//! triangle's inradius √3/6 for the others).
//!
//! The layouts are data, in `pavements.txt`, measured on POV-Ray 3.7: each edge of the
//! cell lattice is a tile edge where POV-Ray's value at its midpoint is 1 (inside a tile
//! it is 0 there), and each layout is stored over its period. The ramp near a corner was
//! fitted to POV-Ray's values (to 1e-6, at random points of every layout) with the
//! default `form`, `exterior` and `interior` 0: at a corner of the tile, bounded by the
//! two tile edges that meet there, the distance is the smaller of the distances to the
//! two edge lines where the tile's angle is under 180 degrees (a pointed corner), and
//! where it is over, the largest of the distances to the lattice lines through the corner
//! (so that the ramp turns sharp corners round a notch too, a hexagon's round the tip of
//! a 60 degree notch).
//!
//! Cells are found through the triangle lattice's vertices `(i + k/2, k √3/2)` (indices
//! `(i, k)`), or the square lattice's `(i, k)`; a hexagon is the six triangles round a
//! vertex whose `i - k` is 1 modulo 3, so that the hexagon of side 1 centred at (1, 0)
//! has its corners at (0, 0) and (2, 0), as in POV-Ray.

mod corners;

use crate::floor::floor_whole_i32;
use crate::scene::Pavement;
use glam::{DVec2, DVec3};
use std::sync::OnceLock;

/// How many patterns POV-Ray has for each number of tiles (1 to 6), by cell.
const TRIANGLE_PATTERNS: [u8; 6] = [1, 1, 1, 3, 4, 12];
const SQUARE_PATTERNS: [u8; 6] = [1, 1, 2, 5, 12, 35];
const HEXAGON_PATTERNS: [u8; 5] = [1, 1, 3, 7, 22];

/// How many patterns there are for tiles of `tiles` cells with `sides` sides; 0 for a
/// combination POV-Ray does not have.
pub fn pattern_count(sides: u8, tiles: u8) -> u8 {
    let counts: &[u8] = match sides {
        3 => &TRIANGLE_PATTERNS,
        4 => &SQUARE_PATTERNS,
        6 => &HEXAGON_PATTERNS,
        _ => &[],
    };
    counts
        .get(usize::from(tiles).wrapping_sub(1))
        .copied()
        .unwrap_or(0)
}

/// Whether the pavement's combination exists; `Err` says what is wrong, in POV-Ray's
/// terms.
pub fn check(pavement: &Pavement) -> Result<(), String> {
    let (sides, tiles, pattern) = (pavement.sides, pavement.tiles, pavement.pattern);
    if pavement.form == 3 && sides != 4 {
        return Err("pavement: form 3 is for square cells (number_of_sides 4) only".into());
    }
    if sides == 6 && tiles == 6 {
        return Err("pavement: number_of_tiles must be from 1 to 5 for hexagons".into());
    }
    let count = pattern_count(sides, tiles);
    if !(1..=count).contains(&pattern) {
        return Err(format!(
            "pavement: pattern {pattern} is out of range for number_of_sides {sides} \
             number_of_tiles {tiles} (1 to {count})"
        ));
    }
    Ok(())
}

const ROOT3_2: f64 = 0.866_025_403_784_438_6;

/// The cells' lattice.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Lattice {
    Square,
    Triangle,
    Hexagon,
}

impl Lattice {
    /// The signed distances of a point at `o` from a vertex to the lattice lines through
    /// it, one per direction of the first half of `steps` (positive to the left of it);
    /// a square vertex has two lines, and the third distance is 0.
    fn across(self, o: DVec2) -> [f64; 3] {
        match self {
            Lattice::Square => [o.y, -o.x, 0.0],
            Lattice::Triangle | Lattice::Hexagon => {
                [o.y, 0.5 * o.y - ROOT3_2 * o.x, -0.5 * o.y - ROOT3_2 * o.x]
            }
        }
    }

    /// The sector round a vertex that holds a point, from its signed distances to the
    /// lattice lines (`across`): sector `s` lies between directions `s` and `s + 1`.
    fn sector(self, [c0, c1, c2]: [f64; 3]) -> usize {
        match (self, c0 >= 0.0) {
            (Lattice::Square, true) => usize::from(c1 >= 0.0),
            (Lattice::Square, false) => 2 + usize::from(c1 <= 0.0),
            (_, true) if c1 < 0.0 => 0,
            (_, true) if c2 < 0.0 => 1,
            (_, true) => 2,
            (_, false) if c1 > 0.0 => 3,
            (_, false) if c2 > 0.0 => 4,
            (_, false) => 5,
        }
    }

    /// The lattice directions round a vertex, counterclockwise from +x, as index steps.
    fn steps(self) -> &'static [(i32, i32)] {
        match self {
            Lattice::Square => &[(1, 0), (0, 1), (-1, 0), (0, -1)],
            Lattice::Triangle | Lattice::Hexagon => {
                &[(1, 0), (0, 1), (-1, 1), (-1, 0), (0, -1), (1, -1)]
            }
        }
    }

    fn position(self, (i, k): (i32, i32)) -> DVec2 {
        match self {
            Lattice::Square => DVec2::new(f64::from(i), f64::from(k)),
            _ => DVec2::new(f64::from(i) + 0.5 * f64::from(k), ROOT3_2 * f64::from(k)),
        }
    }

    /// Where `q` is among the squares or triangles of the lattice: the first vertex `(i,
    /// k)` of the square (its lower left corner) or triangle (the corner from which it
    /// points up, or the one left of where it points down), and whether it points down.
    fn locate(self, q: DVec2) -> ((i32, i32), bool) {
        if self == Lattice::Square {
            return ((floor_whole_i32(q.x).1, floor_whole_i32(q.y).1), false);
        }
        let b = q.y / ROOT3_2;
        let a = q.x - 0.5 * b;
        let ((i, whole_i), (k, whole_k)) = (floor_whole_i32(a), floor_whole_i32(b));
        ((whole_i, whole_k), (a - i) + (b - k) >= 1.0)
    }

    /// The corners of the cell that holds the square or triangle whose first vertex is
    /// `(i, k)` (see `locate`), counterclockwise. A hexagon is the six triangles round a vertex whose
    /// `i - k` is 1 modulo 3.
    fn corners(self, (i, k): (i32, i32), down: bool) -> Vec<(i32, i32)> {
        match (self, down) {
            (Lattice::Square, _) => vec![(i, k), (i + 1, k), (i + 1, k + 1), (i, k + 1)],
            (Lattice::Triangle, false) => vec![(i, k), (i + 1, k), (i, k + 1)],
            (Lattice::Triangle, true) => vec![(i + 1, k), (i + 1, k + 1), (i, k + 1)],
            (Lattice::Hexagon, _) => {
                let triangle = Lattice::Triangle.corners((i, k), down);
                let (ci, ck) = triangle
                    .into_iter()
                    .find(|(i, k)| (i - k).rem_euclid(3) == 1)
                    .unwrap_or((i, k));
                self.steps()
                    .iter()
                    .map(|(di, dk)| (ci + di, ck + dk))
                    .collect()
            }
        }
    }
}

/// How far beyond the ramp a corner's term must stay over a whole square or triangle to
/// be left out of it: far above the rounding of a point's offset from a corner, even a
/// hundred million units out, so a term left out is one that could only give the ramp's
/// end.
const UNREACHED: f64 = 1e-6;

impl Lattice {
    /// The ramp's width: half a square, or a triangle's inradius.
    fn ramp(self) -> f64 {
        match self {
            Lattice::Square => 0.5,
            _ => ROOT3_2 / 3.0,
        }
    }

    /// The corners' positions of the square or triangle whose first vertex is `(i, k)`,
    /// and how many there are.
    fn outline(self, (i, k): (i32, i32), down: bool) -> ([DVec2; 4], usize) {
        let corners = match (self, down) {
            (Lattice::Square, _) => [(i, k), (i + 1, k), (i + 1, k + 1), (i, k + 1)],
            (_, false) => [(i, k), (i + 1, k), (i, k + 1), (i, k)],
            (_, true) => [(i + 1, k), (i + 1, k + 1), (i, k + 1), (i + 1, k)],
        };
        let count = if self == Lattice::Square { 4 } else { 3 };
        (corners.map(|c| self.position(c)), count)
    }

    /// The least each of a corner's terms (its distances to the three lattice lines
    /// through it, and the largest of them) can be over the convex polygon `outline`, or
    /// a lower bound of it.
    fn lowest(self, corner: DVec2, outline: &[DVec2]) -> [f64; 4] {
        let mut low = [f64::INFINITY; 3];
        let mut high = [f64::NEG_INFINITY; 3];
        // The Euclidean distance from the corner to the polygon's edges.
        let mut euclidean = f64::INFINITY;
        for (n, &a) in outline.iter().enumerate() {
            for (line, value) in self.across(a - corner).into_iter().enumerate() {
                low[line] = low[line].min(value);
                high[line] = high[line].max(value);
            }
            let b = outline[(n + 1) % outline.len()];
            let t = ((corner - a).dot(b - a) / (b - a).length_squared()).clamp(0.0, 1.0);
            euclidean = euclidean.min(corner.distance(a + (b - a) * t));
        }
        // A line through the polygon is at no distance from it.
        let line = |n: usize| {
            if low[n] <= 0.0 && high[n] >= 0.0 {
                0.0
            } else {
                low[n].abs().min(high[n].abs())
            }
        };
        // The largest distance is at least the Euclidean distance times the least of it
        // over a circle: 1/√2 for the square lattice's lines, √3/2 for the others'.
        let circle = match self {
            Lattice::Square => std::f64::consts::FRAC_1_SQRT_2,
            _ => ROOT3_2,
        };
        [line(0), line(1), line(2), euclidean * circle]
    }
}

/// Where a corner of the cell that holds a square or triangle lies from it, and what that
/// alone tells of the corner's terms there. It is the same for every square and for every
/// triangle of one kind (see [`Lattice::kind`]), whatever the layout, so a layout works it
/// out once per kind rather than for each square or triangle of its period: moving by
/// lattice steps changes its positions by roundings only, far from deciding on which side
/// of a lattice line a centre lies or whether a distance is within the ramp and
/// [`UNREACHED`].
#[derive(Debug, PartialEq)]
struct CornerPlace {
    /// The corner, in lattice steps from the square's or triangle's first vertex.
    offset: (i32, i32),
    /// The sector round the corner that holds the square or triangle.
    sector: usize,
    /// The lattice direction of the cell's edge from this corner to the next.
    next: Option<usize>,
    /// Which of the corner's terms (in the order of [`CornerTerms::skips`]) may come
    /// within the ramp of some point of the square or triangle.
    within: [bool; 4],
}

impl Lattice {
    /// How many kinds of square or triangle [`Lattice::kind`] tells apart.
    fn kinds(self) -> usize {
        match self {
            Lattice::Square => 1,
            Lattice::Triangle => 2,
            Lattice::Hexagon => 6,
        }
    }

    /// The kind of the square or triangle whose first vertex is `(i, k)`, by which the
    /// corners of the cells holding them lie alike: every square is of one kind; triangles
    /// are of two, pointing up (0) or down (1); in hexagons, each of those comes in three,
    /// by `(i - k) mod 3`, which tells which of the triangle's corners is its hexagon's
    /// centre. The kind `2r + d` holds the triangle at `(r, 0)` pointing down when `d` is 1.
    fn kind(self, (i, k): (i32, i32), down: bool) -> usize {
        match self {
            Lattice::Square => 0,
            Lattice::Triangle => usize::from(down),
            Lattice::Hexagon => 2 * (i - k).rem_euclid(3) as usize + usize::from(down),
        }
    }

    /// The places of the corners of the cell holding the square or triangle whose first
    /// vertex is `(i, k)`, in the cell's order.
    fn corner_places(self, (i, k): (i32, i32), down: bool) -> Vec<CornerPlace> {
        let (outline, count) = self.outline((i, k), down);
        let outline = &outline[..count];
        // The square's or triangle's centre tells each corner's sector.
        let third = if down { 2.0 / 3.0 } else { 1.0 / 3.0 };
        let centre = match self {
            Lattice::Square => DVec2::new(f64::from(i) + 0.5, f64::from(k) + 0.5),
            _ => {
                let (a, b) = (f64::from(i) + third, f64::from(k) + third);
                DVec2::new(a + 0.5 * b, ROOT3_2 * b)
            }
        };
        let corners = self.corners((i, k), down);
        let reach = self.ramp();
        corners
            .iter()
            .enumerate()
            .map(|(n, &corner)| {
                let next = corners[(n + 1) % corners.len()];
                let step = (next.0 - corner.0, next.1 - corner.1);
                let lowest = self.lowest(self.position(corner), outline);
                CornerPlace {
                    offset: (corner.0 - i, corner.1 - k),
                    sector: self.sector(self.across(centre - self.position(corner))),
                    next: self.steps().iter().position(|&s| s == step),
                    within: lowest.map(|lowest| lowest < reach + UNREACHED),
                }
            })
            .collect()
    }
}

/// One layout over its period, as what each corner of each cell of the period adds to
/// a point's distance from the tile edges.
struct Layout {
    lattice: Lattice,
    /// The period in lattice indices along i and along k.
    period: (i32, i32),
    /// For each square or triangle of the period (numbered by its first vertex, k major,
    /// a triangle pointing down after the one pointing up from the same vertex), where
    /// its terms start in `terms`; one past the end, where they end.
    starts: Vec<u32>,
    /// The terms of each square's or triangle's cell's corners, but those that cannot
    /// come within the ramp of any of its points.
    terms: Vec<CornerTerms>,
    /// For each vertex of the period, k major, the lattice directions (bit `d` for
    /// direction `d` of `Lattice::steps`) in which tile edges leave it.
    masks: Vec<u8>,
}

/// What a corner of a cell adds to the distance of a point in a square or triangle of
/// it, which lies in one sector round the corner: the distances to some of the lattice
/// lines through the corner (the cell's edge to the next corner where it is a tile edge,
/// and the tile edges either side of the sector where the tile's angle here is at most
/// a half turn), or, round a notch (an angle over a half turn), the largest distance to
/// those lines (so that the ramp turns sharp corners round a notch too, a hexagon's round
/// the tip of a 60 degree notch).
///
/// The terms are added to the distances rather than chosen by branches, which a point's
/// cell would make unpredictable.
struct CornerTerms {
    /// The corner, in lattice steps from the square's or triangle's first vertex.
    offset: (i32, i32),
    /// For each lattice line through the corner (as `Lattice::across` gives them), then
    /// for the farthest of them, 0 where its distance counts and infinity where not.
    skips: [f64; 4],
}

impl Layout {
    /// The layout whose edge flags are given per edge class (the first half of the
    /// lattice directions), one per vertex of the period, k major.
    fn new(lattice: Lattice, period: (i32, i32), edges: &[Vec<bool>]) -> Layout {
        let (p, q) = period;
        let steps = lattice.steps();
        let half = steps.len() / 2;
        let flag = |class: usize, (i, k): (i32, i32)| {
            edges[class][(k.rem_euclid(q) * p + i.rem_euclid(p)) as usize]
        };
        // For each vertex of the period, k major, the directions (bit `d` for direction
        // `d`) in which tile edges leave it.
        let masks: Vec<u8> = (0..q)
            .flat_map(|k| (0..p).map(move |i| (i, k)))
            .map(|(i, k)| {
                (0..steps.len())
                    .filter(|&d| {
                        if d < half {
                            flag(d, (i, k))
                        } else {
                            let (di, dk) = steps[d];
                            flag(d - half, (i + di, k + dk))
                        }
                    })
                    .fold(0u8, |mask, d| mask | 1 << d)
            })
            .collect();
        let mask = |(i, k): (i32, i32)| masks[(k.rem_euclid(q) * p + i.rem_euclid(p)) as usize];
        let shapes: &[bool] = match lattice {
            Lattice::Square => &[false],
            _ => &[false, true],
        };
        // The corners' places, worked out for one square or triangle of each kind.
        let places: Vec<Vec<CornerPlace>> = (0..lattice.kinds())
            .map(|kind| lattice.corner_places((kind as i32 / 2, 0), kind % 2 == 1))
            .collect();
        let mut terms = Vec::new();
        let mut starts = vec![0];
        for k in 0..q {
            for i in 0..p {
                for &down in shapes {
                    for place in &places[lattice.kind((i, k), down)] {
                        let edges = mask((i + place.offset.0, k + place.offset.1));
                        let mut counts = [false; 4];
                        let rule = lattice.rule(edges, place.sector);
                        match rule.angle {
                            // Where no tile edge leaves a vertex, it has no cell edge and
                            // no tile corner, and nothing counts.
                            _ if edges == 0 => {}
                            std::cmp::Ordering::Less => {
                                counts[usize::from(rule.a)] = true;
                                counts[usize::from(rule.b)] = true;
                            }
                            std::cmp::Ordering::Equal => counts[usize::from(rule.a)] = true,
                            std::cmp::Ordering::Greater => counts[3] = true,
                        }
                        // The cell's own edge from this corner to the next.
                        if let Some(d) = place.next
                            && edges >> d & 1 != 0
                        {
                            counts[d % half] = true;
                        }
                        for (count, within) in counts.iter_mut().zip(place.within) {
                            *count &= within;
                        }
                        if counts.contains(&true) {
                            terms.push(CornerTerms {
                                offset: place.offset,
                                skips: counts.map(|c| if c { 0.0 } else { f64::INFINITY }),
                            });
                        }
                    }
                    starts.push(terms.len() as u32);
                }
            }
        }
        Layout {
            lattice,
            period,
            starts,
            terms,
            masks,
        }
    }

    /// The lattice vertex `(i, k)` taken into the period, `(i mod p, k mod q)`, for
    /// [`Layout::mask_near`]: so that the masks round a cell cost one pair of integer
    /// divisions (some twenty cycles each) rather than a pair apiece.
    fn in_period(&self, (i, k): (i32, i32)) -> (i32, i32) {
        let (p, q) = self.period;
        (i.rem_euclid(p), k.rem_euclid(q))
    }

    /// The directions in which tile edges leave the lattice vertex `(di, dk)` (each -1,
    /// 0 or 1) from `base`, as bits of `Lattice::steps`; `base` is a vertex already in the
    /// period (see [`Layout::in_period`]), which a step leaves by at most one period, and
    /// one addition or subtraction takes back.
    // Out of line in WebAssembly, where the inlined copies at a dozen calls made the
    // plugin larger (what is interpreted gains nothing from inlining here).
    #[cfg_attr(target_arch = "wasm32", inline(never))]
    fn mask_near(&self, base: (i32, i32), (di, dk): (i32, i32)) -> u8 {
        let (p, q) = self.period;
        let wrap = |v: i32, n: i32| {
            if v < 0 {
                v + n
            } else if v >= n {
                v - n
            } else {
                v
            }
        };
        self.masks[(wrap(base.1 + dk, q) * p + wrap(base.0 + di, p)) as usize]
    }

    /// The distance from `q` to the tile's edges as the ramp counts it, where it is
    /// under `reach`.
    fn distance(&self, q: DVec2, reach: f64) -> f64 {
        let ((i, k), down) = self.lattice.locate(q);
        let (p, pk) = self.period;
        let place = (k.rem_euclid(pk) * p + i.rem_euclid(p)) as usize;
        let cell = match self.lattice {
            Lattice::Square => place,
            _ => 2 * place + usize::from(down),
        };
        // No distance is NaN (the point is finite), so the least and the greatest of two
        // are plain comparisons.
        let least = |a: f64, b: f64| if b < a { b } else { a };
        let greatest = |a: f64, b: f64| if b > a { b } else { a };
        let mut nearest = reach;
        let (start, end) = (self.starts[cell], self.starts[cell + 1]);
        for terms in &self.terms[start as usize..end as usize] {
            let corner = (i + terms.offset.0, k + terms.offset.1);
            let [d0, d1, d2] = self
                .lattice
                .across(q - self.lattice.position(corner))
                .map(f64::abs);
            // A square's third distance is 0.
            let farthest = greatest(greatest(d0, d1), d2);
            let [s0, s1, s2, s3] = terms.skips;
            nearest = least(nearest, least(d0 + s0, d1 + s1));
            nearest = least(nearest, least(d2 + s2, farthest + s3));
        }
        nearest
    }
}

/// How the ramp goes round the tile's corner at a vertex, for a point in one sector round
/// it: the lattice lines (indices into `Lattice::across`) of the tile edges either side
/// of the sector, and the tile's angle there against a half turn.
#[derive(Debug, Clone, Copy)]
struct CornerRule {
    a: u8,
    b: u8,
    angle: std::cmp::Ordering,
}

impl CornerRule {
    /// The rule at a vertex whose tile edges leave in the directions `mask` holds, of
    /// `count` lattice directions, for a point in `sector`.
    const fn new(count: usize, mask: u8, sector: usize) -> CornerRule {
        // The sectors from this one up to the next tile edge, and down to the last one
        // (round the whole turn when there is a single edge).
        let mut up = 1;
        while up < count && mask >> ((sector + up) % count) & 1 == 0 {
            up += 1;
        }
        let mut down = 0;
        while down < count && mask >> ((sector + count - down) % count) & 1 == 0 {
            down += 1;
        }
        if down == count {
            down = count - up;
        }
        // The tile's angle here, in sectors: twice the sectors is the full turn.
        let sectors = up + down;
        CornerRule {
            a: ((sector + up) % (count / 2)) as u8,
            b: ((sector + count - down) % (count / 2)) as u8,
            angle: if 2 * sectors < count {
                std::cmp::Ordering::Less
            } else if 2 * sectors == count {
                std::cmp::Ordering::Equal
            } else {
                std::cmp::Ordering::Greater
            },
        }
    }

    /// The rules of every mask (index) and sector of a lattice of `COUNT` directions and
    /// `MASKS` masks of them, worked out when the program is compiled: a layout asks for
    /// one at each corner of each cell of its period.
    const fn table<const COUNT: usize, const MASKS: usize>() -> [[CornerRule; COUNT]; MASKS] {
        let none = CornerRule {
            a: 0,
            b: 0,
            angle: std::cmp::Ordering::Equal,
        };
        let mut table = [[none; COUNT]; MASKS];
        let mut mask = 0;
        while mask < MASKS {
            let mut sector = 0;
            while sector < COUNT {
                table[mask][sector] = CornerRule::new(COUNT, mask as u8, sector);
                sector += 1;
            }
            mask += 1;
        }
        table
    }
}

/// [`CornerRule`]s round the square lattice's vertices and the triangle lattice's.
const SQUARE_RULES: [[CornerRule; 4]; 16] = CornerRule::table();
const TRIANGLE_RULES: [[CornerRule; 6]; 64] = CornerRule::table();

impl Lattice {
    /// The rule at a vertex whose tile edges leave in the directions `mask` holds, for a
    /// point in `sector`.
    fn rule(self, mask: u8, sector: usize) -> CornerRule {
        match self {
            Lattice::Square => SQUARE_RULES[usize::from(mask)][sector],
            _ => TRIANGLE_RULES[usize::from(mask)][sector],
        }
    }
}

/// The layout of a combination (which must pass `check`), read from `pavements.txt` the
/// first time a scene uses it: a scene uses few of them.
fn layout(pavement: &Pavement) -> &'static Layout {
    static READY: [OnceLock<Layout>; LAYOUTS] = [const { OnceLock::new() }; LAYOUTS];
    let index = index(pavement);
    READY[index].get_or_init(|| {
        let line = TABLE[LINE_STARTS[index]..].lines().next().unwrap_or("");
        read_layout(line)
    })
}

/// The layouts, a line `pavement S T P period I K | edge flags...` each, in the order of
/// [`index`], among comments.
const TABLE: &str = include_str!("pavements.txt");

/// Where each layout's line starts in [`TABLE`], found when the program is compiled, so
/// that reading a layout does not scan the lines before it.
const LINE_STARTS: [usize; LAYOUTS] = line_starts(TABLE.as_bytes());

/// The starts of the lines of `text` that begin with `pavement `, which must be
/// [`LAYOUTS`] of them.
const fn line_starts(text: &[u8]) -> [usize; LAYOUTS] {
    const HEAD: &[u8] = b"pavement ";
    let mut starts = [0; LAYOUTS];
    let (mut found, mut at) = (0, 0);
    while at < text.len() {
        let mut n = 0;
        while n < HEAD.len() && at + n < text.len() && text[at + n] == HEAD[n] {
            n += 1;
        }
        if n == HEAD.len() {
            assert!(found < LAYOUTS, "pavements.txt has too many layouts");
            starts[found] = at;
            found += 1;
        }
        while at < text.len() && text[at] != b'\n' {
            at += 1;
        }
        at += 1;
    }
    assert!(found == LAYOUTS, "pavements.txt lacks layouts");
    starts
}

/// The layout a line of `pavements.txt` gives. The text is ours and fixed (a test reads
/// it all), so a malformed line is a bug, not an input error.
fn read_layout(line: &str) -> Layout {
    let mut parts = line.split('|');
    let head: Vec<i32> = parts
        .next()
        .unwrap_or("")
        .split_whitespace()
        .filter_map(|w| w.parse().ok())
        .collect();
    let [sides, _, _, p, q] = head[..] else {
        panic!("pavements.txt: `pavement S T P period I K` expected: {line}");
    };
    let lattice = match sides {
        3 => Lattice::Triangle,
        4 => Lattice::Square,
        _ => Lattice::Hexagon,
    };
    let edges = parts
        .map(|bits| bits.trim().chars().map(|c| c == '1').collect::<Vec<_>>())
        .collect::<Vec<_>>();
    // A hexagon's period must carry hexagons onto hexagons.
    assert!(
        edges.len() == lattice.steps().len() / 2
            && edges.iter().all(|e| e.len() == (p * q) as usize)
            && (lattice != Lattice::Hexagon || (p % 3 == 0 && q % 3 == 0)),
        "pavements.txt: wrong edge flags: {line}"
    );
    Layout::new(lattice, (p, q), &edges)
}

/// Where a combination's layout is in the table: squares, triangles, then hexagons, each
/// by number of tiles and pattern.
fn index(pavement: &Pavement) -> usize {
    let (cell, starts): (usize, &[usize]) = match pavement.sides {
        4 => (0, &SQUARE_STARTS),
        3 => (1, &TRIANGLE_STARTS),
        _ => (2, &HEXAGON_STARTS),
    };
    let tiles = usize::from(pavement.tiles).clamp(1, starts.len()) - 1;
    CELL_STARTS[cell] + starts[tiles] + usize::from(pavement.pattern).max(1) - 1
}

const SQUARE_STARTS: [usize; 6] = starts(&SQUARE_PATTERNS);
const TRIANGLE_STARTS: [usize; 6] = starts(&TRIANGLE_PATTERNS);
const HEXAGON_STARTS: [usize; 5] = starts(&HEXAGON_PATTERNS);
/// Where the squares', triangles' and hexagons' layouts start.
const CELL_STARTS: [usize; 4] = starts(&[
    layouts(&SQUARE_PATTERNS),
    layouts(&TRIANGLE_PATTERNS),
    layouts(&HEXAGON_PATTERNS),
]);
/// How many layouts there are.
const LAYOUTS: usize = CELL_STARTS[3];

/// How many layouts `counts` (patterns per number of tiles) make.
const fn layouts(counts: &[u8]) -> u8 {
    let mut sum = 0;
    let mut i = 0;
    while i < counts.len() {
        sum += counts[i];
        i += 1;
    }
    sum
}

/// For each number of tiles of `counts`, how many layouts the numbers before it have;
/// one past the end, all of them.
const fn starts<const N: usize, const M: usize>(counts: &[u8; N]) -> [usize; M] {
    let mut starts = [0; M];
    let mut i = 1;
    while i < M {
        starts[i] = starts[i - 1] + counts[i - 1] as usize;
        i += 1;
    }
    starts
}

/// The value of the pavement at `p` (y is ignored), in 0..=1. The combination must pass
/// `check`.
pub fn value(pavement: &Pavement, p: DVec3) -> f64 {
    let layout = layout(pavement);
    let ramp = layout.lattice.ramp();
    // Far out (where no float resolves a cell any more) the point is held where the
    // lattice indices and their neighbours stay within i32.
    let q = DVec2::new(p.x, p.z).clamp(DVec2::splat(-1e8), DVec2::splat(1e8));
    let distance = match layout.lattice {
        _ if pavement.sharp() => layout.distance(q, ramp),
        Lattice::Square => corners::square_distance(layout, pavement, q),
        Lattice::Hexagon => corners::hexagon_distance(layout, pavement, q, ramp),
        Lattice::Triangle => corners::triangle_distance(layout, pavement, q, ramp),
    };
    1.0 - distance / ramp
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pavement of a combination with the corners' looks (`form`, `exterior`,
    /// `interior`).
    pub(super) fn pavement(
        (sides, tiles, pattern): (u8, u8, u8),
        (form, exterior, interior): (u8, u8, u8),
    ) -> Pavement {
        Pavement {
            sides,
            tiles,
            pattern,
            form,
            exterior,
            interior,
        }
    }

    /// A stream of pseudo-random numbers in 0..1 (xorshift), the same for a seed.
    pub(super) fn random_numbers(mut seed: u64) -> impl FnMut() -> f64 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    fn at(sides: u8, tiles: u8, pattern: u8, x: f64, z: f64) -> f64 {
        let pavement = pavement((sides, tiles, pattern), (0, 0, 0));
        value(&pavement, DVec3::new(x, 3.0, z))
    }

    /// `number_of_sides`, `number_of_tiles` and `pattern`.
    type Combination = (u8, u8, u8);
    /// A point's x and z, and POV-Ray's value there.
    type Sample = (f64, f64, f64);

    /// Values POV-Ray 3.7 gives at random points (read through a `color_map { [0 rgb 0]
    /// [1 rgb 1] }` pigment function and `#write`), for layouts of every cell and size.
    #[test]
    fn values_match_povrays() {
        #[rustfmt::skip]
        let cases: [(Combination, [Sample; 4]); 10] = [
            ((4, 1, 1), [(-3.714, -0.007, 0.9860000), (1.015, -4.713, 0.9700000), (-3.521, 4.282, 0.4360000), (-4.296, -3.702, 0.4080000)]),
            ((4, 4, 5), [(4.483, 1.219, 0.5620000), (-1.31, 0.114, 0.7720000), (1.628, -2.247, 0.5060000), (-3.62, 2.88, 0.2400000)]),
            ((4, 5, 7), [(1.704, 0.124, 0.7520000), (3.167, 0.491, 0.0180000), (4.809, -2.955, 0.9100000), (0.537, -0.164, 0.0740000)]),
            ((4, 6, 34), [(-1.467, 0.916, 0.0660000), (-2.647, 3.022, 0.9560000), (3.673, -3.712, 0.3460000), (-0.329, -2.229, 0.5420000)]),
            ((3, 1, 1), [(-4.169, 3.959, 0.6498109), (-0.701, -3.523, 0.7959700), (1.734, -2.978, 0.9560473), (4.014, -2.829, 0.2000565)]),
            ((3, 4, 2), [(-4.669, -2.992, 0.0000000), (-1.543, -0.311, 0.1676678), (4.061, 1.974, 0.1618634), (-1.607, -4.831, 0.0000000)]),
            ((3, 6, 12), [(-3.402, 4.964, 0.1958004), (-0.403, 1.91, 0.3835659), (-4.453, -4.659, 0.5713753), (3.459, 0.879, 0.8994727)]),
            ((6, 1, 1), [(-1.913, -1.826, 0.0000000), (-4.108, -3.273, 0.9930023), (-4.754, 3.391, 0.0000000), (-0.337, -3.728, 0.0858292)]),
            ((6, 3, 2), [(2.392, -3.043, 0.0000000), (-4.381, 0.984, 0.8473380), (3.958, -4.731, 0.0000000), (3.051, -3.098, 0.5188934)]),
            ((6, 5, 22), [(-4.071, -4.82, 0.5614849), (-2.07, 2.271, 0.0000000), (-0.068, 3.529, 0.7751854), (-2.828, -1.848, 0.6848299)]),
        ];
        for ((sides, tiles, pattern), points) in cases {
            for (x, z, povray) in points {
                let ours = at(sides, tiles, pattern, x, z);
                assert!(
                    (ours - povray).abs() < 1e-6,
                    "pavement {sides} {tiles} {pattern} at ({x}, {z}): {ours} is not {povray}"
                );
            }
        }
    }

    /// Each cell's corners add their terms separately, so a wrong term would break the
    /// ramp where cells meet: across every lattice line the value is continuous.
    #[test]
    fn values_are_continuous_across_cell_edges() {
        let mut random = random_numbers(0x2545_f491_4f6c_dd1d);
        for sides in [3, 4, 6] {
            let lattice = if sides == 4 {
                Lattice::Square
            } else {
                Lattice::Triangle
            };
            let steps = lattice.steps();
            for tiles in 1..=6 {
                for pattern in 1..=pattern_count(sides, tiles) {
                    for _ in 0..400 {
                        let vertex = ((random() * 40.0) as i32 - 20, (random() * 40.0) as i32 - 20);
                        let d = (random() * (steps.len() / 2) as f64) as usize;
                        let along = lattice.position(steps[d]) - lattice.position((0, 0));
                        let on = lattice.position(vertex) + along * (0.05 + 0.9 * random());
                        let side = along.perp() * 1e-9;
                        let (a, b) = (on + side, on - side);
                        let va = at(sides, tiles, pattern, a.x, a.y);
                        let vb = at(sides, tiles, pattern, b.x, b.y);
                        assert!(
                            (va - vb).abs() < 1e-6,
                            "pavement {sides} {tiles} {pattern} across {on}: {va} and {vb}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn the_table_has_every_combination() {
        let lines: Vec<&str> = TABLE
            .lines()
            .filter(|l| l.starts_with("pavement "))
            .collect();
        assert_eq!(lines.len(), LAYOUTS);
        for (n, line) in lines.iter().enumerate() {
            assert!(TABLE[LINE_STARTS[n]..].starts_with(line), "{line}");
            read_layout(line);
        }
        // Every combination finds its own line.
        for sides in [3, 4, 6] {
            for tiles in 1..=6 {
                for pattern in 1..=pattern_count(sides, tiles) {
                    let pavement = pavement((sides, tiles, pattern), (0, 0, 0));
                    assert!(check(&pavement).is_ok());
                    let head = format!("pavement {sides} {tiles} {pattern} ");
                    assert!(lines[index(&pavement)].starts_with(&head), "{head}");
                }
            }
        }
    }

    #[test]
    fn far_and_undefined_points_give_a_value() {
        for (x, z) in [(1e300, -1e300), (f64::NAN, 0.5), (f64::INFINITY, 3.0)] {
            for (sides, tiles, pattern) in [(3, 6, 12), (4, 6, 35), (6, 5, 22)] {
                let v = at(sides, tiles, pattern, x, z);
                assert!(v.is_nan() || (0.0..=1.0).contains(&v), "{v}");
            }
        }
    }

    /// The places of a cell's corners are the same from each square or triangle of a
    /// kind, near the origin or far out, as a layout takes them to be.
    #[test]
    fn corner_places_are_the_same_for_a_kind_everywhere() {
        for lattice in [Lattice::Square, Lattice::Triangle, Lattice::Hexagon] {
            for kind in 0..lattice.kinds() {
                let (first, down) = ((kind as i32 / 2, 0), kind % 2 == 1);
                assert_eq!(lattice.kind(first, down), kind);
                let places = lattice.corner_places(first, down);
                for (di, dk) in [(3, 0), (-6, 3), (30_000, -15_000), (-3_000_000, 6_000_000)] {
                    let moved = (first.0 + di, first.1 + dk);
                    assert_eq!(lattice.kind(moved, down), kind);
                    assert_eq!(lattice.corner_places(moved, down), places, "{moved:?}");
                }
            }
        }
    }

    #[test]
    fn combinations_povray_lacks_are_refused() {
        let refused =
            |sides, tiles, pattern| check(&pavement((sides, tiles, pattern), (0, 0, 0))).is_err();
        assert!(refused(6, 6, 1));
        assert!(refused(4, 3, 3));
        assert!(refused(3, 4, 0));
        assert!(!refused(4, 6, 35));
    }
}
