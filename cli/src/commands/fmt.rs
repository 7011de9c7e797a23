//! `povrayst fmt PATH...`: formats SDL files in place with the language server's formatter
//! (`analysis::format`), which re-indents and tidies whitespace and changes no other token.
//! Directories are searched recursively for `.pov`, `.inc`, `.mcr` and `.mac` files.
//!
//! With `--check` nothing is written: the files that would change are listed and the exit
//! status is 1 if there are any, for CI. Exit status 2 means a file could not be read or
//! written.

use crate::Outcome;
use crate::scene_paths;
use analysis::files::decode_sdl;
use analysis::format::{FormatConfig, format_text};
use clap::Args;

#[derive(Args, Debug)]
pub struct FmtArgs {
    /// Files, directories (searched recursively) and glob patterns.
    #[arg(required = true, value_name = "PATH")]
    paths: Vec<String>,
    /// Write nothing; list the files that are not formatted and fail if there are any.
    #[arg(long)]
    check: bool,
    /// Spaces per level of nesting.
    #[arg(long, default_value_t = FormatConfig::default().indent_width, value_name = "N")]
    indent_width: usize,
}

pub fn run(args: &FmtArgs) -> Outcome {
    let files = match scene_paths::expand(&args.paths, scene_paths::SDL_FILES) {
        Ok(files) => files,
        Err(error) => {
            eprintln!("povrayst: {error}");
            return Outcome::UsageOrIo;
        }
    };
    let config = FormatConfig {
        indent_width: args.indent_width,
        ..FormatConfig::default()
    };
    let mut unformatted = 0;
    for file in &files {
        let (text, latin1) = match std::fs::read(file) {
            Ok(bytes) => decode_sdl(bytes),
            Err(error) => {
                eprintln!("povrayst: cannot read {}: {error}", file.display());
                return Outcome::UsageOrIo;
            }
        };
        let formatted = format_text(&text, &config);
        if formatted == text {
            continue;
        }
        unformatted += 1;
        if args.check {
            eprintln!("not formatted: {}", file.display());
        } else if let Err(error) = write_back(file, &formatted, latin1) {
            eprintln!("povrayst: cannot write {}: {error}", file.display());
            return Outcome::UsageOrIo;
        }
    }
    if args.check && unformatted > 0 {
        eprintln!(
            "{unformatted} of {} files are not formatted; run `povrayst fmt` on them",
            files.len()
        );
        Outcome::SceneErrors
    } else {
        Outcome::Success
    }
}

/// Writes the formatted text in the encoding the file was read in, so that a Latin-1 scene
/// stays Latin-1 (formatting changes only whitespace, so every character still fits).
fn write_back(file: &std::path::Path, text: &str, latin1: bool) -> std::io::Result<()> {
    let bytes = if latin1 {
        text.chars()
            .map(u8::try_from)
            .collect::<Result<Vec<u8>, _>>()
            .map_err(|_| std::io::Error::other("a character outside Latin-1"))?
    } else {
        text.as_bytes().to_vec()
    };
    crate::whole_file::write(file, &bytes)
}
