//! Times the evaluation of the slowest scenes of Debian's povray-examples three ways: our
//! evaluator natively (CPU time of the best of three runs, with the renderer answering
//! `trace()` and `inside()` as in a render), our evaluator in wasm as Typst runs the plugin
//! (wasmi, inside a real Typst compile of a 16 x 12 render without antialiasing, in CPU
//! time less a compile that only loads the plugin: `tests::plugin_timing`), and POV-Ray
//! 3.7's own "Parse Time" (CPU seconds, `povray -D +WT1 +W16 +H12`). Prints a Markdown
//! table.
//!
//!   cargo run --release -p tests --bin eval-benchmark [--top N] [--no-wasm] [SCENE.pov...]
//!
//! Without scene names, every example is evaluated once natively and the `N` slowest that
//! evaluate without error (10 unless `--top` says otherwise) are benchmarked. The wasm figure
//! also holds the scene's 16 x 12 render, as POV-Ray's run does; it needs the Typst package
//! built (`scripts/install-package`, run here into the target directory) and the `typst`
//! Python module (`scripts/setup`).

use analysis::{DirectoryFiles, EvalOptions};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};
use tests::cpu_time::process_cpu_time;
use tests::example_corpus::{EXAMPLES, example_scenes};
use tests::plugin_timing::{PluginRender, PluginTimer};

const WIDTH: u32 = 16;
const HEIGHT: u32 = 12;

/// One native evaluation of `scene`, as the render pipeline runs it: the CPU time it took
/// and whether it gave a scene without errors.
fn evaluate_natively(scene: &Path) -> (Duration, bool) {
    let dir = scene.parent().expect("a scene lives in a directory");
    let name = scene
        .file_name()
        .and_then(|n| n.to_str())
        .expect("UTF-8 names");
    let files = DirectoryFiles::new([dir.to_path_buf()]);
    let options = EvalOptions {
        image_width: WIDTH,
        image_height: HEIGHT,
        ..EvalOptions::default()
    };
    let cpu_start = process_cpu_time();
    let wall_start = Instant::now();
    let evaluation = analysis::evaluate_with(name, &files, &options, &renderer::SceneGeometry);
    let wall = wall_start.elapsed();
    let time = match (cpu_start, process_cpu_time()) {
        (Some(a), Some(b)) => b.saturating_sub(a),
        _ => wall,
    };
    let ok = evaluation.scene.is_some() && !evaluation.diagnostics.iter().any(|d| d.is_error());
    (time, ok)
}

fn best_native(scene: &Path) -> Duration {
    (0..3)
        .map(|_| evaluate_natively(scene).0)
        .min()
        .expect("three runs")
}

/// POV-Ray's "Parse Time" in CPU seconds, the best of three runs; `None` if it fails. It
/// runs in the temporary directory: scenes that `#write` files (the mesh_camera demos
/// write their lens meshes) write them into POV-Ray's current directory.
fn povray_parse_seconds(scene: &Path) -> Option<f64> {
    let out = std::env::temp_dir().join("eval-benchmark-povray.png");
    let scene = std::path::absolute(scene).ok()?;
    (0..3)
        .map(|_| {
            let run = Command::new("povray")
                .current_dir(std::env::temp_dir())
                .arg(format!("+I{}", scene.display()))
                .arg(format!("+O{}", out.display()))
                .args(["+FN", "-D", "-V", "+WT1", "-A"])
                .arg(format!("+W{WIDTH}"))
                .arg(format!("+H{HEIGHT}"))
                .arg(format!("+L{}", scene.parent()?.display()))
                .output()
                .ok()?;
            let log = String::from_utf8_lossy(&run.stderr);
            parse_cpu_seconds(&log)
        })
        .collect::<Option<Vec<f64>>>()?
        .into_iter()
        .reduce(f64::min)
}

/// The "N CPU-seconds total" figure on the line after POV-Ray's "Parse Time:" line.
fn parse_cpu_seconds(log: &str) -> Option<f64> {
    let mut lines = log.lines().skip_while(|l| !l.contains("Parse Time:"));
    lines.next()?;
    let next = lines.next()?;
    let before = next.split(" CPU-seconds").next()?;
    before.split_whitespace().last()?.parse().ok()
}

/// The scene as the package receives it, at 16 x 12 without antialiasing, with every file
/// of its directory: UTF-8 texts as includes, the others as files.
fn plugin_render(scene: &Path) -> PluginRender {
    let directory = scene.parent().expect("a scene lives in a directory");
    let (mut includes, mut files) = (Vec::new(), Vec::new());
    for entry in std::fs::read_dir(directory).expect("the scene's directory") {
        let path = entry.expect("a directory entry").path();
        let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
            continue;
        };
        if !path.is_file() {
            continue;
        }
        let bytes = std::fs::read(&path).expect("a scene's file");
        match String::from_utf8(bytes) {
            Ok(text) => includes.push((name.to_owned(), text)),
            Err(binary) => files.push((name.to_owned(), binary.into_bytes())),
        }
    }
    PluginRender {
        name: scene
            .file_name()
            .and_then(|n| n.to_str())
            .expect("UTF-8 names")
            .to_owned(),
        source: std::fs::read_to_string(scene).expect("the scene's text"),
        arguments: format!("width: {WIDTH}, height: {HEIGHT}, antialias: false"),
        includes,
        files,
    }
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let no_wasm = args.iter().any(|a| a == "--no-wasm");
    args.retain(|a| a != "--no-wasm");
    let mut top = 10;
    if let Some(i) = args.iter().position(|a| a == "--top") {
        top = args
            .get(i + 1)
            .and_then(|n| n.parse().ok())
            .expect("--top takes a number");
        args.drain(i..i + 2);
    }
    let scenes: Vec<PathBuf> = if args.is_empty() {
        let all = example_scenes();
        if all.is_empty() {
            eprintln!("eval-benchmark: no scenes at {EXAMPLES} (apt-get install povray-examples)");
            std::process::exit(1);
        }
        eprintln!("eval-benchmark: evaluating {} examples once", all.len());
        let mut timed: Vec<(Duration, PathBuf)> = all
            .into_iter()
            .filter_map(|scene| {
                let (time, ok) = evaluate_natively(&scene);
                ok.then_some((time, scene))
            })
            .collect();
        timed.sort_by_key(|t| std::cmp::Reverse(t.0));
        timed.into_iter().take(top).map(|(_, s)| s).collect()
    } else {
        args.iter().map(PathBuf::from).collect()
    };
    let timer = (!no_wasm).then(|| {
        PluginTimer::new(3).unwrap_or_else(|e| panic!("the baseline compile failed: {e}"))
    });
    println!(
        "| scene | ours native (CPU ms) | ours wasm in Typst (CPU ms) | POV-Ray parse (CPU ms) | native / POV-Ray | wasm / POV-Ray |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for scene in &scenes {
        let native = best_native(scene).as_secs_f64() * 1000.0;
        let wasm = timer
            .as_ref()
            .and_then(|timer| match timer.seconds(&plugin_render(scene)) {
                Ok(s) => Some(s * 1000.0),
                Err(e) => {
                    eprintln!("{}: {e}", scene.display());
                    None
                }
            });
        let povray = povray_parse_seconds(scene).map(|s| s * 1000.0);
        let cell = |v: Option<f64>| v.map_or("-".to_owned(), |v| format!("{v:.0}"));
        let ratio = |a: Option<f64>| match (a, povray) {
            (Some(a), Some(p)) if p > 0.0 => format!("{:.2}", a / p),
            _ => "-".to_owned(),
        };
        let name = scene.strip_prefix(EXAMPLES).unwrap_or(scene);
        println!(
            "| {} | {native:.1} | {} | {} | {} | {} |",
            name.display(),
            cell(wasm),
            cell(povray),
            ratio(Some(native)),
            ratio(wasm)
        );
    }
}

#[cfg(test)]
mod povray_log {
    use super::parse_cpu_seconds;

    #[test]
    fn reads_the_cpu_seconds_of_the_parse() {
        let log = "Parser Time\n  Parse Time:       0 hours  0 minutes  2 seconds (2.345 seconds)\n              using 1 thread(s) with 2.301 CPU-seconds total\n  Bounding Time:    0 hours  0 minutes  0 seconds (0.001 seconds)\n              using 1 thread(s) with 0.001 CPU-seconds total\n";
        assert_eq!(parse_cpu_seconds(log), Some(2.301));
    }
}
