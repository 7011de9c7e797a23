//! The protocol front: tower-lsp-server calls these methods, and each one only forwards.
//! Document notifications go to the main loop before the method first awaits, so they
//! keep the order they arrived in; requests run their handler on a snapshot.

use crate::handlers;
use crate::main_loop::{Event, MainLoopHandle};
use crate::publisher::Publisher;
use crate::snapshot::Snapshot;
use serde::Deserialize;
use std::panic::AssertUnwindSafe;
use std::path::PathBuf;
use tower_lsp_server::jsonrpc::{Error, ErrorCode, Result};
use tower_lsp_server::ls_types::*;
use tower_lsp_server::{Client, LanguageServer};

pub struct Server {
    main_loop: MainLoopHandle,
}

/// What clients may pass in `initializationOptions` and `workspace/didChangeConfiguration`.
#[derive(Debug, Default, Deserialize)]
#[serde(rename_all = "camelCase", default)]
struct Settings {
    /// Directories searched for includes after the scene's own, as POV-Ray's `+L`.
    library_paths: Vec<PathBuf>,
}

impl Settings {
    fn from_value(value: Option<serde_json::Value>) -> Option<Settings> {
        let value = value?;
        // Accept both the bare settings and settings under a "povrayst" section.
        let section = value.get("povrayst").cloned().unwrap_or(value);
        serde_json::from_value(section).ok()
    }
}

impl Server {
    pub fn new(client: Client) -> Server {
        let publisher = Publisher::spawn(client);
        Server {
            main_loop: MainLoopHandle::spawn(publisher),
        }
    }

    /// Runs a request's handler on a snapshot, on a blocking thread. A panic becomes an
    /// internal error and a cancellation (a newer edit) "content modified"; either way the
    /// server goes on.
    async fn run<P, R>(&self, params: P, handler: fn(Snapshot, P) -> Result<R>) -> Result<R>
    where
        P: Send + 'static,
        R: Send + 'static,
    {
        let Some(snapshot) = self.main_loop.snapshot().await else {
            return Err(Error::internal_error());
        };
        let answer = tokio::task::spawn_blocking(move || {
            std::panic::catch_unwind(AssertUnwindSafe(|| handler(snapshot, params)))
        })
        .await;
        match answer {
            Ok(Ok(result)) => result,
            Ok(Err(payload)) if payload.is::<salsa::Cancelled>() => Err(Error {
                code: ErrorCode::ContentModified,
                message: "the document changed; ask again".into(),
                data: None,
            }),
            Ok(Err(payload)) => Err(Error {
                code: ErrorCode::InternalError,
                message: format!("povrayst panicked: {}", panic_message(payload.as_ref())).into(),
                data: None,
            }),
            Err(error) => Err(Error {
                code: ErrorCode::InternalError,
                message: format!("povrayst: the request's task failed: {error}").into(),
                data: None,
            }),
        }
    }

    /// `povrayst/render`: a PNG of a scene, for editor previews.
    pub async fn render(
        &self,
        params: handlers::render::RenderParams,
    ) -> Result<handlers::render::RenderResult> {
        self.run(params, handlers::render::handle).await
    }

    /// `povrayst/crashTest`: panics inside a request on purpose, so that clients and tests
    /// can see that one failing request is answered with an error and the server goes on.
    pub async fn crash_test(&self) -> Result<()> {
        self.run((), |_, ()| panic!("crash test requested by the client"))
            .await
    }
}

pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown cause".to_owned())
}

impl LanguageServer for Server {
    async fn initialize(&self, params: InitializeParams) -> Result<InitializeResult> {
        if let Some(settings) = Settings::from_value(params.initialization_options) {
            self.main_loop.send(Event::Configure {
                library_paths: settings.library_paths,
            });
        }
        Ok(InitializeResult {
            capabilities: handlers::capabilities(),
            server_info: Some(ServerInfo {
                name: "povrayst".to_owned(),
                version: Some(env!("CARGO_PKG_VERSION").to_owned()),
            }),
            ..InitializeResult::default()
        })
    }

    async fn shutdown(&self) -> Result<()> {
        Ok(())
    }

    async fn did_open(&self, params: DidOpenTextDocumentParams) {
        let document = params.text_document;
        self.main_loop.send(Event::Open {
            uri: document.uri,
            language_id: document.language_id,
            version: document.version,
            text: document.text,
        });
    }

    async fn did_change(&self, params: DidChangeTextDocumentParams) {
        self.main_loop.send(Event::Change {
            uri: params.text_document.uri,
            version: params.text_document.version,
            changes: params.content_changes,
        });
    }

    async fn did_close(&self, params: DidCloseTextDocumentParams) {
        self.main_loop.send(Event::Close {
            uri: params.text_document.uri,
        });
    }

    async fn did_change_watched_files(&self, params: DidChangeWatchedFilesParams) {
        self.main_loop.send(Event::DiskChanged(params.changes));
    }

    async fn hover(&self, params: HoverParams) -> Result<Option<Hover>> {
        self.run(params, handlers::hover::handle).await
    }

    async fn goto_definition(
        &self,
        params: GotoDefinitionParams,
    ) -> Result<Option<GotoDefinitionResponse>> {
        self.run(params, handlers::goto_definition::handle).await
    }

    async fn references(&self, params: ReferenceParams) -> Result<Option<Vec<Location>>> {
        self.run(params, handlers::references::handle).await
    }

    async fn prepare_rename(
        &self,
        params: TextDocumentPositionParams,
    ) -> Result<Option<PrepareRenameResponse>> {
        self.run(params, handlers::rename::prepare).await
    }

    async fn rename(&self, params: RenameParams) -> Result<Option<WorkspaceEdit>> {
        self.run(params, handlers::rename::handle).await
    }

    async fn document_symbol(
        &self,
        params: DocumentSymbolParams,
    ) -> Result<Option<DocumentSymbolResponse>> {
        self.run(params, handlers::document_symbols::handle).await
    }

    async fn symbol(
        &self,
        params: WorkspaceSymbolParams,
    ) -> Result<Option<WorkspaceSymbolResponse>> {
        self.run(params, handlers::workspace_symbols::handle).await
    }

    async fn document_link(&self, params: DocumentLinkParams) -> Result<Option<Vec<DocumentLink>>> {
        self.run(params, handlers::document_links::handle).await
    }

    async fn completion(&self, params: CompletionParams) -> Result<Option<CompletionResponse>> {
        self.run(params, handlers::completion::handle).await
    }

    async fn signature_help(&self, params: SignatureHelpParams) -> Result<Option<SignatureHelp>> {
        self.run(params, handlers::signature_help::handle).await
    }

    async fn semantic_tokens_full(
        &self,
        params: SemanticTokensParams,
    ) -> Result<Option<SemanticTokensResult>> {
        self.run(params, handlers::semantic_tokens::handle).await
    }

    async fn folding_range(&self, params: FoldingRangeParams) -> Result<Option<Vec<FoldingRange>>> {
        self.run(params, handlers::folding_ranges::handle).await
    }

    async fn document_color(&self, params: DocumentColorParams) -> Result<Vec<ColorInformation>> {
        self.run(params, handlers::document_colours::colours).await
    }

    async fn color_presentation(
        &self,
        params: ColorPresentationParams,
    ) -> Result<Vec<ColorPresentation>> {
        self.run(params, handlers::document_colours::presentations)
            .await
    }

    async fn inlay_hint(&self, params: InlayHintParams) -> Result<Option<Vec<InlayHint>>> {
        self.run(params, handlers::inlay_hints::handle).await
    }

    async fn code_action(&self, params: CodeActionParams) -> Result<Option<CodeActionResponse>> {
        self.run(params, handlers::code_actions::handle).await
    }

    async fn formatting(&self, params: DocumentFormattingParams) -> Result<Option<Vec<TextEdit>>> {
        self.run(params, handlers::formatting::handle).await
    }

    async fn did_change_configuration(&self, params: DidChangeConfigurationParams) {
        if let Some(settings) = Settings::from_value(Some(params.settings)) {
            self.main_loop.send(Event::Configure {
                library_paths: settings.library_paths,
            });
        }
    }
}
