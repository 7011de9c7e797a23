//! Between our data and the protocol's: byte offsets and UTF-16 positions, database files
//! and URIs, our diagnostics and the protocol's. The one module that knows both sides.

use crate::documents::Part;
use crate::snapshot::Snapshot;
use analysis::db::{Checked, FilePath};
use syntax::line_index::{LineCol, LineIndex};
use syntax::{Severity, TextRange, TextSize};
use tower_lsp_server::ls_types::{
    self as lsp, DiagnosticRelatedInformation, DiagnosticSeverity, DiagnosticTag, Location,
    NumberOrString, Position, Range,
};

/// The byte offset of a protocol position, clamped to the text.
pub fn offset(index: &LineIndex, text: &str, position: Position) -> TextSize {
    index.offset_of_utf16(
        text,
        LineCol {
            line: position.line,
            col: position.character,
        },
    )
}

pub fn position(index: &LineIndex, text: &str, offset: TextSize) -> Position {
    let at = index.utf16_line_col(text, offset);
    Position::new(at.line, at.col)
}

pub fn range(index: &LineIndex, text: &str, range: TextRange) -> Range {
    Range::new(
        position(index, text, range.start()),
        position(index, text, range.end()),
    )
}

/// The protocol's diagnostics for one part of a document, from checking it as a scene.
///
/// A diagnostic in the part itself keeps its place. One inside an include file is shown
/// where the part includes that file (or calls the macro that failed), and its related
/// information points into the include, so the editor shows it beside the line that
/// brought it in.
pub fn diagnostics(snapshot: &Snapshot, part: &Part, checked: &Checked) -> Vec<lsp::Diagnostic> {
    let here = |file: &str| checked.path_of(file) == Some(&part.path);
    checked
        .diagnostics
        .iter()
        .map(|diagnostic| {
            let mut related: Vec<DiagnosticRelatedInformation> = Vec::new();
            let range = if here(&diagnostic.span.file) {
                diagnostic.span.range
            } else {
                if let Some(location) = location_of(
                    snapshot,
                    checked,
                    &diagnostic.span.file,
                    diagnostic.span.range,
                ) {
                    related.push(DiagnosticRelatedInformation {
                        location,
                        message: diagnostic.message.clone(),
                    });
                }
                diagnostic
                    .related
                    .iter()
                    .rev()
                    .find(|r| here(&r.span.file))
                    .map_or(TextRange::default(), |r| r.span.range)
            };
            related.extend(diagnostic.related.iter().filter_map(|r| {
                Some(DiagnosticRelatedInformation {
                    location: location_of(snapshot, checked, &r.span.file, r.span.range)?,
                    message: r.message.clone(),
                })
            }));
            lsp::Diagnostic {
                range: snapshot.part_range(part, range),
                severity: Some(severity(diagnostic.severity)),
                code: diagnostic
                    .code
                    .map(|code| NumberOrString::String(code.to_owned())),
                source: Some("povrayst".to_owned()),
                message: with_notes(diagnostic),
                related_information: (!related.is_empty()).then_some(related),
                ..lsp::Diagnostic::default()
            }
        })
        .collect()
}

fn location_of(
    snapshot: &Snapshot,
    checked: &Checked,
    file: &str,
    range: TextRange,
) -> Option<Location> {
    let path: &FilePath = checked.path_of(file)?;
    snapshot.location(path, range)
}

/// Standard base64 with padding, for binary answers such as PNG previews.
pub fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            *chunk.get(1).unwrap_or(&0),
            *chunk.get(2).unwrap_or(&0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(char::from(ALPHABET[(n >> (18 - 6 * i) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// The one diagnostic of a document whose check failed inside Povrayst itself.
pub fn internal_error(cause: &str) -> lsp::Diagnostic {
    lsp::Diagnostic {
        range: Range::default(),
        severity: Some(DiagnosticSeverity::ERROR),
        source: Some("povrayst".to_owned()),
        message: format!("povrayst could not check this file (a bug in povrayst): {cause}"),
        ..lsp::Diagnostic::default()
    }
}

/// The lints of `povrayst check` that lie in the part itself (`main_name` to the linter),
/// with the same words; the editor fades declarations nothing uses and strikes through
/// legacy syntax.
pub fn lints(
    snapshot: &Snapshot,
    part: &Part,
    main_name: &str,
    warnings: &[syntax::Diagnostic],
) -> Vec<lsp::Diagnostic> {
    warnings
        .iter()
        .filter(|warning| warning.span.file == main_name)
        .map(|warning| {
            let tag = match warning.code {
                Some(analysis::lint::UNUSED_CODE) => Some(DiagnosticTag::UNNECESSARY),
                Some(analysis::lint::LEGACY_CODE) => Some(DiagnosticTag::DEPRECATED),
                _ => None,
            };
            lsp::Diagnostic {
                range: snapshot.part_range(part, warning.span.range),
                severity: Some(severity(warning.severity)),
                code: warning
                    .code
                    .map(|code| NumberOrString::String(code.to_owned())),
                source: Some("povrayst".to_owned()),
                message: with_notes(warning),
                tags: tag.map(|tag| vec![tag]),
                ..lsp::Diagnostic::default()
            }
        })
        .collect()
}

fn severity(severity: Severity) -> DiagnosticSeverity {
    match severity {
        Severity::Error => DiagnosticSeverity::ERROR,
        Severity::Warning => DiagnosticSeverity::WARNING,
    }
}

/// The message with its notes on lines of their own, as `povrayst check` prints them.
fn with_notes(diagnostic: &syntax::Diagnostic) -> String {
    let mut message = diagnostic.message.clone();
    for note in &diagnostic.notes {
        message.push_str("\nnote: ");
        message.push_str(note);
    }
    message
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_pads_as_the_standard_says() {
        assert_eq!(base64(b""), "");
        assert_eq!(base64(b"f"), "Zg==");
        assert_eq!(base64(b"fo"), "Zm8=");
        assert_eq!(base64(b"foo"), "Zm9v");
        assert_eq!(base64(b"foobar"), "Zm9vYmFy");
    }
}
