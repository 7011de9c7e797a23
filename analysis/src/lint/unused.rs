//! `#declare` and `#local` names of the scene that nothing reads: not the scene, not the
//! files it includes. Names are compared as text over all files, so a name read anywhere
//! counts as used; the lint misses some unused names and never flags a used one.

use super::workspace::{DefinitionKind, Workspace};
use syntax::Diagnostic;

pub const CODE: &str = "unused-declaration";

pub fn check(workspace: &Workspace) -> Vec<Diagnostic> {
    // What an include file declares is there for the scenes that include it.
    let Some(main) = workspace.main().filter(|main| !main.is_include_file()) else {
        return Vec::new();
    };
    let uses = workspace.use_counts();
    let mut reported = std::collections::HashSet::new();
    main.definitions
        .iter()
        .filter(|definition| {
            matches!(
                definition.kind,
                DefinitionKind::Declare | DefinitionKind::Local
            )
        })
        .filter(|definition| !uses.contains_key(definition.name.as_str()))
        // A name declared again and again is reported once, at its first declaration.
        .filter(|definition| reported.insert(definition.name.as_str()))
        .map(|definition| {
            let directive = match definition.kind {
                DefinitionKind::Local => "#local",
                _ => "#declare",
            };
            Diagnostic::warning(
                &main.name,
                definition.range,
                format!(
                    "'{}' is declared by {directive} but never used",
                    definition.name
                ),
            )
            .with_code(CODE)
        })
        .collect()
}
