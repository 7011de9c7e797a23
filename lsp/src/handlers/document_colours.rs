//! `textDocument/documentColor` and `textDocument/colorPresentation`.

use crate::snapshot::Snapshot;
use analysis::ide::document_colours::{ColourConfig, Rgba, colour_presentation, document_colours};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{
    Color, ColorInformation, ColorPresentation, ColorPresentationParams, DocumentColorParams,
    TextEdit,
};

pub fn colours(snapshot: Snapshot, params: DocumentColorParams) -> Result<Vec<ColorInformation>> {
    let Some(view) = snapshot.document(&params.text_document.uri) else {
        return Ok(Vec::new());
    };
    let mut found = Vec::new();
    for part in &view.parts {
        for literal in document_colours(&snapshot.db, part.file, &ColourConfig::default()) {
            found.push(ColorInformation {
                range: snapshot.part_range(part, literal.range),
                color: Color {
                    red: literal.colour.red as f32,
                    green: literal.colour.green as f32,
                    blue: literal.colour.blue as f32,
                    alpha: literal.colour.alpha as f32,
                },
            });
        }
    }
    Ok(found)
}

pub fn presentations(
    snapshot: Snapshot,
    params: ColorPresentationParams,
) -> Result<Vec<ColorPresentation>> {
    let Some((part, range)) = snapshot.file_range(&params.text_document.uri, params.range) else {
        return Ok(Vec::new());
    };
    let text = part.file.text(&snapshot.db);
    let keyword: String = text
        .get(std::ops::Range::<usize>::from(range))
        .unwrap_or_default()
        .chars()
        .take_while(char::is_ascii_alphabetic)
        .collect();
    let colour = Rgba {
        red: f64::from(params.color.red),
        green: f64::from(params.color.green),
        blue: f64::from(params.color.blue),
        alpha: f64::from(params.color.alpha),
    };
    let label = colour_presentation(&keyword, colour, &ColourConfig::default());
    Ok(vec![ColorPresentation {
        label: label.clone(),
        text_edit: Some(TextEdit {
            range: params.range,
            new_text: label,
        }),
        additional_text_edits: None,
    }])
}
