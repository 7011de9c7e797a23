//! Compiled `function { }` speed: `cargo bench -p analysis --bench functions` measures
//! evaluations per second on the gallery gyroid's functions, the kind isosurfaces evaluate
//! millions of times. (Scene evaluation speed against POV-Ray's parse time is
//! `cargo run --release -p tests --bin eval-benchmark`.)

use analysis::MemoryFiles;
use std::time::Instant;

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
}
