//! Scene, include and data files (images, fonts) from disk, for the evaluator: the scene by the path given on the
//! command line, includes by the name the scene uses, looked up in the scene's own directory
//! and then in each library path (`-L`, POV-Ray's `Library_Path`), as POV-Ray does. The
//! standard includes come after these, from the evaluator itself.

use analysis::FileSource;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The files one scene can read.
#[derive(Debug, Clone)]
pub struct DiskFiles {
    scene: PathBuf,
    search_path: Vec<PathBuf>,
}

impl DiskFiles {
    /// Files for the scene at `scene`: its directory first, then `library_paths`.
    pub fn for_scene(scene: &Path, library_paths: &[PathBuf]) -> DiskFiles {
        let scene_dir = match scene.parent() {
            Some(dir) if !dir.as_os_str().is_empty() => dir.to_path_buf(),
            _ => PathBuf::from("."),
        };
        let search_path = std::iter::once(scene_dir)
            .chain(library_paths.iter().cloned())
            .collect();
        DiskFiles {
            scene: scene.to_path_buf(),
            search_path,
        }
    }
}

impl DiskFiles {
    /// The file on disk that the name `name` stands for, as `read` finds it.
    pub fn locate(&self, name: &str) -> Option<PathBuf> {
        self.candidates(name).next()
    }

    fn candidates<'a>(&'a self, name: &'a str) -> impl Iterator<Item = PathBuf> + 'a {
        let path = Path::new(name);
        // The scene itself, named as on the command line, and absolute include paths; other
        // names are relative to the search path, never to the working directory.
        let direct = path.is_absolute() || path == self.scene;
        direct
            .then(|| path.to_path_buf())
            .into_iter()
            .chain(self.search_path.iter().map(move |dir| dir.join(path)))
            .filter(|candidate| candidate.is_file())
    }
}

impl FileSource for DiskFiles {
    fn read(&self, name: &str) -> Option<Arc<str>> {
        self.candidates(name)
            .find_map(|candidate| analysis::files::read_sdl_file(&candidate).ok())
            .map(Arc::from)
    }

    fn read_bytes(&self, name: &str) -> Option<Arc<[u8]>> {
        self.candidates(name)
            .find_map(|candidate| std::fs::read(candidate).ok())
            .map(Arc::from)
    }

    fn names(&self) -> Vec<String> {
        analysis::files::files_in(self.search_path.iter().map(PathBuf::as_path))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn includes_come_from_the_scene_directory_then_the_library_paths() {
        let scene_dir = tempfile::tempdir().unwrap();
        let library = tempfile::tempdir().unwrap();
        let scene = scene_dir.path().join("scene.pov");
        std::fs::write(&scene, "#include \"a.inc\"").unwrap();
        std::fs::write(scene_dir.path().join("a.inc"), "// scene dir").unwrap();
        std::fs::write(library.path().join("a.inc"), "// library").unwrap();
        std::fs::write(library.path().join("b.inc"), "// library b").unwrap();
        let files = DiskFiles::for_scene(&scene, &[library.path().to_path_buf()]);

        assert_eq!(
            files.read(scene.to_str().unwrap()).as_deref(),
            Some("#include \"a.inc\"")
        );
        assert_eq!(files.read("a.inc").as_deref(), Some("// scene dir"));
        assert_eq!(files.read("b.inc").as_deref(), Some("// library b"));
        assert_eq!(files.read("c.inc"), None);
        assert_eq!(files.locate("b.inc"), Some(library.path().join("b.inc")));
        assert_eq!(files.locate("c.inc"), None);
        // Tests run in the crate's directory, which has a Cargo.toml; it is not on the path.
        assert!(Path::new("Cargo.toml").exists());
        assert_eq!(files.read("Cargo.toml"), None);
        assert_eq!(files.names(), ["a.inc", "b.inc", "scene.pov"]);
    }
}
