//! A typed view over the untyped tree: one type per node kind that editors and the
//! formatter need, with accessors that return `Option` because a tree built from broken
//! text may lack any part. Nothing here panics.

use crate::SyntaxKind::{self, *};
use crate::lexer::unescape_string;
use crate::{SyntaxNode, SyntaxToken};

/// A typed node.
pub trait AstNode: Sized {
    fn can_cast(kind: SyntaxKind) -> bool;
    fn cast(node: SyntaxNode) -> Option<Self>;
    fn syntax(&self) -> &SyntaxNode;
}

macro_rules! ast_node {
    ($(#[$meta:meta])* $name:ident: $($kind:ident)|+) => {
        $(#[$meta])*
        #[derive(Debug, Clone, PartialEq, Eq, Hash)]
        pub struct $name(SyntaxNode);

        impl AstNode for $name {
            fn can_cast(kind: SyntaxKind) -> bool {
                matches!(kind, $($kind)|+)
            }
            fn cast(node: SyntaxNode) -> Option<Self> {
                Self::can_cast(node.kind()).then(|| $name(node))
            }
            fn syntax(&self) -> &SyntaxNode {
                &self.0
            }
        }
    };
}

fn child<N: AstNode>(node: &SyntaxNode) -> Option<N> {
    node.children().find_map(N::cast)
}

fn children<N: AstNode>(node: &SyntaxNode) -> impl Iterator<Item = N> + use<N> {
    node.children().filter_map(N::cast)
}

fn token(node: &SyntaxNode, kind: SyntaxKind) -> Option<SyntaxToken> {
    node.children_with_tokens()
        .filter_map(|e| e.into_token())
        .find(|t| t.kind() == kind)
}

/// The first reserved word among a node's own tokens.
fn keyword(node: &SyntaxNode) -> Option<SyntaxToken> {
    node.children_with_tokens()
        .filter_map(|e| e.into_token())
        .find(|t| t.kind().is_keyword())
}

/// The directive keyword after a node's leading `#`.
fn directive_keyword(node: &SyntaxNode) -> Option<SyntaxToken> {
    let mut tokens = node
        .children_with_tokens()
        .filter_map(|e| e.into_token())
        .filter(|t| !t.kind().is_trivia());
    tokens.find(|t| t.kind() == HASH)?;
    tokens.next().filter(|t| t.kind().is_keyword())
}

ast_node!(
    /// A whole file.
    SourceFile: SOURCE_FILE
);

impl SourceFile {
    pub(crate) fn new(node: SyntaxNode) -> Self {
        SourceFile(node)
    }

    /// The top-level items: directives, blocks, expressions (such as macro calls).
    pub fn items(&self) -> impl Iterator<Item = SyntaxNode> + use<> {
        self.0.children()
    }

    /// Every comment in the file, in order.
    pub fn comments(&self) -> impl Iterator<Item = Comment> + use<> {
        self.0
            .descendants_with_tokens()
            .filter_map(|e| e.into_token())
            .filter_map(Comment::cast)
    }

    /// The declarations anywhere in the file, including inside blocks and directives.
    pub fn declarations(&self) -> impl Iterator<Item = Declare> + use<> {
        self.0.descendants().filter_map(Declare::cast)
    }

    /// The macro definitions anywhere in the file.
    pub fn macros(&self) -> impl Iterator<Item = Macro> + use<> {
        self.0.descendants().filter_map(Macro::cast)
    }

    pub fn includes(&self) -> impl Iterator<Item = Include> + use<> {
        self.0.descendants().filter_map(Include::cast)
    }
}

/// A `//` or `/* */` comment.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Comment(SyntaxToken);

impl Comment {
    pub fn cast(token: SyntaxToken) -> Option<Comment> {
        matches!(token.kind(), LINE_COMMENT | BLOCK_COMMENT).then(|| Comment(token))
    }

    pub fn syntax(&self) -> &SyntaxToken {
        &self.0
    }

    pub fn is_block(&self) -> bool {
        self.0.kind() == BLOCK_COMMENT
    }

    /// The text without the comment markers.
    pub fn content(&self) -> &str {
        let text = self.0.text();
        if self.is_block() {
            let inner = text.strip_prefix("/*").unwrap_or(text);
            inner.strip_suffix("*/").unwrap_or(inner)
        } else {
            text.strip_prefix("//").unwrap_or(text)
        }
    }
}

ast_node!(
    /// A defining occurrence of an identifier: declared, a macro, a parameter.
    Name: NAME
);

impl Name {
    pub fn token(&self) -> Option<SyntaxToken> {
        self.0
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .find(|t| !t.kind().is_trivia())
    }

    pub fn text(&self) -> Option<String> {
        self.token().map(|t| t.text().to_string())
    }
}

ast_node!(
    /// A use of an identifier.
    NameRef: NAME_REF
);

impl NameRef {
    pub fn ident(&self) -> Option<SyntaxToken> {
        token(&self.0, IDENT)
    }

    pub fn text(&self) -> Option<String> {
        self.ident().map(|t| t.text().to_string())
    }
}

ast_node!(
    /// `#declare Name = value;` or `#local Name = value;`.
    Declare: DECLARE
);

impl Declare {
    pub fn is_local(&self) -> bool {
        directive_keyword(&self.0).is_some_and(|t| t.kind() == LOCAL_KW)
    }

    /// The declared name, when the target is a plain name (not `Arr[1]` or `D.key`).
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// The names a tuple assignment declares: `#declare (A, B) = ...` (POV-Ray 3.8).
    pub fn tuple_names(&self) -> impl Iterator<Item = Name> + use<> {
        self.0
            .children()
            .filter(|n| n.kind() == TARGET_LIST)
            .flat_map(|list| {
                list.descendants()
                    .filter_map(Name::cast)
                    .collect::<Vec<_>>()
            })
    }

    /// The target when it is an element: `Arr[1]`, `D.key`.
    pub fn element_target(&self) -> Option<SyntaxNode> {
        self.0
            .children()
            .take_while(|n| n.kind() != NAME)
            .find(|n| matches!(n.kind(), INDEX_EXPR | DOT_EXPR))
    }

    /// The assigned value: an expression or a block.
    pub fn value(&self) -> Option<SyntaxNode> {
        let eq = token(&self.0, EQ)?;
        self.0
            .children()
            .find(|n| n.text_range().start() >= eq.text_range().end())
    }
}

ast_node!(
    /// `#macro Name(params) body #end`.
    Macro: MACRO
);

impl Macro {
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    pub fn params(&self) -> impl Iterator<Item = Param> + use<> {
        child::<ParamList>(&self.0)
            .into_iter()
            .flat_map(|list| children::<Param>(&list.0).collect::<Vec<_>>())
    }

    pub fn body(&self) -> Option<MacroBody> {
        child(&self.0)
    }

    /// Whether the macro has its `#end`.
    pub fn has_end(&self) -> bool {
        token(&self.0, END_KW).is_some()
    }
}

ast_node!(
    /// The parameters of a macro or function.
    ParamList: PARAM_LIST
);

impl ParamList {
    pub fn params(&self) -> impl Iterator<Item = Param> + use<> {
        children(&self.0)
    }
}

ast_node!(Param: PARAM);

impl Param {
    pub fn name(&self) -> Option<Name> {
        child(&self.0)
    }

    /// Whether the parameter is marked `optional` (POV-Ray 3.8).
    pub fn is_optional(&self) -> bool {
        token(&self.0, OPTIONAL_KW).is_some()
    }
}

ast_node!(
    /// A macro's body: a token sequence, with item nodes when it parses on its own.
    MacroBody: MACRO_BODY
);

impl MacroBody {
    /// Whether the body parsed as items (otherwise it is kept as plain tokens).
    pub fn is_structured(&self) -> bool {
        self.0.children().next().is_some()
            || self
                .0
                .children_with_tokens()
                .all(|e| e.as_token().is_some_and(|t| t.kind().is_trivia()))
    }

    pub fn items(&self) -> impl Iterator<Item = SyntaxNode> + use<> {
        self.0.children()
    }
}

ast_node!(
    /// A call of a macro, a user function, a spline or a built-in function.
    Call: CALL
);

impl Call {
    /// The called identifier; `None` for built-in functions.
    pub fn name_ref(&self) -> Option<NameRef> {
        child(&self.0)
    }

    /// The built-in function's keyword, such as `vlength`.
    pub fn builtin(&self) -> Option<SyntaxToken> {
        keyword(&self.0)
    }

    pub fn arg_list(&self) -> Option<ArgList> {
        child(&self.0)
    }
}

ast_node!(ArgList: ARG_LIST);

impl ArgList {
    /// The argument values; empty arguments (`M(1, , 3)`) are not listed.
    pub fn args(&self) -> impl Iterator<Item = SyntaxNode> + use<> {
        self.0.children()
    }
}

ast_node!(
    /// `#include "file.inc"`.
    Include: INCLUDE
);

impl Include {
    /// The string literal naming the file, when it is a literal.
    pub fn path_token(&self) -> Option<SyntaxToken> {
        let literal = child::<Literal>(&self.0)?;
        literal.token().filter(|t| t.kind() == STRING)
    }

    /// The file name with escapes resolved.
    pub fn path(&self) -> Option<String> {
        self.path_token().map(|t| unescape_string(t.text()).0)
    }
}

ast_node!(
    /// A keyword block: objects, textures, camera, lights, maps, settings.
    Block: OBJECT | CAMERA | LIGHT_SOURCE | TEXTURE | PIGMENT | NORMAL | FINISH | INTERIOR
        | MEDIA | DENSITY | GLOBAL_SETTINGS | ATMOSPHERIC | TRANSFORM | SPLINE | FUNCTION
        | BLOCK
);

impl Block {
    /// The keyword that opens the block: `sphere`, `pigment`, `color_map`.
    pub fn keyword(&self) -> Option<SyntaxToken> {
        keyword(&self.0)
    }

    /// What stands inside the braces.
    pub fn items(&self) -> impl Iterator<Item = SyntaxNode> + use<> {
        self.0.children()
    }

    pub fn l_brace(&self) -> Option<SyntaxToken> {
        token(&self.0, L_BRACE)
    }

    pub fn r_brace(&self) -> Option<SyntaxToken> {
        token(&self.0, R_BRACE)
    }
}

ast_node!(
    /// An object, a CSG operation or an `object { }` reference.
    Object: OBJECT
);

impl Object {
    pub fn keyword(&self) -> Option<SyntaxToken> {
        keyword(&self.0)
    }

    /// For `object { Name ... }`, the referenced object.
    pub fn reference(&self) -> Option<NameRef> {
        child(&self.0)
    }
}

ast_node!(Camera: CAMERA);
ast_node!(LightSource: LIGHT_SOURCE);
ast_node!(
    /// `texture`, `material` and `interior_texture` blocks.
    Texture: TEXTURE
);

ast_node!(
    /// A keyword and its argument: `translate x`, `ambient 0.1`, `hollow`.
    Property: PROPERTY
);

impl Property {
    pub fn keyword(&self) -> Option<SyntaxToken> {
        keyword(&self.0)
    }

    pub fn value(&self) -> Option<SyntaxNode> {
        self.0.children().next()
    }
}

ast_node!(
    /// `#if`, `#ifdef` and `#ifndef`, with their `#elseif` and `#else` branches.
    If: IF
);

impl If {
    /// `if`, `ifdef` or `ifndef`.
    pub fn keyword(&self) -> Option<SyntaxToken> {
        directive_keyword(&self.0)
    }

    pub fn condition(&self) -> Option<SyntaxNode> {
        self.0
            .children()
            .find(|n| !matches!(n.kind(), DIRECTIVE_BODY | BRANCH | INACTIVE))
    }

    pub fn body(&self) -> Option<DirectiveBody> {
        child(&self.0)
    }

    pub fn branches(&self) -> impl Iterator<Item = Branch> + use<> {
        children(&self.0)
    }

    /// Whether the conditional was parsed in line because braces cross its branches:
    /// then only one branch has structure and its items follow the node.
    pub fn is_inline(&self) -> bool {
        token(&self.0, END_KW).is_none()
            && self.body().is_none()
            && self.branches().next().is_none()
    }
}

ast_node!(
    /// `#else`, `#elseif (c)`, `#case (c)` or `#range (a, b)` and its items.
    Branch: BRANCH
);

impl Branch {
    pub fn keyword(&self) -> Option<SyntaxToken> {
        directive_keyword(&self.0)
    }

    pub fn condition(&self) -> Option<SyntaxNode> {
        self.0.children().find(|n| n.kind() != DIRECTIVE_BODY)
    }

    pub fn body(&self) -> Option<DirectiveBody> {
        child(&self.0)
    }
}

ast_node!(
    /// The items a directive governs.
    DirectiveBody: DIRECTIVE_BODY
);

impl DirectiveBody {
    pub fn items(&self) -> impl Iterator<Item = SyntaxNode> + use<> {
        self.0.children()
    }
}

ast_node!(While: WHILE);

impl While {
    pub fn condition(&self) -> Option<SyntaxNode> {
        self.0.children().find(|n| n.kind() != DIRECTIVE_BODY)
    }

    pub fn body(&self) -> Option<DirectiveBody> {
        child(&self.0)
    }
}

ast_node!(
    /// `#for (Name, start, end, step)`.
    For: FOR
);

impl For {
    pub fn variable(&self) -> Option<Name> {
        self.0.descendants().find_map(Name::cast)
    }

    pub fn body(&self) -> Option<DirectiveBody> {
        child(&self.0)
    }
}

ast_node!(Switch: SWITCH);

impl Switch {
    pub fn branches(&self) -> impl Iterator<Item = Branch> + use<> {
        children(&self.0)
    }
}

ast_node!(
    /// Any directive: `#declare`, `#if`, `#version`, `#debug`...
    Directive: DECLARE | UNDEF | MACRO | IF | WHILE | FOR | SWITCH | INCLUDE | VERSION
        | DEFAULT | MESSAGE | FILE_IO | BREAK
);

impl Directive {
    /// The keyword after the `#`.
    pub fn keyword(&self) -> Option<SyntaxToken> {
        directive_keyword(&self.0)
    }
}

ast_node!(
    /// A number, string or built-in constant.
    Literal: LITERAL
);

impl Literal {
    pub fn token(&self) -> Option<SyntaxToken> {
        self.0
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .find(|t| !t.kind().is_trivia())
    }
}

/// Whether a kind is one of the expression nodes.
pub fn is_expression(kind: SyntaxKind) -> bool {
    matches!(
        kind,
        LITERAL
            | NAME_REF
            | CALL
            | VECTOR
            | PAREN_EXPR
            | PREFIX_EXPR
            | BIN_EXPR
            | TERNARY_EXPR
            | DOT_EXPR
            | INDEX_EXPR
            | COLOR
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse;

    #[test]
    fn declarations_macros_and_includes() {
        let file = parse(
            "#include \"colors.inc\"\n// a comment\n#declare A = 1;\n#local B[1] = 2;\n\
             #macro M(X, optional Y) sphere { X, 1 } #end\nM(1, 2)\n",
        )
        .source_file();
        let includes: Vec<_> = file.includes().filter_map(|i| i.path()).collect();
        assert_eq!(includes, ["colors.inc"]);
        let declares: Vec<_> = file.declarations().collect();
        assert_eq!(
            declares[0].name().and_then(|n| n.text()).as_deref(),
            Some("A")
        );
        assert_eq!(declares[0].value().map(|v| v.kind()), Some(LITERAL));
        assert!(declares[1].is_local() && declares[1].name().is_none());
        assert_eq!(declares[1].tuple_names().count(), 0);
        assert_eq!(
            declares[1]
                .element_target()
                .map(|t| t.to_string())
                .as_deref(),
            Some("B[1]")
        );
        let m = file.macros().next().unwrap();
        assert_eq!(m.name().and_then(|n| n.text()).as_deref(), Some("M"));
        let params: Vec<_> = m
            .params()
            .map(|p| (p.name().and_then(|n| n.text()).unwrap(), p.is_optional()))
            .collect();
        assert_eq!(params, [("X".to_string(), false), ("Y".to_string(), true)]);
        assert!(m.body().is_some_and(|b| b.is_structured()) && m.has_end());
        let call = file.syntax().descendants().find_map(Call::cast).unwrap();
        assert_eq!(call.name_ref().and_then(|n| n.text()).as_deref(), Some("M"));
        assert_eq!(call.arg_list().unwrap().args().count(), 2);
        assert_eq!(file.items().count(), 5);
        let comments: Vec<_> = file.comments().map(|c| c.content().to_string()).collect();
        assert_eq!(comments, [" a comment"]);
    }

    #[test]
    fn tuple_assignment() {
        let file = parse("#declare (A, , B) = (1, 2, 3);").source_file();
        let names: Vec<_> = file
            .declarations()
            .flat_map(|d| d.tuple_names())
            .filter_map(|n| n.text())
            .collect();
        assert_eq!(names, ["A", "B"]);
    }

    #[test]
    fn blocks_and_directives() {
        let file = parse(
            "#if (A) object { Thing translate x } #else camera { } #end\n\
             light_source { 0 color rgb 1 }",
        )
        .source_file();
        let conditional = file.syntax().descendants().find_map(If::cast).unwrap();
        assert_eq!(conditional.keyword().map(|k| k.kind()), Some(IF_KW));
        assert_eq!(conditional.condition().map(|c| c.kind()), Some(PAREN_EXPR));
        assert_eq!(conditional.branches().count(), 1);
        assert!(!conditional.is_inline());
        let object = file.syntax().descendants().find_map(Object::cast).unwrap();
        assert_eq!(object.keyword().map(|k| k.kind()), Some(OBJECT_KW));
        assert_eq!(
            object.reference().and_then(|r| r.text()).as_deref(),
            Some("Thing")
        );
        let keywords: Vec<_> = file
            .syntax()
            .descendants()
            .filter_map(Block::cast)
            .filter_map(|b| b.keyword())
            .map(|k| k.text().to_string())
            .collect();
        assert_eq!(keywords, ["object", "camera", "light_source"]);
        let property = file
            .syntax()
            .descendants()
            .find_map(Property::cast)
            .unwrap();
        assert_eq!(property.keyword().map(|k| k.kind()), Some(TRANSLATE_KW));
    }

    #[test]
    fn accessors_on_broken_text_return_none() {
        let file = parse("#declare = ;\n#macro\n#include\nobject {").source_file();
        let declare = file.declarations().next().unwrap();
        assert!(declare.name().is_none() && declare.value().is_none());
        let m = file.macros().next().unwrap();
        assert!(m.name().is_none() && m.params().next().is_none());
        assert!(file.includes().next().unwrap().path().is_none());
    }
}
