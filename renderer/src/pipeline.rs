//! Source to pixels, for the CLI and the Typst plugin: `analysis::check` reports the
//! scene's problems or produces its description, and the renderer draws it. Every failure
//! comes back as diagnostics with the sources needed to print them.

use crate::image::Image;
use crate::options::RenderOptions;
use analysis::{EvalOptions, FileSource, Message, Sources};
use syntax::{Diagnostic, TextRange};

/// A finished render with what the scene printed and warned about.
#[derive(Debug, Clone)]
pub struct Rendered {
    pub image: Image,
    /// `#debug` text, in order.
    pub messages: Vec<Message>,
    pub warnings: Vec<Diagnostic>,
    /// Every file the scene read, to print the warnings with.
    pub sources: Sources,
    /// Files the scene wrote with `#fopen`/`#write`, by name; the front end decides where
    /// (and whether) they reach a disk.
    pub written: std::collections::BTreeMap<String, String>,
}

impl Rendered {
    /// The warnings as gcc-style text with source excerpts; empty when there are none.
    pub fn warnings_to_human(&self) -> String {
        syntax::diagnostic::render_human(&self.warnings, &self.sources)
    }
}

/// Why a scene did not render: its errors (and any warnings before them).
#[derive(Debug, Clone)]
pub struct Failure {
    pub diagnostics: Vec<Diagnostic>,
    pub sources: Sources,
    /// The `#debug` text printed before the failure, which POV-Ray users expect to see.
    pub messages: Vec<Message>,
}

impl Failure {
    /// The diagnostics as gcc-style text with source excerpts.
    pub fn to_human(&self) -> String {
        syntax::diagnostic::render_human(&self.diagnostics, &self.sources)
    }
}

/// Evaluates the scene file `main` (read through `files`) and renders it.
pub fn render_source(
    main: &str,
    files: &dyn FileSource,
    options: &RenderOptions,
) -> Result<Rendered, Failure> {
    let eval_options = EvalOptions {
        image_width: options.width,
        image_height: options.height,
        clock: options.clock.unwrap_or(0.0),
        clock_on: options.clock.is_some(),
        declared: options.declared.clone(),
        ..EvalOptions::default()
    };
    render_source_with(main, files, options, &eval_options)
}

/// [`render_source`] with the evaluation's options given, for front ends that know more
/// than the picture options say: the frame of an animation and its clock range.
pub fn render_source_with(
    main: &str,
    files: &dyn FileSource,
    options: &RenderOptions,
    eval_options: &EvalOptions,
) -> Result<Rendered, Failure> {
    // Evaluated without the renderer's check: the render that follows builds the world
    // and stops on the very errors that check reports.
    let evaluation = analysis::evaluate_with(main, files, eval_options, &crate::SceneGeometry);
    let scene = match evaluation.scene {
        Some(scene) if !evaluation.diagnostics.iter().any(Diagnostic::is_error) => scene,
        _ => {
            return Err(Failure {
                diagnostics: evaluation.diagnostics,
                sources: evaluation.sources,
                messages: evaluation.messages,
            });
        }
    };
    match crate::render::render_with_warnings(&scene, options) {
        Ok((image, found)) => {
            let mut warnings = evaluation.diagnostics;
            warnings.extend(found.into_iter().map(|(message, origin)| match origin {
                Some(span) => Diagnostic::warning(span.file, span.range, message),
                None => Diagnostic::warning(main, TextRange::default(), message),
            }));
            Ok(Rendered {
                image,
                messages: evaluation.messages,
                warnings,
                sources: evaluation.sources,
                written: evaluation.written,
            })
        }
        Err(error) => {
            let mut diagnostics = evaluation.diagnostics;
            diagnostics.push(error.diagnostic(main));
            Err(Failure {
                diagnostics,
                sources: evaluation.sources,
                messages: evaluation.messages,
            })
        }
    }
}
