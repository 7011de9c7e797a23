//! Shared support for the integration tests in `tests/tests/`: where the workspace and its
//! build output are, the `povrayst` binary, and the Typst compiler with the package.

pub mod broken_scenes;
pub mod conformance;
pub mod cpu_time;
pub mod example_corpus;
pub mod fidelity;
pub mod image_compare;
pub mod lsp_client;
pub mod plugin_timing;
pub mod typst_compiler;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// The workspace's root directory.
pub fn workspace_root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// The profile directory (`TARGET/debug` or `TARGET/release`) this binary was built into:
/// test binaries live in its `deps` folder, the benchmarks (`src/bin`) in it directly.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the binary has a path");
    let parent = exe.parent().expect("the binary lives in a directory");
    if parent.file_name().is_some_and(|name| name == "deps") {
        parent.parent().expect("TARGET/PROFILE/deps").to_path_buf()
    } else {
        parent.to_path_buf()
    }
}

/// The Cargo target directory this binary was built into.
pub fn target_dir() -> PathBuf {
    profile_dir()
        .parent()
        .expect("the binary lives in TARGET/PROFILE")
        .to_path_buf()
}

/// The `povrayst` binary, built (in the test's own profile) on first use.
pub fn povrayst_binary() -> &'static Path {
    static BUILT: OnceLock<PathBuf> = OnceLock::new();
    BUILT.get_or_init(|| {
        let profile_dir = profile_dir();
        let release = profile_dir
            .file_name()
            .is_some_and(|name| name == "release");
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        let mut build = Command::new(cargo);
        build
            .args(["build", "--quiet", "-p", "povrayst", "--bin", "povrayst"])
            .current_dir(workspace_root())
            .env("CARGO_TARGET_DIR", target_dir());
        if release {
            build.arg("--release");
        }
        let status = build.status().expect("cannot run cargo");
        assert!(status.success(), "cargo build -p povrayst failed");
        profile_dir.join(format!("povrayst{}", std::env::consts::EXE_SUFFIX))
    })
}
