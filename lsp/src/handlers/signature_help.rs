//! `textDocument/signatureHelp`.

use crate::snapshot::Snapshot;
use analysis::ide::signature_help::{SignatureHelpConfig, signature_help};
use tower_lsp_server::jsonrpc::Result;
use tower_lsp_server::ls_types::{
    Documentation, ParameterInformation, ParameterLabel, SignatureHelp, SignatureHelpParams,
    SignatureInformation,
};

pub fn handle(snapshot: Snapshot, params: SignatureHelpParams) -> Result<Option<SignatureHelp>> {
    let at = &params.text_document_position_params;
    let Some((_, position)) = snapshot.analysis_position(&at.text_document.uri, at.position) else {
        return Ok(None);
    };
    Ok(
        signature_help(&snapshot.db, position, &SignatureHelpConfig::default()).map(|help| {
            SignatureHelp {
                signatures: vec![SignatureInformation {
                    label: help.label,
                    documentation: help.documentation.map(Documentation::String),
                    parameters: Some(
                        help.parameters
                            .into_iter()
                            .map(|p| ParameterInformation {
                                label: ParameterLabel::Simple(p),
                                documentation: None,
                            })
                            .collect(),
                    ),
                    active_parameter: help.active_parameter,
                }],
                active_signature: Some(0),
                active_parameter: help.active_parameter,
            }
        }),
    )
}
