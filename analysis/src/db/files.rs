//! How a file names its includes: the files a scene checked in the database can read, found
//! the way the CLI finds them (the scene's directory, then the library paths, then the
//! bundled standard includes), but preferring the database's texts, so that unsaved edits
//! of an open include count.

use super::{Db, File, FilePath};
use crate::FileSource;
use std::cell::RefCell;
use std::path::{Component, Path, PathBuf};
use std::sync::Arc;

/// Where an include name leads.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Resolved {
    /// A file the database holds.
    File(File),
    /// A file on disk that the database does not hold yet.
    OnDisk(PathBuf),
    /// A bundled standard include that the database does not hold.
    Bundled(&'static str),
}

impl Resolved {
    /// Where the file comes from.
    pub fn path(&self, db: &dyn Db) -> FilePath {
        match self {
            Resolved::File(file) => file.path(db).clone(),
            Resolved::OnDisk(path) => FilePath::Disk(path.clone()),
            Resolved::Bundled(name) => FilePath::Bundled(name),
        }
    }
}

/// Resolves `name` as an `#include` in a file at `from`, the way the CLI does for a scene
/// there: the file's directory, then the project's library paths, then the bundled files.
///
/// Reads the project's file list, and looks at the disk for names the database does not
/// hold, which is why it also reads the project's disk revision.
pub fn resolve_include(db: &dyn Db, from: File, name: &str) -> Option<Resolved> {
    let project = from.project(db);
    let candidates = candidates(from.path(db), project.library_paths(db), name);
    let files = project.files(db);
    if let Some(file) = candidates
        .iter()
        .find_map(|path| files.get(&FilePath::Disk(path.clone())))
    {
        return Some(Resolved::File(*file));
    }
    if !candidates.is_empty() {
        project.disk_revision(db);
        if let Some(path) = candidates.into_iter().find(|path| path.is_file()) {
            return Some(Resolved::OnDisk(path));
        }
    }
    let bundled = crate::stdinc::names().find(|bundled| *bundled == name)?;
    Some(match files.get(&FilePath::Bundled(bundled)) {
        Some(file) => Resolved::File(*file),
        None => Resolved::Bundled(bundled),
    })
}

/// The paths an include name may stand for, in search order.
fn candidates(from: &FilePath, library_paths: &[PathBuf], name: &str) -> Vec<PathBuf> {
    let relative = Path::new(name);
    if relative.is_absolute() {
        return vec![normalize(relative)];
    }
    match from {
        FilePath::Disk(_) => from
            .search_dir()
            .into_iter()
            .chain(library_paths.iter().map(PathBuf::as_path))
            .map(|dir| normalize(&dir.join(relative)))
            .collect(),
        FilePath::Bundled(_) | FilePath::Embedded { .. } => Vec::new(),
    }
}

/// Removes `.` and folds `dir/..` without touching the disk, so that one file has one key.
pub fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for component in path.components() {
        match component {
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    out.push("..");
                }
            }
            other => out.push(other),
        }
    }
    out
}

/// The files a scene checked in the database reads, as a [`FileSource`] for the evaluator.
/// Names resolve relative to the scene (the main file), as in the CLI.
pub struct ProjectFiles<'db> {
    db: &'db dyn Db,
    main: File,
    main_name: String,
    /// Disk files read that the database does not hold; the server loads them next.
    unloaded: RefCell<Vec<PathBuf>>,
}

impl<'db> ProjectFiles<'db> {
    pub fn new(db: &'db dyn Db, main: File) -> Self {
        ProjectFiles {
            db,
            main,
            main_name: main.path(db).scene_name(),
            unloaded: RefCell::new(Vec::new()),
        }
    }

    /// The name the evaluator knows the main file by.
    pub fn main_name(&self) -> &str {
        &self.main_name
    }

    /// Disk files the evaluation read past the database.
    pub fn into_unloaded(self) -> Vec<PathBuf> {
        self.unloaded.into_inner()
    }
}

impl FileSource for ProjectFiles<'_> {
    fn read(&self, name: &str) -> Option<Arc<str>> {
        if name == self.main_name {
            return Some(self.main.text(self.db).clone());
        }
        match resolve_include(self.db, self.main, name)? {
            Resolved::File(file) => Some(file.text(self.db).clone()),
            Resolved::OnDisk(path) => {
                // As the CLI: a file that is not UTF-8 cannot be read.
                let text = std::fs::read_to_string(&path).ok()?;
                self.unloaded.borrow_mut().push(path);
                Some(Arc::from(text))
            }
            // The evaluator has the bundled files itself.
            Resolved::Bundled(_) => None,
        }
    }

    /// Images and fonts are read from disk as the CLI reads them, so that the server reports
    /// the same errors about them; the database never holds them, since they are not text.
    fn read_bytes(&self, name: &str) -> Option<Arc<[u8]>> {
        match resolve_include(self.db, self.main, name)? {
            Resolved::File(file) => Some(Arc::from(file.text(self.db).as_bytes())),
            Resolved::OnDisk(path) => std::fs::read(path).ok().map(Arc::from),
            Resolved::Bundled(_) => None,
        }
    }

    fn parse(&self, name: &str) -> Option<syntax::Parse> {
        let file = if name == self.main_name {
            self.main
        } else {
            match resolve_include(self.db, self.main, name)? {
                Resolved::File(file) => file,
                Resolved::OnDisk(_) | Resolved::Bundled(_) => return None,
            }
        };
        Some(crate::db::parse(self.db, file).clone())
    }

    /// The files of the scene's directory and the library paths, as the CLI lists them in
    /// "cannot find" errors.
    fn names(&self) -> Vec<String> {
        let project = self.main.project(self.db);
        project.disk_revision(self.db);
        let path = self.main.path(self.db);
        let Some(dir) = path.search_dir() else {
            return Vec::new();
        };
        crate::files::files_in(
            std::iter::once(dir).chain(project.library_paths(self.db).iter().map(PathBuf::as_path)),
        )
    }
}
