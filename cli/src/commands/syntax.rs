//! `povrayst syntax FILE`: prints the lossless syntax tree, one node or token a line with its
//! byte range, and the syntax errors gcc-style on stderr.

use crate::Outcome;
use clap::Args;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub struct SyntaxArgs {
    /// The scene or include file.
    file: PathBuf,
}

pub fn run(args: &SyntaxArgs) -> Outcome {
    let name = args.file.display().to_string();
    let text = match analysis::files::read_sdl_file(&args.file) {
        Ok(text) => text,
        Err(error) => {
            eprintln!("povrayst: cannot read {name}: {error}");
            return Outcome::UsageOrIo;
        }
    };
    let parse = syntax::parse(&text);
    print!("{}", parse.debug_tree());
    let diagnostics = syntax::syntax_diagnostics(&name, &parse);
    let sources: &[(&str, &str)] = &[(&name, &text)];
    eprint!(
        "{}",
        syntax::diagnostic::render_human(&diagnostics, sources)
    );
    if parse.errors().is_empty() {
        Outcome::Success
    } else {
        Outcome::SceneErrors
    }
}
