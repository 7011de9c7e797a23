//! From a scene description and options to an image: builds the world, picks the pixels of
//! a partial render, samples them with the chosen antialiasing method (rows in parallel
//! natively, one after another on wasm32, with the same result), and encodes the colours
//! for the output file.

use crate::build::{BuildError, BuildSettings, build_world};
use crate::camera::Camera;
use crate::colour::{Curve, EncodeTable, Sample};
use crate::image::Image;
use crate::options::{Extent, Gamma, RenderOptions};
use crate::sampling::{self, CompareCurve, Compared, Sampler, Subdivider};
use crate::tracer::Tracer;
use analysis::scene::Scene;
use glam::DVec3;

/// Renders a scene. `Err` names a scene feature this renderer cannot draw yet.
pub fn render(scene: &Scene, options: &RenderOptions) -> Result<Image, BuildError> {
    let world = build_world(
        scene,
        BuildSettings {
            quality: options.quality,
            output_alpha: options.output_alpha,
            max_trace_level: options.max_trace_level,
        },
    )?;
    let camera = Camera::from_scene(&scene.camera).map_err(|message| BuildError {
        message,
        origin: scene.camera.origin.clone(),
    })?;
    let (width, height) = (options.width.max(1), options.height.max(1));
    let region = Region::from_options(options, width, height);
    let working = match scene.settings.assumed_gamma {
        Some(g) => Curve::from_gamma(Gamma::Power(g)),
        None => Curve::Identity,
    };
    let sampler = Sampler {
        world: &world,
        camera: &camera,
        width: f64::from(width),
        height: f64::from(height),
        threshold: options.aa_threshold,
        depth: options.aa_depth.clamp(1, 9),
        jitter: options.jitter_amount().max(0.0),
        compare: CompareCurve {
            working,
            aa: EncodeTable::new(Curve::Power(options.aa_gamma.unwrap_or(2.5))),
        },
    };
    let samples = if !options.antialias {
        centres(&sampler, &region)
    } else {
        match options.aa_method {
            1 => method1(&sampler, &region),
            _ => method2(&sampler, &region),
        }
    };
    let output = Output {
        // Scenes without assumed_gamma are legacy scenes: POV-Ray 3.7 turns gamma
        // handling off for them and writes working values as they are.
        legacy: scene.settings.assumed_gamma.is_none(),
        working,
        file: output_curve(Curve::from_gamma(options.file_gamma.unwrap_or(Gamma::Srgb))),
        alpha: options.output_alpha,
    };
    let mut image = Image::new(width, height, options.output_alpha);
    for (row, y) in samples.iter().zip(region.y0..=region.y1) {
        for (s, x) in row.iter().zip(region.x0..=region.x1) {
            image.set_pixel(x, y, output.pixel(*s));
        }
    }
    Ok(image)
}

/// The inclusive pixel rectangle a partial render covers.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Region {
    x0: u32,
    x1: u32,
    y0: u32,
    y1: u32,
}

impl Region {
    fn from_options(options: &RenderOptions, width: u32, height: u32) -> Region {
        let bound =
            |e: Option<Extent>, size: u32, default: u32| e.map_or(default, |e| e.resolve(size));
        let x0 = bound(options.start_column, width, 0);
        let x1 = bound(options.end_column, width, width - 1).max(x0);
        let y0 = bound(options.start_row, height, 0);
        let y1 = bound(options.end_row, height, height - 1).max(y0);
        Region { x0, x1, y0, y1 }
    }

    fn columns(&self) -> usize {
        (self.x1 - self.x0 + 1) as usize
    }
}

/// Maps `f` over `0..count`, in parallel where threads exist.
fn map_rows<T: Send>(count: usize, f: impl Fn(usize) -> T + Sync + Send) -> Vec<T> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        use rayon::prelude::*;
        (0..count).into_par_iter().map(f).collect()
    }
    #[cfg(target_arch = "wasm32")]
    {
        (0..count).map(f).collect()
    }
}

/// One ray through each pixel centre.
fn centres(sampler: &Sampler<'_>, region: &Region) -> Vec<Vec<Sample>> {
    map_rows((region.y1 - region.y0 + 1) as usize, |row| {
        let mut tracer = Tracer::new(sampler.world);
        let y = f64::from(region.y0) + row as f64 + 0.5;
        (region.x0..=region.x1)
            .map(|x| sampler.trace(&mut tracer, f64::from(x) + 0.5, y))
            .collect()
    })
}

fn method1(sampler: &Sampler<'_>, region: &Region) -> Vec<Vec<Sample>> {
    let centres = centres(sampler, region);
    let rows = centres.len();
    let cols = region.columns();
    map_rows(rows, |row| {
        let mut tracer = Tracer::new(sampler.world);
        (0..cols)
            .map(|col| {
                let c = centres[row][col];
                let mut neighbours = [c; 4];
                if col > 0 {
                    neighbours[0] = centres[row][col - 1];
                }
                if col + 1 < cols {
                    neighbours[1] = centres[row][col + 1];
                }
                if row > 0 {
                    neighbours[2] = centres[row - 1][col];
                }
                if row + 1 < rows {
                    neighbours[3] = centres[row + 1][col];
                }
                if sampling::needs_supersampling(sampler, c, &neighbours) {
                    let x = region.x0 + col as u32;
                    let y = region.y0 + row as u32;
                    sampling::supersample_grid(sampler, &mut tracer, x, y, c)
                } else {
                    c
                }
            })
            .collect()
    })
}

fn method2(sampler: &Sampler<'_>, region: &Region) -> Vec<Vec<Sample>> {
    let corner_rows = (region.y1 - region.y0 + 2) as usize;
    let corners: Vec<Vec<Compared>> = map_rows(corner_rows, |row| {
        let mut tracer = Tracer::new(sampler.world);
        let y = f64::from(region.y0) + row as f64;
        (region.x0..=region.x1 + 1)
            .map(|x| sampler.compared(sampler.trace(&mut tracer, f64::from(x), y)))
            .collect()
    });
    map_rows(corner_rows - 1, |row| {
        let mut tracer = Tracer::new(sampler.world);
        let mut subdivider = Subdivider::new(sampler.depth);
        (0..region.columns())
            .map(|col| {
                let c = [
                    corners[row][col],
                    corners[row][col + 1],
                    corners[row + 1][col],
                    corners[row + 1][col + 1],
                ];
                let x = region.x0 + col as u32;
                let y = region.y0 + row as u32;
                subdivider.pixel(sampler, &mut tracer, x, y, c)
            })
            .collect()
    })
}

/// The file's transfer curve: tabulated for sRGB, whose linear toe the table follows to
/// 16-bit precision; exact for power curves, whose slope at black a table cannot follow.
fn output_curve(curve: Curve) -> FileCurve {
    match curve {
        Curve::Srgb => FileCurve::Table(EncodeTable::new(curve)),
        other => FileCurve::Exact(other),
    }
}

enum FileCurve {
    Table(EncodeTable),
    Exact(Curve),
}

/// The conversion of averaged samples to output values.
struct Output {
    legacy: bool,
    working: Curve,
    file: FileCurve,
    alpha: bool,
}

impl Output {
    fn pixel(&self, s: Sample) -> [f32; 4] {
        let mut colour = s.colour;
        let mut alpha = 1.0;
        if self.alpha {
            alpha = (1.0 - s.transmit).clamp(0.0, 1.0);
            // Samples carry colour premultiplied by coverage; PNG wants straight alpha.
            colour = if alpha > 0.0 {
                colour / alpha
            } else {
                DVec3::ZERO
            };
        }
        let clipped = colour.clamp(DVec3::ZERO, DVec3::ONE);
        let encoded = if self.legacy {
            clipped
        } else {
            let linear = DVec3::new(
                self.working.decode(clipped.x),
                self.working.decode(clipped.y),
                self.working.decode(clipped.z),
            );
            match &self.file {
                FileCurve::Table(t) => t.encode_vec(linear),
                FileCurve::Exact(c) => c.encode_vec(linear),
            }
        };
        let finite = |v: f64| if v.is_finite() { v as f32 } else { 0.0 };
        [
            finite(encoded.x),
            finite(encoded.y),
            finite(encoded.z),
            finite(alpha),
        ]
    }
}
