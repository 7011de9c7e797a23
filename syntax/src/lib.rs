//! The front of every Povrayst tool: the SDL lexer, the lossless syntax tree built on
//! rowan, and the [`Diagnostic`] type with its renderers. It knows nothing of evaluation,
//! salsa or editors.

pub mod diagnostic;
mod kind;
pub mod lexer;
pub mod line_index;

pub use diagnostic::{Diagnostic, Related, Severity, SourceResolver, Span};
pub use kind::{KEYWORDS, SyntaxKind};
pub use rowan::{TextRange, TextSize};
