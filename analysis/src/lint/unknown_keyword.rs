//! A lower-case name that is declared nowhere and is a small edit away from a reserved
//! word is almost always a misspelt keyword (`pigmnet`): say which one. The evaluator says
//! the same when it reaches the name; this lint also finds it where the parser stops first
//! and in branches that are never taken.

use super::workspace::Workspace;
use std::collections::HashSet;
use syntax::Diagnostic;

pub const CODE: &str = "unknown-keyword";

pub fn check(workspace: &Workspace) -> Vec<Diagnostic> {
    let defined: HashSet<&str> = workspace
        .files
        .iter()
        .flat_map(|file| file.definitions.iter().map(|d| d.name.as_str()))
        .collect();
    let mut warnings = Vec::new();
    for file in workspace.user_files() {
        for (name, range) in file.name_refs() {
            if defined.contains(name.as_str())
                || name.len() < 3
                || name.chars().any(|c| !(c.is_ascii_lowercase() || c == '_'))
            {
                continue;
            }
            if let Some(keyword) = closest_keyword(name) {
                warnings.push(
                    Diagnostic::warning(&file.name, *range, format!("unknown keyword '{name}'"))
                        .with_code(CODE)
                        .with_note(format!("did you mean '{keyword}'?")),
                );
            }
        }
    }
    warnings
}

/// The reserved word nearest to `name`, if one is close enough to be a typo.
fn closest_keyword(name: &str) -> Option<&'static str> {
    crate::spelling::closest(name, syntax::KEYWORDS.iter().map(|(keyword, _)| *keyword))
}
