//! Inlay hints: the parameter names of a macro before the arguments of its calls, so that
//! `Ball(<0, 1, 0>, 2)` reads `Ball(Center: <0, 1, 0>, Radius: 2)`. An argument that is
//! already a name equal to its parameter gets none.

use crate::db::{self, Db, File, SymbolKind};
use std::collections::HashMap;
use syntax::SyntaxKind::*;
use syntax::ast::{self, AstNode};
use syntax::{TextRange, TextSize};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct InlayHintsConfig {
    /// Whether calls of macros get parameter names.
    pub parameter_names: bool,
}

impl Default for InlayHintsConfig {
    fn default() -> Self {
        InlayHintsConfig {
            parameter_names: true,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct InlayHint {
    /// Where the hint is shown: before the argument.
    pub offset: TextSize,
    pub label: String,
}

/// The hints for calls inside `range` of `file`.
pub fn inlay_hints(
    db: &dyn Db,
    file: File,
    range: TextRange,
    config: &InlayHintsConfig,
) -> Vec<InlayHint> {
    if !config.parameter_names {
        return Vec::new();
    }
    let root = db::parse(db, file).syntax_node();
    let resolved = db::resolve_file(db, file);
    let index: HashMap<TextRange, usize> = db::identifiers(&root)
        .enumerate()
        .map(|(i, token)| (token.text_range(), i))
        .collect();
    let mut hints = Vec::new();
    for call in root.descendants().filter_map(ast::Call::cast) {
        if call.syntax().text_range().intersect(range).is_none() {
            continue;
        }
        let Some(callee) = call.name_ref().and_then(|n| n.ident()) else {
            continue;
        };
        let Some(definition) = index
            .get(&callee.text_range())
            .and_then(|&i| resolved.get(i).copied().flatten())
        else {
            continue;
        };
        let SymbolKind::Macro { params } =
            &db::file_symbols(db, definition.file)[definition.symbol as usize].kind
        else {
            continue;
        };
        let Some(args) = call.arg_list() else {
            continue;
        };
        // Arguments by position: commas count, so `M(1, , 3)` leaves the second empty.
        let mut position = 0usize;
        let mut hinted = false;
        for element in args.syntax().children_with_tokens() {
            if element.kind() == COMMA {
                position += 1;
                hinted = false;
                continue;
            }
            match element.into_node() {
                Some(node) if !hinted => {
                    hinted = true;
                    let Some(param) = params.get(position) else {
                        continue;
                    };
                    if node.text() == param.name.as_str() {
                        continue;
                    }
                    hints.push(InlayHint {
                        offset: node.text_range().start(),
                        label: format!("{}:", param.name),
                    });
                }
                _ => {}
            }
        }
    }
    hints
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::expect;

    #[test]
    fn macro_arguments_get_their_parameter_names() {
        let f = Fixture::parse(
            "#macro Ball(Center, Radius, optional Colour) sphere { Center, Radius } #end\n#declare Radius = 1;\nobject { Ball(<0, 1, 0>, Radius) }\nobject { Ball(0, , 2) }\n#declare L = vlength(x);\n",
        );
        let file = f.files[0].1;
        let all = TextRange::up_to(TextSize::of(&**file.text(&f.db)));
        let hints: Vec<String> = inlay_hints(&f.db, file, all, &InlayHintsConfig::default())
            .into_iter()
            .map(|h| {
                format!(
                    "{} before {}",
                    h.label,
                    f.show(file, TextRange::empty(h.offset))
                )
            })
            .collect();
        expect![[r#"
            [
                "Center: before /main.pov 3:15 \"\"",
                "Center: before /main.pov 4:15 \"\"",
                "Colour: before /main.pov 4:20 \"\"",
            ]
        "#]]
        .assert_debug_eq(&hints);
    }
}
