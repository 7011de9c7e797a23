//! `textDocument/completion`.

use crate::snapshot::Snapshot;
use analysis::ide::completion::{CompletionConfig, CompletionKind, completions};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{
    CompletionItem, CompletionItemKind, CompletionParams, CompletionResponse, CompletionTextEdit,
    InsertTextFormat, TextEdit,
};

pub fn handle(snapshot: Snapshot, params: CompletionParams) -> Result<Option<CompletionResponse>> {
    let at = &params.text_document_position;
    let Some((part, position)) = snapshot.analysis_position(&at.text_document.uri, at.position)
    else {
        return Ok(None);
    };
    let items = completions(&snapshot.db, position, &CompletionConfig::default())
        .into_iter()
        .map(|item| CompletionItem {
            kind: Some(match item.kind {
                CompletionKind::Keyword => CompletionItemKind::KEYWORD,
                CompletionKind::Snippet => CompletionItemKind::SNIPPET,
                CompletionKind::Variable => CompletionItemKind::VARIABLE,
                CompletionKind::Macro => CompletionItemKind::FUNCTION,
                CompletionKind::File => CompletionItemKind::FILE,
                CompletionKind::Function => CompletionItemKind::FUNCTION,
            }),
            insert_text_format: Some(if item.kind == CompletionKind::Snippet {
                InsertTextFormat::SNIPPET
            } else {
                InsertTextFormat::PLAIN_TEXT
            }),
            text_edit: Some(CompletionTextEdit::Edit(TextEdit {
                range: snapshot.part_range(part, item.replace_range),
                new_text: item.insert,
            })),
            detail: item.detail,
            label: item.label,
            ..CompletionItem::default()
        })
        .collect();
    Ok(Some(CompletionResponse::Array(items)))
}
