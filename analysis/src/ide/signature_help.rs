//! Signature help: inside the parentheses of a macro call or a built-in function, the
//! signature and which parameter the cursor is on. Found from the tokens before the
//! cursor, since a call being typed is rarely complete.

use super::FilePosition;
use super::keyword_docs::keyword_doc;
use crate::db::{self, Db, MacroParam, SymbolKind};
use syntax::SyntaxKind::*;
use syntax::SyntaxToken;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SignatureHelpConfig {
    /// Whether the comment above a macro is shown with its signature.
    pub documentation: bool,
}

impl Default for SignatureHelpConfig {
    fn default() -> Self {
        SignatureHelpConfig {
            documentation: true,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SignatureHelp {
    /// `Ball(Center, Radius)`.
    pub label: String,
    pub parameters: Vec<String>,
    pub active_parameter: Option<u32>,
    pub documentation: Option<String>,
}

pub fn signature_help(
    db: &dyn Db,
    position: FilePosition,
    config: &SignatureHelpConfig,
) -> Option<SignatureHelp> {
    let root = db::parse(db, position.file).syntax_node();
    let tokens: Vec<SyntaxToken> = root
        .descendants_with_tokens()
        .filter_map(|e| e.into_token())
        .take_while(|t| t.text_range().end() <= position.offset)
        .filter(|t| !t.kind().is_trivia())
        .collect();
    // Back to the unmatched `(`, counting the commas at its level.
    let mut depth = 0usize;
    let mut commas = 0u32;
    let mut open = None;
    for (i, token) in tokens.iter().enumerate().rev() {
        match token.kind() {
            R_PAREN | R_BRACK | GT if token.kind() != GT || depth > 0 => depth += 1,
            L_PAREN | L_BRACK | LT if depth > 0 => depth -= 1,
            L_PAREN => {
                open = Some(i);
                break;
            }
            COMMA if depth == 0 => commas += 1,
            L_BRACE | R_BRACE | SEMICOLON => return None,
            _ => {}
        }
    }
    let callee = tokens.get(open?.checked_sub(1)?)?;
    let (label, parameters, documentation) = if callee.kind() == IDENT {
        let index = db::identifiers(&root).position(|t| t == *callee)?;
        let definition = db::resolve_file(db, position.file)
            .get(index)
            .copied()
            .flatten()?;
        let symbol = &db::file_symbols(db, definition.file)[definition.symbol as usize];
        let SymbolKind::Macro { params } = &symbol.kind else {
            return None;
        };
        let parameters: Vec<String> = params.iter().map(MacroParam::label).collect();
        let label = format!("{}({})", symbol.name, parameters.join(", "));
        (label, parameters, symbol.doc.clone())
    } else {
        let doc = keyword_doc(callee.kind().keyword_text()?)?;
        let inner = doc
            .syntax
            .strip_prefix(doc.word)?
            .strip_prefix('(')?
            .strip_suffix(')')?;
        let parameters = inner
            .split(", ")
            .filter(|p| !p.is_empty())
            .map(str::to_owned)
            .collect();
        (
            doc.syntax.to_owned(),
            parameters,
            Some(doc.summary.to_owned()),
        )
    };
    Some(SignatureHelp {
        active_parameter: Some(commas.min(parameters.len().saturating_sub(1) as u32)),
        label,
        parameters,
        documentation: documentation.filter(|_| config.documentation),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::{Expect, expect};

    #[track_caller]
    fn check(fixture: &str, expect: Expect) {
        let f = Fixture::parse(fixture);
        let shown = signature_help(&f.db, f.position(), &SignatureHelpConfig::default())
            .map_or_else(
                || "none".to_owned(),
                |help| {
                    format!(
                        "{} active {:?}: {:?}",
                        help.label, help.active_parameter, help.documentation
                    )
                },
            );
        expect.assert_eq(&shown);
    }

    #[test]
    fn macro_calls_and_built_in_functions() {
        check(
            "// Makes a ball.\n#macro Ball(Center, optional Radius) sphere { Center, 1 } #end\nobject { Ball(<0, 1, 0>, $0",
            expect![[r#"Ball(Center, optional Radius) active Some(1): Some("Makes a ball.")"#]],
        );
        check(
            "#declare A = vaxis_rotate(x, vcross(x, y)$0",
            expect![[
                r#"vaxis_rotate(V, AXIS, DEGREES) active Some(1): Some("V rotated about an axis.")"#
            ]],
        );
        check(
            "#declare A = vlength($0<1, 2, 3>);",
            expect![[r#"vlength(V) active Some(0): Some("The length of a vector.")"#]],
        );
        check("sphere { 0, 1 }$0", expect!["none"]);
    }
}
