//! The pretrace: camera rays through a mosaic of blocks, from `pretrace_start` to
//! `pretrace_end` of the image size, halving each pass, take radiosity samples wherever the
//! cache does not yet cover their path well enough; a last pass at the picture's own
//! sample positions takes the few still missing, so that the picture only reads the cache.
//!
//! The passes run one ray after another in a fixed order: where one sample is taken
//! decides where the next is needed, and a fixed order makes the cache, and so the
//! picture, the same whatever the number of threads.

use super::gather::{Phase, Walk};
use crate::camera::Camera;
use crate::tracer::{Tracer, World};

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
    let caches = {
        let world: &World = world;
        let mut tracer = Tracer::new(world);
        tracer.radiosity = Some(Walk::filling(radiosity, radiosity.empty_caches()));
        mosaic_passes(&mut tracer, camera, frame);
        fill_pass(&mut tracer, camera, frame);
        tracer
            .radiosity
            .take()
            .expect("the pretrace's walk")
            .into_caches()
    };
    if let Some(radiosity) = &mut world.radiosity {
        radiosity.caches = caches;
    }
}

/// The pretrace passes proper: one ray per block, the blocks halving from pass to pass.
/// With `nearest_count`'s second value (adaptive pretrace), a block whose ray found that
/// many samples is not refined further.
fn mosaic_passes(tracer: &mut Tracer<'_>, camera: &Camera, frame: &Frame) {
    let Some(walk) = &tracer.radiosity else {
        return;
    };
    let settings = walk.radiosity_settings();
    let (x0, x1) = frame.columns;
    let (y0, y1) = frame.rows;
    let (columns, rows) = (f64::from(x1 - x0 + 1), f64::from(y1 - y0 + 1));
    let size = f64::from(frame.width.max(frame.height));
    let adaptive = settings.adaptive_nearest_count.map(f64::from);
    // Pixels of the region where the pretrace has seen enough, for the adaptive pretrace.
    let mut settled = vec![false; (columns * rows) as usize];
    let mut fraction = settings.pretrace_start;
    loop {
        let block = (fraction * size).max(1.0);
        let (across, down) = ((columns / block).ceil(), (rows / block).ceil());
        for by in 0..down as u32 {
            for bx in 0..across as u32 {
                let x = ((f64::from(bx) + 0.5) * block).min(columns - 0.5);
                let y = ((f64::from(by) + 0.5) * block).min(rows - 0.5);
                let pixel = (y as usize) * columns as usize + x as usize;
                if settled[pixel] {
                    continue;
                }
                set_phase(tracer, Phase::Pretrace);
                let Some(ray) = camera.ray(
                    f64::from(x0) + x,
                    f64::from(y0) + y,
                    f64::from(frame.width),
                    f64::from(frame.height),
                ) else {
                    continue;
                };
                tracer.trace_primary(&ray);
                let weakest = tracer.radiosity.as_ref().map_or(0.0, |w| w.weakest);
                if adaptive.is_some_and(|a| weakest >= a) {
                    settle(
                        &mut settled,
                        columns as usize,
                        rows as usize,
                        (bx, by),
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

/// One ray through each position where the picture's first rays will go, taking a sample
/// wherever none covers the point yet.
fn fill_pass(tracer: &mut Tracer<'_>, camera: &Camera, frame: &Frame) {
    let (x0, x1) = frame.columns;
    let (y0, y1) = frame.rows;
    let (offset, extra) = if frame.corners { (0.0, 1) } else { (0.5, 0) };
    for y in y0..=y1 + extra {
        for x in x0..=x1 + extra {
            set_phase(tracer, Phase::Fill);
            if let Some(ray) = camera.ray(
                f64::from(x) + offset,
                f64::from(y) + offset,
                f64::from(frame.width),
                f64::from(frame.height),
            ) {
                tracer.trace_primary(&ray);
            }
        }
    }
}

/// Sets the phase for the next camera ray and resets the coverage it will report.
fn set_phase(tracer: &mut Tracer<'_>, phase: Phase) {
    if let Some(walk) = &mut tracer.radiosity {
        walk.phase = phase;
        walk.weakest = f64::INFINITY;
    }
}
