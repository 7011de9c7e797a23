//! `textDocument/inlayHint`.

use crate::snapshot::Snapshot;
use analysis::ide::inlay_hints::{InlayHintsConfig, inlay_hints};
use syntax::TextRange;
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{InlayHint, InlayHintKind, InlayHintLabel, InlayHintParams};

pub fn handle(snapshot: Snapshot, params: InlayHintParams) -> Result<Option<Vec<InlayHint>>> {
    let Some(view) = snapshot.document(&params.text_document.uri) else {
        return Ok(None);
    };
    let mut hints = Vec::new();
    for part in &view.parts {
        let whole = TextRange::up_to(syntax::TextSize::of(&**part.file.text(&snapshot.db)));
        for hint in inlay_hints(&snapshot.db, part.file, whole, &InlayHintsConfig::default()) {
            let position = snapshot
                .part_range(part, TextRange::empty(hint.offset))
                .start;
            let in_range = params.range.start <= position && position <= params.range.end;
            if in_range {
                hints.push(InlayHint {
                    position,
                    label: InlayHintLabel::String(hint.label),
                    kind: Some(InlayHintKind::PARAMETER),
                    text_edits: None,
                    tooltip: None,
                    padding_left: None,
                    padding_right: Some(true),
                    data: None,
                });
            }
        }
    }
    Ok(Some(hints))
}
