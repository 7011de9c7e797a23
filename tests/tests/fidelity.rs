//! Our renders against POV-Ray 3.7's, scene by scene, at the settings and thresholds of
//! `tests/reference/scenes.txt` (references made by `tests/reference/render.sh`).

use tests::fidelity::manifest;
use tests::image_compare::{Picture, compare};

#[test]
fn renders_match_povray() {
    let mut failures = Vec::new();
    for scene in manifest() {
        let reference = Picture::read(&scene.reference_png()).unwrap();
        let ours = match scene.render_with(&scene.source()) {
            Ok(p) => p,
            Err(e) => {
                failures.push(format!("{}: does not render:\n{e}", scene.name));
                continue;
            }
        };
        match compare(&reference, &ours) {
            Ok(d) => {
                eprintln!("{:<16} {d}", scene.name);
                if let Err(e) = scene.thresholds.check(&d) {
                    failures.push(format!("{}: {e}", scene.name));
                }
            }
            Err(e) => failures.push(format!("{}: {e}", scene.name)),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The thresholds are tight enough to catch a real mistake: basic.pov with its mirrored
/// camera taken the wrong way round fails, as does a light moved a little.
#[test]
fn wrong_renders_fail_the_thresholds() {
    let scenes = manifest();
    let basic = scenes.iter().find(|s| s.name == "basic").unwrap();
    let reference = Picture::read(&basic.reference_png()).unwrap();
    let source = basic.source();
    for (what, from, to) in [
        ("unmirrored camera", "-1.333*x", "1.333*x"),
        ("moved light", "<4, 6, -6>", "<4.5, 6, -6>"),
        ("duller highlight", "specular 0.5", "specular 0.3"),
    ] {
        assert!(source.contains(from), "basic.pov no longer has `{from}`");
        let wrong = basic.render_with(&source.replace(from, to)).unwrap();
        let d = compare(&reference, &wrong).unwrap();
        assert!(basic.thresholds.check(&d).is_err(), "{what} passes: {d}");
    }
}

/// Methods 1 and 3 antialias the same picture: against POV-Ray's method-2 reference of
/// basic.pov (Debian's POV-Ray 3.7 has no method 3 to compare with), each stays within the
/// scene's thresholds.
#[test]
fn other_sampling_methods_agree_with_method_two() {
    let scenes = manifest();
    let basic = scenes.iter().find(|s| s.name == "basic").unwrap();
    let reference = Picture::read(&basic.reference_png()).unwrap();
    for method in ["+AM1", "+AM3"] {
        let mut scene = basic.clone();
        scene.options.push(method.into());
        let ours = scene.render_with(&scene.source()).unwrap();
        let d = compare(&reference, &ours).unwrap();
        eprintln!("basic {method}: {d}");
        scene
            .thresholds
            .check(&d)
            .unwrap_or_else(|e| panic!("{method}: {e}"));
    }
}

/// The robustness scene scaled by 1e-6 and 1e6 draws the same picture, without speckles
/// on its grazing floor and shared faces: tolerances follow the scene's size.
#[test]
fn scaled_scenes_render_alike() {
    let scenes = manifest();
    let scene = scenes.iter().find(|s| s.name == "extremes").unwrap();
    let reference = Picture::read(&scene.reference_png()).unwrap();
    let source = scene.source();
    assert!(source.contains("#declare S = 1;"));
    for scale in ["1e-6", "1e6"] {
        let scaled = source.replace("#declare S = 1;", &format!("#declare S = {scale};"));
        let ours = scene.render_with(&scaled).unwrap();
        let d = compare(&reference, &ours).unwrap();
        eprintln!("extremes at {scale}: {d}");
        scene
            .thresholds
            .check(&d)
            .unwrap_or_else(|e| panic!("scale {scale}: {e}"));
    }
}
