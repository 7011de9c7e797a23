//! Debian's povray-examples and povray-includes, the scene corpus the evaluator's corpus
//! test, the formatter's corpus tests and the evaluation benchmark walk
//! (`apt-get install povray-examples povray-includes`).

use std::path::{Path, PathBuf};

/// Where Debian installs the example scenes (and the include files some of them carry).
pub const EXAMPLES: &str = "/usr/share/doc/povray/examples";

/// Where Debian installs POV-Ray's standard include files.
pub const INCLUDES: &str = "/usr/share/povray-3.7/include";

/// Every `.pov` file of the example corpus, in path order; empty when it is not installed.
pub fn example_scenes() -> Vec<PathBuf> {
    files_under(Path::new(EXAMPLES), &["pov"])
}

/// Every file below `dir` whose extension is one of `extensions` (any case), in path
/// order; empty when `dir` does not exist.
pub fn files_under(dir: &Path, extensions: &[&str]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    walk(dir, extensions, &mut out);
    out
}

fn walk(dir: &Path, extensions: &[&str], out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = entries.filter_map(Result::ok).map(|e| e.path()).collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            walk(&path, extensions, out);
        } else if path
            .extension()
            .is_some_and(|e| extensions.iter().any(|x| e.eq_ignore_ascii_case(x)))
        {
            out.push(path);
        }
    }
}
