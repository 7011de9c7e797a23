//! The formatter over every scene and include we can find: Debian's example scenes and
//! include files (when installed) and our bundled standard includes (always). Formatting
//! must keep every token other than whitespace, comments included, and formatting the
//! result again must change nothing.

use analysis::format::{FormatConfig, format_text};
use std::path::{Path, PathBuf};

const CORPORA: &[&str] = &[
    "/usr/share/doc/povray/examples",
    "/usr/share/povray-3.7/include",
];

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = entries.filter_map(Result::ok).map(|e| e.path()).collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            files(&path, out);
        } else if path.extension().is_some_and(|e| e == "pov" || e == "inc") {
            out.push(path);
        }
    }
}

/// The tokens that are not whitespace, with their text.
fn significant(text: &str) -> Vec<(syntax::SyntaxKind, String)> {
    syntax::lexer::lex(text)
        .tokens
        .iter()
        .filter(|t| t.kind != syntax::SyntaxKind::WHITESPACE)
        .map(|t| (t.kind, text[t.range].to_owned()))
        .collect()
}

#[track_caller]
fn check(name: &str, text: &str) {
    let config = FormatConfig::default();
    let formatted = format_text(text, &config);
    assert!(
        significant(text) == significant(&formatted),
        "{name}: formatting changed a token"
    );
    assert!(
        format_text(&formatted, &config) == formatted,
        "{name}: formatting twice changed the text"
    );
}

#[test]
fn formatting_keeps_every_token_and_is_idempotent() {
    let mut checked = 0;
    for name in analysis::stdinc::names() {
        check(name, analysis::stdinc::get(name).unwrap());
        checked += 1;
    }
    let mut paths = Vec::new();
    for corpus in CORPORA {
        files(Path::new(corpus), &mut paths);
    }
    if paths.is_empty() {
        eprintln!(
            "only the bundled includes: the example corpus is not installed (apt-get install povray-examples povray-includes)"
        );
    }
    for path in &paths {
        let bytes = std::fs::read(path).unwrap();
        // Latin-1 scenes are read byte for byte as characters, as the CLI would show them.
        let text = String::from_utf8(bytes.clone())
            .unwrap_or_else(|_| bytes.iter().map(|&b| char::from(b)).collect());
        check(&path.display().to_string(), &text);
        checked += 1;
    }
    eprintln!("formatted {checked} files");
}
