//! Converts byte offsets to lines and columns, in the units each consumer wants: display
//! columns for gcc-style messages, UTF-16 code units for the language server protocol.

use rowan::TextSize;

/// The start offsets of the lines of one text.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LineIndex {
    line_starts: Vec<u32>,
    len: u32,
}

/// A zero-based line and a zero-based column, in whatever unit was asked for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LineCol {
    pub line: u32,
    pub col: u32,
}

/// Tab stops used when tabs are expanded for display, as gcc does.
pub const TAB_WIDTH: u32 = 8;

impl LineIndex {
    /// Lines end at `\n`, at `\r\n`, and at a lone `\r`, as POV-Ray counts them.
    pub fn new(text: &str) -> Self {
        let bytes = text.as_bytes();
        let mut line_starts = vec![0];
        let mut i = 0;
        while i < bytes.len() {
            match bytes[i] {
                b'\n' => line_starts.push(i as u32 + 1),
                b'\r' if bytes.get(i + 1) != Some(&b'\n') => line_starts.push(i as u32 + 1),
                _ => {}
            }
            i += 1;
        }
        LineIndex {
            line_starts,
            len: text.len() as u32,
        }
    }

    pub fn line_count(&self) -> usize {
        self.line_starts.len()
    }

    /// The zero-based line holding `offset`.
    pub fn line(&self, offset: TextSize) -> u32 {
        let offset = u32::from(offset).min(self.len);
        (self.line_starts.partition_point(|&start| start <= offset) - 1) as u32
    }

    /// The byte offset where a zero-based line starts.
    pub fn line_start(&self, line: u32) -> Option<TextSize> {
        self.line_starts
            .get(line as usize)
            .map(|&s| TextSize::new(s))
    }

    /// The text of a zero-based line, without its line break.
    pub fn line_text<'t>(&self, text: &'t str, line: u32) -> &'t str {
        let start = self
            .line_starts
            .get(line as usize)
            .copied()
            .unwrap_or(self.len) as usize;
        let end = self
            .line_starts
            .get(line as usize + 1)
            .copied()
            .unwrap_or(self.len) as usize;
        let start = start.min(text.len());
        let end = end.min(text.len()).max(start);
        text[start..end].trim_end_matches(['\n', '\r'])
    }

    /// Line and display column (tabs expanded to [`TAB_WIDTH`], one column per char).
    pub fn display_line_col(&self, text: &str, offset: TextSize) -> LineCol {
        let line = self.line(offset);
        let start = self.line_starts[line as usize] as usize;
        let end = (u32::from(offset) as usize).min(text.len());
        let col = display_width(text.get(start..end).unwrap_or(""));
        LineCol { line, col }
    }

    /// Line and UTF-16 column, the language server protocol's default unit.
    pub fn utf16_line_col(&self, text: &str, offset: TextSize) -> LineCol {
        let line = self.line(offset);
        let start = self.line_starts[line as usize] as usize;
        let end = (u32::from(offset) as usize).min(text.len());
        let col = text.get(start..end).unwrap_or("").encode_utf16().count() as u32;
        LineCol { line, col }
    }

    /// The byte offset of a UTF-16 line and column, clamped to the text.
    pub fn offset_of_utf16(&self, text: &str, pos: LineCol) -> TextSize {
        let Some(&start) = self.line_starts.get(pos.line as usize) else {
            return TextSize::new(self.len);
        };
        let line = self.line_text(text, pos.line);
        let mut units = 0u32;
        for (i, c) in line.char_indices() {
            if units >= pos.col {
                return TextSize::new(start + i as u32);
            }
            units += c.len_utf16() as u32;
        }
        TextSize::new(start + line.len() as u32)
    }
}

/// The number of display columns a piece of one line takes, tabs expanded.
pub fn display_width(s: &str) -> u32 {
    s.chars().fold(0, |col, c| {
        if c == '\t' {
            (col / TAB_WIDTH + 1) * TAB_WIDTH
        } else {
            col + 1
        }
    })
}

/// A line with its tabs expanded to spaces, for display under a caret.
pub fn expand_tabs(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut col = 0;
    for c in s.chars() {
        if c == '\t' {
            let next = (col / TAB_WIDTH + 1) * TAB_WIDTH;
            out.extend(std::iter::repeat_n(' ', (next - col) as usize));
            col = next;
        } else {
            out.push(c);
            col += 1;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_end_at_every_kind_of_break() {
        let text = "a\nb\r\nc\rd";
        let index = LineIndex::new(text);
        assert_eq!(index.line_count(), 4);
        assert_eq!(index.line_text(text, 1), "b");
        assert_eq!(index.line_text(text, 3), "d");
        assert_eq!(index.line(TextSize::new(7)), 3);
    }

    #[test]
    fn display_columns_expand_tabs() {
        let text = "\tab";
        let index = LineIndex::new(text);
        assert_eq!(
            index.display_line_col(text, TextSize::new(2)),
            LineCol { line: 0, col: 9 }
        );
        assert_eq!(expand_tabs("\ta"), "        a");
    }

    #[test]
    fn utf16_columns_round_trip() {
        let text = "x\n\"é𝄞\" y";
        let index = LineIndex::new(text);
        let y = TextSize::new(text.find('y').unwrap() as u32);
        let pos = index.utf16_line_col(text, y);
        assert_eq!(pos, LineCol { line: 1, col: 6 });
        assert_eq!(index.offset_of_utf16(text, pos), y);
    }
}
