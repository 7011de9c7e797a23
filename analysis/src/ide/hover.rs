//! Hover: what the thing under the cursor is. Reserved words get their one-line
//! explanation and syntax; declared names their kind and value (`#declare R = 4; // float
//! 4`); macros their signature and the comment above them; include names the file they
//! lead to.

use super::classify::{Target, classify};
use super::keyword_docs::keyword_doc;
use super::{FilePosition, NavigationTarget};
use crate::db::{self, Db, Definition, FilePath, MacroParam, Resolved, SymbolKind};
use std::fmt::Write;
use syntax::TextRange;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct HoverConfig {
    /// Markdown with fenced code, or plain text.
    pub markdown: bool,
    /// The longest declaration shown before it is cut with `…`.
    pub max_declaration_len: usize,
}

impl Default for HoverConfig {
    fn default() -> Self {
        HoverConfig {
            markdown: true,
            max_declaration_len: 120,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct HoverResult {
    pub range: TextRange,
    pub markup: String,
}

pub fn hover(db: &dyn Db, position: FilePosition, config: &HoverConfig) -> Option<HoverResult> {
    let classified = classify(db, position)?;
    let markup = match classified.target {
        Target::Keyword(kind) => {
            let doc = keyword_doc(kind.keyword_text()?)?;
            let mut out = code(config, doc.syntax);
            out.push_str("\n\n");
            out.push_str(doc.summary);
            out
        }
        Target::Symbol(definition) => symbol_markup(db, definition, position, config)?,
        Target::Include { name, resolved } => match resolved {
            Some(resolved) => format!(
                "{}\n\n{}",
                code(config, &format!("#include \"{name}\"")),
                describe_file(db, &resolved)
            ),
            None => format!(
                "{}\n\nNo such file in the scene's directory, the library paths or the standard includes.",
                code(config, &format!("#include \"{name}\""))
            ),
        },
        Target::Unresolved(_) => return None,
    };
    Some(HoverResult {
        range: classified.range,
        markup,
    })
}

fn symbol_markup(
    db: &dyn Db,
    definition: Definition,
    position: FilePosition,
    config: &HoverConfig,
) -> Option<String> {
    let symbols = db::file_symbols(db, definition.file);
    let symbol = symbols.get(definition.symbol as usize)?;
    let target = NavigationTarget::of(db, definition)?;
    let text = definition.file.text(db);
    let mut out = match &symbol.kind {
        SymbolKind::Variable { value, constant } => {
            let declaration = shorten(&text[target.full_range], config.max_declaration_len);
            let value = match constant {
                Some(constant) => format!("{} {constant}", value.describe()),
                None => value.describe().to_owned(),
            };
            code(config, &format!("{declaration} // {value}"))
        }
        SymbolKind::Macro { params } => {
            let params: Vec<String> = params.iter().map(MacroParam::label).collect();
            code(
                config,
                &format!("#macro {}({})", symbol.name, params.join(", ")),
            )
        }
        SymbolKind::Parameter => {
            let owner = symbol
                .container
                .and_then(|m| symbols.get(m as usize))
                .map_or("a macro", |m| m.name.as_str());
            format!(
                "{}\n\nparameter of macro `{owner}`",
                code(config, &symbol.name)
            )
        }
        SymbolKind::LoopVariable => {
            format!("{}\n\n`#for` loop variable", code(config, &symbol.name))
        }
    };
    if let Some(doc) = &symbol.doc {
        let _ = write!(out, "\n\n{doc}");
    }
    if definition.file != position.file {
        let _ = write!(
            out,
            "\n\n{}",
            describe_file(db, &Resolved::File(definition.file))
        );
    }
    Some(out)
}

fn describe_file(db: &dyn Db, resolved: &Resolved) -> String {
    match resolved.path(db) {
        FilePath::Disk(path) => format!("from `{}`", path.display()),
        FilePath::Bundled(name) => {
            format!("from `{name}`, a standard include bundled with Povrayst")
        }
        FilePath::Embedded { index, .. } => {
            format!("from povray block {} of this document", index + 1)
        }
    }
}

fn code(config: &HoverConfig, text: &str) -> String {
    if config.markdown {
        format!("```povray\n{text}\n```")
    } else {
        text.to_owned()
    }
}

/// A declaration on one line, cut at `max` characters.
fn shorten(text: &str, max: usize) -> String {
    let one_line: String = text.split_whitespace().collect::<Vec<_>>().join(" ");
    if one_line.chars().count() <= max {
        return one_line;
    }
    let cut: String = one_line.chars().take(max).collect();
    format!("{cut}…")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::{Expect, expect};

    #[track_caller]
    fn check(fixture: &str, expect: Expect) {
        let f = Fixture::parse(fixture);
        let config = HoverConfig {
            markdown: false,
            ..HoverConfig::default()
        };
        let shown = hover(&f.db, f.position(), &config).map_or_else(
            || "no hover".to_owned(),
            |h| format!("{}\n{}", f.show(f.position().file, h.range), h.markup),
        );
        expect.assert_eq(&shown);
    }

    #[test]
    fn reserved_words_explain_themselves() {
        check(
            "sph$0ere { 0, 1 }",
            expect![[r#"
                /main.pov 1:1 "sphere"
                sphere { CENTER, RADIUS }

                A sphere."#]],
        );
        check(
            "#declare L = vlen$0gth(<1, 2, 2>);",
            expect![[r#"
                /main.pov 1:14 "vlength"
                vlength(V)

                The length of a vector."#]],
        );
    }

    #[test]
    fn declarations_show_their_kind_and_value() {
        check(
            "#declare R = 2 * 2;\nsphere { 0, $0R }",
            expect![[r#"
                /main.pov 2:13 "R"
                #declare R = 2 * 2; // float 4"#]],
        );
        check(
            "// The ground's texture.\n#declare T =\n  texture { pigment { rgb 1 } }\nplane { y, 0 texture { $0T } }",
            expect![[r#"
                /main.pov 4:24 "T"
                #declare T = texture { pigment { rgb 1 } } // texture

                The ground's texture."#]],
        );
    }

    #[test]
    fn macros_show_their_signature_and_comment() {
        check(
            "/* Makes a ball\n   of radius R. */\n#macro Ball(R, optional C)\n  sphere { 0, R }\n#end\nobject { $0Ball(1) }",
            expect![[r#"
                /main.pov 6:10 "Ball"
                #macro Ball(R, optional C)

                Makes a ball
                of radius R."#]],
        );
    }

    #[test]
    fn names_from_includes_say_where_they_come_from() {
        check(
            "//- /scene.pov
#include \"lib.inc\"
pigment { $0Tint }
//- /lib.inc
#declare Tint = rgb <1, 0, 0>;
",
            expect![[r#"
                /scene.pov 2:11 "Tint"
                #declare Tint = rgb <1, 0, 0>; // color

                from `/fixture/lib.inc`"#]],
        );
        check(
            "#include \"no$0where.inc\"",
            expect![[r#"
                /main.pov 1:10 "\"nowhere.inc\""
                #include "nowhere.inc"

                No such file in the scene's directory, the library paths or the standard includes."#]],
        );
    }

    #[test]
    fn in_a_typst_block() {
        check(
            "//- /doc.typ\n```povray\n#declare R = 1;\nsphere { 0, $0R }\n```\n",
            expect![[r#"
                /doc.typ 3:13 "R"
                #declare R = 1; // float 1"#]],
        );
    }
}
