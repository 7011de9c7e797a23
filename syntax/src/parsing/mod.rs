//! From text to a lossless syntax tree: lex, find the structure of brackets and
//! directives, run the grammar, and build the rowan tree from the grammar's events with
//! whitespace and comments put back where they stood.

mod parser;
mod structure;
mod token_set;

pub use parser::SyntaxError;
pub(crate) use parser::{CompletedMarker, DEPTH_LIMIT, Marker, Parser, describe_kind};
pub(crate) use structure::{Group, GroupKind, Mark, Mode};
pub(crate) use token_set::TokenSet;

use crate::lexer::{Token, lex};
use crate::syntax_tree::SyntaxNode;
use crate::{SyntaxKind, grammar};
use parser::Event;

type GreenElement = NodeOrToken<GreenNode, GreenToken>;
use rowan::{GreenNode, GreenToken, NodeOrToken, TextRange};
use std::collections::HashMap;
use std::fmt::Write;

/// The result of parsing one file: a tree that holds every byte of it, and the errors.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Parse {
    green: GreenNode,
    errors: Vec<SyntaxError>,
}

impl Parse {
    pub fn syntax_node(&self) -> SyntaxNode {
        SyntaxNode::new_root(self.green.clone())
    }

    pub fn green(&self) -> &GreenNode {
        &self.green
    }

    /// Lexer and parser errors, in text order.
    pub fn errors(&self) -> &[SyntaxError] {
        &self.errors
    }

    /// The typed root of the tree.
    pub fn source_file(&self) -> crate::ast::SourceFile {
        crate::ast::SourceFile::new(self.syntax_node())
    }

    /// The tree one node or token a line, indented, with byte ranges; then the errors.
    pub fn debug_tree(&self) -> String {
        let mut out = String::new();
        let mut depth = 0usize;
        for event in self.syntax_node().preorder_with_tokens() {
            match event {
                rowan::WalkEvent::Enter(element) => {
                    let _ = write!(out, "{:indent$}", "", indent = depth * 2);
                    match element {
                        rowan::NodeOrToken::Node(node) => {
                            let _ = writeln!(out, "{:?}@{:?}", node.kind(), node.text_range());
                        }
                        rowan::NodeOrToken::Token(token) => {
                            let _ = writeln!(
                                out,
                                "{:?}@{:?} {:?}",
                                token.kind(),
                                token.text_range(),
                                token.text()
                            );
                        }
                    }
                    depth += 1;
                }
                rowan::WalkEvent::Leave(_) => depth -= 1,
            }
        }
        for error in &self.errors {
            let _ = writeln!(out, "error {:?}: {}", error.range, error.message);
        }
        out
    }
}

/// Parses SDL text. Never fails: problems are reported in [`Parse::errors`] and the tree
/// still holds every byte of `text`.
pub fn parse(text: &str) -> Parse {
    let (tokens, events, errors) = run_grammar(text);
    let green = build_tree(text, &tokens, events);
    Parse { green, errors }
}

/// The errors [`parse`] reports, without building the tree: for a front end that only
/// needs to know that a file is well formed before it runs the file's tokens.
pub fn syntax_errors(text: &str) -> Vec<SyntaxError> {
    run_grammar(text).2
}

/// Lexes `text` and runs the grammar over it: every token, the grammar's events and all
/// the errors, in text order.
fn run_grammar(text: &str) -> (Vec<Token>, Vec<Event>, Vec<SyntaxError>) {
    let lexed = lex(text);
    let significant: Vec<&Token> = lexed
        .tokens
        .iter()
        .filter(|t| is_significant(t.kind))
        .collect();
    let kinds: Vec<SyntaxKind> = significant.iter().map(|t| t.kind).collect();
    let ranges: Vec<TextRange> = significant.iter().map(|t| t.range).collect();
    let layout = layout(text, &significant);
    let structure = structure::analyze(&kinds, &layout);
    let directive_errors = directive_errors(&kinds, &ranges, &structure);

    let mut p = Parser::new(&kinds, &ranges, &layout.first_on_line, &structure);
    grammar::source_file(&mut p);
    if p.ran_away() {
        p.finish_runaway();
    }
    let Parser {
        events,
        errors: parse_errors,
        ..
    } = p;

    let mut errors: Vec<SyntaxError> = lexed
        .errors
        .into_iter()
        .map(|e| SyntaxError {
            range: e.range,
            message: e.message,
        })
        .chain(directive_errors)
        .chain(parse_errors)
        .collect();
    errors.sort_by_key(|e| (e.range.start(), e.range.end()));
    (lexed.tokens, events, errors)
}

/// Directives that do not pair up: a group without `#end`, an `#else` or `#end` that
/// belongs to nothing. Reported from the structure rather than by the grammar, so that
/// they also show inside macro bodies kept as tokens.
fn directive_errors(
    kinds: &[SyntaxKind],
    ranges: &[TextRange],
    structure: &structure::Structure,
) -> Vec<SyntaxError> {
    let directive = |hash: usize| ranges[hash].cover(ranges[hash + 1]);
    let name = |hash: usize| kinds[hash + 1].keyword_text().unwrap_or("directive");
    let mut errors = Vec::new();
    for group in &structure.groups {
        if group.end.is_none() {
            let open = group.open as usize;
            errors.push(SyntaxError {
                range: directive(open),
                message: format!("#{} has no matching #end", name(open)),
            });
        }
    }
    for (hash, mark) in structure.marks.iter().enumerate() {
        if *mark != Mark::Stray || kinds[hash] != SyntaxKind::HASH {
            continue;
        }
        let message = match kinds[hash + 1] {
            SyntaxKind::ELSE_KW => "#else without #if or #switch",
            SyntaxKind::ELSEIF_KW => "#elseif without #if",
            SyntaxKind::CASE_KW => "#case outside #switch",
            SyntaxKind::RANGE_KW => "#range outside #switch",
            _ => "#end without #if, #while, #for, #switch or #macro",
        };
        errors.push(SyntaxError {
            range: directive(hash),
            message: message.to_string(),
        });
    }
    errors
}

/// Whether the grammar sees a token: trivia and the lexer's error tokens (already
/// reported by the lexer) are only put back into the tree.
fn is_significant(kind: SyntaxKind) -> bool {
    !kind.is_trivia() && kind != SyntaxKind::ERROR
}

/// Indentation facts about each significant token, for recovery from unclosed regions.
pub(crate) fn layout(text: &str, significant: &[&Token]) -> structure::Layout {
    let bytes = text.as_bytes();
    let mut first_on_line = Vec::with_capacity(significant.len());
    let mut indent = Vec::with_capacity(significant.len());
    let mut line_start = 0usize;
    let mut previous_end = 0usize;
    let mut current_indent = 0u32;
    let mut line_has_token = false;
    for token in significant {
        let start = usize::from(token.range.start());
        if let Some(newline) = bytes[previous_end..start]
            .iter()
            .rposition(|&b| b == b'\n' || b == b'\r')
        {
            line_start = previous_end + newline + 1;
            line_has_token = false;
        }
        let first = !line_has_token;
        if first {
            current_indent = display_column(&bytes[line_start..start]);
        }
        first_on_line.push(first);
        indent.push(current_indent);
        line_has_token = true;
        previous_end = usize::from(token.range.end());
    }
    structure::Layout {
        first_on_line,
        indent,
    }
}

/// The display width of a line's prefix, with tabs to the next multiple of 8.
fn display_column(prefix: &[u8]) -> u32 {
    prefix.iter().fold(0u32, |col, &b| match b {
        b'\t' => (col / 8 + 1) * 8,
        // Continuation bytes of a UTF-8 character add no width.
        0x80..=0xbf => col,
        _ => col + 1,
    })
}

/// Replays the grammar's events over all tokens. Trivia before a node goes outside it,
/// so that a comment or blank line belongs to the enclosing node.
fn build_tree<'t>(text: &'t str, tokens: &[Token], mut events: Vec<Event>) -> GreenNode {
    let mut builder = TreeBuilder::default();
    let mut cursor = 0usize;
    let mut forward_kinds = Vec::new();

    let flush_trivia = |builder: &mut TreeBuilder<'t>, cursor: &mut usize| {
        while let Some(token) = tokens.get(*cursor) {
            if is_significant(token.kind) {
                break;
            }
            builder.token(token.kind, &text[token.range]);
            *cursor += 1;
        }
    };

    for i in 0..events.len() {
        match std::mem::replace(&mut events[i], Event::Tombstone) {
            Event::Start {
                kind,
                forward_parent,
            } => {
                forward_kinds.push(kind);
                let mut at = i;
                let mut next = forward_parent;
                while let Some(offset) = next {
                    at += offset as usize;
                    next = match std::mem::replace(&mut events[at], Event::Tombstone) {
                        Event::Start {
                            kind,
                            forward_parent,
                        } => {
                            forward_kinds.push(kind);
                            forward_parent
                        }
                        _ => None,
                    };
                }
                for kind in forward_kinds.drain(..).rev() {
                    if builder.depth() > 0 {
                        flush_trivia(&mut builder, &mut cursor);
                    }
                    builder.start_node(kind);
                }
            }
            Event::Finish => {
                if builder.depth() == 1 {
                    // The root keeps the trailing whitespace and comments.
                    while cursor < tokens.len() {
                        let token = &tokens[cursor];
                        builder.token(token.kind, &text[token.range]);
                        cursor += 1;
                    }
                }
                builder.finish_node();
            }
            Event::Token => {
                flush_trivia(&mut builder, &mut cursor);
                if let Some(token) = tokens.get(cursor) {
                    builder.token(token.kind, &text[token.range]);
                    cursor += 1;
                }
            }
            Event::Tombstone => {}
        }
    }
    builder.finish()
}

/// Builds green nodes directly. rowan's own builder deduplicates small nodes by hashing
/// their whole subtree, which is quadratic in the depth of a chain such as `1+1+...+1`;
/// only tokens are shared here.
#[derive(Default)]
struct TreeBuilder<'t> {
    parents: Vec<(SyntaxKind, usize)>,
    children: Vec<GreenElement>,
    tokens: HashMap<(SyntaxKind, &'t str), GreenToken>,
}

impl<'t> TreeBuilder<'t> {
    fn depth(&self) -> usize {
        self.parents.len()
    }

    fn start_node(&mut self, kind: SyntaxKind) {
        self.parents.push((kind, self.children.len()));
    }

    fn token(&mut self, kind: SyntaxKind, text: &'t str) {
        // Numbers, strings and comments seldom repeat: sharing them would only fill the
        // table (mesh data files hold hundreds of thousands of distinct numbers).
        let token = if matches!(
            kind,
            SyntaxKind::NUMBER
                | SyntaxKind::STRING
                | SyntaxKind::LINE_COMMENT
                | SyntaxKind::BLOCK_COMMENT
        ) {
            GreenToken::new(kind.into(), text)
        } else {
            self.tokens
                .entry((kind, text))
                .or_insert_with(|| GreenToken::new(kind.into(), text))
                .clone()
        };
        self.children.push(NodeOrToken::Token(token));
    }

    fn finish_node(&mut self) {
        if let Some((kind, first)) = self.parents.pop() {
            let node = GreenNode::new(kind.into(), self.children.drain(first..));
            self.children.push(NodeOrToken::Node(node));
        }
    }

    fn finish(mut self) -> GreenNode {
        while !self.parents.is_empty() {
            self.finish_node();
        }
        match self.children.pop() {
            Some(NodeOrToken::Node(node)) => node,
            _ => GreenNode::new(SyntaxKind::SOURCE_FILE.into(), std::iter::empty()),
        }
    }
}
