//! The JSON form: one array with an object per diagnostic, its place as one-based lines and
//! columns (Unicode scalar values), for scripts and editors that are not LSP clients.

use super::position::{Locator, Region};
use super::{Diagnostic, SourceResolver, Span};
use serde_json::{Value, json};

/// Renders all diagnostics as one pretty-printed JSON array and a newline.
pub fn render_json(diagnostics: &[Diagnostic], sources: &(impl SourceResolver + ?Sized)) -> String {
    let mut locator = Locator::new(sources);
    let items: Vec<Value> = diagnostics
        .iter()
        .map(|diagnostic| {
            let related: Vec<Value> = diagnostic
                .related
                .iter()
                .map(|related| {
                    json!({
                        "file": related.span.file,
                        "range": range(&mut locator, &related.span),
                        "message": related.message,
                    })
                })
                .collect();
            json!({
                "code": diagnostic.code,
                "severity": diagnostic.severity.as_str(),
                "message": diagnostic.message,
                "file": diagnostic.span.file,
                "range": range(&mut locator, &diagnostic.span),
                "related": related,
                "notes": diagnostic.notes,
            })
        })
        .collect();
    let mut out = serde_json::to_string_pretty(&Value::Array(items)).unwrap_or_default();
    out.push('\n');
    out
}

fn range<R: SourceResolver + ?Sized>(locator: &mut Locator<'_, R>, span: &Span) -> Value {
    match locator.region(span) {
        Some(Region { start, end }) => json!({
            "start": { "line": start.line, "column": start.column },
            "end": { "line": end.line, "column": end.column },
        }),
        None => Value::Null,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::test_data::{diagnostics, sources};
    use expect_test::expect;

    #[test]
    fn one_object_per_diagnostic_with_one_based_places() {
        expect![[r#"
            [
              {
                "code": null,
                "file": "scene.pov",
                "message": "undeclared identifier 'Foo'",
                "notes": [
                  "did you mean 'Fog'?"
                ],
                "range": {
                  "end": {
                    "column": 13,
                    "line": 2
                  },
                  "start": {
                    "column": 10,
                    "line": 2
                  }
                },
                "related": [
                  {
                    "file": "a.inc",
                    "message": "a similar name is declared here",
                    "range": {
                      "end": {
                        "column": 13,
                        "line": 1
                      },
                      "start": {
                        "column": 10,
                        "line": 1
                      }
                    }
                  }
                ],
                "severity": "error"
              },
              {
                "code": "missing-version",
                "file": "scene.pov",
                "message": "the scene has no #version directive",
                "notes": [],
                "range": {
                  "end": {
                    "column": 1,
                    "line": 1
                  },
                  "start": {
                    "column": 1,
                    "line": 1
                  }
                },
                "related": [],
                "severity": "warning"
              },
              {
                "code": null,
                "file": "missing.inc",
                "message": "cannot read",
                "notes": [],
                "range": null,
                "related": [],
                "severity": "error"
              }
            ]
        "#]]
        .assert_eq(&render_json(&diagnostics(), sources()));
    }
}
