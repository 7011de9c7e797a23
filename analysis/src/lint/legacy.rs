//! Syntax that POV-Ray 3.7 still reads only for old scenes, or ignores: the obsolete
//! patterned textures, the old blob component, `hf_gray_16`, and the deprecated
//! `glass_old.inc`. Each warning says what replaces it.

use super::workspace::Workspace;
use syntax::{Diagnostic, SyntaxKind};

pub const CODE: &str = "legacy-syntax";

/// What to write instead of each legacy keyword.
pub(super) fn replacement(kind: SyntaxKind) -> Option<&'static str> {
    Some(match kind {
        SyntaxKind::TILES_KW => {
            "'tiles' is an obsolete patterned texture; use 'texture { checker texture { ... } texture { ... } }'"
        }
        SyntaxKind::MATERIAL_MAP_KW => {
            "'material_map' is an obsolete patterned texture; use 'texture { image_pattern { ... } texture_map { ... } }'"
        }
        SyntaxKind::COMPONENT_KW => {
            "'component' is the obsolete form of a blob component; use 'sphere { center, radius, strength }' inside the blob"
        }
        SyntaxKind::HF_GRAY_16_KW => {
            "'hf_gray_16' has no effect since POV-Ray 3.7; choose a grayscale output format instead"
        }
        _ => return None,
    })
}

pub fn check(workspace: &Workspace) -> Vec<Diagnostic> {
    let mut warnings = Vec::new();
    for file in workspace.user_files() {
        for &(kind, range) in file.legacy_tokens.iter() {
            if let Some(message) = replacement(kind) {
                warnings.push(Diagnostic::warning(&file.name, range, message).with_code(CODE));
            }
        }
        for (name, range) in file.includes.iter() {
            if name.eq_ignore_ascii_case("glass_old.inc") {
                warnings.push(
                    Diagnostic::warning(
                        &file.name,
                        *range,
                        "glass_old.inc is deprecated since POV-Ray 3.7; the materials of glass.inc replace it",
                    )
                    .with_code(CODE),
                );
            }
        }
    }
    warnings
}
