//! The bundled standard includes as files an editor can open: written once to a cache
//! directory, so that go-to-definition and document links into `colors.inc` land somewhere
//! real. The database keeps knowing them as bundled files.

use std::path::{Path, PathBuf};
use tower_lsp_server::ls_types::Uri;

#[derive(Debug, Clone)]
pub struct BundledFiles {
    dir: PathBuf,
}

impl BundledFiles {
    /// Under `$XDG_CACHE_HOME` (or `~/.cache`, or the temporary directory), one directory
    /// per Povrayst version, so that an upgrade never shows stale text.
    pub fn new() -> Self {
        let cache = std::env::var_os("XDG_CACHE_HOME")
            .map(PathBuf::from)
            .or_else(|| std::env::var_os("HOME").map(|home| Path::new(&home).join(".cache")))
            .unwrap_or_else(std::env::temp_dir);
        BundledFiles {
            dir: cache
                .join("povrayst")
                .join(format!("stdinc-{}", env!("CARGO_PKG_VERSION"))),
        }
    }

    /// The URI of a bundled include, writing the file first when it is missing or differs.
    pub fn uri(&self, name: &str) -> Option<Uri> {
        let text = analysis::stdinc::get(name)?;
        let path = self.dir.join(name);
        if std::fs::read_to_string(&path).ok().as_deref() != Some(text) {
            std::fs::create_dir_all(&self.dir).ok()?;
            std::fs::write(&path, text).ok()?;
        }
        Uri::from_file_path(&path)
    }

    /// The bundled include a path of the cache directory stands for.
    pub fn name_of(&self, path: &Path) -> Option<&'static str> {
        let name = path.strip_prefix(&self.dir).ok()?.to_str()?;
        analysis::stdinc::names().find(|bundled| *bundled == name)
    }
}
