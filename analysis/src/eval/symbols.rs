//! Identifier scopes with POV-Ray's rules: lookups search the newest table first; `#local`
//! always writes the current table; `#declare` writes the newest existing definition, or
//! creates a global one.
//!
//! Names are interned: a scope maps small numbers to storage, so that the lookups on nearly
//! every token a scene runs hash a number, not a string, once per table searched.

use super::Evaluator;
use super::tokens::FileId;
use super::value::{Slot, Value};
use std::cell::RefCell;
use std::rc::Rc;

/// An interned identifier.
pub type Symbol = u32;

/// One symbol table. The table hashes with the fast non-cryptographic FxHash rather than
/// SipHash: the keys are the evaluator's own symbol numbers.
pub type Scope = std::collections::HashMap<Symbol, Slot, rustc_hash::FxBuildHasher>;

/// How many emptied definitions' storage is kept for reuse at most.
const MAX_SPARE_SLOTS: usize = 256;

/// A token position whose symbol has not been looked up yet.
const UNKNOWN: Symbol = Symbol::MAX;

/// The names met so far, numbered in order of appearance, and the symbol of each identifier
/// token of each file, filled in as the tokens are read.
#[derive(Debug, Default)]
pub struct Interner {
    ids: rustc_hash::FxHashMap<Rc<str>, Symbol>,
    names: Vec<Rc<str>>,
    at_token: Vec<Vec<Symbol>>,
}

impl Interner {
    /// The symbol of `name`, numbered now if it is new.
    pub fn intern(&mut self, name: &str) -> Symbol {
        if let Some(&symbol) = self.ids.get(name) {
            return symbol;
        }
        let symbol = self.names.len() as Symbol;
        let name: Rc<str> = Rc::from(name);
        self.names.push(name.clone());
        self.ids.insert(name, symbol);
        symbol
    }

    /// The symbol of `name` if it was ever met: a name never met is declared nowhere.
    pub fn get(&self, name: &str) -> Option<Symbol> {
        self.ids.get(name).copied()
    }

    pub fn name(&self, symbol: Symbol) -> &str {
        &self.names[symbol as usize]
    }
}

impl Evaluator<'_> {
    /// The symbol of the identifier at token `index` of `file`.
    pub fn symbol_at(&mut self, file: FileId, index: usize) -> Symbol {
        let at_token = &mut self.interner.at_token;
        if at_token.len() <= file as usize {
            at_token.resize_with(file as usize + 1, Vec::new);
        }
        if at_token[file as usize].is_empty() {
            let tokens = self.files[file as usize].tokens.len();
            at_token[file as usize] = vec![UNKNOWN; tokens];
        }
        let known = at_token[file as usize][index];
        if known != UNKNOWN {
            return known;
        }
        let source = &self.files[file as usize];
        let token = source.tokens[index];
        let name = &source.text[token.start as usize..token.end as usize];
        let symbol = self.interner.intern(name);
        self.interner.at_token[file as usize][index] = symbol;
        symbol
    }

    /// Opens the scope of an include file or macro call. Macros run their bodies many
    /// times over, so the tables of scopes that ended are kept and reused with the room
    /// they grew, instead of being allocated and grown anew on every call.
    pub fn push_scope(&mut self) {
        let scope = self.spare_scopes.pop().unwrap_or_default();
        self.scopes.push(scope);
    }

    /// Closes the newest scope; its definitions are dropped now. Their storage, when
    /// nothing else holds it (a by-reference argument's belongs to the caller), is kept
    /// for new definitions: a macro's parameters and locals are defined anew on every call.
    pub fn pop_scope(&mut self) {
        if let Some(mut scope) = self.scopes.pop() {
            for (_, slot) in scope.drain() {
                if self.spare_slots.len() < MAX_SPARE_SLOTS
                    && Rc::strong_count(&slot) == 1
                    && Rc::weak_count(&slot) == 0
                {
                    *slot.borrow_mut() = Value::Uninitialized;
                    self.spare_slots.push(slot);
                }
            }
            self.spare_scopes.push(scope);
        }
    }

    /// New storage holding `value`.
    fn new_slot(&mut self, value: Value) -> Slot {
        match self.spare_slots.pop() {
            Some(slot) => {
                *slot.borrow_mut() = value;
                slot
            }
            None => Rc::new(RefCell::new(value)),
        }
    }

    /// The storage of the most local definition of `name`.
    pub fn lookup(&self, name: &str) -> Option<Slot> {
        self.lookup_in(self.scopes.len() - 1, name)
    }

    /// The storage of the most local definition of `name` in scope `scope` or an outer one.
    pub fn lookup_in(&self, scope: usize, name: &str) -> Option<Slot> {
        let symbol = self.interner.get(name)?;
        self.lookup_symbol_in(scope, symbol)
    }

    /// The storage of the most local definition of `symbol`.
    pub fn lookup_symbol(&self, symbol: Symbol) -> Option<Slot> {
        self.lookup_symbol_in(self.scopes.len() - 1, symbol)
    }

    pub fn lookup_symbol_in(&self, scope: usize, symbol: Symbol) -> Option<Slot> {
        self.scopes[..=scope]
            .iter()
            .rev()
            .find_map(|scope| scope.get(&symbol).cloned())
    }

    /// The storage of `name` in scope `scope` itself.
    pub fn local_slot(&self, scope: usize, name: &str) -> Option<Slot> {
        let symbol = self.interner.get(name)?;
        self.scopes[scope].get(&symbol).cloned()
    }

    /// `#declare name = value`.
    pub fn declare(&mut self, name: &str, value: Value) {
        self.declare_in(self.scopes.len() - 1, name, value);
    }

    /// `#declare name = value` as seen from scope `scope`.
    pub fn declare_in(&mut self, scope: usize, name: &str, value: Value) {
        let symbol = self.interner.intern(name);
        self.declare_symbol_in(scope, symbol, value);
    }

    /// `#declare symbol = value` as seen from scope `scope`.
    pub fn declare_symbol_in(&mut self, scope: usize, symbol: Symbol, value: Value) {
        if let Some(slot) = self.lookup_symbol_in(scope, symbol) {
            *slot.borrow_mut() = value;
        } else {
            self.scopes[0].insert(symbol, Rc::new(RefCell::new(value)));
        }
    }

    /// `#local symbol = value` in the newest scope. An existing local definition keeps its
    /// storage, so that a macro parameter passed by reference still writes through to the
    /// caller.
    pub fn declare_local_symbol(&mut self, symbol: Symbol, value: Value) {
        self.declare_local_symbol_in(self.scopes.len() - 1, symbol, value);
    }

    /// `#local symbol = value` in scope `scope`.
    pub fn declare_local_symbol_in(&mut self, scope: usize, symbol: Symbol, value: Value) {
        match self.scopes[scope].get(&symbol) {
            Some(slot) => *slot.borrow_mut() = value,
            None => {
                let slot = self.new_slot(value);
                self.scopes[scope].insert(symbol, slot);
            }
        }
    }

    /// A global definition of `name` with storage of its own, whatever held the name before.
    pub fn define_global(&mut self, name: &str, value: Value) {
        let symbol = self.interner.intern(name);
        self.scopes[0].insert(symbol, Rc::new(RefCell::new(value)));
    }

    /// Binds `symbol` in the newest scope to existing storage (a by-reference parameter).
    pub fn bind(&mut self, symbol: Symbol, slot: Slot) {
        self.scopes
            .last_mut()
            .expect("there is always a global scope")
            .insert(symbol, slot);
    }

    /// `#undef name`: removes the most local definition. Returns whether there was one.
    pub fn undef(&mut self, name: &str) -> bool {
        let Some(symbol) = self.interner.get(name) else {
            return false;
        };
        self.scopes
            .iter_mut()
            .rev()
            .any(|scope| scope.remove(&symbol).is_some())
    }

    /// The declared name or reserved word closest to a misspelt identifier.
    pub fn suggest(&self, name: &str) -> Option<String> {
        // In order of first appearance, so that of two names as close the same one wins
        // every time.
        let mut symbols: Vec<Symbol> = self
            .scopes
            .iter()
            .flat_map(|scope| scope.keys().copied())
            .collect();
        symbols.sort_unstable();
        let declared = symbols.into_iter().map(|symbol| self.interner.name(symbol));
        // Reserved words are all lower case; a capitalised name is meant as an identifier.
        let lower = name.chars().all(|c| !c.is_ascii_uppercase());
        let keywords = syntax::KEYWORDS
            .iter()
            .map(|(kw, _)| *kw)
            .filter(move |_| lower);
        crate::spelling::closest(name, declared.chain(keywords)).map(str::to_owned)
    }
}
