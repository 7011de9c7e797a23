//! The rowan flavour of our tree: SDL's kinds as rowan's raw kinds.

use crate::SyntaxKind;

/// Marks rowan trees whose kinds are [`SyntaxKind`]s.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum PovLanguage {}

impl rowan::Language for PovLanguage {
    type Kind = SyntaxKind;

    fn kind_from_raw(raw: rowan::SyntaxKind) -> SyntaxKind {
        SyntaxKind::from_raw(raw.0)
    }

    fn kind_to_raw(kind: SyntaxKind) -> rowan::SyntaxKind {
        kind.into()
    }
}

pub type SyntaxNode = rowan::SyntaxNode<PovLanguage>;
pub type SyntaxToken = rowan::SyntaxToken<PovLanguage>;
pub type SyntaxElement = rowan::SyntaxElement<PovLanguage>;
