//! The database's inputs: every file the server knows (open documents, include files read
//! from disk, the bundled standard includes, povray blocks of Typst documents) and the
//! project they belong to, which says where includes are searched.

use crate::EvalOptions;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Where a file's text comes from. Only the server turns these into URIs.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum FilePath {
    /// A file on disk (open in the editor or not), by its absolute path.
    Disk(PathBuf),
    /// One of the standard includes bundled with Povrayst, such as `colors.inc`.
    Bundled(&'static str),
    /// The `index`th ```` ```povray ```` block of a Typst document, counted from zero.
    Embedded { document: PathBuf, index: u32 },
}

impl FilePath {
    /// The name the evaluator gives the file when it is checked as a scene. A disk file is
    /// named as `povrayst check NAME` names it when run in the file's directory; a block of
    /// a Typst document as the Typst plugin names the scenes it renders.
    pub fn scene_name(&self) -> String {
        match self {
            FilePath::Disk(path) => path
                .file_name()
                .map(|name| name.to_string_lossy().into_owned())
                .unwrap_or_else(|| path.display().to_string()),
            FilePath::Bundled(name) => (*name).to_owned(),
            FilePath::Embedded { .. } => "scene.pov".to_owned(),
        }
    }

    /// The directory searched first for the file's includes, as the CLI searches the
    /// scene's own directory. Bundled files and Typst blocks have none: a Typst document
    /// renders its blocks with the standard includes only.
    pub fn search_dir(&self) -> Option<&Path> {
        match self {
            FilePath::Disk(path) => path.parent(),
            FilePath::Bundled(_) | FilePath::Embedded { .. } => None,
        }
    }

    /// Whether the user may edit the file (renames never touch bundled includes).
    pub fn is_editable(&self) -> bool {
        !matches!(self, FilePath::Bundled(_))
    }
}

/// The configuration that decides how includes resolve, and the files known so far.
#[salsa::input(debug)]
pub struct Project {
    /// Directories searched for includes after the scene's own, as POV-Ray's `+L`.
    #[returns(ref)]
    pub library_paths: Vec<PathBuf>,
    /// Every file the database holds, by where it comes from.
    #[returns(ref)]
    pub files: BTreeMap<FilePath, File>,
    /// The options scenes are checked with (image size, clock, budgets).
    #[returns(ref)]
    pub options: EvalOptions,
    /// Bumped by the server whenever files appear on or vanish from disk, or change there
    /// without being held as inputs: queries that looked at the disk read it, so that they
    /// run again then.
    #[returns(copy)]
    pub disk_revision: u64,
}

/// One file's text.
#[salsa::input(debug)]
pub struct File {
    #[returns(ref)]
    pub path: FilePath,
    #[returns(ref)]
    pub text: Arc<str>,
    #[returns(copy)]
    pub project: Project,
}
