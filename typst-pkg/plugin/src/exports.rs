//! The functions Typst calls, through wasm-minimal-protocol. They only move bytes; the
//! work happens in the modules beside this one.

// The protocol macros generate the `extern` glue that copies arguments in and results out.
#![allow(unsafe_code)]

use wasm_minimal_protocol::{initiate_protocol, wasm_func};

initiate_protocol!();

/// The package version this plugin was built for, as text.
#[wasm_func]
pub fn version() -> Vec<u8> {
    env!("CARGO_PKG_VERSION").as_bytes().to_vec()
}

/// Raises `message` as a plugin error. `lib.typ` calls it with a scene's gcc-style error
/// text, so that the text reaches the user verbatim (Typst's `panic` would quote it).
#[wasm_func]
pub fn fail(message: &[u8]) -> Result<Vec<u8>, String> {
    Err(String::from_utf8_lossy(message).into_owned())
}
