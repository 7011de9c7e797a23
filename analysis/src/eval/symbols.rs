//! Identifier scopes with POV-Ray's rules: lookups search the newest table first; `#local`
//! always writes the current table; `#declare` writes the newest existing definition, or
//! creates a global one.

use super::Evaluator;
use super::value::{Slot, Value};
use std::cell::RefCell;
use std::rc::Rc;

/// One symbol table. Identifiers are looked up on nearly every token a scene runs, so the
/// table hashes with the fast non-cryptographic FxHash rather than SipHash: the keys are the
/// scene's own names, not input an attacker could shape into collisions that matter.
pub type Scope = std::collections::HashMap<String, Slot, rustc_hash::FxBuildHasher>;

impl Evaluator<'_> {
    /// Opens the scope of an include file or macro call. Macros run their bodies many
    /// times over, so the tables of scopes that ended are kept and reused with the room
    /// they grew, instead of being allocated and grown anew on every call.
    pub fn push_scope(&mut self) {
        let scope = self.spare_scopes.pop().unwrap_or_default();
        self.scopes.push(scope);
    }

    /// Closes the newest scope; its definitions are dropped now.
    pub fn pop_scope(&mut self) {
        if let Some(mut scope) = self.scopes.pop() {
            scope.clear();
            self.spare_scopes.push(scope);
        }
    }

    /// The storage of the most local definition of `name`.
    pub fn lookup(&self, name: &str) -> Option<Slot> {
        self.lookup_in(self.scopes.len() - 1, name)
    }

    /// The storage of the most local definition of `name` in scope `scope` or an outer one.
    pub fn lookup_in(&self, scope: usize, name: &str) -> Option<Slot> {
        self.scopes[..=scope]
            .iter()
            .rev()
            .find_map(|scope| scope.get(name).cloned())
    }

    /// `#declare name = value`.
    pub fn declare(&mut self, name: &str, value: Value) {
        self.declare_in(self.scopes.len() - 1, name, value);
    }

    /// `#declare name = value` as seen from scope `scope`.
    pub fn declare_in(&mut self, scope: usize, name: &str, value: Value) {
        if let Some(slot) = self.lookup_in(scope, name) {
            *slot.borrow_mut() = value;
        } else {
            self.scopes[0].insert(name.to_owned(), Rc::new(RefCell::new(value)));
        }
    }

    /// `#local name = value`. An existing local definition keeps its storage, so that a
    /// macro parameter passed by reference still writes through to the caller.
    pub fn declare_local(&mut self, name: &str, value: Value) {
        self.declare_local_in(self.scopes.len() - 1, name, value);
    }

    /// `#local name = value` in scope `scope`.
    pub fn declare_local_in(&mut self, scope: usize, name: &str, value: Value) {
        match self.scopes[scope].get(name) {
            Some(slot) => *slot.borrow_mut() = value,
            None => {
                self.scopes[scope].insert(name.to_owned(), Rc::new(RefCell::new(value)));
            }
        }
    }

    /// Binds `name` in the newest scope to existing storage (a by-reference parameter).
    pub fn bind(&mut self, name: &str, slot: Slot) {
        self.scopes
            .last_mut()
            .expect("there is always a global scope")
            .insert(name.to_owned(), slot);
    }

    /// `#undef name`: removes the most local definition. Returns whether there was one.
    pub fn undef(&mut self, name: &str) -> bool {
        self.scopes
            .iter_mut()
            .rev()
            .any(|scope| scope.remove(name).is_some())
    }

    /// The declared name or reserved word closest to a misspelt identifier.
    pub fn suggest(&self, name: &str) -> Option<String> {
        let declared = self
            .scopes
            .iter()
            .flat_map(|scope| scope.keys().map(String::as_str));
        // Reserved words are all lower case; a capitalised name is meant as an identifier.
        let lower = name.chars().all(|c| !c.is_ascii_uppercase());
        let keywords = syntax::KEYWORDS
            .iter()
            .map(|(kw, _)| *kw)
            .filter(move |_| lower);
        crate::spelling::closest(name, declared.chain(keywords)).map(str::to_owned)
    }
}
