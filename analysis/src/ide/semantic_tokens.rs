//! Semantic tokens: what each token of a file is, for highlighting that knows more than a
//! grammar can: a name is a macro, a parameter or a variable by what it resolves to, and a
//! definition from a bundled include is marked as the standard library's.

use super::keyword_docs::keyword_doc;
use crate::db::{self, Db, File, FilePath, SymbolKind};
use syntax::SyntaxKind::{self, *};
use syntax::TextRange;

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct SemanticTokensConfig {
    /// Whether operators and punctuation get tokens too.
    pub operators: bool,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum HighlightTag {
    Comment,
    String,
    Number,
    Keyword,
    /// A directive: `#` and its keyword.
    Directive,
    /// A built-in function such as `vlength`.
    Function,
    /// A built-in constant such as `pi`, `x` or `clock`.
    Constant,
    Variable,
    Macro,
    Parameter,
    Operator,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Highlight {
    pub range: TextRange,
    pub tag: HighlightTag,
    /// The defining occurrence of a name.
    pub definition: bool,
    /// A name defined in a bundled standard include.
    pub library: bool,
}

/// Built-in values that stand alone in expressions.
const CONSTANTS: &[SyntaxKind] = &[
    PI_KW,
    TAU_KW,
    TRUE_KW,
    FALSE_KW,
    YES_KW,
    NO_KW,
    ON_KW,
    OFF_KW,
    X_KW,
    Y_KW,
    Z_KW,
    T_KW,
    U_KW,
    V_KW,
    CLOCK_KW,
    CLOCK_DELTA_KW,
    CLOCK_ON_KW,
    FINAL_CLOCK_KW,
    FINAL_FRAME_KW,
    FRAME_NUMBER_KW,
    IMAGE_HEIGHT_KW,
    IMAGE_WIDTH_KW,
    INITIAL_CLOCK_KW,
    INITIAL_FRAME_KW,
    INPUT_FILE_NAME_KW,
    NOW_KW,
];

pub fn semantic_tokens(db: &dyn Db, file: File, config: &SemanticTokensConfig) -> Vec<Highlight> {
    let root = db::parse(db, file).syntax_node();
    let resolved = db::resolve_file(db, file);
    let mut identifier = 0usize;
    let mut after_hash = false;
    let mut out = Vec::new();
    for token in root
        .descendants_with_tokens()
        .filter_map(|e| e.into_token())
    {
        let kind = token.kind();
        let mut highlight = Highlight {
            range: token.text_range(),
            tag: HighlightTag::Keyword,
            definition: false,
            library: false,
        };
        let tag = match kind {
            LINE_COMMENT | BLOCK_COMMENT => Some(HighlightTag::Comment),
            STRING => Some(HighlightTag::String),
            NUMBER => Some(HighlightTag::Number),
            HASH => Some(HighlightTag::Directive),
            IDENT => {
                let definition = resolved.get(identifier).copied().flatten();
                identifier += 1;
                highlight.definition = token.parent().is_some_and(|p| p.kind() == NAME);
                Some(match definition {
                    Some(definition) => {
                        let symbol =
                            &db::file_symbols(db, definition.file)[definition.symbol as usize];
                        highlight.library =
                            matches!(definition.file.path(db), FilePath::Bundled(_));
                        match symbol.kind {
                            SymbolKind::Macro { .. } => HighlightTag::Macro,
                            SymbolKind::Parameter => HighlightTag::Parameter,
                            _ => HighlightTag::Variable,
                        }
                    }
                    None => HighlightTag::Variable,
                })
            }
            _ if kind.is_keyword() => Some(if after_hash {
                HighlightTag::Directive
            } else if CONSTANTS.contains(&kind) {
                HighlightTag::Constant
            } else if is_function(kind) {
                HighlightTag::Function
            } else {
                HighlightTag::Keyword
            }),
            WHITESPACE | BYTE_ORDER_MARK | ERROR => None,
            _ => config.operators.then_some(HighlightTag::Operator),
        };
        if !kind.is_trivia() {
            after_hash = kind == HASH;
        }
        if let Some(tag) = tag {
            highlight.tag = tag;
            out.push(highlight);
        }
    }
    out
}

/// Whether a reserved word is called like a function: its syntax is `word(...)`.
fn is_function(kind: SyntaxKind) -> bool {
    let Some(word) = kind.keyword_text() else {
        return false;
    };
    keyword_doc(word).is_some_and(|doc| doc.syntax.starts_with(&format!("{word}(")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::expect;

    #[test]
    fn names_are_highlighted_by_what_they_resolve_to() {
        let f = Fixture::parse(
            "#include \"colors.inc\"\n#macro M(P) P * pi #end\n#declare A = vlength(x) + M(1); // c\npigment { Red }\n",
        );
        let file = f.files[0].1;
        let shown: Vec<String> = semantic_tokens(&f.db, file, &SemanticTokensConfig::default())
            .iter()
            .map(|h| {
                let text = &file.text(&f.db)[h.range];
                let flags = format!(
                    "{}{}",
                    if h.definition { " definition" } else { "" },
                    if h.library { " library" } else { "" }
                );
                format!("{text} {:?}{flags}", h.tag)
            })
            .collect();
        expect![[r##"
            [
                "# Directive",
                "include Directive",
                "\"colors.inc\" String",
                "# Directive",
                "macro Directive",
                "M Macro definition",
                "P Parameter definition",
                "P Parameter",
                "pi Constant",
                "# Directive",
                "end Directive",
                "# Directive",
                "declare Directive",
                "A Variable definition",
                "vlength Function",
                "x Constant",
                "M Macro",
                "1 Number",
                "// c Comment",
                "pigment Keyword",
                "Red Variable library",
            ]
        "##]]
        .assert_debug_eq(&shown);
    }
}
