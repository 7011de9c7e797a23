//! Conformance over real scenes: every `.pov` and `.inc` of Debian's `povray-examples`
//! and `povray-includes` parses without syntax errors and the tree holds every byte.
//! The corpus is installed by the README's test command; without it the test says that
//! it skipped.

use std::fs;
use std::path::{Path, PathBuf};

const ROOTS: &[&str] = &[
    "/usr/share/doc/povray/examples",
    "/usr/share/povray-3.7/include",
];

/// Files of the corpus that are not valid SDL, with why. Each must still give errors.
const NOT_SDL: &[(&str, &str)] = &[(
    "portfolio/__empty.pov",
    "a template with '...' placeholders (`array[..]`, `#include \"... .inc\"`) that \
     POV-Ray itself rejects",
)];

fn scene_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            scene_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "pov" || e == "inc") {
            out.push(path);
        }
    }
}

#[test]
fn corpus_parses_without_errors_and_round_trips() {
    let mut files = Vec::new();
    for root in ROOTS {
        scene_files(Path::new(root), &mut files);
    }
    if files.is_empty() {
        println!(
            "skipped: the POV-Ray corpus is not installed (apt-get install povray-examples \
             povray-includes)"
        );
        return;
    }
    files.sort();
    let mut failures = Vec::new();
    let (mut scenes, mut includes, mut bytes) = (0, 0, 0);
    for file in &files {
        // Some example files are Latin-1; the lexer works on text, as the evaluator does.
        let text = String::from_utf8_lossy(&fs::read(file).unwrap()).into_owned();
        bytes += text.len();
        if file.extension().is_some_and(|e| e == "pov") {
            scenes += 1;
        } else {
            includes += 1;
        }
        let parse = syntax::parse(&text);
        if parse.syntax_node().to_string() != text {
            failures.push(format!("{}: the tree does not round-trip", file.display()));
        }
        let not_sdl = NOT_SDL
            .iter()
            .any(|(name, _)| file.to_string_lossy().ends_with(name));
        match (parse.errors().first(), not_sdl) {
            (Some(error), false) => failures.push(format!(
                "{}: {} errors, the first at {:?}: {}",
                file.display(),
                parse.errors().len(),
                error.range,
                error.message
            )),
            (None, true) => failures.push(format!(
                "{}: parses cleanly; take it off NOT_SDL",
                file.display()
            )),
            _ => {}
        }
    }
    println!(
        "corpus: {scenes} .pov and {includes} .inc files, {bytes} bytes, {} known not to be SDL",
        NOT_SDL.len()
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
