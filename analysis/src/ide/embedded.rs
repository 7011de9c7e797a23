//! POV-Ray scenes inside Typst documents: the ```` ```povray ```` raw blocks, found with
//! Typst's own parser, and the maps between a block's text and the document's.
//!
//! Typst dedents block raws and trims their first and last lines, so a block's text is
//! not a slice of the document. It is rebuilt here from the raw's text nodes, one per
//! line, joined by line breaks exactly as Typst builds `raw.text`, and each line keeps
//! where it stands in the document.

use syntax::{TextRange, TextSize};
use typst_syntax::{LinkedNode, SyntaxKind as TypstKind};

/// One povray block of a Typst document.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Block {
    /// The scene as Typst hands it to the plugin.
    pub text: String,
    /// The whole raw block in the document, backticks included.
    pub range: TextRange,
    lines: Vec<Line>,
}

/// A line of a block: where it starts in the block's text and in the document.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Line {
    start: u32,
    host_start: u32,
    len: u32,
}

impl Block {
    /// Where an offset of the block's text stands in the document. The line break that
    /// joins two lines maps to the end of the first.
    pub fn to_host(&self, offset: TextSize) -> TextSize {
        let offset = u32::from(offset);
        let index = self
            .lines
            .partition_point(|line| line.start <= offset)
            .saturating_sub(1);
        match self.lines.get(index) {
            Some(line) => TextSize::new(line.host_start + (offset - line.start).min(line.len)),
            None => self.range.start(),
        }
    }

    pub fn to_host_range(&self, range: TextRange) -> TextRange {
        let start = self.to_host(range.start());
        TextRange::new(start, self.to_host(range.end()).max(start))
    }

    /// Where a document offset stands in the block's text: `None` outside the block's
    /// lines; indentation that Typst trims maps to the start of its line.
    pub fn from_host(&self, offset: TextSize) -> Option<TextSize> {
        let offset = u32::from(offset);
        let first = self.lines.first()?;
        let last = self.lines.last()?;
        if offset < first.host_start || offset > last.host_start + last.len {
            return None;
        }
        let index = self
            .lines
            .partition_point(|line| line.host_start <= offset)
            .saturating_sub(1);
        let line = self.lines[index];
        Some(TextSize::new(
            line.start + (offset - line.host_start).min(line.len),
        ))
    }

    /// Whether a document offset lies inside the block, backticks included.
    pub fn contains_host(&self, offset: TextSize) -> bool {
        self.range.contains_inclusive(offset)
    }
}

/// The ```` ```povray ```` blocks of a Typst document, in order.
pub fn povray_blocks(document: &str) -> Vec<Block> {
    let root = typst_syntax::parse(document);
    let mut blocks = Vec::new();
    collect_blocks(&LinkedNode::new(&root), &mut blocks);
    blocks
}

fn collect_blocks(node: &LinkedNode<'_>, blocks: &mut Vec<Block>) {
    if node.kind() == TypstKind::Raw {
        if let Some(block) = block_of(node) {
            blocks.push(block);
        }
        return;
    }
    for child in node.children() {
        collect_blocks(&child, blocks);
    }
}

fn block_of(raw: &LinkedNode<'_>) -> Option<Block> {
    let mut children = raw.children();
    let delimiter = children.next()?;
    if delimiter.kind() != TypstKind::RawDelim || delimiter.get().leaf_text().len() < 3 {
        return None;
    }
    let lang = raw.children().find(|c| c.kind() == TypstKind::RawLang)?;
    if lang.get().leaf_text() != "povray" {
        return None;
    }
    let mut text = String::new();
    let mut lines = Vec::new();
    for line in raw.children().filter(|c| c.kind() == TypstKind::Text) {
        if !lines.is_empty() {
            text.push('\n');
        }
        lines.push(Line {
            start: text.len() as u32,
            host_start: line.offset() as u32,
            len: line.get().leaf_text().len() as u32,
        });
        text.push_str(line.get().leaf_text());
    }
    Some(Block {
        text,
        range: TextRange::at(
            TextSize::new(raw.offset() as u32),
            TextSize::new(raw.get().len() as u32),
        ),
        lines,
    })
}

/// A scene file a Typst document renders: `render(read("scene.pov"))`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SceneLink {
    /// The string literal naming the file, quotes included.
    pub range: TextRange,
    /// The path as written, relative to the document.
    pub path: String,
}

/// The files read for `render(...)` and `pov(...)` calls of a Typst document.
pub fn scene_links(document: &str) -> Vec<SceneLink> {
    let root = typst_syntax::parse(document);
    let mut links = Vec::new();
    collect_links(&LinkedNode::new(&root), false, &mut links);
    links
}

fn collect_links(node: &LinkedNode<'_>, in_render: bool, links: &mut Vec<SceneLink>) {
    let mut in_render = in_render;
    if node.kind() == TypstKind::FuncCall {
        let callee = node.children().next();
        let name = callee.as_ref().map(callee_name).unwrap_or_default();
        if in_render && name == "read" {
            let string = node
                .children()
                .find(|c| c.kind() == TypstKind::Args)
                .and_then(|args| args.children().find(|c| c.kind() == TypstKind::Str));
            if let Some(string) = string {
                let literal = string.get().leaf_text();
                links.push(SceneLink {
                    range: TextRange::at(
                        TextSize::new(string.offset() as u32),
                        TextSize::new(string.get().len() as u32),
                    ),
                    path: literal.trim_matches('"').to_owned(),
                });
            }
        }
        in_render = matches!(name.as_str(), "render" | "pov");
    }
    for child in node.children() {
        collect_links(&child, in_render, links);
    }
}

/// `render` for `render(...)` and for `povrayst.render(...)`.
fn callee_name(callee: &LinkedNode<'_>) -> String {
    match callee.kind() {
        TypstKind::Ident => callee.get().leaf_text().to_string(),
        TypstKind::FieldAccess => callee
            .children()
            .filter(|c| c.kind() == TypstKind::Ident)
            .last()
            .map(|c| c.get().leaf_text().to_string())
            .unwrap_or_default(),
        _ => String::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use expect_test::expect;

    #[test]
    fn blocks_are_rebuilt_from_their_lines_as_typst_dedents_them() {
        let document = "= Scene\n\n#figure[\n  ```povray\n  #declare R = 1;\n    sphere { 0, R }\n  ```\n]\n\n```rust\nfn main() {}\n```\n";
        let blocks = povray_blocks(document);
        assert_eq!(blocks.len(), 1);
        let block = &blocks[0];
        assert_eq!(block.text, "#declare R = 1;\n  sphere { 0, R }");
        // Every offset of the block text maps to the same character in the document.
        for (offset, c) in block.text.char_indices() {
            let host = usize::from(block.to_host(TextSize::new(offset as u32)));
            if c != '\n' {
                assert_eq!(document[host..].chars().next(), Some(c), "{offset}");
                assert_eq!(
                    block.from_host(TextSize::new(host as u32)),
                    Some(TextSize::new(offset as u32))
                );
            }
        }
        let r = document.rfind("R }").unwrap() as u32;
        assert_eq!(
            block.from_host(TextSize::new(r)),
            block.text.rfind("R }").map(|o| TextSize::new(o as u32))
        );
        assert_eq!(block.from_host(TextSize::new(0)), None);
    }

    #[test]
    fn inline_raws_and_other_languages_are_not_scenes() {
        let texts: Vec<String> =
            povray_blocks("`povray x` and ```povray box{0,1}``` and ```pov\nbox{0,1}\n```")
                .into_iter()
                .map(|block| block.text)
                .collect();
        assert_eq!(texts, ["box{0,1}"]);
    }

    #[test]
    fn render_read_calls_link_to_their_files() {
        let document = "#import \"@local/povrayst:0.1.0\" as p\n#p.render(read(\"scenes/a.pov\"), width: 10)\n#render(read(\"b.pov\"))\n#read(\"c.txt\")\n";
        let links: Vec<_> = scene_links(document)
            .into_iter()
            .map(|link| (link.path, &document[link.range]))
            .collect();
        expect![[r#"
            [
                (
                    "scenes/a.pov",
                    "\"scenes/a.pov\"",
                ),
                (
                    "b.pov",
                    "\"b.pov\"",
                ),
            ]
        "#]]
        .assert_debug_eq(&links);
    }
}
