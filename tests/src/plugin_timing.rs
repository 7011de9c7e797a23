//! The plugin as Typst runs it, for the benchmarks: a scene rendered by `try-render` inside
//! a real Typst compile (see `typst_compiler`), timed in CPU seconds less a compile that only
//! loads the plugin, and the picture it hands to Typst, to compare with the native one.
//!
//! Each compile is a fresh compiler process, so that nothing is memoised; a figure is the
//! best of a few. CPU seconds rather than wall time, as the machine is shared and wall time
//! would measure the neighbours. The compile is a query: Typst evaluates and lays out the
//! document, the image included, but writes no PDF.

use crate::typst_compiler::Document;
use serde_json::Value;

/// A scene as the package receives it.
pub struct PluginRender {
    /// The scene's file name, which its text is read from in the document.
    pub name: String,
    pub source: String,
    /// The keyword arguments of the call in Typst syntax (`width: 16, antialias: false`,
    /// `extra: ("+W320", "-A")`), or nothing for the package's defaults.
    pub arguments: String,
    /// Texts the scene may `#include`, by name.
    pub includes: Vec<(String, String)>,
    /// Other files the scene may read (images, fonts, data), by name.
    pub files: Vec<(String, Vec<u8>)>,
}

impl PluginRender {
    /// A document that renders the scene and puts `result`, an expression of the
    /// `try-render` answer `r`, in `<result>`. The file names are quoted with Rust's
    /// escapes, which are Typst's too (`\"`, `\\`, `\u{..}`).
    fn document(&self, result: &str) -> Document {
        let includes: Vec<String> = self
            .includes
            .iter()
            .map(|(name, _)| format!("{name:?}: read({name:?})"))
            .collect();
        let files: Vec<String> = self
            .files
            .iter()
            .map(|(name, _)| format!("{name:?}: read({name:?}, encoding: none)"))
            .collect();
        let main = format!(
            "#import \"@local/povrayst:0.1.0\": try-render\n\
             #let r = try-render(read({:?}), {}, includes: {}, files: {})\n\
             #metadata({result}) <result>\n",
            self.name,
            self.arguments,
            typst_dictionary(&includes),
            typst_dictionary(&files),
        );
        let mut document = Document::new(&main).with_file(&self.name, &self.source);
        for (name, text) in &self.includes {
            document = document.with_file(name, text);
        }
        for (name, bytes) in &self.files {
            document = document.with_file(name, bytes);
        }
        document
    }

    /// The plugin's picture: rows of 8-bit samples (RGB, or RGBA with alpha), top row
    /// first, as it hands them to Typst; or the scene's error.
    pub fn pixels(&self) -> Result<Vec<u8>, String> {
        let document = self.document("if r.error == none { array(r.pixels) } else { r.error }");
        match document.query("<result>").map_err(|e| e.diagnostic)? {
            Value::Array(samples) => samples
                .iter()
                .map(|s| {
                    s.as_u64()
                        .and_then(|s| u8::try_from(s).ok())
                        .ok_or_else(|| format!("not a sample: {s}"))
                })
                .collect(),
            Value::String(error) => Err(error),
            other => Err(format!("neither pixels nor an error: {other}")),
        }
    }
}

/// A Typst dictionary of `entries` (`key: value` each): `(:)` when there are none.
fn typst_dictionary(entries: &[String]) -> String {
    if entries.is_empty() {
        "(:)".to_owned()
    } else {
        format!("({},)", entries.join(", "))
    }
}

/// Times renders through the plugin against the cost of loading it, each figure the best
/// of `runs` compiles.
pub struct PluginTimer {
    runs: usize,
    baseline: f64,
}

impl PluginTimer {
    /// Builds and installs the package on first use (`typst_compiler::package_path`) and
    /// times a compile that only loads the plugin and calls it once.
    pub fn new(runs: usize) -> Result<PluginTimer, String> {
        let load_only = Document::new(
            "#import \"@local/povrayst:0.1.0\": version\n#metadata(version()) <result>\n",
        );
        let (_, baseline) = best_of(runs, &load_only)?;
        Ok(PluginTimer { runs, baseline })
    }

    /// The CPU seconds of the compile that only loads the plugin.
    pub fn baseline_seconds(&self) -> f64 {
        self.baseline
    }

    /// The CPU seconds the render adds to the compile that only loads the plugin.
    pub fn seconds(&self, render: &PluginRender) -> Result<f64, String> {
        let (error, seconds) = best_of(self.runs, &render.document("r.error"))?;
        if !error.is_null() {
            return Err(format!("the scene failed in the plugin: {error}"));
        }
        Ok((seconds - self.baseline).max(0.0))
    }
}

/// The `<result>` of `document` and the least CPU seconds of `runs` fresh compiles (at
/// least one).
fn best_of(runs: usize, document: &Document) -> Result<(Value, f64), String> {
    let mut best: Option<(Value, f64)> = None;
    for _ in 0..runs.max(1) {
        let (value, seconds) = document.timed_query("<result>").map_err(|e| e.diagnostic)?;
        if best.as_ref().is_none_or(|(_, b)| seconds < *b) {
            best = Some((value, seconds));
        }
    }
    Ok(best.expect("at least one compile"))
}
