//! The syntax tree and line index of a file.

use super::{Db, File};
use syntax::Parse;
use syntax::line_index::LineIndex;

/// The lossless syntax tree of `file` with its syntax errors.
///
/// Re-parses whenever the text changes; a parse is compared by its green tree, so an edit
/// that restores earlier text lets dependents reuse their results.
#[salsa::tracked(returns(ref))]
pub fn parse(db: &dyn Db, file: File) -> Parse {
    syntax::parse(file.text(db))
}

/// Line starts of `file`, for converting offsets to lines and columns.
///
/// Changes with every edit that adds or removes a line break, or moves one; nothing that
/// other queries cache depends on it.
#[salsa::tracked(returns(ref))]
pub fn line_index(db: &dyn Db, file: File) -> LineIndex {
    LineIndex::new(file.text(db))
}
