//! Povrayst's own versions of POV-Ray's standard include files (`colors.inc`,
//! `textures.inc`, ...), embedded in the binary so that `#include "colors.inc"` works with
//! no file system, as in the Typst plugin. The files live in `analysis/stdinc/`; its
//! README says how each was written and where its facts come from.

/// Every embedded include file (and the colour-map files, `ash.map` ...), by the name a
/// scene uses, sorted by name.
const FILES: &[(&str, &str)] = &[
    ("arrays.inc", include_str!("../stdinc/arrays.inc")),
    ("ash.map", include_str!("../stdinc/ash.map")),
    ("benediti.map", include_str!("../stdinc/benediti.map")),
    ("bubinga.map", include_str!("../stdinc/bubinga.map")),
    ("cedar.map", include_str!("../stdinc/cedar.map")),
    ("chars.inc", include_str!("../stdinc/chars.inc")),
    ("colors.inc", include_str!("../stdinc/colors.inc")),
    ("consts.inc", include_str!("../stdinc/consts.inc")),
    ("debug.inc", include_str!("../stdinc/debug.inc")),
    ("finish.inc", include_str!("../stdinc/finish.inc")),
    ("functions.inc", include_str!("../stdinc/functions.inc")),
    ("glass.inc", include_str!("../stdinc/glass.inc")),
    ("glass_old.inc", include_str!("../stdinc/glass_old.inc")),
    ("golds.inc", include_str!("../stdinc/golds.inc")),
    ("logo.inc", include_str!("../stdinc/logo.inc")),
    ("marbteal.map", include_str!("../stdinc/marbteal.map")),
    ("math.inc", include_str!("../stdinc/math.inc")),
    ("metals.inc", include_str!("../stdinc/metals.inc")),
    ("orngwood.map", include_str!("../stdinc/orngwood.map")),
    ("pinkmarb.map", include_str!("../stdinc/pinkmarb.map")),
    ("rad_def.inc", include_str!("../stdinc/rad_def.inc")),
    ("rand.inc", include_str!("../stdinc/rand.inc")),
    ("rdgranit.map", include_str!("../stdinc/rdgranit.map")),
    ("screen.inc", include_str!("../stdinc/screen.inc")),
    ("shapes.inc", include_str!("../stdinc/shapes.inc")),
    ("shapes2.inc", include_str!("../stdinc/shapes2.inc")),
    ("shapes_old.inc", include_str!("../stdinc/shapes_old.inc")),
    ("shapesq.inc", include_str!("../stdinc/shapesq.inc")),
    ("skies.inc", include_str!("../stdinc/skies.inc")),
    ("stage1.inc", include_str!("../stdinc/stage1.inc")),
    ("stars.inc", include_str!("../stdinc/stars.inc")),
    ("stdcam.inc", include_str!("../stdinc/stdcam.inc")),
    ("stdinc.inc", include_str!("../stdinc/stdinc.inc")),
    ("stones.inc", include_str!("../stdinc/stones.inc")),
    ("stones1.inc", include_str!("../stdinc/stones1.inc")),
    ("stones2.inc", include_str!("../stdinc/stones2.inc")),
    ("strings.inc", include_str!("../stdinc/strings.inc")),
    ("sunpos.inc", include_str!("../stdinc/sunpos.inc")),
    ("teak.map", include_str!("../stdinc/teak.map")),
    ("textures.inc", include_str!("../stdinc/textures.inc")),
    ("transforms.inc", include_str!("../stdinc/transforms.inc")),
    ("whiteash.map", include_str!("../stdinc/whiteash.map")),
    ("woodmaps.inc", include_str!("../stdinc/woodmaps.inc")),
    ("woods.inc", include_str!("../stdinc/woods.inc")),
];

/// The text of the standard include file a scene names, such as `"colors.inc"`.
pub fn get(name: &str) -> Option<&'static str> {
    FILES
        .binary_search_by(|(file, _)| (*file).cmp(name))
        .ok()
        .map(|index| FILES[index].1)
}

/// The embedded file's name and text; the name is `'static`, for caches keyed by it.
pub fn get_named(name: &str) -> Option<(&'static str, &'static str)> {
    FILES
        .binary_search_by(|(file, _)| (*file).cmp(name))
        .ok()
        .map(|index| FILES[index])
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

    #[test]
    fn every_file_parses_without_syntax_errors() {
        for name in names() {
            let parse = syntax::parse(get(name).unwrap());
            assert!(parse.errors().is_empty(), "{name}: {:?}", parse.errors());
        }
    }

    const EXPECTED_FAILURES_HEADER: &str = "\
# Probe scenes (analysis/stdinc/probes) whose output differs from POV-Ray's today, one name
# a line with the first difference. analysis/src/stdinc.rs fails when this list is out of
# date; regenerate it with UPDATE_EXPECT=1 cargo test -p analysis stdinc
";

    /// Whether two printed lines agree: the same words, and numbers equal to within 1e-6
    /// relative. POV-Ray keeps colours in single precision (it prints 0.05 as
    /// 0.0500000007), which no scene can rely on.
    fn same_line(want: &str, got: &str) -> bool {
        let words = |line: &str| -> Vec<String> {
            line.split(|c: char| c.is_whitespace() || matches!(c, ',' | '<' | '>'))
                .filter(|word| !word.is_empty())
                .map(str::to_owned)
                .collect()
        };
        let (want, got) = (words(want), words(got));
        want.len() == got.len()
            && want.iter().zip(&got).all(|(a, b)| {
                a == b
                    || match (a.parse::<f64>(), b.parse::<f64>()) {
                        (Ok(x), Ok(y)) => (x - y).abs() <= 1e-6 * x.abs().max(1.0),
                        _ => false,
                    }
            })
    }

    /// What our evaluator prints for one probe scene against what POV-Ray printed for it,
    /// as the first difference, or `None` when they agree.
    fn probe_difference(probe: &std::path::Path) -> Option<String> {
        let scene = std::fs::read_to_string(probe).unwrap();
        let expected = std::fs::read_to_string(probe.with_extension("out")).unwrap();
        let files = crate::MemoryFiles::new().with("probe.pov", scene);
        let evaluation = crate::check("probe.pov", &files, &crate::EvalOptions::default());
        let printed: String = evaluation
            .messages
            .iter()
            .map(|m| m.text.as_str())
            .collect();
        if let Some(error) = evaluation.diagnostics.iter().find(|d| d.is_error()) {
            return Some(format!("error: {}", error.message));
        }
        let mut expected_lines = expected.lines();
        let mut printed_lines = printed.lines();
        for line in 1.. {
            match (expected_lines.next(), printed_lines.next()) {
                (None, None) => return None,
                (Some(want), Some(got)) if same_line(want, got) => continue,
                (want, got) => {
                    return Some(format!(
                        "line {line}: POV-Ray printed {:?}, we printed {:?}",
                        want.unwrap_or("(nothing)"),
                        got.unwrap_or("(nothing)")
                    ));
                }
            }
        }
        unreachable!("the loop returns at the end of both outputs")
    }

    /// Every probe scene prints through our evaluator what POV-Ray printed with its own
    /// include files (the `.out` beside it, recorded by measure.sh). Probes listed in
    /// `probes/expected_failures.txt` differ today; the list may only shrink.
    #[test]
    fn probes_print_what_povray_prints() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("stdinc/probes");
        let mut probes: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|entry| entry.unwrap().path())
            .filter(|path| path.extension().is_some_and(|e| e == "pov"))
            .collect();
        probes.sort();
        assert!(!probes.is_empty());
        let failing: Vec<(String, String)> = probes
            .iter()
            .filter_map(|probe| {
                let name = probe.file_stem().unwrap().to_string_lossy().into_owned();
                probe_difference(probe).map(|difference| (name, difference))
            })
            .collect();
        let list_path = dir.join("expected_failures.txt");
        if std::env::var_os("UPDATE_EXPECT").is_some() {
            let mut text = EXPECTED_FAILURES_HEADER.to_owned();
            for (name, difference) in &failing {
                text.push_str(&format!("{name}  # {difference}\n"));
            }
            std::fs::write(&list_path, text).unwrap();
            return;
        }
        let listed: Vec<String> = std::fs::read_to_string(&list_path)
            .unwrap_or_default()
            .lines()
            .filter(|line| !line.trim().is_empty() && !line.starts_with('#'))
            .map(|line| line.split('#').next().unwrap().trim().to_owned())
            .collect();
        let mut problems = Vec::new();
        for (name, difference) in &failing {
            if !listed.contains(name) {
                problems.push(format!("{name} differs from POV-Ray: {difference}"));
            }
        }
        for name in &listed {
            if !failing.iter().any(|(failed, _)| failed == name) {
                problems.push(format!(
                    "{name} now matches POV-Ray: remove it from expected_failures.txt (UPDATE_EXPECT=1)"
                ));
            }
        }
        assert!(problems.is_empty(), "{}", problems.join("\n"));
    }
}
