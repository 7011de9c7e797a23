//! The `povrayst` command as a process: `render` writes whole PNG files with the options
//! of the Typst package, `check` prints gcc-style reports, and the exit status says what
//! happened (0 fine, 1 scene errors, 2 usage or I/O errors).

use expect_test::expect;
use std::path::Path;
use std::process::{Command, Output};
use tests::povrayst_binary;

const SPHERE: &str = "background { color rgbt <0, 0, 0, 1> }
camera { location <0, 0, -4> look_at 0 angle 40 }
light_source { <3, 4, -5> rgb 1 }
sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }
";

fn povrayst(dir: &Path, args: &[&str]) -> Output {
    Command::new(povrayst_binary())
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Width, height and colour type of a PNG file.
fn png_info(path: &Path) -> (u32, u32, png::ColorType) {
    let decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let info = decoder.read_info().unwrap().info().clone();
    (info.width, info.height, info.color_type)
}

fn scene_dir(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        std::fs::write(dir.path().join(name), text).unwrap();
    }
    dir
}

#[test]
fn render_writes_a_png_of_the_requested_size() {
    let dir = scene_dir(&[("scene.pov", SPHERE)]);
    let output = povrayst(
        dir.path(),
        &["render", "scene.pov", "--width", "40", "--height", "30"],
    );
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(
        png_info(&dir.path().join("scene.png")),
        (40, 30, png::ColorType::Rgb)
    );

    let output = povrayst(
        dir.path(),
        &[
            "render",
            "scene.pov",
            "-o",
            "alpha.png",
            "--width",
            "20",
            "--height",
            "10",
            "--output-alpha",
        ],
    );
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(
        png_info(&dir.path().join("alpha.png")),
        (20, 10, png::ColorType::Rgba)
    );
}

#[test]
fn render_prints_debug_output_and_warnings() {
    let dir = scene_dir(&[("scene.pov", "#debug \"rendering\\n\"\nsphere { 0, 1 }\n")]);
    let output = povrayst(
        dir.path(),
        &["render", "scene.pov", "--width", "4", "--height", "3"],
    );
    assert_eq!(output.status.code(), Some(0));
    expect![[r#"
        rendering
        scene.pov:1:1: warning: this scene has no #version directive; assuming #version 3.7
            1 | #debug "rendering\n"
              | ^
        note: add `#version 3.7;` as the scene's first line
        scene.pov:1:1: warning: assumed_gamma is not set, so colours are not gamma corrected, as in scenes older than POV-Ray 3.7
            1 | #debug "rendering\n"
              | ^
        note: add `assumed_gamma 1.0` to global_settings
    "#]]
    .assert_eq(&stderr(&output));
}

#[test]
fn extra_options_come_after_the_flags() {
    let dir = scene_dir(&[("scene.pov", SPHERE)]);
    let args = [
        "render",
        "scene.pov",
        "--width",
        "40",
        "--extra",
        "+W16",
        "--extra",
        "Height=8",
    ];
    let output = povrayst(dir.path(), &args);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(png_info(&dir.path().join("scene.png")).0, 16);
    assert_eq!(png_info(&dir.path().join("scene.png")).1, 8);
}

#[test]
fn a_failed_render_leaves_the_output_alone() {
    let dir = scene_dir(&[("scene.pov", "sphere { 0, Radius }\n")]);
    std::fs::write(dir.path().join("scene.png"), b"the previous picture").unwrap();
    let output = povrayst(
        dir.path(),
        &["render", "scene.pov", "--width", "8", "--height", "6"],
    );
    assert_eq!(output.status.code(), Some(1));
    expect![[r#"
        scene.pov:1:13: error: undeclared identifier 'Radius'
            1 | sphere { 0, Radius }
              |             ^~~~~~
    "#]]
    .assert_eq(&stderr(&output));
    assert_eq!(
        std::fs::read(dir.path().join("scene.png")).unwrap(),
        b"the previous picture"
    );
    let leftovers: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(leftovers.len(), 2, "no temporary file is left behind");
}

#[test]
fn usage_errors_exit_with_2() {
    let dir = scene_dir(&[("scene.pov", SPHERE)]);
    let cases = [
        &["render", "scene.pov", "--aa-depth", "10"][..],
        &["render", "scene.pov", "--extra", "Frobnicate=on"],
        &["render", "missing.pov"],
        &["check", "missing.pov"],
        &[
            "render",
            "scene.pov",
            "-o",
            "no/such/dir/out.png",
            "--width",
            "4",
            "--height",
            "3",
        ],
    ];
    let reports: Vec<String> = cases
        .iter()
        .map(|args| {
            let output = povrayst(dir.path(), args);
            assert_eq!(output.status.code(), Some(2), "{args:?}");
            let text = stderr(&output);
            let said = text
                .lines()
                .find(|line| line.starts_with("error:") || line.starts_with("povrayst:"))
                .unwrap_or_default()
                .to_owned();
            format!("{}: {said}", args.join(" "))
        })
        .collect();
    expect![[r#"
        render scene.pov --aa-depth 10: error: invalid value '10' for '--aa-depth <aa-depth>': expected an integer from 1 to 9, or none
        render scene.pov --extra Frobnicate=on: povrayst: --extra: option `Frobnicate=on`: unknown option
        render missing.pov: povrayst: cannot read missing.pov: No such file or directory (os error 2)
        check missing.pov: povrayst: cannot read missing.pov: No such file or directory (os error 2)
        render scene.pov -o no/such/dir/out.png --width 4 --height 3: povrayst: cannot write no/such/dir/out.png: No such file or directory (os error 2)"#]].assert_eq(&reports.join("\n"));
}

#[test]
fn check_reports_every_file_and_its_debug_output() {
    let dir = scene_dir(&[
        (
            "good.pov",
            "#version 3.7; global_settings { assumed_gamma 1 }\n#debug \"hello\\n\"\nsphere { 0, 1 }\n",
        ),
        (
            "bad.pov",
            "#version 3.7;\n#include \"shapes.inc\"\nsphere { 0, Size }\n",
        ),
        ("shapes.inc", "#declare Sise = 1;\n"),
    ]);
    let output = povrayst(dir.path(), &["check", "good.pov"]);
    assert_eq!(output.status.code(), Some(0));
    expect![[r#"
        hello
    "#]]
    .assert_eq(&stderr(&output));
    let output = povrayst(dir.path(), &["check", "good.pov", "bad.pov"]);
    assert_eq!(output.status.code(), Some(1));
    expect![[r#"
        hello
        bad.pov:3:13: error: undeclared identifier 'Size'
            3 | sphere { 0, Size }
              |             ^~~~
        note: did you mean 'Sise'?
        checked 2 scenes: 1 error, 0 warnings
    "#]]
    .assert_eq(&stderr(&output));
}

/// `check` answers `trace()`, `inside()`, the extents and the `object` pattern with the
/// renderer's shapes, as a render does, instead of refusing scenes that ask them.
#[test]
fn check_answers_geometric_queries_as_a_render_does() {
    let dir = scene_dir(&[(
        "scene.pov",
        "#version 3.7; global_settings { assumed_gamma 1 }\n\
         #declare S = sphere { 0, 1 }\n\
         #declare P = trace(S, <0, 0, -5>, z);\n\
         #declare F = function { pattern { object { S } } }\n\
         #debug concat(vstr(3, P, \",\", 0, 1), \" \", str(inside(S, 0), 0, 0), \
         str(F(0, 0, 0), 0, 0), \" \", vstr(3, max_extent(S), \",\", 0, 0), \"\\n\")\n\
         object { S pigment { object { S rgb 0, rgb 1 } } }\n",
    )]);
    let output = povrayst(dir.path(), &["check", "scene.pov"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(stderr(&output), "0.0,0.0,-1.0 11 1,1,1\n");
}

#[test]
fn latin1_scenes_and_includes_are_read_as_povray_reads_them() {
    let dir = scene_dir(&[]);
    // "é" as the single byte 0xE9: not UTF-8, as many scenes written for POV-Ray are.
    std::fs::write(
        dir.path().join("scene.pov"),
        b"#version 3.7; global_settings { assumed_gamma 1 }\n// caf\xe9\n#include \"grass.inc\"\n#debug concat(Name, \"\\n\")\n",
    )
    .unwrap();
    std::fs::write(
        dir.path().join("grass.inc"),
        b"#declare Name = \"pr\xe9\";\n",
    )
    .unwrap();
    let output = povrayst(dir.path(), &["check", "scene.pov"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    assert_eq!(stderr(&output), "pr\u{e9}\n");
}

#[test]
fn includes_come_from_the_scene_directory_and_library_paths() {
    let dir = scene_dir(&[]);
    let scenes = dir.path().join("scenes");
    let library = dir.path().join("library");
    std::fs::create_dir_all(&scenes).unwrap();
    std::fs::create_dir_all(&library).unwrap();
    std::fs::write(
        scenes.join("scene.pov"),
        "#version 3.7;\n#include \"local.inc\"\n#include \"shared.inc\"\nsphere { 0, A + B }\n",
    )
    .unwrap();
    std::fs::write(scenes.join("local.inc"), "#declare A = 1;\n").unwrap();
    std::fs::write(library.join("shared.inc"), "#declare B = 1;\n").unwrap();
    let output = povrayst(dir.path(), &["check", "scenes/scene.pov"]);
    assert_eq!(
        output.status.code(),
        Some(1),
        "shared.inc is not found without -L"
    );
    let output = povrayst(dir.path(), &["check", "-L", "library", "scenes/scene.pov"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
}

#[test]
fn syntax_prints_the_tree_and_its_errors() {
    let dir = scene_dir(&[
        ("good.pov", "sphere { 0, 1 }\n"),
        ("bad.pov", "sphere { 0, 1\n"),
    ]);
    let output = povrayst(dir.path(), &["syntax", "good.pov"]);
    assert_eq!(output.status.code(), Some(0), "{}", stderr(&output));
    let tree = String::from_utf8(output.stdout).unwrap();
    assert!(tree.starts_with("SOURCE_FILE@0..16\n"), "{tree}");
    assert!(tree.contains("SPHERE_KW@0..6 \"sphere\""), "{tree}");
    let output = povrayst(dir.path(), &["syntax", "bad.pov"]);
    assert_eq!(output.status.code(), Some(1));
    expect![[r#"
        bad.pov:1:8: error: unclosed '{'
            1 | sphere { 0, 1
              |        ^
    "#]]
    .assert_eq(&stderr(&output));
}

#[test]
fn files_a_scene_writes_land_beside_it_and_nowhere_else() {
    let scene = format!(
        "#version 3.7;\n#fopen F \"data.txt\" write\n#write (F, \"1, 2\\n\")\n#fclose F\n\
         #fopen G \"../escape.txt\" write\n#write (G, \"no\")\n#fclose G\n{SPHERE}"
    );
    let dir = scene_dir(&[("scene.pov", &scene)]);
    let output = povrayst(
        dir.path(),
        &["render", "scene.pov", "--width", "8", "--height", "8"],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(
        std::fs::read_to_string(dir.path().join("data.txt")).unwrap(),
        "1, 2\n"
    );
    assert!(!dir.path().join("../escape.txt").exists());
    assert!(
        stderr(&output).contains("not writing '../escape.txt'"),
        "{}",
        stderr(&output)
    );
}
