//! Parse speed over real scenes: `cargo bench -p syntax`. Reports the time to lex and
//! parse the POV-Ray include folder (target: under 50 ms; about 0.5 MB) and MB/s over
//! the whole corpus, falling back to the gallery when the corpus is not installed. Times
//! are CPU time of the parsing thread.

use std::fs;
use std::path::{Path, PathBuf};
use std::time::Duration;

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

/// CPU time this thread has used, from the thread CPU-time clock
/// (`clock_gettime(CLOCK_THREAD_CPUTIME_ID)`), precise to the nanosecond: on a shared
/// machine wall time would also measure the neighbours.
fn thread_cpu_time() -> Duration {
    let now = rustix::time::clock_gettime(rustix::time::ClockId::ThreadCPUTime);
    Duration::new(
        u64::try_from(now.tv_sec).unwrap_or_default(),
        u32::try_from(now.tv_nsec).unwrap_or_default(),
    )
}

/// The fastest of several runs over all texts, in CPU time. Each run repeats the texts for
/// at least 50 ms of CPU time, so that one run's figure is an average over many parses.
fn best_time(texts: &[String], runs: usize) -> Duration {
    (0..runs)
        .map(|_| {
            let start = thread_cpu_time();
            let mut rounds = 0u32;
            while rounds == 0 || thread_cpu_time() - start < Duration::from_millis(50) {
                for text in texts {
                    let parse = syntax::parse(text);
                    std::hint::black_box(parse.errors().len());
                }
                rounds += 1;
            }
            (thread_cpu_time() - start) / rounds
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
