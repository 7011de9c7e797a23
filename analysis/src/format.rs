//! The formatter: re-indents a file by its structure and tidies the whitespace between
//! lines, and changes nothing else. Every token other than whitespace is kept exactly,
//! comments included, and so is the whitespace inside a line; only the whitespace that
//! holds a line break is rewritten: blank lines are capped, trailing spaces go, and the
//! next line is indented by how deeply it is nested in braces, parentheses and directive
//! blocks (`#if … #end`, `#while`, `#for`, `#switch`, `#macro`). The output depends only on
//! the tokens and where the line breaks are, so formatting twice changes nothing.
//!
//! Used by `povrayst fmt` and by the language server's formatting request.

use syntax::SyntaxKind::{self, *};
use syntax::SyntaxToken;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FormatConfig {
    /// Spaces per level of nesting.
    pub indent_width: usize,
    /// The most blank lines kept in a row.
    pub max_blank_lines: usize,
}

impl Default for FormatConfig {
    fn default() -> Self {
        FormatConfig {
            indent_width: 2,
            max_blank_lines: 1,
        }
    }
}

/// The formatted text of a scene or include file.
pub fn format_text(text: &str, config: &FormatConfig) -> String {
    let tokens: Vec<SyntaxToken> = syntax::parse(text)
        .syntax_node()
        .descendants_with_tokens()
        .filter_map(|e| e.into_token())
        .collect();
    let newline = if text.contains("\r\n") { "\r\n" } else { "\n" };
    let mut out = String::with_capacity(text.len());
    let mut depth = 0usize;
    let mut after_hash = false;
    for (i, token) in tokens.iter().enumerate() {
        let kind = token.kind();
        if kind == WHITESPACE && i == 0 {
            // Leading blank lines and indentation of the first line go.
            out.push_str(&indentation(&tokens[1..], depth, config));
            continue;
        }
        if kind == WHITESPACE && i + 1 == tokens.len() {
            out.push_str(newline);
            continue;
        }
        if kind == WHITESPACE && has_line_break(token.text()) {
            let breaks = line_breaks(token.text()).min(config.max_blank_lines + 1);
            for _ in 0..breaks {
                out.push_str(newline);
            }
            out.push_str(&indentation(&tokens[i + 1..], depth, config));
            continue;
        }
        out.push_str(token.text());
        if kind.is_trivia() {
            continue;
        }
        depth = match kind {
            L_BRACE | L_PAREN | L_BRACK => depth + 1,
            R_BRACE | R_PAREN | R_BRACK => depth.saturating_sub(1),
            _ if after_hash && opens_block(kind) => depth + 1,
            END_KW if after_hash => depth.saturating_sub(1),
            _ => depth,
        };
        after_hash = kind == HASH;
    }
    if !out.ends_with('\n') && !out.is_empty() {
        out.push_str(newline);
    }
    out
}

/// The indentation of a line that starts with `rest`: one level less when it closes
/// something or continues a directive block with `#else`, `#case` and the like.
fn indentation(rest: &[SyntaxToken], depth: usize, config: &FormatConfig) -> String {
    let mut significant = rest
        .iter()
        .filter(|t| t.kind() != WHITESPACE)
        .map(|t| t.kind());
    let first = significant.next();
    let second = significant.next();
    let outdent = match first {
        Some(R_BRACE | R_PAREN | R_BRACK) => true,
        Some(HASH) => matches!(
            second,
            Some(END_KW | ELSE_KW | ELSEIF_KW | CASE_KW | RANGE_KW)
        ),
        _ => false,
    };
    let level = if outdent {
        depth.saturating_sub(1)
    } else {
        depth
    };
    // A line break at the very end of the file is not followed by a line.
    if first.is_none() {
        return String::new();
    }
    " ".repeat(level * config.indent_width)
}

/// Directives whose body runs to an `#end`.
fn opens_block(kind: SyntaxKind) -> bool {
    matches!(
        kind,
        IF_KW | IFDEF_KW | IFNDEF_KW | WHILE_KW | FOR_KW | SWITCH_KW | MACRO_KW
    )
}

fn has_line_break(text: &str) -> bool {
    text.contains(['\n', '\r'])
}

/// Line breaks as POV-Ray counts them: `\n`, `\r\n` and a lone `\r`.
fn line_breaks(text: &str) -> usize {
    text.replace("\r\n", "\n")
        .chars()
        .filter(|&c| c == '\n' || c == '\r')
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;
    use expect_test::expect;

    #[test]
    fn indents_by_braces_parentheses_and_directives() {
        let text = "\n\n#declare A = 1;   \n#macro Ball(R)\nsphere { 0, R\npigment { rgb <1,\n0, 0> }\n}\n#end\n\n\n\n#if (A)\n  box { 0, 1 }\n    #else\n        // a comment\ncylinder { 0, y, 1 }\n#end\n#switch (A)\n#case (1)\nplane { y, 0 }\n#break\n#end";
        expect![[r#"
            #declare A = 1;
            #macro Ball(R)
              sphere { 0, R
                pigment { rgb <1,
                  0, 0> }
              }
            #end

            #if (A)
              box { 0, 1 }
            #else
              // a comment
              cylinder { 0, y, 1 }
            #end
            #switch (A)
            #case (1)
              plane { y, 0 }
              #break
            #end
        "#]]
        .assert_eq(&format_text(text, &FormatConfig::default()));
    }

    #[test]
    fn block_comments_and_line_endings_are_kept() {
        let text = "sphere {\r\n/* keep\r\n      this */ 0, 1\r\n}";
        assert_eq!(
            format_text(text, &FormatConfig::default()),
            "sphere {\r\n  /* keep\r\n      this */ 0, 1\r\n}\r\n"
        );
    }
}
