//! `textDocument/foldingRange`.

use crate::snapshot::Snapshot;
use analysis::ide::folding_ranges::{FoldKind, FoldingRangesConfig, folding_ranges};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{FoldingRange, FoldingRangeKind, FoldingRangeParams};

pub fn handle(snapshot: Snapshot, params: FoldingRangeParams) -> Result<Option<Vec<FoldingRange>>> {
    let Some(view) = snapshot.document(&params.text_document.uri) else {
        return Ok(None);
    };
    let mut ranges = Vec::new();
    for part in &view.parts {
        for fold in folding_ranges(&snapshot.db, part.file, &FoldingRangesConfig::default()) {
            let range = snapshot.part_range(part, fold.range);
            // Keep a closing brace or `#end` visible below the folded lines.
            let end_line = match fold.kind {
                FoldKind::Comment => range.end.line,
                _ => range.end.line.saturating_sub(1).max(range.start.line),
            };
            if end_line > range.start.line {
                ranges.push(FoldingRange {
                    start_line: range.start.line,
                    start_character: None,
                    end_line,
                    end_character: None,
                    kind: (fold.kind == FoldKind::Comment).then_some(FoldingRangeKind::Comment),
                    collapsed_text: None,
                });
            }
        }
    }
    Ok(Some(ranges))
}
