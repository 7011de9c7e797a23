//! Times our render of every fidelity scene (evaluation plus tracing, without PNG encoding;
//! the best of three runs) on one thread and on all threads, beside POV-Ray's own parse plus
//! trace time at `+WT1`, and prints the table. Single-thread figures are CPU time of the
//! process (Linux's per-thread scheduler statistics), as POV-Ray's are CPU seconds: the
//! machine is shared, and wall time would measure the neighbours. All-thread figures are
//! wall time, POV-Ray's as it reports its phases' elapsed seconds.
//!
//!   cargo run --release -p tests --bin fidelity-benchmark [--live-povray] [SCENE...]
//!
//! POV-Ray's times come from `tests/reference/povray-times.txt` (recorded by render.sh),
//! or with `--live-povray` from running `povray` on each scene in the same run (`+WT1`, and
//! with as many threads as ours for the all-thread columns), the best of three, so that both
//! renderers are timed under the same load.

use std::time::{Duration, Instant};
use tests::cpu_time::process_cpu_time;
use tests::fidelity::{manifest, reference_dir};

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

/// What to read off POV-Ray's statistics: its phases' CPU seconds, or their elapsed seconds.
#[derive(Clone, Copy)]
enum Clock {
    Cpu,
    Wall,
}

/// POV-Ray's own seconds for every phase it reports (parse, photons, radiosity pretrace,
/// trace), the best of three runs of `povray` with `threads` render threads on `scene`. As
/// in `tests/reference/render.sh`, standard includes come from our `analysis/stdinc` (an
/// empty `POVINI` keeps POV-Ray's library path out).
fn live_povray_seconds(
    scene: &tests::fidelity::FidelityScene,
    threads: usize,
    clock: Clock,
) -> Option<f64> {
    let path = tests::workspace_root().join(&scene.scene);
    let out = std::env::temp_dir().join(format!("fidelity-benchmark-{}.png", scene.name));
    let no_ini = std::env::temp_dir().join("fidelity-benchmark-empty.ini");
    std::fs::write(&no_ini, "").ok()?;
    let stdinc = tests::workspace_root().join("analysis/stdinc");
    (0..3)
        .map(|_| {
            let run = std::process::Command::new("povray")
                .env("POVINI", &no_ini)
                .arg(format!("+I{}", path.display()))
                .arg(format!("+O{}", out.display()))
                .args(["+FN", "-D", "-V", &format!("+WT{threads}")])
                .args(&scene.options)
                .arg(format!("+L{}", path.parent()?.display()))
                .arg(format!("+L{}", stdinc.display()))
                .output()
                .ok()?;
            let log = String::from_utf8_lossy(&run.stderr);
            run.status.success().then(|| povray_seconds(&log, clock))
        })
        .collect::<Option<Vec<f64>>>()?
        .into_iter()
        .reduce(f64::min)
}

/// The sum over POV-Ray's "... Time:" statistics lines of the elapsed "(N seconds)" each
/// ends with, or of the "N CPU-seconds total" on the line after it.
fn povray_seconds(log: &str, clock: Clock) -> f64 {
    let mut lines = log.lines();
    let mut total = 0.0;
    while let Some(line) = lines.next() {
        if line.trim_start().ends_with("seconds)") && line.contains(" Time:") {
            let seconds = match clock {
                Clock::Wall => line
                    .rsplit('(')
                    .next()
                    .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok()),
                Clock::Cpu => lines.next().and_then(|next| {
                    let before = next.split(" CPU-seconds").next()?;
                    before.split_whitespace().last()?.parse::<f64>().ok()
                }),
            };
            total += seconds.unwrap_or(0.0);
        }
    }
    total
}

fn main() {
    let mut only: Vec<String> = std::env::args().skip(1).collect();
    let live = only.iter().any(|a| a == "--live-povray");
    only.retain(|a| a != "--live-povray");
    let times = std::fs::read_to_string(reference_dir().join("povray-times.txt"))
        .expect("tests/reference/povray-times.txt");
    let recorded = |name: &str| -> Option<f64> {
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
    let threads = rayon::current_num_threads();
    print!(
        "| scene | ours, 1 thread (CPU ms) | POV-Ray +WT1 parse+trace (CPU ms, {}) | ratio | ours, {threads} threads (wall ms) |",
        if live { "this run" } else { "recorded" },
    );
    if live {
        println!(" POV-Ray +WT{threads} (wall ms) | ratio |\n|---|---:|---:|---:|---:|---:|---:|");
    } else {
        println!("\n|---|---:|---:|---:|---:|");
    }
    for scene in manifest() {
        if !only.is_empty() && !only.contains(&scene.name) {
            continue;
        }
        let source = scene.source();
        let one = single.install(|| best_of_three(&scene, &source, true));
        let all = best_of_three(&scene, &source, false);
        let ms = |d: Duration| d.as_secs_f64() * 1000.0;
        let povray = if live {
            live_povray_seconds(&scene, 1, Clock::Cpu)
        } else {
            recorded(&scene.name)
        };
        let (pov, ratio) = match povray {
            Some(p) => (
                format!("{:.0}", p * 1000.0),
                format!("{:.2}", ms(one) / (p * 1000.0)),
            ),
            None => ("-".into(), "-".into()),
        };
        print!(
            "| {} | {:.1} | {} | {} | {:.1} |",
            scene.name,
            ms(one),
            pov,
            ratio,
            ms(all)
        );
        match live.then(|| live_povray_seconds(&scene, threads, Clock::Wall)) {
            Some(Some(p)) => println!(" {:.0} | {:.2} |", p * 1000.0, ms(all) / (p * 1000.0)),
            Some(None) => println!(" - | - |"),
            None => println!(),
        }
    }
}

#[cfg(test)]
mod povray_log {
    use super::{Clock, povray_seconds};

    #[test]
    fn sums_the_seconds_of_every_phase() {
        let log = "Parse Time:    0 hours  0 minutes  0 seconds (0.012 seconds)\n              using 1 thread(s) with 0.011 CPU-seconds total\nPhoton Time:   0 hours  0 minutes  1 seconds (0.500 seconds)\n              using 1 thread(s) with 0.490 CPU-seconds total\nTrace Time:    0 hours  0 minutes  1 seconds (1.250 seconds)\n              using 1 thread(s) with 1.240 CPU-seconds total\n";
        assert!((povray_seconds(log, Clock::Cpu) - 1.741).abs() < 1e-9);
        assert!((povray_seconds(log, Clock::Wall) - 1.762).abs() < 1e-9);
    }
}
