//! The SARIF 2.1.0 form (OASIS Static Analysis Results Interchange Format), which code-scanning
//! services such as GitHub's read: one run of the `povrayst` tool, a rule per diagnostic
//! code, a result per diagnostic with its place and related places.

use super::position::{Locator, Region};
use super::{Diagnostic, Severity, SourceResolver, Span};
use serde_json::{Value, json};
use std::collections::BTreeSet;

/// Renders all diagnostics as one pretty-printed SARIF log and a newline.
pub fn render_sarif(
    diagnostics: &[Diagnostic],
    sources: &(impl SourceResolver + ?Sized),
) -> String {
    let mut locator = Locator::new(sources);
    let rules: BTreeSet<&str> = diagnostics.iter().map(rule_id).collect();
    let rules: Vec<Value> = rules.into_iter().map(|id| json!({ "id": id })).collect();
    let results: Vec<Value> = diagnostics
        .iter()
        .map(|diagnostic| {
            let mut text = diagnostic.message.clone();
            for note in &diagnostic.notes {
                text.push_str("\nnote: ");
                text.push_str(note);
            }
            let related: Vec<Value> = diagnostic
                .related
                .iter()
                .enumerate()
                .map(|(id, related)| {
                    let mut location = location(&mut locator, &related.span);
                    location["id"] = json!(id);
                    location["message"] = json!({ "text": related.message });
                    location
                })
                .collect();
            let mut result = json!({
                "ruleId": rule_id(diagnostic),
                "level": match diagnostic.severity {
                    Severity::Error => "error",
                    Severity::Warning => "warning",
                },
                "message": { "text": text },
                "locations": [location(&mut locator, &diagnostic.span)],
            });
            if !related.is_empty() {
                result["relatedLocations"] = Value::Array(related);
            }
            result
        })
        .collect();
    let log = json!({
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": {
                "driver": {
                    "name": "povrayst",
                    "version": env!("CARGO_PKG_VERSION"),
                    "rules": rules,
                }
            },
            "columnKind": "unicodeCodePoints",
            "results": results,
        }],
    });
    let mut out = serde_json::to_string_pretty(&log).unwrap_or_default();
    out.push('\n');
    out
}

/// The diagnostic's code, or its severity for findings that have no code of their own.
fn rule_id(diagnostic: &Diagnostic) -> &'static str {
    diagnostic.code.unwrap_or(diagnostic.severity.as_str())
}

fn location<R: SourceResolver + ?Sized>(locator: &mut Locator<'_, R>, span: &Span) -> Value {
    let mut physical = json!({ "artifactLocation": { "uri": uri_reference(&span.file) } });
    if let Some(Region { start, end }) = locator.region(span) {
        physical["region"] = json!({
            "startLine": start.line,
            "startColumn": start.column,
            "endLine": end.line,
            "endColumn": end.column,
        });
    }
    json!({ "physicalLocation": physical })
}

/// A file name as a URI reference: relative names stay relative (so that the consumer
/// resolves them against the checkout), absolute ones become `file:` URIs.
fn uri_reference(file: &str) -> String {
    let mut out = String::new();
    let path = file.replace('\\', "/");
    if path.starts_with('/') {
        out.push_str("file://");
    }
    for byte in path.bytes() {
        match byte {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => {
                out.push(byte as char);
            }
            _ => out.push_str(&format!("%{byte:02X}")),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diagnostic::test_data::{diagnostics, sources};
    use expect_test::expect;

    #[test]
    fn one_result_per_diagnostic_and_one_rule_per_code() {
        let log =
            render_sarif(&diagnostics(), sources()).replace(env!("CARGO_PKG_VERSION"), "VERSION");
        expect![[r#"
            {
              "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
              "runs": [
                {
                  "columnKind": "unicodeCodePoints",
                  "results": [
                    {
                      "level": "error",
                      "locations": [
                        {
                          "physicalLocation": {
                            "artifactLocation": {
                              "uri": "scene.pov"
                            },
                            "region": {
                              "endColumn": 13,
                              "endLine": 2,
                              "startColumn": 10,
                              "startLine": 2
                            }
                          }
                        }
                      ],
                      "message": {
                        "text": "undeclared identifier 'Foo'\nnote: did you mean 'Fog'?"
                      },
                      "relatedLocations": [
                        {
                          "id": 0,
                          "message": {
                            "text": "a similar name is declared here"
                          },
                          "physicalLocation": {
                            "artifactLocation": {
                              "uri": "a.inc"
                            },
                            "region": {
                              "endColumn": 13,
                              "endLine": 1,
                              "startColumn": 10,
                              "startLine": 1
                            }
                          }
                        }
                      ],
                      "ruleId": "error"
                    },
                    {
                      "level": "warning",
                      "locations": [
                        {
                          "physicalLocation": {
                            "artifactLocation": {
                              "uri": "scene.pov"
                            },
                            "region": {
                              "endColumn": 1,
                              "endLine": 1,
                              "startColumn": 1,
                              "startLine": 1
                            }
                          }
                        }
                      ],
                      "message": {
                        "text": "the scene has no #version directive"
                      },
                      "ruleId": "missing-version"
                    },
                    {
                      "level": "error",
                      "locations": [
                        {
                          "physicalLocation": {
                            "artifactLocation": {
                              "uri": "missing.inc"
                            }
                          }
                        }
                      ],
                      "message": {
                        "text": "cannot read"
                      },
                      "ruleId": "error"
                    }
                  ],
                  "tool": {
                    "driver": {
                      "name": "povrayst",
                      "rules": [
                        {
                          "id": "error"
                        },
                        {
                          "id": "missing-version"
                        }
                      ],
                      "version": "VERSION"
                    }
                  }
                }
              ],
              "version": "2.1.0"
            }
        "#]]
        .assert_eq(&log);
    }

    #[test]
    fn file_names_become_uri_references() {
        assert_eq!(uri_reference("scenes/a b.pov"), "scenes/a%20b.pov");
        assert_eq!(uri_reference("/srv/x#1.pov"), "file:///srv/x%231.pov");
        assert_eq!(uri_reference("dir\\é.inc"), "dir/%C3%A9.inc");
    }
}
