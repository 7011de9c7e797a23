//! The gcc-style text form: `file:line:col: severity: message`, the source line with tabs
//! expanded, and a caret with tildes under the range.

use super::{Diagnostic, SourceResolver, Span};
use crate::line_index::{LineIndex, display_width, expand_tabs};
use std::collections::HashMap;
use std::fmt::Write;

/// Renders diagnostics one after another, each ending in a newline.
pub fn render_human(
    diagnostics: &[Diagnostic],
    sources: &(impl SourceResolver + ?Sized),
) -> String {
    let mut out = String::new();
    // One index per file, not per diagnostic: a file with thousands of errors must not
    // take quadratic time.
    let mut indexes = HashMap::new();
    for diagnostic in diagnostics {
        excerpt(
            &mut out,
            &mut indexes,
            sources,
            &diagnostic.span,
            diagnostic.severity.as_str(),
            &diagnostic.message,
        );
        for related in &diagnostic.related {
            excerpt(
                &mut out,
                &mut indexes,
                sources,
                &related.span,
                "note",
                &related.message,
            );
        }
        for note in &diagnostic.notes {
            let _ = writeln!(out, "note: {note}");
        }
    }
    out
}

fn excerpt(
    out: &mut String,
    indexes: &mut HashMap<String, LineIndex>,
    sources: &(impl SourceResolver + ?Sized),
    span: &Span,
    label: &str,
    message: &str,
) {
    let Some(text) = sources.source(&span.file) else {
        let _ = writeln!(out, "{}: {label}: {message}", span.file);
        return;
    };
    let index = indexes
        .entry(span.file.clone())
        .or_insert_with(|| LineIndex::new(text));
    let start = index.display_line_col(text, span.range.start());
    let _ = writeln!(
        out,
        "{}:{}:{}: {label}: {message}",
        span.file,
        start.line + 1,
        start.col + 1
    );

    let line = index.line_text(text, start.line);
    let line_start = u32::from(index.line_start(start.line).unwrap_or_default()) as usize;
    let range_end =
        (u32::from(span.range.end()) as usize).clamp(line_start, line_start + line.len());
    let range_start = (u32::from(span.range.start()) as usize).clamp(line_start, range_end);
    let width = display_width(&line[range_start - line_start..range_end - line_start]).max(1);
    let gutter = format!("{:>5}", start.line + 1);
    let _ = writeln!(out, "{gutter} | {}", expand_tabs(line));
    let _ = writeln!(
        out,
        "{} | {}^{}",
        " ".repeat(gutter.len()),
        " ".repeat(start.col as usize),
        "~".repeat(width as usize - 1)
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::Diagnostic;
    use expect_test::expect;
    use rowan::{TextRange, TextSize};

    fn range(text: &str, needle: &str) -> TextRange {
        let at = text.find(needle).unwrap();
        TextRange::at(TextSize::new(at as u32), TextSize::of(needle))
    }

    #[test]
    fn caret_and_tildes_under_the_range() {
        let scene = "camera { }\n\tsphere { Foo, 1 }\n";
        let inc = "#declare A = 1;\n";
        let sources: &[(&str, &str)] = &[("scene.pov", scene), ("a.inc", inc)];
        let diagnostics = [
            Diagnostic::error(
                "scene.pov",
                range(scene, "Foo"),
                "undeclared identifier 'Foo'",
            )
            .with_related(
                crate::diagnostic::Span {
                    file: "a.inc".into(),
                    range: range(inc, "A"),
                },
                "a similar name is declared here",
            )
            .with_note("identifiers are case-sensitive"),
            Diagnostic::warning(
                "scene.pov",
                TextRange::empty(TextSize::of(scene)),
                "no #version",
            ),
            Diagnostic::error("missing.inc", TextRange::default(), "cannot read"),
        ];
        expect![[r#"
            scene.pov:2:18: error: undeclared identifier 'Foo'
                2 |         sphere { Foo, 1 }
                  |                  ^~~
            a.inc:1:10: note: a similar name is declared here
                1 | #declare A = 1;
                  |          ^
            note: identifiers are case-sensitive
            scene.pov:3:1: warning: no #version
                3 | 
                  | ^
            missing.inc: error: cannot read
        "#]]
        .assert_eq(&render_human(&diagnostics, sources));
    }
}
