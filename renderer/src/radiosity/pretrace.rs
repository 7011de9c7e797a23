//! The pretrace: camera rays through a mosaic of blocks, from `pretrace_start` to
//! `pretrace_end` of the image size, halving each pass, take radiosity samples wherever the
//! cache does not yet cover their path well enough; a last pass at the picture's own
//! sample positions takes the few still missing, so that the picture only reads the cache.
//!
//! A pass's rays are traced in rounds, and a round's rays in units that may run on
//! different threads: a unit reads the samples of the rounds before its own and the
//! samples it took itself, and the round's new samples join the cache unit by unit, in
//! the units' order, when the round ends. Rounds and units are cut by ray counts alone,
//! so the cache, and so the picture, is the same whatever the number of threads. Units of
//! one round may take samples close to each other's, which a single unit would have
//! shared: rounds start small, while most rays still take samples, and grow with the
//! number of rays traced, as the cache fills and new samples become rare. A unit's rays
//! take more samples in one part of the picture than in another, so one unit often ends
//! well before the other: from then on, the other's gathers share their rays with the
//! idle thread (see `split`), with the results they would have had alone.

use super::Radiosity;
use super::cache::Cache;
use super::gather::{Phase, Walk};
use crate::camera::Camera;
use crate::parallel::{help_until, map_indices, threads};
use crate::tracer::{Tracer, World};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The part of the image a render covers, and where its first camera rays go.
#[derive(Debug, Clone, Copy)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    /// Inclusive pixel bounds.
    pub columns: (u32, u32),
    pub rows: (u32, u32),
    /// Whether the picture's first rays go through pixel corners (antialiasing method 2)
    /// rather than pixel centres.
    pub corners: bool,
}

/// Fills the world's radiosity caches for a render of `frame`; nothing without radiosity.
pub fn pretrace(world: &mut World, camera: &Camera, frame: &Frame) {
    let Some(radiosity) = &world.radiosity else {
        return;
    };
    let mut pretrace = Pretrace {
        world,
        radiosity,
        camera,
        frame,
        caches: radiosity.empty_caches(),
        traced: 0,
    };
    pretrace.mosaic_passes();
    pretrace.fill_pass();
    let caches = pretrace.caches;
    if let Some(radiosity) = &mut world.radiosity {
        radiosity.caches = caches;
    }
}

/// The fewest and the most rays a round holds; in between, as many as all the rounds
/// before it, so that each round reads at least half of the samples it could have read
/// had the rays gone one by one.
const ROUND_RAYS: (usize, usize) = (8, 4096);

/// How many units a round is cut into. More units would take more samples twice, on
/// one thread as on many: on radiosity-emissive two units cost a thirtieth more work than
/// one ray after another, four a sixth more, for no shorter a pretrace on two threads.
const UNITS_PER_ROUND: usize = 2;

struct Pretrace<'a> {
    world: &'a World,
    radiosity: &'a Radiosity,
    camera: &'a Camera,
    frame: &'a Frame,
    caches: Vec<Cache>,
    /// The camera rays traced so far, over all passes.
    traced: usize,
}

impl Pretrace<'_> {
    /// The pretrace passes proper: one ray per block, the blocks halving from pass to
    /// pass. With `nearest_count`'s second value (adaptive pretrace), a block whose ray
    /// found that many samples is not refined further.
    fn mosaic_passes(&mut self) {
        let settings = &self.radiosity.settings;
        let (x0, x1) = self.frame.columns;
        let (y0, y1) = self.frame.rows;
        let (columns, rows) = (f64::from(x1 - x0 + 1), f64::from(y1 - y0 + 1));
        let size = f64::from(self.frame.width.max(self.frame.height));
        let adaptive = settings.adaptive_nearest_count.map(f64::from);
        // Pixels of the region where the pretrace has seen enough, for the adaptive
        // pretrace.
        let mut settled = vec![false; (columns * rows) as usize];
        let mut fraction = settings.pretrace_start;
        loop {
            let block = (fraction * size).max(1.0);
            let (across, down) = ((columns / block).ceil(), (rows / block).ceil());
            // Each block's ray goes through its centre; blocks of one pass never settle
            // each other's centres, so which are settled is known before the pass.
            let mut blocks = Vec::new();
            let mut spots = Vec::new();
            for by in 0..down as u32 {
                for bx in 0..across as u32 {
                    let x = ((f64::from(bx) + 0.5) * block).min(columns - 0.5);
                    let y = ((f64::from(by) + 0.5) * block).min(rows - 0.5);
                    if !settled[(y as usize) * columns as usize + x as usize] {
                        blocks.push((bx, by));
                        spots.push((f64::from(x0) + x, f64::from(y0) + y));
                    }
                }
            }
            let weakest = self.trace(Phase::Pretrace, &spots);
            if let Some(adaptive) = adaptive {
                for (&block_at, weakest) in blocks.iter().zip(weakest) {
                    if weakest.is_some_and(|w| w >= adaptive) {
                        settle(
                            &mut settled,
                            columns as usize,
                            rows as usize,
                            block_at,
                            block,
                        );
                    }
                }
            }
            if fraction <= settings.pretrace_end || block <= 1.0 {
                return;
            }
            fraction /= 2.0;
        }
    }

    /// One ray through each position where the picture's first rays will go, taking a
    /// sample wherever none covers the point yet.
    fn fill_pass(&mut self) {
        let (x0, x1) = self.frame.columns;
        let (y0, y1) = self.frame.rows;
        let (offset, extra) = if self.frame.corners {
            (0.0, 1)
        } else {
            (0.5, 0)
        };
        let spots: Vec<(f64, f64)> = (y0..=y1 + extra)
            .flat_map(|y| {
                (x0..=x1 + extra).map(move |x| (f64::from(x) + offset, f64::from(y) + offset))
            })
            .collect();
        self.trace(Phase::Fill, &spots);
    }

    /// Traces a camera ray through each of `spots` (pixel coordinates) in `phase`, round
    /// by round, and adds the samples they take to the cache. Returns the weakest
    /// coverage each ray's path found, `None` where the camera sends no ray.
    fn trace(&mut self, phase: Phase, spots: &[(f64, f64)]) -> Vec<Option<f64>> {
        let mut weakest = Vec::with_capacity(spots.len());
        let mut start = 0;
        while start < spots.len() {
            let rays = self.traced.clamp(ROUND_RAYS.0, ROUND_RAYS.1);
            let round = &spots[start..(start + rays).min(spots.len())];
            let unit = round.len().div_ceil(UNITS_PER_ROUND);
            let this = &*self;
            let finished = AtomicUsize::new(0);
            let count = round.len().div_ceil(unit);
            let units = map_indices(count, |u| {
                let spots = &round[u * unit..((u + 1) * unit).min(round.len())];
                let mut tracer = Tracer::new(this.world);
                tracer.radiosity = Some(Walk::filling(this.radiosity, &this.caches, &finished));
                let weakest: Vec<Option<f64>> = {
                    let _finished = Finished(&finished);
                    spots
                        .iter()
                        .map(|&(x, y)| this.trace_one(&mut tracer, phase, x, y))
                        .collect()
                };
                // Shares the gathers of the units still running.
                if threads() > 1 {
                    help_until(|| finished.load(Ordering::Relaxed) == count);
                }
                let walk = tracer.radiosity.take().expect("the unit's walk");
                (walk.into_own_samples(), weakest)
            });
            for (own, unit_weakest) in units {
                for (cache, own) in self.caches.iter_mut().zip(&own) {
                    for sample in own.samples() {
                        cache.insert(*sample);
                    }
                }
                weakest.extend(unit_weakest);
            }
            self.traced += round.len();
            start += round.len();
        }
        weakest
    }

    /// Traces the camera ray through `(x, y)`; the weakest coverage its path found.
    fn trace_one(&self, tracer: &mut Tracer<'_>, phase: Phase, x: f64, y: f64) -> Option<f64> {
        if let Some(walk) = &mut tracer.radiosity {
            walk.phase = phase;
            walk.weakest = f64::INFINITY;
        }
        let ray = self.camera.ray(
            x,
            y,
            f64::from(self.frame.width),
            f64::from(self.frame.height),
        )?;
        tracer.trace_primary(&ray);
        tracer.radiosity.as_ref().map(|w| w.weakest)
    }
}

/// Counts a unit of a round as finished when dropped, also when its rays panic: the
/// threads sharing its gathers wait for the count.
struct Finished<'a>(&'a AtomicUsize);

impl Drop for Finished<'_> {
    fn drop(&mut self) {
        self.0.fetch_add(1, Ordering::Relaxed);
    }
}

/// Marks the pixels of block `(bx, by)` as settled.
fn settle(settled: &mut [bool], columns: usize, rows: usize, (bx, by): (u32, u32), block: f64) {
    let xs = (f64::from(bx) * block) as usize..((f64::from(bx + 1) * block) as usize).min(columns);
    let ys = (f64::from(by) * block) as usize..((f64::from(by + 1) * block) as usize).min(rows);
    for y in ys {
        for x in xs.clone() {
            settled[y * columns + x] = true;
        }
    }
}
