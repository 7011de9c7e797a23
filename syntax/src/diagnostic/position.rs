//! Where a span starts and ends as one-based lines and columns, for the machine-readable
//! formats. Columns count Unicode scalar values, not display cells or UTF-16 units, so a
//! consumer that knows the file's text can find the place without knowing our tab width.

use super::{SourceResolver, Span};
use crate::line_index::LineIndex;
use rowan::TextSize;
use std::collections::HashMap;

/// A one-based line and column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Position {
    pub line: u32,
    pub column: u32,
}

/// The start and end of a span; `None` when the file's text is unknown.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Region {
    pub start: Position,
    pub end: Position,
}

/// Line indexes of the files met so far, one per file, so that many diagnostics in one
/// file cost one index.
pub struct Locator<'s, R: SourceResolver + ?Sized> {
    sources: &'s R,
    indexes: HashMap<String, LineIndex>,
}

impl<'s, R: SourceResolver + ?Sized> Locator<'s, R> {
    pub fn new(sources: &'s R) -> Self {
        Locator {
            sources,
            indexes: HashMap::new(),
        }
    }

    pub fn region(&mut self, span: &Span) -> Option<Region> {
        let text = self.sources.source(&span.file)?;
        let index = self
            .indexes
            .entry(span.file.clone())
            .or_insert_with(|| LineIndex::new(text));
        let position = |offset: TextSize| {
            let line = index.line(offset);
            let start = u32::from(index.line_start(line).unwrap_or_default()) as usize;
            let end = (u32::from(offset) as usize).clamp(start, text.len());
            let column = text.get(start..end).map_or(0, |s| s.chars().count()) as u32;
            Position {
                line: line + 1,
                column: column + 1,
            }
        };
        Some(Region {
            start: position(span.range.start()),
            end: position(span.range.end()),
        })
    }
}
