//! The token getter. Like POV-Ray's, it runs directives and expands macro calls as it
//! meets them, so the statement parsers above it only ever see plain tokens, wherever in a
//! statement the directives stand.

use super::tokens::{Cond, FileId, Frame, FrameKind, RawToken, Token, opens_block};
use super::value::Value;
use super::{Evaluator, Result};
use syntax::SyntaxKind::{self, *};
use syntax::{Span, TextRange, TextSize};

/// What a skip over a false branch stopped at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SkipStop {
    End,
    Else,
    ElseIf,
    Case,
    Range,
    Break,
}

/// Where a skip over a branch not taken ended: the position after it, the steps it took,
/// and the directive it stopped at.
#[derive(Debug, Clone, Copy)]
pub struct Skip {
    end: u32,
    steps: u32,
    stop: SkipStop,
}

/// Skips that ended, by file, starting position and whether they stopped at branches.
pub type Skips = rustc_hash::FxHashMap<(FileId, u32, bool), Skip>;

impl Evaluator<'_> {
    /// The next token after directives and macro expansion. At the end of the main file it
    /// returns an `EOF`-like token of kind `ERROR_NODE` placed at the end of the text.
    pub fn next(&mut self) -> Result<Token> {
        loop {
            if let Some(token) = self.pushed.pop() {
                // A `#declare` held back while a declaration's value was read runs now.
                if token.kind == HASH && !self.declaration_pending() {
                    // A held-back `#declare` keeps its keyword; a stray '#' given back does not.
                    let keyword = match self.pushed.pop() {
                        Some(keyword) => keyword,
                        None => self.next_raw()?,
                    };
                    self.run_directive(token, keyword)?;
                    continue;
                }
                // So does a macro call held back by `next_unexpanded`.
                if !self.macro_calls_held
                    && let Some(def) = macro_of(&token)
                {
                    self.invoke_macro(def, &token)?;
                    continue;
                }
                return Ok(token);
            }
            let raw = self.next_raw()?;
            match raw.kind {
                HASH => {
                    let keyword = self.next_raw()?;
                    if matches!(keyword.kind, DECLARE_KW | LOCAL_KW) && self.declaration_pending() {
                        // As in POV-Ray, a declaration met while reading another one's value
                        // (`#declare A = "a"` with no ';' before the next `#declare`) waits
                        // until that value is assigned.
                        self.pushed.push(keyword);
                        return Ok(raw);
                    }
                    self.run_directive(raw, keyword)?;
                }
                IDENT => {
                    // The identifier just read is the token before the frame's position.
                    let frame = self.frames.last().expect("the main frame is never popped");
                    let symbol = self.symbol_at(frame.file, frame.pos - 1);
                    let slot = self.lookup_symbol(symbol);
                    let token = Token { slot, ..raw };
                    if let Some(def) = macro_of(&token) {
                        if self.macro_calls_held {
                            return Ok(token);
                        }
                        self.invoke_macro(def, &token)?;
                        continue;
                    }
                    return self.resolve_element(token);
                }
                _ => return Ok(raw),
            }
        }
    }

    /// The next token as `next` reads it, except that a macro call is handed back
    /// unexpanded (its token's slot holds the macro) and runs when `next` reads the token
    /// again: for looking past the end of a value that is not assigned yet, which a macro
    /// there may use.
    pub fn next_unexpanded(&mut self) -> Result<Token> {
        self.macro_calls_held = true;
        let token = self.next();
        self.macro_calls_held = false;
        token
    }

    /// Runs a directive met by `next`; macro calls inside it (`#if (M())`) are not part of
    /// any lookahead and expand.
    fn run_directive(&mut self, hash: Token, keyword: Token) -> Result<()> {
        let held = std::mem::replace(&mut self.macro_calls_held, false);
        let result = self.directive(hash, keyword);
        self.macro_calls_held = held;
        result
    }

    /// Whether a declaration's value is being read and the reader has got past its end:
    /// back in the frame where the value started, or in one that frame returned to. Macros
    /// called inside the value run deeper and may declare what they like.
    fn declaration_pending(&self) -> bool {
        self.declaring
            .last()
            .is_some_and(|&depth| self.frames.len() <= depth)
    }

    /// An identifier naming an array or dictionary followed by `[` (or a dictionary by
    /// `.key`) stands for the element: every statement that takes an identifier also takes
    /// `Array[i]`, as in POV-Ray. The token keeps the identifier's place.
    fn resolve_element(&mut self, token: Token) -> Result<Token> {
        let value = match &token.slot {
            Some(slot) if matches!(&*slot.borrow(), Value::Array(_) | Value::Dictionary(_)) => {
                slot.borrow().clone()
            }
            _ => return Ok(token),
        };
        let open = self.next()?;
        let element = match open.kind {
            L_BRACK => self.subscript(&open, value)?,
            DOT if matches!(value, Value::Dictionary(_)) => {
                let item = self.next_raw()?;
                self.dot_item(&item, value)?
            }
            _ => {
                self.unget(open);
                return Ok(token);
            }
        };
        Ok(Token {
            slot: Some(std::rc::Rc::new(std::cell::RefCell::new(element))),
            ..token
        })
    }

    /// Gives a token back; the next `next()` returns it again.
    pub fn unget(&mut self, token: Token) {
        self.pushed.push(token);
    }

    /// The kind of the token `next` would return, when that is a given-back token that
    /// `next` returns as it is (not a held-back directive or macro call): a look at the
    /// token after an operand that takes nothing out and puts nothing back.
    pub fn given_back_kind(&self) -> Option<SyntaxKind> {
        let token = self.pushed.last()?;
        (!matches!(token.kind, HASH | IDENT)).then_some(token.kind)
    }

    /// The kind of the next token, leaving it in place.
    pub fn peek_kind(&mut self) -> Result<SyntaxKind> {
        let token = self.next()?;
        let kind = token.kind;
        self.unget(token);
        Ok(kind)
    }

    /// Consumes the next token when it has `kind`.
    pub fn eat(&mut self, kind: SyntaxKind) -> Result<bool> {
        let token = self.next()?;
        if token.kind == kind {
            Ok(true)
        } else {
            self.unget(token);
            Ok(false)
        }
    }

    /// The next token, which must have `kind`.
    pub fn expect(&mut self, kind: SyntaxKind, what: &str) -> Result<Token> {
        let token = self.next()?;
        if token.kind == kind {
            Ok(token)
        } else {
            Err(self.error_at(
                &token,
                format!("expected {what}, found {}", self.describe(&token)),
            ))
        }
    }

    /// The next significant token of the current frame, without running directives or
    /// expanding macros; ending frames are popped on the way.
    pub fn next_raw(&mut self) -> Result<Token> {
        loop {
            self.spend_step()?;
            let frame = self
                .frames
                .last_mut()
                .expect("the main frame is never popped");
            if frame.pos < frame.end {
                let raw = self.files[frame.file as usize].tokens[frame.pos];
                frame.pos += 1;
                let file = frame.file;
                return Ok(Token {
                    kind: raw.kind,
                    file,
                    start: raw.start,
                    end: raw.end,
                    slot: None,
                });
            }
            if self.frames.len() == 1 {
                let frame = &self.frames[0];
                if let Some(cond) = frame.conds.last() {
                    return Err(self.unclosed(frame.file, cond));
                }
                let end = self.files[frame.file as usize].text.len() as u32;
                return Ok(Token {
                    kind: ERROR_NODE,
                    file: frame.file,
                    start: end,
                    end,
                    slot: None,
                });
            }
            self.pop_frame()?;
        }
    }

    /// Leaves the current include file or macro body.
    pub fn pop_frame(&mut self) -> Result<()> {
        let frame = self
            .frames
            .pop()
            .expect("pop_frame is never called on the main frame");
        if let Some(cond) = frame.conds.last() {
            return Err(self.unclosed(frame.file, cond));
        }
        match frame.kind {
            FrameKind::Main => unreachable!("the main frame is never popped"),
            FrameKind::Include => {
                self.pop_scope();
                self.include_stack.pop();
            }
            FrameKind::Macro { .. } => {
                self.pop_scope();
                self.macro_depth -= 1;
            }
        }
        Ok(())
    }

    fn unclosed(&self, file: FileId, cond: &Cond) -> Box<syntax::Diagnostic> {
        let (what, at) = match cond {
            Cond::If { opened_at } => ("#if", *opened_at),
            Cond::While { opened_at, .. } => ("#while", *opened_at),
            Cond::For { opened_at, .. } => ("#for", *opened_at),
            Cond::Switch { opened_at, .. } => ("#switch", *opened_at),
        };
        let range = TextRange::at(TextSize::new(at), TextSize::of("#"));
        self.error_in(file, range, format!("missing #end for this {what}"))
    }

    /// Skips the tokens of a branch not taken, up to the `#end` (consumed) or, when
    /// `stop_at_branches`, to an `#else`, `#elseif`, `#case`, `#range` or `#break` at the
    /// same nesting depth (consumed, with the `#`).
    ///
    /// Where a skip from a place ends depends on the tokens only, and loops and macros skip
    /// the same branches over and over: a skip that ended is remembered, and the next one
    /// from the same place jumps, counting the same steps.
    pub fn skip_block(&mut self, stop_at_branches: bool, opened: &Token) -> Result<SkipStop> {
        let frame = self.frames.last().expect("the main frame is never popped");
        let key = (frame.file, frame.pos as u32, stop_at_branches);
        if let Some(skip) = self.skips.get(&key) {
            // A jump past the frame's end, or to where the step budget runs out, is
            // scanned instead, to stop at the same token with the same error.
            let steps = self.steps + u64::from(skip.steps);
            if skip.end as usize <= frame.end && steps <= self.options.budgets.steps {
                let (end, stop) = (skip.end as usize, skip.stop);
                self.steps = steps;
                self.frames.last_mut().expect("checked above").pos = end;
                return Ok(stop);
            }
        }
        let steps_before = self.steps;
        let stop = self.scan_block(stop_at_branches, opened)?;
        let skip = Skip {
            end: self.position() as u32,
            steps: (self.steps - steps_before) as u32,
            stop,
        };
        self.skips.insert(key, skip);
        Ok(stop)
    }

    /// [`Self::skip_block`] token by token.
    fn scan_block(&mut self, stop_at_branches: bool, opened: &Token) -> Result<SkipStop> {
        let mut depth = 0usize;
        let frame_index = self.frames.len() - 1;
        loop {
            self.spend_step()?;
            let frame = &mut self.frames[frame_index];
            if frame.pos >= frame.end {
                let range = opened.range();
                return Err(self.error_in(opened.file, range, "missing #end for this directive"));
            }
            let tokens = &self.files[frame.file as usize].tokens;
            let raw = tokens[frame.pos];
            frame.pos += 1;
            if raw.kind != HASH || frame.pos >= frame.end {
                continue;
            }
            let directive = tokens[frame.pos].kind;
            if opens_block(directive) {
                depth += 1;
                frame.pos += 1;
                continue;
            }
            let stop = match directive {
                END_KW => Some(SkipStop::End),
                ELSE_KW => Some(SkipStop::Else),
                ELSEIF_KW => Some(SkipStop::ElseIf),
                CASE_KW => Some(SkipStop::Case),
                RANGE_KW => Some(SkipStop::Range),
                BREAK_KW => Some(SkipStop::Break),
                _ => None,
            };
            match stop {
                Some(SkipStop::End) if depth > 0 => {
                    depth -= 1;
                    frame.pos += 1;
                }
                Some(SkipStop::End) => {
                    frame.pos += 1;
                    return Ok(SkipStop::End);
                }
                Some(stop) if depth == 0 && stop_at_branches => {
                    frame.pos += 1;
                    return Ok(stop);
                }
                _ => {}
            }
        }
    }

    /// The raw token after the next one in the current frame, without consuming anything;
    /// used to tell a by-reference macro argument (`Name,` or `Name)`) from an expression.
    pub fn raw_lookahead(&self, ahead: usize) -> Option<RawToken> {
        if !self.pushed.is_empty() {
            return None;
        }
        let frame = self.frames.last()?;
        let pos = frame.pos + ahead;
        (pos < frame.end).then(|| self.files[frame.file as usize].tokens[pos])
    }

    /// The text of a token.
    pub fn text(&self, token: &Token) -> &str {
        &self.files[token.file as usize].text[token.start as usize..token.end as usize]
    }

    /// A token as messages show it: `'foo'`, or "end of file".
    pub fn describe(&self, token: &Token) -> String {
        if token.kind == ERROR_NODE {
            "end of file".to_owned()
        } else {
            format!("'{}'", self.text(token))
        }
    }

    pub fn span(&self, token: &Token) -> Span {
        Span {
            file: self.files[token.file as usize].name.clone(),
            range: token.range(),
        }
    }

    /// Pushes a frame that reads `file` from token `start` to `end`.
    pub fn push_frame(&mut self, frame: Frame) {
        self.frames.push(frame);
    }

    /// The current frame's open conditionals.
    pub fn conds(&mut self) -> &mut Vec<Cond> {
        &mut self
            .frames
            .last_mut()
            .expect("the main frame is never popped")
            .conds
    }

    /// Moves the current frame's read position (for loops jumping back).
    pub fn seek(&mut self, pos: usize) {
        self.pushed.clear();
        self.frames
            .last_mut()
            .expect("the main frame is never popped")
            .pos = pos;
    }

    /// The current frame's read position.
    pub fn position(&self) -> usize {
        self.frames
            .last()
            .expect("the main frame is never popped")
            .pos
    }
}

/// The macro a token names, if its identifier holds one.
fn macro_of(token: &Token) -> Option<std::rc::Rc<super::macros::MacroDef>> {
    match &*token.slot.as_ref()?.borrow() {
        Value::Macro(def) => Some(def.clone()),
        _ => None,
    }
}
