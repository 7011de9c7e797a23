//! Document links: every `#include` file name links to the file it leads to, in the
//! scene's directory, a library path or the bundled standard includes.

use crate::db::{self, Db, File, Resolved};
use syntax::TextRange;

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct DocumentLinksConfig {
    /// Whether names that lead nowhere are listed too (with no target), for editors that
    /// underline them.
    pub unresolved: bool,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DocumentLink {
    /// The string literal, quotes included.
    pub range: TextRange,
    pub target: Option<Resolved>,
}

pub fn document_links(db: &dyn Db, file: File, config: &DocumentLinksConfig) -> Vec<DocumentLink> {
    db::parse(db, file)
        .source_file()
        .includes()
        .filter_map(|include| {
            let token = include.path_token()?;
            let name = include.path()?;
            let target = db::resolve_include(db, file, &name);
            (target.is_some() || config.unresolved).then(|| DocumentLink {
                range: token.text_range(),
                target,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::expect;

    #[test]
    fn include_names_link_to_their_files() {
        let f = Fixture::parse(
            r#"
            //- /scene.pov
            #include "lib.inc"
            #include "colors.inc"
            #include "missing.inc"
            //- /lib.inc
            #declare A = 1;
            "#,
        );
        let config = DocumentLinksConfig { unresolved: true };
        let links: Vec<String> = document_links(&f.db, f.file("/scene.pov"), &config)
            .into_iter()
            .map(|link| {
                let target = match link.target {
                    Some(Resolved::File(file)) => f.name_of(file),
                    other => format!("{other:?}"),
                };
                format!("{} -> {target}", f.show(f.file("/scene.pov"), link.range))
            })
            .collect();
        expect![[r#"
            [
                "/scene.pov 1:10 \"\\\"lib.inc\\\"\" -> /lib.inc",
                "/scene.pov 2:10 \"\\\"colors.inc\\\"\" -> bundled:colors.inc",
                "/scene.pov 3:10 \"\\\"missing.inc\\\"\" -> None",
            ]
        "#]]
        .assert_debug_eq(&links);
    }
}
