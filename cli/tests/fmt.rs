//! `povrayst fmt --check` and its report (the corpus run is tests/tests/format_corpus.rs).

use std::process::Command;

fn povrayst(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_povrayst"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn check_lists_unformatted_files_and_fails() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("scene.pov");
    std::fs::write(&scene, "#if (1)\nsphere { 0, 1 }   \n#end\n").unwrap();
    let scene = scene.to_str().unwrap();
    let check = povrayst(&["fmt", "--check", scene]);
    assert_eq!(check.status.code(), Some(1));
    assert_eq!(
        String::from_utf8_lossy(&check.stderr),
        format!(
            "not formatted: {scene}\n1 of 1 files are not formatted; run `povrayst fmt` on them\n"
        )
    );
    assert_eq!(povrayst(&["fmt", scene]).status.code(), Some(0));
    assert_eq!(
        std::fs::read_to_string(scene).unwrap(),
        "#if (1)\n  sphere { 0, 1 }\n#end\n"
    );
    assert_eq!(povrayst(&["fmt", "--check", scene]).status.code(), Some(0));
}

#[test]
fn latin1_files_are_formatted_and_stay_latin1() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("scene.pov");
    std::fs::write(&scene, b"// caf\xe9\n#if (1)\nsphere { 0, 1 }\n#end\n").unwrap();
    let scene = scene.to_str().unwrap();
    let formatted = povrayst(&["fmt", scene]);
    assert_eq!(
        formatted.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&formatted.stderr)
    );
    assert_eq!(
        std::fs::read(scene).unwrap(),
        b"// caf\xe9\n#if (1)\n  sphere { 0, 1 }\n#end\n"
    );
}
