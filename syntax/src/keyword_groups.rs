//! The reserved words sorted into the groups that editors colour or offer differently:
//! directives, objects, materials, built-in functions and constants. Completion, the VS Code
//! TextMate grammar and the Typst plugin's highlighting definition all read these lists, so
//! that they agree with each other; every word in them is one of the lexer's [`KEYWORDS`].

use crate::KEYWORDS;

/// Reserved words that follow `#`.
pub const DIRECTIVES: &[&str] = &[
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
pub const OBJECTS: &[&str] = &[
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
    "lemon",
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
pub const MATERIALS: &[&str] = &[
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
pub const FUNCTIONS: &[&str] = &[
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
pub const CONSTANTS: &[&str] = &[
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

/// A regular-expression alternation of `words`, longest first so that a regex engine does
/// not stop at a prefix (`sinh` read as `sin` followed by `h`).
pub fn alternation(words: &[&str]) -> String {
    let mut words = words.to_vec();
    words.sort_by(|a, b| b.len().cmp(&a.len()).then(a.cmp(b)));
    words.join("|")
}

/// The reserved words in none of the groups above.
pub fn ungrouped() -> Vec<&'static str> {
    let grouped = [DIRECTIVES, OBJECTS, MATERIALS, FUNCTIONS, CONSTANTS].concat();
    KEYWORDS
        .iter()
        .map(|(keyword, _)| *keyword)
        .filter(|keyword| !grouped.contains(keyword))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_grouped_word_is_reserved_and_in_one_group() {
        let grouped = [DIRECTIVES, OBJECTS, MATERIALS, FUNCTIONS, CONSTANTS].concat();
        for word in &grouped {
            assert!(
                KEYWORDS.iter().any(|(keyword, _)| keyword == word),
                "'{word}' is not a reserved word"
            );
            assert_eq!(
                grouped.iter().filter(|w| *w == word).count(),
                1,
                "'{word}' is in two groups"
            );
        }
        assert_eq!(grouped.len() + ungrouped().len(), KEYWORDS.len());
    }

    #[test]
    fn alternation_puts_longer_words_first() {
        assert_eq!(alternation(&["sin", "sinh", "abs"]), "sinh|abs|sin");
    }
}
