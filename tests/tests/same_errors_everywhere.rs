//! One broken scene, one report: `povrayst check` prints exactly the text that stops a Typst
//! compile of the same scene through the package (after Typst's "plugin errored with: "),
//! and the language server publishes the same message at the same place.

use serde_json::Value;
use std::process::Command;
use tests::broken_scenes::{BROKEN_SCENES, BrokenScene};
use tests::lsp_client::{LspProcess, uri};
use tests::povrayst_binary;
use tests::typst_compiler::Document;

/// The scene and its includes on disk, as the CLI reads them.
fn on_disk(case: &BrokenScene) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.pov"), case.scene).unwrap();
    for (name, text) in case.includes {
        std::fs::write(dir.path().join(name), text).unwrap();
    }
    dir
}

fn check_report(case: &BrokenScene) -> String {
    let dir = on_disk(case);
    let output = Command::new(povrayst_binary())
        .args(["check", "scene.pov"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert_eq!(
        output.status.code(),
        Some(1),
        "{}: povrayst check must fail",
        case.what
    );
    String::from_utf8(output.stderr).unwrap()
}

fn typst_report(case: &BrokenScene) -> String {
    let includes: String = case
        .includes
        .iter()
        .map(|(name, _)| format!("\"{name}\": read(\"{name}\"), "))
        .collect();
    let includes = if includes.is_empty() {
        ":".into()
    } else {
        includes
    };
    let mut doc = Document::new(&format!(
        "#import \"@local/povrayst:0.1.0\": render\n#render(read(\"scene.pov\"), width: 8, height: 6, includes: ({includes}))\n"
    ))
    .with_file("scene.pov", case.scene);
    for (name, text) in case.includes {
        doc = doc.with_file(name, text);
    }
    doc.compile_error()
}

/// The first diagnostic the language server publishes for the scene, as the first line
/// of a `povrayst check` report: `file:line:column: severity: message`. An error inside an
/// include is published where the scene includes the file, with its own place first in the
/// related information; that place is the one reported.
fn language_server_report(server: &mut LspProcess, case: &BrokenScene) -> String {
    let dir = on_disk(case);
    let scene = uri(dir.path()) + "/scene.pov";
    server.open(&scene, "povray", 1, case.scene);
    let diagnostics = server.diagnostics(&scene, Some(1));
    let first = diagnostics.first().expect("the scene has a diagnostic");
    let in_include = first["relatedInformation"][0]["location"]
        .as_object()
        .filter(|location| location["uri"] != scene.as_str());
    let (file, start) = match in_include {
        Some(location) => {
            let file = location["uri"]
                .as_str()
                .unwrap()
                .rsplit('/')
                .next()
                .unwrap();
            (file.to_owned(), &location["range"]["start"])
        }
        None => ("scene.pov".to_owned(), &first["range"]["start"]),
    };
    let severity = if first["severity"] == 1 {
        "error"
    } else {
        "warning"
    };
    format!(
        "{file}:{}:{}: {severity}: {}",
        start["line"].as_i64().unwrap() + 1,
        start["character"].as_i64().unwrap() + 1,
        first["message"].as_str().unwrap().lines().next().unwrap()
    )
}

#[test]
fn check_and_typst_report_the_same_text() {
    for case in BROKEN_SCENES {
        let check = check_report(case);
        assert!(
            check.contains("scene.pov:") || check.contains(".inc:"),
            "{}: {check}",
            case.what
        );
        assert_eq!(
            typst_report(case),
            format!("plugin errored with: {check}"),
            "{}",
            case.what
        );
    }
}

#[test]
fn check_and_the_language_server_report_the_same_error_at_the_same_place() {
    let dir = tempfile::tempdir().unwrap();
    let (mut server, _) = LspProcess::start(dir.path(), Value::Null);
    for case in BROKEN_SCENES {
        let check = check_report(case);
        assert_eq!(
            language_server_report(&mut server, case),
            check.lines().next().unwrap(),
            "{}",
            case.what
        );
    }
}
