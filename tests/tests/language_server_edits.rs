//! A thousand random edits, sent as fast as an editor could: the server must never die,
//! must apply them in order, and must end with the diagnostics a fresh server gives the
//! final text.

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};
use serde_json::{Value, json};
use tests::lsp_client::{LspProcess, uri};

const SCENE: &str = r#"#version 3.7;
#include "colors.inc"
#include "shapes.inc"
// A ball on a floor.
#declare Radius = 1;
#macro Ball(Center, R)
  sphere { Center, R pigment { rgb <1, 0.5, 0> } }
#end
camera { location <0, 2, -6> look_at 0 }
light_source { <5, 5, -5> color White }
object { Ball(<0, Radius, 0>, Radius) }
plane { y, 0 pigment { checker Black, White } }
"#;

/// Pieces of SDL, broken and whole, that edits insert.
const FRAGMENTS: &[&str] = &[
    "",
    "{",
    "}",
    "(",
    ")",
    "<1, 2, 3>",
    "\n",
    " ",
    "\"",
    "é",
    "𝄞",
    "#declare X = 1;",
    "sphere { 0, 1 }",
    "#if (Radius > 0)",
    "#end",
    "/*",
    "*/",
    "// note\n",
    "Raduis",
    "#include \"colors.inc\"\n",
    "#macro M(A) A #end",
    "Ball(0, 1)",
    "#local",
    ";",
    ",",
    "pigment { Red }",
    "#else",
    "texture {",
    "#undef Radius\n",
    "0.5",
];

/// An edit, placed relative to the text it applies to.
#[derive(Debug, Clone)]
struct Edit {
    at: f64,
    delete: usize,
    insert: usize,
}

fn edits() -> impl Strategy<Value = Vec<Edit>> {
    prop::collection::vec(
        (0.0..=1.0f64, 0..12usize, 0..FRAGMENTS.len()).prop_map(|(at, delete, insert)| Edit {
            at,
            delete,
            insert,
        }),
        1000,
    )
}

/// Zero-based line and UTF-16 column of a char index.
fn position(text: &str, char_index: usize) -> (u32, u32) {
    let before: String = text.chars().take(char_index).collect();
    let line = before.matches('\n').count() as u32;
    let column = before
        .rsplit('\n')
        .next()
        .unwrap_or_default()
        .encode_utf16()
        .count() as u32;
    (line, column)
}

#[test]
fn a_thousand_random_edits_end_where_a_fresh_open_starts() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("shapes.inc"),
        "#declare Unit = box { 0, 1 }\n",
    )
    .unwrap();
    let scene = uri(dir.path()) + "/scene.pov";
    // A fixed seed keeps the test deterministic; one case is one run of 1,000 edits.
    let config = Config {
        cases: 1,
        max_shrink_iters: 0,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner =
        TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha));
    runner
        .run(&edits(), |edits| {
            let (mut server, _) = LspProcess::start(dir.path(), Value::Null);
            server.open(&scene, "povray", 0, SCENE);
            let mut text = SCENE.to_owned();
            for (version, edit) in edits.iter().enumerate() {
                let chars = text.chars().count();
                let start = ((chars as f64) * edit.at) as usize;
                let end = (start + edit.delete).min(chars);
                let insert = FRAGMENTS[edit.insert];
                server.edit(
                    &scene,
                    version as i64 + 1,
                    position(&text, start),
                    position(&text, end),
                    insert,
                );
                let prefix: String = text.chars().take(start).collect();
                let suffix: String = text.chars().skip(end).collect();
                text = prefix + insert + &suffix;
            }
            let last = edits.len() as i64;
            let edited = server.diagnostics(&scene, Some(last));
            prop_assert!(server.is_running());
            // The server still answers requests about the final text.
            let hover = server.request(
                "textDocument/hover",
                json!({"textDocument": {"uri": scene}, "position": {"line": 0, "character": 1}}),
            );
            prop_assert!(hover.is_ok());
            prop_assert_eq!(server.stop(), Some(0));

            let (mut fresh, _) = LspProcess::start(dir.path(), Value::Null);
            fresh.open(&scene, "povray", 1, &text);
            let opened = fresh.diagnostics(&scene, Some(1));
            prop_assert_eq!(edited, opened, "final text:\n{}", text);
            Ok(())
        })
        .unwrap();
}
