//! `textDocument/references`.

use crate::snapshot::Snapshot;
use analysis::ide::references::{ReferencesConfig, find_references};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{Location, ReferenceParams};

pub fn handle(snapshot: Snapshot, params: ReferenceParams) -> Result<Option<Vec<Location>>> {
    let at = &params.text_document_position;
    let Some((_, position)) = snapshot.analysis_position(&at.text_document.uri, at.position) else {
        return Ok(None);
    };
    let config = ReferencesConfig {
        include_declaration: params.context.include_declaration,
    };
    Ok(
        find_references(&snapshot.db, position, &config).map(|found| {
            found
                .references
                .into_iter()
                .filter_map(|r| snapshot.file_location(r.file, r.range))
                .collect()
        }),
    )
}
