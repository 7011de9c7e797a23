//! `textDocument/prepareRename` and `textDocument/rename`.

use crate::snapshot::Snapshot;
use analysis::ide::rename::{RenameConfig, prepare_rename, rename};
use std::collections::HashMap;
use tower_lsp_server::jsonrpc::{Error, Result};
use tower_lsp_server::ls_types::{
    PrepareRenameResponse, RenameParams, TextDocumentPositionParams, TextEdit, WorkspaceEdit,
};

pub fn prepare(
    snapshot: Snapshot,
    params: TextDocumentPositionParams,
) -> Result<Option<PrepareRenameResponse>> {
    let Some((part, position)) =
        snapshot.analysis_position(&params.text_document.uri, params.position)
    else {
        return Ok(None);
    };
    match prepare_rename(&snapshot.db, position) {
        Ok(range) => Ok(Some(PrepareRenameResponse::Range(
            snapshot.part_range(part, range),
        ))),
        Err(reason) => Err(Error::invalid_params(reason)),
    }
}

pub fn handle(snapshot: Snapshot, params: RenameParams) -> Result<Option<WorkspaceEdit>> {
    let at = &params.text_document_position;
    let Some((_, position)) = snapshot.analysis_position(&at.text_document.uri, at.position) else {
        return Ok(None);
    };
    let config = RenameConfig {
        refuse_clashes: true,
    };
    let change =
        rename(&snapshot.db, position, &params.new_name, &config).map_err(Error::invalid_params)?;
    let mut changes: HashMap<_, Vec<TextEdit>> = HashMap::new();
    for (file, edits) in change.edits {
        for edit in edits {
            if let Some(location) = snapshot.file_location(file, edit.range) {
                changes.entry(location.uri).or_default().push(TextEdit {
                    range: location.range,
                    new_text: edit.insert,
                });
            }
        }
    }
    Ok(Some(WorkspaceEdit {
        changes: Some(changes),
        ..WorkspaceEdit::default()
    }))
}
