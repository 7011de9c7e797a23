//! Folding ranges: braces that span lines, the directive blocks `#if … #end`, `#while`,
//! `#for`, `#switch` and `#macro … #end`, block comments, and runs of line comments.

use crate::db::{self, Db, File};
use syntax::SyntaxKind::*;
use syntax::{TextRange, TextSize};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FoldingRangesConfig {
    /// Whether comments fold too.
    pub comments: bool,
}

impl Default for FoldingRangesConfig {
    fn default() -> Self {
        FoldingRangesConfig { comments: true }
    }
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FoldKind {
    Block,
    Directive,
    Comment,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fold {
    pub range: TextRange,
    pub kind: FoldKind,
}

pub fn folding_ranges(db: &dyn Db, file: File, config: &FoldingRangesConfig) -> Vec<Fold> {
    let text = file.text(db);
    let root = db::parse(db, file).syntax_node();
    let spans_lines = |range: TextRange| text[range].contains('\n');
    let mut folds = Vec::new();
    for node in root.descendants() {
        let kind = match node.kind() {
            IF | WHILE | FOR | SWITCH | MACRO => FoldKind::Directive,
            _ => FoldKind::Block,
        };
        let range = match kind {
            FoldKind::Directive => Some(node.text_range()),
            _ => {
                let braces: Vec<_> = node
                    .children_with_tokens()
                    .filter_map(|e| e.into_token())
                    .filter(|t| matches!(t.kind(), L_BRACE | R_BRACE))
                    .collect();
                match (braces.first(), braces.last()) {
                    (Some(open), Some(close))
                        if open.kind() == L_BRACE && close.kind() == R_BRACE =>
                    {
                        Some(TextRange::new(
                            open.text_range().start(),
                            close.text_range().end(),
                        ))
                    }
                    _ => None,
                }
            }
        };
        if let Some(range) = range.filter(|r| spans_lines(*r)) {
            folds.push(Fold { range, kind });
        }
    }
    if config.comments {
        let mut run: Option<TextRange> = None;
        let tokens = root
            .descendants_with_tokens()
            .filter_map(|e| e.into_token());
        for token in tokens {
            match token.kind() {
                BLOCK_COMMENT if spans_lines(token.text_range()) => folds.push(Fold {
                    range: token.text_range(),
                    kind: FoldKind::Comment,
                }),
                LINE_COMMENT => {
                    run = Some(match run {
                        Some(r) => r.cover(token.text_range()),
                        None => token.text_range(),
                    });
                    continue;
                }
                WHITESPACE if token.text().matches('\n').count() <= 1 => continue,
                _ => {}
            }
            if let Some(r) = run.take().filter(|r| spans_lines(*r)) {
                folds.push(Fold {
                    range: r,
                    kind: FoldKind::Comment,
                });
            }
        }
        if let Some(r) = run.filter(|r| spans_lines(*r)) {
            folds.push(Fold {
                range: r,
                kind: FoldKind::Comment,
            });
        }
    }
    folds.sort_by_key(|f| (f.range.start(), std::cmp::Reverse(f.range.end())));
    folds.dedup_by_key(|f| f.range);
    folds.retain(|f| f.range.end() > f.range.start() + TextSize::new(1));
    folds
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ide::fixture::Fixture;
    use expect_test::expect;

    #[test]
    fn blocks_directives_and_comments_fold() {
        let f = Fixture::parse(
            r#"
            // A scene
            // in two lines.
            #macro Ball(R)
              sphere { 0, R
                pigment { rgb 1 }
              }
            #end
            #if (1) box { 0, 1 } #end
            /* A long
               comment. */
            "#,
        );
        let file = f.files[0].1;
        let folds: Vec<String> = folding_ranges(&f.db, file, &FoldingRangesConfig::default())
            .iter()
            .map(|fold| format!("{:?} {}", fold.kind, f.show(file, fold.range)))
            .collect();
        expect![[r##"
            [
                "Comment /main.pov 1:1 \"// A scene…\"",
                "Directive /main.pov 3:1 \"#macro Ball(R)…\"",
                "Block /main.pov 4:10 \"{ 0, R…\"",
                "Comment /main.pov 9:1 \"/* A long…\"",
            ]
        "##]]
        .assert_debug_eq(&folds);
    }
}
