//! Completion that knows where the cursor is: file names inside `#include "…"`, directive
//! names after `#`, patterns and pigment items inside `pigment { }`, finish items inside
//! `finish { }` (and so on for every block), snippets for objects where a statement may
//! stand, and the identifiers in scope everywhere a value may stand.
//!
//! The context comes from the tokens before the cursor, not the tree, because the text
//! being typed is usually broken: braces are counted and each `{` remembers the keyword
//! that opened it.

use super::FilePosition;
use super::keyword_docs::keyword_doc;
use crate::db::{self, Db, File, FilePath, SymbolKind, ValueKind};
use std::collections::BTreeMap;
use syntax::SyntaxKind::{self, *};
use syntax::keyword_groups::{DIRECTIVES, OBJECTS};
use syntax::{SyntaxToken, TextRange, TextSize};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CompletionConfig {
    /// Whether objects and blocks are offered as snippets with placeholders.
    pub snippets: bool,
}

impl Default for CompletionConfig {
    fn default() -> Self {
        CompletionConfig { snippets: true }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum CompletionKind {
    Keyword,
    Snippet,
    Variable,
    Macro,
    File,
    Function,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct CompletionItem {
    pub label: String,
    pub kind: CompletionKind,
    pub detail: Option<String>,
    /// What replaces [`CompletionItem::replace_range`]; a snippet with `${1:…}` tab stops
    /// when `kind` is [`CompletionKind::Snippet`].
    pub insert: String,
    pub replace_range: TextRange,
}

/// Where the cursor stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Context {
    IncludeName,
    Directive,
    /// Inside the braces opened after this keyword (`None`: a `{` after a name or the
    /// file's top level).
    Block(Option<SyntaxKind>),
    /// Where a value is expected: after `=`, `,`, `(`, `<` or an operator.
    Value,
}

pub fn completions(
    db: &dyn Db,
    position: FilePosition,
    config: &CompletionConfig,
) -> Vec<CompletionItem> {
    let root = db::parse(db, position.file).syntax_node();
    let offset = position.offset;
    let tokens: Vec<SyntaxToken> = root
        .descendants_with_tokens()
        .filter_map(|e| e.into_token())
        .take_while(|t| t.text_range().start() < offset)
        .collect();
    let typed = tokens
        .last()
        .filter(|t| t.text_range().end() == offset && (t.kind() == IDENT || t.kind().is_keyword()));
    let replace_range = typed.map_or(TextRange::empty(offset), |t| {
        TextRange::new(t.text_range().start(), offset)
    });
    let before: Vec<&SyntaxToken> = tokens[..tokens.len() - usize::from(typed.is_some())]
        .iter()
        .filter(|t| !t.kind().is_trivia())
        .collect();
    let mut items = Vec::new();
    match context(&before, offset) {
        Context::IncludeName => {
            let start = before
                .last()
                .map_or(offset, |t| t.text_range().start() + TextSize::new(1));
            include_names(db, position.file, TextRange::new(start, offset), &mut items);
        }
        Context::Directive => {
            for word in DIRECTIVES {
                items.push(keyword_item(word, CompletionKind::Keyword, replace_range));
            }
        }
        Context::Block(keyword) => {
            let (words, kinds) = block_vocabulary(keyword);
            for word in words {
                items.push(keyword_item(word, CompletionKind::Keyword, replace_range));
            }
            if matches!(
                keyword,
                None | Some(UNION_KW | INTERSECTION_KW | DIFFERENCE_KW | MERGE_KW)
            ) {
                for (label, snippet) in SNIPPETS {
                    items.push(if config.snippets {
                        CompletionItem {
                            label: (*label).to_owned(),
                            kind: CompletionKind::Snippet,
                            detail: keyword_doc(label).map(|d| d.summary.to_owned()),
                            insert: (*snippet).to_owned(),
                            replace_range,
                        }
                    } else {
                        keyword_item(label, CompletionKind::Keyword, replace_range)
                    });
                }
            }
            identifiers(db, position, kinds, replace_range, &mut items);
        }
        Context::Value => {
            for (word, _) in syntax::KEYWORDS {
                if let Some(doc) = keyword_doc(word)
                    && doc.syntax.starts_with(&format!("{word}("))
                {
                    items.push(keyword_item(word, CompletionKind::Function, replace_range));
                }
            }
            identifiers(db, position, &[], replace_range, &mut items);
        }
    }
    items.sort_by(|a, b| a.kind.cmp(&b.kind).then_with(|| a.label.cmp(&b.label)));
    items.dedup_by(|a, b| a.label == b.label);
    items
}

fn context(before: &[&SyntaxToken], offset: TextSize) -> Context {
    let last = before.last().map(|t| t.kind());
    // `#include "col|`: an unfinished string is an error token starting with a quote.
    if let Some(string) = before.last()
        && matches!(string.kind(), STRING | ERROR)
        && string.text().starts_with('"')
        && (string.text_range().end() > offset
            || string.text().len() == 1
            || !string.text().ends_with('"'))
        && before.len() >= 3
        && before[before.len() - 2].kind() == INCLUDE_KW
    {
        return Context::IncludeName;
    }
    if last == Some(HASH) {
        return Context::Directive;
    }
    if matches!(
        last,
        Some(EQ | COMMA | L_PAREN | LT | PLUS | MINUS | STAR | SLASH | QUESTION | COLON | L_BRACK)
    ) {
        return Context::Value;
    }
    let mut stack: Vec<Option<SyntaxKind>> = Vec::new();
    for (i, token) in before.iter().enumerate() {
        match token.kind() {
            L_BRACE => {
                let opener = i
                    .checked_sub(1)
                    .map(|j| before[j].kind())
                    .filter(|k| k.is_keyword());
                stack.push(opener);
            }
            R_BRACE => {
                stack.pop();
            }
            _ => {}
        }
    }
    Context::Block(stack.last().copied().flatten())
}

fn keyword_item(word: &str, kind: CompletionKind, replace_range: TextRange) -> CompletionItem {
    CompletionItem {
        label: word.to_owned(),
        kind,
        detail: keyword_doc(word).map(|d| d.syntax.to_owned()),
        insert: word.to_owned(),
        replace_range,
    }
}

/// The names a file can include: the bundled standard includes, the `.inc` files the
/// database holds beside it, and those on disk there.
fn include_names(
    db: &dyn Db,
    file: File,
    replace_range: TextRange,
    items: &mut Vec<CompletionItem>,
) {
    let mut names: BTreeMap<String, &str> = crate::stdinc::names()
        .map(|name| (name.to_owned(), "standard include"))
        .collect();
    if let Some(dir) = file.path(db).search_dir() {
        for path in file.project(db).files(db).keys() {
            if let FilePath::Disk(path) = path
                && path.parent() == Some(dir)
                && path.extension().is_some_and(|e| e == "inc")
                && let Some(name) = path.file_name().and_then(|n| n.to_str())
            {
                names.insert(name.to_owned(), "beside this file");
            }
        }
        for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
            if let Some(name) = entry.file_name().to_str()
                && name.ends_with(".inc")
            {
                names.insert(name.to_owned(), "beside this file");
            }
        }
    }
    for (name, detail) in names {
        items.push(CompletionItem {
            label: name.clone(),
            kind: CompletionKind::File,
            detail: Some(detail.to_owned()),
            insert: name,
            replace_range,
        });
    }
}

/// The names in scope at the cursor: the enclosing macros' parameters and locals, the
/// file's own definitions, and those of its includes. With `kinds`, only values of those
/// kinds (and of kinds the text cannot tell) are offered.
fn identifiers(
    db: &dyn Db,
    position: FilePosition,
    kinds: &[ValueKind],
    replace_range: TextRange,
    items: &mut Vec<CompletionItem>,
) {
    let file = position.file;
    let symbols = db::file_symbols(db, file);
    let ranges = db::name_ranges(db, file);
    let root = db::parse(db, file).syntax_node();
    let macros_here: Vec<u32> = symbols
        .iter()
        .enumerate()
        .filter(|(_, s)| matches!(s.kind, SymbolKind::Macro { .. }))
        .filter(|(_, s)| {
            let name = ranges[s.name_index as usize];
            root.covering_element(name)
                .ancestors()
                .find(|n| n.kind() == MACRO)
                .is_some_and(|m| m.text_range().contains_inclusive(position.offset))
        })
        .map(|(i, _)| i as u32)
        .collect();
    let own = symbols.iter().filter(|s| match s.container {
        None => true,
        Some(container) => {
            !s.local && s.kind != SymbolKind::Parameter || macros_here.contains(&container)
        }
    });
    let scope = db::include_scope(db, file);
    let included = scope
        .values()
        .map(|d| &db::file_symbols(db, d.file)[d.symbol as usize]);
    for symbol in own.chain(included) {
        let (kind, detail) = match &symbol.kind {
            SymbolKind::Variable { value, .. } => {
                if !kinds.is_empty() && *value != ValueKind::Unknown && !kinds.contains(value) {
                    continue;
                }
                (CompletionKind::Variable, value.describe().to_owned())
            }
            SymbolKind::Macro { params } => {
                let params: Vec<&str> = params.iter().map(|p| p.name.as_str()).collect();
                (
                    CompletionKind::Macro,
                    format!("#macro {}({})", symbol.name, params.join(", ")),
                )
            }
            SymbolKind::Parameter => (CompletionKind::Variable, "parameter".to_owned()),
            SymbolKind::LoopVariable => (CompletionKind::Variable, "loop variable".to_owned()),
        };
        items.push(CompletionItem {
            label: symbol.name.clone(),
            kind,
            detail: Some(detail),
            insert: symbol.name.clone(),
            replace_range,
        });
    }
}

const SNIPPETS: &[(&str, &str)] = &[
    ("box", "box { <${1:-1, -1, -1}>, <${2:1, 1, 1}> }"),
    (
        "camera",
        "camera {\n\tlocation <${1:0, 1, -5}>\n\tlook_at <${2:0, 0, 0}>\n}",
    ),
    (
        "cone",
        "cone { <${1:0, 0, 0}>, ${2:1}, <${3:0, 1, 0}>, ${4:0} }",
    ),
    (
        "cylinder",
        "cylinder { <${1:0, 0, 0}>, <${2:0, 1, 0}>, ${3:1} }",
    ),
    ("difference", "difference {\n\t$0\n}"),
    ("intersection", "intersection {\n\t$0\n}"),
    (
        "light_source",
        "light_source { <${1:5, 5, -5}> color rgb ${2:1} }",
    ),
    ("merge", "merge {\n\t$0\n}"),
    ("object", "object { ${1:Name} }"),
    ("plane", "plane { <${1:0, 1, 0}>, ${2:0} }"),
    ("sphere", "sphere { <${1:0, 0, 0}>, ${2:1} }"),
    ("torus", "torus { ${1:1}, ${2:0.25} }"),
    ("union", "union {\n\t$0\n}"),
];

/// What a scene holds besides objects, cameras and lights.
const SCENE_ITEMS: &[&str] = &[
    "background",
    "fog",
    "global_settings",
    "rainbow",
    "sky_sphere",
];

const TRANSFORMS: &[&str] = &["matrix", "rotate", "scale", "transform", "translate"];

const OBJECT_MODIFIERS: &[&str] = &[
    "bounded_by",
    "clipped_by",
    "double_illuminate",
    "finish",
    "hollow",
    "interior",
    "interior_texture",
    "inverse",
    "material",
    "no_image",
    "no_radiosity",
    "no_reflection",
    "no_shadow",
    "normal",
    "open",
    "photons",
    "pigment",
    "radiosity",
    "sturm",
    "texture",
];

const PATTERNS: &[&str] = &[
    "agate",
    "aoi",
    "average",
    "boxed",
    "bozo",
    "brick",
    "bumps",
    "cells",
    "checker",
    "crackle",
    "cubic",
    "cylindrical",
    "density_file",
    "dents",
    "facets",
    "function",
    "gradient",
    "granite",
    "hexagon",
    "image_map",
    "image_pattern",
    "julia",
    "leopard",
    "magnet",
    "mandel",
    "marble",
    "onion",
    "pavement",
    "pigment_pattern",
    "planar",
    "quilted",
    "radial",
    "ripples",
    "slope",
    "spherical",
    "spiral1",
    "spiral2",
    "spotted",
    "square",
    "tiling",
    "triangular",
    "waves",
    "wood",
    "wrinkles",
];

const PATTERN_MODIFIERS: &[&str] = &[
    "cubic_wave",
    "frequency",
    "lambda",
    "octaves",
    "omega",
    "phase",
    "poly_wave",
    "ramp_wave",
    "scallop_wave",
    "sine_wave",
    "triangle_wave",
    "turbulence",
    "warp",
];

const PIGMENT_ITEMS: &[&str] = &[
    "color",
    "color_map",
    "colour",
    "colour_map",
    "pigment_map",
    "quick_color",
    "rgb",
    "rgbf",
    "rgbft",
    "rgbt",
    "srgb",
    "srgbf",
    "srgbft",
    "srgbt",
];

const FINISH_ITEMS: &[&str] = &[
    "albedo",
    "ambient",
    "brilliance",
    "conserve_energy",
    "crand",
    "diffuse",
    "emission",
    "fresnel",
    "irid",
    "metallic",
    "phong",
    "phong_size",
    "reflection",
    "reflection_exponent",
    "roughness",
    "specular",
    "subsurface",
];

const NORMAL_ITEMS: &[&str] = &["bump_map", "bump_size", "normal_map", "slope_map"];

const CAMERA_ITEMS: &[&str] = &[
    "angle",
    "aperture",
    "blur_samples",
    "confidence",
    "cylinder",
    "direction",
    "fisheye",
    "focal_point",
    "location",
    "look_at",
    "omnimax",
    "orthographic",
    "panoramic",
    "perspective",
    "right",
    "sky",
    "spherical",
    "ultra_wide_angle",
    "up",
    "variance",
];

const LIGHT_ITEMS: &[&str] = &[
    "adaptive",
    "area_light",
    "circular",
    "color",
    "colour",
    "cylinder",
    "fade_distance",
    "fade_power",
    "falloff",
    "jitter",
    "looks_like",
    "media_attenuation",
    "media_interaction",
    "orient",
    "parallel",
    "point_at",
    "projected_through",
    "radius",
    "rgb",
    "shadowless",
    "spotlight",
    "tightness",
];

const INTERIOR_ITEMS: &[&str] = &[
    "caustics",
    "dispersion",
    "dispersion_samples",
    "fade_color",
    "fade_colour",
    "fade_distance",
    "fade_power",
    "ior",
    "media",
];

const TEXTURE_ITEMS: &[&str] = &[
    "finish",
    "material_map",
    "normal",
    "pigment",
    "texture_map",
    "uv_mapping",
];

const GLOBAL_ITEMS: &[&str] = &[
    "adc_bailout",
    "ambient_light",
    "assumed_gamma",
    "charset",
    "irid_wavelength",
    "max_trace_level",
    "noise_generator",
    "number_of_waves",
    "photons",
    "radiosity",
];

/// The words that may stand inside a block opened by `keyword`, and the kinds of
/// declared values that fit there.
fn block_vocabulary(keyword: Option<SyntaxKind>) -> (Vec<&'static str>, &'static [ValueKind]) {
    let join = |lists: &[&[&'static str]]| lists.concat();
    match keyword {
        None => (join(&[OBJECTS, SCENE_ITEMS]), &[]),
        Some(PIGMENT_KW) => (
            join(&[PATTERNS, PATTERN_MODIFIERS, PIGMENT_ITEMS, TRANSFORMS]),
            &[ValueKind::Pigment, ValueKind::Color],
        ),
        Some(NORMAL_KW) => (
            join(&[PATTERNS, PATTERN_MODIFIERS, NORMAL_ITEMS, TRANSFORMS]),
            &[ValueKind::Normal],
        ),
        Some(FINISH_KW) => (join(&[FINISH_ITEMS]), &[ValueKind::Finish]),
        Some(TEXTURE_KW) => (
            join(&[TEXTURE_ITEMS, PATTERNS, TRANSFORMS]),
            &[ValueKind::Texture],
        ),
        Some(INTERIOR_KW) => (join(&[INTERIOR_ITEMS]), &[ValueKind::Interior]),
        Some(CAMERA_KW) => (join(&[CAMERA_ITEMS, TRANSFORMS]), &[ValueKind::Camera]),
        Some(LIGHT_SOURCE_KW) => (join(&[LIGHT_ITEMS, TRANSFORMS]), &[ValueKind::Color]),
        Some(GLOBAL_SETTINGS_KW) => (join(&[GLOBAL_ITEMS]), &[]),
        Some(UNION_KW | INTERSECTION_KW | DIFFERENCE_KW | MERGE_KW) => (
            join(&[OBJECTS, OBJECT_MODIFIERS, TRANSFORMS]),
            &[ValueKind::Object],
        ),
        Some(COLOR_MAP_KW | COLOUR_MAP_KW) => (join(&[PIGMENT_ITEMS]), &[ValueKind::Color]),
        Some(_) => (
            join(&[OBJECT_MODIFIERS, TRANSFORMS]),
            &[
                ValueKind::Object,
                ValueKind::Texture,
                ValueKind::Pigment,
                ValueKind::Finish,
                ValueKind::Normal,
                ValueKind::Interior,
                ValueKind::Transform,
            ],
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::{Expect, expect};

    /// The labels offered, with their kinds, filtered by what was typed as editors do.
    #[track_caller]
    fn check(fixture: &str, expect: Expect) {
        let f = Fixture::parse(fixture);
        let position = f.position();
        let items = completions(&f.db, position, &CompletionConfig::default());
        let text = position.file.text(&f.db);
        let shown: Vec<String> = items
            .iter()
            .filter(|item| {
                let typed = &text[item.replace_range];
                item.label.starts_with(typed)
            })
            .map(|item| format!("{:?} {}", item.kind, item.label))
            .collect();
        expect.assert_eq(&shown.join("\n"));
    }

    #[test]
    fn patterns_and_pigment_items_inside_pigment() {
        check(
            "#declare Tint = rgb 1;\n#declare Shape = sphere { 0, 1 }\nsphere { 0, 1 pigment { gr$0 } }",
            expect![[r#"
                Keyword gradient
                Keyword granite"#]],
        );
        check(
            "#declare Tint = rgb 1;\n#declare Shape = sphere { 0, 1 }\nsphere { 0, 1 pigment { T$0 } }",
            expect!["Variable Tint"],
        );
    }

    #[test]
    fn finish_items_inside_finish() {
        check(
            "sphere { 0, 1 finish { sp$0 } }",
            expect!["Keyword specular"],
        );
    }

    #[test]
    fn directives_after_a_hash_and_snippets_at_the_top() {
        check("#dec$0", expect!["Keyword declare"]);
        check(
            "#declare R = 1;\nsph$0",
            expect![[r#"
                Keyword sphere
                Keyword sphere_sweep
                Snippet sphere"#]],
        );
    }

    #[test]
    fn scene_items_at_the_top_and_only_objects_inside_csg() {
        check(
            "#declare R = 1;\nl$0",
            expect![[r#"
                Keyword lathe
                Keyword lemon
                Keyword light_group
                Keyword light_source
                Snippet light_source"#]],
        );
        check("#declare R = 1;\nbac$0", expect!["Keyword background"]);
        check("union { sphere { 0, 1 } bac$0 }", expect![""]);
        check("union { sphere { 0, 1 } le$0 }", expect!["Keyword lemon"]);
    }

    #[test]
    fn identifiers_in_scope_where_a_value_goes() {
        check(
            r#"
            //- /scene.pov
            #include "lib.inc"
            #macro M(Size) #local Half = Size / 2; box { 0, Ha$0 } #end
            //- /lib.inc
            #declare Height = 3;
            #declare Other = 3;
            "#,
            expect![[r#"
                Variable Half"#]],
        );
        check(
            r#"
            //- /scene.pov
            #include "lib.inc"
            #declare A = vl$0
            //- /lib.inc
            #declare vlimit = 3;
            "#,
            expect![[r#"
                Variable vlimit
                Function vlength"#]],
        );
    }

    #[test]
    fn include_file_names() {
        check("#include \"col$0", expect!["File colors.inc"]);
    }

    #[test]
    fn in_a_typst_block() {
        check(
            "//- /doc.typ\n```povray\nsphere { 0, 1 finish { amb$0 } }\n```\n",
            expect!["Keyword ambient"],
        );
    }
}
