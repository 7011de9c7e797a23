//! Open documents as the client sees them: which ones we serve, where their text lives in
//! the database, and how the client's edits change their text.

use analysis::db::{File, FilePath};
use std::path::PathBuf;
use std::sync::Arc;
use syntax::line_index::LineIndex;
use tower_lsp_server::ls_types::{TextDocumentContentChangeEvent, Uri};

/// The documents the server answers for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DocumentKind {
    /// A scene or include file (`.pov`, `.inc`, `.mcr`).
    Scene,
    /// A Typst document, served only inside its ```` ```povray ```` blocks.
    Typst,
}

impl DocumentKind {
    /// Recognises a document by the client's language id, then by its extension.
    pub fn of(uri: &Uri, language_id: &str) -> Option<DocumentKind> {
        match language_id {
            "povray" | "pov" | "povray-sdl" => return Some(DocumentKind::Scene),
            "typst" => return Some(DocumentKind::Typst),
            _ => {}
        }
        let path = uri.path().as_str().to_ascii_lowercase();
        let extension = path.rsplit_once('.').map_or("", |(_, ext)| ext);
        match extension {
            "pov" | "inc" | "mcr" => Some(DocumentKind::Scene),
            "typ" => Some(DocumentKind::Typst),
            _ => None,
        }
    }
}

/// The path the database knows a document by. Documents that are not files (an unsaved
/// `untitled:` buffer) get a path of their own under a directory that does not exist, so
/// that they find only the bundled includes.
pub fn path_of(uri: &Uri) -> PathBuf {
    let is_file = uri.scheme().as_str().eq_ignore_ascii_case("file");
    match uri.to_file_path() {
        Some(path) if is_file && path.is_absolute() => analysis::db::normalize(&path),
        _ => PathBuf::from("/povrayst-unsaved").join(uri.as_str().replace(['/', ':'], "_")),
    }
}

/// A document the client has open.
#[derive(Debug, Clone)]
pub struct OpenDocument {
    pub kind: DocumentKind,
    pub version: i32,
    pub text: String,
}

/// One piece of a document that the database holds as a file: a whole scene, or one
/// povray block of a Typst document with the map between the two texts.
#[derive(Debug, Clone)]
pub struct Part {
    pub file: File,
    pub path: FilePath,
    pub block: Option<Arc<analysis::ide::embedded::Block>>,
}

/// What requests and diagnostics jobs need to know about an open document.
#[derive(Debug, Clone)]
pub struct DocumentView {
    pub kind: DocumentKind,
    pub version: i32,
    pub text: Arc<str>,
    pub line_index: Arc<LineIndex>,
    pub path: PathBuf,
    pub parts: Vec<Part>,
}

/// Applies one change from `textDocument/didChange`: a whole new text, or a range in
/// UTF-16 line and column replaced by new text.
pub fn apply_change(text: &mut String, change: &TextDocumentContentChangeEvent) {
    let Some(range) = change.range else {
        text.clone_from(&change.text);
        return;
    };
    let index = LineIndex::new(text);
    let start = usize::from(crate::convert::offset(&index, text, range.start));
    let end = usize::from(crate::convert::offset(&index, text, range.end)).max(start);
    text.replace_range(start..end, &change.text);
}

#[cfg(test)]
mod tests {
    use super::*;
    use tower_lsp_server::ls_types::{Position, Range};

    fn change(
        range: Option<((u32, u32), (u32, u32))>,
        text: &str,
    ) -> TextDocumentContentChangeEvent {
        TextDocumentContentChangeEvent {
            range: range.map(|((l1, c1), (l2, c2))| {
                Range::new(Position::new(l1, c1), Position::new(l2, c2))
            }),
            range_length: None,
            text: text.to_owned(),
        }
    }

    #[test]
    fn edits_apply_in_utf16_columns() {
        let mut text = "#declare é = 1;\nsphere { 0, 1 }\n".to_owned();
        apply_change(&mut text, &change(Some(((0, 9), (0, 10))), "A"));
        assert_eq!(text, "#declare A = 1;\nsphere { 0, 1 }\n");
        apply_change(&mut text, &change(Some(((1, 12), (1, 13))), "A"));
        assert_eq!(text, "#declare A = 1;\nsphere { 0, A }\n");
        apply_change(&mut text, &change(Some(((5, 0), (9, 9))), "// end\n"));
        assert_eq!(text, "#declare A = 1;\nsphere { 0, A }\n// end\n");
        apply_change(&mut text, &change(None, "new"));
        assert_eq!(text, "new");
    }

    #[test]
    fn documents_are_recognised_by_language_then_extension() {
        let uri = |s: &str| s.parse::<Uri>().unwrap();
        assert_eq!(
            DocumentKind::of(&uri("file:///a/b.POV"), ""),
            Some(DocumentKind::Scene)
        );
        assert_eq!(
            DocumentKind::of(&uri("file:///a/b.inc"), "plaintext"),
            Some(DocumentKind::Scene)
        );
        assert_eq!(
            DocumentKind::of(&uri("file:///a/b.typ"), ""),
            Some(DocumentKind::Typst)
        );
        assert_eq!(
            DocumentKind::of(&uri("untitled:1"), "povray"),
            Some(DocumentKind::Scene)
        );
        assert_eq!(DocumentKind::of(&uri("file:///a/b.rs"), "rust"), None);
    }
}
