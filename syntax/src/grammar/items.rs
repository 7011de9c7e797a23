//! Items: what stands at the top level, in blocks, in map entries and in directive
//! bodies. Blocks (`sphere { }`), properties (`translate x`), expressions, separators and
//! directives may all stand in any of these places.

use super::vocabulary::{
    BOOL_CONSTANTS, COLOR_STARTS, CONSTANTS, FUNCTIONS, NO_ARGUMENT, OPTIONAL_BOOL, PATTERNS,
    block_kind,
};
use super::{delimited, directives, expressions, with_operators};
use crate::SyntaxKind::*;
use crate::parsing::{CompletedMarker, DEPTH_LIMIT, Parser, TokenSet};

/// Tokens that start an item: a run of unexpected tokens stops before them.
const ITEM_STARTS: TokenSet = TokenSet::new(&[
    HASH, IDENT, NUMBER, STRING, LT, L_PAREN, L_BRACK, L_BRACE, R_BRACE, R_PAREN, R_BRACK, COMMA,
    SEMICOLON, MINUS, PLUS, BANG,
]);

/// Items up to the current limit.
pub(super) fn item_list(p: &mut Parser<'_>) {
    if p.depth >= DEPTH_LIMIT {
        too_deep(p);
        return;
    }
    p.depth += 1;
    while !p.at_end() {
        item(p);
    }
    p.depth -= 1;
}

/// Reports nesting too deep to follow (once per file) and keeps the rest of the region
/// as tokens.
pub(super) fn too_deep(p: &mut Parser<'_>) -> CompletedMarker {
    let m = p.start();
    p.error_too_deep();
    p.bump_rest();
    m.complete(p, ERROR_NODE)
}

/// One item.
fn item(p: &mut Parser<'_>) {
    match p.current() {
        HASH => directives::directive(p),
        // test map_entries
        // color_map { [0 color Red] [0.5, 0.7 rgb 1 rgb 0] [1 Blue] }
        L_BRACK => map_entry(p),
        // test_err bare_brace_group
        // sphere { 0, 1 } { pigment { Red } }
        L_BRACE => {
            p.error_here("unexpected '{': a block starts with a keyword such as 'union {'");
            brace_group(p);
        }
        // test separators
        // #version 3.7; ; sphere { <0, 0, 0>, 1 };
        COMMA | SEMICOLON => p.bump_any(),
        // test_err stray_closers
        // sphere { 0, 1 } } )
        R_BRACE | R_PAREN | R_BRACK => {
            let found = p.describe_current();
            p.error_here(format!("unmatched {found}"));
            let m = p.start();
            p.bump_any();
            m.complete(p, ERROR_NODE);
        }
        kind if kind.is_keyword() => keyword_item(p),
        _ if expressions::at_expr_start(p) => {
            expressions::expr(p);
        }
        // test_err unexpected_tokens
        // sphere { 0 = * 1 }
        _ => {
            let found = p.describe_current();
            p.err_and_bump_run(&format!("unexpected {found}"), ITEM_STARTS.union(KEYWORDS));
        }
    }
}

/// Every reserved word, so that a run of unexpected tokens stops before one.
const KEYWORDS: TokenSet = {
    let mut set = TokenSet::EMPTY;
    let mut i = 0;
    while i < crate::KEYWORDS.len() {
        set = set.union(TokenSet::new(&[crate::KEYWORDS[i].1]));
        i += 1;
    }
    set
};

/// An item that starts with a reserved word.
fn keyword_item(p: &mut Parser<'_>) {
    let kw = p.current();
    match kw {
        // test legacy_directives
        // declare R = 1;
        // include "colors.inc"
        // version 3.1;
        // default { finish { ambient 0.2 } }
        DECLARE_KW => directives::declare(p),
        INCLUDE_KW => directives::include(p),
        VERSION_KW => directives::version(p),
        DEFAULT_KW => directives::default(p),
        FUNCTION_KW => function(p),
        PATTERN_KW => pattern(p),
        ARRAY_KW => array(p),
        DICTIONARY_KW => dictionary(p),
        _ if p.nth(1) == L_BRACE => block(p),
        _ if COLOR_STARTS.contains(kw)
            || CONSTANTS.contains(kw)
            || (FUNCTIONS.contains(kw) && p.nth(1) == L_PAREN) =>
        {
            expressions::expr(p);
        }
        _ => property(p),
    }
}

/// A value: what `#declare` assigns and macros take as arguments, a block or an
/// expression. Returns whether there was one.
pub(super) fn opt_value(p: &mut Parser<'_>) -> bool {
    let kw = p.current();
    match kw {
        FUNCTION_KW => function(p),
        ARRAY_KW => array(p),
        DICTIONARY_KW => dictionary(p),
        PATTERN_KW => pattern(p),
        _ if kw.is_keyword() && p.nth(1) == L_BRACE => block(p),
        _ if block_kind(kw) != BLOCK && !expressions::at_expr_start(p) => {
            headless_block(p);
        }
        _ => return expressions::opt_expr(p).is_some(),
    }
    true
}

// test_err block_without_brace
// #declare T = texture pigment { Red } };
/// A value that names a block but lacks its `{`: the keyword alone, with the error.
fn headless_block(p: &mut Parser<'_>) {
    let kw = p.current();
    let m = p.start();
    p.bump_any();
    let name = kw.keyword_text().unwrap_or_default();
    p.error_expected(&format!("'{{' after '{name}'"));
    m.complete(p, block_kind(kw));
}

// test blocks
// camera { location <0, 2, -3> look_at 0 }
// light_source { <2, 4, -3> color rgb 1 }
// sphere { <0, 1, 2>, 2 texture { pigment { color Yellow } } }
// global_settings { assumed_gamma 1.0 radiosity { count 100 } }
// background { color rgbt <0, 0, 0, 1> }
/// A keyword block: `sphere { <0, 1, 0>, 1 pigment { Red } }`.
fn block(p: &mut Parser<'_>) {
    let kind = block_kind(p.current());
    let m = p.start();
    p.bump_any();
    block_body(p);
    m.complete(p, kind);
}

/// `{ items }` of a block, whose expressions use the plain operator set.
pub(super) fn block_body(p: &mut Parser<'_>) {
    with_operators(p, false, false, |p| delimited(p, R_BRACE, item_list));
}

// test_err unclosed_brace
// union {
//   sphere { 0, 1
//   box { 0, 1 }
// }
// camera { }
// test_err unclosed_block_at_end
// sphere { 0, 1
// light_source { 0 color 1 }
/// `{ items }` without a keyword: only array initialisers have them.
fn brace_group(p: &mut Parser<'_>) {
    let m = p.start();
    delimited(p, R_BRACE, item_list);
    m.complete(p, BRACE_GROUP);
}

// test properties
// object { Thing translate <1, 2, 3> rotate 45*y hollow no_shadow sturm off }
// lathe { linear_spline 3, <0, 0>, <1, 1>, <0, 2> }
// pigment { checker color Red color Blue scale 0.5 }
/// A keyword and its optional argument: `translate x`, `hollow on`, `no_shadow`.
fn property(p: &mut Parser<'_>) {
    let kw = p.current();
    let m = p.start();
    p.bump_any();
    if NO_ARGUMENT.contains(kw) {
        // Nothing follows that belongs to the keyword.
    } else if OPTIONAL_BOOL.contains(kw) {
        if p.at_ts(BOOL_CONSTANTS) {
            expressions::expr(p);
        }
    } else if PATTERNS.contains(kw) {
        if expressions::at_expr_start(p) && !p.at_ts(COLOR_STARTS) {
            expressions::expr(p);
        }
    } else if expressions::at_expr_start(p) {
        expressions::expr(p);
    }
    m.complete(p, PROPERTY);
}

/// `[ items ]` in a colour, pigment, normal, texture, slope or density map.
fn map_entry(p: &mut Parser<'_>) {
    let m = p.start();
    with_operators(p, false, false, |p| delimited(p, R_BRACK, item_list));
    m.complete(p, MAP_ENTRY);
}

// test functions
// #declare F = function { x*x + y*y < 1 & z > 0 }
// #declare G = function(a, b, z) { select(a, b, z) + F(a, b, 0) }
// #declare P = function { pigment { checker } }
// height_field { function 100, 100 { x*y } }
/// `function { body }`, `function(x, y) { body }`, `function 100, 100 { body }`.
fn function(p: &mut Parser<'_>) {
    let m = p.start();
    p.bump(FUNCTION_KW);
    if p.at(L_PAREN) {
        param_list(p);
    } else {
        header_arguments(p);
    }
    function_body(p);
    m.complete(p, FUNCTION);
}

/// The `{ }` of a function: an expression with every operator.
fn function_body(p: &mut Parser<'_>) {
    if p.at(L_BRACE) {
        with_operators(p, true, false, |p| delimited(p, R_BRACE, item_list));
    } else {
        p.error_expected("'{'");
    }
}

// test pattern_blocks
// #declare F = function { pattern { checker } }
// pigment { image_map { pattern 100, 100 { gradient x } } }
/// `pattern { body }`, or with the resolution of an image pattern before the body.
fn pattern(p: &mut Parser<'_>) {
    let m = p.start();
    p.bump(PATTERN_KW);
    header_arguments(p);
    if p.at(L_BRACE) {
        block_body(p);
        m.complete(p, BLOCK);
    } else {
        m.complete(p, PROPERTY);
    }
}

/// The comma-separated expressions between a keyword and its `{`.
fn header_arguments(p: &mut Parser<'_>) {
    while expressions::at_expr_start(p) {
        expressions::expr(p);
        if !p.eat(COMMA) {
            break;
        }
    }
}

/// `(a, b, optional c)`: the parameters of a function or macro.
pub(super) fn param_list(p: &mut Parser<'_>) {
    let m = p.start();
    delimited(p, R_PAREN, |p| {
        while !p.at_end() {
            match p.current() {
                COMMA => p.bump_any(),
                IDENT | OPTIONAL_KW => param(p),
                // Functions name their parameters x, y, z, u and v, all reserved words.
                X_KW | Y_KW | Z_KW | U_KW | V_KW => param(p),
                _ if p.lenient_end => break,
                _ => {
                    let found = p.describe_current();
                    p.err_and_bump_run(
                        &format!("expected a parameter name, found {found}"),
                        TokenSet::new(&[COMMA, IDENT]),
                    );
                }
            }
        }
    });
    m.complete(p, PARAM_LIST);
}

fn param(p: &mut Parser<'_>) {
    let m = p.start();
    if p.at(OPTIONAL_KW) && p.nth(1) != COMMA && p.nth(1) != EOF {
        p.bump_any();
    }
    name(p);
    m.complete(p, PARAM);
}

/// A defining occurrence of a name.
pub(super) fn name(p: &mut Parser<'_>) {
    let m = p.start();
    p.bump_any();
    m.complete(p, NAME);
}

// test arrays
// #declare A = array[3] { 1, 2, 3 };
// #declare M = array[2][2] { { 1, 2 }, { 3, 4 } };
// #declare O = array mixed[2] { sphere { 0, 1 }, "two" };
// #declare E = array[4];
/// `array[3]`, `array mixed[2][2] { {...}, {...} }`.
fn array(p: &mut Parser<'_>) {
    let m = p.start();
    p.bump(ARRAY_KW);
    p.eat(MIXED_KW);
    if p.at(L_BRACK) {
        let dims = p.start();
        while p.at(L_BRACK) {
            with_operators(p, true, false, |p| {
                delimited(p, R_BRACK, |p| {
                    expressions::opt_expr(p);
                })
            });
        }
        dims.complete(p, ARRAY_DIMENSIONS);
    }
    if p.at(L_BRACE) {
        array_initializer(p);
    }
    m.complete(p, ARRAY);
}

/// `{ value, value }` or nested rows `{ {...}, {...} }`.
fn array_initializer(p: &mut Parser<'_>) {
    if p.depth >= DEPTH_LIMIT {
        too_deep(p);
        return;
    }
    p.depth += 1;
    let m = p.start();
    with_operators(p, false, false, |p| {
        delimited(p, R_BRACE, |p| {
            while !p.at_end() {
                match p.current() {
                    L_BRACE => array_initializer(p),
                    HASH => directives::directive(p),
                    COMMA => p.bump_any(),
                    _ => {
                        if !opt_value(p) {
                            if p.lenient_end {
                                break;
                            }
                            let found = p.describe_current();
                            p.err_and_bump_run(
                                &format!("expected an array element, found {found}"),
                                ITEM_STARTS.union(KEYWORDS),
                            );
                        }
                    }
                }
            }
        })
    });
    m.complete(p, BRACE_GROUP);
    p.depth -= 1;
}

// test dictionaries
// #declare D = dictionary { ["one"]: 1, ["two"]: <2, 2>, .three: "3" };
/// `dictionary { ["key"]: value, .key: value }`.
fn dictionary(p: &mut Parser<'_>) {
    let m = p.start();
    p.bump(DICTIONARY_KW);
    if p.at(L_BRACE) {
        with_operators(p, false, false, |p| {
            delimited(p, R_BRACE, |p| {
                while !p.at_end() {
                    match p.current() {
                        L_BRACK | DOT => dictionary_entry(p),
                        HASH => directives::directive(p),
                        COMMA | SEMICOLON => p.bump_any(),
                        _ => {
                            let found = p.describe_current();
                            p.err_and_bump_run(
                                &format!("expected a dictionary entry, found {found}"),
                                TokenSet::new(&[L_BRACK, DOT, HASH, COMMA]),
                            );
                        }
                    }
                }
            })
        });
    }
    m.complete(p, DICTIONARY);
}

fn dictionary_entry(p: &mut Parser<'_>) {
    let m = p.start();
    if p.at(L_BRACK) {
        with_operators(p, true, false, |p| {
            delimited(p, R_BRACK, |p| {
                if expressions::opt_expr(p).is_none() {
                    p.error_expected("a key");
                }
            })
        });
    } else {
        p.bump(DOT);
        if p.at(IDENT) || p.current().is_keyword() {
            p.bump_any();
        } else {
            p.error_expected("a key");
        }
    }
    if p.expect(COLON, "':'") && !opt_value(p) {
        p.error_expected("a value");
    }
    m.complete(p, DICTIONARY_ENTRY);
}
