//! GitHub Actions workflow commands (`::error file=...,line=...::message`): printed on
//! standard output by a workflow step, each becomes an annotation on the file's line in the
//! pull request.

use super::position::Locator;
use super::{Diagnostic, Severity, SourceResolver};
use std::fmt::Write;

/// Renders one workflow command line per diagnostic.
pub fn render_github(
    diagnostics: &[Diagnostic],
    sources: &(impl SourceResolver + ?Sized),
) -> String {
    let mut locator = Locator::new(sources);
    let mut out = String::new();
    for diagnostic in diagnostics {
        let command = match diagnostic.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
        };
        let mut properties = format!("file={}", escape_property(&diagnostic.span.file));
        if let Some(region) = locator.region(&diagnostic.span) {
            let _ = write!(
                properties,
                ",line={},col={},endLine={},endColumn={}",
                region.start.line, region.start.column, region.end.line, region.end.column
            );
        }
        let title = match diagnostic.code {
            Some(code) => format!("povrayst ({code})"),
            None => "povrayst".to_owned(),
        };
        let _ = write!(properties, ",title={}", escape_property(&title));
        let mut message = diagnostic.message.clone();
        for related in &diagnostic.related {
            let _ = write!(message, "\n{}: {}", related.span.file, related.message);
        }
        for note in &diagnostic.notes {
            let _ = write!(message, "\nnote: {note}");
        }
        let _ = writeln!(out, "::{command} {properties}::{}", escape_data(&message));
    }
    out
}

/// Escapes a message the way the runner unescapes it: `%`, carriage return and newline.
fn escape_data(text: &str) -> String {
    text.replace('%', "%25")
        .replace('\r', "%0D")
        .replace('\n', "%0A")
}

/// Escapes a property value, which also must not hold the `:` and `,` that delimit them.
fn escape_property(text: &str) -> String {
    escape_data(text).replace(':', "%3A").replace(',', "%2C")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::test_data::{diagnostics, sources};
    use expect_test::expect;

    #[test]
    fn one_command_per_diagnostic_with_escaped_text() {
        expect![[r#"
            ::error file=scene.pov,line=2,col=10,endLine=2,endColumn=13,title=povrayst::undeclared identifier 'Foo'%0Aa.inc: a similar name is declared here%0Anote: did you mean 'Fog'?
            ::warning file=scene.pov,line=1,col=1,endLine=1,endColumn=1,title=povrayst (missing-version)::the scene has no #version directive
            ::error file=missing.inc,title=povrayst::cannot read
        "#]]
        .assert_eq(&render_github(&diagnostics(), sources()));
    }

    #[test]
    fn delimiters_in_names_and_messages_are_escaped() {
        assert_eq!(escape_property("C:\\a,b%.pov"), "C%3A\\a%2Cb%25.pov");
        assert_eq!(escape_data("50%\r\nx: y"), "50%25%0D%0Ax: y");
    }
}
