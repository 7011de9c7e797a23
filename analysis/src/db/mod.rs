//! The incremental analysis database the language server queries, built on salsa.
//!
//! Inputs are the texts of files ([`File`]) and the include search configuration
//! ([`Project`]); everything else is a query, a documented free function whose result salsa
//! caches until an input it read changes. Queries that other queries build on keep absolute
//! positions out of their results (symbols are numbered, not located), so that an edit
//! which only moves text leaves them equal and their dependents are reused.
//!
//! A write to an input cancels every query running on a clone of the database: those
//! unwind with [`salsa::Cancelled`], which the server turns into a "content modified" answer.

mod diagnostics;
mod files;
mod include_graph;
mod inputs;
mod resolve;
mod symbols;
mod tree;

pub use diagnostics::{Checked, check_file};
pub use files::ProjectFiles;
pub use files::{Resolved, normalize, resolve_include};
pub use include_graph::{
    Definition, IncludeTarget, include_scope, include_targets, includes, unloaded_includes,
};
pub use inputs::{File, FilePath, Project};
pub use resolve::{identifiers, name_index, resolve_file};
pub use symbols::{
    Constant, MacroParam, Symbol, SymbolKind, ValueKind, doc_comment, file_symbols, fold,
    name_ranges,
};
pub use tree::{line_index, parse};

use crate::geometry::{Geometry, NoGeometry};
use std::sync::Arc;

/// The queries' view of the database.
#[salsa::db]
pub trait Db: salsa::Database {
    /// What answers the scenes' geometric queries (`trace()`, `inside()`, the extents, the
    /// `object` pattern) while they are checked: the renderer, for the language server.
    fn geometry(&self) -> &dyn Geometry;
}

/// The one concrete database: the language server holds one and hands clones to the
/// threads that answer requests.
#[salsa::db]
#[derive(Clone)]
pub struct RootDatabase {
    storage: salsa::Storage<Self>,
    geometry: Arc<dyn Geometry>,
}

#[salsa::db]
impl salsa::Database for RootDatabase {}

#[salsa::db]
impl Db for RootDatabase {
    fn geometry(&self) -> &dyn Geometry {
        &*self.geometry
    }
}

impl Default for RootDatabase {
    fn default() -> Self {
        RootDatabase::with_events(None)
    }
}

impl RootDatabase {
    /// A database that reports salsa's events (query runs, cancellations) to `callback`,
    /// for tests that check what is recomputed.
    ///
    /// Registers every input and query by hand: salsa's automatic registration relies on
    /// link-time constructors that we do not want.
    pub fn with_events(callback: Option<Box<dyn Fn(salsa::Event) + Send + Sync>>) -> Self {
        let mut builder = salsa::Storage::builder();
        if let Some(callback) = callback {
            builder = builder.event_callback(callback);
        }
        let storage = builder
            .ingredient::<Project>()
            .ingredient::<File>()
            .ingredient::<tree::parse>()
            .ingredient::<tree::line_index>()
            .ingredient::<symbols::file_symbols>()
            .ingredient::<symbols::name_ranges>()
            .ingredient::<include_graph::includes>()
            .ingredient::<include_graph::include_targets>()
            .ingredient::<include_graph::include_scope>()
            .ingredient::<resolve::resolve_file>()
            .ingredient::<diagnostics::check_file>()
            .build();
        RootDatabase {
            storage,
            geometry: Arc::new(NoGeometry),
        }
    }

    /// The database with `geometry` answering the scenes' geometric queries; without it
    /// they are located errors.
    pub fn with_geometry(self, geometry: Arc<dyn Geometry>) -> Self {
        RootDatabase { geometry, ..self }
    }
}

#[cfg(test)]
mod tests;
