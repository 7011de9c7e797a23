//! The VS Code extension's TextMate grammar (editors/vscode/syntaxes/povray.tmLanguage.json)
//! is written by this test from the lexer's list of reserved words, so that the editor
//! highlights exactly the words we parse. `UPDATE_EXPECT=1 cargo test -p povrayst --test
//! textmate_grammar` rewrites it after the keyword list changes.

use expect_test::expect_file;
use serde_json::{Value, json};
use syntax::KEYWORDS;

/// Reserved words that follow `#`.
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

/// Shapes, CSG and the other things a scene is made of.
const OBJECTS: &[&str] = &[
    "bicubic_patch",
    "blob",
    "box",
    "camera",
    "cone",
    "cubic",
    "cylinder",
    "difference",
    "disc",
    "height_field",
    "intersection",
    "isosurface",
    "julia_fractal",
    "lathe",
    "light_group",
    "light_source",
    "merge",
    "mesh",
    "mesh2",
    "object",
    "ovus",
    "parametric",
    "plane",
    "poly",
    "polygon",
    "polynomial",
    "prism",
    "quadric",
    "quartic",
    "sor",
    "sphere",
    "sphere_sweep",
    "superellipsoid",
    "text",
    "torus",
    "triangle",
    "smooth_triangle",
    "union",
];

/// Blocks that describe what an object looks like and its surroundings.
const MATERIALS: &[&str] = &[
    "background",
    "finish",
    "fog",
    "global_settings",
    "interior",
    "material",
    "media",
    "normal",
    "photons",
    "pigment",
    "radiosity",
    "rainbow",
    "sky_sphere",
    "texture",
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

/// The words of `list` that the lexer reserves, longest first so that a regex alternation
/// does not stop at a prefix.
fn alternatives(list: &[&str]) -> String {
    let mut words: Vec<&str> = list
        .iter()
        .copied()
        .filter(|word| KEYWORDS.iter().any(|(keyword, _)| keyword == word))
        .collect();
    words.sort_by(|a, b| b.len().cmp(&a.len()).then(a.cmp(b)));
    words.join("|")
}

fn grammar() -> Value {
    let categorised = [DIRECTIVES, OBJECTS, MATERIALS, FUNCTIONS, CONSTANTS].concat();
    let others: Vec<&str> = KEYWORDS
        .iter()
        .map(|(keyword, _)| *keyword)
        .filter(|keyword| !categorised.contains(keyword))
        .collect();
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
                "match": format!("(#)\\s*(?:{})\\b", alternatives(DIRECTIVES)),
                "name": "keyword.control.directive.povray",
                "captures": { "1": { "name": "punctuation.definition.directive.povray" } }
            },
            "numbers": {
                "name": "constant.numeric.povray",
                "match": "(?:\\b[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE][-+]?[0-9]+)?"
            },
            "keywords": {
                "patterns": [
                    { "name": "storage.type.object.povray", "match": format!("\\b(?:{})\\b", alternatives(OBJECTS)) },
                    { "name": "storage.type.material.povray", "match": format!("\\b(?:{})\\b", alternatives(MATERIALS)) },
                    { "name": "support.function.povray", "match": format!("\\b(?:{})\\b", alternatives(FUNCTIONS)) },
                    { "name": "constant.language.povray", "match": format!("\\b(?:{})\\b", alternatives(CONSTANTS)) },
                    { "name": "keyword.other.povray", "match": format!("\\b(?:{})\\b", alternatives(&others)) }
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

#[test]
fn every_categorised_word_is_reserved() {
    for word in [DIRECTIVES, OBJECTS, MATERIALS, FUNCTIONS, CONSTANTS].concat() {
        assert!(
            KEYWORDS.iter().any(|(keyword, _)| *keyword == word),
            "'{word}' is not a reserved word"
        );
    }
}
