//! One handler per request: each takes a snapshot and the protocol's parameters, asks an
//! IDE feature, and converts its plain answer with [`crate::convert`].

pub mod render;

use tower_lsp_server::ls_types::*;

/// What the server can do, announced in `initialize`.
pub fn capabilities() -> ServerCapabilities {
    ServerCapabilities {
        text_document_sync: Some(TextDocumentSyncCapability::Options(
            TextDocumentSyncOptions {
                open_close: Some(true),
                change: Some(TextDocumentSyncKind::INCREMENTAL),
                ..TextDocumentSyncOptions::default()
            },
        )),
        ..ServerCapabilities::default()
    }
}
