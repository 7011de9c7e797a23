//! `#macro` definitions and calls. A call evaluates its arguments in the caller's scope,
//! binds them in a new scope (an identifier argument by reference, anything else by
//! value), and continues reading from the macro body.

use super::symbols::Symbol;
use super::tokens::{FileId, Frame, FrameKind, Token};
use super::value::Value;
use super::{Evaluator, Result};
use std::rc::Rc;
use syntax::Span;
use syntax::SyntaxKind::*;

/// A macro parameter; `optional` ones (POV-Ray 3.8) may be left out by the caller.
#[derive(Debug, Clone, PartialEq)]
pub struct Param {
    pub name: String,
    /// The name interned, which each call binds.
    pub symbol: Symbol,
    pub optional: bool,
}

/// A macro: its parameters and where its body's tokens lie.
#[derive(Debug, Clone, PartialEq)]
pub struct MacroDef {
    pub name: String,
    pub params: Vec<Param>,
    pub file: FileId,
    pub body_start: usize,
    pub body_end: usize,
    pub defined_at: Span,
}

/// How one argument is passed.
enum Argument {
    ByValue(Value),
    ByReference(super::value::Slot),
    Omitted,
}

impl Evaluator<'_> {
    /// `#macro Name(A, B, optional C) ... #end`, after the `macro` keyword.
    pub fn define_macro(&mut self, hash: &Token) -> Result<()> {
        let name = self.next_raw()?;
        if name.kind != IDENT {
            return Err(self.error_at(
                &name,
                format!("expected a macro name, found {}", self.describe(&name)),
            ));
        }
        let open = self.next_raw()?;
        if open.kind != L_PAREN {
            return Err(self.error_at(
                &open,
                format!(
                    "expected '(' after the macro name, found {}",
                    self.describe(&open)
                ),
            ));
        }
        let mut params: Vec<Param> = Vec::new();
        loop {
            let mut token = self.next_raw()?;
            if token.kind == R_PAREN && params.is_empty() {
                break;
            }
            let optional = token.kind == OPTIONAL_KW;
            if optional {
                token = self.next_raw()?;
            }
            if token.kind != IDENT {
                return Err(self.error_at(
                    &token,
                    format!("expected a parameter name, found {}", self.describe(&token)),
                ));
            }
            let param = self.text(&token).to_owned();
            if params.iter().any(|p| p.name == param) {
                return Err(self.error_at(&token, format!("parameter '{param}' appears twice")));
            }
            let symbol = self.interner.intern(&param);
            params.push(Param {
                name: param,
                symbol,
                optional,
            });
            let separator = self.next_raw()?;
            match separator.kind {
                COMMA => continue,
                R_PAREN => break,
                _ => {
                    return Err(self.error_at(
                        &separator,
                        format!(
                            "expected ',' or ')' in the parameter list, found {}",
                            self.describe(&separator)
                        ),
                    ));
                }
            }
        }
        let body_start = self.position();
        self.skip_block(false, hash)?;
        let body_end = self.position() - 2;
        let file = self
            .frames
            .last()
            .expect("the main frame is never popped")
            .file;
        let def = MacroDef {
            name: self.text(&name).to_owned(),
            params,
            file,
            body_start,
            body_end,
            defined_at: self.span(&name),
        };
        let text = def.name.clone();
        self.declare(&text, Value::Macro(Rc::new(def)));
        Ok(())
    }

    /// Expands a macro call whose name was just read.
    pub fn invoke_macro(&mut self, def: Rc<MacroDef>, call: &Token) -> Result<()> {
        if self.macro_depth >= self.options.budgets.macro_depth {
            return Err(self.budget_error(
                format!(
                    "macro calls nested more than {} deep (runaway recursion?)",
                    self.options.budgets.macro_depth
                ),
                "max-macro-depth",
            ));
        }
        let open = self.next()?;
        if open.kind != L_PAREN {
            return Err(self.error_at(
                &open,
                format!(
                    "expected '(' after macro '{}', found {}",
                    def.name,
                    self.describe(&open)
                ),
            ));
        }
        let mut args = Vec::with_capacity(def.params.len());
        let mut closed = false;
        if self.raw_lookahead(0).is_some_and(|t| t.kind == R_PAREN) {
            self.next_raw()?;
            closed = true;
        }
        while !closed {
            args.push(self.macro_argument(&def, args.len())?);
            let separator = self.next()?;
            match separator.kind {
                COMMA => continue,
                R_PAREN => closed = true,
                // As in POV-Ray, the comma may be left out where an argument cannot go on,
                // such as after an object (`Align_Object(Center_Object(T, x) -y, 0)`).
                _ if args.len() < def.params.len() => self.unget(separator),
                _ => {
                    return Err(self.error_at(
                        &separator,
                        format!(
                            "expected ',' or ')' in the arguments of '{}', found {}",
                            def.name,
                            self.describe(&separator)
                        ),
                    ));
                }
            }
        }
        let required = def.params.iter().filter(|p| !p.optional).count();
        if args.len() > def.params.len() || args.len() < required {
            let expected = if required == def.params.len() {
                format!("{required}")
            } else {
                format!("{required} to {}", def.params.len())
            };
            let mut error = self.error_at(
                call,
                format!(
                    "macro '{}' takes {expected} arguments, but {} were given",
                    def.name,
                    args.len()
                ),
            );
            error.related.push(syntax::Related {
                span: def.defined_at.clone(),
                message: "the macro is defined here".into(),
            });
            return Err(error);
        }
        self.push_scope();
        for (param, arg) in def.params.iter().zip(args) {
            match arg {
                Argument::ByValue(value) => {
                    self.declare_local_symbol(param.symbol, value);
                }
                Argument::ByReference(slot) => self.bind(param.symbol, slot),
                Argument::Omitted => {}
            }
        }
        self.macro_depth += 1;
        self.push_frame(Frame {
            file: def.file,
            pos: def.body_start,
            end: def.body_end,
            entered_at: Some((call.file, call.range())),
            kind: FrameKind::Macro { def },
            conds: Vec::new(),
        });
        Ok(())
    }

    fn macro_argument(&mut self, def: &MacroDef, index: usize) -> Result<Argument> {
        if let (Some(ident), Some(after)) = (self.raw_lookahead(0), self.raw_lookahead(1))
            && ident.kind == IDENT
            && matches!(after.kind, COMMA | R_PAREN)
        {
            let frame = self.frames.last().expect("the main frame is never popped");
            let symbol = self.symbol_at(frame.file, frame.pos);
            if let Some(slot) = self.lookup_symbol(symbol)
                && !matches!(&*slot.borrow(), Value::Macro(_))
            {
                self.next_raw()?;
                return Ok(Argument::ByReference(slot));
            }
        }
        let optional = def.params.get(index).is_some_and(|p| p.optional);
        if optional && matches!(self.peek_kind()?, COMMA | R_PAREN) {
            return Ok(Argument::Omitted);
        }
        // The separator after the argument is read by the caller, and counts as a step then.
        if let Some(value) = self.replayed_rvalue(&[COMMA, R_PAREN], 0) {
            return Ok(Argument::ByValue(value));
        }
        Ok(Argument::ByValue(self.rvalue()?))
    }
}
