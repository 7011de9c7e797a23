//! `povrayst render SCENE [OPTION|FILE.ini]... -o OUT.png`: renders a scene to a PNG file
//! with the options of the Typst package (`--width`, `--aa-threshold`, ...) and POV-Ray's
//! own, on the command line (`+W640 +H480 +A0.3 +Q9`, `Width=640`), in `.ini` files and
//! with `--extra`. Animations (`+KFI1 +KFF30`, `Final_Frame=30`) render each frame to a
//! file whose name carries the frame number; `--frames A-B` and `--tile i/n` render a
//! part, for job arrays. A progress bar is drawn when standard error is a terminal.
//! Files appear whole or not at all: each is written beside its destination and renamed.

use crate::Outcome;
use crate::animation::{Animation, Frame};
use crate::disk_files::DiskFiles;
use crate::invocation::Invocation;
use crate::progress::Progress;
use crate::render_flags::RenderFlags;
use crate::tiles::Tile;
use analysis::EvalOptions;
use clap::Args;
use renderer::{Image, RenderOptions};
use std::path::{Path, PathBuf};

#[derive(Args, Debug)]
pub struct RenderArgs {
    /// The scene file, POV-Ray options (`+W640 +H480 +A0.3`, `Width=640`) and `.ini` files,
    /// applied left to right after the flags. Options that start with `-` go after `--`.
    #[arg(required = true, value_name = "SCENE|OPTION|FILE.ini")]
    inputs: Vec<String>,
    /// The PNG file to write; the scene's name with `.png` by default. Frames of an
    /// animation get their number before the extension, tiles `.tile-I-of-N`.
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
    /// Render only these frames of the animation (`5-9`, or `7`), as +SF/+EF do.
    #[arg(long, value_name = "A-B")]
    frames: Option<String>,
    /// Render only horizontal band I of N (from 1) to its own file; `povrayst stitch`
    /// joins the bands.
    #[arg(long, value_name = "I/N", value_parser = Tile::parse)]
    tile: Option<Tile>,
}

/// Everything a render needs, read from the arguments.
struct Job {
    scene: PathBuf,
    output: PathBuf,
    library_paths: Vec<PathBuf>,
    options: RenderOptions,
    animation: Animation,
    frames: Vec<Frame>,
}

pub fn run(args: &RenderArgs) -> Outcome {
    let job = match job(args) {
        Ok(job) => job,
        Err(error) => {
            eprintln!("povrayst: {error}");
            return Outcome::UsageOrIo;
        }
    };
    let Some(name) = job.scene.to_str() else {
        eprintln!(
            "povrayst: {}: the file name is not UTF-8",
            job.scene.display()
        );
        return Outcome::UsageOrIo;
    };
    if let Err(error) = std::fs::metadata(&job.scene) {
        eprintln!("povrayst: cannot read {name}: {error}");
        return Outcome::UsageOrIo;
    }
    // `+WTn` limits the threads; the picture is the same with any number.
    if let Some(threads) = job.options.threads {
        match rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
            Ok(pool) => return pool.install(|| render_job(args, &job, name)),
            Err(error) => {
                eprintln!("povrayst: cannot start {threads} threads: {error}");
                return Outcome::UsageOrIo;
            }
        }
    }
    render_job(args, &job, name)
}

/// Renders every frame of `job`, whose scene file is `name`.
fn render_job(args: &RenderArgs, job: &Job, name: &str) -> Outcome {
    let files = DiskFiles::for_scene(&job.scene, &job.library_paths);
    let mut progress = Progress::new(name, job.frames.len());
    for &frame in &job.frames {
        let animated = job.animation.is_animated();
        // A still is frame 0, with the clock of `+K`, as the Typst package renders it.
        let eval_options = EvalOptions {
            image_width: job.options.width,
            image_height: job.options.height,
            clock: if animated {
                frame.clock
            } else {
                job.options.clock.unwrap_or(frame.clock)
            },
            clock_on: animated || job.options.clock.is_some(),
            frame_number: if animated { frame.number } else { 0 },
            initial_frame: job.animation.initial_frame,
            final_frame: job.animation.final_frame,
            initial_clock: job.animation.initial_clock,
            final_clock: job.animation.final_clock,
            declared: job.options.declared.clone(),
            ..EvalOptions::default()
        };
        let rendered =
            renderer::pipeline::render_source_with(name, &files, &job.options, &eval_options);
        progress.clear();
        let rendered = match rendered {
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
        if let Err(outcome) = keep_written_files(&job.scene, &rendered.written) {
            return outcome;
        }
        eprint!("{}", rendered.warnings_to_human());
        let mut output = job.animation.output_for(&job.output, frame);
        let mut image = rendered.image;
        if let Some(tile) = args.tile {
            image = band(&image, tile);
            output = tile.output_for(&output);
        }
        if let Err(error) =
            crate::whole_file::write(&output, &renderer::encode_png(&image, &job.options))
        {
            progress.clear();
            eprintln!("povrayst: cannot write {}: {error}", output.display());
            return Outcome::UsageOrIo;
        }
        progress.step();
    }
    progress.finish();
    Outcome::Success
}

fn job(args: &RenderArgs) -> Result<Job, String> {
    let invocation = Invocation::read(&args.inputs)?;
    let scene = invocation
        .scene
        .clone()
        .ok_or("no scene named: give a .pov file, or Input_File_Name in an .ini file")?;
    let options = render_options(args, &invocation)?;
    let mut animation = invocation.animation.clone();
    if let Some(range) = &args.frames {
        animation
            .apply_frame_range(range)
            .map_err(|error| format!("--frames: {error}"))?;
    }
    let frames = animation.frames()?;
    let output = args
        .output
        .clone()
        .or(invocation.output)
        .unwrap_or_else(|| scene.with_extension("png"));
    let library_paths = invocation
        .library_paths
        .into_iter()
        .chain(args.library_paths.iter().cloned())
        .collect();
    let mut job = Job {
        scene,
        output,
        library_paths,
        options,
        animation,
        frames,
    };
    if let Some(tile) = args.tile {
        let (first, last) = tile.rows(job.options.height).ok_or_else(|| {
            format!(
                "tile {}/{} has no rows in a picture {} rows high",
                tile.index, tile.count, job.options.height
            )
        })?;
        // POV-Ray's rows count from 1.
        job.options
            .apply_povray_option(&format!("Start_Row={}", first + 1))?;
        job.options
            .apply_povray_option(&format!("End_Row={}", last + 1))?;
    }
    Ok(job)
}

/// The package defaults, then the flags, then the POV-Ray options and `.ini` files of the
/// command line, then `--extra`, each through POV-Ray's option parser.
fn render_options(args: &RenderArgs, invocation: &Invocation) -> Result<RenderOptions, String> {
    let mut options = RenderOptions::default();
    for option in args.flags.povray_options() {
        options.apply_povray_option(&option)?;
    }
    for option in &invocation.picture_options {
        options.apply_povray_option(option)?;
    }
    for option in &args.extra {
        options
            .apply_povray_option(option)
            .map_err(|error| format!("--extra: {error}"))?;
    }
    Ok(options)
}

/// The rows of a tile's band, cut out of the full-size picture a partial render fills.
fn band(image: &Image, tile: Tile) -> Image {
    let (first, last) = tile.rows(image.height).unwrap_or((0, 0));
    let width = image.width as usize;
    Image {
        width: image.width,
        height: last - first + 1,
        has_alpha: image.has_alpha,
        pixels: image.pixels[first as usize * width..(last as usize + 1) * width].to_vec(),
    }
}

/// Writes the files the scene wrote with `#write` beside the scene, as POV-Ray writes them
/// relative to where the scene runs. Only plain relative names are allowed, so a scene
/// cannot write outside its own directory.
fn keep_written_files(
    scene: &Path,
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
