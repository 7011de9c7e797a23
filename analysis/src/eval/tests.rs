//! Evaluator tests: small scenes in, `#debug` text, scene entities or errors out.

use super::*;
use crate::files::MemoryFiles;
use crate::scene::{Shape, Texture};
use expect_test::{Expect, expect};

fn eval(text: &str) -> Evaluation {
    let files = MemoryFiles::new().with("scene.pov", text);
    evaluate("scene.pov", &files, &EvalOptions::default())
}

/// Every diagnostic of a scene text, rendered as the front ends print them.
pub(super) fn check_diagnostics(text: &str, expect: Expect) {
    let evaluation = eval(text);
    expect.assert_eq(&syntax::diagnostic::render_human(
        &evaluation.diagnostics,
        &evaluation.sources,
    ));
}

/// The evaluation of a 3.7 scene text.
pub(super) fn evaluate_37(text: &str) -> Evaluation {
    eval(&format!("#version 3.7;\n{text}"))
}

/// The scene a 3.7 scene text describes; panics with the diagnostics if it has errors.
pub(super) fn evaluate_ok(text: &str) -> Scene {
    let evaluation = evaluate_37(text);
    match evaluation.scene {
        Some(scene) if !evaluation.has_errors() => scene,
        _ => panic!("{:?}", evaluation.diagnostics),
    }
}

/// The message of the error that stops a 3.7 scene text; panics when there is none.
pub(super) fn evaluate_err(text: &str) -> String {
    let evaluation = evaluate_37(text);
    match evaluation.diagnostics.iter().find(|d| d.is_error()) {
        Some(error) => error.message.clone(),
        None => panic!("no error in {text}"),
    }
}

/// The `#debug` output, or the rendered error.
pub(super) fn check_debug(text: &str, expect: Expect) {
    let evaluation = evaluate_37(text);
    let errors: Vec<_> = evaluation
        .diagnostics
        .iter()
        .filter(|d| d.is_error())
        .cloned()
        .collect();
    let out = if errors.is_empty() {
        evaluation.debug_text()
    } else {
        syntax::diagnostic::render_human(&errors, &evaluation.sources)
    };
    expect.assert_eq(&out);
}

#[test]
fn arithmetic_and_precedence() {
    check_debug(
        r#"#declare A = 1 + 2 * 3 - -4 / 2;
#debug concat(str(A, 0, 3), "\n")
#declare V = <1, 2, 3> * 2 + 1;
#debug concat(vstr(3, V, ",", 0, 1), "\n")
#debug concat(str((1 < 2) + (2 = 2) + (1 ? 5 : 7), 0, 0), "\n")
#debug concat(str(-<2.5, 1, 1>.x, 0, 2), " ", str(int(-3.7), 0, 0), " ", str(mod(-7, 3), 0, 0), "\n")
"#,
        expect![[r#"
            9.000
            3.0,5.0,7.0
            7
            -2.50 -3 -1
        "#]],
    );
}

#[test]
fn macros_loops_and_scopes() {
    check_debug(
        r#"#macro Twice(V) V * 2 #end
#macro Bump(N) #declare N = N + 1; #end
#declare I = 0;
#declare Sum = 0;
#while (I < 4)
  #declare Sum = Sum + Twice(I);
  Bump(I)
#end
#debug concat(str(Sum, 0, 0), " ", str(I, 0, 0), "\n")
#for (K, 10, 1, -3) #debug str(K, 0, 0) #end
#debug "\n"
#switch (2)
  #case (1) #debug "one" #break
  #range (2, 3) #debug "two-three" #break
  #else #debug "other"
#end
#debug "\n"
#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end
#debug concat(str(Fact(5), 0, 0), "\n")
"#,
        expect![[r#"
            12 4
            10741
            two-three
            120
        "#]],
    );
}

#[test]
fn arrays_and_functions() {
    check_debug(
        r#"#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };
#debug concat(str(A[1][2], 0, 0), " ", str(dimension_size(A, 2), 0, 0), "\n")
#declare F = function(a, b) { a * a + b }
#declare G = function { F(x, 2) * y }
#debug concat(str(G(3, 2, 0), 0, 1), "\n")
#declare R = seed(0);
#debug concat(str(rand(R), 0, 9), "\n")
"#,
        expect![[r#"
            6 3
            22.0
            0.000002874
        "#]],
    );
}

#[test]
fn errors_are_located() {
    check_debug(
        "sphere { Foo, 1 }\n",
        expect![[r#"
            scene.pov:2:10: error: undeclared identifier 'Foo'
                2 | sphere { Foo, 1 }
                  |          ^~~
        "#]],
    );
    check_debug(
        "#macro M(A, B) A #end\n#declare X = M(1);\n",
        expect![[r#"
            scene.pov:3:14: error: macro 'M' takes 2 arguments, but 1 were given
                3 | #declare X = M(1);
                  |              ^
            scene.pov:2:8: note: the macro is defined here
                2 | #macro M(A, B) A #end
                  |        ^
        "#]],
    );
    check_debug(
        "#declare I = 0;\n#while (1) #declare I = I + 1; #end\n",
        expect![[r#"
            scene.pov:3:1: error: loop iteration budget of 10000000 exceeded (endless loop?)
                3 | #while (1) #declare I = I + 1; #end
                  | ^
            note: raise the limit with the `max-loop-iterations` option if the scene really needs more
        "#]],
    );
}

#[test]
fn csg_scene_evaluates() {
    let evaluation = eval(include_str!("../../../gallery/csg.pov"));
    let scene = evaluation.scene.expect("csg.pov evaluates");
    assert_eq!(scene.lights.len(), 2);
    assert_eq!(scene.objects.len(), 1);
    let Shape::Csg { children, .. } = &scene.objects[0].shape else {
        panic!("a difference")
    };
    assert_eq!(children.len(), 2);
    assert!(scene.objects[0].texture.is_some());
}

#[test]
fn debug_axes_scene_evaluates() {
    let evaluation = eval(include_str!("../../../gallery/debug-axes.pov"));
    let scene = evaluation.scene.expect("debug-axes.pov evaluates");
    assert_eq!(scene.objects.len(), 1 + 3 * (2 + 3));
    let warnings: Vec<_> = evaluation
        .diagnostics
        .iter()
        .map(|d| d.message.as_str())
        .collect();
    assert_eq!(
        warnings,
        ["this scene has no #version directive; assuming #version 3.7"]
    );
}

#[test]
fn scenes_without_assumed_gamma_get_povrays_warning() {
    // A 3.7 scene is read at gamma 1.0, an older one without gamma handling: POV-Ray 3.7
    // warns of each, at the end of parsing.
    check_diagnostics(
        "#version 3.7;\nsphere { 0, 1 }\n",
        expect![[r#"
            scene.pov:1:1: warning: assumed_gamma is not set in this POV-Ray 3.7 scene; taking assumed_gamma 1.0
                1 | #version 3.7;
                  | ^~~~~~~~
            note: add `assumed_gamma 1.0` to global_settings
        "#]],
    );
    check_diagnostics(
        "sphere { 0, 1 }\n#version 3.6;\n",
        expect![[r#"
            scene.pov:2:1: warning: assumed_gamma is not set, so colours are not gamma corrected, as in scenes older than POV-Ray 3.7
                2 | #version 3.6;
                  | ^~~~~~~~
            note: add `assumed_gamma 1.0` to global_settings
        "#]],
    );
    check_diagnostics(
        "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n",
        expect![""],
    );
}

#[test]
fn basic_scene_camera_follows_mirrored_right() {
    let evaluation = eval(include_str!("../../../gallery/basic.pov"));
    let scene = evaluation.scene.expect("basic.pov evaluates");
    let camera = &scene.camera;
    assert!(
        camera.right.x < 0.0,
        "right stays mirrored: {:?}",
        camera.right
    );
    assert!((camera.right.length() - 1.333).abs() < 1e-9);
    let expected_direction = 0.5 * 1.333 / (35f64.to_radians() / 2.0).tan();
    assert!((camera.direction.length() - expected_direction).abs() < 1e-9);
}

#[test]
fn files_written_can_be_read_back() {
    check_debug(
        r#"#fopen F "data.txt" write
#write (F, "\"name\",", -1.5, ",", <1, 2, 3>, "\n")
#fclose F
#fopen G "data.txt" read
#read (G, S, A, V)
#debug concat(S, " ", str(A, 0, 2), " ", vstr(3, V, ",", 0, 0), "\n")
#debug concat("open after the last item: ", str(defined(G), 0, 0), "\n")
"#,
        expect![[r#"
            name -1.50 1,2,3
            open after the last item: 0
        "#]],
    );
}

/// A stand-in renderer that knows spheres only, to test the calls that ask it. It counts
/// the tracers it prepares.
#[derive(Default)]
pub(super) struct SpheresOnly {
    prepared: std::sync::atomic::AtomicUsize,
}

impl crate::geometry::Geometry for SpheresOnly {
    fn tracer(&self, object: &crate::scene::Object) -> std::result::Result<crate::Tracer, String> {
        let Shape::Sphere { center, radius } = object.shape else {
            return Err("spheres only".into());
        };
        self.prepared
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        Ok(crate::Tracer::new(move |origin, direction| {
            let d = direction.normalize();
            let oc = origin - center;
            let b = oc.dot(d);
            let disc = b * b - (oc.length_squared() - radius * radius);
            if disc < 0.0 {
                return Ok(None);
            }
            let t = -b - disc.sqrt();
            let p = origin + d * t;
            Ok(Some((p, (p - center) / radius)))
        }))
    }

    fn inside_test(
        &self,
        object: &crate::scene::Object,
    ) -> std::result::Result<crate::InsideTest, String> {
        let Shape::Sphere { center, radius } = object.shape else {
            return Err("spheres only".into());
        };
        Ok(crate::InsideTest::new(move |point| {
            (point - center).length() < radius
        }))
    }

    fn extent(
        &self,
        object: &crate::scene::Object,
    ) -> std::result::Result<(glam::DVec3, glam::DVec3), String> {
        let Shape::Sphere { center, radius } = object.shape else {
            return Err("spheres only".into());
        };
        Ok((center - radius, center + radius))
    }
}

#[test]
fn trace_inside_and_extents_ask_the_renderer() {
    let text = r#"#version 3.7;
#declare S = sphere { <0, 1, 0>, 2 }
#declare P = trace(S, <0, 10, 0>, -y, N);
#debug concat(vstr(3, P, ",", 0, 1), " ", vstr(3, N, ",", 0, 1), "\n")
#debug concat(str(inside(S, <0, 2, 0>), 0, 0), str(inside(S, 5), 0, 0), "\n")
#debug concat(vstr(3, min_extent(S), ",", 0, 0), " ", vstr(3, max_extent(S), ",", 0, 0), "\n")
"#;
    let files = MemoryFiles::new().with("scene.pov", text);
    let evaluation = evaluate_with(
        "scene.pov",
        &files,
        &EvalOptions::default(),
        &SpheresOnly::default(),
    );
    expect![[r#"
        0.0,3.0,0.0 0.0,1.0,0.0
        10
        -2,-1,-2 2,3,2
    "#]]
    .assert_eq(&evaluation.debug_text());
    let refused = eval("#declare P = trace(sphere { 0, 1 }, 5, -x);");
    expect![[r#"
        scene.pov:1:14: error: this front end cannot answer geometric queries (trace, inside, extents, object pattern)
            1 | #declare P = trace(sphere { 0, 1 }, 5, -x);
              |              ^~~~~
    "#]]
    .assert_eq(&syntax::diagnostic::render_human(
        &refused.diagnostics.into_iter().filter(|d| d.is_error()).collect::<Vec<_>>(),
        &refused.sources,
    ));
}

#[test]
fn a_declared_object_is_prepared_for_tracing_once() {
    let text = r#"#version 3.7;
#declare S = sphere { 0, 1 }
#declare Sum = 0;
#for (I, 1, 10)
  #declare Sum = Sum + trace(S, <0, 5, 0>, -y).y;
#end
#declare S = sphere { 0, 2 }
#declare Sum = Sum + trace(S, <0, 5, 0>, -y).y;
#debug concat(str(Sum, 0, 0), "\n")
"#;
    let files = MemoryFiles::new().with("scene.pov", text);
    let geometry = SpheresOnly::default();
    let evaluation = evaluate_with("scene.pov", &files, &EvalOptions::default(), &geometry);
    // Ten rays against the first sphere, one against its redeclared successor.
    assert_eq!(evaluation.debug_text(), "12\n");
    assert_eq!(
        geometry.prepared.load(std::sync::atomic::Ordering::Relaxed),
        2
    );
}

#[test]
fn legacy_forms_still_work() {
    check_debug(
        r#"#macro Hello() #debug "hello\n" #end
#Hello()
declare A = 2;
#debug concat(str(A, 0, 0), "\n")
"#,
        expect![[r#"
            hello
            2
        "#]],
    );
}

/// Inputs the fuzzer found; each once panicked.
const FUZZER_FINDINGS: &[&str] = &["#debug \"before\\n\"##default { sphere { 0, 1 } }"];

#[test]
fn fuzzer_findings_give_located_errors() {
    for text in FUZZER_FINDINGS {
        let evaluation = eval(text);
        syntax::diagnostic::render_human(&evaluation.diagnostics, &evaluation.sources);
    }
}

#[test]
fn texture_map_entries_are_texture_bodies() {
    // POV-Ray 3.7 reads `[value ...]` as the inside of a texture: an identifier and its
    // modifiers, or pigment, normal and finish items; `texture { }` there is an error.
    let scene = evaluate_ok(
        "#declare T = texture { pigment { rgb 1 } }
         sphere { 0, 1 texture { gradient x texture_map {
             [0 T finish { phong 1 }]
             [1 pigment { rgb 0 } normal { bumps 0.3 } scale 2] } } }",
    );
    let texture = scene.objects[0].texture.clone().expect("a texture");
    let Texture::Pattern { map, .. } = &*texture else {
        panic!("not a texture map")
    };
    assert_eq!(map.entries.len(), 2);
    let Texture::Plain { finish, .. } = &map.entries[0].1 else {
        panic!("not a plain texture")
    };
    assert_eq!(finish.phong, 1.0);
    let message = evaluate_err(
        "#declare T = texture { gradient x texture_map { [0 texture { pigment { rgb 1 } }] } }",
    );
    assert!(message.contains("in texture, found"), "{message}");
}

#[test]
fn average_maps_may_leave_out_their_weights() {
    let scene = evaluate_ok(
        "sphere { 0, 1 texture { average texture_map { [pigment { rgb 1 }] [2 finish { phong 1 }] } } }
         sphere { 0, 1 normal { average normal_map { [gradient x, -5 scallop_wave] [bumps 0.5] } } }",
    );
    let texture = scene.objects[0].texture.clone().expect("a texture");
    let Texture::Pattern { map, .. } = &*texture else {
        panic!("not a texture map")
    };
    let weights: Vec<f64> = map.entries.iter().map(|(w, _)| *w).collect();
    assert_eq!(weights, [1.0, 2.0]);
    let normal_texture = scene.objects[1].texture.clone().expect("a texture");
    let Texture::Plain {
        normal: Some(normal),
        ..
    } = &*normal_texture
    else {
        panic!("no normal")
    };
    let crate::scene::NormalKind::Map { map, .. } = &normal.kind else {
        panic!("not a normal map")
    };
    assert_eq!(map.entries.len(), 2);
}

#[test]
fn a_sor_needs_distinct_heights_around_its_end_slopes() {
    // POV-Ray 3.7 stops ("Incorrect point in surface of revolution") when the first and third
    // points, or the last and third from last, are at one height, and accepts any other
    // heights for the first and last points.
    let message = evaluate_err("sor { 5, <0, 2> <1, 1> <1, 2> <1, 3> <0, 4> }");
    assert!(message.contains("different y coordinates"), "{message}");
    evaluate_ok("sor { 5, <0, 2.5> <1, 1> <1, 2> <1, 3> <0, 2.01> }");
}

/// Commas POV-Ray 3.7 lets a scene leave out or put in, as the example scenes do.
#[test]
fn optional_commas_of_the_example_scenes() {
    let scene = evaluate_ok(
        "#macro Second(A, B) B #end
         sphere { 0, Second(sphere { 0, 1 } 2) }
         bicubic_patch { type 1 u_steps 2 v_steps 2,
           <0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>, <0,1,0>,<1,1,0>,<2,1,0>,<3,1,0>,
           <0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>, <0,3,0>,<1,3,0>,<2,3,0>,<3,3,0> }
         sphere { 0, 1 finish { reflection { 0.1 0.9 fresnel on } } }
         text { ttf \"none.ttf\", \"A\", 0.1, 0 }",
    );
    let Some(Texture::Plain { finish, .. }) = scene.objects[2].texture.as_deref() else {
        panic!("a plain texture");
    };
    let reflection = finish.reflection.as_ref().expect("a reflection");
    assert_eq!((reflection.min.rgb.x, reflection.max.rgb.x), (0.1, 0.9));
}

/// `object { Light }` places a declared light; inside a CSG it takes no part in the shape.
#[test]
fn a_light_identifier_is_an_object() {
    let scene = evaluate_ok(
        "#declare Lamp = light_source { <0, 1, 0>, 1 }
         object { Lamp translate x }
         union { sphere { 0, 1 } object { Lamp translate y } }
         intersection { sphere { 0, 1 } object { Lamp } sphere { x, 1 } }",
    );
    let at: Vec<glam::DVec3> = scene.lights.iter().map(|l| l.position).collect();
    assert_eq!(
        at,
        [
            glam::DVec3::new(1.0, 1.0, 0.0),
            glam::DVec3::new(0.0, 2.0, 0.0),
            glam::DVec3::Y
        ]
    );
    let Shape::Csg { children, .. } = &scene.objects[1].shape else {
        panic!("an intersection");
    };
    assert_eq!(children.len(), 2);
}

/// `quick_color` is read after a pattern's colours too.
#[test]
fn quick_color_follows_a_pattern() {
    evaluate_ok("sphere { 0, 1 pigment { checker rgb 1 rgb 0 quick_color rgb 0.5 scale 2 } }");
}

#[test]
fn a_macro_call_after_a_texture_declaration_runs_once_the_texture_is_declared() {
    // The declaration looks past the texture for another layer; screen.inc's Screen_Plane
    // is called right after the texture it is given, as in incdemo/screen.pov.
    check_debug(
        r#"#declare T = texture { pigment { rgb 1 } }
#macro Show(Tex) #local Copy = texture { Tex } #debug "shown\n" #end
Show(T)
#declare L = texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } }
Show(L)
"#,
        expect![[r#"
            shown
            shown
        "#]],
    );
}

#[test]
fn macros_called_one_after_another_in_a_declaration_run_their_own_directives() {
    // shapes.inc's HF macros subtract two calls of a macro whose body starts with #local.
    check_debug(
        r#"#macro Half(K) #local H = K / 2; H #end
#declare A = Half(8) - Half(2);
#debug concat(str(A, 0, 1), "\n")
"#,
        expect![[r#"
            3.0
        "#]],
    );
}

#[test]
fn a_local_takes_the_value_a_macro_leaves_before_its_end() {
    // tracevines.pov: FindTmp's body ends in `Q;`, so the #local in Grow is assigned while
    // FindTmp's scope is still open; it must land in Grow's scope all the same.
    check_debug(
        r#"#macro Find(P) #local Q = P + 1; Q; #end
#macro Grow(P)
  #local Found = Find(P)
  #local Again = Find(Found)
  #debug concat(str(Found, 0, 0), " ", str(Again, 0, 0), "\n")
#end
Grow(4)
#declare G = Find(1)
#debug concat(str(G, 0, 0), "\n")
"#,
        expect![[r#"
            5 6
            2
        "#]],
    );
}

#[test]
fn declared_options_are_globals_the_scene_can_test_and_override() {
    let text = "#version 3.7;\n#ifdef (Photons) #debug str(Photons, 0, 1) #end\n\
                #declare Count = Count + 1; #debug str(Count, 0, 0)";
    let files = MemoryFiles::new().with("scene.pov", text);
    let options = EvalOptions {
        declared: vec![("Photons".into(), 1.0), ("Count".into(), 2.0)],
        ..EvalOptions::default()
    };
    let evaluation = evaluate("scene.pov", &files, &options);
    assert!(!evaluation.has_errors(), "{:?}", evaluation.diagnostics);
    let text: String = evaluation
        .messages
        .iter()
        .map(|m| m.text.as_str())
        .collect();
    assert_eq!(text, "1.03");
}
