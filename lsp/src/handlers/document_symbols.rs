//! `textDocument/documentSymbol`: the outline; for a Typst document, the outline of each
//! of its povray blocks.

use crate::documents::Part;
use crate::snapshot::Snapshot;
use analysis::ide::document_symbols::{self, DocumentSymbolsConfig, OutlineKind};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{
    DocumentSymbol, DocumentSymbolParams, DocumentSymbolResponse, SymbolKind,
};

pub fn handle(
    snapshot: Snapshot,
    params: DocumentSymbolParams,
) -> Result<Option<DocumentSymbolResponse>> {
    let Some(view) = snapshot.document(&params.text_document.uri) else {
        return Ok(None);
    };
    let config = DocumentSymbolsConfig::default();
    let symbols = view
        .parts
        .iter()
        .flat_map(|part| {
            document_symbols::document_symbols(&snapshot.db, part.file, &config)
                .into_iter()
                .map(|symbol| convert(&snapshot, part, symbol))
        })
        .collect();
    Ok(Some(DocumentSymbolResponse::Nested(symbols)))
}

#[allow(deprecated)] // `deprecated` is a required field of the protocol's struct.
fn convert(
    snapshot: &Snapshot,
    part: &Part,
    symbol: document_symbols::DocumentSymbol,
) -> DocumentSymbol {
    DocumentSymbol {
        name: symbol.name,
        detail: symbol.detail,
        kind: match symbol.kind {
            OutlineKind::Variable => SymbolKind::VARIABLE,
            OutlineKind::Macro => SymbolKind::FUNCTION,
            OutlineKind::Parameter => SymbolKind::TYPE_PARAMETER,
            OutlineKind::Camera => SymbolKind::EVENT,
            OutlineKind::Light => SymbolKind::CONSTANT,
            OutlineKind::Object => SymbolKind::OBJECT,
        },
        tags: None,
        deprecated: None,
        range: snapshot.part_range(part, symbol.full_range),
        selection_range: snapshot.part_range(part, symbol.focus_range),
        children: Some(
            symbol
                .children
                .into_iter()
                .map(|c| convert(snapshot, part, c))
                .collect(),
        ),
    }
}
