//! The shape of a token stream before it is parsed: which bracket closes which, which
//! `#else` and `#end` belong to which `#if`, and how to recover when they do not match.
//!
//! SDL directives may stand between any two tokens, so braces and directives can cross:
//! `#if (A) union { #else merge { #end ... }` is a valid scene. Such a conditional is parsed
//! "in line": one branch as if its tokens stood in the surrounding text, the others kept
//! as tokens. Every other conditional, loop and macro is parsed as a tree whose branches
//! hold items. Brackets are matched along the branches that are parsed, and the parser
//! then parses each bracketed region up to its known closer, so that one missing brace
//! gives one error instead of swallowing the rest of the file.
//!
//! When the brackets of a file do not match, every conditional is parsed as a tree and
//! brackets are matched within each branch, with indentation guessing where an unclosed
//! region was meant to end.

use crate::SyntaxKind::{self, *};

/// What the parser needs to know about one significant token.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Mark {
    None,
    /// An opening bracket: the region it opens ends at `end`, its closer when `closed`.
    Open {
        end: u32,
        closed: bool,
    },
    /// A closing bracket or a directive that matches nothing.
    Stray,
    /// The `#` of a directive that opens, continues or ends the group with this index.
    Group(u32),
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum GroupKind {
    /// `#if`, `#ifdef`, `#ifndef`.
    If,
    Switch,
    /// `#while`, `#for`.
    Loop,
    Macro,
}

/// How the parser treats a group's branches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Mode {
    /// A node whose branches hold items.
    Tree,
    /// The branch with this index is parsed in line, the others are kept as tokens.
    Inline { active: usize },
    /// A macro body whose brackets do not balance: kept as tokens.
    Flat,
}

/// A directive with its branches and its `#end`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Group {
    pub(crate) kind: GroupKind,
    /// The `#` of the opening directive.
    pub(crate) open: u32,
    /// The `#` of each `#else`, `#elseif`, `#case` and `#range`, in order.
    pub(crate) boundaries: Vec<u32>,
    /// The `#` of the `#end`, when there is one.
    pub(crate) end: Option<u32>,
    /// Where the last branch stops: `end`, or where a missing `#end` was probably meant.
    pub(crate) stop: u32,
    pub(crate) mode: Mode,
    /// Where the bracketed part of the opening directive ends (a macro's parameters,
    /// a condition in parentheses): it is parsed even when the body is not.
    pub(crate) header_end: u32,
}

impl Group {
    /// The `#` that starts branch `i` (the opening directive for branch 0).
    pub(crate) fn branch_start(&self, i: usize) -> u32 {
        if i == 0 {
            self.open
        } else {
            self.boundaries[i - 1]
        }
    }

    /// Where branch `i` stops: the next branch's `#`, or `stop`.
    pub(crate) fn branch_stop(&self, i: usize) -> u32 {
        self.boundaries.get(i).copied().unwrap_or(self.stop)
    }

    /// Where the tokens of the group end, `#end` included.
    pub(crate) fn after(&self) -> u32 {
        self.end.map_or(self.stop, |end| end + 2)
    }
}

/// Where each significant token stands on its line, for recovery by indentation.
pub(crate) struct Layout {
    /// Whether the token is the first significant one on its line.
    pub(crate) first_on_line: Vec<bool>,
    /// The display column of the first significant token on the token's line.
    pub(crate) indent: Vec<u32>,
}

/// The result of the pre-pass.
pub(crate) struct Structure {
    pub(crate) marks: Vec<Mark>,
    pub(crate) groups: Vec<Group>,
}

/// The directive keyword after a `#`, if any.
pub(crate) fn directive_keyword(kinds: &[SyntaxKind], hash: usize) -> Option<SyntaxKind> {
    let kw = *kinds.get(hash + 1)?;
    matches!(
        kw,
        DECLARE_KW
            | LOCAL_KW
            | UNDEF_KW
            | MACRO_KW
            | END_KW
            | WHILE_KW
            | FOR_KW
            | IF_KW
            | IFDEF_KW
            | IFNDEF_KW
            | ELSE_KW
            | ELSEIF_KW
            | SWITCH_KW
            | CASE_KW
            | RANGE_KW
            | BREAK_KW
            | INCLUDE_KW
            | VERSION_KW
            | DEFAULT_KW
            | DEBUG_KW
            | WARNING_KW
            | ERROR_KW
            | RENDER_KW
            | STATISTICS_KW
            | FOPEN_KW
            | FCLOSE_KW
            | READ_KW
            | WRITE_KW
    )
    .then_some(kw)
}

/// Computes the structure of a stream of significant tokens.
pub(crate) fn analyze(kinds: &[SyntaxKind], layout: &Layout) -> Structure {
    let mut pass = Pass {
        kinds,
        layout,
        marks: vec![Mark::None; kinds.len()],
        groups: Vec::new(),
        jump: vec![0; kinds.len()],
    };
    let order = pass.match_directives();
    pass.choose_modes(&order);
    pass.match_brackets();
    Structure {
        marks: pass.marks,
        groups: pass.groups,
    }
}

struct Pass<'a> {
    kinds: &'a [SyntaxKind],
    layout: &'a Layout,
    marks: Vec<Mark>,
    groups: Vec<Group>,
    /// For a token that opens a resolved region (a group or a bracket pair), the index
    /// just after the region; 0 otherwise. Recovery scans step over such regions.
    jump: Vec<u32>,
}

fn opener_of(kind: SyntaxKind) -> Option<SyntaxKind> {
    match kind {
        R_BRACE => Some(L_BRACE),
        R_PAREN => Some(L_PAREN),
        R_BRACK => Some(L_BRACK),
        _ => None,
    }
}

fn is_opener(kind: SyntaxKind) -> bool {
    matches!(kind, L_BRACE | L_PAREN | L_BRACK)
}

impl Pass<'_> {
    fn col(&self, i: usize) -> u32 {
        self.layout.indent[i]
    }

    /// Matches directives; returns the groups in the order they were closed, inner first.
    fn match_directives(&mut self) -> Vec<usize> {
        let hashes: Vec<(usize, SyntaxKind)> = (0..self.kinds.len())
            .filter(|&i| self.kinds[i] == HASH)
            .filter_map(|i| directive_keyword(self.kinds, i).map(|kw| (i, kw)))
            .collect();
        let order = self.match_directives_with(&hashes, false);
        let clean =
            self.groups.iter().all(|g| g.end.is_some()) && !self.marks.contains(&Mark::Stray);
        if clean {
            return order;
        }
        // Something does not match: start again, letting indentation decide which
        // group an `#end` or `#else` was meant for.
        self.groups.clear();
        self.marks.fill(Mark::None);
        self.jump.fill(0);
        self.match_directives_with(&hashes, true)
    }

    fn match_directives_with(&mut self, hashes: &[(usize, SyntaxKind)], guess: bool) -> Vec<usize> {
        let mut stack: Vec<usize> = Vec::new();
        let mut order = Vec::new();
        for &(h, kw) in hashes {
            let kind = match kw {
                IF_KW | IFDEF_KW | IFNDEF_KW => Some(GroupKind::If),
                SWITCH_KW => Some(GroupKind::Switch),
                WHILE_KW | FOR_KW => Some(GroupKind::Loop),
                MACRO_KW => Some(GroupKind::Macro),
                _ => None,
            };
            if let Some(kind) = kind {
                stack.push(self.groups.len());
                self.marks[h] = Mark::Group(self.groups.len() as u32);
                self.groups.push(Group {
                    kind,
                    open: h as u32,
                    boundaries: Vec::new(),
                    end: None,
                    stop: self.kinds.len() as u32,
                    mode: Mode::Tree,
                    header_end: h as u32 + 2,
                });
                continue;
            }
            let accepts = |g: &Group| match kw {
                ELSE_KW => matches!(g.kind, GroupKind::If | GroupKind::Switch),
                ELSEIF_KW => g.kind == GroupKind::If,
                CASE_KW | RANGE_KW => g.kind == GroupKind::Switch,
                END_KW => true,
                _ => false,
            };
            if !matches!(kw, ELSE_KW | ELSEIF_KW | CASE_KW | RANGE_KW | END_KW) {
                continue;
            }
            if guess {
                self.unwind_by_indent(&mut stack, &mut order, h, &accepts);
            }
            let Some(&top) = stack.last() else {
                self.marks[h] = Mark::Stray;
                continue;
            };
            if !accepts(&self.groups[top]) {
                self.marks[h] = Mark::Stray;
                continue;
            }
            self.marks[h] = Mark::Group(top as u32);
            if kw == END_KW {
                stack.pop();
                let group = &mut self.groups[top];
                group.end = Some(h as u32);
                group.stop = h as u32;
                self.jump[group.open as usize] = group.after();
                order.push(top);
            } else {
                self.groups[top].boundaries.push(h as u32);
            }
        }
        let len = self.kinds.len();
        while let Some(top) = stack.pop() {
            self.close_unterminated(top, len, &mut order);
        }
        order
    }

    /// When a directive at the start of a line is less indented than the innermost open
    /// group and lines up with an outer one that accepts it, the groups in between are
    /// taken to be missing their `#end`.
    fn unwind_by_indent(
        &mut self,
        stack: &mut Vec<usize>,
        order: &mut Vec<usize>,
        h: usize,
        accepts: &dyn Fn(&Group) -> bool,
    ) {
        if !self.layout.first_on_line[h] {
            return;
        }
        let col = self.col(h);
        let Some(target) = stack.iter().rposition(|&g| {
            self.col(self.groups[g].open as usize) == col && accepts(&self.groups[g])
        }) else {
            return;
        };
        while stack.len() > target + 1 {
            let top = stack[stack.len() - 1];
            if self.col(self.groups[top].open as usize) <= col {
                return;
            }
            stack.pop();
            self.close_unterminated(top, h, order);
        }
    }

    fn close_unterminated(&mut self, g: usize, limit: usize, order: &mut Vec<usize>) {
        let open = self.groups[g].open as usize;
        let first_body = self.groups[g]
            .boundaries
            .last()
            .map_or(open, |&b| b as usize)
            + 2;
        let stop = self.recovery_point(open, first_body, limit);
        let group = &mut self.groups[g];
        group.stop = stop as u32;
        // Boundaries past the recovery point would belong to nothing.
        group.boundaries.retain(|&b| (b as usize) < stop);
        self.jump[open] = stop as u32;
        order.push(g);
    }

    /// Where a region opened at `open` and left unclosed probably ends: before the first
    /// line, from `from` on, indented no deeper than the line that opened it.
    fn recovery_point(&self, open: usize, from: usize, limit: usize) -> usize {
        let indent = self.col(open);
        let mut j = from.min(limit);
        while j < limit {
            if self.jump[j] > j as u32 {
                j = self.jump[j] as usize;
                continue;
            }
            if self.layout.first_on_line[j] && self.col(j) <= indent {
                return j;
            }
            j += 1;
        }
        limit
    }

    fn choose_modes(&mut self, order: &[usize]) {
        for &g in order {
            let group = &self.groups[g];
            let branches = group.boundaries.len() + 1;
            let mut balanced = true;
            let mut first_shift = None;
            for b in 0..branches {
                let start = group.branch_start(b) as usize + 2;
                let stop = group.branch_stop(b) as usize;
                // Nested tree groups balance by definition: skipping them keeps this
                // linear in the size of the branch however deep groups nest.
                let tokens = self.walk(start, stop, false);
                let (ok, shift) = self.balance(&tokens);
                balanced &= ok;
                if shift != 0 && first_shift.is_none() {
                    first_shift = Some(b);
                }
            }
            let header_end = self.header_end(group);
            let mode = if balanced {
                Mode::Tree
            } else if group.kind == GroupKind::Macro {
                Mode::Flat
            } else {
                Mode::Inline {
                    active: first_shift.unwrap_or(0),
                }
            };
            self.groups[g].mode = mode;
            self.groups[g].header_end = header_end as u32;
        }
    }

    /// Where the bracketed part of a group's opening directive ends: the `(...)` after
    /// a macro's name, or the one right after the directive keyword.
    fn header_end(&self, group: &Group) -> usize {
        let open = group.open as usize;
        let at = if group.kind == GroupKind::Macro {
            open + 3
        } else {
            open + 2
        };
        let stop = group.branch_stop(0) as usize;
        if self.kinds.get(at) != Some(&L_PAREN) || at >= stop {
            return open + 2;
        }
        let mut depth = 0usize;
        for i in at..stop {
            match self.kinds[i] {
                L_PAREN => depth += 1,
                R_PAREN => {
                    depth -= 1;
                    if depth == 0 {
                        return i + 1;
                    }
                }
                _ => {}
            }
        }
        stop
    }

    /// Whether brackets pair up within `tokens`, and how many more open than close.
    fn balance(&self, tokens: &[usize]) -> (bool, i64) {
        let mut stack = Vec::new();
        let mut ok = true;
        let mut shift = 0i64;
        for &i in tokens {
            let kind = self.kinds[i];
            if is_opener(kind) {
                stack.push(kind);
                shift += 1;
            } else if let Some(open) = opener_of(kind) {
                shift -= 1;
                if stack.pop() != Some(open) {
                    ok = false;
                }
            }
        }
        (ok && stack.is_empty(), shift)
    }

    /// The bracket tokens between `start` and `stop` that the parser will meet in line:
    /// inline groups contribute their active branch, flat macros nothing, and tree groups
    /// everything when `into_trees` (otherwise they are scopes of their own).
    fn walk(&self, start: usize, stop: usize, into_trees: bool) -> Vec<usize> {
        let mut out = Vec::new();
        let mut frames = vec![(start, stop)];
        while let Some(frame) = frames.last_mut() {
            let i = frame.0;
            if i >= frame.1 {
                frames.pop();
                continue;
            }
            if let Mark::Group(g) = self.marks[i] {
                let group = &self.groups[g as usize];
                if group.open as usize == i {
                    frame.0 = (group.after() as usize).max(i + 1);
                    match group.mode {
                        Mode::Flat => frames.push((i + 2, group.header_end as usize)),
                        Mode::Tree if into_trees => {
                            frames.push((i + 2, group.stop as usize));
                        }
                        Mode::Tree => {}
                        Mode::Inline { active } => {
                            let from = group.branch_start(active) as usize + 2;
                            frames.push((from, group.branch_stop(active) as usize));
                            if active > 0 {
                                // The condition is parsed though its branch is not;
                                // pushed last so that it is walked first.
                                frames.push((i + 2, group.header_end as usize));
                            }
                        }
                    }
                    continue;
                }
            }
            let kind = self.kinds[i];
            if is_opener(kind) || opener_of(kind).is_some() {
                out.push(i);
            }
            frame.0 += 1;
        }
        out
    }

    fn match_brackets(&mut self) {
        let all = self.walk(0, self.kinds.len(), true);
        if let Some(pairs) = self.pair_exactly(&all) {
            for (open, close) in pairs {
                self.marks[open] = Mark::Open {
                    end: close as u32,
                    closed: true,
                };
            }
            return;
        }
        // The brackets do not match: every group becomes a tree whose branches are
        // scopes of their own, so that a mistake stays inside the branch it is in.
        for group in &mut self.groups {
            if let Mode::Inline { .. } = group.mode {
                group.mode = Mode::Tree;
            }
        }
        let mut scopes = vec![(0, self.kinds.len())];
        for group in &self.groups {
            if group.mode == Mode::Tree {
                for b in 0..=group.boundaries.len() {
                    scopes.push((
                        group.branch_start(b) as usize + 2,
                        group.branch_stop(b) as usize,
                    ));
                }
            }
        }
        // Inner scopes first, so that recovery in an outer scope steps over them.
        scopes.sort_by_key(|&(start, stop)| (stop - start.min(stop), start));
        for (start, stop) in scopes {
            self.match_scope(start, stop);
        }
    }

    fn pair_exactly(&self, tokens: &[usize]) -> Option<Vec<(usize, usize)>> {
        let mut stack = Vec::new();
        let mut pairs = Vec::with_capacity(tokens.len() / 2);
        for &i in tokens {
            let kind = self.kinds[i];
            if is_opener(kind) {
                stack.push(i);
            } else {
                let open = stack.pop()?;
                if Some(self.kinds[open]) != opener_of(kind) {
                    return None;
                }
                pairs.push((open, i));
            }
        }
        stack.is_empty().then_some(pairs)
    }

    fn match_scope(&mut self, start: usize, stop: usize) {
        let tokens = self.walk(start, stop, false);
        let mut stack: Vec<usize> = Vec::new();
        for i in tokens {
            let kind = self.kinds[i];
            if is_opener(kind) {
                stack.push(i);
                continue;
            }
            let Some(open_kind) = opener_of(kind) else {
                continue;
            };
            let Some(target) = self.closer_target(&stack, i, open_kind) else {
                self.marks[i] = Mark::Stray;
                continue;
            };
            while stack.len() > target + 1 {
                let inner = stack.pop().unwrap_or_default();
                self.mark_unclosed(inner, i);
            }
            let open = stack.pop().unwrap_or_default();
            self.marks[open] = Mark::Open {
                end: i as u32,
                closed: true,
            };
            self.jump[open] = i as u32 + 1;
        }
        while let Some(open) = stack.pop() {
            self.mark_unclosed(open, stop);
        }
    }

    /// Which open bracket a closer at `i` closes: the innermost one of its kind, unless
    /// the closer starts a line and lines up with an outer one of its kind.
    fn closer_target(&self, stack: &[usize], i: usize, open_kind: SyntaxKind) -> Option<usize> {
        let innermost = stack.iter().rposition(|&o| self.kinds[o] == open_kind)?;
        if !self.layout.first_on_line[i] {
            return Some(innermost);
        }
        let col = self.col(i);
        if self.col(stack[innermost]) <= col {
            return Some(innermost);
        }
        let aligned = stack[..innermost]
            .iter()
            .rposition(|&o| self.kinds[o] == open_kind && self.col(o) == col);
        Some(aligned.unwrap_or(innermost))
    }

    fn mark_unclosed(&mut self, open: usize, limit: usize) {
        let end = self.recovery_point(open, open + 1, limit);
        self.marks[open] = Mark::Open {
            end: end as u32,
            closed: false,
        };
        self.jump[open] = end as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lexer::lex;

    /// Describes the structure of `text`: each bracket and directive with what it matched.
    fn describe(text: &str) -> String {
        let lexed = lex(text);
        let significant: Vec<_> = lexed
            .tokens
            .iter()
            .filter(|t| !t.kind.is_trivia() && t.kind != ERROR)
            .collect();
        let kinds: Vec<_> = significant.iter().map(|t| t.kind).collect();
        let layout = super::super::layout(text, &significant);
        let structure = analyze(&kinds, &layout);
        let mut out = String::new();
        for (i, mark) in structure.marks.iter().enumerate() {
            let text_at = |j: u32| &text[significant[j as usize].range];
            match *mark {
                Mark::None => {}
                Mark::Open { end, closed } => out.push_str(&format!(
                    "{i} {} {} {end}\n",
                    text_at(i as u32),
                    if closed {
                        "closed by"
                    } else {
                        "unclosed, ends before"
                    }
                )),
                Mark::Stray => out.push_str(&format!("{i} {} stray\n", text_at(i as u32))),
                Mark::Group(_) => {}
            }
        }
        for g in &structure.groups {
            out.push_str(&format!(
                "group {:?} at {} boundaries {:?} end {:?} stop {} {:?}\n",
                g.kind, g.open, g.boundaries, g.end, g.stop, g.mode
            ));
        }
        out
    }

    #[test]
    fn balanced_groups_are_trees() {
        expect_test::expect![[r#"
            0 { closed by 8
            3 ( closed by 5
            group If at 1 boundaries [] end Some(6) stop 6 Tree
        "#]]
        .assert_eq(&describe("{ #if (A) #end }"));
    }

    #[test]
    fn braces_crossing_a_conditional_parse_in_line() {
        expect_test::expect![[r#"
            2 ( closed by 4
            6 { closed by 16
            14 { closed by 15
            group If at 0 boundaries [7] end Some(11) stop 11 Inline { active: 0 }
        "#]]
        .assert_eq(&describe("#if (A) union { #else merge { #end sphere {} }"));
    }

    #[test]
    fn the_shifting_branch_is_the_one_parsed_in_line() {
        expect_test::expect![[r#"
            2 ( closed by 4
            8 { closed by 11
            group If at 0 boundaries [5] end Some(9) stop 9 Inline { active: 1 }
        "#]]
        .assert_eq(&describe("#if (A) #else union { #end }"));
    }

    #[test]
    fn unclosed_brace_ends_where_indentation_drops() {
        expect_test::expect![[r#"
            1 { unclosed, ends before 7
            3 ( closed by 5
            8 { closed by 9
        "#]]
        .assert_eq(&describe("union {\n  box (1)\n  sphere\ncamera { }\n"));
    }

    #[test]
    fn closing_brace_lines_up_with_its_opener() {
        expect_test::expect![[r#"
            1 { closed by 10
            3 { unclosed, ends before 7
            5 { closed by 6
            8 { closed by 9
        "#]]
        .assert_eq(&describe(
            "union {\n  sphere {\n    pigment {}\n  box {}\n}\n",
        ));
    }

    #[test]
    fn missing_end_is_guessed_by_indentation() {
        expect_test::expect![[r#"
            2 ( closed by 4
            7 ( closed by 9
            group Loop at 0 boundaries [] end Some(17) stop 17 Tree
            group If at 5 boundaries [] end None stop 11 Tree
        "#]]
        .assert_eq(&describe(
            "#while (I)\n  #if (A)\n    sphere\n  #local I = I;\n#end\n",
        ));
    }

    #[test]
    fn strays() {
        expect_test::expect![[r#"
            0 } stray
            1 ) stray
            2 # stray
            4 # stray
        "#]]
        .assert_eq(&describe("} ) #else #end"));
    }
}
