//! The database's promises: checks equal `analysis::check`, includes resolve through the
//! project, and edits that only move text leave position-free queries equal, so their
//! dependents are not run again.

use super::*;
use crate::{EvalOptions, MemoryFiles};
use salsa::Setter;
use std::collections::BTreeMap;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};

/// A database with files on (imaginary) disk under `/scenes`, and a log of query runs.
struct Fixture {
    db: RootDatabase,
    files: Vec<File>,
    log: Arc<Mutex<Vec<String>>>,
}

fn fixture(files: &[(&str, &str)]) -> Fixture {
    let log = Arc::new(Mutex::new(Vec::new()));
    let sink = log.clone();
    let db = RootDatabase::with_events(Some(Box::new(move |event: salsa::Event| {
        if let salsa::EventKind::WillExecute { database_key } = event.kind {
            sink.lock().unwrap().push(format!("{database_key:?}"));
        }
    })));
    let mut db = db;
    let project = Project::new(&db, Vec::new(), BTreeMap::new(), EvalOptions::default(), 0);
    let mut map = BTreeMap::new();
    let files = files
        .iter()
        .map(|(name, text)| {
            let path = FilePath::Disk(PathBuf::from("/scenes").join(name));
            let file = File::new(&db, path.clone(), Arc::from(*text), project);
            map.insert(path, file);
            file
        })
        .collect();
    project.set_files(&mut db).to(map);
    Fixture { db, files, log }
}

impl Fixture {
    /// The names of the queries run since the last call.
    fn runs(&self) -> Vec<String> {
        let mut log = self.log.lock().unwrap();
        let runs = log
            .iter()
            .map(|key| key.split('(').next().unwrap_or_default().to_owned())
            .collect();
        log.clear();
        runs
    }
}

#[test]
fn checks_equal_the_evaluator_with_the_same_files() {
    let scene = "#version 3.7;\n#include \"shapes.inc\"\nobject { Ball pigment { Colour } }\n";
    let include = "#declare Ball = sphere { 0, 1 }\n";
    let f = fixture(&[("scene.pov", scene), ("shapes.inc", include)]);
    let checked = check_file(&f.db, f.files[0]);
    let memory = MemoryFiles::new()
        .with("scene.pov", scene)
        .with("shapes.inc", include);
    let expected = crate::check("scene.pov", &memory, &EvalOptions::default());
    assert_eq!(checked.diagnostics, expected.diagnostics);
    assert_eq!(
        checked.path_of("shapes.inc"),
        Some(&FilePath::Disk(PathBuf::from("/scenes/shapes.inc")))
    );
    assert!(checked.unloaded.is_empty());
}

#[test]
fn the_include_scope_sees_declarations_through_includes() {
    let f = fixture(&[
        ("scene.pov", "#include \"a.inc\"\n"),
        (
            "a.inc",
            "#include \"b.inc\"\n#declare A = 1;\n#local Hidden = 2;\n",
        ),
        ("b.inc", "#macro B(X) X #end\n#declare A = 3;\n"),
    ]);
    let scope = include_scope(&f.db, f.files[0]);
    let described: Vec<String> = scope
        .iter()
        .map(|(name, definition)| {
            let symbol = &file_symbols(&f.db, definition.file)[definition.symbol as usize];
            format!(
                "{name} in {:?} ({:?})",
                definition.file.path(&f.db),
                symbol.kind
            )
        })
        .collect();
    expect_test::expect![[r#"
        [
            "A in Disk(\"/scenes/a.inc\") (Variable { value: Float, constant: Some(\"1\") })",
            "B in Disk(\"/scenes/b.inc\") (Macro { params: [MacroParam { name: \"X\", optional: false }] })",
        ]
    "#]]
    .assert_debug_eq(&described);
}

#[test]
fn moving_text_in_an_include_reruns_nothing_that_depends_on_its_symbols() {
    let mut f = fixture(&[
        ("scene.pov", "#include \"a.inc\"\n"),
        ("a.inc", "#declare A = 1;\n"),
    ]);
    include_scope(&f.db, f.files[0]);
    f.runs();

    f.files[1]
        .set_text(&mut f.db)
        .to(Arc::from("\n\n#declare A = 1;   // A comment.\n"));
    include_scope(&f.db, f.files[0]);
    // The include is parsed again and its table rebuilt, equal, so the scope is reused.
    assert_eq!(f.runs(), ["parse", "includes", "file_symbols"]);

    f.files[1]
        .set_text(&mut f.db)
        .to(Arc::from("#declare A = 2;\n"));
    include_scope(&f.db, f.files[0]);
    assert_eq!(
        f.runs(),
        ["parse", "includes", "file_symbols", "include_scope"]
    );
}
