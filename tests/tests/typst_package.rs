//! The Typst package through the real Typst compiler, where no rendering is needed: every
//! keyword argument is checked before the plugin runs and a wrong one stops the document
//! with a message that names it; `defaults`, `version()` and syntax highlighting.

use expect_test::expect;
use tests::typst_compiler::Document;

const IMPORT: &str = "#import \"@local/povrayst:0.1.0\": *\n";

/// The message of compiling `#render("sphere { 0, 1 }", ARGS)`.
fn render_error(args: &str) -> String {
    Document::new(&format!("{IMPORT}#render(\"sphere {{ 0, 1 }}\", {args})\n")).compile_error()
}

#[test]
fn every_argument_rejects_a_wrong_type_by_name() {
    let cases = [
        "width: 1.5",
        "height: \"600\"",
        "quality: 12",
        "antialias: 1",
        "aa-threshold: -0.1",
        "aa-method: 4",
        "aa-depth: 0",
        "aa-jitter: \"yes\"",
        "aa-jitter-amount: 1.5",
        "aa-gamma: 0",
        "display-gamma: \"linear\"",
        "file-gamma: -2.2",
        "max-trace-level: 0",
        "bounding: none, remove-bounds: 2",
        "bounding-threshold: -1",
        "split-unions: 0",
        "start-row: 0",
        "end-row: 1.5",
        "start-column: -0.5",
        "end-column: \"all\"",
        "output-alpha: \"on\"",
        "compression: 10",
        "includes: (\"materials.inc\": 3)",
        "includes: \"materials.inc\"",
        "files: (\"map.png\": 3)",
        "extra: 3",
        "extra: (\"+A0.1\", 2)",
        "colour: red",
        "start-row: 10, end-row: 5",
        "start-column: 0.8, end-column: 0.2",
    ];
    let messages: Vec<String> = cases
        .iter()
        .map(|args| format!("{args}\n  {}", render_error(args)))
        .collect();
    expect![[r#"
        width: 1.5
          assertion failed: render: `width` must be an integer from 1 to 16384 (or none), got 1.5
        height: "600"
          assertion failed: render: `height` must be an integer from 1 to 16384 (or none), got "600"
        quality: 12
          assertion failed: render: `quality` must be an integer from 0 to 11 (or none), got 12
        antialias: 1
          assertion failed: render: `antialias` must be true or false (or none), got 1
        aa-threshold: -0.1
          assertion failed: render: `aa-threshold` must be a number of at least 0 (or none), got -0.1
        aa-method: 4
          assertion failed: render: `aa-method` must be 1, 2 or 3 (or none), got 4
        aa-depth: 0
          assertion failed: render: `aa-depth` must be an integer from 1 to 9 (or none), got 0
        aa-jitter: "yes"
          assertion failed: render: `aa-jitter` must be true or false (or none), got "yes"
        aa-jitter-amount: 1.5
          assertion failed: render: `aa-jitter-amount` must be a number from 0 to 1 (or none), got 1.5
        aa-gamma: 0
          assertion failed: render: `aa-gamma` must be a number above 0 or "srgb" (or none), got 0
        display-gamma: "linear"
          assertion failed: render: `display-gamma` must be a number above 0 or "srgb" (or none), got "linear"
        file-gamma: -2.2
          assertion failed: render: `file-gamma` must be a number above 0 or "srgb" (or none), got -2.2
        max-trace-level: 0
          assertion failed: render: `max-trace-level` must be an integer from 1 to 256 (or none), got 0
        bounding: none, remove-bounds: 2
          assertion failed: render: `remove-bounds` must be true or false (or none), got 2
        bounding-threshold: -1
          assertion failed: render: `bounding-threshold` must be an integer of at least 0 (or none), got -1
        split-unions: 0
          assertion failed: render: `split-unions` must be true or false (or none), got 0
        start-row: 0
          assertion failed: render: `start-row` must be an integer of at least 1 (a pixel) or a float from 0.0 to 1.0 (a fraction) (or none), got 0
        end-row: 1.5
          assertion failed: render: `end-row` must be an integer of at least 1 (a pixel) or a float from 0.0 to 1.0 (a fraction) (or none), got 1.5
        start-column: -0.5
          assertion failed: render: `start-column` must be an integer of at least 1 (a pixel) or a float from 0.0 to 1.0 (a fraction) (or none), got -0.5
        end-column: "all"
          assertion failed: render: `end-column` must be an integer of at least 1 (a pixel) or a float from 0.0 to 1.0 (a fraction) (or none), got "all"
        output-alpha: "on"
          assertion failed: render: `output-alpha` must be true or false (or none), got "on"
        compression: 10
          assertion failed: render: `compression` must be an integer from 0 to 9 (or none), got 10
        includes: ("materials.inc": 3)
          assertion failed: render: `includes` maps file names to their text; "materials.inc" is int
        includes: "materials.inc"
          assertion failed: render: `includes` must be a dictionary of texts by file name, got "materials.inc"
        files: ("map.png": 3)
          assertion failed: render: `files` maps file names to bytes; "map.png" is int
        extra: 3
          assertion failed: render: `extra` must be an array of POV-Ray option strings such as ("+A0.1", "Jitter=off"), got 3
        extra: ("+A0.1", 2)
          assertion failed: render: `extra` must be an array of POV-Ray option strings such as ("+A0.1", "Jitter=off"), got ("+A0.1", 2)
        colour: red
          assertion failed: render: unknown argument `colour`; the arguments are includes, files, width, height, quality, antialias, aa-threshold, aa-method, aa-depth, aa-jitter, aa-jitter-amount, aa-gamma, display-gamma, file-gamma, max-trace-level, bounding, bounding-threshold, remove-bounds, split-unions, start-row, end-row, start-column, end-column, output-alpha, compression, extra
        start-row: 10, end-row: 5
          assertion failed: render: `start-row` (10) is after `end-row` (5)
        start-column: 0.8, end-column: 0.2
          assertion failed: render: `start-column` (0.8) is after `end-column` (0.2)"#]].assert_eq(&messages.join("\n"));
}

#[test]
fn the_scene_must_be_text() {
    let doc = Document::new(&format!(
        "{IMPORT}#render(```povray\nsphere {{ 0, 1 }}\n```)\n"
    ));
    expect!["assertion failed: render: the scene must be a string, got content; `pov` also takes raw blocks"]
        .assert_eq(&doc.compile_error());
    let doc = Document::new(&format!("{IMPORT}#pov(42)\n"));
    expect!["assertion failed: pov: the scene must be a string or a raw block, got int"]
        .assert_eq(&doc.compile_error());
    let doc = Document::new(&format!("{IMPORT}#pov(\"sphere {{ 0, 1 }}\", 640)\n"));
    expect!["assertion failed: pov: takes one positional argument, the scene; got 2"]
        .assert_eq(&doc.compile_error());
}

#[test]
fn defaults_and_version() {
    let doc = Document::new(&format!(
        "{IMPORT}#metadata((version: version(), defaults: defaults)) <result>\n"
    ));
    let result = doc.query("<result>").unwrap();
    let toml =
        std::fs::read_to_string(tests::workspace_root().join("typst-pkg/typst.toml")).unwrap();
    assert!(toml.contains(&format!("\nversion = {}\n", result["version"])));
    assert_eq!(result["version"], env!("CARGO_PKG_VERSION"));
    expect![[r#"{"aa-depth":3,"aa-gamma":null,"aa-jitter":true,"aa-jitter-amount":null,"aa-method":2,"aa-threshold":0.3,"antialias":true,"bounding":null,"bounding-threshold":null,"compression":null,"display-gamma":null,"end-column":null,"end-row":null,"extra":[],"file-gamma":null,"files":{},"height":600,"includes":{},"max-trace-level":null,"output-alpha":false,"quality":9,"remove-bounds":null,"split-unions":null,"start-column":null,"start-row":null,"width":800}"#]].assert_eq(&result["defaults"].to_string());
}

/// The distinct fill colours of the text in the SVG of a document.
fn text_colours(doc: &Document) -> usize {
    let svg = doc.dir().join("main.svg");
    doc.compile_to(&svg).unwrap();
    let svg = std::fs::read_to_string(svg).unwrap();
    let mut fills: Vec<&str> = svg.split("fill=\"").skip(1).map(|s| &s[..7]).collect();
    fills.sort();
    fills.dedup();
    fills.len()
}

#[test]
fn highlight_colours_povray_blocks() {
    let block = "```povray\n#declare R = 1; // radius\nsphere { <0, 1, 2>, R pigment { rgb sin(pi) } }\n```\n";
    let plain = Document::new(&format!("{IMPORT}{block}"));
    let highlighted = Document::new(&format!("{IMPORT}#show: highlight\n{block}"));
    // Black text on a white page, against keywords, functions, numbers and comments.
    assert_eq!(text_colours(&plain), 2);
    assert!(text_colours(&highlighted) >= 5);
}

#[test]
fn povray_options_are_what_the_arguments_stand_for() {
    let doc = Document::new(&format!(
        "{IMPORT}#metadata(povray-options(width: 480, antialias: none, aa-method: none, \
         aa-threshold: 0.7, start-row: 1.0, end-row: 200, display-gamma: \"SRGB\", \
         file-gamma: 2.2, quality: none, extra: \"+Q2\")) <result>\n"
    ));
    expect![[r#"["Width=480","Height=600","Antialias=off","Antialias_Threshold=0.7","Sampling_Method=1","Antialias_Depth=3","Jitter=on","Display_Gamma=sRGB","File_Gamma=2.2","Start_Row=1.0","End_Row=200","Output_Alpha=off","+Q2"]"#]].assert_eq(&doc.query("<result>").unwrap().to_string());
}
