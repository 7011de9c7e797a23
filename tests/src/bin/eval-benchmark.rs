//! Times the evaluation of the slowest scenes of Debian's povray-examples three ways: our
//! evaluator natively (CPU time of the best of three runs, with the renderer answering
//! `trace()` and `inside()` as in a render), our evaluator in wasm as Typst runs the plugin
//! (wasmi, inside a real Typst compile of a 16 x 12 render without antialiasing, minus a
//! compile that only loads the plugin), and POV-Ray 3.7's own "Parse Time" (CPU seconds,
//! `povray -D +WT1 +W16 +H12`). Prints a Markdown table.
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
use tests::workspace_root;

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
    let evaluation = analysis::check_with(name, &files, &options, &renderer::SceneGeometry);
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

/// POV-Ray's "Parse Time" in CPU seconds, the best of three runs; `None` if it fails.
fn povray_parse_seconds(scene: &Path) -> Option<f64> {
    let out = std::env::temp_dir().join("eval-benchmark-povray.png");
    (0..3)
        .map(|_| {
            let run = Command::new("povray")
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

/// The Typst side: the package installed into the target directory, and a document per
/// scene in a temporary directory with the files of the scene's own directory.
struct Typst {
    package_path: PathBuf,
}

impl Typst {
    fn install() -> Typst {
        let exe = std::env::current_exe().expect("the benchmark has a path");
        let target = exe
            .ancestors()
            .nth(2)
            .expect("the benchmark lives in TARGET/PROFILE");
        let package_path = target.join("typst-packages");
        let status = Command::new(workspace_root().join("scripts/install-package"))
            .arg(&package_path)
            .env("CARGO_TARGET_DIR", target)
            .stdout(std::process::Stdio::null())
            .status()
            .expect("cannot run scripts/install-package");
        assert!(status.success(), "scripts/install-package failed");
        Typst { package_path }
    }

    /// The compile time of `main.typ` in `dir` as the compiler reports it (Python's
    /// start-up and the import of the binding left out), the best of three fresh processes.
    fn compile_seconds(&self, dir: &Path) -> Result<f64, String> {
        let mut best = f64::INFINITY;
        for _ in 0..3 {
            let run = Command::new("python3")
                .arg(workspace_root().join("scripts/typst-compile.py"))
                .arg(dir.join("main.typ"))
                .args(["--query", "<result>", "--timings", "--root"])
                .arg(dir)
                .arg("--package-path")
                .arg(&self.package_path)
                .output()
                .map_err(|e| format!("cannot run python3: {e}"))?;
            let stderr = String::from_utf8_lossy(&run.stderr);
            if !run.status.success() {
                return Err(stderr.into_owned());
            }
            let stdout = String::from_utf8_lossy(&run.stdout);
            if stdout.trim() != "null" {
                return Err(format!("the scene failed in the plugin: {}", stdout.trim()));
            }
            let seconds = stderr
                .lines()
                .find_map(|l| l.rsplit(" in ").next()?.strip_suffix(" s")?.parse().ok())
                .ok_or_else(|| format!("no compile time in: {stderr}"))?;
            best = best.min(seconds);
        }
        Ok(best)
    }

    /// A document that renders `scene` (or, with `None`, only loads the plugin) and puts
    /// the render's error, `none` if it rendered, in `<result>`.
    fn document(scene: Option<&Path>) -> tempfile::TempDir {
        let dir = tempfile::tempdir().expect("a temporary directory");
        let call = match scene {
            None => "{ let _ = version(); none }".to_owned(),
            Some(scene) => {
                let source = scene.parent().expect("a scene lives in a directory");
                let (mut includes, mut files) = (String::new(), String::new());
                for entry in std::fs::read_dir(source).expect("the scene's directory") {
                    let path = entry.expect("a directory entry").path();
                    let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
                        continue;
                    };
                    if !path.is_file() || name.contains('"') {
                        continue;
                    }
                    std::fs::copy(&path, dir.path().join(name)).expect("copy a scene's file");
                    if std::fs::read_to_string(&path).is_ok() {
                        includes.push_str(&format!("\"{name}\": read(\"{name}\"), "));
                    } else {
                        files.push_str(&format!("\"{name}\": read(\"{name}\", encoding: none), "));
                    }
                }
                let name = scene.file_name().and_then(|n| n.to_str()).expect("UTF-8");
                // A Typst dictionary: `(:)` when empty, `("a": .., )` otherwise.
                let dictionary = |entries: String| {
                    if entries.is_empty() {
                        "(:)".to_owned()
                    } else {
                        format!("({entries})")
                    }
                };
                format!(
                    "try-render(read(\"{name}\"), width: {WIDTH}, height: {HEIGHT}, \
                     antialias: false, includes: {}, files: {}).error",
                    dictionary(includes),
                    dictionary(files)
                )
            }
        };
        let main = format!(
            "#import \"@local/povrayst:0.1.0\": try-render, version\n\
             #let result = {call}\n\
             #metadata(result) <result>\n"
        );
        std::fs::write(dir.path().join("main.typ"), main).expect("write main.typ");
        dir
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
    let typst = (!no_wasm).then(Typst::install);
    let baseline = typst.as_ref().map(|t| {
        let dir = Typst::document(None);
        t.compile_seconds(dir.path())
            .unwrap_or_else(|e| panic!("the baseline compile failed: {e}"))
    });
    println!(
        "| scene | ours native (CPU ms) | ours wasm in Typst (ms) | POV-Ray parse (CPU ms) | native / POV-Ray | wasm / POV-Ray |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for scene in &scenes {
        let native = best_native(scene).as_secs_f64() * 1000.0;
        let wasm = match (&typst, baseline) {
            (Some(t), Some(base)) => {
                let dir = Typst::document(Some(scene));
                match t.compile_seconds(dir.path()) {
                    Ok(s) => Some(((s - base) * 1000.0).max(0.0)),
                    Err(e) => {
                        eprintln!("{}: {e}", scene.display());
                        None
                    }
                }
            }
            _ => None,
        };
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
