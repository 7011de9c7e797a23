//! `povrayst lsp` as a process, driven over JSON-RPC as an editor drives it: initialize,
//! open, edit, and read what it publishes.

use serde_json::{Value, json};
use tests::lsp_client::{LspProcess, uri};

fn scene_dir(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in files {
        std::fs::write(dir.path().join(name), text).unwrap();
    }
    dir
}

/// A server started in an empty directory, with `scene.pov` open at version 1 holding
/// `text`.
fn server_with_scene(text: &str) -> (tempfile::TempDir, LspProcess, String) {
    let dir = scene_dir(&[]);
    let (mut server, _) = LspProcess::start(dir.path(), Value::Null);
    let scene = uri(dir.path()) + "/scene.pov";
    server.open(&scene, "povray", 1, text);
    (dir, server, scene)
}

/// Each error and warning as `line:column severity message`, one-based as `povrayst check`
/// says.
fn summary(diagnostics: &[Value]) -> Vec<String> {
    diagnostics
        .iter()
        .map(|d| {
            let severity = match d["severity"].as_i64() {
                Some(1) => "error",
                Some(2) => "warning",
                _ => "other",
            };
            format!(
                "{}:{} {severity} {}",
                d["range"]["start"]["line"].as_i64().unwrap() + 1,
                d["range"]["start"]["character"].as_i64().unwrap() + 1,
                d["message"]
                    .as_str()
                    .unwrap()
                    .lines()
                    .next()
                    .unwrap_or_default()
            )
        })
        .collect()
}

#[test]
fn diagnostics_follow_opens_and_edits_in_order() {
    let dir = scene_dir(&[]);
    let (mut server, init) = LspProcess::start(dir.path(), Value::Null);
    assert_eq!(init["serverInfo"]["name"], "povrayst");
    assert_eq!(init["capabilities"]["textDocumentSync"]["change"], 2);

    let scene = uri(dir.path()).to_owned() + "/scene.pov";
    server.open(
        &scene,
        "povray",
        1,
        "#version 3.7; global_settings { assumed_gamma 1 }\n#declare Radius = 1;\nsphere { 0, Raduis }\n",
    );
    assert_eq!(
        summary(&server.diagnostics(&scene, Some(1))),
        [
            "3:13 error undeclared identifier 'Raduis'",
            "2:10 warning 'Radius' is declared by #declare but never used"
        ]
    );

    // Two edits sent back to back: the second only makes sense after the first.
    server.edit(&scene, 2, (2, 12), (2, 18), "Radius");
    server.edit(&scene, 3, (2, 12), (2, 18), "R");
    assert_eq!(
        summary(&server.diagnostics(&scene, Some(3))),
        [
            "3:13 error undeclared identifier 'R'",
            "2:10 warning 'Radius' is declared by #declare but never used"
        ]
    );
    server.edit(&scene, 4, (1, 9), (1, 15), "R");
    assert_eq!(
        summary(&server.diagnostics(&scene, Some(4))),
        Vec::<String>::new()
    );

    server.notify(
        "textDocument/didClose",
        json!({"textDocument": {"uri": scene}}),
    );
    assert_eq!(server.diagnostics(&scene, None), Vec::<Value>::new());
    assert_eq!(server.stop(), Some(0));
}

/// The server checks scenes with the renderer's shapes answering `trace()`, `inside()`
/// and the `object` pattern, as `povrayst check` and a render do.
#[test]
fn scenes_asking_geometric_questions_check_clean() {
    let (_dir, mut server, scene) = server_with_scene(
        "#version 3.7; global_settings { assumed_gamma 1 }\n#declare S = sphere { 0, 1 }\n#declare P = trace(S, -5*z, z);\n\
         #declare I = inside(S, 0);\n\
         object { S pigment { object { S rgb P.z, rgb I } } }\n",
    );
    assert_eq!(
        summary(&server.diagnostics(&scene, Some(1))),
        Vec::<String>::new()
    );
    assert_eq!(server.stop(), Some(0));
}

#[test]
fn an_error_inside_an_include_shows_where_it_is_included() {
    let dir = scene_dir(&[(
        "materials.inc",
        "#declare Copper = texture {\n  pigment { color\n  rgb Tint }\n}\n",
    )]);
    let (mut server, _) = LspProcess::start(dir.path(), Value::Null);
    let scene = uri(dir.path()) + "/scene.pov";
    server.open(
        &scene,
        "povray",
        1,
        "#version 3.7;\n#include \"materials.inc\"\n",
    );
    let diagnostics = server.diagnostics(&scene, Some(1));
    assert_eq!(
        summary(&diagnostics),
        ["2:10 error undeclared identifier 'Tint'"]
    );
    let related = &diagnostics[0]["relatedInformation"][0];
    assert_eq!(
        related["location"]["uri"],
        uri(dir.path()) + "/materials.inc"
    );
    assert_eq!(
        related["location"]["range"]["start"],
        json!({"line": 2, "character": 6})
    );
}

#[test]
fn a_panicking_request_is_answered_with_an_error_and_the_server_goes_on() {
    let dir = scene_dir(&[]);
    let (mut server, _) = LspProcess::start(dir.path(), Value::Null);
    let error = server
        .request("povrayst/crashTest", Value::Null)
        .unwrap_err();
    assert_eq!(error.code, -32603);
    assert!(
        error.message.contains("crash test requested"),
        "{}",
        error.message
    );

    let scene = uri(dir.path()) + "/scene.pov";
    server.open(&scene, "povray", 1, "sphere { 0, 1\n");
    assert_eq!(
        summary(&server.diagnostics(&scene, Some(1))),
        ["1:8 error unclosed '{'"]
    );
    assert!(server.is_running());
    assert_eq!(server.stop(), Some(0));
}

fn at(uri: &str, line: u32, character: u32) -> Value {
    json!({"textDocument": {"uri": uri}, "position": {"line": line, "character": character}})
}

#[test]
fn navigation_requests_answer_in_scenes_and_typst_blocks() {
    let dir = scene_dir(&[("lib.inc", "// The ball's size.\n#declare Size = 2;\n")]);
    let (mut server, _) = LspProcess::start(dir.path(), Value::Null);
    let scene = uri(dir.path()) + "/scene.pov";
    let lib = uri(dir.path()) + "/lib.inc";
    server.open(
        &scene,
        "povray",
        1,
        "#version 3.7;\n#include \"lib.inc\"\nsphere { 0, Size }\n",
    );
    server.diagnostics(&scene, Some(1));

    let hover = server
        .request("textDocument/hover", at(&scene, 2, 13))
        .unwrap();
    assert_eq!(
        hover["contents"]["value"].as_str().unwrap().lines().nth(1),
        Some("#declare Size = 2; // float 2")
    );
    let definition = server
        .request("textDocument/definition", at(&scene, 2, 13))
        .unwrap();
    assert_eq!(definition[0]["uri"], lib.as_str());
    assert_eq!(
        definition[0]["range"]["start"],
        json!({"line": 1, "character": 9})
    );

    let mut params = at(&scene, 2, 13);
    params["context"] = json!({"includeDeclaration": true});
    let references = server.request("textDocument/references", params).unwrap();
    let places: Vec<(String, i64)> = references
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            (
                r["uri"]
                    .as_str()
                    .unwrap()
                    .rsplit('/')
                    .next()
                    .unwrap()
                    .to_owned(),
                r["range"]["start"]["line"].as_i64().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        places,
        [("lib.inc".to_owned(), 1), ("scene.pov".to_owned(), 2)]
    );

    let mut params = at(&scene, 2, 13);
    params["newName"] = json!("Radius");
    let edit = server.request("textDocument/rename", params).unwrap();
    assert_eq!(edit["changes"][&scene][0]["newText"], "Radius");
    assert_eq!(
        edit["changes"][&lib][0]["range"]["start"],
        json!({"line": 1, "character": 9})
    );
    let refused = server
        .request("textDocument/prepareRename", at(&scene, 2, 1))
        .unwrap_err();
    assert_eq!(refused.message, "reserved words cannot be renamed");

    let links = server
        .request(
            "textDocument/documentLink",
            json!({"textDocument": {"uri": scene}}),
        )
        .unwrap();
    assert_eq!(links[0]["target"], lib.as_str());

    // A Typst document: features inside its povray block, positions in the document.
    let doc = uri(dir.path()) + "/doc.typ";
    let typst = "= Scenes\n#render(read(\"scene.pov\"))\n\n  ```povray\n  #declare R = 1;\n  sphere { 0, R }\n  ```\n";
    server.open(&doc, "typst", 1, typst);
    let definition = server
        .request("textDocument/definition", at(&doc, 5, 14))
        .unwrap();
    assert_eq!(definition[0]["uri"], doc.as_str());
    assert_eq!(
        definition[0]["range"]["start"],
        json!({"line": 4, "character": 11})
    );
    let symbols = server
        .request(
            "textDocument/documentSymbol",
            json!({"textDocument": {"uri": doc}}),
        )
        .unwrap();
    assert_eq!(symbols[0]["name"], "R");
    assert_eq!(
        symbols[0]["selectionRange"]["start"],
        json!({"line": 4, "character": 11})
    );
    let links = server
        .request(
            "textDocument/documentLink",
            json!({"textDocument": {"uri": doc}}),
        )
        .unwrap();
    assert_eq!(links[0]["target"], scene.as_str());
    assert_eq!(
        server
            .request("textDocument/hover", at(&doc, 0, 3))
            .unwrap(),
        Value::Null
    );

    let found = server
        .request("workspace/symbol", json!({"query": "Size"}))
        .unwrap();
    assert_eq!(found[0]["name"], "Size");
    assert_eq!(server.stop(), Some(0));
}

fn whole(uri: &str) -> Value {
    json!({"textDocument": {"uri": uri}})
}

#[test]
fn editing_aids_answer_over_the_protocol() {
    let dir = scene_dir(&[]);
    let (mut server, init) = LspProcess::start(dir.path(), Value::Null);
    for capability in [
        "completionProvider",
        "signatureHelpProvider",
        "semanticTokensProvider",
        "foldingRangeProvider",
        "colorProvider",
        "inlayHintProvider",
        "codeActionProvider",
        "documentFormattingProvider",
    ] {
        assert!(!init["capabilities"][capability].is_null(), "{capability}");
    }
    let scene = uri(dir.path()) + "/scene.pov";
    let text = "#version 3.7;\n#declare Unused = 1;\n#macro Ball(Center, Radius)\nsphere { Center, Radius\npigment { rgb <1, 0.5, 0> }\n}\n#end\nobject { Ball(0, 1) }\nspher { 0, 1 }\n";
    server.open(&scene, "povray", 1, text);
    let diagnostics = server.diagnostics(&scene, Some(1));
    // The lint `povrayst check` reports, in its words, faded by the editor.
    let unused = diagnostics
        .iter()
        .find(|d| d["code"] == "unused-declaration")
        .unwrap();
    assert_eq!(
        unused["message"],
        "'Unused' is declared by #declare but never used"
    );
    assert_eq!(unused["severity"], 2);
    assert_eq!(unused["tags"], json!([1]));

    let completion = server
        .request("textDocument/completion", at(&scene, 4, 10))
        .unwrap();
    let labels: Vec<&str> = completion
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i["label"].as_str().unwrap())
        .collect();
    assert!(
        labels.contains(&"gradient") && labels.contains(&"color_map"),
        "{labels:?}"
    );
    assert!(!labels.contains(&"ambient"), "{labels:?}");

    let help = server
        .request("textDocument/signatureHelp", at(&scene, 7, 17))
        .unwrap();
    assert_eq!(help["signatures"][0]["label"], "Ball(Center, Radius)");
    assert_eq!(help["activeParameter"], 1);

    let tokens = server
        .request("textDocument/semanticTokens/full", whole(&scene))
        .unwrap();
    assert_eq!(tokens["data"].as_array().unwrap().len() % 5, 0);
    assert!(tokens["data"].as_array().unwrap().len() > 5 * 20);

    let folds = server
        .request("textDocument/foldingRange", whole(&scene))
        .unwrap();
    assert_eq!(folds[0]["startLine"], 2);

    let colours = server
        .request("textDocument/documentColor", whole(&scene))
        .unwrap();
    assert_eq!(
        colours[0]["range"]["start"],
        json!({"line": 4, "character": 10})
    );
    let mut params = whole(&scene);
    params["color"] = json!({"red": 0.0, "green": 0.0, "blue": 1.0, "alpha": 1.0});
    params["range"] = colours[0]["range"].clone();
    let presentation = server
        .request("textDocument/colorPresentation", params)
        .unwrap();
    assert_eq!(presentation[0]["label"], "rgb <0, 0, 1>");

    let mut params = whole(&scene);
    params["range"] =
        json!({"start": {"line": 0, "character": 0}, "end": {"line": 9, "character": 0}});
    let hints = server.request("textDocument/inlayHint", params).unwrap();
    let labels: Vec<&str> = hints
        .as_array()
        .unwrap()
        .iter()
        .map(|h| h["label"].as_str().unwrap())
        .collect();
    assert_eq!(labels, ["Center:", "Radius:"]);

    let mut params = whole(&scene);
    params["range"] =
        json!({"start": {"line": 8, "character": 2}, "end": {"line": 8, "character": 2}});
    params["context"] = json!({"diagnostics": []});
    let actions = server.request("textDocument/codeAction", params).unwrap();
    assert_eq!(actions[0]["title"], "Replace with `sphere`");
    assert_eq!(
        actions[0]["edit"]["changes"][&scene][0]["newText"],
        "sphere"
    );

    let mut params = whole(&scene);
    params["options"] = json!({"tabSize": 2, "insertSpaces": true});
    let edits = server.request("textDocument/formatting", params).unwrap();
    assert!(!edits.as_array().unwrap().is_empty());
    assert_eq!(server.stop(), Some(0));
}

#[test]
fn render_previews_a_scene_as_a_png() {
    let (_dir, mut server, scene) = server_with_scene(
        "#version 3.7;\ncamera { location <0, 0, -4> look_at 0 }\nlight_source { <3, 4, -5> rgb 1 }\nsphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }\n",
    );
    let mut params = whole(&scene);
    params["width"] = json!(16);
    params["height"] = json!(12);
    let preview = server.request("povrayst/render", params.clone()).unwrap();
    assert_eq!(
        (preview["width"].as_i64(), preview["height"].as_i64()),
        (Some(16), Some(12))
    );
    // Base64 of the PNG signature.
    assert!(preview["png"].as_str().unwrap().starts_with("iVBORw0KGgo"));

    server.edit(&scene, 2, (3, 12), (3, 12), "Raduis");
    let error = server.request("povrayst/render", params).unwrap_err();
    assert!(
        error.message.starts_with("scene.pov:4:13: error:"),
        "{}",
        error.message
    );
    assert_eq!(server.stop(), Some(0));
}
