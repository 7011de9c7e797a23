//! Files that appear whole or not at all: written beside their destination and renamed
//! over it, so that a reader (an image viewer, an editor, a CI step) never sees half a file.

use std::io::Write;
use std::path::Path;

/// Writes `bytes` to a temporary file in the destination's directory and renames it over
/// the destination.
pub fn write(destination: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let file_name = destination
        .file_name()
        .unwrap_or_default()
        .to_string_lossy();
    let temporary =
        destination.with_file_name(format!(".{file_name}.{}.povrayst-tmp", std::process::id()));
    let written = std::fs::File::create_new(&temporary).and_then(|mut file| {
        // A file rewritten in place keeps its permissions.
        if let Ok(existing) = std::fs::metadata(destination) {
            file.set_permissions(existing.permissions())?;
        }
        file.write_all(bytes)?;
        file.sync_all()
    });
    let renamed = written.and_then(|()| std::fs::rename(&temporary, destination));
    if renamed.is_err() {
        // Nothing to do if it was never made.
        let _ = std::fs::remove_file(&temporary);
    }
    renamed
}
