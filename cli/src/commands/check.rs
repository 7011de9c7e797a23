//! `povrayst check FILE...`: evaluates each scene as the renderer would and prints what is
//! wrong, gcc-style, on stderr, after the scene's own `#debug` output, as POV-Ray shows it.

use crate::Outcome;
use crate::disk_files::DiskFiles;
use analysis::EvalOptions;
use clap::Args;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub struct CheckArgs {
    /// Scene files to check.
    #[arg(required = true)]
    files: Vec<PathBuf>,
    /// A directory to search for include files after the scene's own (POV-Ray's +L).
    #[arg(short = 'L', long = "library-path", value_name = "DIR")]
    library_paths: Vec<PathBuf>,
}

pub fn run(args: &CheckArgs) -> Outcome {
    let mut outcome = Outcome::Success;
    for file in &args.files {
        let Some(name) = file.to_str() else {
            eprintln!("povrayst: {}: the file name is not UTF-8", file.display());
            return Outcome::UsageOrIo;
        };
        if let Err(error) = std::fs::metadata(file) {
            eprintln!("povrayst: cannot read {name}: {error}");
            return Outcome::UsageOrIo;
        }
        let files = DiskFiles::for_scene(file, &args.library_paths);
        let evaluation = analysis::check(name, &files, &EvalOptions::default());
        eprint!("{}", evaluation.debug_text());
        eprint!(
            "{}",
            syntax::diagnostic::render_human(&evaluation.diagnostics, &evaluation.sources)
        );
        if evaluation.has_errors() {
            outcome = Outcome::SceneErrors;
        }
    }
    outcome
}
