//! Evaluates every scene of Debian's povray-examples with our evaluator and standard
//! includes: each must give a scene or a located error, never a panic or a hang. Prints the
//! counts and the most common unsupported features. Skips (and says so) when the corpus is
//! not installed; the README's test command installs it.

use analysis::{Budgets, DirectoryFiles, EvalOptions, evaluate};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

const EXAMPLES: &str = "/usr/share/doc/povray/examples";

fn scenes(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = entries.filter_map(Result::ok).map(|e| e.path()).collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            scenes(&path, out);
        } else if path.extension().is_some_and(|e| e == "pov") {
            out.push(path);
        }
    }
}

#[test]
fn every_example_scene_evaluates_or_fails_with_a_located_error() {
    let mut paths = Vec::new();
    scenes(Path::new(EXAMPLES), &mut paths);
    if paths.is_empty() {
        eprintln!(
            "skipped: the example corpus is not installed at {EXAMPLES} (apt-get install povray-examples)"
        );
        return;
    }
    let options = EvalOptions {
        budgets: Budgets {
            steps: 20_000_000,
            loop_iterations: 2_000_000,
            ..Budgets::default()
        },
        ..EvalOptions::default()
    };
    let mut evaluated = 0;
    let mut unsupported: BTreeMap<String, usize> = BTreeMap::new();
    let mut other_errors = Vec::new();
    for path in &paths {
        let dir = path
            .parent()
            .expect("a scene lives in a directory")
            .to_path_buf();
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .expect("UTF-8 names")
            .to_owned();
        let files = DirectoryFiles::new([dir]);
        let evaluation = std::panic::catch_unwind(|| evaluate(&name, &files, &options))
            .unwrap_or_else(|_| panic!("the evaluator panicked on {}", path.display()));
        match evaluation.diagnostics.iter().find(|d| d.is_error()) {
            None => evaluated += 1,
            Some(error) => {
                assert!(
                    !error.span.file.is_empty(),
                    "unlocated error for {}",
                    path.display()
                );
                match error.message.strip_prefix("not supported yet: ") {
                    Some(feature) => *unsupported.entry(feature.to_owned()).or_default() += 1,
                    None => {
                        let text = evaluation
                            .sources
                            .get(&error.span.file)
                            .map(|t| t.to_string())
                            .unwrap_or_default();
                        let index = syntax::line_index::LineIndex::new(&text);
                        let at = index.display_line_col(&text, error.span.range.start());
                        other_errors.push(format!(
                            "{} ({}:{}:{}): {}",
                            path.display(),
                            error.span.file,
                            at.line + 1,
                            at.col + 1,
                            error.message
                        ));
                    }
                }
            }
        }
    }
    let mut features: Vec<_> = unsupported.iter().collect();
    features.sort_by(|a, b| b.1.cmp(a.1));
    eprintln!(
        "{} scenes: {evaluated} evaluated, {} not supported yet, {} other errors",
        paths.len(),
        unsupported.values().sum::<usize>(),
        other_errors.len()
    );
    for (feature, count) in features.iter().take(25) {
        eprintln!("  {count:4}  not supported yet: {feature}");
    }
    for error in &other_errors {
        eprintln!("  error: {error}");
    }
}
