//! POV-Ray 3.7's solid noise, value for value: the tables and the blend were recovered by
//! probing POV-Ray's `f_noise_generator`, `vturbulence` and patterns (max error 1.7e-11
//! over 120 000 points up to ±1e5, for generators 1 and 2 and the vector noise; generator
//! 3, a noise of its own, in [`improved`]). Each lattice point (cell coordinates offset by
//! 10 000 and taken modulo 4096) hashes to one of 256 corners through [`tables::HASH`]; a
//! corner carries a value and a gradient from [`tables::COEFFICIENTS`], and a point blends
//! the value plus gradient·offset of its cell's eight corners by the weights 3t² − 2t³ of
//! its position in the cell.

mod improved;
mod improved_tables;
mod tables;

use crate::floor::{ROUNDER, ROUNDS_BELOW, floor_whole};
use glam::DVec3;
use std::cell::RefCell;
use std::ops::{Add, Mul, Sub};
use tables::{COEFFICIENTS, HASH};

/// POV-Ray shifts every coordinate by this much before finding its cell, so the lattice's
/// wrap every 4096 cells falls at −10 000 + 4096·n.
const LATTICE_OFFSET: f64 = 10_000.0;

/// Generator 2's range correction (POV-Ray 3.7's default): the original noise moved and
/// scaled so that it fills 0..1 more evenly, then clipped to it. Measured: exact in double.
const RANGE_SHIFT: f64 = 0.55242;
const RANGE_SCALE: f64 = 0.48985582;

/// For each of the 256 hashes, its corners' coefficients for the noise: the value (half
/// the table's entry) and the gradient, from [`COEFFICIENTS`] at the hash. Ready-made so
/// that a corner costs one lookup, bounds checked by the mask of its index.
static CORNERS: [[f64; 4]; 256] = corners();

/// The same for the vector noise, whose second and third components take the coefficients
/// four and eight entries further: entry `a` of a hash holds the three components'
/// coefficients `a` side by side, so that a corner's three values are four vector
/// operations.
static VECTOR_CORNERS: [[DVec3; 4]; 256] = vector_corners();

const fn coefficient(hash: usize, component: usize, a: usize) -> f64 {
    let c = COEFFICIENTS[hash + 4 * component + a];
    if a == 0 { 0.5 * c } else { c }
}

const fn corners() -> [[f64; 4]; 256] {
    let mut table = [[0.0; 4]; 256];
    let mut hash = 0;
    while hash < 256 {
        let mut a = 0;
        while a < 4 {
            table[hash][a] = coefficient(hash, 0, a);
            a += 1;
        }
        hash += 1;
    }
    table
}

const fn vector_corners() -> [[DVec3; 4]; 256] {
    let mut table = [[DVec3::ZERO; 4]; 256];
    let mut hash = 0;
    while hash < 256 {
        let mut a = 0;
        while a < 4 {
            table[hash][a] = DVec3::new(
                coefficient(hash, 0, a),
                coefficient(hash, 1, a),
                coefficient(hash, 2, a),
            );
            a += 1;
        }
        hash += 1;
    }
    table
}

/// POV-Ray's hash of an integer cube, 0..4096: the lattice hash applied to each coordinate
/// (taken modulo 4096) in turn, x first, each result xor the next. The cell patterns
/// (cells, crackle) number their cubes by it, without the noise's lattice offset.
pub fn cube_hash(x: i64, y: i64, z: i64) -> usize {
    let hx = usize::from(HASH[lattice(x, 0)]);
    let hxy = usize::from(HASH[(hx ^ lattice(y, 0)) & 4095]);
    usize::from(HASH[(hxy ^ lattice(z, 0)) & 4095])
}

fn s_curve(t: f64) -> f64 {
    t * t * (3.0 - 2.0 * t)
}

/// A corner's contribution from its coefficients `c` (a value and a gradient, each an
/// `f64` for the noise or a `DVec3` for the vector noise): value plus gradient dotted with
/// the point's offset `d` from the corner. `ON_Y_PLANE`, for a point on a plane of the
/// lattice across y, leaves out the y term: `d.y` is 0 there, and adding a zero leaves the
/// sum as it is (but for the sign of a zero, which no sum of octaves or offset of a point
/// keeps). A floor at y = 0 with a bumpy normal takes this way at every octave, and skips
/// a third of its corners' work.
#[inline(always)]
fn corner_value<T, const ON_Y_PLANE: bool>(c: &[T; 4], d: DVec3) -> T
where
    T: Copy + Add<Output = T> + Mul<f64, Output = T>,
{
    let sum = c[0] + c[1] * d.x;
    let sum = if ON_Y_PLANE { sum } else { sum + c[2] * d.y };
    sum + c[3] * d.z
}

/// The blend of the eight corners of the cell around `p`, each corner's coefficients found
/// in `table` at its hash (0..256). One blend serves one noise ([`signed`], from
/// [`CORNERS`]) and three sharing their hashes ([`vector`], from [`VECTOR_CORNERS`]).
///
/// A blend whose weight is 0 keeps its near end without finding its far one: the blend
/// would add a zero to it, which leaves it as it is (but for the sign of a zero, as in
/// [`corner_value`]). Points on a plane of the lattice take this way along its axis: a
/// floor at y = 0, say, whose rounding errors vanish against [`LATTICE_OFFSET`] at every
/// octave, blends four corners instead of eight. The parts are functions inlined by force,
/// not closures, which the compiler kept out of line and the interpreted plugin paid a
/// call for each.
#[inline(always)]
fn blend_cell<T>(p: DVec3, table: &'static [[T; 4]; 256]) -> T
where
    T: Copy + Add<Output = T> + Sub<Output = T> + Mul<f64, Output = T>,
{
    let cell = Cell::around(p);
    if cell.t.y == 0.0 {
        // The y weight is then 0 too, known here so that its test folds away.
        let s = DVec3::new(s_curve(cell.t.x), 0.0, s_curve(cell.t.z));
        cell.blend::<T, true, _>(s, Lattice(table))
    } else {
        let s = DVec3::new(s_curve(cell.t.x), s_curve(cell.t.y), s_curve(cell.t.z));
        cell.blend::<T, false, _>(s, Lattice(table))
    }
}

/// [`blend_cell`] of the vector noise with its corners taken from `known` when `p` lies in
/// the cell whose corners it holds, and kept there otherwise: the same corners, so the
/// same value.
#[inline(always)]
fn blend_cell_known(p: DVec3, known: &mut KnownCell) -> DVec3 {
    let cell = Cell::around(p);
    if cell.t.y == 0.0 {
        let s = DVec3::new(s_curve(cell.t.x), 0.0, s_curve(cell.t.z));
        let corners = known.corners(&cell, 1);
        cell.blend::<DVec3, true, _>(s, corners)
    } else {
        let s = DVec3::new(s_curve(cell.t.x), s_curve(cell.t.y), s_curve(cell.t.z));
        let corners = known.corners(&cell, 2);
        cell.blend::<DVec3, false, _>(s, corners)
    }
}

/// Where a blend finds its corners' coefficients: each corner's through its face's (the
/// corners at one x) and its edge's (at one x and y), so that the lattice's hashes of x
/// and of x and y are each found once for the corners that share them. Each step takes
/// the cell's coordinate along its axis.
trait Corners<T: 'static>: Copy {
    type Face: Copy;
    type Edge: Copy;
    fn face(self, x: i64, i: i64) -> Self::Face;
    fn edge(self, y: i64, face: Self::Face, j: i64) -> Self::Edge;
    fn corner(self, z: i64, edge: Self::Edge, k: i64) -> &'static [T; 4];
}

/// The corners found from the lattice, in a table of coefficients: the hash of x, then of
/// that xor y, then of that xor z picks the corner's entry.
struct Lattice<T: 'static>(&'static [[T; 4]; 256]);

impl<T> Clone for Lattice<T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T> Copy for Lattice<T> {}

impl<T> Corners<T> for Lattice<T> {
    type Face = usize;
    type Edge = usize;

    #[inline(always)]
    fn face(self, x: i64, i: i64) -> usize {
        usize::from(HASH[lattice(x, i)])
    }

    #[inline(always)]
    fn edge(self, y: i64, hx: usize, j: i64) -> usize {
        usize::from(HASH[(hx ^ lattice(y, j)) & 4095])
    }

    #[inline(always)]
    fn corner(self, z: i64, hxy: usize, k: i64) -> &'static [T; 4] {
        &self.0[usize::from(HASH[(hxy ^ lattice(z, k)) & 4095]) & 255]
    }
}

/// A cell's corners in [`VECTOR_CORNERS`], by x, y and z offset.
type KnownCorners = [[[&'static [DVec3; 4]; 2]; 2]; 2];

impl Corners<DVec3> for &KnownCorners {
    type Face = usize;
    type Edge = (usize, usize);

    #[inline(always)]
    fn face(self, _: i64, i: i64) -> usize {
        i as usize
    }

    #[inline(always)]
    fn edge(self, _: i64, i: usize, j: i64) -> (usize, usize) {
        (i, j as usize)
    }

    #[inline(always)]
    fn corner(self, _: i64, (i, j): (usize, usize), k: i64) -> &'static [DVec3; 4] {
        self[i][j][k as usize]
    }
}

/// The corners of the last cell an octave of [`turbulence`] met. Neighbouring pixels and
/// a pixel's antialiasing samples mostly fall in one cell at each octave but the finest
/// (caustic.pov: 88% of its octaves), and then find their corners without the three
/// dependent table lookups of each.
#[derive(Clone, Copy)]
struct KnownCell {
    x: i64,
    y: i64,
    z: i64,
    /// How many rows along y of `corners` hold the cell's: 0, 1 (a cell met on one of the
    /// lattice's y planes, which blends only those) or 2.
    rows: i64,
    corners: KnownCorners,
}

impl KnownCell {
    const NONE: KnownCell = KnownCell {
        x: 0,
        y: 0,
        z: 0,
        rows: 0,
        corners: [[[&VECTOR_CORNERS[0]; 2]; 2]; 2],
    };

    /// `cell`'s corners in its first `rows` rows along y, found here when they were the
    /// last ones found, and otherwise found and kept.
    #[inline(always)]
    fn corners(&mut self, cell: &Cell, rows: i64) -> &KnownCorners {
        let known = self.x == cell.x && self.y == cell.y && self.z == cell.z;
        if !(known && self.rows >= rows) {
            self.find(cell.x, cell.y, cell.z, rows);
        }
        &self.corners
    }

    /// The corners of the cell at `x`, `y`, `z`, kept. Out of line, with the coordinates
    /// passed as they are rather than the cell by reference, which would keep the cell in
    /// memory at every octave: a cell changes at few samples.
    #[inline(never)]
    fn find(&mut self, x: i64, y: i64, z: i64, rows: i64) {
        let lattice = Lattice(&VECTOR_CORNERS);
        for i in 0..2 {
            let hx = lattice.face(x, i);
            for j in 0..rows {
                let hxy = lattice.edge(y, hx, j);
                for k in 0..2 {
                    self.corners[i as usize][j as usize][k as usize] = lattice.corner(z, hxy, k);
                }
            }
        }
        (self.x, self.y, self.z, self.rows) = (x, y, z, rows);
    }
}

/// How many octaves of [`turbulence`] keep their last cell's corners; finer ones (rarely
/// asked for: POV-Ray's default is 6) find theirs each time.
const KNOWN_OCTAVES: usize = 8;

thread_local! {
    /// This thread's last cells of the octaves of [`turbulence`]: corners are a function
    /// of the cell alone, so whether they come from here or are found again changes no
    /// value, and no render depends on which thread traced what.
    static KNOWN_CELLS: RefCell<[KnownCell; KNOWN_OCTAVES]> =
        const { RefCell::new([KnownCell::NONE; KNOWN_OCTAVES]) };
}

/// A lattice cell: its coordinates and a point's fractions in it.
struct Cell {
    x: i64,
    y: i64,
    z: i64,
    t: DVec3,
}

impl Cell {
    /// The cell around `p`.
    #[inline(always)]
    fn around(p: DVec3) -> Cell {
        let q = p + DVec3::splat(LATTICE_OFFSET);
        if !cfg!(target_arch = "wasm32") && q.abs().cmplt(DVec3::splat(ROUNDS_BELOW)).all() {
            return Cell::around_rounding(q);
        }
        let (fx, x) = floor_whole(q.x);
        let (fy, y) = floor_whole(q.y);
        let (fz, z) = floor_whole(q.z);
        Cell {
            x,
            y,
            z,
            t: q - DVec3::new(fx, fy, fz),
        }
    }

    /// The cell around `q` (offset already), each coordinate under 2^51 in size: the
    /// floors of [`floor_whole`] with one test of the range for all three, not one each,
    /// and without its care for the sign of a zero (a floor of +0.0 for -0.0), which only
    /// turns the sign of a zero fraction, and no blend keeps that.
    #[inline(always)]
    fn around_rounding(q: DVec3) -> Cell {
        let floor = |x: f64| {
            let nearest = (x + ROUNDER) - ROUNDER;
            // A choice between two floats, a compare and a mask: no branch to mispredict.
            let floor = if nearest > x { nearest - 1.0 } else { nearest };
            let whole = (floor + ROUNDER).to_bits().wrapping_sub(ROUNDER.to_bits()) as i64;
            (floor, whole)
        };
        let ((fx, x), (fy, y), (fz, z)) = (floor(q.x), floor(q.y), floor(q.z));
        Cell {
            x,
            y,
            z,
            t: q - DVec3::new(fx, fy, fz),
        }
    }

    /// The blend over x, y and z (weights `s`) of the cell's corners, found in `corners`.
    #[inline(always)]
    fn blend<T, const ON_Y_PLANE: bool, C: Corners<T>>(&self, s: DVec3, corners: C) -> T
    where
        T: Copy + Add<Output = T> + Sub<Output = T> + Mul<f64, Output = T> + 'static,
    {
        let near = self.face::<T, ON_Y_PLANE, C>(s, corners, 0);
        if s.x == 0.0 {
            return near;
        }
        let far = self.face::<T, ON_Y_PLANE, C>(s, corners, 1);
        near + (far - near) * s.x
    }

    /// The blend over y and z (weights `s.y` and `s.z`) of the corners of the face at x
    /// offset `i` (0 or 1).
    #[inline(always)]
    fn face<T, const ON_Y_PLANE: bool, C: Corners<T>>(&self, s: DVec3, corners: C, i: i64) -> T
    where
        T: Copy + Add<Output = T> + Sub<Output = T> + Mul<f64, Output = T> + 'static,
    {
        let face = corners.face(self.x, i);
        let near = self.edge::<T, ON_Y_PLANE, C>(corners, face, s.z, i, 0);
        if s.y == 0.0 {
            return near;
        }
        let far = self.edge::<T, ON_Y_PLANE, C>(corners, face, s.z, i, 1);
        near + (far - near) * s.y
    }

    /// The blend along z (weight `sz`) of the two corners at x offset `i` and y offset
    /// `j`, on the face `face` of `corners`.
    #[inline(always)]
    fn edge<T, const ON_Y_PLANE: bool, C: Corners<T>>(
        &self,
        corners: C,
        face: C::Face,
        sz: f64,
        i: i64,
        j: i64,
    ) -> T
    where
        T: Copy + Add<Output = T> + Sub<Output = T> + Mul<f64, Output = T> + 'static,
    {
        let edge = corners.edge(self.y, face, j);
        let d = self.t - DVec3::new(i as f64, j as f64, 0.0);
        let near = corner_value::<T, ON_Y_PLANE>(corners.corner(self.z, edge, 0), d);
        if sz == 0.0 {
            return near;
        }
        let far = corner_value::<T, ON_Y_PLANE>(corners.corner(self.z, edge, 1), d - DVec3::Z);
        near + (far - near) * sz
    }
}

/// A cell coordinate `step` further, modulo 4096 (two's complement wraps negatives as
/// rem_euclid does); the masks also spare the table lookups their bounds checks.
#[inline(always)]
fn lattice(c: i64, step: i64) -> usize {
    (c.wrapping_add(step) & 4095) as usize
}

/// POV-Ray's original noise less 0.5: roughly −1..1, 0 on average.
pub fn signed(p: DVec3) -> f64 {
    signed_inline(p)
}

/// [`signed`], inlined into the noises built on it: granite and wrinkles call
/// [`octave_noise`] for each octave, and the call of `signed` inside it passed the point
/// through memory again.
#[inline(always)]
fn signed_inline(p: DVec3) -> f64 {
    // A coordinate that is not finite makes the fractions, and with them the blend, NaN:
    // one test of the result instead of one per coordinate.
    let value = blend_cell(p, &CORNERS);
    if value.is_nan() { 0.0 } else { value }
}

/// The noise of POV-Ray's `noise_generator` before its clipping to 0..1: 1 the original
/// noise, 2 the range-corrected one, 3 the one POV-Ray calls Perlin's improved noise.
#[inline(always)]
fn unclipped(p: DVec3, generator: u8) -> f64 {
    match generator {
        3 => improved::unclipped(p),
        // One copy of the blend for generators 1 and 2.
        _ => {
            let original = signed_inline(p) + 0.5;
            if generator == 1 {
                original
            } else {
                (original + RANGE_SHIFT) * RANGE_SCALE
            }
        }
    }
}

/// POV-Ray's noise by `noise_generator` (see [`unclipped`]), 0..1.
pub fn noise_with_generator(p: DVec3, generator: u8) -> f64 {
    unclipped(p, generator).clamp(0.0, 1.0)
}

/// POV-Ray's `Noise` with its default generator (2): 0..1.
pub fn noise(p: DVec3) -> f64 {
    noise_with_generator(p, 2)
}

/// The noise the octave sums (granite, wrinkles, the scalar turbulence) add up, not
/// clipped: generator 1's noise clipped to 0..1, but the others' doubled less 0.5 (their
/// range stretched about 0.25), unclipped. Measured: each of these patterns is exact with
/// it for all three generators. Inlined into the octave loops that call it: granite takes
/// 24 of them for each bumped normal, and each call passed its point through memory.
#[inline(always)]
pub fn octave_noise(p: DVec3, generator: u8) -> f64 {
    if generator == 1 {
        noise_with_generator(p, 1)
    } else {
        2.0 * unclipped(p, generator) - 0.5
    }
}

/// POV-Ray's vector noise (`DNoise`): three noises on one lattice, the first [`signed`]
/// itself, the others taking their corners' coefficients four and eight entries further.
/// One cell's work, not three, for three values.
pub fn vector(p: DVec3) -> DVec3 {
    vector_inline(p)
}

/// [`vector`], inlined into the octave loop of [`turbulence`]: the interpreted plugin
/// pays for each call's frame and for the result passed back through memory, six times
/// for each point of the usual turbulence.
#[inline(always)]
fn vector_inline(p: DVec3) -> DVec3 {
    let value = blend_cell(p, &VECTOR_CORNERS);
    // A fraction that is NaN reaches every component through its gradient term, so the
    // first component tells for all three.
    if value.x.is_nan() { DVec3::ZERO } else { value }
}

/// [`vector_inline`] with its corners known when `p` lies in `known`'s cell.
#[inline(always)]
fn vector_known(p: DVec3, known: &mut KnownCell) -> DVec3 {
    let value = blend_cell_known(p, known);
    if value.x.is_nan() { DVec3::ZERO } else { value }
}

/// The classic turbulence displacement: octaves of vector noise, each `lambda` times finer
/// and `omega` times weaker than the last. POV-Ray keeps `omega` and `lambda` in single
/// precision: so do we, or its values at fine octaves differ by up to 3e-5.
pub fn turbulence(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> DVec3 {
    KNOWN_CELLS.with_borrow_mut(|known| {
        let (omega, lambda) = (f64::from(omega as f32), f64::from(lambda as f32));
        let mut sum = DVec3::ZERO;
        let (mut scale, mut amplitude) = (1.0, 1.0);
        for octave in 0..octaves.max(1) as usize {
            let q = p * scale;
            let value = match known.get_mut(octave) {
                Some(cell) => vector_known(q, cell),
                None => vector_inline(q),
            };
            sum += value * amplitude;
            scale *= lambda;
            amplitude *= omega;
        }
        sum
    })
}

/// POV-Ray's scalar turbulence (marble's, the spirals'): [`octave_noise`] at `p` clipped to
/// 0..1, plus that of each further octave, `lambda` times finer and `omega` times weaker
/// than the last, unclipped; `omega` and `lambda` in single precision as for
/// [`turbulence`].
pub fn scalar_turbulence(p: DVec3, octaves: u32, omega: f64, lambda: f64, generator: u8) -> f64 {
    let (omega, lambda) = (f64::from(omega as f32), f64::from(lambda as f32));
    let mut sum = octave_noise(p, generator).clamp(0.0, 1.0);
    let (mut scale, mut amplitude) = (1.0, 1.0);
    for _ in 1..octaves.max(1) {
        scale *= lambda;
        amplitude *= omega;
        sum += octave_noise(p * scale, generator) * amplitude;
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Points in several octants, near and far from the origin, across the lattice's wrap
    /// at −10 000 and on lattice points, with POV-Ray 3.7's values there, printed to 15
    /// digits by `str(f_noise_generator(x, y, z, g), 0, 15)` and
    /// `vturbulence(lambda, omega, octaves, <x, y, z>)`.
    const PROBES: [[f64; 3]; 7] = [
        [0.3, 0.7, 0.1],
        [-12.25, 3.5, 100.75],
        [1000.123, -0.001, -77.7],
        [-9876.5, 4321.25, -0.375],
        [5e4, -3.3e4, 12.5],
        [0.0, 0.0, 0.0],
        [-10000.5, 2.25, -4096.75],
    ];

    fn assert_close(ours: f64, povray: f64, at: [f64; 3]) {
        assert!(
            (ours - povray).abs() < 1e-11,
            "{at:?}: {ours} against {povray}"
        );
    }

    #[test]
    fn both_generators_give_povray_s_values() {
        let original = [
            0.25394256473603,
            0.880359546166992,
            0.539136251178147,
            0.496178312345886,
            0.29470525,
            0.0565805,
            0.470417718237305,
        ];
        let range_corrected = [
            0.395001395366071,
            0.70185539946686,
            0.534705182496997,
            0.51366198614481,
            0.414969233981455,
            0.29832243930791,
            0.501043009194064,
        ];
        for (i, at) in PROBES.into_iter().enumerate() {
            let p = DVec3::from(at);
            assert_close(noise_with_generator(p, 1), original[i], at);
            assert_close(noise_with_generator(p, 2), range_corrected[i], at);
            assert_close(noise(p), range_corrected[i], at);
        }
    }

    #[test]
    fn generator_3_gives_povray_s_values() {
        // Its gradients are measured to about 1e-10, its values to 2e-9.
        let improved = [
            0.507016502894317,
            0.398311189284258,
            0.565029615984952,
            0.405089410720213,
            0.673608897417664,
            0.511354305373036,
            0.6841505966924,
        ];
        for (i, at) in PROBES.into_iter().enumerate() {
            let ours = noise_with_generator(DVec3::from(at), 3);
            assert!((ours - improved[i]).abs() < 2e-9, "{at:?}: {ours}");
        }
        // POV-Ray's f_noise_generator is 1 here, where the blend would be 1.013.
        let p = DVec3::new(-194.4839424580785, 78.43632842411377, 266.0563016144515);
        assert_eq!(noise_with_generator(p, 3), 1.0);
    }

    #[test]
    fn generator_2_is_clipped_to_0_1() {
        // POV-Ray's f_noise3d is 1 here, where the corrected noise would be 1.029.
        let p = DVec3::new(84.03584222049425, -113.27506654123101, -90.5409127137498);
        assert!(signed(p) > 0.55, "{}", signed(p));
        assert_eq!(noise(p), 1.0);
    }

    #[test]
    fn vector_noise_and_turbulence_give_povray_s_values() {
        let one_octave = [
            [-0.24605743526397, -0.210488883555057, -0.167081377580844],
            [0.380359546166992, 0.2446112375, 0.007969196655273],
            [0.039136251178147, -0.242112409582349, 0.208623315247929],
            [-0.003821687654114, -0.087472610862732, -0.049164281433105],
            [-0.20529475, 0.09229425, 0.060372475],
            [-0.4434195, 0.3610055, -0.459716],
            [-0.029582281762695, -0.032559061669922, -0.042724117443848],
        ];
        // lambda 2.7, omega 0.6, 4 octaves: right only with both in single precision.
        let four_octaves = [
            [-0.135003282767764, -0.278917289193795, -0.120183994402154],
            [0.570812278883368, 0.015813176525148, 0.09226038243969],
            [0.173921108035367, 0.062280864326915, 0.311277855995124],
            [0.04778312334805, -0.3072214362861, -0.042287115527192],
            [-0.435375976477611, 0.102729454128611, -0.406854287996067],
            [-0.964880866675979, 0.785547996231098, -1.00034205195039],
            [0.179847305383549, -0.162386290696476, 0.14728941664174],
        ];
        for (i, at) in PROBES.into_iter().enumerate() {
            let p = DVec3::from(at);
            let (v, t) = (vector(p), turbulence(p, 4, 0.6, 2.7));
            for axis in 0..3 {
                assert_close(v[axis], one_octave[i][axis], at);
                assert_close(t[axis], four_octaves[i][axis], at);
            }
        }
    }

    /// The blend of [`blend_cell`] with every corner's y term, as points off the lattice's
    /// y planes take it.
    fn blend_with_y_terms<T>(p: DVec3, table: &'static [[T; 4]; 256]) -> T
    where
        T: Copy + Add<Output = T> + Sub<Output = T> + Mul<f64, Output = T> + 'static,
    {
        let cell = Cell::around(p);
        let s = DVec3::new(s_curve(cell.t.x), s_curve(cell.t.y), s_curve(cell.t.z));
        cell.blend::<T, false, _>(s, Lattice(table))
    }

    #[test]
    fn points_on_a_y_plane_of_the_lattice_leave_out_only_zeros() {
        for i in 0..3000 {
            let p = DVec3::new(
                i as f64 * 0.173 - 250.0,
                f64::from(i % 7) - 3.0,
                i as f64 * -0.0371 + 9.0,
            );
            assert_eq!(signed(p), blend_with_y_terms(p, &CORNERS), "{p}");
            assert_eq!(vector(p), blend_with_y_terms(p, &VECTOR_CORNERS), "{p}");
        }
    }

    /// [`turbulence`] as it was before octaves kept their cells: every octave's vector
    /// noise found from the lattice.
    fn turbulence_from_the_lattice(p: DVec3, octaves: u32, omega: f64, lambda: f64) -> DVec3 {
        let (omega, lambda) = (f64::from(omega as f32), f64::from(lambda as f32));
        let mut sum = DVec3::ZERO;
        let (mut scale, mut amplitude) = (1.0, 1.0);
        for _ in 0..octaves.max(1) {
            sum += vector(p * scale) * amplitude;
            scale *= lambda;
            amplitude *= omega;
        }
        sum
    }

    #[test]
    fn known_cells_give_the_lattice_s_corners() {
        let mut known = KnownCell::NONE;
        let points = [
            // A first cell on a y plane, again in it (known), then off the plane in the
            // same cell (a row short: found again), back on the plane (known), and on to
            // a cell across the lattice's wrap and one far out.
            DVec3::new(0.3, 0.0, 0.1),
            DVec3::new(0.7, 0.0, 0.9),
            DVec3::new(0.5, 0.25, 0.5),
            DVec3::new(0.2, 0.0, 0.6),
            DVec3::new(-10_000.5, 2.25, -4096.75),
            DVec3::new(5e4, -3.3e4, 12.5),
        ];
        for p in points {
            let cell = Cell::around(p);
            let rows = if cell.t.y == 0.0 { 1 } else { 2 };
            let corners = *known.corners(&cell, rows);
            let lattice = Lattice(&VECTOR_CORNERS);
            for i in 0..2 {
                let hx = lattice.face(cell.x, i);
                for j in 0..rows {
                    let hxy = lattice.edge(cell.y, hx, j);
                    for k in 0..2 {
                        let want = lattice.corner(cell.z, hxy, k);
                        let got = corners[i as usize][j as usize][k as usize];
                        assert!(std::ptr::eq(got, want), "{p} {i} {j} {k}");
                    }
                }
            }
        }
    }

    #[test]
    fn turbulence_with_known_cells_is_the_lattice_s() {
        // Steps of a few hundredths, as from pixel to pixel: most octaves stay in their
        // cells, the finest move on. On and off a y plane, with more octaves than are
        // kept, and two turbulences taking turns.
        for i in 0..4000 {
            let t = f64::from(i);
            let y = if i % 500 < 250 { 0.0 } else { 0.37 + t * 1e-4 };
            let p = DVec3::new(t * 0.013 - 20.0, y, (t * 0.0071).sin() * 3.0);
            for (octaves, omega, lambda) in [(6, 0.5, 2.0), (11, 0.6, 2.7), (1, 0.5, 2.0)] {
                let want = turbulence_from_the_lattice(p, octaves, omega, lambda);
                assert_eq!(turbulence(p, octaves, omega, lambda), want, "{p} {octaves}");
            }
        }
    }

    #[test]
    fn the_rounding_cell_is_the_floor_s_cell() {
        // Whole numbers, halves (where rounding goes to even), values a hair either side
        // of them, and small negatives, whose nearest whole number is a zero above them.
        let mut values = vec![
            0.0,
            -0.0,
            1e-300,
            -1e-300,
            0.3,
            -0.3,
            1e15 + 0.5,
            -1e15 - 0.5,
        ];
        for i in -40..40 {
            let x = f64::from(i) * 0.5;
            values.extend([x, x.next_up(), x.next_down()]);
        }
        for (i, &x) in values.iter().enumerate() {
            let q = DVec3::new(x, values[(i + 7) % values.len()], -x);
            let cell = Cell::around_rounding(q);
            let (fx, x) = floor_whole(q.x);
            let (fy, y) = floor_whole(q.y);
            let (fz, z) = floor_whole(q.z);
            assert_eq!((cell.x, cell.y, cell.z), (x, y, z), "{q}");
            assert_eq!(cell.t, q - DVec3::new(fx, fy, fz), "{q}");
        }
    }

    #[test]
    fn coordinates_that_are_not_finite_give_zero() {
        assert_eq!(signed(DVec3::new(f64::NAN, 0.0, 0.0)), 0.0);
        assert_eq!(vector(DVec3::new(0.0, f64::INFINITY, 0.0)), DVec3::ZERO);
        assert!(signed(DVec3::new(-0.5, 1e17, -3.0)).is_finite());
    }

    #[test]
    fn the_hash_is_a_permutation() {
        let mut sorted = HASH.to_vec();
        sorted.sort_unstable();
        assert!(sorted.iter().enumerate().all(|(i, &h)| usize::from(h) == i));
    }

    #[test]
    fn noise_has_povray_range_and_mean() {
        let mut sum = 0.0;
        let n = 20_000;
        for i in 0..n {
            let p = DVec3::new(
                i as f64 * 0.173,
                (i % 97) as f64 * 0.311,
                (i % 13) as f64 * 0.71,
            );
            let v = noise(p);
            assert!((0.0..=1.0).contains(&v));
            sum += v;
        }
        let mean = sum / n as f64;
        assert!((mean - 0.5).abs() < 0.02, "{mean}");
    }

    #[test]
    fn the_vector_s_first_component_is_the_signed_noise() {
        for i in 0..2000 {
            let p = DVec3::new(
                i as f64 * 0.137 - 90.0,
                (i % 41) as f64 * 0.29,
                i as f64 * -0.071,
            );
            assert_eq!(vector(p).x, signed(p), "{p}");
        }
    }

    /// Samples of `f` at a fixed scatter of points, and at the same points moved by
    /// `shift`.
    fn samples(f: impl Fn(DVec3) -> f64, shift: DVec3) -> (Vec<f64>, Vec<f64>) {
        let mut state = 0x9e37_79b9u32;
        let mut next = || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            f64::from(state >> 8) / f64::from(1u32 << 24)
        };
        (0..40_000)
            .map(|_| {
                let p = DVec3::new(next(), next(), next()) * 200.0 - DVec3::splat(100.0);
                (f(p), f(p + shift))
            })
            .unzip()
    }

    fn correlation(a: &[f64], b: &[f64]) -> f64 {
        let n = a.len() as f64;
        let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
        let cov: f64 = a.iter().zip(b).map(|(x, y)| (x - ma) * (y - mb)).sum();
        let va: f64 = a.iter().map(|x| (x - ma).powi(2)).sum();
        let vb: f64 = b.iter().map(|y| (y - mb).powi(2)).sum();
        cov / (va * vb).sqrt()
    }

    fn deviation(a: &[f64]) -> f64 {
        let n = a.len() as f64;
        let mean = a.iter().sum::<f64>() / n;
        (a.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / n).sqrt()
    }

    #[test]
    fn the_vector_s_components_are_alike_and_decorrelated() {
        // Each component has the scalar noise's mean (POV-Ray's are all about -0.02 over
        // 400 000 points), spread and range, and its features' size (the correlation of
        // values half a cell apart); no two components go together, at one point or half
        // a cell apart (POV-Ray's correlate by 0.03 at most).
        let half = DVec3::new(0.5, 0.3, -0.2);
        let (scalar, scalar_moved) = samples(signed, half);
        let spread = deviation(&scalar);
        let feature = correlation(&scalar, &scalar_moved);
        let component = |axis: usize| samples(|p| vector(p)[axis], half);
        let components = [component(0), component(1), component(2)];
        for (axis, (values, moved)) in components.iter().enumerate() {
            let mean = values.iter().sum::<f64>() / values.len() as f64;
            assert!(mean.abs() < 0.03, "{axis}: mean {mean}");
            let ratio = deviation(values) / spread;
            assert!((ratio - 1.0).abs() < 0.08, "{axis}: spread {ratio}");
            assert!(values.iter().all(|v| v.abs() <= 1.1), "{axis}");
            let own = correlation(values, moved);
            assert!(
                (own - feature).abs() < 0.05,
                "{axis}: {own} against {feature}"
            );
        }
        for a in 0..3 {
            for b in a + 1..3 {
                let here = correlation(&components[a].0, &components[b].0);
                let apart = correlation(&components[a].0, &components[b].1);
                assert!(
                    here.abs() < 0.04 && apart.abs() < 0.04,
                    "{a} {b}: {here} {apart}"
                );
            }
        }
    }
}
