//! `workspace/symbol`.

use crate::snapshot::Snapshot;
use analysis::ide::workspace_symbols::{WorkspaceSymbolsConfig, workspace_symbols};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{
    SymbolInformation, SymbolKind, WorkspaceSymbolParams, WorkspaceSymbolResponse,
};

pub fn handle(
    snapshot: Snapshot,
    params: WorkspaceSymbolParams,
) -> Result<Option<WorkspaceSymbolResponse>> {
    let files: Vec<_> = snapshot
        .world
        .project
        .files(&snapshot.db)
        .values()
        .copied()
        .collect();
    let found = workspace_symbols(
        &snapshot.db,
        &files,
        &params.query,
        &WorkspaceSymbolsConfig::default(),
    );
    #[allow(deprecated)] // `deprecated` is a required field of the protocol's struct.
    let symbols = found
        .into_iter()
        .filter_map(|symbol| {
            Some(SymbolInformation {
                location: snapshot.file_location(symbol.target.file, symbol.target.focus_range)?,
                name: symbol.target.name,
                kind: if symbol.is_macro {
                    SymbolKind::FUNCTION
                } else {
                    SymbolKind::VARIABLE
                },
                tags: None,
                deprecated: None,
                container_name: Some(symbol.container),
            })
        })
        .collect();
    Ok(Some(WorkspaceSymbolResponse::Flat(symbols)))
}
