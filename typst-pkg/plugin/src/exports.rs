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

/// The Sublime syntax definition of SDL, for `raw(syntaxes: ..)`.
#[wasm_func]
pub fn syntax_definition() -> Vec<u8> {
    crate::syntax_definition::sublime_syntax().into_bytes()
}

/// Raises `message` as a plugin error. `lib.typ` calls it with a scene's gcc-style error
/// text, so that the text reaches the user verbatim (Typst's `panic` would quote it).
#[wasm_func]
pub fn fail(message: &[u8]) -> Result<Vec<u8>, String> {
    Err(String::from_utf8_lossy(message).into_owned())
}

/// Renders a request (see `request`) and answers with pixels or the scene's error text (see
/// `response`). Only a malformed request, which `lib.typ` never sends, is a plugin error.
#[wasm_func]
pub fn render(request: &[u8]) -> Result<Vec<u8>, String> {
    let request = crate::request::Request::decode(request)?;
    Ok(crate::render_job::run(&request).encode())
}
