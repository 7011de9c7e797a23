//! The speed/accuracy trade of the settings that buy precision with time: isosurface
//! accuracy, julia precision, sphere_sweep tolerance, sturm on and off, and the antialias
//! threshold and depth. Each setting is swept over a scene of the fidelity manifest; every
//! point is rendered on one thread (CPU time, the best of two runs) and compared with the
//! same scene rendered at a far stricter setting (mean channel error on the 0-255 scale,
//! and 1 - SSIM). The knee of each curve is its first value, from cheap to costly, whose
//! picture passes for the reference's: a mean error under half a grey level for the
//! geometric settings, SSIM above 0.9998 for antialiasing (whose errors sit on edges,
//! where the mean hides them). Past the knee, time buys nothing a viewer sees.
//!
//!   cargo run --release -p tests --bin speed-accuracy [OUT_DIR]
//!
//! writes OUT_DIR/speed-accuracy.csv and OUT_DIR/speed-accuracy.svg (by default
//! docs/speed-accuracy/) and prints each sweep's knee.

use plotters::prelude::*;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Duration;
use tests::cpu_time::process_cpu_time;
use tests::fidelity::{FidelityScene, manifest};
use tests::image_compare::{Picture, compare};

/// One setting swept over one scene.
struct Sweep {
    title: &'static str,
    scene: &'static str,
    /// Options replacing the scene's (a smaller picture keeps the sweep short).
    options: &'static [&'static str],
    values: &'static [&'static str],
    /// POV-Ray's default, which is ours.
    default: &'static str,
    reference: &'static str,
    /// How a point is judged against the reference.
    metric: Metric,
    /// The scene's source and extra options with the setting at a value.
    apply: fn(&str, &str) -> (String, Vec<String>),
}

/// When a point's picture counts as the reference's: geometric settings move whole
/// surfaces, which the mean error sees; antialiasing changes only edge pixels, which the
/// mean hides and SSIM shows.
#[derive(Clone, Copy)]
enum Metric {
    /// Mean channel error below half a grey level (0.5 on the 0-255 scale).
    Mean,
    /// SSIM above 0.9998.
    Ssim,
}

impl Metric {
    fn passes(self, p: &Point) -> bool {
        match self {
            Metric::Mean => p.mean_error < 0.5,
            Metric::Ssim => p.dssim < 2e-4,
        }
    }
}

/// Replaces `from` (which must occur) in the source.
fn replaced(source: &str, from: &str, to: &str) -> String {
    assert!(source.contains(from), "the scene no longer has `{from}`");
    source.replacen(from, to, 1)
}

const SWEEPS: &[Sweep] = &[
    Sweep {
        title: "isosurface accuracy (gyroid)",
        scene: "gyroid",
        options: &["+W260", "+H195", "-A"],
        values: &["0.3", "0.1", "0.03", "0.01", "0.003", "0.001", "0.0003"],
        default: "0.001",
        reference: "0.00001",
        metric: Metric::Mean,
        apply: |s, v| {
            (
                replaced(s, "accuracy 0.018", &format!("accuracy {v}")),
                vec![],
            )
        },
    },
    Sweep {
        title: "julia precision (julia)",
        scene: "julia",
        options: &["+W210", "+H158", "-A"],
        values: &["5", "10", "20", "50", "100", "200"],
        default: "20",
        reference: "2000",
        metric: Metric::Mean,
        apply: |s, v| {
            (
                replaced(s, "precision 50", &format!("precision {v}")),
                vec![],
            )
        },
    },
    Sweep {
        title: "sphere_sweep tolerance (knot)",
        scene: "knot",
        options: &["+W240", "+H160", "-A"],
        values: &["1e-1", "1e-2", "1e-3", "1e-4", "1e-6", "1e-8"],
        default: "1e-6",
        reference: "1e-12",
        metric: Metric::Mean,
        apply: |s, v| {
            let at = "  pigment { color rgb <0, 0.25, 1> }";
            (replaced(s, at, &format!("  tolerance {v}\n{at}")), vec![])
        },
    },
    Sweep {
        title: "sturm (clebsch cubic)",
        scene: "clebsch",
        options: &["+W240", "+H180", "-A"],
        values: &["off", "on"],
        default: "off",
        reference: "on",
        metric: Metric::Mean,
        apply: |s, v| {
            let source = if v == "on" {
                with_sturm(s)
            } else {
                s.to_string()
            };
            (source, vec![])
        },
    },
    Sweep {
        title: "antialias threshold (basic, depth 3)",
        scene: "basic",
        options: &["+W240", "+H150", "+AM2", "-J"],
        values: &["1.0", "0.5", "0.3", "0.2", "0.1", "0.05", "0.0"],
        default: "0.3",
        reference: "reference",
        metric: Metric::Ssim,
        apply: |s, v| {
            let options = if v == "reference" {
                vec!["+A0.0".into(), "+R5".into()]
            } else {
                vec![format!("+A{v}"), "+R3".into()]
            };
            (s.to_string(), options)
        },
    },
    Sweep {
        title: "antialias depth (basic, threshold 0.3)",
        scene: "basic",
        options: &["+W240", "+H150", "+AM2", "-J"],
        values: &["1", "2", "3", "4", "5"],
        default: "3",
        reference: "reference",
        metric: Metric::Ssim,
        apply: |s, v| {
            let options = if v == "reference" {
                vec!["+A0.0".into(), "+R5".into()]
            } else {
                vec!["+A0.3".into(), format!("+R{v}")]
            };
            (s.to_string(), options)
        },
    },
];

/// The scene with `sturm` after its cubic's coefficients, which end at the first `>`.
fn with_sturm(source: &str) -> String {
    let at = source.find("cubic {").expect("the scene has a cubic");
    let close = at
        + source[at..]
            .find('>')
            .expect("the cubic's coefficients end with '>'");
    format!("{} sturm{}", &source[..=close], &source[close + 1..])
}

/// A point of a sweep.
struct Point {
    value: String,
    cpu: Duration,
    mean_error: f64,
    dssim: f64,
}

fn scene_with(base: &FidelityScene, options: &[&str], extra: Vec<String>) -> FidelityScene {
    let mut scene = base.clone();
    scene.options = options.iter().map(|o| o.to_string()).collect();
    scene.options.extend(extra);
    scene
}

fn render(scene: &FidelityScene, source: &str) -> Picture {
    scene
        .render_with(source)
        .unwrap_or_else(|e| panic!("{}: {e}", scene.name))
}

/// Single-thread CPU time of a render, the best of two.
fn timed(scene: &FidelityScene, source: &str, pool: &rayon::ThreadPool) -> (Duration, Picture) {
    let mut best = Duration::MAX;
    let mut picture = None;
    for _ in 0..2 {
        let start = process_cpu_time().unwrap_or_default();
        let p = pool.install(|| render(scene, source));
        let used = process_cpu_time().unwrap_or_default().saturating_sub(start);
        best = best.min(used);
        picture = Some(p);
    }
    (best, picture.expect("two runs"))
}

/// The knee: the first value, in the sweep's order from cheap to costly, whose picture
/// passes for the reference's. Past it, time buys differences no viewer sees. (The order
/// rather than the measured time decides, so that timing noise between neighbours does
/// not move the knee.)
fn knee(points: &[Point], metric: Metric) -> Option<usize> {
    points.iter().position(|p| metric.passes(p))
}

fn main() {
    let out_dir = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| tests::workspace_root().join("docs/speed-accuracy"));
    std::fs::create_dir_all(&out_dir).expect("the output folder");
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    let scenes = manifest();
    let mut csv = String::from("sweep,value,default,knee,cpu_ms,mean_error,one_minus_ssim\n");
    let mut results: Vec<(&Sweep, Vec<Point>, Option<usize>)> = Vec::new();
    for sweep in SWEEPS {
        let base = scenes
            .iter()
            .find(|s| s.name == sweep.scene)
            .unwrap_or_else(|| panic!("no scene {} in scenes.txt", sweep.scene));
        let source = base.source();
        let (ref_source, ref_options) = (sweep.apply)(&source, sweep.reference);
        let reference = render(&scene_with(base, sweep.options, ref_options), &ref_source);
        let mut points = Vec::new();
        for value in sweep.values {
            let (variant, extra) = (sweep.apply)(&source, value);
            let scene = scene_with(base, sweep.options, extra);
            let (cpu, picture) = timed(&scene, &variant, &pool);
            let d = compare(&reference, &picture).expect("same size");
            eprintln!(
                "{:<40} {value:>8}: {:>9.1} ms, mean error {:.3}/255, 1-SSIM {:.5}",
                sweep.title,
                cpu.as_secs_f64() * 1000.0,
                d.mean_error,
                1.0 - d.ssim
            );
            points.push(Point {
                value: value.to_string(),
                cpu,
                mean_error: d.mean_error,
                dssim: 1.0 - d.ssim,
            });
        }
        let knee = knee(&points, sweep.metric);
        for (i, p) in points.iter().enumerate() {
            writeln!(
                csv,
                "{},{},{},{},{:.2},{:.4},{:.6}",
                sweep.title,
                p.value,
                p.value == sweep.default,
                Some(i) == knee,
                p.cpu.as_secs_f64() * 1000.0,
                p.mean_error,
                p.dssim
            )
            .expect("writing to a string");
        }
        match knee {
            Some(k) => println!(
                "{}: knee at {} (default {})",
                sweep.title, points[k].value, sweep.default
            ),
            None => println!(
                "{}: no setting within half a grey level of the reference",
                sweep.title
            ),
        }
        results.push((sweep, points, knee));
    }
    std::fs::write(out_dir.join("speed-accuracy.csv"), csv).expect("writing the CSV");
    plot(&out_dir.join("speed-accuracy.svg"), &results).expect("drawing the plot");
}

/// One panel per sweep: mean error against CPU time (log), each point labelled with its
/// value, the default drawn as a square and the knee ringed.
fn plot(
    path: &std::path::Path,
    results: &[(&Sweep, Vec<Point>, Option<usize>)],
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1200, 800)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((2, 3));
    for ((sweep, points, knee), panel) in results.iter().zip(panels.iter()) {
        let ms: Vec<f64> = points
            .iter()
            .map(|p| p.cpu.as_secs_f64() * 1000.0)
            .collect();
        let (lo, hi) = ms
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(l, h), v| (l.min(*v), h.max(*v)));
        let top = points
            .iter()
            .map(|p| p.mean_error)
            .fold(0.0f64, f64::max)
            .max(0.01);
        let mut chart = ChartBuilder::on(panel)
            .caption(sweep.title, ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(45)
            .build_cartesian_2d((lo * 0.8..hi * 1.25).log_scale(), 0.0..top * 1.15)?;
        chart
            .configure_mesh()
            .x_desc("CPU ms, one thread")
            .y_desc("mean error /255")
            .draw()?;
        let series: Vec<(f64, f64)> = ms
            .iter()
            .zip(points)
            .map(|(t, p)| (*t, p.mean_error))
            .collect();
        chart.draw_series(LineSeries::new(series.iter().copied(), BLUE))?;
        for (i, (&(t, e), p)) in series.iter().zip(points).enumerate() {
            if p.value == sweep.default {
                chart.draw_series(std::iter::once(Rectangle::new(
                    [(t * 0.96, e - top * 0.02), (t * 1.04, e + top * 0.02)],
                    RED.filled(),
                )))?;
            } else {
                chart.draw_series(std::iter::once(Circle::new((t, e), 3, BLUE.filled())))?;
            }
            if Some(i) == *knee {
                chart.draw_series(std::iter::once(Circle::new(
                    (t, e),
                    9,
                    GREEN.stroke_width(2),
                )))?;
            }
            chart.draw_series(std::iter::once(Text::new(
                p.value.clone(),
                (t, e + top * 0.05),
                ("sans-serif", 12),
            )))?;
        }
    }
    root.present()?;
    Ok(())
}
