//! The output formats a list of diagnostics can be rendered in, by name, so that a
//! command-line flag or a setting picks one renderer.

use super::{Diagnostic, SourceResolver};
use std::fmt;
use std::str::FromStr;

/// How diagnostics are written out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Format {
    /// gcc-style text with the source line and a caret, for people.
    #[default]
    Human,
    /// One JSON array of findings, for scripts.
    Json,
    /// A SARIF 2.1.0 log, for code-scanning services.
    Sarif,
    /// GitHub Actions workflow commands, which become annotations on the changed lines.
    Github,
}

impl Format {
    pub const ALL: [Format; 4] = [Format::Human, Format::Json, Format::Sarif, Format::Github];

    pub fn name(self) -> &'static str {
        match self {
            Format::Human => "human",
            Format::Json => "json",
            Format::Sarif => "sarif",
            Format::Github => "github",
        }
    }
}

impl fmt::Display for Format {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Format {
    type Err = String;

    fn from_str(name: &str) -> Result<Format, String> {
        Format::ALL
            .into_iter()
            .find(|format| format.name() == name)
            .ok_or_else(|| {
                let names: Vec<&str> = Format::ALL.iter().map(|f| f.name()).collect();
                format!(
                    "unknown format '{name}'; expected one of {}",
                    names.join(", ")
                )
            })
    }
}

/// Renders `diagnostics` in `format`; the machine formats end in a newline too.
pub fn render(
    format: Format,
    diagnostics: &[Diagnostic],
    sources: &(impl SourceResolver + ?Sized),
) -> String {
    match format {
        Format::Human => super::render_human(diagnostics, sources),
        Format::Json => super::render_json(diagnostics, sources),
        Format::Sarif => super::render_sarif(diagnostics, sources),
        Format::Github => super::render_github(diagnostics, sources),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_unknown_names_list_the_known_ones() {
        for format in Format::ALL {
            assert_eq!(format.name().parse::<Format>(), Ok(format));
        }
        assert_eq!(
            "xml".parse::<Format>(),
            Err("unknown format 'xml'; expected one of human, json, sarif, github".to_owned())
        );
    }
}
