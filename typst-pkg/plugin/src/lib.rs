//! The Typst plugin: receives a scene and its options from Typst as bytes, renders it, and
//! hands back pixels or a located error. Only this crate knows the plugin protocol.

pub mod render_job;
pub mod request;
pub mod response;
pub mod syntax_definition;

#[cfg(target_arch = "wasm32")]
mod exports;
