//! Expressions, by precedence climbing. Outside parentheses SDL has only `+ - * /` and
//! the prefix operators; inside parentheses and in `function { }` bodies it also has
//! comparisons, `&`, `|` and `? :`. Vectors are `< >` lists, in which `>` closes.

use super::items::{opt_value, too_deep};
use super::vocabulary::{COLOR_COMPONENTS, COLOR_STARTS, COLOR_VECTORS, CONSTANTS, FUNCTIONS};
use super::{at_unclosed, delimited, directives, with_operators};
use crate::SyntaxKind::{self, *};
use crate::parsing::{CompletedMarker, DEPTH_LIMIT, Marker, Parser, TokenSet};

const PREFIX_POWER: u8 = 13;

const BINARY_FORMATS: TokenSet = TokenSet::new(&[
    UINT8_KW,
    SINT8_KW,
    UINT16BE_KW,
    UINT16LE_KW,
    SINT16BE_KW,
    SINT16LE_KW,
    SINT32BE_KW,
    SINT32LE_KW,
]);
/// Operand of a colour keyword: everything up to the end of the expression.
const COLOR_OPERAND_POWER: u8 = 3;

/// Whether an expression starts here (for optional arguments: a keyword followed by
/// `(` only counts when it is a built-in function).
pub(super) fn at_expr_start(p: &mut Parser<'_>) -> bool {
    match p.current() {
        NUMBER | STRING | IDENT | LT | L_PAREN | MINUS | PLUS | BANG => true,
        kind => {
            COLOR_STARTS.contains(kind)
                || CONSTANTS.contains(kind)
                || (FUNCTIONS.contains(kind) && p.nth(1) == L_PAREN)
        }
    }
}

/// An expression that the caller knows starts here.
pub(super) fn expr(p: &mut Parser<'_>) {
    if opt_expr(p).is_none() {
        p.error_expected("an expression");
    }
}

/// An expression that must be here; `what` names it in the error.
pub(super) fn expr_or_error(p: &mut Parser<'_>, what: &str) {
    while p.at(HASH) {
        directives::directive(p);
    }
    if opt_expr(p).is_none() {
        p.error_expected(what);
    }
}

pub(super) fn opt_expr(p: &mut Parser<'_>) -> Option<CompletedMarker> {
    expr_bp(p, 0)
}

/// An operand after an operator: required, unless a directive stands in for it.
fn operand(p: &mut Parser<'_>, power: u8) {
    while p.at(HASH) {
        directives::directive(p);
    }
    if expr_bp(p, power).is_none() {
        p.error_expected("an expression");
    }
}

fn infix_power(p: &Parser<'_>, kind: SyntaxKind) -> Option<(u8, u8)> {
    let full = p.full_operators;
    Some(match kind {
        STAR | SLASH => (11, 12),
        PLUS | MINUS => (9, 10),
        LT | LT_EQ | EQ | NEQ if full => (7, 8),
        GT | GT_EQ if full && !p.no_gt => (7, 8),
        AMP if full => (5, 6),
        PIPE if full => (3, 4),
        QUESTION if full => (2, 1),
        _ => return None,
    })
}

// test expressions
// #declare A = -1 + 2*3 - 4/5;
// #declare B = (A < 1 & A >= 0 | !A ? 1 : 2);
// #declare C = <1, 2, 3>.x + V.y + D["key"] + Arr[1][2] + D.field;
// #declare E = vlength(<1, 2, 3>) + max(1, 2, 3) + Macro(1, , "s");
// #declare F = <(A > 1), 2>;
/// Operators binding at least as tightly as `min_power`, and their operands.
fn expr_bp(p: &mut Parser<'_>, min_power: u8) -> Option<CompletedMarker> {
    if p.depth >= DEPTH_LIMIT {
        return Some(too_deep(p));
    }
    p.depth += 1;
    let result = expr_bp_inner(p, min_power);
    p.depth -= 1;
    result
}

fn expr_bp_inner(p: &mut Parser<'_>, min_power: u8) -> Option<CompletedMarker> {
    let mut lhs = lhs(p)?;
    // A chain like `1+1+...+1` nests one node per operator. Past the depth limit the
    // remaining operands join one node instead, so that the tree (and every recursive
    // walk or drop of it) stays shallow; at one level the operators' precedence never
    // rises, so reading that node left to right keeps the meaning.
    let mut chain = 0u32;
    let mut flat: Option<Marker> = None;
    loop {
        let op = p.current();
        let Some((left, right)) = infix_power(p, op) else {
            break;
        };
        if left < min_power {
            break;
        }
        if op == QUESTION {
            if let Some(m) = flat.take() {
                lhs = m.complete(p, BIN_EXPR);
            }
            let m = lhs.precede(p);
            p.bump_any();
            operand(p, 0);
            if p.expect(COLON, "':'") {
                operand(p, right);
            }
            lhs = m.complete(p, TERNARY_EXPR);
            continue;
        }
        if flat.is_some() {
            p.bump_any();
            operand(p, right);
            continue;
        }
        let m = lhs.precede(p);
        p.bump_any();
        operand(p, right);
        chain += 1;
        if chain >= DEPTH_LIMIT {
            flat = Some(m);
        } else {
            lhs = m.complete(p, BIN_EXPR);
        }
    }
    if let Some(m) = flat {
        lhs = m.complete(p, BIN_EXPR);
    }
    Some(lhs)
}

fn lhs(p: &mut Parser<'_>) -> Option<CompletedMarker> {
    match p.current() {
        MINUS | PLUS | BANG => {
            let m = p.start();
            p.bump_any();
            operand(p, PREFIX_POWER);
            Some(m.complete(p, PREFIX_EXPR))
        }
        _ => {
            let (atom, kind) = atom(p)?;
            Some(postfix(p, atom, kind))
        }
    }
}

fn atom(p: &mut Parser<'_>) -> Option<(CompletedMarker, SyntaxKind)> {
    let kind = p.current();
    let done = match kind {
        NUMBER | STRING => {
            let m = p.start();
            p.bump_any();
            (m.complete(p, LITERAL), LITERAL)
        }
        IDENT if p.nth(1) == L_PAREN => (call(p), CALL),
        IDENT => {
            let m = p.start();
            p.bump_any();
            (m.complete(p, NAME_REF), NAME_REF)
        }
        LT => (vector(p), VECTOR),
        L_PAREN => (paren(p), PAREN_EXPR),
        _ if COLOR_STARTS.contains(kind) => (color(p), COLOR),
        _ if CONSTANTS.contains(kind) => {
            let m = p.start();
            p.bump_any();
            (m.complete(p, LITERAL), LITERAL)
        }
        _ if kind.is_keyword() && p.nth(1) == L_PAREN => (call(p), CALL),
        _ => return None,
    };
    Some(done)
}

/// `.x`, `.red`, `.key` and `[index]` after an operand.
fn postfix(p: &mut Parser<'_>, mut lhs: CompletedMarker, mut kind: SyntaxKind) -> CompletedMarker {
    for chain in 0.. {
        if chain >= DEPTH_LIMIT && matches!(p.current(), DOT | L_BRACK) {
            p.error_too_deep();
            return lhs;
        }
        match p.current() {
            DOT if p.nth(1) == IDENT || p.nth(1).is_keyword() => {
                let m = lhs.precede(p);
                p.bump(DOT);
                p.bump_any();
                lhs = m.complete(p, DOT_EXPR);
                kind = DOT_EXPR;
            }
            // Only names index: after a number or a vector, `[` starts a map entry.
            L_BRACK if matches!(kind, NAME_REF | INDEX_EXPR | DOT_EXPR | CALL) => {
                let m = lhs.precede(p);
                with_operators(p, true, false, |p| {
                    delimited(p, R_BRACK, |p| {
                        if opt_expr(p).is_none() {
                            p.error_expected("an index");
                        }
                    })
                });
                lhs = m.complete(p, INDEX_EXPR);
                kind = INDEX_EXPR;
            }
            _ => return lhs,
        }
    }
    lhs
}

/// `Name(arguments)` or `builtin(arguments)`.
fn call(p: &mut Parser<'_>) -> CompletedMarker {
    let m = p.start();
    if p.at(IDENT) {
        let name = p.start();
        p.bump_any();
        name.complete(p, NAME_REF);
    } else {
        p.bump_any();
    }
    arg_list(p);
    m.complete(p, CALL)
}

// test calls
// Row(1, sphere { 0, 1 }, pigment { Red })
// Field(HF, off, off <100, 100>, on)
// #declare V = vrotate(x, <0, 90, 0>);
// #declare P = S(0.5, natural_spline);
/// `(value, value, ...)`: arguments may be any value; an empty one is a macro's
/// optional parameter left out.
pub(super) fn arg_list(p: &mut Parser<'_>) {
    let m = p.start();
    // Arguments are plain expressions, as outside parentheses: `max(1 < 2)` is an
    // error in POV-Ray, and a missing comma before a vector (`off <1, 1>`) is not.
    let full = p.full_operators;
    let no_gt = at_unclosed(p) && p.no_gt;
    with_operators(p, full, no_gt, |p| {
        delimited(p, R_PAREN, |p| {
            while !p.at_end() {
                match p.current() {
                    COMMA => p.bump_any(),
                    HASH => directives::directive(p),
                    // A spline called as another type: `S(t, natural_spline)`.
                    LINEAR_SPLINE_KW | QUADRATIC_SPLINE_KW | CUBIC_SPLINE_KW
                    | NATURAL_SPLINE_KW => {
                        let m = p.start();
                        p.bump_any();
                        m.complete(p, PROPERTY);
                    }
                    // The binary formats of `#write`: `uint8 Value`.
                    kind if BINARY_FORMATS.contains(kind) => {
                        let m = p.start();
                        p.bump_any();
                        expr_or_error(p, "a value to write");
                        m.complete(p, PROPERTY);
                    }
                    _ => {
                        if !opt_value(p) {
                            if p.lenient_end {
                                break;
                            }
                            let found = p.describe_current();
                            p.err_and_bump_run(
                                &format!("expected an argument, found {found}"),
                                TokenSet::new(&[COMMA, HASH]),
                            );
                        }
                    }
                }
            }
        })
    });
    m.complete(p, ARG_LIST);
}

// test vectors
// #declare V = <1, -2, 3*4> + <A, B> * <1, 2, 3, 4, 5>;
// #declare W = <1 0 -1>;
// sphere_sweep { b_spline 2, #while (I < 2) <I, 0, 0>, 1 #local I = I + 1; #end }
// test_err vector_missing_close
// sphere { <0, 0, 0, 1 pigment { Red } }
// sphere { <0, 1,
//   1 }
// #declare V = <1, , 2>;
/// `<a, b, c>`, in which directives may stand between the components.
fn vector(p: &mut Parser<'_>) -> CompletedMarker {
    let m = p.start();
    p.bump(LT);
    let full = p.full_operators;
    with_operators(p, full, true, |p| {
        loop {
            while p.at(HASH) {
                directives::directive(p);
            }
            if p.at(GT) || p.at_end() {
                break;
            }
            if opt_expr(p).is_none() {
                // `<1,,2>`; otherwise the vector ends here and the missing `>` is the
                // error.
                if p.at(COMMA) {
                    p.error_expected("a vector component");
                    p.bump(COMMA);
                    continue;
                }
                break;
            }
            // Commas between components are optional: `<1 0 0>` is a vector.
            if !p.eat(COMMA) && !at_expr_start(p) && !p.at(HASH) {
                break;
            }
        }
    });
    p.expect(GT, "'>'");
    m.complete(p, VECTOR)
}

/// `(expression)`, or a comma list as in `#range (1, 5)`.
fn paren(p: &mut Parser<'_>) -> CompletedMarker {
    let m = p.start();
    // In a parenthesis that is never closed, `>` still closes an enclosing vector:
    // the `)` was probably meant to stand before it.
    let no_gt = at_unclosed(p) && p.no_gt;
    with_operators(p, true, no_gt, |p| {
        delimited(p, R_PAREN, |p| {
            loop {
                while p.at(HASH) {
                    directives::directive(p);
                }
                if opt_expr(p).is_none() {
                    if !p.lenient_end {
                        p.error_expected("an expression");
                    }
                    break;
                }
                if !p.eat(COMMA) {
                    break;
                }
            }
        })
    });
    m.complete(p, PAREN_EXPR)
}

// test colors
// pigment { color rgb <1, 0, 0> filter 0.5 }
// pigment { color Red transmit 0.2 }
// pigment { color red 1 green 0.5 blue 0 }
// pigment { rgbft <1, 1, 1, 0.5, 0> * 0.5 }
/// `color Red`, `rgb <1, 0, 0>`, `color red 1 green 0.5`, with trailing components.
fn color(p: &mut Parser<'_>) -> CompletedMarker {
    let m = p.start();
    let first = p.current();
    p.bump_any();
    if matches!(first, COLOR_KW | COLOUR_KW) {
        if p.at_ts(COLOR_VECTORS) {
            p.bump_any();
            operand(p, COLOR_OPERAND_POWER);
        } else if !p.at_ts(COLOR_COMPONENTS) {
            operand(p, COLOR_OPERAND_POWER);
        }
    } else {
        // `rgb <...>`, or the first component of `red 1 green 0.5`.
        operand(p, COLOR_OPERAND_POWER);
    }
    while p.at_ts(COLOR_COMPONENTS) && at_component_value(p) {
        p.bump_any();
        operand(p, COLOR_OPERAND_POWER);
    }
    m.complete(p, COLOR)
}

/// Whether the token after a colour component is its value (`filter 0.5`), as opposed
/// to another use of the word (`filter all 0.5` in an image map).
fn at_component_value(p: &mut Parser<'_>) -> bool {
    match p.nth(1) {
        NUMBER | IDENT | LT | L_PAREN | MINUS | PLUS => true,
        kind => CONSTANTS.contains(kind) || FUNCTIONS.contains(kind),
    }
}
