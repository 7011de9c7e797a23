//! Diagnostics beyond the check: the check itself ([`crate::db::check_file`]) gives
//! exactly what `povrayst check` prints, and these lints only add hints an editor shows
//! faded or struck through: declarations nothing uses, and legacy syntax that newer
//! POV-Ray versions replaced.

use crate::db::{self, Db, File, FilePath, SymbolKind};
use syntax::SyntaxKind::{self, *};
use syntax::TextRange;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DiagnosticsConfig {
    /// Whether declarations nothing uses are reported.
    pub unused: bool,
    /// Whether legacy syntax is reported.
    pub legacy: bool,
}

impl Default for DiagnosticsConfig {
    fn default() -> Self {
        DiagnosticsConfig {
            unused: true,
            legacy: true,
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LintKind {
    Unused,
    Legacy,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Lint {
    pub range: TextRange,
    pub kind: LintKind,
    pub message: String,
}

/// Reserved words kept for old scenes, and what replaced them.
const LEGACY: &[(SyntaxKind, &str)] = &[
    (COMPOSITE_KW, "`composite` is legacy syntax; use `union`"),
    (
        TILES_KW,
        "`tiles` is legacy syntax; use a `checker` texture_map",
    ),
    (
        MATERIAL_MAP_KW,
        "`material_map` is legacy syntax; use a texture_map with `image_pattern`",
    ),
    (
        MAX_INTERSECTIONS_KW,
        "`max_intersections` has had no effect since POV-Ray 3.5",
    ),
    (
        COMPONENT_KW,
        "`component` is legacy blob syntax; use `sphere` and `cylinder` components",
    ),
];

pub fn lints(db: &dyn Db, file: File, config: &DiagnosticsConfig) -> Vec<Lint> {
    let mut found = Vec::new();
    if config.unused {
        unused_declarations(db, file, &mut found);
    }
    if config.legacy {
        let root = db::parse(db, file).syntax_node();
        for token in root
            .descendants_with_tokens()
            .filter_map(|e| e.into_token())
        {
            if let Some((_, message)) = LEGACY.iter().find(|(kind, _)| *kind == token.kind()) {
                found.push(Lint {
                    range: token.text_range(),
                    kind: LintKind::Legacy,
                    message: (*message).to_owned(),
                });
            }
        }
    }
    found.sort_by_key(|lint| lint.range.start());
    found
}

/// Declarations that no name in the file refers to. An include file's `#declare`s are
/// meant for the scenes that include it, so there only `#local`s count.
fn unused_declarations(db: &dyn Db, file: File, found: &mut Vec<Lint>) {
    let library = match file.path(db) {
        FilePath::Disk(path) => path.extension().is_some_and(|e| e != "pov"),
        FilePath::Bundled(_) => return,
        FilePath::Embedded { .. } => false,
    };
    let symbols = db::file_symbols(db, file);
    let ranges = db::name_ranges(db, file);
    let mut uses = vec![0usize; symbols.len()];
    for definition in db::resolve_file(db, file).iter().flatten() {
        if definition.file == file {
            uses[definition.symbol as usize] += 1;
        }
    }
    for (index, symbol) in symbols.iter().enumerate() {
        let counts =
            matches!(symbol.kind, SymbolKind::Variable { .. }) && (symbol.local || !library);
        // One use is the defining name itself.
        if counts && uses[index] <= 1 {
            let directive = if symbol.local { "#local" } else { "#declare" };
            found.push(Lint {
                range: ranges[symbol.name_index as usize],
                kind: LintKind::Unused,
                message: format!(
                    "'{}' is declared with {directive} but never used",
                    symbol.name
                ),
            });
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::expect;

    #[test]
    fn unused_declarations_and_legacy_syntax() {
        let f = Fixture::parse(
            r#"
            //- /scene.pov
            #declare Used = 1;
            #declare Unused = 2;
            #macro M(P) #local Scratch = P; P #end
            composite { sphere { 0, Used } }
            //- /lib.inc
            #declare ForScenes = 1;
            #local Helper = 2;
            "#,
        );
        let mut shown = Vec::new();
        for name in ["/scene.pov", "/lib.inc"] {
            let file = f.file(name);
            for lint in lints(&f.db, file, &DiagnosticsConfig::default()) {
                shown.push(format!(
                    "{} {:?}: {}",
                    f.show(file, lint.range),
                    lint.kind,
                    lint.message
                ));
            }
        }
        expect![[r#"
            [
                "/scene.pov 2:10 \"Unused\" Unused: 'Unused' is declared with #declare but never used",
                "/scene.pov 3:20 \"Scratch\" Unused: 'Scratch' is declared with #local but never used",
                "/scene.pov 4:1 \"composite\" Legacy: `composite` is legacy syntax; use `union`",
                "/lib.inc 2:8 \"Helper\" Unused: 'Helper' is declared with #local but never used",
            ]
        "#]]
        .assert_debug_eq(&shown);
    }
}
