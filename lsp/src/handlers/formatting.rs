//! `textDocument/formatting`, for scene and include files. A Typst document is left to
//! the Typst tools: its povray blocks are indented as part of the document.

use crate::documents::DocumentKind;
use crate::snapshot::Snapshot;
use analysis::format::FormatConfig;
use analysis::ide::formatting::formatting;
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{DocumentFormattingParams, TextEdit};

pub fn handle(
    snapshot: Snapshot,
    params: DocumentFormattingParams,
) -> Result<Option<Vec<TextEdit>>> {
    let Some(view) = snapshot.document(&params.text_document.uri) else {
        return Ok(None);
    };
    let (DocumentKind::Scene, Some(part)) = (view.kind, view.parts.first()) else {
        return Ok(None);
    };
    let config = FormatConfig {
        indent_width: params.options.tab_size.clamp(1, 16) as usize,
        ..FormatConfig::default()
    };
    Ok(Some(
        formatting(&snapshot.db, part.file, &config)
            .into_iter()
            .map(|edit| TextEdit {
                range: snapshot.part_range(part, edit.range),
                new_text: edit.insert,
            })
            .collect(),
    ))
}
