//! Evaluates every scene of Debian's povray-examples as a render does (our evaluator and
//! standard includes, the renderer answering `trace()` and `inside()`): each must give a
//! scene or a located error, never a panic or a hang, and the errors that are not "not
//! supported yet" must be the scenes' own, listed below. Prints the counts and the most
//! common unsupported features. Skips (and says so) when the corpus is not installed; the
//! README's test command installs it.

use analysis::{DirectoryFiles, EvalOptions, FileSource};
use expect_test::expect;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::Arc;
use tests::example_corpus::{EXAMPLES, example_scenes};

/// Where Debian's POV-Ray finds the fonts, images and colour maps the examples use.
const POVRAY_DATA: &str = "/usr/share/povray-3.7/include";

/// A scene's directory for every file, and POV-Ray's library directory for the fonts,
/// images and data files it ships, but not for its include files: those are ours.
struct ExampleFiles {
    scene_dir: DirectoryFiles,
    povray_data: DirectoryFiles,
}

impl FileSource for ExampleFiles {
    fn read(&self, name: &str) -> Option<Arc<str>> {
        self.scene_dir.read(name)
    }

    fn read_bytes(&self, name: &str) -> Option<Arc<[u8]>> {
        self.scene_dir
            .read_bytes(name)
            .or_else(|| self.povray_data.read_bytes(name))
    }

    fn names(&self) -> Vec<String> {
        self.scene_dir.names()
    }
}

#[test]
fn every_example_scene_evaluates_or_fails_with_a_located_error() {
    let paths = example_scenes();
    if paths.is_empty() {
        eprintln!(
            "skipped: the example corpus is not installed at {EXAMPLES} (apt-get install povray-examples)"
        );
        return;
    }
    // A small render's size: the mesh_camera scenes build one mesh face per pixel, which
    // at the default 800 x 600 takes POV-Ray itself over ten seconds of parsing each.
    let options = EvalOptions {
        image_width: 160,
        image_height: 120,
        ..EvalOptions::default()
    };
    let mut evaluated = 0;
    let mut unsupported: BTreeMap<String, usize> = BTreeMap::new();
    let mut other_errors = Vec::new();
    for path in &paths {
        let dir = path
            .parent()
            .expect("a scene lives in a directory")
            .to_path_buf();
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .expect("UTF-8 names")
            .to_owned();
        let files = ExampleFiles {
            scene_dir: DirectoryFiles::new([dir]),
            povray_data: DirectoryFiles::new([PathBuf::from(POVRAY_DATA)]),
        };
        let evaluation = std::panic::catch_unwind(|| {
            analysis::check_with(&name, &files, &options, &renderer::SceneGeometry)
        })
        .unwrap_or_else(|_| panic!("the evaluator panicked on {}", path.display()));
        match evaluation.diagnostics.iter().find(|d| d.is_error()) {
            None => evaluated += 1,
            Some(error) => {
                assert!(
                    !error.span.file.is_empty(),
                    "unlocated error for {}",
                    path.display()
                );
                match error.message.strip_prefix("not supported yet: ") {
                    Some(feature) => *unsupported.entry(feature.to_owned()).or_default() += 1,
                    None => {
                        let text = evaluation
                            .sources
                            .get(&error.span.file)
                            .map(|t| t.to_string())
                            .unwrap_or_default();
                        let index = syntax::line_index::LineIndex::new(&text);
                        let at = index.display_line_col(&text, error.span.range.start());
                        let scene = path.strip_prefix(EXAMPLES).unwrap_or(path);
                        other_errors.push(format!(
                            "{} ({}:{}): {}",
                            scene.display(),
                            error.span.file,
                            at.line + 1,
                            error.message
                        ));
                    }
                }
            }
        }
    }
    let mut features: Vec<_> = unsupported.iter().collect();
    features.sort_by(|a, b| b.1.cmp(a.1));
    eprintln!(
        "{} scenes: {evaluated} evaluated, {} not supported yet, {} other errors",
        paths.len(),
        unsupported.values().sum::<usize>(),
        other_errors.len()
    );
    for (feature, count) in &features {
        eprintln!("  {count:4}  not supported yet: {feature}");
    }
    // The errors left are all the scenes' own, and POV-Ray 3.7 stops on each of them too:
    // cliche.pov's image "sign" has no file (same line), the portfolio scenes index their
    // arrays by `frame_number - 1` and need their animation's .ini file ("Negative
    // subscript", same lines), and `__empty.pov` is a template with `...` placeholders
    // (POV-Ray stops first on its `#include "... .inc"`; our syntax check, which runs
    // before any include, on the `...` further down).
    expect![[r#"
        advanced/cliche/cliche.pov (cliche.pov:105): cannot find image file 'sign'
        portfolio/__empty.pov (__empty.pov:32): unexpected '.' before ']'
        portfolio/allnormals.pov (allnormals.pov:107): array index -1 out of range: this dimension has 33 elements (0 to 32)
        portfolio/allpatterns.pov (allpatterns.pov:202): array index -1 out of range: this dimension has 32 elements (0 to 31)
        portfolio/c_colors.pov (c_colors.pov:115): array index -1 out of range: this dimension has 130 elements (0 to 129)
        portfolio/f_finish.pov (f_finish.pov:80): array index -1 out of range: this dimension has 8 elements (0 to 7)
        portfolio/m_textures.pov (m_textures.pov:77): array index -1 out of range: this dimension has 14 elements (0 to 13)
        portfolio/o_2shapes.pov (o_2shapes.pov:78): array index -1 out of range: this dimension has 12 elements (0 to 11)
        portfolio/o_shapes_old.pov (o_shapes_old.pov:92): array index -1 out of range: this dimension has 21 elements (0 to 20)
        portfolio/p_skies.pov (p_skies.pov:64): array index -1 out of range: this dimension has 4 elements (0 to 3)
        portfolio/p_textures.pov (p_textures.pov:80): array index -1 out of range: this dimension has 33 elements (0 to 32)
        portfolio/p_woods.pov (p_woods.pov:82): array index -1 out of range: this dimension has 38 elements (0 to 37)
        portfolio/t_1stones.pov (t_1stones.pov:99): array index -1 out of range: this dimension has 83 elements (0 to 82)
        portfolio/t_2stones.pov (t_2stones.pov:74): array index -1 out of range: this dimension has 20 elements (0 to 19)
        portfolio/t_metals.pov (t_metals.pov:127): array index -1 out of range: this dimension has 125 elements (0 to 124)
        portfolio/t_stars.pov (t_stars.pov:65): array index -1 out of range: this dimension has 6 elements (0 to 5)
        portfolio/t_textures.pov (t_textures.pov:86): array index -1 out of range: this dimension has 40 elements (0 to 39)
        portfolio/t_woods.pov (t_woods.pov:80): array index -1 out of range: this dimension has 35 elements (0 to 34)"#]].assert_eq(&other_errors.join("\n"));
}
