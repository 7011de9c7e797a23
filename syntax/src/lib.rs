//! The front of every Povrayst tool: the SDL lexer, the lossless syntax tree built on
//! rowan with its parser and typed view, and the [`Diagnostic`] type with its renderers.
//! It knows nothing of evaluation, salsa or editors.

pub mod ast;
pub mod diagnostic;
mod grammar;
pub mod green_walk;
pub mod keyword_groups;
mod kind;
pub mod lexer;
pub mod line_index;
mod parsing;
mod syntax_tree;
#[cfg(test)]
mod tests;

pub use diagnostic::{Diagnostic, Related, Severity, SourceResolver, Span};
pub use kind::{KEYWORDS, SyntaxKind};
pub use parsing::{Parse, SyntaxError, parse, syntax_errors};
pub use rowan::{TextRange, TextSize};
pub use syntax_tree::{PovLanguage, SyntaxElement, SyntaxNode, SyntaxToken};

/// The syntax errors of a parsed file as diagnostics, for `analysis::check` and every
/// front end.
pub fn syntax_diagnostics(file: &str, parse: &Parse) -> Vec<Diagnostic> {
    parse
        .errors()
        .iter()
        .map(|error| Diagnostic::error(file, error.range, error.message.clone()))
        .collect()
}
