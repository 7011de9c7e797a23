//! The Typst plugin: receives a scene and its options from Typst as bytes, renders it, and
//! hands back pixels or a located error. Only this crate knows the plugin protocol.
