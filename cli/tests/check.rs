//! `povrayst check` as CI runs it: scenes named by file, directory and pattern, each output
//! format, `--deny warnings`, and the exit status.

use expect_test::{Expect, expect};
use std::path::Path;
use std::process::{Command, Output};

/// A clean scene, one with lint warnings only, and one with an error, in a tree of folders.
fn project() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let files = [
        (
            "scenes/clean.pov",
            "#version 3.7;\nglobal_settings { assumed_gamma 1 }\nsphere { 0, 1 }\n",
        ),
        (
            "scenes/more/lint.pov",
            "#include \"parts.inc\"\n#declare Unused = 1;\nsphere { 0, Radius }\n",
        ),
        ("scenes/more/parts.inc", "#declare Radius = 1;\n"),
        (
            "broken/broken.pov",
            "#version 3.7;\n#declare Radius = 1;\nsphere { 0, Raduis }\n",
        ),
    ];
    for (name, text) in files {
        let path = dir.path().join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    }
    dir
}

fn povrayst(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_povrayst"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

#[track_caller]
fn check(args: &[&str], status: i32, stdout: Expect, stderr: Expect) {
    let dir = project();
    let output = povrayst(dir.path(), args);
    let text = |bytes: &[u8]| String::from_utf8(bytes.to_vec()).unwrap();
    stdout.assert_eq(&text(&output.stdout));
    stderr.assert_eq(&text(&output.stderr));
    assert_eq!(output.status.code(), Some(status), "{args:?}");
}

#[test]
fn warnings_alone_pass_unless_denied() {
    check(
        &["check", "scenes"],
        0,
        expect![""],
        expect![[r#"
            scenes/more/lint.pov:1:1: warning: this scene has no #version directive; assuming #version 3.7
                1 | #include "parts.inc"
                  | ^
            note: add `#version 3.7;` as the scene's first line
            scenes/more/lint.pov:1:1: warning: assumed_gamma is not set, so colours are not gamma corrected, as in scenes older than POV-Ray 3.7
                1 | #include "parts.inc"
                  | ^
            note: add `assumed_gamma 1.0` to global_settings
            scenes/more/lint.pov:2:10: warning: 'Unused' is declared by #declare but never used
                2 | #declare Unused = 1;
                  |          ^~~~~~
            checked 2 scenes: 0 errors, 3 warnings
        "#]],
    );
    check(
        &["check", "scenes", "--deny", "warnings"],
        1,
        expect![""],
        expect![[r#"
            scenes/more/lint.pov:1:1: warning: this scene has no #version directive; assuming #version 3.7
                1 | #include "parts.inc"
                  | ^
            note: add `#version 3.7;` as the scene's first line
            scenes/more/lint.pov:1:1: warning: assumed_gamma is not set, so colours are not gamma corrected, as in scenes older than POV-Ray 3.7
                1 | #include "parts.inc"
                  | ^
            note: add `assumed_gamma 1.0` to global_settings
            scenes/more/lint.pov:2:10: warning: 'Unused' is declared by #declare but never used
                2 | #declare Unused = 1;
                  |          ^~~~~~
            checked 2 scenes: 0 errors, 3 warnings
        "#]],
    );
}

#[test]
fn errors_fail_and_patterns_name_scenes() {
    check(
        &["check", "scenes/*.pov", "broken"],
        1,
        expect![""],
        expect![[r#"
            broken/broken.pov:3:13: error: undeclared identifier 'Raduis'
                3 | sphere { 0, Raduis }
                  |             ^~~~~~
            note: did you mean 'Radius'?
            checked 2 scenes: 1 error, 0 warnings
        "#]],
    );
}

#[test]
fn json_format() {
    check(
        &[
            "check",
            "--format",
            "json",
            "scenes/more/lint.pov",
            "broken",
        ],
        1,
        expect![[r#"
            [
              {
                "code": "missing-version",
                "file": "scenes/more/lint.pov",
                "message": "this scene has no #version directive; assuming #version 3.7",
                "notes": [
                  "add `#version 3.7;` as the scene's first line"
                ],
                "range": {
                  "end": {
                    "column": 1,
                    "line": 1
                  },
                  "start": {
                    "column": 1,
                    "line": 1
                  }
                },
                "related": [],
                "severity": "warning"
              },
              {
                "code": "missing-assumed-gamma",
                "file": "scenes/more/lint.pov",
                "message": "assumed_gamma is not set, so colours are not gamma corrected, as in scenes older than POV-Ray 3.7",
                "notes": [
                  "add `assumed_gamma 1.0` to global_settings"
                ],
                "range": {
                  "end": {
                    "column": 1,
                    "line": 1
                  },
                  "start": {
                    "column": 1,
                    "line": 1
                  }
                },
                "related": [],
                "severity": "warning"
              },
              {
                "code": "unused-declaration",
                "file": "scenes/more/lint.pov",
                "message": "'Unused' is declared by #declare but never used",
                "notes": [],
                "range": {
                  "end": {
                    "column": 16,
                    "line": 2
                  },
                  "start": {
                    "column": 10,
                    "line": 2
                  }
                },
                "related": [],
                "severity": "warning"
              },
              {
                "code": null,
                "file": "broken/broken.pov",
                "message": "undeclared identifier 'Raduis'",
                "notes": [
                  "did you mean 'Radius'?"
                ],
                "range": {
                  "end": {
                    "column": 19,
                    "line": 3
                  },
                  "start": {
                    "column": 13,
                    "line": 3
                  }
                },
                "related": [],
                "severity": "error"
              }
            ]
        "#]],
        expect![""],
    );
}

#[test]
fn sarif_format() {
    let dir = project();
    let output = povrayst(
        dir.path(),
        &["check", "--format", "sarif", "scenes", "broken"],
    );
    assert_eq!(output.status.code(), Some(1));
    let log: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    let results: Vec<String> = log["runs"][0]["results"]
        .as_array()
        .unwrap()
        .iter()
        .map(|result| {
            let location = &result["locations"][0]["physicalLocation"];
            format!(
                "{} {} {}:{}: {}",
                result["level"].as_str().unwrap(),
                result["ruleId"].as_str().unwrap(),
                location["artifactLocation"]["uri"].as_str().unwrap(),
                location["region"]["startLine"],
                result["message"]["text"]
                    .as_str()
                    .unwrap()
                    .lines()
                    .next()
                    .unwrap(),
            )
        })
        .collect();
    expect![[r#"
        warning missing-version scenes/more/lint.pov:1: this scene has no #version directive; assuming #version 3.7
        warning missing-assumed-gamma scenes/more/lint.pov:1: assumed_gamma is not set, so colours are not gamma corrected, as in scenes older than POV-Ray 3.7
        warning unused-declaration scenes/more/lint.pov:2: 'Unused' is declared by #declare but never used
        error error broken/broken.pov:3: undeclared identifier 'Raduis'"#]].assert_eq(&results.join("\n"));
}

#[test]
fn github_format() {
    check(
        &["check", "--format", "github", "scenes", "broken"],
        1,
        expect![[r#"
            ::warning file=scenes/more/lint.pov,line=1,col=1,endLine=1,endColumn=1,title=povrayst (missing-version)::this scene has no #version directive; assuming #version 3.7%0Anote: add `#version 3.7;` as the scene's first line
            ::warning file=scenes/more/lint.pov,line=1,col=1,endLine=1,endColumn=1,title=povrayst (missing-assumed-gamma)::assumed_gamma is not set, so colours are not gamma corrected, as in scenes older than POV-Ray 3.7%0Anote: add `assumed_gamma 1.0` to global_settings
            ::warning file=scenes/more/lint.pov,line=2,col=10,endLine=2,endColumn=16,title=povrayst (unused-declaration)::'Unused' is declared by #declare but never used
            ::error file=broken/broken.pov,line=3,col=13,endLine=3,endColumn=19,title=povrayst::undeclared identifier 'Raduis'%0Anote: did you mean 'Radius'?
        "#]],
        expect![""],
    );
}

#[test]
fn usage_errors_exit_with_2() {
    check(
        &["check", "no-such-dir/*.pov"],
        2,
        expect![""],
        expect![[r#"
            povrayst: no file matches no-such-dir/*.pov
        "#]],
    );
    check(
        &["check", "--format", "xml", "scenes"],
        2,
        expect![""],
        expect![[r#"
            error: invalid value 'xml' for '--format <FORMAT>': unknown format 'xml'; expected one of human, json, sarif, github

            For more information, try '--help'.
        "#]],
    );
}
