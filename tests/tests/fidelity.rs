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
