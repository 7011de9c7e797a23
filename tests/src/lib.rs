//! Shared support for the integration tests in `tests/tests/`: where the workspace and its
//! build output are, the `povrayst` binary, and the Typst compiler with the package.

pub mod broken_scenes;
pub mod conformance;
pub mod cpu_time;
pub mod example_corpus;
pub mod fidelity;
pub mod image_compare;
pub mod lsp_client;
pub mod typst_compiler;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// The workspace's root directory.
pub fn workspace_root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// The Cargo target directory this test binary was built into (`target/debug/deps/TEST`
/// is three levels below it).
pub fn target_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test binary has a path");
    exe.ancestors()
        .nth(3)
        .expect("the test binary lives in TARGET/PROFILE/deps")
        .to_path_buf()
}

/// The `povrayst` binary, built (in the test's own profile) on first use.
pub fn povrayst_binary() -> &'static Path {
    static BUILT: OnceLock<PathBuf> = OnceLock::new();
    BUILT.get_or_init(|| {
        let exe = std::env::current_exe().expect("the test binary has a path");
        let profile_dir = exe.ancestors().nth(2).expect("TARGET/PROFILE/deps/TEST");
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
