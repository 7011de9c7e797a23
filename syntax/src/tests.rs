//! Golden tests of the parser: every `.pov` file under `test_data/parser` is parsed and
//! its tree compared with the `.rast` file beside it (`UPDATE_EXPECT=1` rewrites them).
//! Files under `ok` must parse without errors, files under `err` with some. The files
//! under `inline` come from the `// test name` comments in the grammar's source.

use crate::parse;
use expect_test::expect_file;
use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

fn test_data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("test_data/parser")
}

fn updating() -> bool {
    std::env::var_os("UPDATE_EXPECT").is_some()
}

#[test]
fn parser_golden_files() {
    for (dir, expect_errors) in [
        ("ok", false),
        ("err", true),
        ("inline/ok", false),
        ("inline/err", true),
    ] {
        let dir = test_data().join(dir);
        let mut files: Vec<PathBuf> = fs::read_dir(&dir)
            .map(|entries| entries.filter_map(|e| Some(e.ok()?.path())).collect())
            .unwrap_or_default();
        files.retain(|f| f.extension().is_some_and(|e| e == "pov"));
        files.sort();
        assert!(!files.is_empty(), "no test files in {}", dir.display());
        for file in files {
            let text = fs::read_to_string(&file).unwrap();
            let parse = parse(&text);
            assert_eq!(
                parse.syntax_node().to_string(),
                text,
                "{} does not round-trip",
                file.display()
            );
            assert_eq!(
                crate::syntax_errors(&text),
                parse.errors(),
                "{}: the errors without a tree differ from the parse's",
                file.display()
            );
            let has_errors = !parse.errors().is_empty();
            assert_eq!(
                has_errors,
                expect_errors,
                "{}: {}",
                file.display(),
                if has_errors {
                    "unexpected errors"
                } else {
                    "no errors"
                }
            );
            expect_file![file.with_extension("rast")].assert_eq(&parse.debug_tree());
        }
    }
}

/// The `// test name` and `// test_err name` examples in the grammar's comments.
fn inline_tests() -> BTreeMap<PathBuf, String> {
    let grammar = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/grammar");
    let mut sources = vec![grammar.with_extension("rs")];
    let mut entries: Vec<PathBuf> = fs::read_dir(&grammar)
        .unwrap()
        .filter_map(|e| Some(e.ok()?.path()))
        .collect();
    entries.sort();
    sources.extend(entries);

    let mut tests = BTreeMap::new();
    for source in sources {
        let text = fs::read_to_string(&source).unwrap();
        let mut lines = text.lines().map(str::trim_start).peekable();
        while let Some(line) = lines.next() {
            let (dir, name) = if let Some(name) = line.strip_prefix("// test_err ") {
                ("err", name)
            } else if let Some(name) = line.strip_prefix("// test ") {
                ("ok", name)
            } else {
                continue;
            };
            let mut body = String::new();
            while let Some(next) = lines.peek() {
                let Some(content) = next.strip_prefix("//") else {
                    break;
                };
                if content.starts_with(" test ") || content.starts_with(" test_err ") {
                    break;
                }
                if next.starts_with("///") {
                    break;
                }
                body.push_str(content.strip_prefix(' ').unwrap_or(content));
                body.push('\n');
                lines.next();
            }
            let path = test_data()
                .join("inline")
                .join(dir)
                .join(format!("{}.pov", name.trim()));
            assert!(
                tests.insert(path.clone(), body).is_none(),
                "two inline tests are named {}",
                path.display()
            );
        }
    }
    tests
}

#[test]
fn inline_test_files_are_up_to_date() {
    let tests = inline_tests();
    let mut stale = Vec::new();
    for (path, body) in &tests {
        if fs::read_to_string(path).ok().as_deref() != Some(body.as_str()) {
            if updating() {
                fs::create_dir_all(path.parent().unwrap()).unwrap();
                fs::write(path, body).unwrap();
            } else {
                stale.push(path.display().to_string());
            }
        }
    }
    for dir in ["ok", "err"] {
        let dir = test_data().join("inline").join(dir);
        for entry in fs::read_dir(&dir).into_iter().flatten().flatten() {
            let path = entry.path();
            let source = path.with_extension("pov");
            if !tests.contains_key(&source) {
                if updating() {
                    fs::remove_file(&path).unwrap();
                } else {
                    stale.push(format!("{} (no longer in the grammar)", path.display()));
                }
            }
        }
    }
    assert!(
        stale.is_empty(),
        "inline test files out of date, run with UPDATE_EXPECT=1:\n{}",
        stale.join("\n")
    );
}

#[test]
fn gallery_scenes_parse_without_errors() {
    let gallery = Path::new(env!("CARGO_MANIFEST_DIR")).join("../gallery");
    let mut count = 0;
    for entry in fs::read_dir(&gallery).unwrap().flatten() {
        let path = entry.path();
        if path.extension().is_some_and(|e| e == "pov") {
            let text = fs::read_to_string(&path).unwrap();
            let parse = parse(&text);
            assert_eq!(parse.errors(), &[], "{}", path.display());
            assert_eq!(parse.syntax_node().to_string(), text);
            count += 1;
        }
    }
    assert!(
        count >= 9,
        "expected the nine gallery scenes, found {count}"
    );
}

/// Inputs that once took quadratic time or could overflow the stack: they parse, keep
/// every byte, and deep nesting is reported once.
#[test]
fn pathological_inputs() {
    let cases = [
        (format!("#declare A = {}1;", "1+".repeat(50_000)), 0),
        (
            format!(
                "{}sphere {{ 0, 1 }}{}",
                "#if (1)\n".repeat(5_000),
                "#end\n".repeat(5_000)
            ),
            1,
        ),
        ("#if (1)\n".repeat(5_000), 5_001),
        (
            format!("#declare A = {}1{};", "(".repeat(5_000), ")".repeat(5_000)),
            1,
        ),
        (format!("#declare A = {}1;", "-".repeat(5_000)), 1),
        ("union {\n".repeat(5_000), 5_000),
        ("}\n".repeat(5_000), 5_000),
        (format!("#declare A = B{};", "[1]".repeat(5_000)), 1),
    ];
    for (text, errors) in cases {
        let parse = parse(&text);
        assert_eq!(parse.syntax_node().to_string(), text);
        assert_eq!(parse.errors().len(), errors, "{}", &text[..40]);
    }
}
