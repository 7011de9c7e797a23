//! The conformance suite's programs (`tests/conformance/<group>/<name>.pov`) and the check of
//! one of them: evaluate it with `analysis::check_with` (the renderer answering `trace`,
//! `inside` and the extents, as in the CLI) and compare what it printed with what
//! POV-Ray 3.7 printed, as `tests/conformance/regenerate.sh` recorded it. The README there
//! describes the expectation files and the comparison rules.

use analysis::{EvalOptions, MemoryFiles, Stream};
use std::path::{Path, PathBuf};

/// The suite's directory.
pub fn suite_dir() -> PathBuf {
    crate::workspace_root().join("tests/conformance")
}

/// The settings POV-Ray ran every program with (`+W64 +H48 +K0.25`, no animation).
pub fn options() -> EvalOptions {
    EvalOptions {
        image_width: 64,
        image_height: 48,
        clock: 0.25,
        clock_on: true,
        frame_number: 0,
        initial_frame: 0,
        final_frame: 0,
        initial_clock: 0.0,
        final_clock: 0.0,
        ..EvalOptions::default()
    }
}

/// One program of the suite.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Program {
    pub group: String,
    /// The file name without `.pov`.
    pub name: String,
    dir: PathBuf,
}

impl Program {
    /// `group/name`, the program's name in reports and in `expected_failures.txt`.
    pub fn id(&self) -> String {
        format!("{}/{}", self.group, self.name)
    }

    fn file_name(&self) -> String {
        format!("{}.pov", self.name)
    }

    fn expectation(&self, extension: &str) -> Option<String> {
        std::fs::read_to_string(self.dir.join(format!("{}.{extension}", self.name))).ok()
    }

    /// The program and the other files of its group (includes, data files), as the
    /// evaluator's in-memory file source.
    fn files(&self) -> MemoryFiles {
        let mut files = MemoryFiles::new();
        for path in sorted_entries(&self.dir) {
            let is_expectation = path
                .extension()
                .is_some_and(|e| e == "out" || e == "err" || e == "warn");
            let (Some(name), false) = (path.file_name().and_then(|n| n.to_str()), is_expectation)
            else {
                continue;
            };
            if let Ok(text) = std::fs::read_to_string(&path) {
                files.insert(name, text);
            }
        }
        files
    }
}

fn sorted_entries(dir: &Path) -> Vec<PathBuf> {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.expect("a readable directory entry").path())
        .collect();
    entries.sort();
    entries
}

/// Every program under `root`, by group and name.
pub fn programs(root: &Path) -> Vec<Program> {
    let mut programs = Vec::new();
    for dir in sorted_entries(root).into_iter().filter(|p| p.is_dir()) {
        let group = dir
            .file_name()
            .and_then(|n| n.to_str())
            .expect("UTF-8 group names");
        for path in sorted_entries(&dir) {
            if path.extension().is_some_and(|e| e == "pov") {
                let name = path
                    .file_stem()
                    .and_then(|n| n.to_str())
                    .expect("UTF-8 names");
                programs.push(Program {
                    group: group.to_owned(),
                    name: name.to_owned(),
                    dir: dir.clone(),
                });
            }
        }
    }
    programs
}

/// A message POV-Ray printed at a place: a line of `.err` or `.warn` (`file:line: message`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Located {
    pub file: String,
    /// One-based, as POV-Ray counts.
    pub line: u32,
    pub message: String,
}

impl Located {
    pub fn parse(text: &str) -> Option<Located> {
        let (file, rest) = text.split_once(':')?;
        let (line, message) = rest.split_once(": ")?;
        Some(Located {
            file: file.to_owned(),
            line: line.parse().ok()?,
            message: message.to_owned(),
        })
    }

    /// Where one of our diagnostics points (file, byte offset, message), in the same terms.
    fn of(file: &str, offset: u32, message: &str, evaluation: &analysis::Evaluation) -> Located {
        let text = evaluation.sources.get(file).map(|t| &**t).unwrap_or("");
        let before = text.get(..offset as usize).unwrap_or(text);
        Located {
            file: file.to_owned(),
            line: before.matches('\n').count() as u32 + 1,
            message: message.to_owned(),
        }
    }

    fn same_place(&self, other: &Located) -> bool {
        self.line == other.line && base_name(&self.file) == base_name(&other.file)
    }
}

impl std::fmt::Display for Located {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}: {}", self.file, self.line, self.message)
    }
}

fn base_name(file: &str) -> &str {
    file.rsplit('/').next().unwrap_or(file)
}

/// POV-Ray prints a message's line breaks as spaces and ends it at the last one; compare
/// texts the same way.
fn normalise(text: &str) -> String {
    text.replace(['\n', '\r'], " ").trim().to_owned()
}

const ERROR_DIRECTIVE: &str = "Parse Error: Parse halted by #error directive: ";
const WARNING_PREFIX: &str = "Parse Warning: ";

/// Evaluates `program` and returns how it differs from POV-Ray's output, one finding a line;
/// empty when it conforms.
pub fn check(program: &Program) -> Vec<String> {
    let files = program.files();
    let main = program.file_name();
    let options = options();
    let evaluation = match std::panic::catch_unwind(|| {
        analysis::check_with(&main, &files, &options, &renderer::SceneGeometry)
    }) {
        Ok(evaluation) => evaluation,
        Err(_) => return vec!["the evaluator panicked".to_owned()],
    };
    let mut findings = Vec::new();

    let printed: String = evaluation
        .messages
        .iter()
        .filter(|m| m.stream == Stream::Debug)
        .map(|m| m.text.as_str())
        .collect();
    let expected = program.expectation("out").unwrap_or_default();
    // A syntax error stops us before anything runs, where POV-Ray, which parses as it runs,
    // has printed what came before it: a program that fails may print nothing.
    let stopped_silently = printed.is_empty() && evaluation.has_errors();
    if let Some(difference) = first_difference(&expected, &printed)
        && !(stopped_silently && program.expectation("err").is_some())
    {
        findings.push(difference);
    }

    let ours = evaluation
        .diagnostics
        .iter()
        .find(|d| d.is_error())
        .map(|d| {
            let start = u32::from(d.span.range.start());
            Located::of(&d.span.file, start, &d.message, &evaluation)
        });
    let theirs = program.expectation("err").map(|text| {
        Located::parse(text.trim_end()).unwrap_or_else(|| panic!("{}.err: `{text}`", program.id()))
    });
    match (theirs, ours) {
        (None, None) => {}
        (None, Some(ours)) => findings.push(format!("unexpected error: {ours}")),
        (Some(theirs), None) => findings.push(format!("no error; POV-Ray: {theirs}")),
        (Some(theirs), Some(ours)) => {
            let user_text = theirs.message.strip_prefix(ERROR_DIRECTIVE);
            let text_differs =
                user_text.is_some_and(|text| normalise(&ours.message) != normalise(text));
            if !theirs.same_place(&ours) || text_differs {
                findings.push(format!("error differs: ours {ours}; POV-Ray: {theirs}"));
            }
        }
    }

    let warnings: Vec<Located> = evaluation
        .diagnostics
        .iter()
        .filter(|d| !d.is_error())
        .map(|d| {
            let start = u32::from(d.span.range.start());
            Located::of(&d.span.file, start, &d.message, &evaluation)
        })
        .collect();
    for line in program.expectation("warn").unwrap_or_default().lines() {
        let theirs =
            Located::parse(line).unwrap_or_else(|| panic!("{}.warn: `{line}`", program.id()));
        let text = normalise(
            theirs
                .message
                .strip_prefix(WARNING_PREFIX)
                .unwrap_or(&theirs.message),
        );
        let found = warnings
            .iter()
            .any(|ours| ours.same_place(&theirs) && normalise(&ours.message) == text);
        if !found {
            findings.push(format!("missing warning: {theirs}"));
        }
    }
    findings
}

/// The first line where `ours` differs from `expected`, quoted.
fn first_difference(expected: &str, ours: &str) -> Option<String> {
    if expected == ours {
        return None;
    }
    let mut theirs_lines = expected.split_inclusive('\n');
    let mut our_lines = ours.split_inclusive('\n');
    let mut number = 1;
    loop {
        match (theirs_lines.next(), our_lines.next()) {
            (Some(a), Some(b)) if a == b => number += 1,
            (a, b) => {
                return Some(format!(
                    "#debug line {number}: expected {:?}, got {:?}",
                    a.unwrap_or("<end>"),
                    b.unwrap_or("<end>")
                ));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn write(dir: &Path, name: &str, text: &str) {
        std::fs::write(dir.join(name), text).unwrap();
    }

    /// A one-program suite in a temporary directory.
    fn suite(files: &[(&str, &str)]) -> (tempfile::TempDir, Program) {
        let root = tempfile::tempdir().unwrap();
        let group = root.path().join("group");
        std::fs::create_dir(&group).unwrap();
        for (name, text) in files {
            write(&group, name, text);
        }
        let program = programs(root.path()).remove(0);
        (root, program)
    }

    #[test]
    fn located_lines_parse() {
        let located = Located::parse("a.pov:12: Parse Error: Bad: thing").unwrap();
        assert_eq!(located.file, "a.pov");
        assert_eq!(located.line, 12);
        assert_eq!(located.message, "Parse Error: Bad: thing");
        assert_eq!(Located::parse("povray exited with status 1"), None);
    }

    #[test]
    fn matching_output_conforms() {
        let (_root, program) = suite(&[
            (
                "p.pov",
                "#version 3.7;\n#debug concat(str(1 + 2, 0, 1), \"\\n\")\n",
            ),
            ("p.out", "3.0\n"),
        ]);
        assert_eq!(check(&program), Vec::<String>::new());
    }

    #[test]
    fn a_different_value_is_reported_with_its_line() {
        let (_root, program) = suite(&[
            ("p.pov", "#version 3.7;\n#debug \"a\\n\"\n#debug \"b\\n\"\n"),
            ("p.out", "a\nc\n"),
        ]);
        assert_eq!(
            check(&program),
            ["#debug line 2: expected \"c\\n\", got \"b\\n\""]
        );
    }

    #[test]
    fn a_missing_error_is_reported() {
        let (_root, program) = suite(&[
            ("p.pov", "#version 3.7;\n#debug \"a\\n\"\n"),
            ("p.out", "a\n"),
            ("p.err", "p.pov:2: Parse Error: Something\n"),
        ]);
        assert_eq!(
            check(&program),
            ["no error; POV-Ray: p.pov:2: Parse Error: Something"]
        );
    }

    #[test]
    fn an_error_directive_matches_by_line_and_text() {
        let source = "#version 3.7;\n#debug \"a\\n\"\n#error \"stop\\n\"\n";
        let (_root, program) = suite(&[
            ("p.pov", source),
            ("p.out", "a\n"),
            (
                "p.err",
                "p.pov:3: Parse Error: Parse halted by #error directive: stop \n",
            ),
        ]);
        assert_eq!(check(&program), Vec::<String>::new());
        let (_root, program) = suite(&[
            ("p.pov", source),
            ("p.out", "a\n"),
            (
                "p.err",
                "p.pov:2: Parse Error: Parse halted by #error directive: go\n",
            ),
        ]);
        assert_eq!(check(&program).len(), 1);
    }

    #[test]
    fn a_syntax_error_may_stop_before_any_output() {
        let (_root, program) = suite(&[
            ("p.pov", "#version 3.7;\n#debug \"before\\n\"\n#end\n"),
            ("p.out", "before\n"),
            ("p.err", "p.pov:3: Parse Error: Mis-matched '#end'.\n"),
        ]);
        assert_eq!(check(&program), Vec::<String>::new());
    }

    #[test]
    fn include_files_of_the_group_are_available() {
        let (_root, program) = suite(&[
            (
                "p.pov",
                "#version 3.7;\n#include \"q.inc\"\n#debug concat(str(Q, 0, 0), \"\\n\")\n",
            ),
            ("p.out", "5\n"),
            ("q.inc", "#declare Q = 5;\n"),
        ]);
        assert_eq!(check(&program), Vec::<String>::new());
    }
}
