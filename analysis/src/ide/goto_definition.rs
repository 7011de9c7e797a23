//! Go to definition: from a use of a name to its `#declare`, `#local`, `#macro`, macro
//! parameter or `#for` variable, in this file, an include file or a bundled standard
//! include; from an `#include` file name to the file.

use super::classify::{Target, classify};
use super::{FilePosition, NavigationTarget};
use crate::db::{Db, Resolved};
use syntax::TextRange;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GotoDefinitionConfig {
    /// Whether an `#include` file name leads to the file.
    pub include_files: bool,
}

impl Default for GotoDefinitionConfig {
    fn default() -> Self {
        GotoDefinitionConfig {
            include_files: true,
        }
    }
}

pub fn goto_definition(
    db: &dyn Db,
    position: FilePosition,
    config: &GotoDefinitionConfig,
) -> Vec<NavigationTarget> {
    let Some(classified) = classify(db, position) else {
        return Vec::new();
    };
    match classified.target {
        Target::Symbol(definition) => NavigationTarget::of(db, definition).into_iter().collect(),
        Target::Include {
            name,
            resolved: Some(Resolved::File(file)),
        } if config.include_files => vec![NavigationTarget {
            file,
            full_range: TextRange::up_to(syntax::TextSize::of(&**file.text(db))),
            focus_range: TextRange::default(),
            name,
        }],
        _ => Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::{Expect, expect};

    #[track_caller]
    fn check(fixture: &str, expect: Expect) {
        let f = Fixture::parse(fixture);
        let targets: Vec<String> =
            goto_definition(&f.db, f.position(), &GotoDefinitionConfig::default())
                .into_iter()
                .map(|t| {
                    format!(
                        "{} in {}",
                        f.show(t.file, t.focus_range),
                        f.show(t.file, t.full_range)
                    )
                })
                .collect();
        expect.assert_debug_eq(&targets);
    }

    #[test]
    fn declarations_macros_and_parameters() {
        check(
            "#declare R = 1;\nsphere { 0, $0R }",
            expect![[r##"
                [
                    "/main.pov 1:10 \"R\" in /main.pov 1:1 \"#declare R = 1;\"",
                ]
            "##]],
        );
        check(
            "#macro Ball(P) sphere { $0P, 1 } #end",
            expect![[r#"
                [
                    "/main.pov 1:13 \"P\" in /main.pov 1:13 \"P\"",
                ]
            "#]],
        );
        check(
            "#macro Ball(P) sphere { P, 1 } #end\nobject { Ba$0ll(0) }",
            expect![[r##"
                [
                    "/main.pov 1:8 \"Ball\" in /main.pov 1:1 \"#macro Ball(P) sphere { P, 1 } #end\"",
                ]
            "##]],
        );
        check(
            "#for (I, 0, 3) box { $0I, 1 } #end",
            expect![[r##"
                [
                    "/main.pov 1:7 \"I\" in /main.pov 1:1 \"#for (I, 0, 3) box { I, 1 } #end\"",
                ]
            "##]],
        );
    }

    #[test]
    fn across_includes_and_into_bundled_files() {
        check(
            r#"
            //- /scene.pov
            #include "lib.inc"
            object { Ball$0() }
            //- /lib.inc
            #macro Ball() sphere { 0, 1 } #end
            "#,
            expect![[r##"
                [
                    "/lib.inc 1:8 \"Ball\" in /lib.inc 1:1 \"#macro Ball() sphere { 0, 1 } #end\"",
                ]
            "##]],
        );
        check(
            "//- /scene.pov
#include \"li$0b.inc\"
//- /lib.inc
#declare A = 1;
",
            expect![[r##"
                [
                    "/lib.inc 1:1 \"\" in /lib.inc 1:1 \"#declare A = 1;…\"",
                ]
            "##]],
        );
    }

    #[test]
    fn in_a_typst_block() {
        check(
            "//- /doc.typ\n```povray\n#declare R = 1;\nsphere { 0, $0R }\n```\n",
            expect![[r##"
                [
                    "/doc.typ 2:10 \"R\" in /doc.typ 2:1 \"#declare R = 1;\"",
                ]
            "##]],
        );
    }
}
