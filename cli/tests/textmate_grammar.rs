//! The VS Code extension's TextMate grammar (editors/vscode/syntaxes/povray.tmLanguage.json)
//! is written by this test from the lexer's reserved words and their groups
//! (`syntax::keyword_groups`), so that the editor
//! highlights exactly the words we parse. `UPDATE_EXPECT=1 cargo test -p povrayst --test
//! textmate_grammar` rewrites it after the keyword list changes.

use expect_test::expect_file;
use serde_json::{Value, json};
use syntax::keyword_groups::{
    CONSTANTS, DIRECTIVES, FUNCTIONS, MATERIALS, OBJECTS, alternation, ungrouped,
};

fn grammar() -> Value {
    let others = ungrouped();
    let identifier = "[A-Za-z_][A-Za-z0-9_]*";
    json!({
        "$schema": "https://raw.githubusercontent.com/martinring/tmlanguage/master/tmlanguage.json",
        "name": "POV-Ray",
        "scopeName": "source.povray",
        "comment": "Written by cli/tests/textmate_grammar.rs from the lexer's reserved words; do not edit by hand.",
        "fileTypes": ["pov", "inc", "mcr", "mac"],
        "patterns": [{ "include": "#main" }],
        "repository": {
            "main": {
                "patterns": [
                    { "include": "#comments" },
                    { "include": "#strings" },
                    { "include": "#declaration" },
                    { "include": "#macro-definition" },
                    { "include": "#directives" },
                    { "include": "#numbers" },
                    { "include": "#keywords" },
                    { "include": "#calls" },
                    { "include": "#identifiers" },
                    { "include": "#operators" },
                    { "include": "#punctuation" }
                ]
            },
            "comments": {
                "patterns": [
                    {
                        "name": "comment.line.double-slash.povray",
                        "begin": "//",
                        "beginCaptures": { "0": { "name": "punctuation.definition.comment.povray" } },
                        "end": "$"
                    },
                    { "include": "#block-comment" }
                ]
            },
            "block-comment": {
                "comment": "POV-Ray's block comments nest.",
                "name": "comment.block.povray",
                "begin": "/\\*",
                "beginCaptures": { "0": { "name": "punctuation.definition.comment.begin.povray" } },
                "end": "\\*/",
                "endCaptures": { "0": { "name": "punctuation.definition.comment.end.povray" } },
                "patterns": [{ "include": "#block-comment" }]
            },
            "strings": {
                "name": "string.quoted.double.povray",
                "begin": "\"",
                "beginCaptures": { "0": { "name": "punctuation.definition.string.begin.povray" } },
                "end": "\"",
                "endCaptures": { "0": { "name": "punctuation.definition.string.end.povray" } },
                "patterns": [{ "name": "constant.character.escape.povray", "match": "\\\\." }]
            },
            "declaration": {
                "match": format!("(#)\\s*(declare|local)\\s+(?:(deprecated)\\s+(?:(once)\\s+)?(?:\"[^\"]*\"\\s+)?)?({identifier})"),
                "captures": {
                    "1": { "name": "punctuation.definition.directive.povray" },
                    "2": { "name": "keyword.control.directive.povray" },
                    "3": { "name": "storage.modifier.povray" },
                    "4": { "name": "storage.modifier.povray" },
                    "5": { "name": "variable.other.definition.povray" }
                }
            },
            "macro-definition": {
                "match": format!("(#)\\s*(macro)\\s+({identifier})"),
                "captures": {
                    "1": { "name": "punctuation.definition.directive.povray" },
                    "2": { "name": "keyword.control.directive.povray" },
                    "3": { "name": "entity.name.function.povray" }
                }
            },
            "directives": {
                "match": format!("(#)\\s*(?:{})\\b", alternation(DIRECTIVES)),
                "name": "keyword.control.directive.povray",
                "captures": { "1": { "name": "punctuation.definition.directive.povray" } }
            },
            "numbers": {
                "name": "constant.numeric.povray",
                "match": "(?:\\b[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE][-+]?[0-9]+)?"
            },
            "keywords": {
                "patterns": [
                    { "name": "storage.type.object.povray", "match": format!("\\b(?:{})\\b", alternation(OBJECTS)) },
                    { "name": "storage.type.material.povray", "match": format!("\\b(?:{})\\b", alternation(MATERIALS)) },
                    { "name": "support.function.povray", "match": format!("\\b(?:{})\\b", alternation(FUNCTIONS)) },
                    { "name": "constant.language.povray", "match": format!("\\b(?:{})\\b", alternation(CONSTANTS)) },
                    { "name": "keyword.other.povray", "match": format!("\\b(?:{})\\b", alternation(&others)) }
                ]
            },
            "calls": {
                "comment": "A macro call: an identifier followed by '('.",
                "match": format!("\\b({identifier})(?=\\s*\\()"),
                "captures": { "1": { "name": "entity.name.function.call.povray" } }
            },
            "identifiers": {
                "name": "variable.other.povray",
                "match": format!("\\b{identifier}\\b")
            },
            "operators": {
                "name": "keyword.operator.povray",
                "match": "<=|>=|!=|[-+*/=<>!?:&|]"
            },
            "punctuation": {
                "patterns": [
                    { "name": "punctuation.separator.povray", "match": "[,;]" },
                    { "name": "punctuation.accessor.povray", "match": "\\." },
                    { "name": "punctuation.section.braces.povray", "match": "[{}]" },
                    { "name": "punctuation.section.brackets.povray", "match": "[\\[\\]]" },
                    { "name": "punctuation.section.parens.povray", "match": "[()]" }
                ]
            }
        }
    })
}

#[test]
fn the_grammar_is_written_from_the_lexers_reserved_words() {
    let mut text = serde_json::to_string_pretty(&grammar()).unwrap();
    text.push('\n');
    expect_file!["../../editors/vscode/syntaxes/povray.tmLanguage.json"].assert_eq(&text);
}
