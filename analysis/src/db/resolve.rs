//! Name resolution: what each identifier of a file names. SDL resolves names when the
//! scene runs, so this follows the shape of a typical scene: a macro's parameters and
//! `#local`s first, then the file's own definitions (the last one before the use, or the
//! first after it), then what the file's includes define.

use super::{Db, Definition, File, SymbolKind, file_symbols, include_scope, name_ranges};
use std::collections::HashMap;
use syntax::SyntaxKind::*;
use syntax::{SyntaxNode, SyntaxToken};

/// For each identifier of `file` (its `IDENT` tokens in text order, defining names
/// included), the definition it names, if one is in sight. Dictionary keys (`D.key`) name
/// nothing.
///
/// Position-free: an edit that changes no resolution leaves it equal, so references in
/// other files that depend on it are reused.
#[salsa::tracked(returns(ref))]
pub fn resolve_file(db: &dyn Db, file: File) -> Vec<Option<Definition>> {
    let root = super::parse(db, file).syntax_node();
    let resolver = Resolver::new(db, file);
    identifiers(&root)
        .map(|token| resolver.resolve(&token))
        .collect()
}

/// The identifier tokens of a tree, in the order [`resolve_file`] numbers them.
pub fn identifiers(root: &SyntaxNode) -> impl Iterator<Item = SyntaxToken> + use<> {
    root.descendants_with_tokens()
        .filter_map(|element| element.into_token())
        .filter(|token| token.kind() == IDENT)
}

struct Resolver<'db> {
    db: &'db dyn Db,
    file: File,
    /// Symbol indices by the number of their defining name.
    by_name_index: HashMap<u32, u32>,
    /// Symbol indices by name, in text order, so that a use looks only at its namesakes.
    by_name: HashMap<&'db str, Vec<usize>>,
}

impl<'db> Resolver<'db> {
    fn new(db: &'db dyn Db, file: File) -> Self {
        let symbols = file_symbols(db, file);
        let by_name_index = symbols
            .iter()
            .enumerate()
            .map(|(index, symbol)| (symbol.name_index, index as u32))
            .collect();
        let mut by_name: HashMap<&'db str, Vec<usize>> = HashMap::new();
        for (index, symbol) in symbols.iter().enumerate() {
            by_name.entry(symbol.name.as_str()).or_default().push(index);
        }
        Resolver {
            db,
            file,
            by_name_index,
            by_name,
        }
    }

    fn definition(&self, symbol: u32) -> Definition {
        Definition {
            file: self.file,
            symbol,
        }
    }

    fn resolve(&self, token: &SyntaxToken) -> Option<Definition> {
        let parent = token.parent()?;
        if parent.kind() == NAME {
            let index = name_index(self.db, self.file, token)?;
            return self.by_name_index.get(&index).map(|&s| self.definition(s));
        }
        if is_dictionary_key(token) {
            return None;
        }
        let name = token.text();
        let offset = token.text_range().start();
        let symbols = file_symbols(self.db, self.file);
        let ranges = name_ranges(self.db, self.file);
        let defined_at = |index: usize| ranges[symbols[index].name_index as usize].start();
        let namesakes: &[usize] = self.by_name.get(name).map_or(&[], Vec::as_slice);

        // Inside macros, innermost first: parameters, then the macro's own #locals.
        let containers = if namesakes.iter().any(|&i| symbols[i].container.is_some()) {
            self.containers(token)
        } else {
            Vec::new()
        };
        for container in containers {
            let locals = namesakes
                .iter()
                .copied()
                .filter(|&i| symbols[i].container == Some(container));
            if let Some(index) = locals
                .clone()
                .find(|&i| symbols[i].kind == SymbolKind::Parameter)
            {
                return Some(self.definition(index as u32));
            }
            let before = locals
                .clone()
                .rfind(|&i| defined_at(i) < offset)
                .or_else(|| locals.clone().next());
            if let Some(index) = before
                && symbols[index].local
            {
                return Some(self.definition(index as u32));
            }
        }

        // The file's own definitions that are visible everywhere in it.
        let visible = namesakes.iter().copied().filter(|&i| {
            let s = &symbols[i];
            s.kind != SymbolKind::Parameter && (s.container.is_none() || !s.local)
        });
        let chosen = visible
            .clone()
            .rfind(|&i| defined_at(i) < offset)
            .or_else(|| visible.clone().next());
        if let Some(index) = chosen {
            return Some(self.definition(index as u32));
        }
        include_scope(self.db, self.file).get(name).copied()
    }

    /// The symbol indices of the macros around a token, innermost first.
    fn containers(&self, token: &SyntaxToken) -> Vec<u32> {
        let symbols = file_symbols(self.db, self.file);
        token
            .parent_ancestors()
            .filter(|node| node.kind() == MACRO)
            .filter_map(|node| {
                let name = node.children().find(|c| c.kind() == NAME)?;
                let ident = name
                    .children_with_tokens()
                    .filter_map(|e| e.into_token())
                    .find(|t| t.kind() == IDENT)?;
                let index = name_index(self.db, self.file, &ident)?;
                symbols
                    .iter()
                    .position(|s| s.name_index == index)
                    .map(|i| i as u32)
            })
            .collect()
    }
}

/// The number of the `NAME` node that holds an identifier, as [`super::Symbol::name_index`]
/// counts them.
pub fn name_index(db: &dyn Db, file: File, token: &SyntaxToken) -> Option<u32> {
    let ranges = name_ranges(db, file);
    let range = token.text_range();
    ranges
        .binary_search_by(|r| r.start().cmp(&range.start()))
        .ok()
        .map(|i| i as u32)
}

/// `key` in `Dict.key`: a member, not a name.
fn is_dictionary_key(token: &SyntaxToken) -> bool {
    let mut previous = token.prev_token();
    while let Some(t) = &previous {
        if !t.kind().is_trivia() {
            break;
        }
        previous = t.prev_token();
    }
    previous.is_some_and(|t| t.kind() == DOT)
}
