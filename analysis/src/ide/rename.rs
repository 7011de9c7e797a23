//! Rename a `#declare`, `#local`, macro, parameter or loop variable and every use that
//! resolves to it, in every file, leaving shadowed names of the same spelling alone.
//! Bundled standard includes are never edited.

use super::classify::{Target, classify};
use super::references::uses;
use super::{FilePosition, SourceChange, TextEdit};
use crate::db::Db;
use syntax::TextRange;

#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct RenameConfig {
    /// Whether to refuse a new name that another definition in sight already has.
    pub refuse_clashes: bool,
}

/// The range of the name that would be renamed, or why it cannot be.
pub fn prepare_rename(db: &dyn Db, position: FilePosition) -> Result<TextRange, String> {
    let classified = classify(db, position).ok_or("there is no name here")?;
    match classified.target {
        Target::Symbol(definition) => {
            if !definition.file.path(db).is_editable() {
                return Err("this name is defined in a bundled standard include".to_owned());
            }
            Ok(classified.range)
        }
        Target::Unresolved(name) => Err(format!("'{name}' is not declared anywhere in sight")),
        Target::Keyword(_) => Err("reserved words cannot be renamed".to_owned()),
        Target::Include { .. } => Err("include file names cannot be renamed".to_owned()),
    }
}

pub fn rename(
    db: &dyn Db,
    position: FilePosition,
    new_name: &str,
    config: &RenameConfig,
) -> Result<SourceChange, String> {
    prepare_rename(db, position)?;
    if !is_identifier(new_name) {
        return Err(format!("'{new_name}' is not an identifier"));
    }
    if syntax::SyntaxKind::from_keyword(new_name).is_some() {
        return Err(format!("'{new_name}' is a reserved word"));
    }
    let Some(Target::Symbol(definition)) = classify(db, position).map(|c| c.target) else {
        return Err("there is no name here".to_owned());
    };
    if config.refuse_clashes {
        let scope = crate::db::include_scope(db, position.file);
        let own = crate::db::file_symbols(db, position.file);
        if scope.contains_key(new_name) || own.iter().any(|s| s.name == new_name) {
            return Err(format!("'{new_name}' is already defined"));
        }
    }
    let mut change = SourceChange::default();
    for found in uses(db, definition) {
        let edit = TextEdit {
            range: found.range,
            insert: new_name.to_owned(),
        };
        match change
            .edits
            .iter_mut()
            .find(|(file, _)| *file == found.file)
        {
            Some((_, edits)) => edits.push(edit),
            None => change.edits.push((found.file, vec![edit])),
        }
    }
    Ok(change)
}

fn is_identifier(name: &str) -> bool {
    let mut chars = name.chars();
    chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
        && chars.all(|c| c.is_ascii_alphanumeric() || c == '_')
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::{Expect, expect};

    #[track_caller]
    fn check(fixture: &str, new_name: &str, expect: Expect) {
        let f = Fixture::parse(fixture);
        let config = RenameConfig {
            refuse_clashes: true,
        };
        let shown = match rename(&f.db, f.position(), new_name, &config) {
            Ok(change) => change
                .edits
                .iter()
                .map(|(file, edits)| {
                    let mut text = file.text(&f.db).to_string();
                    for edit in edits.iter().rev() {
                        text.replace_range(
                            std::ops::Range::<usize>::from(edit.range),
                            &edit.insert,
                        );
                    }
                    format!("{}:\n{text}", f.name_of(*file))
                })
                .collect::<Vec<_>>()
                .join(""),
            Err(error) => format!("error: {error}"),
        };
        expect.assert_eq(&shown);
    }

    #[test]
    fn renames_every_use_across_files_and_nothing_shadowed() {
        check(
            r#"
            //- /scene.pov
            #include "lib.inc"
            #macro M(Size) box { 0, Size } #end
            object { M($0Size) }
            //- /lib.inc
            #declare Size = 2;
            "#,
            "Width",
            expect![[r#"
                /lib.inc:
                #declare Width = 2;
                /scene.pov:
                #include "lib.inc"
                #macro M(Size) box { 0, Size } #end
                object { M(Width) }
            "#]],
        );
    }

    #[test]
    fn refuses_what_cannot_be_renamed() {
        check(
            "#include \"colors.inc\"\npigment { $0Red }",
            "Rouge",
            expect!["error: this name is defined in a bundled standard include"],
        );
        check(
            "#declare $0A = 1;",
            "sphere",
            expect!["error: 'sphere' is a reserved word"],
        );
        check(
            "#declare $0A = 1;",
            "2x",
            expect!["error: '2x' is not an identifier"],
        );
        check(
            "#declare $0A = 1;\n#declare B = 2;",
            "B",
            expect!["error: 'B' is already defined"],
        );
        check(
            "sphere { 0, $0Q }",
            "R",
            expect!["error: 'Q' is not declared anywhere in sight"],
        );
    }
}
