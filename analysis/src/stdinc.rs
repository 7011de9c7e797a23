//! Povrayst's own versions of POV-Ray's standard include files (`colors.inc`,
//! `textures.inc`, ...), embedded in the binary so that `#include "colors.inc"` works with
//! no file system, as in the Typst plugin. The files live in `analysis/stdinc/`; its
//! README says how each was written and where its facts come from.

/// Every embedded include file, by the name a scene uses, sorted by name.
const FILES: &[(&str, &str)] = &[
    ("colors.inc", include_str!("../stdinc/colors.inc")),
    ("consts.inc", include_str!("../stdinc/consts.inc")),
    ("functions.inc", include_str!("../stdinc/functions.inc")),
    ("math.inc", include_str!("../stdinc/math.inc")),
    ("shapes.inc", include_str!("../stdinc/shapes.inc")),
    ("shapes_old.inc", include_str!("../stdinc/shapes_old.inc")),
    ("strings.inc", include_str!("../stdinc/strings.inc")),
    ("transforms.inc", include_str!("../stdinc/transforms.inc")),
];

/// The text of the standard include file a scene names, such as `"colors.inc"`.
pub fn get(name: &str) -> Option<&'static str> {
    FILES
        .binary_search_by(|(file, _)| (*file).cmp(name))
        .ok()
        .map(|index| FILES[index].1)
}

/// The names of every embedded include file, in sorted order.
pub fn names() -> impl Iterator<Item = &'static str> {
    FILES.iter().map(|(name, _)| *name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_are_sorted_and_found_by_name() {
        let listed: Vec<_> = names().collect();
        let mut sorted = listed.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(listed, sorted);
        for name in names() {
            assert!(get(name).is_some_and(|text| !text.is_empty()), "{name}");
        }
        assert_eq!(get("no-such-file.inc"), None);
    }

    #[test]
    fn every_file_lexes_without_errors() {
        for name in names() {
            let lexed = syntax::lexer::lex(get(name).unwrap());
            assert!(lexed.errors.is_empty(), "{name}: {:?}", lexed.errors);
        }
    }

    /// Every `#include "..."` inside a standard include names another embedded file, so a
    /// scene never needs anything from disk to use them. The one exception is the file
    /// that strings.inc's Parse_String writes and then includes.
    #[test]
    fn includes_between_files_resolve() {
        use syntax::SyntaxKind::{HASH, INCLUDE_KW, STRING};
        let written_at_run_time = ["parse_string.tmp"];
        let mut found = 0;
        for name in names() {
            let text = get(name).unwrap();
            let tokens: Vec<_> = syntax::lexer::lex(text)
                .tokens
                .into_iter()
                .filter(|token| !token.kind.is_trivia())
                .collect();
            for window in tokens.windows(3) {
                if window[0].kind != HASH || window[1].kind != INCLUDE_KW {
                    continue;
                }
                assert_eq!(
                    window[2].kind, STRING,
                    "{name}: #include without a literal name"
                );
                let included = text[window[2].range].trim_matches('"');
                found += 1;
                assert!(
                    get(included).is_some() || written_at_run_time.contains(&included),
                    "{name} includes missing {included}"
                );
            }
        }
        assert!(found > 0, "no #include found: the token pattern is wrong");
    }
}
