//! A macro parameter or a `#local` inside a macro that has the name of a global
//! declaration or a macro: inside the macro the global is out of reach, which is seldom
//! what was meant when the global comes from an include.

use super::workspace::{Definition, DefinitionKind, Workspace};
use std::collections::HashMap;
use syntax::{Diagnostic, Span};

pub const CODE: &str = "shadowed-identifier";

pub fn check(workspace: &Workspace) -> Vec<Diagnostic> {
    let Some(main) = workspace.main() else {
        return Vec::new();
    };
    let mut globals: HashMap<&str, (&str, &Definition)> = HashMap::new();
    for file in &workspace.files {
        for definition in file.definitions.iter() {
            let global = match definition.kind {
                DefinitionKind::Declare => !definition.in_macro,
                DefinitionKind::Macro => true,
                _ => false,
            };
            if global {
                globals
                    .entry(definition.name.as_str())
                    .or_insert((file.name.as_str(), definition));
            }
        }
    }
    main.definitions
        .iter()
        .filter(|definition| match definition.kind {
            DefinitionKind::MacroParameter => true,
            DefinitionKind::Local => definition.in_macro,
            _ => false,
        })
        .filter_map(|definition| {
            let (file, global) = globals.get(definition.name.as_str())?;
            let what = match definition.kind {
                DefinitionKind::MacroParameter => "macro parameter",
                _ => "#local",
            };
            let global_what = match global.kind {
                DefinitionKind::Macro => "the macro",
                _ => "the global",
            };
            Some(
                Diagnostic::warning(
                    &main.name,
                    definition.range,
                    format!(
                        "{what} '{}' shadows {global_what} of the same name",
                        definition.name
                    ),
                )
                .with_code(CODE)
                .with_related(
                    Span {
                        file: (*file).to_owned(),
                        range: global.range,
                    },
                    format!("{global_what} '{}' is declared here", global.name),
                ),
            )
        })
        .collect()
}
