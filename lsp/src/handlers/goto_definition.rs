//! `textDocument/definition`.

use crate::snapshot::Snapshot;
use analysis::ide::goto_definition::{GotoDefinitionConfig, goto_definition};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{GotoDefinitionParams, GotoDefinitionResponse};

pub fn handle(
    snapshot: Snapshot,
    params: GotoDefinitionParams,
) -> Result<Option<GotoDefinitionResponse>> {
    let at = &params.text_document_position_params;
    let Some((_, position)) = snapshot.analysis_position(&at.text_document.uri, at.position) else {
        return Ok(None);
    };
    let locations: Vec<_> =
        goto_definition(&snapshot.db, position, &GotoDefinitionConfig::default())
            .into_iter()
            .filter_map(|target| snapshot.file_location(target.file, target.focus_range))
            .collect();
    Ok((!locations.is_empty()).then_some(GotoDefinitionResponse::Array(locations)))
}
