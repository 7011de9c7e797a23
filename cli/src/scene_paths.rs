//! The files named on a command line: files as given, directories searched recursively
//! for files with the wanted extensions (`.pov` scenes for `check`, every SDL file for
//! `fmt`), and glob patterns (`scenes/**/*.pov`) for shells that pass them on unexpanded
//! or for patterns quoted on purpose.

use std::path::{Path, PathBuf};

/// Scene files, which `check` looks for in directories. Include files are not scenes: they
/// are checked through the scenes that include them.
pub const SCENES: &[&str] = &["pov"];

/// Every kind of SDL file, which `fmt` looks for in directories.
pub const SDL_FILES: &[&str] = &["pov", "inc", "mcr", "mac"];

/// Expands each argument in turn; files found in a directory come sorted by path. A name
/// that is neither an existing path nor a pattern that matches something is an error.
pub fn expand(arguments: &[String], extensions: &[&str]) -> Result<Vec<PathBuf>, String> {
    let mut scenes = Vec::new();
    for argument in arguments {
        let path = Path::new(argument);
        if path.is_dir() {
            let mut found = Vec::new();
            collect(path, extensions, &mut found)
                .map_err(|error| format!("cannot read directory {argument}: {error}"))?;
            found.sort();
            scenes.extend(found);
        } else if path.exists() || !is_pattern(argument) {
            std::fs::metadata(path).map_err(|error| format!("cannot read {argument}: {error}"))?;
            scenes.push(path.to_path_buf());
        } else {
            let matches =
                glob::glob(argument).map_err(|error| format!("bad pattern {argument}: {error}"))?;
            let before = scenes.len();
            for entry in matches {
                let path = entry.map_err(|error| format!("cannot read {argument}: {error}"))?;
                if path.is_file() {
                    scenes.push(path);
                }
            }
            if scenes.len() == before {
                return Err(format!("no file matches {argument}"));
            }
        }
    }
    let mut seen = std::collections::HashSet::new();
    scenes.retain(|scene| seen.insert(scene.clone()));
    Ok(scenes)
}

fn is_pattern(argument: &str) -> bool {
    argument.contains(['*', '?', '['])
}

/// The files under `dir`, at any depth, whose extension is one of `extensions`.
fn collect(dir: &Path, extensions: &[&str], found: &mut Vec<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let entry = entry?;
        let path = entry.path();
        let file_type = entry.file_type()?;
        if file_type.is_dir() {
            collect(&path, extensions, found)?;
        } else if path.extension().is_some_and(|ext| {
            extensions
                .iter()
                .any(|wanted| ext.eq_ignore_ascii_case(wanted))
        }) {
            found.push(path);
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_directories_and_patterns() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        std::fs::create_dir_all(root.join("a/b")).unwrap();
        for name in [
            "top.pov",
            "a/one.pov",
            "a/b/two.POV",
            "a/b/lib.inc",
            "notes.txt",
        ] {
            std::fs::write(root.join(name), "").unwrap();
        }
        let at = |name: &str| root.join(name).to_str().unwrap().to_owned();
        let shown = |scenes: Vec<PathBuf>| -> Vec<String> {
            scenes
                .iter()
                .map(|p| p.strip_prefix(root).unwrap().to_str().unwrap().to_owned())
                .collect()
        };

        assert_eq!(
            shown(expand(&[at("a")], SCENES).unwrap()),
            ["a/b/two.POV", "a/one.pov"]
        );
        assert_eq!(
            shown(expand(&[at("a")], SDL_FILES).unwrap()),
            ["a/b/lib.inc", "a/b/two.POV", "a/one.pov"]
        );
        assert_eq!(
            shown(expand(&[at("notes.txt"), at("*.pov"), at("top.pov")], SCENES).unwrap()),
            ["notes.txt", "top.pov"]
        );
        assert_eq!(
            shown(expand(&[at("a/**/*.inc")], SCENES).unwrap()),
            ["a/b/lib.inc"]
        );
        let missing = expand(&[at("missing.pov")], SCENES).unwrap_err();
        assert!(missing.starts_with("cannot read "), "{missing}");
        let nothing = expand(&[at("*.mcr")], SCENES).unwrap_err();
        assert!(nothing.starts_with("no file matches "), "{nothing}");
    }
}
