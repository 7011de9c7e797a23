//! `textDocument/semanticTokens/full`: our highlights in the protocol's relative encoding,
//! one token per line of a token that spans lines.

use crate::convert;
use crate::snapshot::Snapshot;
use analysis::ide::semantic_tokens::{HighlightTag, SemanticTokensConfig, semantic_tokens};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{
    SemanticToken, SemanticTokenModifier, SemanticTokenType, SemanticTokens, SemanticTokensLegend,
    SemanticTokensParams, SemanticTokensResult,
};

/// The token types, in the order their indices refer to.
const TYPES: &[SemanticTokenType] = &[
    SemanticTokenType::COMMENT,
    SemanticTokenType::STRING,
    SemanticTokenType::NUMBER,
    SemanticTokenType::KEYWORD,
    SemanticTokenType::MACRO,
    SemanticTokenType::FUNCTION,
    SemanticTokenType::VARIABLE,
    SemanticTokenType::PARAMETER,
    SemanticTokenType::OPERATOR,
];

const MODIFIERS: &[SemanticTokenModifier] = &[
    SemanticTokenModifier::DECLARATION,
    SemanticTokenModifier::DEFAULT_LIBRARY,
    SemanticTokenModifier::READONLY,
];

pub fn legend() -> SemanticTokensLegend {
    SemanticTokensLegend {
        token_types: TYPES.to_vec(),
        token_modifiers: MODIFIERS.to_vec(),
    }
}

pub fn handle(
    snapshot: Snapshot,
    params: SemanticTokensParams,
) -> Result<Option<SemanticTokensResult>> {
    let Some(view) = snapshot.document(&params.text_document.uri) else {
        return Ok(None);
    };
    let mut absolute: Vec<(u32, u32, u32, u32, u32)> = Vec::new();
    for part in &view.parts {
        for highlight in semantic_tokens(&snapshot.db, part.file, &SemanticTokensConfig::default())
        {
            let (kind, mut modifiers) = match highlight.tag {
                HighlightTag::Comment => (0, 0),
                HighlightTag::String => (1, 0),
                HighlightTag::Number => (2, 0),
                HighlightTag::Keyword => (3, 0),
                HighlightTag::Directive => (4, 0),
                HighlightTag::Function => (5, 0b010),
                HighlightTag::Constant => (6, 0b110),
                HighlightTag::Variable => (6, 0),
                HighlightTag::Macro => (5, 0),
                HighlightTag::Parameter => (7, 0),
                HighlightTag::Operator => (8, 0),
            };
            if highlight.definition {
                modifiers |= 0b001;
            }
            if highlight.library {
                modifiers |= 0b010;
            }
            let range = match &part.block {
                Some(block) => block.to_host_range(highlight.range),
                None => highlight.range,
            };
            // One protocol token per line the token covers.
            let start = convert::position(&view.line_index, &view.text, range.start());
            let end = convert::position(&view.line_index, &view.text, range.end());
            for line in start.line..=end.line {
                let from = if line == start.line {
                    start.character
                } else {
                    0
                };
                let to = if line == end.line {
                    end.character
                } else {
                    let text = view.line_index.line_text(&view.text, line);
                    text.encode_utf16().count() as u32
                };
                if to > from {
                    absolute.push((line, from, to - from, kind, modifiers));
                }
            }
        }
    }
    absolute.sort();
    let mut data = Vec::with_capacity(absolute.len());
    let (mut previous_line, mut previous_start) = (0, 0);
    for (line, start, length, kind, modifiers) in absolute {
        let delta_start = if line == previous_line {
            start - previous_start
        } else {
            start
        };
        data.push(SemanticToken {
            delta_line: line - previous_line,
            delta_start,
            length,
            token_type: kind,
            token_modifiers_bitset: modifiers,
        });
        (previous_line, previous_start) = (line, start);
    }
    Ok(Some(SemanticTokensResult::Tokens(SemanticTokens {
        result_id: None,
        data,
    })))
}
