//! The include graph: which files a file includes by literal name, where those names lead,
//! and the global definitions a file sees through its includes.

use super::files::{Resolved, resolve_include};
use super::{Db, File, file_symbols};
use std::collections::{BTreeMap, HashSet};
use std::path::PathBuf;
use syntax::ast;

/// The names of `file`'s `#include`s that are string literals, in text order. Names built
/// by expressions are only known to the evaluator.
///
/// Position-free: unchanged by edits elsewhere in the file.
#[salsa::tracked(returns(ref))]
pub fn includes(db: &dyn Db, file: File) -> Vec<String> {
    super::parse(db, file)
        .source_file()
        .includes()
        .filter_map(|include: ast::Include| include.path())
        .collect()
}

/// Where one `#include` leads.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IncludeTarget {
    pub name: String,
    /// The file, when the database holds it; `None` for a missing file or one on disk
    /// that the server has not loaded yet.
    pub file: Option<File>,
}

/// Where each of [`includes`] leads, in the same order.
///
/// Reads the project's file list and library paths, and the disk revision for names the
/// database does not hold.
#[salsa::tracked(returns(ref))]
pub fn include_targets(db: &dyn Db, file: File) -> Vec<IncludeTarget> {
    includes(db, file)
        .iter()
        .map(|name| IncludeTarget {
            name: name.clone(),
            file: match resolve_include(db, file, name) {
                Some(Resolved::File(target)) => Some(target),
                _ => None,
            },
        })
        .collect()
}

/// A symbol of some file: the file and the symbol's index in [`file_symbols`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Definition {
    pub file: File,
    pub symbol: u32,
}

/// The global definitions `file` sees through its includes, followed transitively, by
/// name; a later definition of a name replaces an earlier one, as it does when the scene
/// runs. `#local`s and macro parameters stay in their own file.
///
/// Position-free, and equal as long as no included file changes what it defines.
#[salsa::tracked(returns(ref))]
pub fn include_scope(db: &dyn Db, file: File) -> BTreeMap<String, Definition> {
    let mut scope = BTreeMap::new();
    let mut seen = HashSet::from([file]);
    let mut order = Vec::new();
    visit(db, file, &mut seen, &mut order);
    for included in order {
        for (index, symbol) in file_symbols(db, included).iter().enumerate() {
            if symbol.local || matches!(symbol.kind, super::SymbolKind::Parameter) {
                continue;
            }
            scope.insert(
                symbol.name.clone(),
                Definition {
                    file: included,
                    symbol: index as u32,
                },
            );
        }
    }
    scope
}

/// Appends the files `file` includes, depth first in the order they run, each once.
fn visit(db: &dyn Db, file: File, seen: &mut HashSet<File>, order: &mut Vec<File>) {
    for target in include_targets(db, file) {
        let Some(included) = target.file else {
            continue;
        };
        if seen.insert(included) {
            visit(db, included, seen, order);
            order.push(included);
        }
    }
}

/// Disk files that `file` includes, directly or through other includes, by names the
/// database cannot resolve to a file it holds. The server loads them, so that navigation
/// and the include scope reach them.
pub fn unloaded_includes(db: &dyn Db, file: File) -> Vec<PathBuf> {
    let mut unloaded = Vec::new();
    let mut seen = HashSet::from([file]);
    let mut stack = vec![file];
    while let Some(from) = stack.pop() {
        for target in include_targets(db, from) {
            match target.file {
                Some(included) => {
                    if seen.insert(included) {
                        stack.push(included);
                    }
                }
                None => {
                    if let Some(Resolved::OnDisk(path)) = resolve_include(db, from, &target.name) {
                        unloaded.push(path);
                    }
                }
            }
        }
    }
    unloaded
}
