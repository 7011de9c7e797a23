//! `textDocument/hover`.

use crate::snapshot::Snapshot;
use analysis::ide::hover::{HoverConfig, hover};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{Hover, HoverContents, HoverParams, MarkupContent, MarkupKind};

pub fn handle(snapshot: Snapshot, params: HoverParams) -> Result<Option<Hover>> {
    let at = &params.text_document_position_params;
    let Some((part, position)) = snapshot.analysis_position(&at.text_document.uri, at.position)
    else {
        return Ok(None);
    };
    Ok(
        hover(&snapshot.db, position, &HoverConfig::default()).map(|result| Hover {
            contents: HoverContents::Markup(MarkupContent {
                kind: MarkupKind::Markdown,
                value: result.markup,
            }),
            range: Some(snapshot.part_range(part, result.range)),
        }),
    )
}
