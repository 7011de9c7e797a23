//! Sends diagnostics to the client in order. Diagnostics jobs finish in any order; each
//! result carries the generation of the edits it saw, and a result older than one already
//! sent for the same document is dropped, so the editor never goes back in time.

use std::collections::HashMap;
use tokio::sync::mpsc;
use tower_lsp_server::Client;
use tower_lsp_server::ls_types::{Diagnostic, Uri};

/// The diagnostics of one document as of one generation of edits.
#[derive(Debug)]
pub struct Publication {
    pub uri: Uri,
    pub version: Option<i32>,
    pub generation: u64,
    pub diagnostics: Vec<Diagnostic>,
}

/// Where jobs hand their results.
#[derive(Debug, Clone)]
pub struct Publisher {
    sender: mpsc::UnboundedSender<Publication>,
}

impl Publisher {
    /// Starts the publishing task on the current tokio runtime.
    pub fn spawn(client: Client) -> Publisher {
        let (sender, mut receiver) = mpsc::unbounded_channel::<Publication>();
        tokio::spawn(async move {
            let mut latest: HashMap<Uri, u64> = HashMap::new();
            while let Some(publication) = receiver.recv().await {
                let newest = latest.entry(publication.uri.clone()).or_default();
                if *newest > publication.generation {
                    continue;
                }
                *newest = publication.generation;
                client
                    .publish_diagnostics(
                        publication.uri,
                        publication.diagnostics,
                        publication.version,
                    )
                    .await;
            }
        });
        Publisher { sender }
    }

    pub fn publish(&self, publication: Publication) {
        // The task only ends with the runtime, when nobody listens any more.
        let _ = self.sender.send(publication);
    }
}
