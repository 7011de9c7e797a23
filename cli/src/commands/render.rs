//! `povrayst render SCENE -o OUT.png`: renders a scene to a PNG file with the options of the
//! Typst package (`--width`, `--aa-threshold`, ...) and POV-Ray's own (`--extra +A0.1`).
//! The file appears whole or not at all: it is written beside its destination and renamed.

use crate::Outcome;
use crate::disk_files::DiskFiles;
use crate::render_flags::RenderFlags;
use clap::Args;
use renderer::RenderOptions;
use std::path::PathBuf;

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// The scene file.
    scene: PathBuf,
    /// The PNG file to write; the scene's name with `.png` by default.
    #[arg(short, long, value_name = "OUT.png")]
    output: Option<PathBuf>,
    #[command(flatten)]
    flags: RenderFlags,
    /// A POV-Ray command-line or .ini option (`+A0.1`, `Jitter=off`), applied after the
    /// flags; repeat for more.
    #[arg(long, value_name = "OPTION", allow_hyphen_values = true)]
    extra: Vec<String>,
    /// A directory to search for include files after the scene's own (POV-Ray's +L).
    #[arg(short = 'L', long = "library-path", value_name = "DIR")]
    library_paths: Vec<PathBuf>,
}

pub fn run(args: &RenderArgs) -> Outcome {
    let options = match render_options(args) {
        Ok(options) => options,
        Err(error) => {
            eprintln!("povrayst: {error}");
            return Outcome::UsageOrIo;
        }
    };
    let Some(name) = args.scene.to_str() else {
        eprintln!(
            "povrayst: {}: the file name is not UTF-8",
            args.scene.display()
        );
        return Outcome::UsageOrIo;
    };
    if let Err(error) = std::fs::metadata(&args.scene) {
        eprintln!("povrayst: cannot read {name}: {error}");
        return Outcome::UsageOrIo;
    }
    let files = DiskFiles::for_scene(&args.scene, &args.library_paths);
    let rendered = match renderer::pipeline::render_source(name, &files, &options) {
        Ok(rendered) => rendered,
        Err(failure) => {
            for message in &failure.messages {
                eprint!("{}", message.text);
            }
            eprint!("{}", failure.to_human());
            return Outcome::SceneErrors;
        }
    };
    for message in &rendered.messages {
        eprint!("{}", message.text);
    }
    if let Err(outcome) = keep_written_files(&args.scene, &rendered.written) {
        return outcome;
    }
    eprint!("{}", rendered.warnings_to_human());
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| args.scene.with_extension("png"));
    match crate::whole_file::write(&output, &renderer::encode_png(&rendered.image, &options)) {
        Ok(()) => Outcome::Success,
        Err(error) => {
            eprintln!("povrayst: cannot write {}: {error}", output.display());
            Outcome::UsageOrIo
        }
    }
}

/// The package defaults, then the flags, then `--extra`, each through POV-Ray's option parser.
fn render_options(args: &RenderArgs) -> Result<RenderOptions, String> {
    let mut options = RenderOptions::default();
    for option in args.flags.povray_options() {
        options.apply_povray_option(&option)?;
    }
    for option in &args.extra {
        options
            .apply_povray_option(option)
            .map_err(|error| format!("--extra: {error}"))?;
    }
    Ok(options)
}

/// Writes the files the scene wrote with `#write` beside the scene, as POV-Ray writes them
/// relative to where the scene runs. Only plain relative names are allowed, so a scene
/// cannot write outside its own directory.
fn keep_written_files(
    scene: &std::path::Path,
    written: &std::collections::BTreeMap<String, String>,
) -> Result<(), Outcome> {
    let dir = match scene.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    for (name, text) in written {
        let path = std::path::Path::new(name);
        let inside = path
            .components()
            .all(|c| matches!(c, std::path::Component::Normal(_)));
        if !inside {
            eprintln!(
                "povrayst: not writing '{name}': scenes may only write files inside their own directory"
            );
            continue;
        }
        if let Err(error) = crate::whole_file::write(&dir.join(path), text.as_bytes()) {
            eprintln!(
                "povrayst: cannot write {}: {error}",
                dir.join(path).display()
            );
            return Err(Outcome::UsageOrIo);
        }
    }
    Ok(())
}
