//! Times our render of every fidelity scene (evaluation plus tracing, without PNG encoding;
//! the best of three runs) on one thread and on all threads, beside POV-Ray's own parse plus trace time at
//! `+WT1` from `tests/reference/povray-times.txt`, and prints the table. Single-thread
//! figures are CPU time of the process (Linux's per-thread scheduler statistics), as
//! POV-Ray's are CPU seconds: the machine is shared, and wall time would measure the
//! neighbours. All-thread figures are wall time.
//!
//!   cargo run --release -p tests --bin fidelity-benchmark [SCENE...]

use std::time::{Duration, Instant};
use tests::fidelity::{manifest, reference_dir};

/// CPU time used so far by every thread of this process, where Linux tells it.
fn process_cpu_time() -> Option<Duration> {
    let mut total = 0u64;
    for task in std::fs::read_dir("/proc/self/task").ok()? {
        let stat = std::fs::read_to_string(task.ok()?.path().join("schedstat")).ok()?;
        total += stat.split_whitespace().next()?.parse::<u64>().ok()?;
    }
    Some(Duration::from_nanos(total))
}

fn best_of_three(scene: &tests::fidelity::FidelityScene, source: &str, cpu_time: bool) -> Duration {
    (0..3)
        .map(|_| {
            let cpu_start = process_cpu_time();
            let start = Instant::now();
            if let Err(e) = scene.render_image(source) {
                eprintln!("{}: {e}", scene.name);
                std::process::exit(1);
            }
            let wall = start.elapsed();
            match (cpu_time, cpu_start, process_cpu_time()) {
                (true, Some(a), Some(b)) => b.saturating_sub(a),
                _ => wall,
            }
        })
        .min()
        .expect("three runs")
}

fn main() {
    let only: Vec<String> = std::env::args().skip(1).collect();
    let times = std::fs::read_to_string(reference_dir().join("povray-times.txt"))
        .expect("tests/reference/povray-times.txt");
    let povray = |name: &str| -> Option<f64> {
        times.lines().find_map(|l| {
            let mut w = l.split_whitespace();
            (w.next() == Some(name)).then(|| {
                let parse: f64 = w.next()?.parse().ok()?;
                let trace: f64 = w.next()?.parse().ok()?;
                Some(parse + trace)
            })?
        })
    };
    let single = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    println!(
        "| scene | ours, 1 thread (CPU ms) | POV-Ray +WT1 parse+trace (CPU ms) | ratio | ours, {} threads (wall ms) |",
        rayon::current_num_threads()
    );
    println!("|---|---:|---:|---:|---:|");
    for scene in manifest() {
        if !only.is_empty() && !only.contains(&scene.name) {
            continue;
        }
        let source = scene.source();
        let one = single.install(|| best_of_three(&scene, &source, true));
        let all = best_of_three(&scene, &source, false);
        let ms = |d: Duration| d.as_secs_f64() * 1000.0;
        let (pov, ratio) = match povray(&scene.name) {
            Some(p) => (
                format!("{:.0}", p * 1000.0),
                format!("{:.2}", ms(one) / (p * 1000.0)),
            ),
            None => ("-".into(), "-".into()),
        };
        println!(
            "| {} | {:.1} | {} | {} | {:.1} |",
            scene.name,
            ms(one),
            pov,
            ratio,
            ms(all)
        );
    }
}
