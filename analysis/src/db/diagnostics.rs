//! A file's diagnostics: the file checked as a scene by [`crate::check_with`], exactly as
//! `povrayst check` and the Typst plugin check it, so that every front end reports the
//! same words at the same place.

use super::files::{ProjectFiles, resolve_include};
use super::{Db, File, FilePath};
use std::path::PathBuf;
use syntax::Diagnostic;

/// What checking one file as a scene found.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Checked {
    /// Syntax errors, or the evaluator's warnings and the error that stopped it, in the
    /// order `povrayst check` prints them.
    pub diagnostics: Vec<Diagnostic>,
    /// Where each file name used by the diagnostics leads.
    pub files: Vec<(String, FilePath)>,
    /// Disk files the check read that the database does not hold yet; the server loads
    /// them so that the next check tracks them.
    pub unloaded: Vec<PathBuf>,
}

impl Checked {
    /// Where a file name used by a diagnostic leads.
    pub fn path_of(&self, name: &str) -> Option<&FilePath> {
        self.files
            .iter()
            .find(|(known, _)| known == name)
            .map(|(_, path)| path)
    }
}

/// Checks `file` as a scene with the project's options.
///
/// Runs the whole evaluator again when the file, any include it read or the project's
/// configuration changed; the result holds absolute positions, so nothing else is built
/// on it.
#[salsa::tracked(returns(ref))]
pub fn check_file(db: &dyn Db, file: File) -> Checked {
    let files = ProjectFiles::new(db, file);
    let evaluation = crate::check_with(
        files.main_name(),
        &files,
        file.project(db).options(db),
        db.geometry(),
    );
    let main_name = files.main_name().to_owned();
    let unloaded = files.into_unloaded();
    let names = evaluation
        .sources
        .iter()
        .filter_map(|(name, _)| {
            let path = if name == main_name {
                file.path(db).clone()
            } else {
                resolve_include(db, file, name)?.path(db)
            };
            Some((name.to_owned(), path))
        })
        .collect();
    Checked {
        diagnostics: evaluation.diagnostics,
        files: names,
        unloaded,
    }
}
