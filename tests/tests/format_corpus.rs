//! The formatter over every scene and include we can find: Debian's example scenes and
//! include files (scripts/test installs them) and our bundled standard includes. Formatting
//! must keep every token other than whitespace, comments included, and formatting the
//! result again must change nothing: through the library, and through `povrayst fmt` on a
//! copy of the corpus.

use analysis::format::{FormatConfig, format_text};
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use tests::example_corpus::{EXAMPLES, INCLUDES, files_under};
use tests::povrayst_binary;

const SDL_EXTENSIONS: &[&str] = &["pov", "inc", "mcr", "mac"];

/// The scenes and includes of both corpora; fails when they are not installed.
fn corpus() -> Vec<PathBuf> {
    let paths: Vec<_> = [EXAMPLES, INCLUDES]
        .iter()
        .flat_map(|dir| files_under(Path::new(dir), SDL_EXTENSIONS))
        .collect();
    assert!(
        paths.len() > 400,
        "{} files: the corpus is missing (apt-get install povray-examples povray-includes; scripts/test does)",
        paths.len()
    );
    paths
}

/// A file's text; Latin-1 files are read byte for byte as characters, as the CLI shows them.
fn read_text(path: &Path) -> String {
    let bytes = std::fs::read(path).unwrap();
    String::from_utf8(bytes.clone())
        .unwrap_or_else(|_| bytes.iter().map(|&b| char::from(b)).collect())
}

/// The tokens that are not whitespace, with their text.
fn significant(text: &str) -> Vec<(syntax::SyntaxKind, &str)> {
    syntax::lexer::lex(text)
        .tokens
        .iter()
        .filter(|t| t.kind != syntax::SyntaxKind::WHITESPACE)
        .map(|t| (t.kind, &text[t.range]))
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
    for path in corpus() {
        check(&path.display().to_string(), &read_text(&path));
        checked += 1;
    }
    eprintln!("formatted {checked} files");
}

fn povrayst(args: &[&str]) -> Output {
    Command::new(povrayst_binary()).args(args).output().unwrap()
}

#[test]
fn fmt_command_keeps_every_token_of_the_corpus_and_is_idempotent() {
    let copy = tempfile::tempdir().unwrap();
    let mut pairs = Vec::new();
    for original in corpus() {
        let (root, relative) = [EXAMPLES, INCLUDES]
            .iter()
            .find_map(|dir| Some((*dir, original.strip_prefix(dir).ok()?)))
            .unwrap();
        let target = copy
            .path()
            .join(Path::new(root).file_name().unwrap())
            .join(relative);
        std::fs::create_dir_all(target.parent().unwrap()).unwrap();
        std::fs::copy(&original, &target).unwrap();
        pairs.push((original, target));
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
    for (original, formatted) in &pairs {
        let before = read_text(original);
        let after = read_text(formatted);
        assert!(
            significant(&before) == significant(&after),
            "{}: fmt changed a token",
            original.display()
        );
        changed += usize::from(before != after);
    }
    eprintln!("fmt reformatted {changed} of {} files", pairs.len());

    let second = povrayst(&["fmt", "--check", root]);
    assert_eq!(
        second.status.code(),
        Some(0),
        "fmt is not idempotent: {}",
        String::from_utf8_lossy(&second.stderr)
    );
}
