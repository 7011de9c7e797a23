//! Formatting a file in the editor: [`crate::format::format_text`], answered as the one
//! edit that replaces the part that changed, so the cursor and undo history stay put
//! elsewhere.

use super::TextEdit;
use crate::db::{Db, File};
use crate::format::{FormatConfig, format_text};
use syntax::{TextRange, TextSize};

/// The edits that format `file`; none when it is already formatted.
pub fn formatting(db: &dyn Db, file: File, config: &FormatConfig) -> Vec<TextEdit> {
    let text = file.text(db);
    let formatted = format_text(text, config);
    minimal_edit(text, &formatted).into_iter().collect()
}

/// One edit that turns `old` into `new`, covering only what lies between their common
/// beginning and end.
pub fn minimal_edit(old: &str, new: &str) -> Option<TextEdit> {
    if old == new {
        return None;
    }
    let prefix = common_prefix(old, new);
    let suffix = common_prefix_rev(&old[prefix..], &new[prefix..]);
    Some(TextEdit {
        range: TextRange::new(
            TextSize::new(prefix as u32),
            TextSize::new((old.len() - suffix) as u32),
        ),
        insert: new[prefix..new.len() - suffix].to_owned(),
    })
}

fn common_prefix(a: &str, b: &str) -> usize {
    a.char_indices()
        .zip(b.chars())
        .find(|((_, x), y)| x != y)
        .map_or(a.len().min(b.len()), |((i, _), _)| i)
}

fn common_prefix_rev(a: &str, b: &str) -> usize {
    a.chars()
        .rev()
        .zip(b.chars().rev())
        .take_while(|(x, y)| x == y)
        .map(|(x, _)| x.len_utf8())
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;

    #[test]
    fn one_edit_covers_what_changed() {
        let f = Fixture::parse("#declare A = 1;\nsphere {\n0, A\n}\n");
        let file = f.files[0].1;
        let edits = formatting(&f.db, file, &FormatConfig::default());
        assert_eq!(edits.len(), 1);
        assert_eq!(f.show(file, edits[0].range), "/main.pov 3:1 \"\"");
        assert_eq!(edits[0].insert, "  ");
        assert_eq!(minimal_edit("abc", "abc"), None);
        let edit = minimal_edit("aé b", "aé  b").unwrap();
        assert_eq!(
            (edit.range, edit.insert.as_str()),
            (TextRange::empty(TextSize::new(4)), " ")
        );
    }
}
