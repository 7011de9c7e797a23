//! The evaluator's input: the significant tokens of every loaded file, and the stack of
//! frames (the main file, include files, macro bodies) that the token getter reads from.

use super::value::Slot;
use syntax::SyntaxKind::{self, *};
use syntax::lexer;
use syntax::{TextRange, TextSize};

/// An index into the evaluator's list of loaded files.
pub type FileId = u32;

/// One loaded file: its text and its significant tokens (comments and whitespace dropped).
#[derive(Debug)]
pub struct SourceFile {
    pub name: String,
    pub text: std::sync::Arc<str>,
    pub tokens: std::sync::Arc<[RawToken]>,
    /// A bundled standard include: checked by the test suite, lexed once per process.
    pub standard: bool,
}

/// A significant token of a loaded file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RawToken {
    pub kind: SyntaxKind,
    pub start: u32,
    pub end: u32,
}

impl SourceFile {
    pub fn new(name: String, text: std::sync::Arc<str>) -> SourceFile {
        let tokens = significant_tokens(&text);
        SourceFile {
            name,
            text,
            tokens,
            standard: false,
        }
    }

    /// A bundled standard include, whose tokens are shared by every evaluation in the
    /// process: scenes include the same few large files over and over.
    pub fn standard(name: &'static str, text: &'static str) -> SourceFile {
        static CACHE: std::sync::OnceLock<std::sync::Mutex<TokenCache>> =
            std::sync::OnceLock::new();
        let cache = CACHE.get_or_init(Default::default);
        let tokens = match cache.lock() {
            Ok(mut map) => map
                .entry(name)
                .or_insert_with(|| significant_tokens(text))
                .clone(),
            Err(_) => significant_tokens(text),
        };
        SourceFile {
            name: name.to_owned(),
            text: std::sync::Arc::from(text),
            tokens,
            standard: true,
        }
    }
}

/// Tokens of the bundled includes by file name.
type TokenCache = std::collections::HashMap<&'static str, std::sync::Arc<[RawToken]>>;

fn significant_tokens(text: &str) -> std::sync::Arc<[RawToken]> {
    lexer::lex(text)
        .tokens
        .iter()
        .filter(|t| !t.kind.is_trivia())
        .map(|t| RawToken {
            kind: t.kind,
            start: t.range.start().into(),
            end: t.range.end().into(),
        })
        .collect()
}

/// A token as the statement parsers see it: where it came from, and for identifiers the
/// storage they named at the moment they were read (a macro's locals vanish when its body
/// ends, possibly before the parser looks at the value).
#[derive(Debug, Clone)]
pub struct Token {
    pub kind: SyntaxKind,
    pub file: FileId,
    pub start: u32,
    pub end: u32,
    pub slot: Option<Slot>,
}

impl Token {
    pub fn range(&self) -> TextRange {
        TextRange::new(TextSize::new(self.start), TextSize::new(self.end))
    }
}

/// Why a frame exists, which decides what happens when it ends.
#[derive(Debug, Clone, PartialEq)]
pub enum FrameKind {
    Main,
    /// An include file; its `#local`s live in the scope it pushed.
    Include,
    /// A macro body; its parameters and `#local`s live in the scope it pushed.
    Macro {
        def: std::rc::Rc<super::macros::MacroDef>,
    },
}

/// An open conditional or loop directive, waiting for its `#end`.
#[derive(Debug, Clone, PartialEq)]
pub enum Cond {
    /// Inside the branch of an `#if`/`#ifdef`/`#ifndef` that was taken; `#else` and
    /// `#elseif` skip to the `#end`.
    If { opened_at: u32 },
    /// Inside a `#while` body; `#end` jumps back to the condition at `cond_pos`.
    While { cond_pos: usize, opened_at: u32 },
    /// Inside a `#for` body.
    For {
        variable: super::symbols::Symbol,
        end: f64,
        step: f64,
        body_pos: usize,
        opened_at: u32,
    },
    /// Inside a `#switch` whose value is `value`: before its first clause, or (`taken`)
    /// in a clause that matched.
    Switch {
        value: f64,
        opened_at: u32,
        taken: bool,
    },
}

/// A token sequence being read: a file from `pos` to `end`.
#[derive(Debug)]
pub struct Frame {
    pub file: FileId,
    pub pos: usize,
    pub end: usize,
    pub kind: FrameKind,
    pub conds: Vec<Cond>,
    /// Where this frame was entered from (the `#include` or the macro call), for messages.
    pub entered_at: Option<(FileId, TextRange)>,
}

/// True for the directives that open a block closed by `#end`.
pub fn opens_block(kind: SyntaxKind) -> bool {
    matches!(
        kind,
        IF_KW | IFDEF_KW | IFNDEF_KW | WHILE_KW | FOR_KW | SWITCH_KW | MACRO_KW
    )
}
