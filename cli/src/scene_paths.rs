//! The scenes named on a command line: files as given, directories searched recursively
//! for `.pov` files, and glob patterns (`scenes/**/*.pov`) for shells that pass them on
//! unexpanded or for patterns quoted on purpose.

use std::path::{Path, PathBuf};

/// Expands each argument in turn; scenes found in a directory come sorted by path. A name
/// that is neither an existing path nor a pattern that matches something is an error.
pub fn expand(arguments: &[String]) -> Result<Vec<PathBuf>, String> {
    let mut scenes = Vec::new();
    for argument in arguments {
        let path = Path::new(argument);
        if path.is_dir() {
            let mut found = Vec::new();
            collect_scenes(path, &mut found)
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

/// The `.pov` files under `dir`, at any depth. Include files are not scenes: they are
/// checked through the scenes that include them.
fn collect_scenes(dir: &Path, found: &mut Vec<PathBuf>) -> std::io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let entry = entry?;
        let path = entry.path();
        let file_type = entry.file_type()?;
        if file_type.is_dir() {
            collect_scenes(&path, found)?;
        } else if path
            .extension()
            .is_some_and(|ext| ext.eq_ignore_ascii_case("pov"))
        {
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
            shown(expand(&[at("a")]).unwrap()),
            ["a/b/two.POV", "a/one.pov"]
        );
        assert_eq!(
            shown(expand(&[at("notes.txt"), at("*.pov"), at("top.pov")]).unwrap()),
            ["notes.txt", "top.pov"]
        );
        assert_eq!(shown(expand(&[at("a/**/*.inc")]).unwrap()), ["a/b/lib.inc"]);
        let missing = expand(&[at("missing.pov")]).unwrap_err();
        assert!(missing.starts_with("cannot read "), "{missing}");
        let nothing = expand(&[at("*.mcr")]).unwrap_err();
        assert!(nothing.starts_with("no file matches "), "{nothing}");
    }
}
