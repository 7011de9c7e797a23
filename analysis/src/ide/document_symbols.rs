//! Document symbols, the outline of a file: its declarations, macros (with their
//! parameters and locals), camera, lights and top-level objects, looking through `#if`,
//! `#while` and the other directives that hold them.

use crate::db::{self, Db, File, SymbolKind as DbSymbolKind};
use syntax::SyntaxKind::{self, *};
use syntax::ast::{self, AstNode};
use syntax::{SyntaxNode, TextRange};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DocumentSymbolsConfig {
    /// Whether a macro lists its parameters and `#local`s.
    pub macro_members: bool,
}

impl Default for DocumentSymbolsConfig {
    fn default() -> Self {
        DocumentSymbolsConfig {
            macro_members: true,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OutlineKind {
    Variable,
    Macro,
    Parameter,
    Camera,
    Light,
    Object,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DocumentSymbol {
    pub name: String,
    /// The kind of a declared value, or the object's keyword.
    pub detail: Option<String>,
    pub kind: OutlineKind,
    pub full_range: TextRange,
    pub focus_range: TextRange,
    pub children: Vec<DocumentSymbol>,
}

pub fn document_symbols(
    db: &dyn Db,
    file: File,
    config: &DocumentSymbolsConfig,
) -> Vec<DocumentSymbol> {
    let root = db::parse(db, file).syntax_node();
    let mut out = Vec::new();
    items(db, file, &root, config, &mut out);
    out
}

/// The outline entries among a node's children, looking through directives.
fn items(
    db: &dyn Db,
    file: File,
    node: &SyntaxNode,
    config: &DocumentSymbolsConfig,
    out: &mut Vec<DocumentSymbol>,
) {
    for child in node.children() {
        match child.kind() {
            DECLARE => out.extend(declaration(db, file, &child)),
            MACRO => out.extend(macro_symbol(db, file, &child, config)),
            CAMERA => out.push(keyword_symbol(&child, OutlineKind::Camera)),
            LIGHT_SOURCE => out.push(keyword_symbol(&child, OutlineKind::Light)),
            OBJECT => out.push(object_symbol(&child)),
            IF | WHILE | FOR | SWITCH | BRANCH | DIRECTIVE_BODY => {
                items(db, file, &child, config, out)
            }
            _ => {}
        }
    }
}

fn declaration(db: &dyn Db, file: File, node: &SyntaxNode) -> Option<DocumentSymbol> {
    let declare = ast::Declare::cast(node.clone())?;
    let name = declare.name()?;
    let token = name.token()?;
    let detail = symbol_at(db, file, token.text_range()).and_then(|kind| match kind {
        DbSymbolKind::Variable { value, .. } => Some(value.describe().to_owned()),
        _ => None,
    });
    Some(DocumentSymbol {
        name: token.text().to_owned(),
        detail,
        kind: OutlineKind::Variable,
        full_range: node.text_range(),
        focus_range: token.text_range(),
        children: Vec::new(),
    })
}

fn macro_symbol(
    db: &dyn Db,
    file: File,
    node: &SyntaxNode,
    config: &DocumentSymbolsConfig,
) -> Option<DocumentSymbol> {
    let definition = ast::Macro::cast(node.clone())?;
    let token = definition.name()?.token()?;
    let mut children = Vec::new();
    if config.macro_members {
        for param in definition.params() {
            if let Some(name) = param.name().and_then(|n| n.token()) {
                children.push(DocumentSymbol {
                    name: name.text().to_owned(),
                    detail: param.is_optional().then(|| "optional".to_owned()),
                    kind: OutlineKind::Parameter,
                    full_range: param.syntax().text_range(),
                    focus_range: name.text_range(),
                    children: Vec::new(),
                });
            }
        }
        if let Some(body) = definition.body() {
            items(db, file, body.syntax(), config, &mut children);
        }
    }
    Some(DocumentSymbol {
        name: token.text().to_owned(),
        detail: None,
        kind: OutlineKind::Macro,
        full_range: node.text_range(),
        focus_range: token.text_range(),
        children,
    })
}

fn keyword_symbol(node: &SyntaxNode, kind: OutlineKind) -> DocumentSymbol {
    let keyword = first_keyword(node);
    DocumentSymbol {
        name: keyword
            .map_or("?", |(k, _)| k.keyword_text().unwrap_or("?"))
            .to_owned(),
        detail: None,
        kind,
        full_range: node.text_range(),
        focus_range: keyword.map_or(node.text_range(), |(_, range)| range),
        children: Vec::new(),
    }
}

fn object_symbol(node: &SyntaxNode) -> DocumentSymbol {
    let mut symbol = keyword_symbol(node, OutlineKind::Object);
    if symbol.name != "object" {
        return symbol;
    }
    if let Some(reference) = ast::Object::cast(node.clone())
        .and_then(|o| o.reference())
        .and_then(|r| r.text())
    {
        symbol.detail = Some(reference);
    }
    symbol
}

fn first_keyword(node: &SyntaxNode) -> Option<(SyntaxKind, TextRange)> {
    node.children_with_tokens()
        .filter_map(|e| e.into_token())
        .find(|t| t.kind().is_keyword())
        .map(|t| (t.kind(), t.text_range()))
}

/// The kind of the symbol whose name is at `range`.
fn symbol_at(db: &dyn Db, file: File, range: TextRange) -> Option<DbSymbolKind> {
    let ranges = db::name_ranges(db, file);
    let index = ranges.iter().position(|r| *r == range)? as u32;
    db::file_symbols(db, file)
        .iter()
        .find(|s| s.name_index == index)
        .map(|s| s.kind.clone())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::{Expect, expect};

    fn render(f: &Fixture, file: File, symbols: &[DocumentSymbol], depth: usize, out: &mut String) {
        for symbol in symbols {
            let detail = symbol
                .detail
                .as_deref()
                .map(|d| format!(" ({d})"))
                .unwrap_or_default();
            out.push_str(&format!(
                "{}{:?} {}{detail} at {}\n",
                "  ".repeat(depth),
                symbol.kind,
                symbol.name,
                f.show(file, symbol.focus_range)
            ));
            render(f, file, &symbol.children, depth + 1, out);
        }
    }

    #[track_caller]
    fn check(fixture: &str, expect: Expect) {
        let f = Fixture::parse(fixture);
        let file = f.files[0].1;
        let mut out = String::new();
        render(
            &f,
            file,
            &document_symbols(&f.db, file, &DocumentSymbolsConfig::default()),
            0,
            &mut out,
        );
        expect.assert_eq(&out);
    }

    #[test]
    fn the_outline_of_a_scene() {
        check(
            r#"
            #include "colors.inc"
            #declare R = 1;
            #declare Floor = plane { y, 0 }
            #macro Ball(P, optional S)
              #local Q = P + 1;
              sphere { Q, R }
            #end
            camera { location <0, 1, -5> look_at 0 }
            light_source { <5, 5, -5> rgb 1 }
            #if (R > 0)
              object { Floor }
            #end
            sphere { 0, R }
            "#,
            expect![[r#"
                Variable R (float) at /main.pov 2:10 "R"
                Variable Floor (object) at /main.pov 3:10 "Floor"
                Macro Ball at /main.pov 4:8 "Ball"
                  Parameter P at /main.pov 4:13 "P"
                  Parameter S (optional) at /main.pov 4:25 "S"
                  Variable Q (value) at /main.pov 5:10 "Q"
                  Object sphere at /main.pov 6:3 "sphere"
                Camera camera at /main.pov 8:1 "camera"
                Light light_source at /main.pov 9:1 "light_source"
                Object object (Floor) at /main.pov 11:3 "object"
                Object sphere at /main.pov 13:1 "sphere"
            "#]],
        );
    }
}
