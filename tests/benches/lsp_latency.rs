//! From an edit to its published diagnostics, measured through `povrayst lsp` as a process:
//! a generated 5,000-line scene and the largest of Debian's example scenes, each edited 200
//! times (a space typed at the end of a middle line, then deleted), waiting each time for
//! the diagnostics of the new version. Prints the median and 99th percentile, the server's
//! CPU time per edit (which, unlike the latency, other work on a shared machine does not
//! inflate much) and its memory. Run with `cargo bench -p tests --bench lsp_latency`.

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
use tests::lsp_client::{LspProcess, uri};

const EDITS: usize = 200;
const EXAMPLES: &str = "/usr/share/doc/povray/examples";

/// Five thousand lines: a thousand spheres with their declarations, textures and finishes.
fn generated_scene() -> String {
    let mut text = String::from(
        "#version 3.7;\n#include \"colors.inc\"\ncamera { location <0, 20, -60> look_at 0 }\nlight_source { <50, 50, -50> color White }\n",
    );
    let mut lines = 4;
    let mut i = 0;
    while lines < 5000 {
        text.push_str(&format!(
            "#declare R{i} = 0.2 + mod({i}, 7) * 0.05;\nsphere {{ <mod({i}, 40) - 20, 0, div({i}, 40)>, R{i}\n  pigment {{ rgb <mod({i}, 3) / 2, 0.5, 1> }}\n  finish {{ phong 0.5 }}\n}}\n"
        ));
        lines += 5;
        i += 1;
    }
    text
}

fn largest_example() -> Option<(PathBuf, String)> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
            let path = entry.path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "pov") {
                out.push(path);
            }
        }
    }
    let mut paths = Vec::new();
    walk(Path::new(EXAMPLES), &mut paths);
    let path = paths.into_iter().max_by_key(|p| {
        (
            std::fs::metadata(p).map(|m| m.len()).unwrap_or(0),
            p.clone(),
        )
    })?;
    let bytes = std::fs::read(&path).ok()?;
    let text = String::from_utf8(bytes.clone())
        .unwrap_or_else(|_| bytes.iter().map(|&b| char::from(b)).collect());
    Some((path, text))
}

fn memory(pid: u32) -> String {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
    let field = |name: &str| {
        status
            .lines()
            .find(|l| l.starts_with(name))
            .map(|l| l[name.len()..].trim().to_owned())
            .unwrap_or_else(|| "?".to_owned())
    };
    format!("resident {} (peak {})", field("VmRSS:"), field("VmHWM:"))
}

/// CPU time the process has used, user and system, from `/proc/PID/stat` (in clock ticks
/// of 10 ms, so only sums over many edits are meaningful).
fn cpu_time(pid: u32) -> Option<Duration> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // The fields after the command name, which is in parentheses and may hold spaces.
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    let ticks: u64 = fields.get(11)?.parse::<u64>().ok()? + fields.get(12)?.parse::<u64>().ok()?;
    Some(Duration::from_millis(ticks * 10))
}

fn percentile(sorted: &[Duration], fraction: f64) -> Duration {
    let index = ((sorted.len() as f64 - 1.0) * fraction).round() as usize;
    sorted[index]
}

fn measure(label: &str, dir: &Path, name: &str, text: &str) {
    let (mut server, _) = LspProcess::start(dir, Value::Null);
    let scene = uri(dir) + "/" + name;
    let opened = Instant::now();
    server.open(&scene, "povray", 0, text);
    let first = server.diagnostics(&scene, Some(0));
    let open_time = opened.elapsed();
    let lines: Vec<&str> = text.lines().collect();
    let line = lines.len() / 2;
    let column = lines[line].encode_utf16().count() as u32;
    let mut latencies = Vec::with_capacity(EDITS);
    let cpu_before = cpu_time(server.pid());
    for version in 1..=EDITS as i64 {
        let start = Instant::now();
        if version % 2 == 1 {
            server.edit(
                &scene,
                version,
                (line as u32, column),
                (line as u32, column),
                " ",
            );
        } else {
            server.edit(
                &scene,
                version,
                (line as u32, column),
                (line as u32, column + 1),
                "",
            );
        }
        server.diagnostics(&scene, Some(version));
        latencies.push(start.elapsed());
    }
    let cpu_per_edit = match (cpu_before, cpu_time(server.pid())) {
        (Some(before), Some(after)) => format!(
            "{:.1} ms",
            (after - before).as_secs_f64() * 1e3 / EDITS as f64
        ),
        _ => "?".to_owned(),
    };
    latencies.sort();
    println!(
        "{label} ({} lines, {} diagnostics): open {:.1} ms; edit to diagnostics median {:.2} ms, p99 {:.2} ms, max {:.2} ms over {EDITS} edits; server CPU {cpu_per_edit} an edit; server {}",
        lines.len(),
        first.len(),
        open_time.as_secs_f64() * 1e3,
        percentile(&latencies, 0.5).as_secs_f64() * 1e3,
        percentile(&latencies, 0.99).as_secs_f64() * 1e3,
        latencies.last().unwrap().as_secs_f64() * 1e3,
        memory(server.pid()),
    );
    server.stop();
}

fn main() {
    let dir = tempfile::tempdir().unwrap();
    measure(
        "generated scene",
        dir.path(),
        "generated.pov",
        &generated_scene(),
    );
    match largest_example() {
        Some((path, text)) => {
            let dir = path.parent().unwrap();
            let name = path.file_name().unwrap().to_str().unwrap();
            measure(
                &format!("largest example {}", path.display()),
                dir,
                name,
                &text,
            );
        }
        None => println!(
            "largest example: skipped, {EXAMPLES} is not installed (apt-get install povray-examples)"
        ),
    }
}
