//! Our renders against POV-Ray 3.7's, scene by scene, at the settings and thresholds of
//! `tests/reference/scenes.txt` (references made by `tests/reference/render.sh`).

use tests::fidelity::{FidelityScene, manifest};
use tests::image_compare::{Picture, compare, compare_blurred};

/// The manifest's scene called `name` and POV-Ray's picture of it.
fn scene_and_reference(name: &str) -> (FidelityScene, Picture) {
    let scene = manifest().into_iter().find(|s| s.name == name).unwrap();
    let reference = Picture::read(&scene.reference_png()).unwrap();
    (scene, reference)
}

/// `FIDELITY_ONLY=prefix,...` narrows the run to the scenes whose names start with one of
/// the prefixes, for working on a few of them; unset, every scene is compared.
#[test]
fn renders_match_povray() {
    let only: Vec<String> = std::env::var("FIDELITY_ONLY")
        .map(|v| v.split(',').map(str::to_string).collect())
        .unwrap_or_default();
    let mut failures = Vec::new();
    for scene in manifest() {
        if !only.is_empty() && !only.iter().any(|p| scene.name.starts_with(p.as_str())) {
            continue;
        }
        let reference = Picture::read(&scene.reference_png()).unwrap();
        let ours = match scene.render_with(&scene.source()) {
            Ok(p) => p,
            Err(e) => {
                failures.push(format!("{}: does not render:\n{e}", scene.name));
                continue;
            }
        };
        match compare_blurred(&reference, &ours, scene.thresholds.blur) {
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
    wrong_versions_fail(
        "basic",
        &[
            ("unmirrored camera", "-1.333*x", "1.333*x"),
            ("moved light", "<4, 6, -6>", "<4.5, 6, -6>"),
            ("duller highlight", "specular 0.5", "specular 0.3"),
        ],
    );
}

/// The radiosity thresholds, loose as stochastic light needs, still catch wrong light: the
/// Cornell box with one bounce fewer, or with its indirect light 10 % dimmer, fails.
#[test]
fn wrong_radiosity_fails_the_thresholds() {
    let scenes = manifest();
    let cornell = scenes
        .iter()
        .find(|s| s.name == "radiosity-cornell")
        .unwrap();
    let reference = Picture::read(&cornell.reference_png()).unwrap();
    let source = cornell.source();
    let from = "radiosity { count 60 }";
    assert!(
        source.contains(from),
        "radiosity-cornell.pov no longer has `{from}`"
    );
    for (what, to) in [
        ("one bounce", "radiosity { count 60 recursion_limit 1 }"),
        ("dimmer", "radiosity { count 60 brightness 0.9 }"),
    ] {
        let wrong = cornell.render_with(&source.replace(from, to)).unwrap();
        let d = compare_blurred(&reference, &wrong, cornell.thresholds.blur).unwrap();
        assert!(cornell.thresholds.check(&d).is_err(), "{what} passes: {d}");
    }
}

/// The subsurface thresholds, loose as stochastic light needs, still catch light that does
/// not travel under the surface: the same scene without `global_settings { subsurface { }
/// }`, whose wax slab lit from behind shows no glow and whose marble's shadow side no
/// light, fails them.
#[test]
fn wrong_subsurface_fails_the_thresholds() {
    wrong_versions_fail(
        "subsurface",
        &[("subsurface ignored", "subsurface { samples 50, 50 }", "")],
    );
}

/// Methods 1 and 3 antialias the same picture: against POV-Ray's method-2 reference of
/// basic.pov (Debian's POV-Ray 3.7 has no method 3 to compare with), each stays within the
/// scene's thresholds.
#[test]
fn other_sampling_methods_agree_with_method_two() {
    let (basic, reference) = scene_and_reference("basic");
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
    let (scene, reference) = scene_and_reference("extremes");
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

/// Mean, standard deviation and mean difference between horizontal neighbours (a measure
/// of spatial frequency) of a picture's red channel.
fn statistics(p: &Picture) -> (f64, f64, f64) {
    let values: Vec<f64> = p.pixels.iter().map(|v| v[0]).collect();
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let sd = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n).sqrt();
    let mut steps = 0.0;
    for row in values.chunks(p.width) {
        steps += row.windows(2).map(|w| (w[1] - w[0]).abs()).sum::<f64>();
    }
    let gradient = steps / (p.height * (p.width - 1)) as f64;
    (mean, sd, gradient)
}

/// Noise patterns match POV-Ray statistically (as they do pixel for pixel, see
/// scenes.txt): over a plane showing a few hundred features of bozo mapped to grey, the
/// mean differs by less than 0.02 and the standard deviation and the mean neighbour
/// difference by less than 10 %.
#[test]
fn noise_statistics_match_povray() {
    let (scene, reference) = scene_and_reference("noise-bozo");
    let (m0, s0, g0) = statistics(&reference);
    let (m1, s1, g1) = statistics(&scene.render_with(&scene.source()).unwrap());
    eprintln!("POV-Ray: mean {m0:.3} sd {s0:.3} gradient {g0:.4}; ours: {m1:.3} {s1:.3} {g1:.4}");
    assert!((m0 - m1).abs() < 0.02, "mean {m0} against {m1}");
    assert!(
        (s0 - s1).abs() < 0.1 * s0,
        "standard deviation {s0} against {s1}"
    );
    assert!(
        (g0 - g1).abs() < 0.1 * g0,
        "spatial frequency {g0} against {g1}"
    );
}

/// Media sampled with jitter are noisy, in POV-Ray's render as in ours, with different
/// noise. At the scale a viewer sees (5 × 5 pixel means) the pictures agree: SSIM at least
/// 0.98, and the mean brightness of each cell of a 4 × 3 grid within 8/255. Unblurred they
/// differ more, which shows the noise is there to blur. The cells across the beam are the
/// farthest apart (125 against 119 now): POV-Ray's few default steps overestimate the
/// light in a spotlight's falloff zone (a lone beam gives 0.622 with 10 samples, 0.575
/// with 100, and the exact integral is 0.561), and jitter adds to it.
#[test]
fn jittered_media_match_povray_at_viewing_scale() {
    let (scene, reference) = scene_and_reference("media-jitter");
    let ours = scene.render_with(&scene.source()).unwrap();
    let sharp = compare(&reference, &ours).unwrap();
    let blurred = compare(&reference.blurred(2), &ours.blurred(2)).unwrap();
    eprintln!("media-jitter sharp: {sharp}\nmedia-jitter blurred: {blurred}");
    assert!(blurred.ssim >= 0.98, "{blurred}");
    assert!(sharp.ssim < blurred.ssim, "{sharp} against {blurred}");
    let (a, b) = (reference.region_means(4, 3), ours.region_means(4, 3));
    for (cell, (a, b)) in a.iter().zip(&b).enumerate() {
        assert!(
            (a - b).abs() <= 8.0,
            "cell {cell}: POV-Ray {a:.1}, ours {b:.1}"
        );
    }
}

/// Focal blur is stochastic in POV-Ray as in ours (both sample the lens adaptively, with
/// their own sequences), so the pictures are compared as a viewer sees them: after a 7 × 7
/// box filter the SSIM is at least 0.98, and the mean colour of each region of a 4 × 4
/// grid is within 1/255 of POV-Ray's. A picture without blur, or with the focal point on
/// the box instead of the sphere, fails.
#[test]
fn focal_blur_matches_povray_at_viewer_level() {
    let (scene, reference) = scene_and_reference("focal-blur");
    let source = scene.source();
    let viewer_difference = |ours: &Picture| {
        let ssim = compare(&reference.blurred(3), &ours.blurred(3))
            .unwrap()
            .ssim;
        let region = reference
            .region_means(4, 4)
            .iter()
            .zip(ours.region_means(4, 4))
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        (ssim, region)
    };
    let (ssim, region) = viewer_difference(&scene.render_with(&source).unwrap());
    eprintln!(
        "focal blur: blurred SSIM {ssim:.4}, largest regional mean difference {region:.3}/255"
    );
    assert!(ssim >= 0.98, "blurred SSIM {ssim}");
    assert!(region <= 1.0, "regional mean difference {region}/255");
    for (what, from, to) in [
        ("no blur", "aperture 0.6", "aperture 0"),
        (
            "focus on the box",
            "focal_point <0.7, -0.4, -5>",
            "focal_point <0, 0, 0>",
        ),
    ] {
        assert!(
            source.contains(from),
            "focal-blur.pov no longer has `{from}`"
        );
        let wrong = scene.render_with(&source.replace(from, to)).unwrap();
        let (ssim, region) = viewer_difference(&wrong);
        eprintln!("{what}: blurred SSIM {ssim:.4}, regional difference {region:.3}/255");
        assert!(
            ssim < 0.98 || region > 1.0,
            "{what} passes: {ssim} {region}"
        );
    }
}

/// The grey values (mean of the colour channels, 0-255) of a picture's pixels, sorted.
fn sorted_greys(p: &Picture) -> Vec<f64> {
    let mut greys: Vec<f64> = p
        .pixels
        .iter()
        .map(|v| (v[0] + v[1] + v[2]) / 3.0 * 255.0)
        .collect();
    greys.sort_by(f64::total_cmp);
    greys
}

/// How far apart two pictures' light is, at the scale a viewer sees a caustic: the largest
/// difference of the mean grey of the cells of a 4 × 3 grid, and of the 50th, 90th and 99th
/// percentiles of the grey values (how much of the picture the caustic lights, and how
/// brightly), all on the 0-255 scale.
fn light_difference(a: &Picture, b: &Picture) -> (f64, f64) {
    let cells = a
        .region_means(4, 3)
        .iter()
        .zip(&b.region_means(4, 3))
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    let (ga, gb) = (sorted_greys(a), sorted_greys(b));
    let at = |g: &[f64], q: f64| g[((g.len() - 1) as f64 * q) as usize];
    let percentiles = [0.5, 0.9, 0.99]
        .iter()
        .map(|&q| (at(&ga, q) - at(&gb, q)).abs())
        .fold(0.0, f64::max);
    (cells, percentiles)
}

/// caustic.pov's photons are stochastic (their jitter is not POV-Ray's), so its picture
/// matches POV-Ray's blurred (the scenes.txt thresholds). Here the brightness of the floor that the caustic lights
/// is compared: the 4 × 3 cells' mean grey within 4/255 and the 50th, 90th and 99th
/// percentiles of the grey values within 3/255 (1.8 and 1.0 now). The same scene without
/// photons, whose floor misses the caustic's light, fails that (18.1 and 59.3).
#[test]
fn photon_caustic_lights_the_floor_as_povray_does() {
    let scenes = manifest();
    let caustic = scenes.iter().find(|s| s.name == "caustic").unwrap();
    let reference = Picture::read(&caustic.reference_png()).unwrap();
    let source = caustic.source();
    let ours = caustic.render_with(&source).unwrap();
    let (cells, percentiles) = light_difference(&reference, &ours);
    eprintln!("caustic: cells {cells:.1}, percentiles {percentiles:.1}");
    assert!(cells <= 4.0 && percentiles <= 3.0, "{cells} {percentiles}");
    let block = "photons { spacing 0.10 gather 3, 8 }";
    assert!(
        source.contains(block),
        "caustic.pov no longer has `{block}`"
    );
    let dark = caustic.render_with(&source.replace(block, "")).unwrap();
    let (cells, percentiles) = light_difference(&reference, &dark);
    eprintln!("caustic without photons: cells {cells:.1}, percentiles {percentiles:.1}");
    assert!(cells > 4.0 || percentiles > 3.0, "{cells} {percentiles}");
}

/// Renders the manifest's scene `name` with each `(what, from, to)` change to its source and
/// asserts that every such wrong picture fails the scene's thresholds (blurred as the
/// scene's comparison is).
fn wrong_versions_fail(name: &str, changes: &[(&str, &str, &str)]) {
    let (scene, reference) = scene_and_reference(name);
    let source = scene.source();
    for (what, from, to) in changes {
        assert!(source.contains(from), "{name} no longer has `{from}`");
        let wrong = scene.render_with(&source.replace(from, to)).unwrap();
        let d = compare_blurred(&reference, &wrong, scene.thresholds.blur).unwrap();
        eprintln!("{name} with {what}: {d}");
        assert!(scene.thresholds.check(&d).is_err(), "{what} passes: {d}");
    }
}

/// The light-transport scenes' thresholds catch wrong light: the dispersing prism's
/// (blurred by 2 pixels, as photons are stochastic) a spectrum that is missing or white,
/// fog-ground's a fog thinning a little faster or along the untilted up direction,
/// rainbow's a bow one degree wider or arcs fading over other angles, photons-in-media's a
/// beam without its media photons or in a medium that scatters 30% less.
#[test]
fn wrong_light_transport_fails_the_thresholds() {
    let photons = "photons { count 40000 gather 15, 60 autostop 0 jitter 0.4 }";
    wrong_versions_fail(
        "photons-prism",
        &[
            ("no photons", photons, ""),
            ("no dispersion", "dispersion 1.2", "dispersion 1"),
        ],
    );
    wrong_versions_fail(
        "fog-ground",
        &[
            ("a lower fog", "fog_alt 0.7", "fog_alt 0.6"),
            ("an upright fog", "up <0.15, 1, 0>", "up y"),
        ],
    );
    wrong_versions_fail(
        "rainbow",
        &[
            ("a wider bow", "angle 42", "angle 43"),
            ("other fading", "falloff_angle 90", "falloff_angle 120"),
        ],
    );
    wrong_versions_fail(
        "photons-in-media",
        &[
            ("no media photons", "media 60, 1", ""),
            (
                "weaker scattering",
                "rgb 0.35 extinction",
                "rgb 0.25 extinction",
            ),
        ],
    );
}
