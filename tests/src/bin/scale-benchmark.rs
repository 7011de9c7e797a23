//! How the renderer scales with the size of a scene: for each named fidelity scene (by
//! default the two with a hundred thousand objects or triangles), the CPU time of its
//! evaluation, of building the world (the bounding volume hierarchies over objects and
//! mesh triangles above all) and of the whole render on one thread, with what the world
//! holds, the bytes of its hierarchies and meshes, and the process's peak memory so far.
//!
//!   cargo run --release -p tests --bin scale-benchmark [SCENE...]

use std::time::Duration;
use tests::cpu_time::{peak_resident_bytes, process_cpu_time};
use tests::fidelity::manifest;

/// The CPU time `work` takes, with its result.
fn timed<T>(work: impl FnOnce() -> T) -> (T, Duration) {
    let start = process_cpu_time().expect("Linux's per-thread CPU time");
    let value = work();
    let end = process_cpu_time().expect("Linux's per-thread CPU time");
    (value, end.saturating_sub(start))
}

fn main() {
    let mut names: Vec<String> = std::env::args().skip(1).collect();
    if names.is_empty() {
        names = vec!["spheres-100k".into(), "mesh2-100k".into()];
    }
    let single = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .expect("a one-thread pool");
    println!(
        "| scene | objects | triangles | evaluate (CPU ms) | build (CPU ms) | render incl. build (CPU ms) | object BVH (KiB) | objects (KiB) | meshes (KiB) | peak RSS so far (MiB) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let ms = |d: Duration| d.as_secs_f64() * 1000.0;
    for scene in manifest() {
        if !names.contains(&scene.name) {
            continue;
        }
        let options = scene.render_options();
        let file = scene
            .scene
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or("scene.pov");
        let files = analysis::MemoryFiles::new().with(file, scene.source());
        let eval_options = analysis::EvalOptions {
            image_width: options.width,
            image_height: options.height,
            ..analysis::EvalOptions::default()
        };
        single.install(|| {
            let (evaluation, evaluate) = timed(|| {
                analysis::evaluate_with(file, &files, &eval_options, &renderer::SceneGeometry)
            });
            let failed = evaluation.has_errors();
            let Some(parsed) = evaluation.scene.filter(|_| !failed) else {
                eprintln!("{}: does not evaluate", scene.name);
                std::process::exit(1);
            };
            let (statistics, build) = timed(|| renderer::world_statistics(&parsed));
            let statistics = statistics.unwrap_or_else(|e| {
                eprintln!("{}: {}", scene.name, e.message);
                std::process::exit(1);
            });
            let (image, render) = timed(|| renderer::render(&parsed, &options));
            if let Err(e) = image {
                eprintln!("{}: {}", scene.name, e.message);
                std::process::exit(1);
            }
            let kib = |bytes: usize| bytes as f64 / 1024.0;
            println!(
                "| {} | {} | {} | {:.0} | {:.0} | {:.0} | {:.0} | {:.0} | {:.0} | {:.0} |",
                scene.name,
                statistics.objects,
                statistics.mesh_triangles,
                ms(evaluate),
                ms(build),
                ms(render),
                kib(statistics.bvh_bytes),
                kib(statistics.object_bytes),
                kib(statistics.mesh_bytes),
                peak_resident_bytes().unwrap_or(0) as f64 / (1024.0 * 1024.0),
            );
        });
    }
}
