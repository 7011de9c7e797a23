//! The mathematical shapes against POV-Ray's pictures beyond the plain fidelity run: the
//! lemon (which POV-Ray 3.7 lacks) against the same solid drawn as a lathe, and every
//! shape scene scaled to 1e-5 and 1e5, where tolerances that do not follow the scene's
//! size show as speckles.

use tests::fidelity::{FidelityScene, manifest};
use tests::image_compare::{Picture, compare};

fn scene(name: &str) -> FidelityScene {
    manifest()
        .into_iter()
        .find(|s| s.name == name)
        .unwrap_or_else(|| panic!("no scene {name} in scenes.txt"))
}

/// Pixels whose largest channel differs from the reference by more than a quarter of the
/// range: isolated wrong hits (holes, acne, lost silhouettes) rather than shading drift.
fn speckles(reference: &Picture, ours: &Picture) -> usize {
    reference
        .pixels
        .iter()
        .zip(&ours.pixels)
        .filter(|(a, b)| (0..3).any(|c| (a[c] - b[c]).abs() > 0.25))
        .count()
}

/// Our `lemon` draws the solid that the reference draws as a lathe of Bézier arcs (within
/// 1e-5 of the circle): SSIM at least 0.98 against POV-Ray's picture.
#[test]
fn lemon_matches_its_lathe_in_povray() {
    let scene = scene("shape-lemon");
    let reference = Picture::read(&scene.reference_png()).unwrap();
    let source = scene.source();
    assert!(source.contains("#declare Native = 0;"));
    let native = source.replace("#declare Native = 0;", "#declare Native = 1;");
    let ours = scene.render_with(&native).unwrap();
    let d = compare(&reference, &ours).unwrap();
    eprintln!("lemon: {d}, {} speckles", speckles(&reference, &ours));
    scene.thresholds.check(&d).unwrap();
}

/// Each shape family's scene, scaled by 1e-5 and 1e5 (camera and lights with it), draws
/// POV-Ray's picture within the scene's thresholds and with at most 0.2 % speckled pixels.
#[test]
fn shape_scenes_render_alike_at_extreme_scales() {
    let mut failures = Vec::new();
    for scene in manifest()
        .into_iter()
        .filter(|s| s.name.starts_with("shape-"))
    {
        let reference = Picture::read(&scene.reference_png()).unwrap();
        let source = scene.source();
        assert!(source.contains("#declare S = 1;"), "{}", scene.name);
        for scale in ["1e-5", "1e5"] {
            let scaled = source.replace("#declare S = 1;", &format!("#declare S = {scale};"));
            let ours = match scene.render_with(&scaled) {
                Ok(p) => p,
                Err(e) => {
                    failures.push(format!("{} at {scale}: {e}", scene.name));
                    continue;
                }
            };
            let d = compare(&reference, &ours).unwrap();
            let count = speckles(&reference, &ours);
            eprintln!("{:<22} at {scale:>4}: {d}, {count} speckles", scene.name);
            if let Err(e) = scene.thresholds.check(&d) {
                failures.push(format!("{} at {scale}: {e}", scene.name));
            }
            if count * 500 > reference.pixels.len() {
                failures.push(format!("{} at {scale}: {count} speckles", scene.name));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
