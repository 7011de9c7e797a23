//! Compiles Typst documents with the real Typst compiler against the installed Povrayst
//! package. The compiler is the `typst` Python module (Typst 0.15's own Rust code behind a
//! binding), driven by `scripts/typst-compile.py`; the package is built and installed once
//! per test process by `scripts/install-package` into the target directory.

use crate::{target_dir, workspace_root};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// The package directory that holds `local/povrayst/VERSION`, built and installed on first use.
pub fn package_path() -> &'static Path {
    static INSTALLED: OnceLock<PathBuf> = OnceLock::new();
    INSTALLED.get_or_init(|| {
        let packages = target_dir().join("typst-packages");
        let output = Command::new(workspace_root().join("scripts/install-package"))
            .arg(&packages)
            .env("CARGO_TARGET_DIR", target_dir())
            .output()
            .expect("cannot run scripts/install-package");
        assert!(
            output.status.success(),
            "scripts/install-package failed:\n{}",
            String::from_utf8_lossy(&output.stderr)
        );
        packages
    })
}

/// A Typst document in a directory of its own, with the files it reads.
pub struct Document {
    dir: tempfile::TempDir,
}

impl Document {
    /// `main.typ` with `source`, which usually starts with
    /// `#import "@local/povrayst:0.1.0": *`.
    pub fn new(source: &str) -> Document {
        let dir = tempfile::tempdir().expect("cannot make a temporary directory");
        std::fs::write(dir.path().join("main.typ"), source).expect("cannot write main.typ");
        Document { dir }
    }

    /// Adds a file the document reads, such as a scene or an include; `name` may name a
    /// folder too (`assets/map.png`).
    pub fn with_file(self, name: &str, contents: impl AsRef<[u8]>) -> Document {
        let path = self.dir.path().join(name);
        if let Some(folder) = path.parent() {
            std::fs::create_dir_all(folder).expect("cannot make a folder");
        }
        std::fs::write(path, contents).expect("cannot write a file");
        self
    }

    pub fn dir(&self) -> &Path {
        self.dir.path()
    }

    /// Compiles to PDF, or fails with the compiler's error.
    pub fn compile(&self) -> Result<Vec<u8>, CompileError> {
        let pdf = self.dir.path().join("main.pdf");
        self.compile_to(&pdf)?;
        Ok(std::fs::read(pdf).expect("the compiler wrote no PDF"))
    }

    /// Compiles to `output`, a `.pdf`, `.png` or `.svg` file.
    pub fn compile_to(&self, output: &Path) -> Result<(), CompileError> {
        self.run(&[output.to_str().expect("a UTF-8 path")])?;
        Ok(())
    }

    /// The error message of a compile that must fail.
    #[track_caller]
    pub fn compile_error(&self) -> String {
        match self.compile() {
            Ok(_) => panic!("the document compiled, but an error was expected"),
            Err(error) => error.message,
        }
    }

    /// The `value` of the `metadata` labelled `label` (`<result>`), as JSON.
    pub fn query(&self, label: &str) -> Result<serde_json::Value, CompileError> {
        let (stdout, _) = self.run(&["--query", label])?;
        Ok(serde_json::from_str(&stdout).expect("the query printed no JSON"))
    }

    /// [`Document::query`] and the CPU seconds the compile took, every thread of the
    /// compiler counted (Python's start-up and the import of the binding left out).
    pub fn timed_query(&self, label: &str) -> Result<(serde_json::Value, f64), CompileError> {
        let (stdout, stderr) = self.run(&["--query", label, "--timings"])?;
        let seconds = stderr
            .lines()
            .find_map(|l| l.rsplit(", ").next()?.strip_suffix(" CPU s")?.parse().ok())
            .unwrap_or_else(|| panic!("no compile time in: {stderr}"));
        let value = serde_json::from_str(&stdout).expect("the query printed no JSON");
        Ok((value, seconds))
    }

    /// The compiler's standard output and standard error.
    fn run(&self, args: &[&str]) -> Result<(String, String), CompileError> {
        let output = Command::new("python3")
            .arg(workspace_root().join("scripts/typst-compile.py"))
            .arg(self.dir.path().join("main.typ"))
            .args(args)
            .arg("--root")
            .arg(self.dir.path())
            .arg("--package-path")
            .arg(package_path())
            .arg("--json-errors")
            .output()
            .expect("cannot run python3: install it with scripts/setup");
        let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
        match output.status.code() {
            Some(0) => Ok((String::from_utf8_lossy(&output.stdout).into_owned(), stderr)),
            Some(1) => Err(serde_json::from_str(&stderr)
                .unwrap_or_else(|e| panic!("no JSON error report ({e}):\n{stderr}"))),
            _ => panic!(
                "scripts/typst-compile.py failed to run (is `typst` installed? run scripts/setup):\n{stderr}"
            ),
        }
    }
}

/// A failed compile, as the compiler reports it.
#[derive(Debug, Clone, PartialEq, Eq, serde::Deserialize)]
pub struct CompileError {
    /// The message alone, as Typst shows it after `error: `.
    pub message: String,
    pub hints: Vec<String>,
    /// The whole report: message, source locations, hints.
    pub diagnostic: String,
}
