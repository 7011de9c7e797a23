//! Turns SDL source into meaning: the evaluator that runs directives, macros and expressions
//! and produces a [`scene::Scene`], the compiled `function { }` form, and the incremental
//! analysis database that the language server queries.

#[cfg(feature = "ide")]
pub mod db;
pub mod eval;
pub mod files;
mod floor;
pub mod font;
pub mod format;
pub mod function;
pub mod geometry;
#[cfg(feature = "ide")]
pub mod ide;
pub mod image;
pub mod lint;
pub mod noise;
pub mod pattern;
pub mod scene;
pub mod spelling;
pub mod spline;
pub mod stdinc;
pub mod trig;

pub use eval::{Budgets, EvalOptions, Evaluation, Message, Stream, evaluate, evaluate_with};
pub use files::{DirectoryFiles, FileSource, MemoryFiles, Sources};
pub use geometry::{Geometry, InsideTest, NoGeometry, Tracer};

/// Checks a scene the way every front end does: the syntax errors of the main file first;
/// when there are none, the evaluator's findings. The CLI's `check`, the renderer pipeline,
/// the Typst plugin and the language server all call this, so they report the same errors.
pub fn check(main: &str, files: &dyn FileSource, options: &EvalOptions) -> Evaluation {
    evaluate(main, files, options)
}

/// [`check`] with a renderer answering `trace()`, `inside()` and the extents, and telling
/// what in the scene it would refuse to draw ([`Geometry::render_error`]).
pub fn check_with(
    main: &str,
    files: &dyn FileSource,
    options: &EvalOptions,
    geometry: &dyn Geometry,
) -> Evaluation {
    let mut evaluation = evaluate_with(main, files, options, geometry);
    if !evaluation.has_errors()
        && let Some(scene) = &evaluation.scene
        && let Some(error) = geometry.render_error(main, scene)
    {
        evaluation.diagnostics.push(error);
    }
    evaluation
}

/// The syntax errors of one file's text, as diagnostics located in `name`.
pub fn syntax_errors(name: &str, text: &str) -> Vec<syntax::Diagnostic> {
    syntax::syntax_errors(text)
        .into_iter()
        .map(|error| syntax::Diagnostic::error(name, error.range, error.message))
        .collect()
}
