//! Diagnostics as data: what went wrong, where, and how sure we are. Rendering to text is
//! one module per output format, so that the CLI, the Typst plugin and the language server
//! all show the same words at the same place.

mod format;
mod github;
mod human;
mod json;
mod position;
mod sarif;

pub use format::{Format, render};
pub use github::render_github;
pub use human::render_human;
pub use json::render_json;
pub use sarif::render_sarif;

use rowan::TextRange;
use std::collections::HashMap;

/// How bad a diagnostic is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Severity {
    Warning,
    Error,
}

impl Severity {
    pub fn as_str(self) -> &'static str {
        match self {
            Severity::Warning => "warning",
            Severity::Error => "error",
        }
    }
}

/// A place in one file: the file's name as the user knows it and a byte range in its text.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Span {
    pub file: String,
    pub range: TextRange,
}

/// A secondary place that explains a diagnostic, such as the `#macro` whose arity was wrong.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Related {
    pub span: Span,
    pub message: String,
}

/// One finding about a scene.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub struct Diagnostic {
    /// A stable name for the kind of finding (`unused-declaration`), for machine-readable
    /// output and for turning a lint off; `None` for errors that have no name of their own.
    pub code: Option<&'static str>,
    pub severity: Severity,
    pub message: String,
    pub span: Span,
    pub related: Vec<Related>,
    /// Free-standing hints, printed after the source excerpt.
    pub notes: Vec<String>,
}

impl Diagnostic {
    pub fn error(file: impl Into<String>, range: TextRange, message: impl Into<String>) -> Self {
        Self::new(Severity::Error, file, range, message)
    }

    pub fn warning(file: impl Into<String>, range: TextRange, message: impl Into<String>) -> Self {
        Self::new(Severity::Warning, file, range, message)
    }

    fn new(
        severity: Severity,
        file: impl Into<String>,
        range: TextRange,
        message: impl Into<String>,
    ) -> Self {
        Diagnostic {
            code: None,
            severity,
            message: message.into(),
            span: Span {
                file: file.into(),
                range,
            },
            related: Vec::new(),
            notes: Vec::new(),
        }
    }

    pub fn with_code(mut self, code: &'static str) -> Self {
        self.code = Some(code);
        self
    }

    pub fn with_note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }

    pub fn with_related(mut self, span: Span, message: impl Into<String>) -> Self {
        self.related.push(Related {
            span,
            message: message.into(),
        });
        self
    }

    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

/// Where renderers find the text of the files that diagnostics point into.
pub trait SourceResolver {
    fn source(&self, file: &str) -> Option<&str>;
}

impl SourceResolver for HashMap<String, String> {
    fn source(&self, file: &str) -> Option<&str> {
        self.get(file).map(String::as_str)
    }
}

impl SourceResolver for [(&str, &str)] {
    fn source(&self, file: &str) -> Option<&str> {
        self.iter()
            .find(|(name, _)| *name == file)
            .map(|(_, text)| *text)
    }
}

/// Diagnostics every renderer's snapshot test shows: an error with a related place in
/// another file and a note, a coded warning at the very start, and one in an unknown file.
#[cfg(test)]
mod test_data {
    use super::{Diagnostic, Span};
    use rowan::{TextRange, TextSize};

    const SCENE: &str = "camera { }\nsphere { Foo, 1 }\n";
    const INC: &str = "#declare Fog = 1;\n";

    fn range(text: &str, needle: &str) -> TextRange {
        let at = text.find(needle).unwrap();
        TextRange::at(TextSize::new(at as u32), TextSize::of(needle))
    }

    pub fn sources() -> &'static [(&'static str, &'static str)] {
        &[("scene.pov", SCENE), ("a.inc", INC)]
    }

    pub fn diagnostics() -> Vec<Diagnostic> {
        vec![
            Diagnostic::error(
                "scene.pov",
                range(SCENE, "Foo"),
                "undeclared identifier 'Foo'",
            )
            .with_related(
                Span {
                    file: "a.inc".into(),
                    range: range(INC, "Fog"),
                },
                "a similar name is declared here",
            )
            .with_note("did you mean 'Fog'?"),
            Diagnostic::warning(
                "scene.pov",
                TextRange::empty(TextSize::new(0)),
                "the scene has no #version directive",
            )
            .with_code("missing-version"),
            Diagnostic::error("missing.inc", TextRange::default(), "cannot read"),
        ]
    }
}
