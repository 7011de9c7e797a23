//! `textDocument/documentLink`: `#include` names link to their files; in a Typst document,
//! so do the scene files its `render(read("scene.pov"))` calls read.

use crate::documents::DocumentKind;
use crate::snapshot::Snapshot;
use analysis::db::Resolved;
use analysis::ide::document_links::{DocumentLinksConfig, document_links};
use analysis::ide::embedded::scene_links;
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{DocumentLink, DocumentLinkParams, Uri};

pub fn handle(snapshot: Snapshot, params: DocumentLinkParams) -> Result<Option<Vec<DocumentLink>>> {
    let uri = &params.text_document.uri;
    let Some(view) = snapshot.document(uri) else {
        return Ok(None);
    };
    let mut links = Vec::new();
    for part in &view.parts {
        for link in document_links(&snapshot.db, part.file, &DocumentLinksConfig::default()) {
            let target = match &link.target {
                Some(Resolved::OnDisk(path)) => Uri::from_file_path(path),
                Some(resolved) => snapshot.uri(&resolved.path(&snapshot.db)),
                None => None,
            };
            links.push(DocumentLink {
                range: snapshot.part_range(part, link.range),
                target,
                tooltip: None,
                data: None,
            });
        }
    }
    if view.kind == DocumentKind::Typst {
        let dir = view
            .path
            .parent()
            .map(std::path::Path::to_path_buf)
            .unwrap_or_default();
        for link in scene_links(&view.text) {
            links.push(DocumentLink {
                range: crate::convert::range(&view.line_index, &view.text, link.range),
                target: Uri::from_file_path(analysis::db::normalize(&dir.join(&link.path))),
                tooltip: Some("the scene this call renders".to_owned()),
                data: None,
            });
        }
    }
    Ok(Some(links))
}
