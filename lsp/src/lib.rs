//! The Povrayst language server: speaks the language server protocol over stdio and answers
//! from the analysis database. Only this crate knows LSP types.
