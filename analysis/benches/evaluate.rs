//! Evaluation speed: `cargo bench -p analysis --bench evaluate`.
//!
//! 1. Evaluates every example scene of Debian's povray-examples (when installed) and
//!    prints the slowest, beside POV-Ray's own parse time for them when `povray` is
//!    installed (its "Parse Time" line; we run it at 1x1 so that tracing costs nothing).
//! 2. Measures compiled `function { }` evaluations per second on the gallery gyroid's
//!    functions, the kind isosurfaces evaluate millions of times.

use analysis::{DirectoryFiles, EvalOptions, MemoryFiles, evaluate};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

const EXAMPLES: &str = "/usr/share/doc/povray/examples";

fn scenes(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            scenes(&path, out);
        } else if path.extension().is_some_and(|e| e == "pov") {
            out.push(path);
        }
    }
}

/// The fastest of `runs` evaluations of one scene.
fn time_scene(path: &Path, runs: usize) -> Duration {
    let dir = path
        .parent()
        .expect("a scene lives in a directory")
        .to_path_buf();
    let name = path
        .file_name()
        .and_then(|n| n.to_str())
        .expect("UTF-8 names")
        .to_owned();
    let files = DirectoryFiles::new([dir]);
    (0..runs)
        .map(|_| {
            let start = Instant::now();
            let evaluation = evaluate(&name, &files, &EvalOptions::default());
            std::hint::black_box(evaluation);
            start.elapsed()
        })
        .min()
        .unwrap_or_default()
}

/// POV-Ray's own parse time for a scene, from its statistics.
fn povray_parse_time(path: &Path) -> Option<f64> {
    let output = Command::new("povray")
        .arg(format!("+I{}", path.display()))
        .args(["-O/dev/null", "+W1", "+H1", "-D", "+WT1"])
        .current_dir(path.parent()?)
        .output()
        .ok()?;
    let text = String::from_utf8_lossy(&output.stderr).into_owned()
        + &String::from_utf8_lossy(&output.stdout);
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("Parse Time:"))?;
    let seconds = line.rsplit('(').next()?.split_whitespace().next()?;
    seconds.parse().ok()
}

fn corpus() {
    let mut paths = Vec::new();
    scenes(Path::new(EXAMPLES), &mut paths);
    if paths.is_empty() {
        println!("example corpus not installed at {EXAMPLES}: skipping the scene timings");
        return;
    }
    paths.sort();
    let start = Instant::now();
    let mut timed: Vec<(Duration, PathBuf)> = paths
        .iter()
        .map(|p| (time_scene(p, 1), p.clone()))
        .collect();
    println!(
        "evaluated {} example scenes in {:.2} s",
        paths.len(),
        start.elapsed().as_secs_f64()
    );
    timed.sort_by_key(|(time, _)| std::cmp::Reverse(*time));
    println!(
        "{:<48} {:>12} {:>16}",
        "slowest scenes", "ours (ms)", "POV-Ray parse (ms)"
    );
    for (_, path) in timed.iter().take(10) {
        let ours = time_scene(path, 3).as_secs_f64() * 1e3;
        let theirs = povray_parse_time(path).map_or("-".to_owned(), |s| format!("{:.1}", s * 1e3));
        let name = path
            .strip_prefix(EXAMPLES)
            .unwrap_or(path)
            .display()
            .to_string();
        println!("{name:<48} {ours:>12.1} {theirs:>16}");
    }
}

fn functions() {
    let scene = r#"#version 3.7;
#declare K = 2.0;
#declare R = 4;
#declare Slab = function(x, y, z) {
  abs(sin(K*x)*cos(K*y) + sin(K*y)*cos(K*z) + sin(K*z)*cos(K*x)) - (0.15 + 0.32 * (x*x + y*y + z*z) / (R*R))
}
#declare SphereSD = function(x, y, z) { sqrt(x*x + y*y + z*z) - R }
#declare SmoothMax = function(a, b, k) { (a + b + sqrt((a - b)*(a - b) + k*k)) / 2 }
#declare Gyroid = function { SmoothMax(Slab(x, y, z), SphereSD(x, y, z), 0.25) }
"#;
    let files = MemoryFiles::new().with("gyroid.pov", scene);
    let gyroid = analysis::eval::declared_function("gyroid.pov", &files, "Gyroid")
        .expect("the scene declares Gyroid");
    let n = 2_000_000;
    let start = Instant::now();
    let mut sum = 0.0;
    for i in 0..n {
        let t = i as f64 * 1e-6;
        sum += gyroid.eval(&[t, 0.5 - t, 1.0 + t]);
    }
    std::hint::black_box(sum);
    let per_second = n as f64 / start.elapsed().as_secs_f64();
    println!(
        "gyroid function: {:.1} million evaluations per second natively",
        per_second / 1e6
    );
}

fn main() {
    functions();
    corpus();
}
