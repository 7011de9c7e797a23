//! The evaluator on any text: no panic and no hang. Small budgets turn endless loops and
//! runaway recursion into their located errors; every diagnostic points into a file that
//! the evaluation read, and renders.

#![no_main]

use analysis::{Budgets, EvalOptions, MemoryFiles, evaluate};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|text: &str| {
    let files = MemoryFiles::new().with("fuzz.pov", text).with("fuzz.inc", text);
    let options = EvalOptions {
        image_width: 32,
        image_height: 24,
        budgets: Budgets {
            loop_iterations: 10_000,
            macro_depth: 64,
            include_depth: 8,
            steps: 200_000,
            array_elements: 100_000,
            string_bytes: 1 << 16,
        },
        ..EvalOptions::default()
    };
    let evaluation = evaluate("fuzz.pov", &files, &options);
    for diagnostic in &evaluation.diagnostics {
        let source = evaluation.sources.get(&diagnostic.span.file);
        if let Some(source) = source {
            assert!(usize::from(diagnostic.span.range.end()) <= source.len());
        }
    }
    syntax::diagnostic::render_human(&evaluation.diagnostics, &evaluation.sources);
});
