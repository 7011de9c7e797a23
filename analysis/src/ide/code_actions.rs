//! Code actions: quick fixes for the cursor's line. Declare a name that is declared
//! nowhere, replace a misspelt name or reserved word with the nearest one in sight ("did
//! you mean"), and add the `#version` directive a scene lacks.

use super::classify::{Target, classify};
use super::{FilePosition, FileRange, SourceChange, TextEdit};
use crate::db::{self, Db};
use syntax::SyntaxKind::*;
use syntax::{TextRange, TextSize};

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CodeActionsConfig {
    /// The version `#version` is set to: the one the evaluator assumes without it.
    pub version: String,
    /// The most "did you mean" suggestions offered.
    pub max_suggestions: usize,
}

impl Default for CodeActionsConfig {
    fn default() -> Self {
        CodeActionsConfig {
            version: "3.7".to_owned(),
            max_suggestions: 3,
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CodeAction {
    pub title: String,
    pub change: SourceChange,
}

pub fn code_actions(db: &dyn Db, range: FileRange, config: &CodeActionsConfig) -> Vec<CodeAction> {
    let file = range.file;
    let mut actions = Vec::new();
    let position = FilePosition {
        file,
        offset: range.range.start(),
    };
    if let Some(classified) = classify(db, position)
        && let Target::Unresolved(name) = &classified.target
    {
        for suggestion in suggestions(db, position, name, config.max_suggestions) {
            actions.push(CodeAction {
                title: format!("Replace with `{suggestion}`"),
                change: edit(file, classified.range, suggestion),
            });
        }
        let root = db::parse(db, file).syntax_node();
        let statement = root
            .covering_element(classified.range)
            .ancestors()
            .find(|node| node.parent().is_some_and(|p| p.kind() == SOURCE_FILE))
            .map_or(TextSize::new(0), |node| node.text_range().start());
        actions.push(CodeAction {
            title: format!("Declare `{name}`"),
            change: edit(
                file,
                TextRange::empty(statement),
                format!("#declare {name} = 0;\n"),
            ),
        });
    }
    let text = file.text(db);
    let first_line_end = TextSize::new(text.find('\n').unwrap_or(text.len()) as u32);
    let has_version = db::parse(db, file)
        .syntax_node()
        .descendants()
        .any(|node| node.kind() == VERSION);
    if !has_version && range.range.start() <= first_line_end {
        actions.push(CodeAction {
            title: format!("Add `#version {};`", config.version),
            change: edit(
                file,
                TextRange::empty(TextSize::new(0)),
                format!("#version {};\n", config.version),
            ),
        });
    }
    actions
}

fn edit(file: crate::db::File, range: TextRange, insert: String) -> SourceChange {
    SourceChange {
        edits: vec![(file, vec![TextEdit { range, insert }])],
    }
}

/// The names in sight and the reserved words nearest to `name`, closest first.
fn suggestions(db: &dyn Db, position: FilePosition, name: &str, limit: usize) -> Vec<String> {
    let file = position.file;
    let own = db::file_symbols(db, file).iter().map(|s| s.name.clone());
    let included = db::include_scope(db, file).keys().cloned();
    let keywords = syntax::KEYWORDS.iter().map(|(word, _)| (*word).to_owned());
    let most = if name.chars().count() <= 3 { 1 } else { 2 };
    let mut near: Vec<(usize, String)> = own
        .chain(included)
        .chain(keywords)
        .filter(|candidate| candidate != name)
        .filter_map(|candidate| {
            let distance = crate::spelling::edit_distance(name, &candidate);
            (distance <= most).then_some((distance, candidate))
        })
        .collect();
    near.sort();
    near.dedup_by(|a, b| a.1 == b.1);
    near.into_iter().take(limit).map(|(_, c)| c).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::{Expect, expect};

    #[track_caller]
    fn check(fixture: &str, expect: Expect) {
        let f = Fixture::parse(fixture);
        let position = f.position();
        let range = FileRange {
            file: position.file,
            range: TextRange::empty(position.offset),
        };
        let shown: Vec<String> = code_actions(&f.db, range, &CodeActionsConfig::default())
            .into_iter()
            .map(|action| {
                let (file, edits) = &action.change.edits[0];
                let mut text = file.text(&f.db).to_string();
                for edit in edits.iter().rev() {
                    text.replace_range(std::ops::Range::<usize>::from(edit.range), &edit.insert);
                }
                format!("{}:\n{text}", action.title)
            })
            .collect();
        expect.assert_eq(&shown.join("---\n"));
    }

    #[test]
    fn fixes_for_a_misspelt_name() {
        check(
            "#version 3.7;\n#declare Radius = 1;\nsphere { 0, Raduis$0 }\n",
            expect![[r#"
                Replace with `Radius`:
                #version 3.7;
                #declare Radius = 1;
                sphere { 0, Radius }
                ---
                Declare `Raduis`:
                #version 3.7;
                #declare Radius = 1;
                #declare Raduis = 0;
                sphere { 0, Raduis }
            "#]],
        );
    }

    #[test]
    fn did_you_mean_a_reserved_word() {
        check(
            "#version 3.7;\nspher$0 { 0, 1 }\n",
            expect![[r#"
                Replace with `sphere`:
                #version 3.7;
                sphere { 0, 1 }
                ---
                Declare `spher`:
                #version 3.7;
                #declare spher = 0;
                spher { 0, 1 }
            "#]],
        );
    }

    #[test]
    fn add_the_missing_version() {
        check(
            "$0sphere { 0, 1 }\n",
            expect![[r#"
                Add `#version 3.7;`:
                #version 3.7;
                sphere { 0, 1 }
            "#]],
        );
    }
}
