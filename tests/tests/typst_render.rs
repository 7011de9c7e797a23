//! Renders through the Typst package and the real Typst compiler: the image it hands Typst
//! (size, channels, alpha, partial renders), the options that reach the renderer, includes,
//! messages, the show rule, and the exact text of scene errors.

use expect_test::expect;
use serde_json::Value;
use tests::typst_compiler::Document;

const IMPORT: &str = "#import \"@local/povrayst:0.1.0\": *\n";

/// A small lit sphere on a transparent background, centred.
const SPHERE: &str = "background { color rgbt <0, 0, 0, 1> }
camera { location <0, 0, -4> look_at 0 angle 40 }
light_source { <3, 4, -5> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
";

/// What `try-render(scene, ARGS)` produced, as seen from Typst: size, encoding, the alpha
/// of the top-left and centre pixels, the rows with any non-zero sample (how many, and the
/// first), and the error text.
fn probe(scene: &str, args: &str) -> Value {
    let doc = Document::new(&format!(
        "{IMPORT}#let scene = read(\"scene.pov\")
#let r = try-render(scene{args})
#let channels = if r.encoding == \"rgba8\" {{ 4 }} else {{ 3 }}
#let sample(x, y, c) = r.pixels.at((y * r.width + x) * channels + c)
#let lit = if r.error != none {{ () }} else {{
  range(r.height).filter(y => range(r.width * channels).any(i => r.pixels.at(y * r.width * channels + i) != 0))
}}
#metadata((
  width: r.width, height: r.height, encoding: r.encoding, error: r.error,
  bytes: if r.pixels != none {{ r.pixels.len() }},
  corner-rgb: if r.error == none {{ range(3).map(c => sample(0, 0, c)) }},
  corner-alpha: if r.error == none and channels == 4 {{ sample(0, 0, 3) }},
  centre-alpha: if r.error == none and channels == 4 {{ sample(calc.quo(r.width, 2), calc.quo(r.height, 2), 3) }},
  lit-rows: lit.len(),
  first-lit-row: lit.at(0, default: none),
)) <result>
"
    ))
    .with_file("scene.pov", scene);
    doc.query("<result>").expect("the probe document compiles")
}

#[test]
fn an_opaque_render_is_rgb_of_the_requested_size() {
    let result = probe(SPHERE, ", width: 32, height: 24");
    assert_eq!(result["error"], Value::Null);
    assert_eq!(result["width"], 32);
    assert_eq!(result["height"], 24);
    assert_eq!(result["encoding"], "rgb8");
    assert_eq!(result["bytes"], 32 * 24 * 3);
    // Without output-alpha a transparent background is opaque black, as in POV-Ray.
    assert_eq!(result["corner-rgb"], serde_json::json!([0, 0, 0]));
}

#[test]
fn output_alpha_keeps_a_transparent_background() {
    let result = probe(SPHERE, ", width: 32, height: 24, output-alpha: true");
    assert_eq!(result["encoding"], "rgba8");
    assert_eq!(result["bytes"], 32 * 24 * 4);
    assert_eq!(result["corner-alpha"], 0);
    assert_eq!(result["centre-alpha"], 255);
}

#[test]
fn extra_options_come_after_the_arguments_and_win() {
    let result = probe(
        SPHERE,
        ", width: 32, height: 24, extra: (\"+W20\", \"Height=10\")",
    );
    assert_eq!(
        (result["width"].clone(), result["height"].clone()),
        (20.into(), 10.into())
    );
}

/// A scene that covers every pixel, so that the rows drawn are the rows with colour.
const FULL: &str = "background { rgb 1 }\ncamera { location -4*z look_at 0 }\n";

#[test]
fn a_partial_render_draws_only_its_rows() {
    let full = probe(FULL, ", width: 32, height: 24");
    let pixels = probe(FULL, ", width: 32, height: 24, start-row: 9, end-row: 16");
    // POV-Ray 3.7 renders rows 10 to 24 for `Start_Row=0.375 End_Row=1.0` at this size.
    let fraction = probe(
        FULL,
        ", width: 32, height: 24, start-row: 0.375, end-row: 1.0",
    );
    let rows = |result: &Value| (result["first-lit-row"].clone(), result["lit-rows"].clone());
    assert_eq!(rows(&full), (0.into(), 24.into()));
    assert_eq!(rows(&pixels), (8.into(), 8.into()));
    assert_eq!(rows(&fraction), (9.into(), 15.into()));
    assert_eq!(
        (pixels["width"].clone(), pixels["height"].clone()),
        (32.into(), 24.into())
    );
}

#[test]
fn none_keeps_povray_defaults_and_every_argument_is_accepted() {
    let args = ", width: 16, height: 12, quality: none, antialias: none, aa-threshold: 0.2, \
        aa-method: 1, aa-depth: 2, aa-jitter: false, aa-jitter-amount: 0.5, aa-gamma: 2.2, \
        display-gamma: \"srgb\", file-gamma: 1.0, max-trace-level: 4, bounding: true, \
        bounding-threshold: 3, remove-bounds: true, split-unions: false, start-column: 1, \
        end-column: 1.0, output-alpha: none, compression: 6, includes: (:), files: (:)";
    let result = probe(SPHERE, args);
    assert_eq!(result["error"], Value::Null, "{result}");
    assert_eq!(result["encoding"], "rgb8");
}

/// A PNG of `width` by `height` RGB pixels.
fn png_bytes(width: u32, height: u32, rgb: &[u8]) -> Vec<u8> {
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(rgb).unwrap();
    writer.finish().unwrap();
    bytes
}

#[test]
fn an_image_map_from_files_colours_the_render() {
    // Red on the left, blue on the right, filling the view; `#fopen` reads a text file
    // passed the same way.
    let doc = Document::new(&format!(
        "{IMPORT}#let r = try-render(read(\"scene.pov\"), width: 4, height: 2, antialias: false,
  files: (\"map.png\": read(\"map.png\", encoding: none), \"size.txt\": read(\"size.txt\")))
#metadata((error: r.error, pixels: array(r.pixels))) <result>
"
    ))
    .with_file(
        "scene.pov",
        "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n#fopen F \"size.txt\" read\n#read (F, S)\n\
         camera { orthographic location <0.5, 0.5, -1> look_at <0.5, 0.5, 0> right x * S up y * S / 2 }\n\
         plane { -z, 0 pigment { image_map { png \"map.png\" } } finish { ambient 1 diffuse 0 } }\n",
    )
    .with_file("map.png", png_bytes(2, 1, &[255, 0, 0, 0, 0, 255]))
    .with_file("size.txt", "1\n");
    let result = doc.query("<result>").unwrap();
    assert_eq!(result["error"], Value::Null, "{result}");
    let red = [255, 0, 0];
    let blue = [0, 0, 255];
    let expected: Vec<u8> = [red, red, blue, blue, red, red, blue, blue].concat();
    assert_eq!(result["pixels"], serde_json::json!(expected));
}

#[test]
fn includes_are_read_by_the_evaluator() {
    let doc = Document::new(&format!(
        "{IMPORT}#let r = try-render(read(\"scene.pov\"), width: 8, height: 6,
  includes: (\"materials.inc\": read(\"materials.inc\"), \"inner.inc\": \"#declare R = 1;\"))
#metadata(r.error) <result>
"
    ))
    .with_file(
        "scene.pov",
        "#include \"materials.inc\"\ncamera { location -4*z look_at 0 }\nsphere { 0, R texture { Copper } }\n",
    )
    .with_file(
        "materials.inc",
        "#include \"inner.inc\"\n#declare Copper = texture { pigment { rgb <0.8, 0.4, 0.2> } }\n",
    );
    assert_eq!(doc.query("<result>").unwrap(), Value::Null);
}

#[test]
fn warnings_reach_typst_as_text() {
    let doc = Document::new(&format!(
        "{IMPORT}#metadata(try-render(read(\"scene.pov\"), width: 4, height: 3).warnings) <result>\n"
    ))
    .with_file("scene.pov", "#version 3.7; global_settings { assumed_gamma 1 }\n#warning \"careful\"\nsphere { 0, 1 }\n");
    expect![[r#"
        scene.pov:2:1: warning: careful
            2 | #warning "careful"
              | ^
    "#]]
    .assert_eq(doc.query("<result>").unwrap().as_str().unwrap());
}

#[test]
fn standard_includes_need_no_setup() {
    let scene = "#include \"colors.inc\"\ncamera { location -4*z look_at 0 }\nsphere { 0, 1 pigment { color Orange } }\n";
    assert_eq!(probe(scene, ", width: 8, height: 6")["error"], Value::Null);
}

#[test]
fn messages_returns_the_debug_output() {
    let doc = Document::new(&format!(
        "{IMPORT}#metadata(messages(\"#debug \\\"one\\\\n\\\"\\n#declare N = 2;\\n#debug concat(\\\"N = \\\", str(N, 0, 0), \\\"\\\\n\\\")\\nsphere {{ 0, 1 }}\", width: 4, height: 3)) <result>\n"
    ));
    expect![[r#"[{"stream":"debug","text":"one\n"},{"stream":"debug","text":"N = 2\n"}]"#]]
        .assert_eq(&doc.query("<result>").unwrap().to_string());
}

#[test]
fn the_show_rule_renders_povray_blocks() {
    let doc = Document::new(&format!(
        "{IMPORT}#set page(width: auto, height: auto)
#show raw.where(lang: \"povray\"): it => pov(it, width: 8, height: 6)
```povray
camera {{ location -4*z look_at 0 }}
sphere {{ 0, 1 pigment {{ rgb 1 }} }}
```
#context [#metadata(query(image).len()) <result>]
"
    ));
    assert_eq!(doc.query("<result>").unwrap(), 1);
    let plain = Document::new(&format!(
        "{IMPORT}#show raw.where(lang: \"povray\"): pov\n```povray\nsphere {{ 0, 1 }}\n```\n"
    ));
    plain
        .compile()
        .expect("a povray block with the default options renders");
}

/// The message of rendering `scene` (with `args`) in a document, without the list of
/// standard includes, which grows as they are written.
fn render_error(scene: &str, args: &str) -> String {
    let message = Document::new(&format!("{IMPORT}#render(read(\"scene.pov\"){args})\n"))
        .with_file("scene.pov", scene)
        .compile_error();
    let lines: Vec<&str> = message
        .lines()
        .filter(|line| !line.starts_with("note: standard includes:"))
        .collect();
    lines.join("\n")
}

#[test]
fn scene_errors_are_the_gcc_style_report() {
    let cases = [
        ("unclosed brace", "sphere { 0, 1\n  pigment { rgb 1 }\n", ""),
        (
            "undeclared identifier",
            "#declare Radius = 1;\nsphere { 0, Raduis }\n",
            "",
        ),
        ("missing #end", "#if (1)\n  sphere { 0, 1 }\n", ""),
        (
            "#error",
            "#declare N = 3;\n#error concat(\"N is \", str(N, 0, 0))\n",
            "",
        ),
        (
            "missing include",
            "#include \"materials.inc\"\n",
            ", includes: (\"other.inc\": \"\")",
        ),
        (
            "error inside an include",
            "#include \"materials.inc\"\nsphere { 0, 1 texture { Copper } }\n",
            ", includes: (\"materials.inc\": \"#declare Copper = texture {\\n  pigment { color\\n  rgb Tint }\\n}\\n\")",
        ),
        (
            "include cycle",
            "#include \"a.inc\"\n",
            ", includes: (\"a.inc\": \"#include \\\"b.inc\\\"\\n\", \"b.inc\": \"#include \\\"a.inc\\\"\\n\")",
        ),
        (
            "missing image",
            "plane { -z, 0 pigment { image_map { png \"missing.png\" } } }\n",
            ", files: (\"map.png\": bytes((137, 80, 78, 71)), \"data.txt\": \"1, 2\")",
        ),
        (
            "corrupt image",
            "plane { -z, 0 pigment { image_map { png \"map.png\" } } }\n",
            ", files: (\"map.png\": bytes((137, 80, 78, 71)))",
        ),
        (
            "unknown extra option",
            "sphere { 0, 1 }\n",
            ", extra: (\"+A0.1\", \"Frobnicate=on\")",
        ),
    ];
    let reports: Vec<String> = cases
        .iter()
        .map(|(what, scene, args)| format!("--- {what}\n{}", render_error(scene, args)))
        .collect();
    expect![[r#"
        --- unclosed brace
        plugin errored with: scene.pov:1:8: error: unclosed '{'
            1 | sphere { 0, 1
              |        ^
        --- undeclared identifier
        plugin errored with: scene.pov:2:13: error: undeclared identifier 'Raduis'
            2 | sphere { 0, Raduis }
              |             ^~~~~~
        note: did you mean 'Radius'?
        --- missing #end
        plugin errored with: scene.pov:1:1: error: #if has no matching #end
            1 | #if (1)
              | ^~~
        --- #error
        plugin errored with: scene.pov:2:1: error: N is 3
            2 | #error concat("N is ", str(N, 0, 0))
              | ^
        --- missing include
        plugin errored with: scene.pov:1:10: error: cannot find include file 'materials.inc'
            1 | #include "materials.inc"
              |          ^~~~~~~~~~~~~~~
        note: files available: other.inc
        --- error inside an include
        plugin errored with: materials.inc:3:7: error: undeclared identifier 'Tint'
            3 |   rgb Tint }
              |       ^~~~
        scene.pov:1:10: note: in 'materials.inc' included here
            1 | #include "materials.inc"
              |          ^~~~~~~~~~~~~~~
        --- include cycle
        plugin errored with: b.inc:1:10: error: include cycle: a.inc -> b.inc -> a.inc
            1 | #include "a.inc"
              |          ^~~~~~~
        a.inc:1:10: note: in 'b.inc' included here
            1 | #include "b.inc"
              |          ^~~~~~~
        scene.pov:1:10: note: in 'a.inc' included here
            1 | #include "a.inc"
              |          ^~~~~~~
        --- missing image
        plugin errored with: scene.pov:1:41: error: cannot find image file 'missing.png'
            1 | plane { -z, 0 pigment { image_map { png "missing.png" } } }
              |                                         ^~~~~~~~~~~~~
        note: files available: map.png
        --- corrupt image
        plugin errored with: scene.pov:1:41: error: cannot read 'map.png': not a valid PNG file: unexpected end of file
            1 | plane { -z, 0 pigment { image_map { png "map.png" } } }
              |                                         ^~~~~~~~~
        --- unknown extra option
        plugin errored with: extra: option `Frobnicate=on`: unknown option"#]]
    .assert_eq(&reports.join("\n"));
}

/// Photons in the plugin: the reflective caustic scene renders through Typst (wasm,
/// interpreted) to the same pixels as natively on every core. The photon map is
/// seeded from each photon's place in its spiral, never from timing, so neither the
/// thread count nor the platform changes it.
#[test]
fn photon_caustics_render_the_same_in_typst_and_natively() {
    renders_the_same_in_typst_and_natively("photons-reflect");
}

/// Subsurface light in the plugin: the marble and wax scene renders through Typst to the
/// same pixels as natively. Its probe rays are seeded from the point they start from.
#[test]
fn subsurface_light_renders_the_same_in_typst_and_natively() {
    renders_the_same_in_typst_and_natively("subsurface");
}

/// Renders the manifest's scene `name` at 96 × 72 without antialiasing natively and in a
/// Typst document, and asserts that every channel of every pixel is the same.
fn renders_the_same_in_typst_and_natively(name: &str) {
    let scenes = tests::fidelity::manifest();
    let mut scene = scenes.iter().find(|s| s.name == name).unwrap().clone();
    scene.options = ["+W96", "+H72", "-A"].map(String::from).to_vec();
    let native = scene.render_with(&scene.source()).unwrap();
    let doc = Document::new(&format!(
        "{IMPORT}#let r = try-render(read(\"scene.pov\"), width: 96, height: 72, antialias: false)
#metadata((error: r.error, encoding: r.encoding, pixels: array(r.pixels))) <result>
"
    ))
    .with_file("scene.pov", scene.source());
    let result = doc.query("<result>").unwrap();
    assert_eq!(result["error"], Value::Null);
    assert_eq!(result["encoding"], "rgb8");
    let typst: Vec<u8> = result["pixels"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_u64().unwrap() as u8)
        .collect();
    let ours: Vec<u8> = native
        .pixels
        .iter()
        .flat_map(|p| [p[0], p[1], p[2]].map(|c| (c * 255.0).round() as u8))
        .collect();
    assert_eq!(typst.len(), ours.len());
    let differing = typst.iter().zip(&ours).filter(|(a, b)| a != b).count();
    assert_eq!(
        differing,
        0,
        "{differing} of {} channels differ",
        ours.len()
    );
}
