//! `povrayst fmt` over Debian's whole example corpus (every scene and include of
//! povray-examples, which scripts/test installs): it changes no token but whitespace, and
//! a second run, as `fmt --check`, finds nothing to change.

use std::path::{Path, PathBuf};
use std::process::Command;

const EXAMPLES: &str = "/usr/share/doc/povray/examples";

fn sdl_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sdl_files(&path, out);
        } else if path.extension().is_some_and(|e| {
            ["pov", "inc", "mcr", "mac"]
                .iter()
                .any(|x| e.eq_ignore_ascii_case(x))
        }) {
            out.push(path);
        }
    }
}

/// The tokens other than whitespace and comments, with their text.
fn significant(text: &str) -> Vec<(syntax::SyntaxKind, &str)> {
    syntax::lexer::lex(text)
        .tokens
        .iter()
        .filter(|t| !t.kind.is_trivia())
        .map(|t| (t.kind, &text[t.range]))
        .collect()
}

fn povrayst(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_povrayst"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn fmt_keeps_every_token_of_the_example_corpus_and_is_idempotent() {
    let examples = Path::new(EXAMPLES);
    assert!(
        examples.is_dir(),
        "the example corpus is missing: apt-get install povray-examples (scripts/test does)"
    );
    let mut originals = Vec::new();
    sdl_files(examples, &mut originals);
    let copy = tempfile::tempdir().unwrap();
    let mut copies = Vec::new();
    for original in &originals {
        let target = copy.path().join(original.strip_prefix(examples).unwrap());
        std::fs::create_dir_all(target.parent().unwrap()).unwrap();
        std::fs::copy(original, &target).unwrap();
        copies.push(target);
    }
    let root = copy.path().to_str().unwrap();

    let first = povrayst(&["fmt", root]);
    assert_eq!(
        first.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&first.stderr)
    );
    let mut changed = 0;
    for (original, formatted) in originals.iter().zip(&copies) {
        let before = std::fs::read_to_string(original).unwrap();
        let after = std::fs::read_to_string(formatted).unwrap();
        assert!(
            significant(&before) == significant(&after),
            "{}: fmt changed a token",
            original.display()
        );
        changed += usize::from(before != after);
    }
    eprintln!("fmt reformatted {changed} of {} files", originals.len());
    assert!(originals.len() > 400, "{} files", originals.len());

    let second = povrayst(&["fmt", "--check", root]);
    assert_eq!(
        second.status.code(),
        Some(0),
        "fmt is not idempotent: {}",
        String::from_utf8_lossy(&second.stderr)
    );
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
