//! Radiosity against light levels known in closed form, and its promises: the same
//! picture on any number of threads, and nothing computed without it.

use crate::build::{BuildSettings, build_world};
use crate::camera::Camera;
use crate::options::RenderOptions;
use crate::render::render;
use crate::tracer::Tracer;
use analysis::{EvalOptions, MemoryFiles};
use glam::DVec3;
use std::sync::atomic::AtomicUsize;

fn evaluate(text: &str) -> analysis::scene::Scene {
    let files = MemoryFiles::new().with("scene.pov", text);
    let evaluation = analysis::evaluate("scene.pov", &files, &EvalOptions::default());
    evaluation.scene.expect("the scene evaluates")
}

/// The world of `scene` at full quality.
fn built(scene: &analysis::scene::Scene) -> crate::tracer::World {
    let settings = BuildSettings {
        quality: 9,
        output_alpha: false,
        max_trace_level: None,
    };
    build_world(scene, settings).expect("the scene builds")
}

/// The radiosity of `text` after the pretrace for a 64 × 48 picture.
fn pretraced(text: &str) -> super::Radiosity {
    let scene = evaluate(text);
    let mut world = built(&scene);
    let camera = Camera::from_scene(&scene.camera).expect("a camera");
    let frame = super::Frame {
        width: 64,
        height: 48,
        columns: (0, 63),
        rows: (0, 47),
        corners: false,
    };
    super::pretrace(&mut world, &camera, &frame);
    world.radiosity.expect("radiosity")
}

/// How many samples the pretrace of `text` takes at each bounce depth, for a 64 × 48
/// picture.
fn samples_taken(text: &str) -> Vec<usize> {
    pretraced(text).sample_counts()
}

/// Renders `text` at 24 × 18 without antialiasing into a file of gamma 1; the scenes of
/// 3.7 set no `assumed_gamma` (and so have 1.0), so pixels hold the shading's own values.
fn render_scene(text: &str, quality: u8) -> crate::Image {
    let scene = evaluate(text);
    let options = RenderOptions {
        width: 24,
        height: 18,
        antialias: false,
        quality,
        file_gamma: Some(crate::options::Gamma::Power(1.0)),
        ..RenderOptions::default()
    };
    render(&scene, &options).expect("the scene renders")
}

/// The red, green and blue of the centre pixel.
fn centre(text: &str) -> [f32; 3] {
    let image = render_scene(text, 9);
    let p = image.pixel(12, 9);
    [p[0], p[1], p[2]]
}

/// A camera looking down at a floor with `diffuse 0.8`, under `sky`, with radiosity
/// `settings`.
fn floor_under(sky: &str, settings: &str, floor: &str) -> String {
    format!(
        "#version 3.7;
         global_settings {{ radiosity {{ {settings} }} }}
         camera {{ location <0, 5, 0> look_at 0 }}
         {sky}
         plane {{ y, 0 pigment {{ rgb 1 }} finish {{ diffuse 0.8 ambient 0.3 }} {floor} }}"
    )
}

fn close(a: [f32; 3], b: [f32; 3]) -> bool {
    a.iter().zip(b).all(|(a, b)| (a - b).abs() < 1e-5)
}

#[test]
fn a_floor_under_a_uniform_sky_gets_its_diffuse_share_of_it() {
    // Every gathering ray sees the background, so the light is exact: 0.8 × 0.5. The
    // finish's ambient counts for nothing with radiosity on.
    let lit = centre(&floor_under("background { rgb 0.5 }", "", ""));
    assert!(close(lit, [0.4; 3]), "{lit:?}");
    // A glowing dome in place of the background gives the same light.
    let dome = "sphere { 0, 100 hollow pigment { rgb 0.5 } finish { emission 1 diffuse 0 } }";
    let lit = centre(&floor_under(dome, "", ""));
    assert!(close(lit, [0.4; 3]), "{lit:?}");
}

#[test]
fn brightness_gray_threshold_and_max_sample_shape_the_gathered_light() {
    let red_sky = "background { rgb <1, 0, 0> }";
    let lit = centre(&floor_under(red_sky, "brightness 2", ""));
    assert!(close(lit, [1.0, 0.0, 0.0]), "{lit:?}");
    // Fully grey: the sky's brightness without its hue.
    let lit = centre(&floor_under(red_sky, "gray_threshold 1", ""));
    assert!(close(lit, [0.8 * 0.297; 3]), "{lit:?}");
    // A sky of brightness 4 limited to 1 keeps its colour.
    let lit = centre(&floor_under("background { rgb 4 }", "max_sample 1", ""));
    assert!(close(lit, [0.8; 3]), "{lit:?}");
}

#[test]
fn legacy_scenes_keep_ambient_as_a_glow_and_low_quality_turns_radiosity_off() {
    let scene = floor_under("background { rgb 0.5 }", "", "").replace(
        "#version 3.7;",
        "#version 3.6; global_settings { ambient_light 0.5 }",
    );
    let lit = centre(&scene);
    assert!(close(lit, [0.4 + 0.3 * 0.5; 3]), "{lit:?}");
    // Below quality 9 the scene renders as without radiosity: ambient times
    // ambient_light, and no light source.
    let image = render_scene(&floor_under("background { rgb 0.5 }", "", ""), 8);
    let p = image.pixel(12, 9);
    assert!(close([p[0], p[1], p[2]], [0.3; 3]), "{p:?}");
}

#[test]
fn no_radiosity_objects_are_invisible_to_gathering_rays() {
    let roof = "box { <-50, 1, -50>, <50, 2, 50> no_image pigment { rgb 0 } }";
    let covered = centre(&floor_under(
        &format!("background {{ rgb 0.5 }} {roof}"),
        "",
        "",
    ));
    assert!(close(covered, [0.0; 3]), "{covered:?}");
    let hidden = roof.replace("no_image", "no_image no_radiosity");
    let open = centre(&floor_under(
        &format!("background {{ rgb 0.5 }} {hidden}"),
        "",
        "",
    ));
    assert!(close(open, [0.4; 3]), "{open:?}");
}

#[test]
fn rays_left_unshaded_by_importance_are_stood_in_for() {
    // The dome is met by every ray but only a fifth of them are shaded: the light must
    // still be all of the dome's.
    let dome = "sphere { 0, 100 hollow pigment { rgb 0.5 } finish { emission 1 diffuse 0 }
                radiosity { importance 0.2 } }";
    let lit = centre(&floor_under(dome, "count 50", ""));
    assert!(close(lit, [0.4; 3]), "{lit:?}");
}

#[test]
fn more_bounces_bring_more_light_into_the_shade() {
    // A floor under a white roof lit from above through a gap: the floor sees the lit
    // roof's underside only after two bounces.
    let room = |limit: u32| {
        format!(
            "#version 3.7;
             global_settings {{ radiosity {{ recursion_limit {limit} count 100 }} }}
             camera {{ location <0, 1, -3> look_at 0 }}
             light_source {{ <0, 10, 0> rgb 1 }}
             plane {{ y, 0 pigment {{ rgb 1 }} finish {{ diffuse 0.8 }} }}
             box {{ <-0.5, 2, -0.5>, <0.5, 2.1, 0.5> pigment {{ rgb 1 }} }}
             box {{ <-20, 0, 3>, <20, 8, 3.2> pigment {{ rgb 1 }} finish {{ diffuse 0.8 }} }}"
        )
    };
    let one = centre(&room(1))[0];
    let two = centre(&room(2))[0];
    assert!(two > one * 1.05, "one bounce {one}, two {two}");
}

#[test]
fn the_picture_is_the_same_on_one_thread_and_on_many() {
    let scene = "#version 3.7;
        global_settings { radiosity { count 30 recursion_limit 2 } }
        camera { location <0, 2, -4> look_at <0, 0.5, 0> }
        light_source { <2, 4, -2> rgb 1 }
        plane { y, 0 pigment { checker rgb 1, rgb <1, 0.3, 0.2> } }
        sphere { <0, 0.7, 0>, 0.7 pigment { rgb <0.3, 0.5, 1> } }
        box { <-3, 0, 1.5>, <3, 3, 1.7> pigment { rgb 0.9 } }";
    let render_on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool");
        pool.install(|| render_scene(scene, 9))
    };
    let one = render_on(1);
    let many = render_on(4);
    assert!(one == many, "the pictures differ");
}

/// The pretrace takes samples where the cache is thin: more for a tighter error bound,
/// more for more bounces, fewer when the adaptive pretrace (`nearest_count`'s second
/// value) stops refining covered areas, and none at all where no surface is diffuse.
#[test]
fn the_pretrace_takes_samples_where_they_are_needed() {
    let room = |settings: &str, diffuse: f64| {
        format!(
            "#version 3.7;
             global_settings {{ radiosity {{ pretrace_end 0.01 {settings} }} }}
             camera {{ location <0, 1.5, -2.5> look_at <0, 1, 0> }}
             light_source {{ <0, 2.5, 0> rgb 1 }}
             box {{ <-3, 0, -3>, <3, 3, 3> inverse pigment {{ rgb 0.8 }} finish {{ diffuse {diffuse} }} }}
             sphere {{ <0.5, 0.5, 0.5>, 0.5 pigment {{ rgb <1, 0.5, 0.2> }} finish {{ diffuse {diffuse} }} }}"
        )
    };
    let plain = samples_taken(&room("", 0.7));
    let tight = samples_taken(&room("error_bound 0.9", 0.7));
    let adaptive = samples_taken(&room("nearest_count 5, 2", 0.7));
    let deep = samples_taken(&room("recursion_limit 3", 0.7));
    eprintln!("plain {plain:?} tight {tight:?} adaptive {adaptive:?} deep {deep:?}");
    assert_eq!((plain.len(), deep.len()), (2, 3));
    assert!(plain[0] > 10 && plain[1] > 0, "{plain:?}");
    assert!(tight[0] > plain[0] * 2, "{tight:?} against {plain:?}");
    assert!(adaptive[0] < plain[0], "{adaptive:?} against {plain:?}");
    assert!(deep[2] > 0, "{deep:?}");
    assert_eq!(samples_taken(&room("", 0.0)), [0, 0]);
}

/// The samples the pretrace of `text` takes for a 64 × 48 picture, depth by depth, on
/// `threads` threads.
fn samples_on(text: &str, threads: usize) -> Vec<Vec<super::cache::Sample>> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    let radiosity = pool.install(|| pretraced(text));
    radiosity
        .caches
        .iter()
        .map(|c| c.samples().to_vec())
        .collect()
}

/// A box and a sphere on a checkered floor under the sky, lit by radiosity with
/// `recursion_limit` `limit`.
fn floor_box_and_sphere(limit: u32) -> String {
    format!(
        "#version 3.7;
         global_settings {{ radiosity {{ count 40 recursion_limit {limit} }} }}
         camera {{ location <0, 1, -4> look_at <0, 1, 0> }}
         light_source {{ <2, 6, -3> rgb 1 }}
         background {{ rgb <0.4, 0.6, 1> }}
         plane {{ y, 0 pigment {{ checker rgb 1, rgb <1, 0.4, 0.2> }} }}
         box {{ <-1, 0, -0.5>, <1, 0.8, 0.5> rotate y * 30 pigment {{ rgb 0.8 }} }}
         sphere {{ <1.5, 0.5, -1>, 0.5 pigment {{ rgb <0.2, 0.5, 1> }} }}"
    )
}

#[test]
fn gathers_shared_with_a_free_thread_take_the_samples_one_thread_takes() {
    // The upper half of the picture is sky: the first unit of a round whose rays cross
    // the horizon, those through the upper pixels, ends early, and its thread shares the
    // other's gathers.
    for limit in [1, 2, 3] {
        let scene = floor_box_and_sphere(limit);
        let one = samples_on(&scene, 1);
        assert!(one.iter().all(|depth| !depth.is_empty()), "{limit}");
        for _ in 0..4 {
            assert!(samples_on(&scene, 2) == one, "recursion_limit {limit}");
        }
    }
}

/// Takes up the other half of a shared gather at once, tracing it before this half as a
/// faster thread would: its rays never see this half's samples.
struct TakenFirst;

impl super::split::Offer for TakenFirst {
    fn join<A: Send, B: Send>(
        mine: impl FnOnce() -> A + Send,
        theirs: impl FnOnce() -> B + Send,
    ) -> (A, Option<B>) {
        let theirs = theirs();
        (mine(), Some(theirs))
    }
}

/// Takes up the other half of a shared gather after this half is traced: it stops at
/// once if this half took a sample.
struct TakenLast;

impl super::split::Offer for TakenLast {
    fn join<A: Send, B: Send>(
        mine: impl FnOnce() -> A + Send,
        theirs: impl FnOnce() -> B + Send,
    ) -> (A, Option<B>) {
        let mine = mine();
        (mine, Some(theirs()))
    }
}

/// Never takes up the other half, as when no thread is free: one thread's results.
struct Declined;

impl super::split::Offer for Declined {
    fn join<A: Send, B: Send>(
        mine: impl FnOnce() -> A + Send,
        _: impl FnOnce() -> B + Send,
    ) -> (A, Option<B>) {
        (mine(), None)
    }
}

/// What gathers at points across the floor of `text` bring back, one gather after another
/// on one pretrace tracer with their shares offered as `O` offers them, and the samples
/// they take, depth by depth.
fn gathers_offered<O: super::split::Offer>(
    text: &str,
) -> (Vec<super::gather::Gathered>, Vec<Vec<super::cache::Sample>>) {
    let world = built(&evaluate(text));
    let radiosity = world.radiosity.as_ref().expect("radiosity");
    let shared = radiosity.empty_caches();
    // No unit has finished, so the gathers deeper down stay on this thread.
    let finished = AtomicUsize::new(0);
    let mut tracer = Tracer::new(&world);
    tracer.radiosity = Some(super::Walk::filling(radiosity, &shared, &finished));
    let mut gathered = Vec::new();
    for i in 0..32 {
        let p = DVec3::new(
            f64::from(i % 8) * 0.5 - 2.0,
            0.0,
            f64::from(i / 8) * 0.5 - 2.0,
        );
        let rays = super::gather::GatherRays::new(&world, radiosity, p, DVec3::Y, 1, 0);
        let directions: Vec<DVec3> = radiosity.directions.gather(i as u64).collect();
        // Offered even after a gather that took samples, which a render keeps whole.
        if let Some(walk) = &mut tracer.radiosity {
            walk.quiet = true;
        }
        tracer.gather_shared::<O>(&rays, &directions, &mut gathered);
    }
    let walk = tracer.radiosity.take().expect("the tracer's walk");
    let samples = walk.into_own_samples();
    (
        gathered,
        samples.iter().map(|c| c.samples().to_vec()).collect(),
    )
}

#[test]
fn a_gather_whose_share_is_taken_up_brings_back_what_one_thread_does() {
    // Whether a free thread takes up a share depends on timing; here it always does,
    // before or after this half, and the results must be those of a gather never shared.
    for limit in [1, 2, 3] {
        let scene = floor_box_and_sphere(limit);
        let alone = gathers_offered::<Declined>(&scene);
        assert!(alone.1.iter().all(|depth| !depth.is_empty()), "{limit}");
        let first = gathers_offered::<TakenFirst>(&scene);
        assert!(first == alone, "taken up first, recursion_limit {limit}");
        let last = gathers_offered::<TakenLast>(&scene);
        assert!(last == alone, "taken up last, recursion_limit {limit}");
    }
}
