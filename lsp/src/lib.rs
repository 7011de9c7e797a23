//! The Povrayst language server: speaks the language server protocol over stdio and answers
//! from the analysis database. Only this crate knows LSP types.
//!
//! Three kinds of threads cooperate. The protocol runs on tokio (tower-lsp-server), whose
//! handlers stay thin: notifications that change documents go, in the order they arrived,
//! to the main loop, the one thread that writes to the database; requests ask the main
//! loop for a snapshot (a clone of the database taken after every earlier edit) and run
//! their feature on a blocking thread, where a panic becomes an error answer and a
//! cancellation a "content modified" one. After each batch of edits the main loop starts
//! a diagnostics job on its own snapshot, and a publisher task sends the results in order.
//!
//! For clients: documents with the language id `povray` (or a `.pov`, `.inc`, `.mcr`
//! name) are scenes; `typst` documents (`.typ`) are served inside their ```` ```povray ````
//! blocks only. `initializationOptions` and `workspace/didChangeConfiguration` take
//! `{"libraryPaths": ["/usr/share/povray-3.7/include"]}` (POV-Ray's `+L`). Two requests of
//! our own: `povrayst/render` with `{textDocument, width, height, position?}` answers
//! `{png, width, height}` (base64 PNG) or an error carrying `povrayst check`'s report;
//! `povrayst/crashTest` panics on purpose, to show a failing request does not stop the
//! server.

mod bundled;
mod convert;
mod documents;
mod handlers;
mod main_loop;
mod publisher;
mod server;
mod snapshot;

use tower_lsp_server::LspService;

/// Runs the language server on stdin and stdout until the client says `exit` or closes
/// the connection.
pub fn run_stdio() -> std::io::Result<()> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()?;
    runtime.block_on(async {
        let (service, socket) = LspService::build(server::Server::new)
            .custom_method("povrayst/render", server::Server::render)
            .custom_method("povrayst/crashTest", server::Server::crash_test)
            .finish();
        tower_lsp_server::Server::new(tokio::io::stdin(), tokio::io::stdout(), socket)
            .serve(service)
            .await;
    });
    Ok(())
}
