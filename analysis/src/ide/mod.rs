//! IDE features over the analysis database, one per module. Each takes the database, a
//! position or file and a config struct, and returns plain data with byte ranges; only the
//! language server turns that into protocol messages.

pub mod classify;
pub mod code_actions;
pub mod completion;
pub mod document_colours;
pub mod document_links;
pub mod document_symbols;
pub mod embedded;
pub mod folding_ranges;
pub mod formatting;
pub mod goto_definition;
pub mod hover;
pub mod inlay_hints;
pub mod keyword_docs;
pub mod references;
pub mod rename;
pub mod semantic_tokens;
pub mod signature_help;
pub mod workspace_symbols;

#[cfg(test)]
mod fixture;

use crate::db::File;
use syntax::{TextRange, TextSize};

/// A place in a file of the database.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FilePosition {
    pub file: File,
    pub offset: TextSize,
}

/// A range in a file of the database.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FileRange {
    pub file: File,
    pub range: TextRange,
}

/// Where a definition is: its whole extent, and the name to put the cursor on.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct NavigationTarget {
    pub file: File,
    pub full_range: TextRange,
    pub focus_range: TextRange,
    pub name: String,
}

/// Text to put in place of a range.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TextEdit {
    pub range: TextRange,
    pub insert: String,
}

/// Edits to several files, each file's edits in text order and not overlapping.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SourceChange {
    pub edits: Vec<(File, Vec<TextEdit>)>,
}

impl NavigationTarget {
    /// Where a symbol is defined: its name, and the whole `#declare`, `#macro` or
    /// parameter around it.
    pub fn of(db: &dyn crate::db::Db, definition: crate::db::Definition) -> Option<Self> {
        let symbol =
            crate::db::file_symbols(db, definition.file).get(definition.symbol as usize)?;
        let focus_range =
            *crate::db::name_ranges(db, definition.file).get(symbol.name_index as usize)?;
        let root = crate::db::parse(db, definition.file).syntax_node();
        let full_range = root
            .covering_element(focus_range)
            .ancestors()
            .find(|node| node.kind() == syntax::SyntaxKind::NAME)
            .and_then(|name| name.parent())
            .map_or(focus_range, |owner| owner.text_range());
        Some(NavigationTarget {
            file: definition.file,
            full_range,
            focus_range,
            name: symbol.name.clone(),
        })
    }
}
