//! Workspace symbols: the declarations and macros of every file the database holds whose
//! name matches a query, as the editor's "go to symbol in workspace" lists them.

use super::NavigationTarget;
use crate::db::{self, Db, Definition, File, FilePath, SymbolKind};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WorkspaceSymbolsConfig {
    /// Whether the bundled standard includes are searched too.
    pub include_bundled: bool,
    /// The most symbols returned.
    pub limit: usize,
}

impl Default for WorkspaceSymbolsConfig {
    fn default() -> Self {
        WorkspaceSymbolsConfig {
            include_bundled: true,
            limit: 256,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct WorkspaceSymbol {
    pub target: NavigationTarget,
    pub is_macro: bool,
    /// The file's name, to tell equal names apart.
    pub container: String,
}

/// Symbols whose name holds the query's characters in order, ignoring case; the ones that
/// start with the query first. Parameters, loop variables and `#local`s inside macros are
/// left out.
pub fn workspace_symbols(
    db: &dyn Db,
    files: &[File],
    query: &str,
    config: &WorkspaceSymbolsConfig,
) -> Vec<WorkspaceSymbol> {
    let query = query.to_lowercase();
    let mut found: Vec<(bool, WorkspaceSymbol)> = Vec::new();
    for &file in files {
        let path = file.path(db);
        if matches!(path, FilePath::Bundled(_)) && !config.include_bundled {
            continue;
        }
        for (index, symbol) in db::file_symbols(db, file).iter().enumerate() {
            let listed = match symbol.kind {
                SymbolKind::Variable { .. } => symbol.container.is_none() || !symbol.local,
                SymbolKind::Macro { .. } => true,
                SymbolKind::Parameter | SymbolKind::LoopVariable => false,
            };
            let name = symbol.name.to_lowercase();
            if !listed || !is_subsequence(&query, &name) {
                continue;
            }
            let definition = Definition {
                file,
                symbol: index as u32,
            };
            if let Some(target) = NavigationTarget::of(db, definition) {
                found.push((
                    !name.starts_with(&query),
                    WorkspaceSymbol {
                        target,
                        is_macro: matches!(symbol.kind, SymbolKind::Macro { .. }),
                        container: container_name(path),
                    },
                ));
            }
        }
    }
    found.sort_by(|(a, x), (b, y)| a.cmp(b).then_with(|| x.target.name.cmp(&y.target.name)));
    found
        .into_iter()
        .take(config.limit)
        .map(|(_, symbol)| symbol)
        .collect()
}

fn container_name(path: &FilePath) -> String {
    match path {
        FilePath::Disk(path) => path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into_owned(),
        ),
        FilePath::Bundled(name) => (*name).to_owned(),
        FilePath::Embedded { document, index } => format!(
            "{} block {}",
            document
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default(),
            index + 1
        ),
    }
}

fn is_subsequence(query: &str, name: &str) -> bool {
    let mut name = name.chars();
    query.chars().all(|q| name.any(|c| c == q))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::expect;

    #[test]
    fn matching_names_across_files_prefixes_first() {
        let f = Fixture::parse(
            r#"
            //- /scene.pov
            #declare BallSize = 1;
            #macro Ball(Size) sphere { 0, Size } #end
            //- /lib.inc
            #declare BigAmbientLight = 1;
            #declare BlackBall = 3;
            //- /doc.typ
            ```povray
            #declare BlueBall = 2;
            ```
            "#,
        );
        let files: Vec<File> = f.files.iter().map(|(_, file)| *file).collect();
        let config = WorkspaceSymbolsConfig::default();
        let found: Vec<String> = workspace_symbols(&f.db, &files, "ball", &config)
            .iter()
            .map(|s| {
                format!(
                    "{} {} ({})",
                    f.show(s.target.file, s.target.focus_range),
                    if s.is_macro { "macro" } else { "value" },
                    s.container
                )
            })
            .collect();
        expect![[r#"
            [
                "/scene.pov 2:8 \"Ball\" macro (scene.pov)",
                "/scene.pov 1:10 \"BallSize\" value (scene.pov)",
                "/lib.inc 2:10 \"BlackBall\" value (lib.inc)",
                "/doc.typ 2:10 \"BlueBall\" value (doc.typ block 1)",
            ]
        "#]]
        .assert_debug_eq(&found);
    }
}
