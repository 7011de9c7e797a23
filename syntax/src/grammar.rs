//! The SDL grammar: one function per rule, named after it. Rules whose name starts with
//! `opt_` may consume nothing; the others are called only where their first token is.
//!
//! SDL is a macro language and its evaluator works on tokens, so this grammar is lenient
//! wherever SDL is: any item may stand in any block (the evaluator says what does not
//! belong), an identifier may stand for any value, and a directive may stand between any
//! two tokens. What it does report are the mistakes no expansion can repair: unbalanced
//! brackets and directives, missing operands, tokens that start nothing.
//!
//! `// test name` comments hold example inputs; `tests.rs` turns them into files under
//! `test_data/parser/inline` and checks their trees.

mod directives;
mod expressions;
mod items;
mod vocabulary;

use crate::SyntaxKind::{self, *};
use crate::parsing::{Mark, Parser, describe_kind};

/// A whole file: items up to the end.
pub(crate) fn source_file(p: &mut Parser<'_>) {
    let m = p.start();
    items::item_list(p);
    m.complete(p, SOURCE_FILE);
}

/// Runs `f` with the expression operators of a context: `full` for the relational,
/// logical and conditional operators, which POV-Ray only accepts inside parentheses and
/// `function { }` bodies (elsewhere `<` starts a vector); `no_gt` inside `< >`, where
/// `>` closes the vector.
fn with_operators<R>(
    p: &mut Parser<'_>,
    full: bool,
    no_gt: bool,
    f: impl FnOnce(&mut Parser<'_>) -> R,
) -> R {
    let saved = (p.full_operators, p.no_gt);
    p.full_operators = full;
    p.no_gt = no_gt;
    let result = f(p);
    (p.full_operators, p.no_gt) = saved;
    result
}

/// A bracketed region, `{ }`, `( )` or `[ ]`, parsed up to the closer the pre-pass
/// matched with its opener, so that a missing closer is reported once, at the opener.
/// Tokens `body` leaves before the closer become one error. In a `( )` or `[ ]` that is
/// never closed, `body` stops at the first token that does not fit (see
/// [`Parser::lenient_end`]) and the rest is left to the enclosing rule.
fn delimited(p: &mut Parser<'_>, close: SyntaxKind, body: impl FnOnce(&mut Parser<'_>)) {
    let open = p.pos();
    let open_kind = p.current();
    let (end, closed) = match p.mark(open) {
        // A closer past the current limit (a macro header cut short by `#end`) cannot
        // be reached from here: the bracket is unclosed as far as this rule can see.
        Mark::Open { end, closed } => (Some(end as usize), closed && p.within_limit(end as usize)),
        // Not seen by the pre-pass, which sees everything parsed structurally; kept
        // for robustness.
        _ => (None, false),
    };
    p.bump_any();
    let saved = p.lenient_end;
    p.lenient_end = !closed && open_kind != L_BRACE;
    p.with_limit(end.unwrap_or(usize::MAX), |p| {
        body(p);
        if closed && !p.at_end() {
            let found = p.describe_current();
            p.err_and_bump_run(
                &format!("unexpected {found} before {}", describe_kind(close)),
                crate::parsing::TokenSet::EMPTY,
            );
        }
    });
    p.lenient_end = saved;
    if closed {
        p.bump(close);
    } else if end.is_some() {
        let range = p.range_of(open);
        p.error_at(range, format!("unclosed {}", describe_kind(open_kind)));
    } else {
        p.expect(close, &describe_kind(close));
    }
}

/// Whether the bracket at the current token is never closed.
fn at_unclosed(p: &Parser<'_>) -> bool {
    matches!(p.mark(p.pos()), Mark::Open { closed: false, .. })
}
