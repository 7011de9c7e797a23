//! TrueType and OpenType fonts for the `text` shape: glyph outlines laid out along a
//! string as POV-Ray 3.7 lays them out (measured with its `min_extent` and `max_extent`):
//! sizes in ems, the string starting at the left edge of the first glyph's outline, each
//! next glyph one advance further, moved by the font's kerning pair (its legacy `kern`
//! table, the one POV-Ray reads) and by the scene's per-character offset.

use crate::scene::math_shapes::OutlineSegment;
use glam::DVec2;

/// The font used when a scene names one the caller did not supply: DejaVu Serif cut down
/// to Latin-1 (see analysis/fonts/LICENSE).
pub const BUNDLED_FONT: &[u8] = include_bytes!("../../fonts/DejaVuSerif-Latin1.ttf");

/// The name the bundled font goes by in warnings.
pub const BUNDLED_FONT_NAME: &str = "DejaVu Serif";

/// The most characters one text object may have, so that a runaway string is an error
/// rather than an outline that never ends.
pub const MAX_CHARACTERS: usize = 1 << 16;

/// One glyph's outline, placed: closed contours of segments in ems, in the x-y plane.
pub type GlyphOutline = Vec<OutlineSegment>;

/// Lays out `text` in the font `bytes`; `Err` says why the font cannot be read. Characters
/// the font lacks take its missing-glyph outline and advance, as POV-Ray draws them.
pub fn layout(bytes: &[u8], text: &str, offset: DVec2) -> Result<Vec<GlyphOutline>, String> {
    let face = ttf_parser::Face::parse(bytes, 0)
        .map_err(|e| format!("not a valid TrueType or OpenType font: {e}"))?;
    let em = f64::from(face.units_per_em());
    if em <= 0.0 {
        return Err("not a valid TrueType or OpenType font: its em size is zero".into());
    }
    if text.chars().count() > MAX_CHARACTERS {
        return Err(format!(
            "a text object may have at most {MAX_CHARACTERS} characters"
        ));
    }
    let kerning = face.tables().kern;
    let mut glyphs = Vec::new();
    let mut pen = DVec2::ZERO;
    let mut previous = None;
    for (i, c) in text.chars().enumerate() {
        let id = face.glyph_index(c).unwrap_or(ttf_parser::GlyphId(0));
        if let (Some(left), Some(table)) = (previous, kerning) {
            let pair = table
                .subtables
                .into_iter()
                .filter(|s| s.horizontal && !s.variable)
                .find_map(|s| s.glyphs_kerning(left, id));
            if let Some(kern) = pair {
                pen.x += f64::from(kern) / em;
            }
        }
        if i == 0 {
            // The string starts at the first outline's left edge, not at its origin.
            if let Some(bounds) = face.glyph_bounding_box(id) {
                pen.x -= f64::from(bounds.x_min) / em;
            }
        } else {
            pen += offset;
        }
        let mut outline = Outline {
            segments: Vec::new(),
            start: DVec2::ZERO,
            at: DVec2::ZERO,
            origin: pen,
            em,
        };
        face.outline_glyph(id, &mut outline);
        outline.close();
        glyphs.push(outline.segments);
        let advance = face.glyph_hor_advance(id).unwrap_or(0);
        pen.x += f64::from(advance) / em;
        previous = Some(id);
    }
    Ok(glyphs)
}

/// Collects a glyph's outline as segments in ems, moved to the pen position.
struct Outline {
    segments: Vec<OutlineSegment>,
    start: DVec2,
    at: DVec2,
    origin: DVec2,
    em: f64,
}

impl Outline {
    fn point(&self, x: f32, y: f32) -> DVec2 {
        self.origin + DVec2::new(f64::from(x), f64::from(y)) / self.em
    }

    /// Ends the contour with a line back to its start, if it does not end there.
    fn close(&mut self) {
        if self.at != self.start {
            self.segments
                .push(OutlineSegment::Line(self.at, self.start));
            self.at = self.start;
        }
    }
}

impl ttf_parser::OutlineBuilder for Outline {
    fn move_to(&mut self, x: f32, y: f32) {
        self.close();
        self.start = self.point(x, y);
        self.at = self.start;
    }

    fn line_to(&mut self, x: f32, y: f32) {
        let to = self.point(x, y);
        if to != self.at {
            self.segments.push(OutlineSegment::Line(self.at, to));
        }
        self.at = to;
    }

    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (control, to) = (self.point(x1, y1), self.point(x, y));
        self.segments
            .push(OutlineSegment::Quad(self.at, control, to));
        self.at = to;
    }

    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (c1, c2, to) = (self.point(x1, y1), self.point(x2, y2), self.point(x, y));
        self.segments
            .push(OutlineSegment::Cubic(self.at, c1, c2, to));
        self.at = to;
    }

    fn close(&mut self) {
        Outline::close(self);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn extent(glyphs: &[GlyphOutline]) -> (DVec2, DVec2) {
        let mut lo = DVec2::splat(f64::INFINITY);
        let mut hi = DVec2::splat(f64::NEG_INFINITY);
        for segment in glyphs.iter().flatten() {
            for p in segment.points() {
                lo = lo.min(p);
                hi = hi.max(p);
            }
        }
        (lo, hi)
    }

    #[test]
    fn layout_matches_povray_extents() {
        // POV-Ray 3.7's max_extent of text { ttf "DejaVuSerif-Latin1.ttf" S 1, 0 } for
        // "A", "AV" (kerned), "A A" and "AA" with offset <0.5, 0.25>.
        let cases = [
            ("A", DVec2::ZERO, 0.73781),
            ("AV", DVec2::ZERO, 1.41506),
            ("A A", DVec2::ZERO, 1.77785),
            ("AA", DVec2::new(0.5, 0.25), 1.95998),
        ];
        for (text, offset, max_x) in cases {
            let (lo, hi) = extent(&layout(BUNDLED_FONT, text, offset).unwrap());
            assert!(lo.x.abs() < 1e-4, "{text}: {lo}");
            assert!((hi.x - max_x).abs() < 1e-4, "{text}: {} not {max_x}", hi.x);
        }
        let (_, hi) = extent(&layout(BUNDLED_FONT, "AA", DVec2::new(0.5, 0.25)).unwrap());
        assert!((hi.y - 0.97904).abs() < 1e-4);
    }

    #[test]
    fn a_corrupt_font_is_an_error() {
        assert!(layout(&BUNDLED_FONT[..100], "A", DVec2::ZERO).is_err());
        assert!(layout(b"not a font", "A", DVec2::ZERO).is_err());
    }
}
