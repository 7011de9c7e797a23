//! Find references: every use of the name under the cursor that resolves to the same
//! definition, in every file the database holds, so that a `#declare` in an include file
//! finds its uses in the scenes that include it and a shadowed name finds only its own.

use super::classify::{Target, classify};
use super::{FilePosition, FileRange, NavigationTarget};
use crate::db::{self, Db, Definition};

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ReferencesConfig {
    /// Whether the defining name is listed among the references.
    pub include_declaration: bool,
}

/// The definition and the places that name it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct References {
    pub definition: NavigationTarget,
    pub references: Vec<FileRange>,
}

pub fn find_references(
    db: &dyn Db,
    position: FilePosition,
    config: &ReferencesConfig,
) -> Option<References> {
    let Target::Symbol(definition) = classify(db, position)?.target else {
        return None;
    };
    let target = NavigationTarget::of(db, definition)?;
    let references = uses(db, definition)
        .into_iter()
        .filter(|r| {
            config.include_declaration || !(r.file == target.file && r.range == target.focus_range)
        })
        .collect();
    Some(References {
        definition: target,
        references,
    })
}

/// Every identifier that names `definition`, its defining name included, file by file in
/// the project's order and in text order within a file.
pub fn uses(db: &dyn Db, definition: Definition) -> Vec<FileRange> {
    let name = &db::file_symbols(db, definition.file)[definition.symbol as usize].name;
    let project = definition.file.project(db);
    let mut found = Vec::new();
    for &file in project.files(db).values() {
        // Most files never mention the name; skip them without resolving anything.
        if !file.text(db).contains(name.as_str()) {
            continue;
        }
        let resolved = db::resolve_file(db, file);
        if !resolved.contains(&Some(definition)) {
            continue;
        }
        let root = db::parse(db, file).syntax_node();
        for (token, resolution) in db::identifiers(&root).zip(resolved) {
            if *resolution == Some(definition) {
                found.push(FileRange {
                    file,
                    range: token.text_range(),
                });
            }
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::{Expect, expect};

    #[track_caller]
    fn check(fixture: &str, expect: Expect) {
        let f = Fixture::parse(fixture);
        let config = ReferencesConfig {
            include_declaration: true,
        };
        let found: Vec<String> = find_references(&f.db, f.position(), &config)
            .map(|r| r.references)
            .unwrap_or_default()
            .into_iter()
            .map(|r| f.show(r.file, r.range))
            .collect();
        expect.assert_debug_eq(&found);
    }

    #[test]
    fn shadowed_names_are_not_references() {
        check(
            "#declare X = 1;\n#macro M(X) X + 1 #end\nsphere { $0X, M(X) }\n",
            expect![[r#"
                [
                    "/main.pov 1:10 \"X\"",
                    "/main.pov 3:10 \"X\"",
                    "/main.pov 3:15 \"X\"",
                ]
            "#]],
        );
        check(
            "#declare X = 1;\n#macro M($0X) X + 1 #end\nsphere { X, M(X) }\n",
            expect![[r#"
                [
                    "/main.pov 2:10 \"X\"",
                    "/main.pov 2:13 \"X\"",
                ]
            "#]],
        );
    }

    #[test]
    fn uses_in_files_that_include_the_definition() {
        check(
            r#"
            //- /lib.inc
            #declare $0Size = 2;
            //- /a.pov
            #include "lib.inc"
            box { 0, Size }
            //- /b.pov
            #declare Size = 3;
            box { 0, Size }
            "#,
            expect![[r#"
                [
                    "/a.pov 2:10 \"Size\"",
                    "/lib.inc 1:10 \"Size\"",
                ]
            "#]],
        );
    }

    #[test]
    fn in_a_typst_block() {
        check(
            "//- /doc.typ\n```povray\n#declare R = 1;\nsphere { 0, $0R }\n```\n\n```povray\nsphere { 0, R }\n```\n",
            expect![[r#"
                [
                    "/doc.typ 2:10 \"R\"",
                    "/doc.typ 3:13 \"R\"",
                ]
            "#]],
        );
    }
}
