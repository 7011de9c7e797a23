//! The parser on any text: no panic, no hang (libFuzzer's timeout), the tree holds
//! exactly the text, errors point into it, and the typed view and the diagnostic
//! renderer survive whatever tree comes out.

#![no_main]

use libfuzzer_sys::fuzz_target;
use syntax::ast::{self, AstNode};

fuzz_target!(|text: &str| {
    let parse = syntax::parse(text);
    let root = parse.syntax_node();
    assert_eq!(root.to_string(), text, "the tree must round-trip");
    for error in parse.errors() {
        assert!(usize::from(error.range.end()) <= text.len());
    }
    let tree = parse.debug_tree();
    assert!(tree.starts_with("SOURCE_FILE"));

    let diagnostics = syntax::syntax_diagnostics("fuzz.pov", &parse);
    let sources: &[(&str, &str)] = &[("fuzz.pov", text)];
    syntax::diagnostic::render_human(&diagnostics, sources);

    let file = parse.source_file();
    for comment in file.comments() {
        comment.content();
    }
    for node in root.descendants() {
        if let Some(declare) = ast::Declare::cast(node.clone()) {
            declare.name().and_then(|n| n.text());
            declare.value();
            declare.element_target();
            declare.is_local();
        }
        if let Some(m) = ast::Macro::cast(node.clone()) {
            m.name();
            m.params().for_each(|p| {
                p.name();
                p.is_optional();
            });
            m.body().map(|b| b.is_structured());
        }
        if let Some(call) = ast::Call::cast(node.clone()) {
            call.name_ref().and_then(|n| n.text());
            call.builtin();
            call.arg_list().map(|a| a.args().count());
        }
        if let Some(include) = ast::Include::cast(node.clone()) {
            include.path();
        }
        if let Some(block) = ast::Block::cast(node.clone()) {
            block.keyword();
            block.items().count();
        }
        if let Some(conditional) = ast::If::cast(node.clone()) {
            conditional.condition();
            conditional.is_inline();
            conditional.branches().for_each(|b| {
                b.condition();
                b.body();
            });
        }
        if let Some(property) = ast::Property::cast(node) {
            property.keyword();
            property.value();
        }
    }
});
