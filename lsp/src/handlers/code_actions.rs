//! `textDocument/codeAction`: our quick fixes as workspace edits.

use crate::snapshot::Snapshot;
use analysis::ide::FileRange;
use analysis::ide::code_actions::{CodeActionsConfig, code_actions};
use std::collections::HashMap;
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{
    CodeAction, CodeActionKind, CodeActionOrCommand, CodeActionParams, CodeActionResponse,
    TextEdit, WorkspaceEdit,
};

pub fn handle(snapshot: Snapshot, params: CodeActionParams) -> Result<Option<CodeActionResponse>> {
    let Some((part, range)) = snapshot.file_range(&params.text_document.uri, params.range) else {
        return Ok(None);
    };
    let range = FileRange {
        file: part.file,
        range,
    };
    let actions = code_actions(&snapshot.db, range, &CodeActionsConfig::default())
        .into_iter()
        .map(|action| {
            let mut changes: HashMap<_, Vec<TextEdit>> = HashMap::new();
            for (file, edits) in action.change.edits {
                for edit in edits {
                    if let Some(location) = snapshot.file_location(file, edit.range) {
                        changes.entry(location.uri).or_default().push(TextEdit {
                            range: location.range,
                            new_text: edit.insert,
                        });
                    }
                }
            }
            CodeActionOrCommand::CodeAction(CodeAction {
                title: action.title,
                kind: Some(CodeActionKind::QUICKFIX),
                edit: Some(WorkspaceEdit {
                    changes: Some(changes),
                    ..WorkspaceEdit::default()
                }),
                ..CodeAction::default()
            })
        })
        .collect();
    Ok(Some(actions))
}
