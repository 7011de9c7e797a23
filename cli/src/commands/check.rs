//! `povrayst check PATH...`: evaluates each scene as the renderer would, lints it, and
//! reports what it found in one of four formats. Paths may be scene files, directories
//! (searched recursively for `.pov` files) and glob patterns. Scenes are checked in
//! parallel and reported in the order named.
//!
//! A scene with errors reports just its errors, the same text a render or a Typst compile
//! shows; the lints (unused declarations, shadowed identifiers, legacy syntax, a missing
//! `#version`, misspelt keywords) come on scenes that evaluate cleanly.
//!
//! Exit status: 0 when no scene has an error (and, under `--deny warnings`, no warning);
//! 1 when one has; 2 for bad arguments and files that cannot be read.

use crate::Outcome;
use crate::disk_files::DiskFiles;
use crate::scene_paths;
use analysis::{EvalOptions, Sources};
use clap::{Args, ValueEnum};
use rayon::prelude::*;
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use syntax::Diagnostic;
use syntax::diagnostic::{Format, SourceResolver};

#[derive(Args, Debug)]
pub struct CheckArgs {
    /// Scene files, directories (searched recursively for .pov files) and glob patterns.
    #[arg(required = true, value_name = "PATH")]
    paths: Vec<String>,
    /// A directory to search for include files after the scene's own (POV-Ray's +L).
    #[arg(short = 'L', long = "library-path", value_name = "DIR")]
    library_paths: Vec<PathBuf>,
    /// How to report: human (gcc-style, on stderr), json, sarif or github (workflow
    /// annotations), the last three on stdout.
    #[arg(long, default_value_t = Format::Human, value_parser = parse_format)]
    format: Format,
    /// Treat warnings as errors for the exit status.
    #[arg(long, value_enum, value_name = "KIND")]
    deny: Vec<Deny>,
}

/// What `--deny` can turn into failures.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Deny {
    Warnings,
}

fn parse_format(name: &str) -> Result<Format, String> {
    name.parse()
}

/// One scene's findings and the texts they point into.
struct Report {
    debug_text: String,
    diagnostics: Vec<Diagnostic>,
    sources: Sources,
}

pub fn run(args: &CheckArgs) -> Outcome {
    let scenes = match scene_paths::expand(&args.paths, scene_paths::SCENES) {
        Ok(scenes) => scenes,
        Err(error) => {
            eprintln!("povrayst: {error}");
            return Outcome::UsageOrIo;
        }
    };
    for scene in &scenes {
        if scene.to_str().is_none() {
            eprintln!("povrayst: {}: the file name is not UTF-8", scene.display());
            return Outcome::UsageOrIo;
        }
    }
    let reports: Vec<Report> = scenes
        .par_iter()
        .map(|scene| check_scene(scene, &args.library_paths))
        .collect();

    // A warning in an include shared by many scenes is reported once.
    let mut seen = HashSet::new();
    let mut diagnostics = Vec::new();
    for report in &reports {
        let fresh: Vec<Diagnostic> = report
            .diagnostics
            .iter()
            .filter(|diagnostic| seen.insert(*diagnostic))
            .cloned()
            .collect();
        if args.format == Format::Human {
            eprint!("{}", report.debug_text);
            eprint!(
                "{}",
                syntax::diagnostic::render_human(&fresh, &report.sources)
            );
        }
        diagnostics.extend(fresh);
    }
    let errors = diagnostics.iter().filter(|d| d.is_error()).count();
    let warnings = diagnostics.len() - errors;
    match args.format {
        Format::Human if scenes.len() > 1 => eprintln!(
            "checked {} scenes: {errors} {}, {warnings} {}",
            scenes.len(),
            plural(errors, "error"),
            plural(warnings, "warning")
        ),
        Format::Human => {}
        format => {
            let sources: Vec<&Sources> = reports.iter().map(|r| &r.sources).collect();
            print!(
                "{}",
                syntax::diagnostic::render(format, &diagnostics, &AnySources(&sources))
            );
        }
    }
    let deny_warnings = args.deny.contains(&Deny::Warnings);
    if errors > 0 || (deny_warnings && warnings > 0) {
        Outcome::SceneErrors
    } else {
        Outcome::Success
    }
}

fn check_scene(scene: &Path, library_paths: &[PathBuf]) -> Report {
    let name = scene.to_str().unwrap_or_default();
    let files = DiskFiles::for_scene(scene, library_paths);
    let evaluation = analysis::check_with(
        name,
        &files,
        &EvalOptions::default(),
        &renderer::SceneGeometry,
    );
    let mut diagnostics = evaluation.diagnostics.clone();
    let clean = !evaluation.has_errors();
    let debug_text = evaluation.debug_text();
    let mut sources = evaluation.sources;
    if clean {
        let linted = analysis::lint::lint(name, &files);
        diagnostics.extend(linted.warnings);
        for (file, text) in linted.sources.iter() {
            sources.insert(file, text.clone());
        }
    }
    // Include names become the paths they were found at, so that a report over scenes in
    // several directories says which `shapes.inc` it means.
    let path_of = |file: &str| -> String {
        match files.locate(file) {
            Some(path) if file != name => {
                let path = path.to_string_lossy();
                path.strip_prefix("./").unwrap_or(&path).to_owned()
            }
            _ => file.to_owned(),
        }
    };
    for diagnostic in &mut diagnostics {
        diagnostic.span.file = path_of(&diagnostic.span.file);
        for related in &mut diagnostic.related {
            related.span.file = path_of(&related.span.file);
        }
    }
    let mut renamed = Sources::default();
    for (file, text) in sources.iter() {
        renamed.insert(&path_of(file), text.clone());
    }
    Report {
        debug_text,
        diagnostics,
        sources: renamed,
    }
}

fn plural(count: usize, word: &str) -> String {
    if count == 1 {
        word.to_owned()
    } else {
        format!("{word}s")
    }
}

/// The texts of every scene's files. Files found on disk are named by their paths, and the
/// standard includes are the same for every scene, so the first text found is the right one.
struct AnySources<'s>(&'s [&'s Sources]);

impl SourceResolver for AnySources<'_> {
    fn source(&self, file: &str) -> Option<&str> {
        self.0.iter().find_map(|sources| sources.source(file))
    }
}
