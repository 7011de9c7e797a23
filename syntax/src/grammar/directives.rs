//! Directives: `#declare`, `#macro`, `#if`, `#while` and the rest. They may stand
//! between any two tokens; the pre-pass has already decided how each conditional, loop
//! and macro is parsed (see `parsing::structure`).

use super::expressions;
use super::items::{block_body, item_list, name, opt_value, param_list};
use crate::SyntaxKind::{self, *};
use crate::parsing::{Group, GroupKind, Mark, Mode, Parser};

/// A directive at a `#`.
pub(super) fn directive(p: &mut Parser<'_>) {
    let hash = p.pos();
    match p.mark(hash) {
        Mark::Group(g) => {
            let structure = p.structure;
            let group = &structure.groups[g as usize];
            if group.open as usize != hash {
                inline_tail(p, group);
            } else {
                match group.mode {
                    Mode::Tree => tree_group(p, group),
                    Mode::Inline { active } => inline_open(p, group, active),
                    Mode::Flat => flat_macro(p, group),
                }
            }
        }
        Mark::Stray => stray(p),
        _ => simple(p),
    }
    p.after_directive = true;
}

fn simple(p: &mut Parser<'_>) {
    match p.nth(1) {
        DECLARE_KW | LOCAL_KW => declare(p),
        UNDEF_KW => undef(p),
        INCLUDE_KW => include(p),
        VERSION_KW => version(p),
        DEFAULT_KW => default(p),
        DEBUG_KW | WARNING_KW | ERROR_KW | RENDER_KW | STATISTICS_KW => message(p),
        FOPEN_KW | FCLOSE_KW | READ_KW | WRITE_KW => file_io(p),
        BREAK_KW => {
            let m = p.start();
            p.bump(HASH);
            p.bump(BREAK_KW);
            m.complete(p, BREAK);
        }
        _ => lone_hash(p),
    }
}

// test lone_hash
// #Macro(1)
// camera { look_at 0 # }
/// `#` before something that is not a directive: POV-Ray reads past it.
fn lone_hash(p: &mut Parser<'_>) {
    p.bump(HASH);
}

// test_err stray_directives
// #else
// sphere { 0, 1 }
// #end
/// An `#else`, `#case` or `#end` that belongs to nothing (reported with the structure,
/// see `parsing::directive_errors`).
fn stray(p: &mut Parser<'_>) {
    let m = p.start();
    p.bump(HASH);
    p.bump_any();
    m.complete(p, ERROR_NODE);
}

fn node_kind(keyword: SyntaxKind) -> SyntaxKind {
    match keyword {
        SWITCH_KW => SWITCH,
        WHILE_KW => WHILE,
        FOR_KW => FOR,
        MACRO_KW => MACRO,
        _ => IF,
    }
}

// test conditionals
// #if (A) sphere { 0, 1 } #elseif (B) box { 0, 1 } #else #debug "none" #end
// #ifdef (Foo) #declare Bar = Foo; #end
// #switch (N) #case (1) #debug "one" #break #range (2, 5) #debug "few" #else #debug "many" #end
// test loops
// #while (I < 10) #local I = I + 1; #end
// #for (I, 0, 10, 2) sphere { <I, 0, 0>, 1 } #end
// test macros
// #macro Ring(R, optional Thickness)
//   torus { R, Thickness }
// #end
// #macro Half(V) V/2 #end
/// A conditional, loop or macro whose branches hold items.
fn tree_group(p: &mut Parser<'_>, group: &Group) {
    let kind = node_kind(p.nth(1));
    let m = p.start();
    p.with_limit(group.branch_stop(0) as usize, |p| {
        header(p, group);
        body(p, group);
    });
    for b in 1..=group.boundaries.len() {
        let branch = p.start();
        p.with_limit(group.branch_stop(b) as usize, |p| {
            boundary_header(p);
            body(p, group);
        });
        branch.complete(p, BRANCH);
    }
    end(p, group);
    m.complete(p, kind);
}

/// The `#end` of a group, or the error for its absence.
fn end(p: &mut Parser<'_>, group: &Group) {
    // A missing `#end` is reported with the structure, see `parsing::directive_errors`.
    if group.end.is_some() && p.at(HASH) {
        p.bump(HASH);
        p.bump(END_KW);
    }
}

// test_err missing_end
// #while (I < 3)
//   #if (I = 1)
//     sphere { 0, 1 }
//   #local I = I + 1;
// #end
// camera { }
fn body(p: &mut Parser<'_>, group: &Group) {
    if group.kind == GroupKind::Macro {
        macro_body(p);
    } else if !p.at_end() {
        let m = p.start();
        item_list(p);
        m.complete(p, DIRECTIVE_BODY);
    }
}

/// A macro body: items when they parse on their own, else the tokens as they are,
/// since a macro may expand to a fragment that only fits where it is called.
fn macro_body(p: &mut Parser<'_>) {
    let m = p.start();
    let snapshot = p.snapshot();
    item_list(p);
    if p.errors.len() > snapshot.error_count() {
        p.restore(snapshot);
        p.bump_rest();
    }
    m.complete(p, MACRO_BODY);
}

// test_err macro_header_cut_by_end
// #macro M(a #end )
// #declare After = 1;
// test macro_fragments
// #macro Open() union { #end
// #macro Close() } #end
// #macro Tail() , 1 } #end
/// A macro whose brackets do not balance: its body stays a token sequence.
fn flat_macro(p: &mut Parser<'_>, group: &Group) {
    let m = p.start();
    p.with_limit(group.stop as usize, |p| {
        p.with_limit(group.header_end as usize, |p| header(p, group));
        let body = p.start();
        p.bump_rest();
        body.complete(p, MACRO_BODY);
    });
    end(p, group);
    m.complete(p, MACRO);
}

// test inline_conditionals
// #if (Merge) merge { #else union { #end
//   sphere { 0, 1 }
//   sphere { x, 1 }
// }
// #if (A) #else object { B #end translate x }
/// A conditional whose braces only balance across its `#end`: its header, the
/// branches before the one parsed in line, and that branch's header.
fn inline_open(p: &mut Parser<'_>, group: &Group, active: usize) {
    let kind = node_kind(p.nth(1));
    let m = p.start();
    p.with_limit(group.branch_stop(0) as usize, |p| header(p, group));
    if active > 0 {
        let branch = group.branch_start(active) as usize;
        if p.pos() < branch {
            let skipped = p.start();
            p.bump_until(branch);
            skipped.complete(p, INACTIVE);
        }
        p.with_limit(group.branch_stop(active) as usize, boundary_header);
    }
    m.complete(p, kind);
}

/// The rest of an in-line conditional, from the end of its parsed branch to `#end`.
fn inline_tail(p: &mut Parser<'_>, group: &Group) {
    let m = p.start();
    p.bump_until(group.after() as usize);
    m.complete(p, INACTIVE);
}

/// `#if (c)`, `#while (c)`, `#for (I, 0, 9)`, `#switch (x)`, `#macro Name(params)`.
fn header(p: &mut Parser<'_>, group: &Group) {
    p.bump(HASH);
    let keyword = p.current();
    p.bump_any();
    match keyword {
        FOR_KW => for_header(p),
        MACRO_KW => {
            if p.at(IDENT) {
                name(p);
            } else {
                p.error_expected("a macro name");
            }
            if p.at(L_PAREN) {
                param_list(p);
            } else {
                p.error_expected("'('");
            }
        }
        _ => {
            debug_assert!(group.kind != GroupKind::Macro);
            expressions::expr_or_error(p, "a condition");
        }
    }
}

/// `(I, start, end[, step])`.
fn for_header(p: &mut Parser<'_>) {
    if !p.at(L_PAREN) {
        p.error_expected("'('");
        return;
    }
    super::with_operators(p, true, false, |p| {
        super::delimited(p, R_PAREN, |p| {
            if p.at(IDENT) {
                name(p);
            } else {
                p.error_expected("a loop variable");
            }
            while p.eat(COMMA) {
                expressions::expr_or_error(p, "an expression");
            }
        })
    });
}

/// `#else`, `#elseif (c)`, `#case (c)`, `#range (a, b)`.
fn boundary_header(p: &mut Parser<'_>) {
    p.bump(HASH);
    let keyword = p.current();
    p.bump_any();
    if keyword != ELSE_KW {
        expressions::expr_or_error(p, "a condition");
    }
}

// test declarations
// #declare A = 1;
// #local B = <1, 2, 3>
// #declare S = sphere { 0, 1 }
// #declare T = texture { pigment { Red } };
// #declare Arr[2] = 5;
// #declare D.key = "value";
// #declare deprecated once "use B" Old = 1;
// #declare X = #if (A) 1 #else 2 #end;
// declare Legacy = 1;
// test_err declaration_errors
// #declare = 1;
// #declare C 3;
// #declare E = ;
/// `#declare Name = value;`, `#local Arr[1] = value;`.
pub(super) fn declare(p: &mut Parser<'_>) {
    let m = p.start();
    // Before POV-Ray 3.0 these four had no `#`; 3.7 still accepts that, with a warning.
    p.eat(HASH);
    p.bump_any();
    if p.eat(DEPRECATED_KW) {
        p.eat(ONCE_KW);
        p.eat(STRING);
    }
    super::with_operators(p, false, false, |p| {
        declare_target(p);
        if p.expect(EQ, "'='") {
            value_or_error(p);
        }
    });
    p.eat(SEMICOLON);
    m.complete(p, DECLARE);
}

fn declare_target(p: &mut Parser<'_>) {
    match p.current() {
        L_PAREN => target_list(p),
        IDENT if matches!(p.nth(1), L_BRACK | DOT) => {
            expressions::expr(p);
        }
        IDENT => name(p),
        // A reserved word of a later POV-Ray may be a name in older files (math.inc
        // of 3.7 declares `atand`); whether it may be redeclared is the evaluator's call.
        kind if kind.is_keyword() => name(p),
        _ => p.error_expected("an identifier"),
    }
}

// test tuple_declarations
// #declare (A, B, C) = (1, 2, 3);
// #local (, Second) = Pair();
/// `(A, B)`: the targets of a tuple assignment (POV-Ray 3.8).
fn target_list(p: &mut Parser<'_>) {
    let m = p.start();
    super::delimited(p, R_PAREN, |p| {
        while !p.at_end() {
            match p.current() {
                COMMA => p.bump_any(),
                IDENT | L_PAREN => declare_target(p),
                _ if p.lenient_end => break,
                _ => {
                    let found = p.describe_current();
                    p.err_and_bump_run(
                        &format!("expected an identifier, found {found}"),
                        crate::parsing::TokenSet::new(&[COMMA, IDENT]),
                    );
                }
            }
        }
    });
    m.complete(p, TARGET_LIST);
}

/// A required value, which a directive before it may stand in for.
fn value_or_error(p: &mut Parser<'_>) {
    while p.at(HASH) {
        directive(p);
    }
    if !opt_value(p) {
        p.error_expected("a value");
    }
}

// test simple_directives
// #version 3.7;
// #include "colors.inc"
// #default { finish { ambient 0.1 } }
// #undef Foo
// #debug concat("x = ", str(X, 0, 2), "\n")
// #warning "careful"
// #fopen F "data.txt" read
// #read (F, A, B)
// #write (F, A, ",", B, "\n")
// #write (F, uint16be <X, Y, Z>, sint8 -1)
// #fclose F
fn undef(p: &mut Parser<'_>) {
    let m = p.start();
    p.bump(HASH);
    p.bump(UNDEF_KW);
    if p.at(IDENT) {
        let r = p.start();
        p.bump(IDENT);
        r.complete(p, NAME_REF);
    } else {
        p.error_expected("an identifier");
    }
    m.complete(p, UNDEF);
}

pub(super) fn include(p: &mut Parser<'_>) {
    let m = p.start();
    // Before POV-Ray 3.0 these four had no `#`; 3.7 still accepts that, with a warning.
    p.eat(HASH);
    p.bump(INCLUDE_KW);
    expressions::expr_or_error(p, "a file name");
    m.complete(p, INCLUDE);
}

pub(super) fn version(p: &mut Parser<'_>) {
    let m = p.start();
    // Before POV-Ray 3.0 these four had no `#`; 3.7 still accepts that, with a warning.
    p.eat(HASH);
    p.bump(VERSION_KW);
    expressions::expr_or_error(p, "a version number");
    p.eat(SEMICOLON);
    m.complete(p, VERSION);
}

pub(super) fn default(p: &mut Parser<'_>) {
    let m = p.start();
    // Before POV-Ray 3.0 these four had no `#`; 3.7 still accepts that, with a warning.
    p.eat(HASH);
    p.bump(DEFAULT_KW);
    if p.at(L_BRACE) {
        block_body(p);
    } else {
        p.error_expected("'{'");
    }
    m.complete(p, DEFAULT);
}

fn message(p: &mut Parser<'_>) {
    let m = p.start();
    p.bump(HASH);
    p.bump_any();
    expressions::expr_or_error(p, "a message");
    m.complete(p, MESSAGE);
}

fn file_io(p: &mut Parser<'_>) {
    let m = p.start();
    p.bump(HASH);
    let keyword = p.current();
    p.bump_any();
    match keyword {
        FOPEN_KW => {
            if p.at(IDENT) {
                name(p);
            } else {
                p.error_expected("a file identifier");
            }
            expressions::expr_or_error(p, "a file name");
            if p.at(READ_KW) || p.at(WRITE_KW) || p.at(APPEND_KW) {
                p.bump_any();
            } else {
                p.error_expected("'read', 'write' or 'append'");
            }
        }
        FCLOSE_KW => {
            if p.at(IDENT) {
                let r = p.start();
                p.bump(IDENT);
                r.complete(p, NAME_REF);
            } else {
                p.error_expected("a file identifier");
            }
        }
        _ => {
            if p.at(L_PAREN) {
                expressions::arg_list(p);
            } else {
                p.error_expected("'('");
            }
        }
    }
    m.complete(p, FILE_IO);
}
