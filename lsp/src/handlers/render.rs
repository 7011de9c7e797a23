//! `povrayst/render`: renders the scene of a document (or the povray block of a Typst
//! document at a position) at a given size and answers with a PNG, for editor previews.
//! A scene with errors is answered with an error whose message is `povrayst check`'s
//! report.

use crate::convert;
use crate::documents::DocumentKind;
use crate::snapshot::Snapshot;
use analysis::MemoryFiles;
use analysis::db::{self, FilePath};
use analysis::files::read_sdl_file;
use renderer::RenderOptions;
use serde::{Deserialize, Serialize};
use tower_lsp_server::jsonrpc::{Error, ErrorCode, Result};
use tower_lsp_server::ls_types::{Position, TextDocumentIdentifier};

#[derive(Debug, Deserialize)]
#[serde(rename_all = "camelCase")]
pub struct RenderParams {
    pub text_document: TextDocumentIdentifier,
    /// In a Typst document, a position inside the block to render (the first block when
    /// absent).
    #[serde(default)]
    pub position: Option<Position>,
    pub width: u32,
    pub height: u32,
}

#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct RenderResult {
    /// The PNG file, base64-encoded.
    pub png: String,
    pub width: u32,
    pub height: u32,
}

/// The largest preview side we render, to keep a preview a preview.
const MAX_SIDE: u32 = 4096;

pub fn handle(snapshot: Snapshot, params: RenderParams) -> Result<RenderResult> {
    if !(1..=MAX_SIDE).contains(&params.width) || !(1..=MAX_SIDE).contains(&params.height) {
        return Err(Error::invalid_params(format!(
            "width and height must be between 1 and {MAX_SIDE}"
        )));
    }
    let uri = &params.text_document.uri;
    let view = snapshot
        .document(uri)
        .ok_or_else(|| Error::invalid_params("the document is not open"))?;
    let part = match (view.kind, params.position) {
        (DocumentKind::Typst, Some(position)) => {
            snapshot.file_position(uri, position).map(|(part, _)| part)
        }
        _ => view.parts.first(),
    }
    .ok_or_else(|| Error::invalid_params("there is no scene here"))?;

    // Copy out every text the scene reads, then let go of the database before the long
    // part, so that edits are not held up by the render.
    let main_name = part.path.scene_name();
    let checked = db::check_file(&snapshot.db, part.file);
    let mut files = MemoryFiles::new();
    for (name, path) in &checked.files {
        let text = match snapshot.world.project.files(&snapshot.db).get(path) {
            Some(file) => Some(file.text(&snapshot.db).clone()),
            None => match path {
                FilePath::Disk(disk) => read_sdl_file(disk).ok().map(Into::into),
                _ => None,
            },
        };
        if let Some(text) = text {
            files.insert(name.clone(), text);
        }
    }
    drop(snapshot);

    let options = RenderOptions {
        width: params.width,
        height: params.height,
        ..RenderOptions::default()
    };
    match renderer::pipeline::render_source(&main_name, &files, &options) {
        Ok(rendered) => Ok(RenderResult {
            png: convert::base64(&renderer::encode_png(&rendered.image, &options)),
            width: params.width,
            height: params.height,
        }),
        Err(failure) => Err(Error {
            code: ErrorCode::ServerError(1),
            message: failure.to_human().into(),
            data: None,
        }),
    }
}
