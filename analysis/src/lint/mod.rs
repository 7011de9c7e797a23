//! Warnings about a scene that are not errors: unused declarations, shadowed identifiers,
//! legacy syntax and unknown keywords (the evaluator itself warns of a missing `#version`). They are read from the syntax
//! trees of the scene and the files it includes by literal name, not from an evaluation, so
//! they are found even in a scene the evaluator stops early on, and in `#if` branches it
//! never takes. `povrayst check` reports them; the evaluator's own findings come first.

mod legacy;
mod shadowed;
mod unknown_keyword;
mod unused;
mod workspace;

#[cfg(test)]
mod tests;

use crate::files::{FileSource, Sources};
use syntax::Diagnostic;
pub use workspace::{FileFacts, Origin, Workspace};

/// The stable codes of the lints, as [`Diagnostic::code`] carries them.
pub const CODES: [&str; 4] = [
    unused::CODE,
    shadowed::CODE,
    legacy::CODE,
    unknown_keyword::CODE,
];

/// The code of the lint for declarations nothing uses, which editors show faded.
pub const UNUSED_CODE: &str = unused::CODE;
/// The code of the lint for legacy syntax, which editors show struck through.
pub const LEGACY_CODE: &str = legacy::CODE;

/// What [`lint`] found, with the texts of the files it read so that the warnings can be
/// rendered even where an evaluation stopped before reading them.
#[derive(Debug, Clone)]
pub struct Linted {
    pub warnings: Vec<Diagnostic>,
    pub sources: Sources,
}

/// The warnings for the scene `main`, reading it and its includes from `files` and then
/// from the standard includes, ordered by file and place.
pub fn lint(main: &str, files: &dyn FileSource) -> Linted {
    let workspace = Workspace::load(main, files);
    let mut warnings = Vec::new();
    warnings.extend(unused::check(&workspace));
    warnings.extend(shadowed::check(&workspace));
    warnings.extend(legacy::check(&workspace));
    warnings.extend(unknown_keyword::check(&workspace));
    warnings.sort_by(|a, b| {
        (a.span.file.as_str(), a.span.range.start())
            .cmp(&(b.span.file.as_str(), b.span.range.start()))
    });
    let mut sources = Sources::default();
    for file in &workspace.files {
        sources.insert(&file.name, file.text.clone());
    }
    Linted { warnings, sources }
}
