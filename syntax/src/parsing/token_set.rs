//! A set of token kinds as a bit set, so that "is the current token one of these" costs a
//! shift and a mask.

use crate::SyntaxKind;

const WORDS: usize = 10;

/// A set of [`SyntaxKind`]s, built at compile time.
#[derive(Clone, Copy)]
pub(crate) struct TokenSet([u64; WORDS]);

impl TokenSet {
    pub(crate) const EMPTY: TokenSet = TokenSet([0; WORDS]);

    pub(crate) const fn new(kinds: &[SyntaxKind]) -> TokenSet {
        let mut words = [0u64; WORDS];
        let mut i = 0;
        while i < kinds.len() {
            let raw = kinds[i] as usize;
            words[raw / 64] |= 1 << (raw % 64);
            i += 1;
        }
        TokenSet(words)
    }

    pub(crate) const fn union(self, other: TokenSet) -> TokenSet {
        let mut words = self.0;
        let mut i = 0;
        while i < WORDS {
            words[i] |= other.0[i];
            i += 1;
        }
        TokenSet(words)
    }

    pub(crate) const fn contains(&self, kind: SyntaxKind) -> bool {
        let raw = kind as usize;
        raw / 64 < WORDS && self.0[raw / 64] & (1 << (raw % 64)) != 0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SyntaxKind::*;

    #[test]
    fn membership_and_union() {
        assert!(
            (INACTIVE as usize) < WORDS * 64,
            "TokenSet is too small for SyntaxKind"
        );
        let set = TokenSet::new(&[IDENT, Z_KW]).union(TokenSet::new(&[INACTIVE]));
        assert!(set.contains(IDENT) && set.contains(Z_KW) && set.contains(INACTIVE));
        assert!(!set.contains(NUMBER) && !TokenSet::EMPTY.contains(IDENT));
    }
}
