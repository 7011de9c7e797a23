//! Parse speed over real scenes: `cargo bench -p syntax`. Reports the time to lex and
//! parse the POV-Ray include folder (target: under 50 ms for its ~1 MB) and MB/s over
//! the whole corpus, falling back to the gallery when the corpus is not installed. Times
//! are CPU time of the parsing thread.

use std::fs;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

fn scene_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            scene_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "pov" || e == "inc") {
            out.push(path);
        }
    }
}

fn load(dirs: &[&Path]) -> Vec<String> {
    let mut files = Vec::new();
    for dir in dirs {
        scene_files(dir, &mut files);
    }
    files.sort();
    files
        .iter()
        .map(|f| String::from_utf8_lossy(&fs::read(f).unwrap_or_default()).into_owned())
        .collect()
}

/// CPU time this thread has used, where Linux tells it: on a shared machine wall time
/// would also measure the neighbours.
fn thread_cpu_time() -> Option<Duration> {
    let stat = fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    Some(Duration::from_nanos(
        stat.split_whitespace().next()?.parse().ok()?,
    ))
}

/// The fastest of several runs over all texts, in CPU time (wall time where Linux's
/// scheduler statistics are missing). Each run repeats the texts for at least 50 ms,
/// since the scheduler updates its statistics only every few milliseconds.
fn best_time(texts: &[String], runs: usize) -> Duration {
    (0..runs)
        .map(|_| {
            let cpu = thread_cpu_time();
            let start = Instant::now();
            let mut rounds = 0u32;
            while rounds == 0 || start.elapsed() < Duration::from_millis(50) {
                for text in texts {
                    let parse = syntax::parse(text);
                    std::hint::black_box(parse.errors().len());
                }
                rounds += 1;
            }
            let spent = match (cpu, thread_cpu_time()) {
                (Some(before), Some(after)) => after.saturating_sub(before),
                _ => start.elapsed(),
            };
            spent / rounds
        })
        .min()
        .unwrap_or_default()
}

fn report(name: &str, texts: &[String]) {
    let bytes: usize = texts.iter().map(String::len).sum();
    if bytes == 0 {
        println!("{name}: not installed, skipped");
        return;
    }
    let time = best_time(texts, 15);
    let mb = bytes as f64 / 1e6;
    println!(
        "{name}: {} files, {mb:.2} MB in {:.1} ms: {:.1} MB/s",
        texts.len(),
        time.as_secs_f64() * 1e3,
        mb / time.as_secs_f64()
    );
}

fn main() {
    let includes = Path::new("/usr/share/povray-3.7/include");
    let examples = Path::new("/usr/share/doc/povray/examples");
    let gallery = Path::new(env!("CARGO_MANIFEST_DIR")).join("../gallery");
    report("include folder", &load(&[includes]));
    report("whole corpus", &load(&[includes, examples]));
    report("gallery", &load(&[&gallery]));
}
