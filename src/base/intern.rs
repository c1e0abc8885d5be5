//! String interning: every distinct name gets a dense `u32` id.
//!
//! Invariant: `Sym(i)` is valid for the interner that produced it; `resolve(intern(s)) == s`.
//! Interners are per run and never shrink.

use hashbrown::{DefaultHashBuilder, HashTable};
use std::hash::BuildHasher;
use std::sync::Arc;

/// An interned string.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Sym(pub u32);

/// Maps strings to [`Sym`]s and back.
#[derive(Default, Clone)]
pub struct Interner {
    /// Ids, hashed by their string (each string is stored once, in `strings`).
    table: HashTable<Sym>,
    hasher: DefaultHashBuilder,
    /// String of each id.
    strings: Vec<Arc<str>>,
}

impl std::fmt::Debug for Interner {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Interner")
            .field("strings", &self.strings)
            .finish()
    }
}

impl Interner {
    /// An empty interner.
    pub fn new() -> Interner {
        Interner::default()
    }

    /// The id of `s`, created if new.
    pub fn intern(&mut self, s: &str) -> Sym {
        let hash = self.hasher.hash_one(s);
        let strings = &self.strings;
        if let Some(&sym) = self.table.find(hash, |&k| &*strings[k.0 as usize] == s) {
            return sym;
        }
        let sym = Sym(self.strings.len() as u32);
        self.strings.push(s.into());
        let Interner {
            table,
            hasher,
            strings,
        } = self;
        table.insert_unique(hash, sym, |&k| hasher.hash_one(&*strings[k.0 as usize]));
        sym
    }

    /// The id of `s` if it was interned.
    pub fn get(&self, s: &str) -> Option<Sym> {
        let hash = self.hasher.hash_one(s);
        self.table
            .find(hash, |&k| &*self.strings[k.0 as usize] == s)
            .copied()
    }

    /// The string of `sym`.
    pub fn resolve(&self, sym: Sym) -> &str {
        &self.strings[sym.0 as usize]
    }

    /// The string of `sym`, shared: a clone of the interner's own copy (no allocation), for
    /// values that outlive the interner (`control::Symbol` names).
    pub fn resolve_shared(&self, sym: Sym) -> Arc<str> {
        Arc::clone(&self.strings[sym.0 as usize])
    }

    /// Number of interned strings.
    pub fn len(&self) -> usize {
        self.strings.len()
    }

    /// True when nothing was interned.
    pub fn is_empty(&self) -> bool {
        self.strings.is_empty()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        let mut i = Interner::new();
        let a = i.intern("a");
        let b = i.intern("b");
        assert_ne!(a, b);
        assert_eq!(i.intern("a"), a);
        assert_eq!(i.resolve(b), "b");
        assert_eq!(i.get("c"), None);
    }
}
