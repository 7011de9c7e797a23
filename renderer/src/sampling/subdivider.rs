//! Method 2's subdivision of the pixels whose corners differ, a row of pixels at a time
//! and in rounds, so that the row's samples are traced together in batches (see
//! [`Sampler::trace_all`]): the interpreted plugin runs the same code for many rays in a
//! row much faster than one sample's path at a time, interleaved with the subdivision.

use super::{Compared, Sampler};
use crate::colour::Sample;
use crate::tracer::Tracer;

/// The grid points a subdivider holds at most (some 70 bytes each): a strip of columns
/// is no wider than this allows, so that a wide picture subdivided deeply is sampled in
/// strips, one after another.
const POINTS_HELD: usize = 1 << 17;

/// Method 2 for the pixels of a strip of columns, row after row from the top, whose corner
/// samples are known. Each pixel has a grid of `side` × `side` points, shared with its
/// neighbours on its edges, which would trace the very same positions (the jitter follows
/// the position): each position is traced once, and kept for every pixel that has it.
///
/// A row goes in rounds. In each, every split pixel not finished is subdivided as far as
/// its traced points go: a square whose new points are not all traced asks for those
/// that are not, and goes no deeper. At the end of the round all the points asked for are
/// traced at once. A square asks only for the points it needs, so no sample is traced
/// that one pixel after another would not trace, and a subdivision `depth` deep takes
/// `depth` rounds.
pub struct Subdivider {
    /// Points on a side of a pixel's grid.
    side: usize,
    /// Points across the strip: `side - 1` for each pixel and one more.
    across: usize,
    /// The jitter of the samples off their grid points (see [`Sampler::jittered`]).
    jitter: f64,
    /// Samples on `side` lines of the grid, in a ring: a grid line (counted from the top
    /// of the image, `side - 1` to a row of pixels) is in place `line % side`, so that a
    /// row's bottom line, which the next row has at its top, is where that row looks.
    points: Vec<Compared>,
    /// Whether each point of `points` is traced or asked for, and for which grid line:
    /// see [`asked`] and [`traced`]; 0 when it never was either.
    marks: Vec<u64>,
    /// The split pixels of the row not finished yet, by column in the strip.
    unfinished: Vec<usize>,
    /// The points asked for in the round, by place in `points` and grid line, and the
    /// image positions to trace them at.
    asked: Vec<(usize, u64)>,
    positions: Vec<(f64, f64)>,
    traced: Vec<Sample>,
}

/// The mark of a point of grid line `line` asked for in the current round.
fn asked(line: u64) -> u64 {
    2 * line + 1
}

/// The mark of a traced point of grid line `line`.
fn traced(line: u64) -> u64 {
    2 * line + 2
}

/// Where a split pixel's grid points are.
#[derive(Clone, Copy)]
struct Pixel {
    /// The place of its left column in a line of `points`.
    left: usize,
    /// Its top grid line.
    top: u64,
    /// The image position of its top-left corner.
    x: f64,
    y: f64,
}

impl Subdivider {
    /// For a strip of `columns` pixels sampled by `sampler`.
    pub fn new(sampler: &Sampler<'_>, columns: usize) -> Subdivider {
        let side = side(sampler.depth);
        let across = columns * (side - 1) + 1;
        Subdivider {
            side,
            across,
            // POV-Ray divides the jitter amount by 2^depth + 1.
            jitter: sampler.jitter / f64::from((1u32 << sampler.depth) + 1),
            points: vec![Compared::default(); across * side],
            marks: vec![0; across * side],
            unfinished: Vec::new(),
            asked: Vec::new(),
            positions: Vec::new(),
            traced: Vec::new(),
        }
    }

    /// The widest strip, in pixels, a subdivider `depth` deep samples.
    pub fn columns_held(depth: u32) -> usize {
        let side = side(depth);
        (POINTS_HELD / ((side - 1) * side)).max(1)
    }

    /// The pixels `out` of image row `y`, from column `x0` on, whose corner samples are in
    /// `top` and `bottom` (one more than the pixels). A row sampled right after the one
    /// above it takes the points on their shared line from it.
    pub fn row(
        &mut self,
        sampler: &Sampler<'_>,
        tracer: &mut Tracer<'_>,
        (x0, y): (u32, u32),
        [top, bottom]: [&[Compared]; 2],
        out: &mut [Sample],
    ) {
        let last = self.side - 1;
        let mut unfinished = std::mem::take(&mut self.unfinished);
        // Each pixel's corners from the windows of its two corner rows, without the eight
        // bounds checks of indexing them, paid for every pixel.
        for (col, ((t, b), out)) in top
            .windows(2)
            .zip(bottom.windows(2))
            .zip(out.iter_mut())
            .enumerate()
        {
            let corners = [&t[0], &t[1], &b[0], &b[1]];
            // Most pixels are not split: their corners are averaged where they lie,
            // without being copied into the grid first.
            if sampler.depth <= 1 || !differ_at_corners(corners, sampler.threshold) {
                *out = mean_of_corners(corners);
                continue;
            }
            let pixel = self.pixel((x0, y), col);
            for ((gx, gy), corner) in [(0, 0), (last, 0), (0, last), (last, last)]
                .into_iter()
                .zip(corners)
            {
                let (i, line) = self.place(pixel, gx, gy);
                self.points[i] = *corner;
                self.marks[i] = traced(line);
            }
            unfinished.push(col);
        }
        let levels = sampler.depth.saturating_sub(1);
        while !unfinished.is_empty() {
            unfinished.retain(|&col| {
                let pixel = self.pixel((x0, y), col);
                match self.square(sampler, pixel, (0, 0), last, levels) {
                    Some(mean) => {
                        out[col] = mean;
                        false
                    }
                    None => true,
                }
            });
            self.trace_asked(sampler, tracer);
        }
        self.unfinished = unfinished;
    }

    fn pixel(&self, (x0, y): (u32, u32), col: usize) -> Pixel {
        let last = self.side - 1;
        Pixel {
            left: col * last,
            top: u64::from(y) * last as u64,
            x: f64::from(x0) + col as f64,
            y: f64::from(y),
        }
    }

    /// The place in `points` of a pixel's grid point, and the point's grid line.
    fn place(&self, pixel: Pixel, gx: usize, gy: usize) -> (usize, u64) {
        let line = pixel.top + gy as u64;
        let ring = (line % self.side as u64) as usize;
        (ring * self.across + pixel.left + gx, line)
    }

    /// A traced grid point of a pixel.
    fn get(&self, pixel: Pixel, gx: usize, gy: usize) -> &Compared {
        let (i, line) = self.place(pixel, gx, gy);
        debug_assert_eq!(self.marks[i], traced(line));
        &self.points[i]
    }

    /// Whether a pixel's grid point is traced; if not, it is asked for, once however many
    /// squares want it.
    fn ready(&mut self, sampler: &Sampler<'_>, pixel: Pixel, (gx, gy): (usize, usize)) -> bool {
        let (i, line) = self.place(pixel, gx, gy);
        let mark = self.marks[i];
        if mark == traced(line) {
            return true;
        }
        if mark != asked(line) {
            self.marks[i] = asked(line);
            self.asked.push((i, line));
            let unit = 1.0 / (self.side - 1) as f64;
            let (x, y) = (pixel.x + gx as f64 * unit, pixel.y + gy as f64 * unit);
            self.positions.push(sampler.jittered(x, y, self.jitter));
        }
        false
    }

    /// Traces the points asked for in the round, all at once.
    fn trace_asked(&mut self, sampler: &Sampler<'_>, tracer: &mut Tracer<'_>) {
        self.traced.clear();
        sampler.trace_all(tracer, &self.positions, &mut self.traced);
        for (&(i, line), &s) in self.asked.iter().zip(&self.traced) {
            self.points[i] = sampler.compared(s);
            self.marks[i] = traced(line);
        }
        self.asked.clear();
        self.positions.clear();
    }

    /// The mean over a pixel's square with top-left grid point `(bx, by)` and `step`
    /// points across, subdividing while `level` allows and the corners differ; `None`
    /// while some point it needs is not traced yet (and is then asked for).
    fn square(
        &mut self,
        sampler: &Sampler<'_>,
        pixel: Pixel,
        (bx, by): (usize, usize),
        step: usize,
        level: u32,
    ) -> Option<Sample> {
        let c = [
            self.get(pixel, bx, by),
            self.get(pixel, bx + step, by),
            self.get(pixel, bx, by + step),
            self.get(pixel, bx + step, by + step),
        ];
        let split = level > 0 && step >= 2 && differ_at_corners(c, sampler.threshold);
        if !split {
            return Some(mean_of_corners(c));
        }
        let half = step / 2;
        let mut ready = true;
        for point in [
            (bx, by + half),
            (bx + half, by),
            (bx + step, by + half),
            (bx + half, by + step),
            (bx + half, by + half),
        ] {
            ready &= self.ready(sampler, pixel, point);
        }
        if !ready {
            return None;
        }
        // Every quarter is subdivided even after one is found unready, so that the round
        // asks for all their points.
        let mut sum = Some(Sample::default());
        for quarter in [
            (bx, by),
            (bx + half, by),
            (bx, by + half),
            (bx + half, by + half),
        ] {
            let part = self.square(sampler, pixel, quarter, half, level - 1);
            sum = sum.zip(part).map(|(sum, part)| sum + part);
        }
        sum.map(|sum| sum * 0.25)
    }
}

/// Points on a side of a pixel's grid, `depth` deep.
fn side(depth: u32) -> usize {
    (1usize << depth.saturating_sub(1)) + 1
}

/// Whether some two of a square's corners differ by the threshold or more. No two differ
/// by more than the corners' spread (the sum of each channel's range), which most squares
/// keep below the threshold: those need no comparing of pairs. Rounding keeps the bound,
/// since each pair's distance is the same sum of differences no larger than the ranges.
/// The ranges take plain comparisons, a handful of instructions each: a NaN skips them
/// unless it comes first, and then the spread is NaN and the pairs are compared, in which
/// a NaN never differs.
/// Inlined always: every pixel asks, and WebAssembly kept it a call, whose cost in the
/// interpreter was more than the inlined copies' (clebsch in wasmi: 1.1% of the compile).
#[inline(always)]
fn differ_at_corners(c: [&Compared; 4], threshold: f64) -> bool {
    let range = |channel: fn(&Sample) -> f64| {
        let first = channel(&c[0].encoded);
        let (mut lo, mut hi) = (first, first);
        for s in &c[1..] {
            let v = channel(&s.encoded);
            if v < lo {
                lo = v;
            }
            if v > hi {
                hi = v;
            }
        }
        hi - lo
    };
    // Summed in the order `Sample::distance` sums a pair's differences.
    let spread = range(|s| s.colour.x)
        + range(|s| s.colour.y)
        + range(|s| s.colour.z)
        + range(|s| s.transmit);
    if spread < threshold {
        return false;
    }
    (0..4).any(|i| (i + 1..4).any(|j| c[i].encoded.distance(c[j].encoded) >= threshold))
}

/// The mean of a square's corner samples.
fn mean_of_corners(c: [&Compared; 4]) -> Sample {
    (c[0].sample + c[1].sample + c[2].sample + c[3].sample) * 0.25
}
