//! `povrayst`: render, check and inspect POV-Ray scenes.
//!
//! Exit status: 0 when all went well, 1 when a scene has errors, 2 for usage and I/O errors.

mod animation;
mod commands;
mod disk_files;
mod invocation;
mod progress;
mod render_flags;
mod scene_paths;
mod tiles;
mod whole_file;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser, Debug)]
#[command(
    name = "povrayst",
    version,
    about = "POV-Ray scenes: render, check, format, inspect"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Render a scene to a PNG file.
    Render(commands::render::RenderArgs),
    /// Report the errors and warnings of scenes, files, directories or globs.
    Check(commands::check::CheckArgs),
    /// Format SDL files in place, or with --check list those that are not formatted.
    Fmt(commands::fmt::FmtArgs),
    /// Join the bands that `render --tile i/n` wrote into one picture.
    Stitch(commands::stitch::StitchArgs),
    /// Print a scene's syntax tree, and its syntax errors on stderr.
    Syntax(commands::syntax::SyntaxArgs),
    /// Run the language server on stdin and stdout.
    Lsp,
}

/// How a command ended, as the process's exit status.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Outcome {
    Success,
    /// A scene has errors (they have been printed).
    SceneErrors,
    /// Bad arguments or a file that cannot be read or written (said on stderr).
    UsageOrIo,
}

impl From<Outcome> for ExitCode {
    fn from(outcome: Outcome) -> ExitCode {
        ExitCode::from(match outcome {
            Outcome::Success => 0,
            Outcome::SceneErrors => 1,
            Outcome::UsageOrIo => 2,
        })
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Render(args) => commands::render::run(&args),
        Command::Check(args) => commands::check::run(&args),
        Command::Fmt(args) => commands::fmt::run(&args),
        Command::Stitch(args) => commands::stitch::run(&args),
        Command::Syntax(args) => commands::syntax::run(&args),
        Command::Lsp => match lsp::run_stdio() {
            Ok(()) => Outcome::Success,
            Err(error) => {
                eprintln!("povrayst lsp: {error}");
                Outcome::UsageOrIo
            }
        },
    }
    .into()
}
