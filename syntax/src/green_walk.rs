//! A walk over every node and token of a tree that reads the shared green tree directly.
//! Rowan's cursors allocate and free a node record for each element they visit; this walk
//! allocates nothing per element, which makes a whole-file pass several times faster. The
//! lints walk every token of a scene on each edit in the editor.

use crate::SyntaxKind;
use crate::syntax_tree::SyntaxNode;
use rowan::{Children, GreenNodeData, NodeOrToken, TextRange, TextSize};

/// A node met in the walk: the node being entered, or one around the current element.
#[derive(Debug, Clone, Copy)]
pub struct GreenNodeRef<'a> {
    green: &'a GreenNodeData,
    start: TextSize,
}

impl<'a> GreenNodeRef<'a> {
    pub fn kind(&self) -> SyntaxKind {
        SyntaxKind::from_raw(self.green.kind().0)
    }

    pub fn range(&self) -> TextRange {
        TextRange::at(self.start, self.green.text_len())
    }

    /// The kinds of the tokens directly inside the node, in order.
    pub fn child_token_kinds(&self) -> impl Iterator<Item = SyntaxKind> + 'a {
        self.green.children().filter_map(|child| match child {
            NodeOrToken::Token(token) => Some(SyntaxKind::from_raw(token.kind().0)),
            NodeOrToken::Node(_) => None,
        })
    }

    /// The node as the root of a tree of its own, for the typed AST: its positions count
    /// from the node's start, not the file's.
    pub fn detached(&self) -> SyntaxNode {
        SyntaxNode::new_root(self.green.to_owned())
    }
}

/// A token met in the walk.
#[derive(Debug, Clone, Copy)]
pub struct GreenTokenRef<'a> {
    pub kind: SyntaxKind,
    pub text: &'a str,
    pub range: TextRange,
}

/// One element of the walk, in document order: a node as it is entered, before its
/// contents, or a token.
#[derive(Debug, Clone, Copy)]
pub enum Step<'a> {
    Node(GreenNodeRef<'a>),
    Token(GreenTokenRef<'a>),
}

/// Visits every node and token below `root` in document order. Besides each element the
/// visitor gets the nodes around it, outermost first, `root` included.
pub fn walk(root: &SyntaxNode, visit: impl FnMut(Step<'_>, &[GreenNodeRef<'_>])) {
    let green = root.green();
    walk_green(&green, root.text_range().start(), visit);
}

fn walk_green<'a>(
    root: &'a GreenNodeData,
    start: TextSize,
    mut visit: impl FnMut(Step<'a>, &[GreenNodeRef<'a>]),
) {
    // An explicit stack: deeply nested input must not exhaust the thread's stack.
    let mut enclosing = vec![GreenNodeRef { green: root, start }];
    let mut pending: Vec<(Children<'a>, TextSize)> = vec![(root.children(), start)];
    while let Some((children, offset)) = pending.last_mut() {
        let Some(child) = children.next() else {
            pending.pop();
            enclosing.pop();
            continue;
        };
        let at = *offset;
        match child {
            NodeOrToken::Node(node) => {
                *offset += node.text_len();
                let entered = GreenNodeRef {
                    green: node,
                    start: at,
                };
                visit(Step::Node(entered), &enclosing);
                enclosing.push(entered);
                pending.push((node.children(), at));
            }
            NodeOrToken::Token(token) => {
                *offset += token.text_len();
                let token = GreenTokenRef {
                    kind: SyntaxKind::from_raw(token.kind().0),
                    text: token.text(),
                    range: TextRange::at(at, token.text_len()),
                };
                visit(Step::Token(token), &enclosing);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::SyntaxElement;

    /// The walk meets the same elements, with the same ranges and the same ancestors, as
    /// rowan's cursor walk.
    #[test]
    fn agrees_with_the_cursor_walk() {
        let text = "#declare A = <1, 2, 3>;\nsphere { A, 1 pigment { rgb <1, 0, 0> } // red\n}\n#macro M(X) X #end\n";
        let root = crate::parse(text).syntax_node();
        let mut walked = Vec::new();
        walk(&root, |step, enclosing| {
            let around: Vec<SyntaxKind> = enclosing.iter().map(|n| n.kind()).collect();
            walked.push(match step {
                Step::Node(node) => (node.kind(), node.range(), around),
                Step::Token(token) => (token.kind, token.range, around),
            });
        });
        let expected: Vec<_> = root
            .descendants_with_tokens()
            .skip(1)
            .map(|element: SyntaxElement| {
                let mut around: Vec<SyntaxKind> = element
                    .parent()
                    .into_iter()
                    .flat_map(|p| p.ancestors())
                    .map(|n| n.kind())
                    .collect();
                around.reverse();
                (element.kind(), element.text_range(), around)
            })
            .collect();
        assert_eq!(walked, expected);
    }

    #[test]
    fn a_detached_node_is_the_same_subtree_from_offset_zero() {
        let root = crate::parse("sphere { 0, 1 }\n#include \"colors.inc\"\n").syntax_node();
        let mut include = None;
        walk(&root, |step, _| {
            if let Step::Node(node) = step
                && node.kind() == SyntaxKind::INCLUDE
            {
                include = Some((node.range(), node.detached()));
            }
        });
        let (range, detached) = include.expect("an include node");
        assert_eq!(detached.kind(), SyntaxKind::INCLUDE);
        assert_eq!(detached.text_range(), TextRange::up_to(range.len()));
        assert_eq!(
            detached.text().to_string().trim_end(),
            "#include \"colors.inc\""
        );
    }
}
