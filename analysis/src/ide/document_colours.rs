//! The colour provider: a swatch beside every `rgb <…>` (and `rgbf`, `rgbt`, `rgbft`,
//! `srgb…`) whose components are constants, and the text that writes back a colour picked
//! in the editor. Editors show sRGB; POV-Ray's `rgb` is linear light (with
//! `assumed_gamma 1`), so `rgb` values are encoded for the swatch and decoded back.

use crate::db::{self, Constant, Db, File};
use syntax::SyntaxKind::{self, *};
use syntax::TextRange;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ColourConfig {
    /// Whether `rgb` components are linear light (POV-Ray 3.7 with `assumed_gamma 1`).
    pub linear_rgb: bool,
}

impl Default for ColourConfig {
    fn default() -> Self {
        ColourConfig { linear_rgb: true }
    }
}

/// A colour as editors show it: sRGB components and opacity, each from 0 to 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rgba {
    pub red: f64,
    pub green: f64,
    pub blue: f64,
    pub alpha: f64,
}

#[derive(Debug, Clone, PartialEq)]
pub struct ColourLiteral {
    /// From the colour keyword to the end of its value.
    pub range: TextRange,
    pub colour: Rgba,
}

pub fn document_colours(db: &dyn Db, file: File, config: &ColourConfig) -> Vec<ColourLiteral> {
    let root = db::parse(db, file).syntax_node();
    let mut found = Vec::new();
    for node in root.descendants().filter(|n| n.kind() == COLOR) {
        let Some(keyword) = node
            .children_with_tokens()
            .filter_map(|e| e.into_token())
            .find(|t| space(t.kind()).is_some())
        else {
            continue;
        };
        let Some(value) = node
            .children()
            .find(|c| c.text_range().start() >= keyword.text_range().end())
        else {
            continue;
        };
        let Some((srgb, filter, transmit)) = space(keyword.kind()) else {
            continue;
        };
        let components = match db::fold(&value) {
            Some(Constant::Float(v)) => vec![v; 3],
            Some(Constant::Vector(v)) => v,
            None => continue,
        };
        let expected = 3 + usize::from(filter) + usize::from(transmit);
        if components.len() < expected {
            continue;
        }
        let shown = |c: f64| {
            let c = c.clamp(0.0, 1.0);
            if srgb || !config.linear_rgb {
                c
            } else {
                encode_srgb(c)
            }
        };
        let f = if filter { components[3] } else { 0.0 };
        let t = if transmit {
            components[3 + usize::from(filter)]
        } else {
            0.0
        };
        found.push(ColourLiteral {
            range: TextRange::new(keyword.text_range().start(), value.text_range().end()),
            colour: Rgba {
                red: shown(components[0]),
                green: shown(components[1]),
                blue: shown(components[2]),
                alpha: (1.0 - f - t).clamp(0.0, 1.0),
            },
        });
    }
    found
}

/// The text for a colour picked in the editor, in place of a literal written with
/// `keyword`: the same colour space, with transmit when the colour is not opaque.
pub fn colour_presentation(keyword: &str, colour: Rgba, config: &ColourConfig) -> String {
    let srgb = keyword.starts_with("srgb");
    let stored = |c: f64| {
        if srgb || !config.linear_rgb {
            c
        } else {
            decode_srgb(c)
        }
    };
    let (r, g, b) = (
        stored(colour.red),
        stored(colour.green),
        stored(colour.blue),
    );
    let prefix = if srgb { "srgb" } else { "rgb" };
    if colour.alpha >= 1.0 && !keyword.ends_with('t') {
        format!("{prefix} <{}, {}, {}>", number(r), number(g), number(b))
    } else {
        format!(
            "{prefix}t <{}, {}, {}, {}>",
            number(r),
            number(g),
            number(b),
            number(1.0 - colour.alpha)
        )
    }
}

/// For a colour keyword: whether it is sRGB, and whether it takes filter and transmit.
fn space(kind: SyntaxKind) -> Option<(bool, bool, bool)> {
    Some(match kind {
        RGB_KW => (false, false, false),
        RGBF_KW => (false, true, false),
        RGBT_KW => (false, false, true),
        RGBFT_KW => (false, true, true),
        SRGB_KW => (true, false, false),
        SRGBF_KW => (true, true, false),
        SRGBT_KW => (true, false, true),
        SRGBFT_KW => (true, true, true),
        _ => return None,
    })
}

fn encode_srgb(linear: f64) -> f64 {
    if linear <= 0.003_130_8 {
        12.92 * linear
    } else {
        1.055 * linear.powf(1.0 / 2.4) - 0.055
    }
}

fn decode_srgb(encoded: f64) -> f64 {
    if encoded <= 0.040_45 {
        encoded / 12.92
    } else {
        ((encoded + 0.055) / 1.055).powf(2.4)
    }
}

/// Three decimals at most, without trailing zeros.
fn number(x: f64) -> String {
    let text = format!("{:.3}", x.clamp(0.0, 1.0));
    text.trim_end_matches('0').trim_end_matches('.').to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::expect;

    #[test]
    fn constant_colours_get_swatches_in_srgb() {
        let f = Fixture::parse(
            "#declare A = color rgb <1, 0.5, 0>;\n#declare B = rgbt <1, 1, 1, 0.25>;\n#declare C = srgb 0.5;\n#declare D = rgb <A.x, 0, 0>;\n",
        );
        let file = f.files[0].1;
        let shown: Vec<String> = document_colours(&f.db, file, &ColourConfig::default())
            .iter()
            .map(|c| {
                let rgba = c.colour;
                format!(
                    "{} = {:.3} {:.3} {:.3} {:.2}",
                    f.show(file, c.range),
                    rgba.red,
                    rgba.green,
                    rgba.blue,
                    rgba.alpha
                )
            })
            .collect();
        expect![[r#"
            [
                "/main.pov 1:20 \"rgb <1, 0.5, 0>\" = 1.000 0.735 0.000 1.00",
                "/main.pov 2:14 \"rgbt <1, 1, 1, 0.25>\" = 1.000 1.000 1.000 0.75",
                "/main.pov 3:14 \"srgb 0.5\" = 0.500 0.500 0.500 1.00",
            ]
        "#]]
        .assert_debug_eq(&shown);
    }

    #[test]
    fn picked_colours_are_written_back_in_the_literal_s_space() {
        let config = ColourConfig::default();
        let orange = Rgba {
            red: 1.0,
            green: encode_srgb(0.5),
            blue: 0.0,
            alpha: 1.0,
        };
        assert_eq!(
            colour_presentation("rgb", orange, &config),
            "rgb <1, 0.5, 0>"
        );
        assert_eq!(
            colour_presentation("srgb", orange, &config),
            "srgb <1, 0.735, 0>"
        );
        let clear = Rgba {
            alpha: 0.75,
            ..orange
        };
        assert_eq!(
            colour_presentation("rgb", clear, &config),
            "rgbt <1, 0.5, 0, 0.25>"
        );
    }
}
