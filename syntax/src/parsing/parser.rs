//! The parser's state and the few primitives every grammar rule is written with.
//!
//! Grammar rules see only significant tokens (no whitespace, comments or lexer error
//! tokens) and record what they find as a flat list of [`Event`]s; the tree is built from
//! the events afterwards, with the trivia put back. Every region a rule parses has a
//! limit (the closer of its bracket, the end of a directive branch) past which the rule
//! sees `EOF`, so no rule can run into its neighbour's tokens.

use super::structure::{Mark, Structure};
use super::token_set::TokenSet;
use crate::SyntaxKind::{self, *};
use rowan::{TextRange, TextSize};

/// Guards against a grammar rule that stops making progress: a bug, never a user error,
/// so it only ends parsing early instead of looping.
const STEP_LIMIT_PER_TOKEN: u64 = 64;
/// Deeper nesting than this is reported, not recursed into, so that the stack holds.
pub(crate) const DEPTH_LIMIT: u32 = 200;

#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Event {
    /// Starts a node. `forward_parent` points at a later `Start` event whose node must
    /// enclose this one (set by [`CompletedMarker::precede`]).
    Start {
        kind: SyntaxKind,
        forward_parent: Option<u32>,
    },
    Finish,
    /// The next significant token.
    Token,
    /// The slot of a node that has started but not finished, or an event already used.
    Tombstone,
}

/// A problem the parser found, with where it is in the text.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct SyntaxError {
    pub range: TextRange,
    pub message: String,
}

pub(crate) struct Parser<'t> {
    kinds: &'t [SyntaxKind],
    ranges: &'t [TextRange],
    /// Whether each token starts its line: a missing token is reported where the
    /// previous line ends rather than on the next line.
    first_on_line: &'t [bool],
    pub(crate) structure: &'t Structure,
    pos: usize,
    limit: usize,
    pub(crate) events: Vec<Event>,
    pub(crate) errors: Vec<SyntaxError>,
    steps: u64,
    max_steps: u64,
    pub(crate) depth: u32,
    /// Whether relational, logical and conditional operators are allowed here.
    pub(crate) full_operators: bool,
    /// Whether `>` closes a vector here instead of comparing.
    pub(crate) no_gt: bool,
    /// Whether the current `( )` or `[ ]` is never closed: lists in it end at the first
    /// token that does not fit, without an error, since the missing closer was probably
    /// meant to stand there.
    pub(crate) lenient_end: bool,
    /// Whether a directive was the last thing parsed: the text it stands for is unknown,
    /// so a missing operand or value right after it is not an error.
    pub(crate) after_directive: bool,
    reported_too_deep: bool,
}

impl<'t> Parser<'t> {
    pub(crate) fn new(
        kinds: &'t [SyntaxKind],
        ranges: &'t [TextRange],
        first_on_line: &'t [bool],
        structure: &'t Structure,
    ) -> Self {
        Parser {
            kinds,
            ranges,
            first_on_line,
            structure,
            pos: 0,
            limit: kinds.len(),
            events: Vec::with_capacity(kinds.len() * 2),
            errors: Vec::new(),
            steps: 0,
            max_steps: (kinds.len() as u64 + 16) * STEP_LIMIT_PER_TOKEN,
            depth: 0,
            full_operators: false,
            no_gt: false,
            lenient_end: false,
            after_directive: false,
            reported_too_deep: false,
        }
    }

    /// The kind of the token `n` places ahead, or `EOF` past the current limit.
    pub(crate) fn nth(&mut self, n: usize) -> SyntaxKind {
        self.steps += 1;
        // Past the step limit a rule has stopped making progress: pretend the input ended
        // so that every loop terminates; `finish_runaway` reports what is left.
        let at = self.pos + n;
        if at < self.limit && self.steps <= self.max_steps {
            self.kinds[at]
        } else {
            EOF
        }
    }

    pub(crate) fn current(&mut self) -> SyntaxKind {
        self.nth(0)
    }

    pub(crate) fn at(&mut self, kind: SyntaxKind) -> bool {
        self.current() == kind
    }

    pub(crate) fn at_ts(&mut self, set: TokenSet) -> bool {
        set.contains(self.current())
    }

    pub(crate) fn at_end(&mut self) -> bool {
        self.current() == EOF
    }

    /// The index of the current significant token.
    pub(crate) fn pos(&self) -> usize {
        self.pos
    }

    pub(crate) fn mark(&self, at: usize) -> Mark {
        self.structure.marks.get(at).copied().unwrap_or(Mark::None)
    }

    /// Consumes the current token.
    pub(crate) fn bump_any(&mut self) {
        if self.pos < self.limit && self.steps <= self.max_steps {
            self.pos += 1;
            self.events.push(Event::Token);
            self.after_directive = false;
        }
    }

    /// Consumes the current token, which the caller knows to be `kind`.
    pub(crate) fn bump(&mut self, kind: SyntaxKind) {
        debug_assert_eq!(self.current(), kind);
        self.bump_any();
    }

    pub(crate) fn eat(&mut self, kind: SyntaxKind) -> bool {
        if self.at(kind) {
            self.bump_any();
            true
        } else {
            false
        }
    }

    /// Consumes `kind` or reports that it is missing.
    pub(crate) fn expect(&mut self, kind: SyntaxKind, what: &str) -> bool {
        if self.eat(kind) {
            return true;
        }
        self.error_expected(what);
        false
    }

    /// Reports that `what` is missing at the current token, unless a directive just
    /// before may have supplied it.
    pub(crate) fn error_expected(&mut self, what: &str) {
        if self.after_directive {
            return;
        }
        let found = self.describe_current();
        let message = format!("expected {what}, found {found}");
        let at_line_start =
            self.pos >= self.limit || self.first_on_line.get(self.pos).copied().unwrap_or(true);
        if at_line_start && self.pos > 0 {
            self.error_at(TextRange::empty(self.previous_end()), message);
        } else {
            self.error_here(message);
        }
    }

    /// Reports nesting beyond [`DEPTH_LIMIT`], once: the levels below the first report
    /// would only repeat it.
    pub(crate) fn error_too_deep(&mut self) {
        if !self.reported_too_deep {
            self.reported_too_deep = true;
            self.error_here("nesting too deep");
        }
    }

    /// Reports an error at the current token, or just after the previous one at the end.
    pub(crate) fn error_here(&mut self, message: impl Into<String>) {
        let range = if self.pos < self.limit {
            self.ranges[self.pos]
        } else {
            TextRange::empty(self.previous_end())
        };
        self.error_at(range, message);
    }

    pub(crate) fn error_at(&mut self, range: TextRange, message: impl Into<String>) {
        self.errors.push(SyntaxError {
            range,
            message: message.into(),
        });
    }

    pub(crate) fn range_of(&self, index: usize) -> TextRange {
        self.ranges
            .get(index)
            .copied()
            .unwrap_or_else(|| TextRange::empty(self.previous_end()))
    }

    fn previous_end(&self) -> TextSize {
        self.pos
            .checked_sub(1)
            .and_then(|p| self.ranges.get(p))
            .map_or(TextSize::new(0), |r| r.end())
    }

    /// How the current token reads in an error message.
    pub(crate) fn describe_current(&mut self) -> String {
        match self.current() {
            EOF if self.limit < self.kinds.len() => {
                describe_kind(self.kinds[self.limit]).to_string()
            }
            EOF => "end of file".to_string(),
            kind => describe_kind(kind).to_string(),
        }
    }

    /// Consumes a run of tokens the grammar has no place for, as one error node with one
    /// error, stopping before anything in `recovery`.
    pub(crate) fn err_and_bump_run(&mut self, message: &str, recovery: TokenSet) {
        let m = self.start();
        let start = self.pos;
        self.bump_any();
        while !self.at_end() && !self.at_ts(recovery) {
            self.bump_any();
        }
        let range = TextRange::new(self.ranges[start].start(), self.ranges[self.pos - 1].end());
        self.error_at(range, message);
        m.complete(self, ERROR_NODE);
    }

    /// Whether token `at` lies before the current limit, inside the region being parsed.
    pub(crate) fn within_limit(&self, at: usize) -> bool {
        at < self.limit
    }

    /// Runs `f` with the input ending at `end` (never later than the current limit).
    pub(crate) fn with_limit<R>(&mut self, end: usize, f: impl FnOnce(&mut Self) -> R) -> R {
        let outer = self.limit;
        self.limit = end.min(outer);
        let result = f(self);
        self.limit = outer;
        result
    }

    /// Consumes every token up to the current limit without structure.
    pub(crate) fn bump_rest(&mut self) {
        self.bump_until(self.limit);
    }

    /// Consumes tokens up to `end` (or the limit) without structure.
    pub(crate) fn bump_until(&mut self, end: usize) {
        while self.pos < end.min(self.limit) && !self.ran_away() {
            self.bump_any();
        }
    }

    pub(crate) fn start(&mut self) -> Marker {
        let pos = self.events.len() as u32;
        self.events.push(Event::Tombstone);
        Marker { pos }
    }

    /// A checkpoint for trying a parse and taking it back.
    pub(crate) fn snapshot(&self) -> Snapshot {
        Snapshot {
            pos: self.pos,
            events: self.events.len(),
            errors: self.errors.len(),
        }
    }

    pub(crate) fn restore(&mut self, snapshot: Snapshot) {
        self.pos = snapshot.pos;
        self.events.truncate(snapshot.events);
        self.errors.truncate(snapshot.errors);
    }

    /// Whether the parse stopped early because it was not making progress.
    pub(crate) fn ran_away(&self) -> bool {
        self.steps > self.max_steps
    }

    /// Reports and consumes whatever a runaway parse left behind.
    pub(crate) fn finish_runaway(&mut self) {
        if self.pos < self.kinds.len() {
            self.limit = self.kinds.len();
            self.steps = 0;
            self.max_steps = u64::MAX;
            let m = self.start();
            let range = self.ranges[self.pos];
            self.bump_rest();
            self.error_at(range, "the parser gave up here");
            m.complete(self, ERROR_NODE);
        }
    }
}

#[derive(Debug, Clone, Copy)]
pub(crate) struct Snapshot {
    pos: usize,
    events: usize,
    errors: usize,
}

impl Snapshot {
    /// How many errors had been reported when the snapshot was taken.
    pub(crate) fn error_count(&self) -> usize {
        self.errors
    }
}

/// A node that has started but not yet ended.
#[must_use]
pub(crate) struct Marker {
    pos: u32,
}

impl Marker {
    pub(crate) fn complete(self, p: &mut Parser<'_>, kind: SyntaxKind) -> CompletedMarker {
        p.events[self.pos as usize] = Event::Start {
            kind,
            forward_parent: None,
        };
        p.events.push(Event::Finish);
        CompletedMarker { pos: self.pos }
    }
}

#[derive(Debug, Clone, Copy)]
pub(crate) struct CompletedMarker {
    pos: u32,
}

impl CompletedMarker {
    /// Starts a node that will enclose this completed one: `1` becomes the left operand
    /// of `1 + 2` once the `+` is seen.
    pub(crate) fn precede(self, p: &mut Parser<'_>) -> Marker {
        let m = p.start();
        if let Event::Start { forward_parent, .. } = &mut p.events[self.pos as usize] {
            *forward_parent = Some(m.pos - self.pos);
        }
        m
    }
}

/// A token kind as error messages name it.
pub(crate) fn describe_kind(kind: SyntaxKind) -> String {
    if let Some(text) = kind.keyword_text() {
        return format!("'{text}'");
    }
    let text = match kind {
        NUMBER => "a number",
        STRING => "a string",
        IDENT => "an identifier",
        L_BRACE => "'{'",
        R_BRACE => "'}'",
        L_PAREN => "'('",
        R_PAREN => "')'",
        L_BRACK => "'['",
        R_BRACK => "']'",
        LT => "'<'",
        GT => "'>'",
        LT_EQ => "'<='",
        GT_EQ => "'>='",
        EQ => "'='",
        NEQ => "'!='",
        PLUS => "'+'",
        MINUS => "'-'",
        STAR => "'*'",
        SLASH => "'/'",
        COMMA => "','",
        SEMICOLON => "';'",
        COLON => "':'",
        QUESTION => "'?'",
        DOT => "'.'",
        AMP => "'&'",
        PIPE => "'|'",
        BANG => "'!'",
        HASH => "'#'",
        EOF => "end of file",
        _ => "a token",
    };
    text.to_string()
}
