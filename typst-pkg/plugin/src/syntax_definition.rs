//! The Sublime syntax definition that `highlight` gives Typst for povray raw blocks,
//! written from the lexer's own list of reserved words so that it cannot drift from the
//! language we parse.

use syntax::KEYWORDS;

/// Directives: reserved words that follow `#`.
const DIRECTIVES: &[&str] = &[
    "break",
    "case",
    "debug",
    "declare",
    "default",
    "else",
    "elseif",
    "end",
    "error",
    "fclose",
    "fopen",
    "for",
    "if",
    "ifdef",
    "ifndef",
    "include",
    "local",
    "macro",
    "range",
    "read",
    "render",
    "statistics",
    "switch",
    "undef",
    "version",
    "warning",
    "while",
    "write",
];

/// Built-in functions of floats, vectors and strings.
const FUNCTIONS: &[&str] = &[
    "abs",
    "acos",
    "acosh",
    "asc",
    "asin",
    "asinh",
    "atan",
    "atan2",
    "atanh",
    "bitwise_and",
    "bitwise_or",
    "bitwise_xor",
    "ceil",
    "chr",
    "concat",
    "cos",
    "cosh",
    "datetime",
    "defined",
    "degrees",
    "dimension_size",
    "dimensions",
    "div",
    "exp",
    "file_exists",
    "floor",
    "inside",
    "int",
    "ln",
    "log",
    "max",
    "max_extent",
    "min",
    "min_extent",
    "mod",
    "pow",
    "radians",
    "rand",
    "seed",
    "select",
    "sin",
    "sinh",
    "sqrt",
    "str",
    "strcmp",
    "strlen",
    "strlwr",
    "strupr",
    "substr",
    "tan",
    "tanh",
    "trace",
    "val",
    "vaxis_rotate",
    "vcross",
    "vdot",
    "vlength",
    "vnormalize",
    "vrotate",
    "vstr",
    "vturbulence",
];

/// Named constants and the scene's read-only values.
const CONSTANTS: &[&str] = &[
    "clock",
    "clock_delta",
    "clock_on",
    "false",
    "final_clock",
    "final_frame",
    "frame_number",
    "image_height",
    "image_width",
    "initial_clock",
    "initial_frame",
    "input_file_name",
    "no",
    "now",
    "off",
    "on",
    "pi",
    "t",
    "tau",
    "true",
    "u",
    "v",
    "x",
    "y",
    "yes",
    "z",
];

fn alternatives(words: &[&str]) -> String {
    let mut words = words.to_vec();
    // Longest first, so that `sinh` is not read as `sin` followed by `h`.
    words.sort_by(|a, b| b.len().cmp(&a.len()).then(a.cmp(b)));
    words.join("|")
}

fn reserved(list: &[&'static str]) -> Vec<&'static str> {
    list.iter()
        .copied()
        .filter(|word| KEYWORDS.iter().any(|(keyword, _)| keyword == word))
        .collect()
}

/// The definition, in the YAML form of Sublime Text's `.sublime-syntax` files.
pub fn sublime_syntax() -> String {
    let special: Vec<&str> = [FUNCTIONS, CONSTANTS].concat();
    let functions = reserved(FUNCTIONS);
    let constants = reserved(CONSTANTS);
    let others: Vec<&str> = KEYWORDS
        .iter()
        .map(|(keyword, _)| *keyword)
        .filter(|keyword| !special.contains(keyword))
        .collect();
    format!(
        r#"%YAML 1.2
---
# POV-Ray's scene description language, for highlighting povray raw blocks in Typst.
# Written by the Povrayst plugin from its lexer's reserved words.
name: POV-Ray
file_extensions: [povray, pov, inc, mcr]
scope: source.povray
contexts:
  main:
    - match: '//.*$'
      scope: comment.line.double-slash.povray
    - match: '/\*'
      scope: punctuation.definition.comment.begin.povray
      push: block_comment
    - match: '"'
      scope: punctuation.definition.string.begin.povray
      push: string
    - match: '#\s*(?:{directives})\b'
      scope: keyword.control.directive.povray
    - match: '\b(?:{functions})\b'
      scope: support.function.povray
    - match: '\b(?:{constants})\b'
      scope: constant.language.povray
    - match: '\b(?:{others})\b'
      scope: keyword.other.povray
    - match: '\b[A-Za-z_][A-Za-z0-9_]*\b'
      scope: variable.other.povray
    - match: '(?:\b[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][-+]?[0-9]+)?'
      scope: constant.numeric.povray
    - match: '[-+*/=<>!?:&|]'
      scope: keyword.operator.povray
  block_comment:
    - meta_scope: comment.block.povray
    - match: '/\*'
      push: block_comment
    - match: '\*/'
      scope: punctuation.definition.comment.end.povray
      pop: true
  string:
    - meta_scope: string.quoted.double.povray
    - match: '\\.'
      scope: constant.character.escape.povray
    - match: '"'
      scope: punctuation.definition.string.end.povray
      pop: true
"#,
        directives = alternatives(DIRECTIVES),
        functions = alternatives(&functions),
        constants = alternatives(&constants),
        others = alternatives(&others),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_reserved_word_is_highlighted() {
        let definition = sublime_syntax();
        for (keyword, _) in KEYWORDS {
            let listed = definition
                .lines()
                .filter(|line| line.contains("- match: '\\b(?:"))
                .any(|line| {
                    line.split(['(', ':', '|', ')'])
                        .any(|word| word == *keyword)
                });
            assert!(listed, "{keyword} is not highlighted");
        }
        assert!(definition.starts_with("%YAML 1.2\n---\n"));
        assert!(definition.contains("file_extensions: [povray, pov, inc, mcr]"));
    }
}
