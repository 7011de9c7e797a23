//! The Sublime syntax definition that `highlight` gives Typst for povray raw blocks,
//! written from the lexer's own reserved words and their groups so that it cannot drift from the
//! language we parse.

use syntax::keyword_groups::{
    CONSTANTS, DIRECTIVES, FUNCTIONS, MATERIALS, OBJECTS, alternation, ungrouped,
};

/// The definition, in the YAML form of Sublime Text's `.sublime-syntax` files.
pub fn sublime_syntax() -> String {
    // Objects and materials are not told apart here, and a directive's word without its
    // `#` is a plain keyword too.
    let others = [DIRECTIVES, OBJECTS, MATERIALS, &ungrouped()].concat();
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
        directives = alternation(DIRECTIVES),
        functions = alternation(FUNCTIONS),
        constants = alternation(CONSTANTS),
        others = alternation(&others),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use syntax::KEYWORDS;

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
