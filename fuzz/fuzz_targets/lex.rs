//! The lexer on any text: no panic, and the tokens cover the text exactly, in order.

#![no_main]

use libfuzzer_sys::fuzz_target;
use syntax::SyntaxKind;
use syntax::lexer::{lex, unescape_string};

fuzz_target!(|text: &str| {
    let lexed = lex(text);
    let mut at = 0usize;
    for token in &lexed.tokens {
        assert_eq!(usize::from(token.range.start()), at, "tokens must be contiguous");
        assert!(!token.range.is_empty(), "tokens must not be empty");
        at = usize::from(token.range.end());
        if token.kind == SyntaxKind::STRING {
            unescape_string(&text[token.range]);
        }
    }
    assert_eq!(at, text.len(), "tokens must cover the text");
    for error in &lexed.errors {
        assert!(usize::from(error.range.end()) <= text.len());
    }
});
