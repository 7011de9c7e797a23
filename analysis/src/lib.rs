//! Turns SDL source into meaning: the evaluator that runs directives, macros and expressions
//! and produces a [`scene::Scene`], the compiled `function { }` form, and the incremental
//! analysis database that the language server queries.

pub mod function;
pub mod scene;
pub mod stdinc;
