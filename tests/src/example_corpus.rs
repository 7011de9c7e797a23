//! Debian's povray-examples, the scene corpus the evaluator's corpus test and benchmark
//! walk (`apt-get install povray-examples`).

use std::path::{Path, PathBuf};

/// Where Debian installs the example scenes.
pub const EXAMPLES: &str = "/usr/share/doc/povray/examples";

/// Every `.pov` file of the corpus, in path order; empty when it is not installed.
pub fn example_scenes() -> Vec<PathBuf> {
    let mut out = Vec::new();
    walk(Path::new(EXAMPLES), &mut out);
    out
}

fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = entries.filter_map(Result::ok).map(|e| e.path()).collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            walk(&path, out);
        } else if path.extension().is_some_and(|e| e == "pov") {
            out.push(path);
        }
    }
}
