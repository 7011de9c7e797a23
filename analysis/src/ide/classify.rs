//! What is under the cursor, decided once so that hover, go to definition, references and
//! rename agree: a name (defined here or used), a reserved word, or an include file name.

use super::FilePosition;
use crate::db::{self, Db, Definition, Resolved};
use syntax::SyntaxKind::{self, *};
use syntax::{SyntaxNode, SyntaxToken, TextRange, TextSize};

/// The thing a cursor is on.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Target {
    /// A name with a definition in sight.
    Symbol(Definition),
    /// A name with none, such as a typo or something declared by the evaluator.
    Unresolved(String),
    /// A reserved word: a keyword, a built-in function or constant.
    Keyword(SyntaxKind),
    /// The file name of an `#include`.
    Include {
        name: String,
        resolved: Option<Resolved>,
    },
}

/// A classified token and its range.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Classified {
    pub range: TextRange,
    pub target: Target,
    /// Whether the token is the defining occurrence of the name.
    pub is_definition: bool,
}

pub fn classify(db: &dyn Db, position: FilePosition) -> Option<Classified> {
    let root = db::parse(db, position.file).syntax_node();
    let token = token_at(&root, position.offset)?;
    let range = token.text_range();
    let kind = token.kind();
    if kind == IDENT {
        let index = db::identifiers(&root).position(|t| t == token)?;
        let definition = db::resolve_file(db, position.file)
            .get(index)
            .copied()
            .flatten();
        let is_definition = token.parent().is_some_and(|p| p.kind() == NAME);
        let target = match definition {
            Some(definition) => Target::Symbol(definition),
            None => Target::Unresolved(token.text().to_owned()),
        };
        return Some(Classified {
            range,
            target,
            is_definition,
        });
    }
    if kind == STRING {
        let include = token.parent()?.parent().filter(|n| n.kind() == INCLUDE)?;
        let name = syntax::ast::AstNode::cast(include)
            .and_then(|include: syntax::ast::Include| include.path())?;
        let resolved = db::resolve_include(db, position.file, &name);
        return Some(Classified {
            range,
            target: Target::Include { name, resolved },
            is_definition: false,
        });
    }
    kind.is_keyword().then_some(Classified {
        range,
        target: Target::Keyword(kind),
        is_definition: false,
    })
}

/// The token a cursor at `offset` means: between two tokens, the one that names
/// something.
pub fn token_at(root: &SyntaxNode, offset: TextSize) -> Option<SyntaxToken> {
    let rank = |token: &SyntaxToken| match token.kind() {
        IDENT => 3,
        STRING => 2,
        kind if kind.is_keyword() => 2,
        kind if kind.is_trivia() => 0,
        _ => 1,
    };
    root.token_at_offset(offset)
        .max_by_key(rank)
        .filter(|token| rank(token) > 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::{Expect, expect};

    #[track_caller]
    fn check(fixture: &str, expect: Expect) {
        let f = Fixture::parse(fixture);
        let classified = classify(&f.db, f.position());
        let shown = classified.map(|c| {
            let target = match c.target {
                Target::Symbol(d) => {
                    let symbol = &db::file_symbols(&f.db, d.file)[d.symbol as usize];
                    let at = db::name_ranges(&f.db, d.file)[symbol.name_index as usize];
                    format!("symbol at {}", f.show(d.file, at))
                }
                Target::Include { name, resolved } => {
                    let resolved = resolved.map(|r| match r {
                        Resolved::File(file) => f.name_of(file),
                        other => format!("{other:?}"),
                    });
                    format!("include {name:?} -> {resolved:?}")
                }
                other => format!("{other:?}"),
            };
            format!(
                "{} -> {target}{}",
                f.show(f.position().file, c.range),
                if c.is_definition { " (definition)" } else { "" }
            )
        });
        expect.assert_eq(&shown.unwrap_or_else(|| "nothing".to_owned()));
    }

    #[test]
    fn names_resolve_to_the_last_definition_before_them() {
        check(
            "#declare A = 1;\n#declare A = 2;\nsphere { 0, $0A }\n#declare A = 3;\n",
            expect![[r#"/main.pov 3:13 "A" -> symbol at /main.pov 2:10 "A""#]],
        );
        check(
            "sphere { 0, $0A }\n#declare A = 3;\n",
            expect![[r#"/main.pov 1:13 "A" -> symbol at /main.pov 2:10 "A""#]],
        );
        check(
            "#declare $0A = 1;",
            expect![[r#"/main.pov 1:10 "A" -> symbol at /main.pov 1:10 "A" (definition)"#]],
        );
    }

    #[test]
    fn macro_parameters_and_locals_come_first() {
        check(
            "#declare X = 1;\n#macro M(X) #local Y = X; Y #end\n#macro N() $0X #end\n",
            expect![[r#"/main.pov 3:12 "X" -> symbol at /main.pov 1:10 "X""#]],
        );
        check(
            "#declare X = 1;\n#macro M(X) #local Y = $0X; Y #end\n",
            expect![[r#"/main.pov 2:24 "X" -> symbol at /main.pov 2:10 "X""#]],
        );
        check(
            "#declare Y = 1;\n#macro M(X) #local Y = X; $0Y #end\n",
            expect![[r#"/main.pov 2:27 "Y" -> symbol at /main.pov 2:20 "Y""#]],
        );
    }

    #[test]
    fn names_resolve_through_includes() {
        check(
            r#"
            //- /scene.pov
            #include "shapes.inc"
            object { $0Ball }
            //- /shapes.inc
            #declare Ball = sphere { 0, 1 }
            "#,
            expect![[r#"/scene.pov 2:10 "Ball" -> symbol at /shapes.inc 1:10 "Ball""#]],
        );
        check(
            "#include \"colors.inc\"\npigment { $0Red }",
            expect![[r#"/main.pov 2:11 "Red" -> symbol at bundled:colors.inc 18:10 "Red""#]],
        );
    }

    #[test]
    fn keywords_includes_and_unknown_names() {
        check(
            "sph$0ere { 0, 1 }",
            expect![[r#"/main.pov 1:1 "sphere" -> Keyword(SPHERE_KW)"#]],
        );
        check(
            "#include \"col$0ors.inc\"",
            expect![[
                r#"/main.pov 1:10 "\"colors.inc\"" -> include "colors.inc" -> Some("bundled:colors.inc")"#
            ]],
        );
        check(
            "sphere { 0, Rad$0ius }",
            expect![[r#"/main.pov 1:13 "Radius" -> Unresolved("Radius")"#]],
        );
        check("sphere {$0 0, 1 }", expect!["nothing"]);
        check(
            "#declare D = dictionary { .a: 1 };\n#declare E = D.$0a;",
            expect![[r#"/main.pov 2:16 "a" -> Unresolved("a")"#]],
        );
    }

    #[test]
    fn names_in_typst_blocks_resolve_inside_their_block() {
        check(
            "//- /main.typ\n= Title\n\n```povray\n#declare R = 1;\nsphere { 0, $0R }\n```\n",
            expect![[r#"/main.typ 5:13 "R" -> symbol at /main.typ 4:10 "R""#]],
        );
    }
}
