//! One broken scene, one report: `povrayst check` prints exactly the text that stops a Typst
//! compile of the same scene through the package (after Typst's "plugin errored with: ").

use std::process::Command;
use tests::broken_scenes::{BROKEN_SCENES, BrokenScene};
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
