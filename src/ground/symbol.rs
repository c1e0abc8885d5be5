//! Ground terms (symbols): a hash-consed table of flat nodes with `u32` ids, clingo's total
//! order on them, and their printed form (by `syntax::printer::write_symbol`, through
//! [`TableSym`]).
//!
//! Invariants:
//! - Structurally equal symbols have the same [`SymId`] (hash-consing), so equality is id
//!   equality and a symbol's arguments are ids of symbols created before it (children before
//!   parents, as egg's `RecExpr`).
//! - The order ([`order`], the crate's one symbol order, for this table [`Symbols::compare`]
//!   and for `control::Symbol`) is clingo's: `#inf` < integers < constants (positive
//!   before classically negated, then by name) < strings < functions and tuples (by arity, then
//!   positive before negated, then name, then arguments left to right) < `#sup`. Checked against
//!   clingo 5.8.3's `Symbol.__lt__`.
//! - Integers are 32-bit, as in clingo.
//! - Small integers (`SMALL_MIN..SMALL_MAX`) are also found through a direct table, so the
//!   arithmetic of the grounder's inner loops does not hash; the table only caches ids that the
//!   hash-consing table holds too.

use std::cmp::Ordering;

use hashbrown::HashTable;

use crate::base::intern::{Interner, Sym};
use crate::syntax::printer::{write_symbol, GroundTerm, Shape};

/// A ground term, an index into [`Symbols`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SymId(pub u32);

/// One node of the symbol table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SymData {
    /// `#inf`
    Inf,
    /// An integer.
    Num(i32),
    /// A string (its unescaped text, interned).
    Str(Sym),
    /// A function, constant (no arguments) or tuple (empty name), possibly classically negated.
    Fun {
        /// The name; the empty name for tuples.
        name: Sym,
        /// Classical negation `-f(...)`.
        neg: bool,
        /// Start of the arguments in the argument arena.
        start: u32,
        /// Number of arguments.
        len: u32,
    },
    /// `#sup`
    Sup,
}

/// The symbol table: interned names and hash-consed ground terms.
#[derive(Debug, Clone)]
pub struct Symbols {
    /// Names of functions and texts of strings.
    pub names: Interner,
    /// Node of each symbol.
    data: Vec<SymData>,
    /// Argument arena: the arguments of `Fun` nodes, contiguous per node.
    args: Vec<SymId>,
    /// Hash-consing table over `data`, hashed by [`key_hash`].
    table: HashTable<SymId>,
    /// Id of each small integer, at index `small_index(n)` (`u32::MAX` when not created yet);
    /// grown on demand, so a table that only sees small numbers stays small.
    small: Vec<u32>,
}

/// Smallest integer of the direct table.
const SMALL_MIN: i32 = -1024;
/// One past the largest integer of the direct table.
const SMALL_MAX: i32 = 16384;

/// The index of a small integer in the direct table: `0, -1, 1, -2, 2, ...` interleaved, so
/// that the table grows with the magnitude of the numbers seen.
#[inline]
fn small_index(n: i32) -> usize {
    if n >= 0 {
        2 * n as usize
    } else {
        2 * (-(n as i64)) as usize - 1
    }
}

impl Default for Symbols {
    fn default() -> Self {
        Symbols::new()
    }
}

impl Symbols {
    /// An empty table.
    pub fn new() -> Symbols {
        Symbols {
            names: Interner::new(),
            data: Vec::new(),
            args: Vec::new(),
            table: HashTable::new(),
            small: Vec::new(),
        }
    }

    /// Makes room for `n` more symbols (with two arguments each on average), so that a
    /// grounding whose size is known roughly does not rehash the table as it grows.
    pub fn reserve(&mut self, n: usize) {
        let Symbols {
            table, data, args, ..
        } = self;
        table.reserve(n, |&other| key_hash(&key_from(data, args, other)));
        data.reserve(n);
        args.reserve(2 * n);
    }

    /// Number of distinct symbols.
    pub fn len(&self) -> usize {
        self.data.len()
    }

    /// True when no symbol exists.
    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    /// The node of `id`.
    pub fn get(&self, id: SymId) -> SymData {
        self.data[id.0 as usize]
    }

    /// The arguments of a function symbol (empty for other symbols).
    pub fn args(&self, id: SymId) -> &[SymId] {
        match self.get(id) {
            SymData::Fun { start, len, .. } => &self.args[start as usize..(start + len) as usize],
            _ => &[],
        }
    }

    /// The integer value of `id`, if it is an integer.
    pub fn num(&self, id: SymId) -> Option<i32> {
        match self.get(id) {
            SymData::Num(n) => Some(n),
            _ => None,
        }
    }

    fn hash_key(&self, kind: &KeyRef<'_>) -> u64 {
        key_hash(kind)
    }

    fn key_of(&self, id: SymId) -> KeyRef<'_> {
        match self.get(id) {
            SymData::Inf => KeyRef::Inf,
            SymData::Sup => KeyRef::Sup,
            SymData::Num(n) => KeyRef::Num(n),
            SymData::Str(s) => KeyRef::Str(s),
            SymData::Fun { name, neg, .. } => KeyRef::Fun(name, neg, self.args(id)),
        }
    }

    fn intern_key(&mut self, key: KeyRef<'_>) -> SymId {
        let hash = self.hash_key(&key);
        if let Some(&id) = self.table.find(hash, |&id| self.key_of(id) == key) {
            return id;
        }
        self.insert_new(hash, key)
    }

    /// Adds the symbol of `key`, which is not in the table, with its hash.
    fn insert_new(&mut self, hash: u64, key: KeyRef<'_>) -> SymId {
        let id = SymId(self.data.len() as u32);
        let data = match key {
            KeyRef::Inf => SymData::Inf,
            KeyRef::Sup => SymData::Sup,
            KeyRef::Num(n) => SymData::Num(n),
            KeyRef::Str(s) => SymData::Str(s),
            KeyRef::Fun(name, neg, args) => {
                let start = self.args.len() as u32;
                self.args.extend_from_slice(args);
                SymData::Fun {
                    name,
                    neg,
                    start,
                    len: args.len() as u32,
                }
            }
        };
        self.data.push(data);
        let Symbols {
            table, data, args, ..
        } = self;
        table.insert_unique(hash, id, |&other| key_hash(&key_from(data, args, other)));
        id
    }

    /// The integer `n`.
    #[inline]
    pub fn int(&mut self, n: i32) -> SymId {
        if (SMALL_MIN..SMALL_MAX).contains(&n) {
            let i = small_index(n);
            if let Some(&id) = self.small.get(i) {
                if id != u32::MAX {
                    return SymId(id);
                }
            }
            let id = self.intern_key(KeyRef::Num(n));
            if self.small.len() <= i {
                // Powers of two from 64: a one-shot table of a small program allocates little
                // (the whole range would be 68 KiB per table).
                self.small
                    .resize((i + 1).next_power_of_two().max(64), u32::MAX);
            }
            self.small[i] = id.0;
            return id;
        }
        self.intern_key(KeyRef::Num(n))
    }

    /// `#inf`.
    pub fn inf(&mut self) -> SymId {
        self.intern_key(KeyRef::Inf)
    }

    /// `#sup`.
    pub fn sup(&mut self) -> SymId {
        self.intern_key(KeyRef::Sup)
    }

    /// The string with text `s`.
    pub fn string(&mut self, s: &str) -> SymId {
        let s = self.names.intern(s);
        self.intern_key(KeyRef::Str(s))
    }

    /// The function `name(args)` (a constant when `args` is empty, a tuple when `name` is empty).
    pub fn fun(&mut self, name: Sym, neg: bool, args: &[SymId]) -> SymId {
        let key = KeyRef::Fun(name, neg, args);
        let hash = key_hash(&key);
        // The probe compares the node's fields directly (no key is built per candidate).
        let (data, arena) = (&self.data, &self.args);
        let found = self.table.find(hash, |&id| match data[id.0 as usize] {
            SymData::Fun {
                name: n,
                neg: g,
                start,
                len,
            } => {
                n == name
                    && g == neg
                    && len as usize == args.len()
                    && arena[start as usize..(start + len) as usize] == *args
            }
            _ => false,
        });
        if let Some(&id) = found {
            return id;
        }
        self.insert_new(hash, key)
    }

    /// The function `name(args)` if it was created before, without creating it.
    pub fn find_fun(&self, name: Sym, neg: bool, args: &[SymId]) -> Option<SymId> {
        let key = KeyRef::Fun(name, neg, args);
        let hash = self.hash_key(&key);
        self.table.find(hash, |&id| self.key_of(id) == key).copied()
    }

    /// The integer `n` if it was created before, without creating it.
    pub fn find_int(&self, n: i32) -> Option<SymId> {
        self.find_key(KeyRef::Num(n))
    }

    /// The string with text `s` if it was created before, without creating it.
    pub fn find_string(&self, s: &str) -> Option<SymId> {
        let s = self.names.get(s)?;
        self.find_key(KeyRef::Str(s))
    }

    /// `#inf` (`sup == false`) or `#sup` if it was created before, without creating it.
    pub fn find_bound(&self, sup: bool) -> Option<SymId> {
        self.find_key(if sup { KeyRef::Sup } else { KeyRef::Inf })
    }

    fn find_key(&self, key: KeyRef<'_>) -> Option<SymId> {
        let hash = self.hash_key(&key);
        self.table.find(hash, |&id| self.key_of(id) == key).copied()
    }

    /// Like [`Symbols::fun`] with a name given as text.
    pub fn fun_str(&mut self, name: &str, neg: bool, args: &[SymId]) -> SymId {
        let name = self.names.intern(name);
        self.fun(name, neg, args)
    }

    /// The symbol with the classical sign flipped, for functions, constants and tuples (clingo
    /// has `-(1,2)` and `-()`).
    pub fn flip_sign(&mut self, id: SymId) -> Option<SymId> {
        match self.get(id) {
            SymData::Fun { name, neg, .. } => {
                let args: smallvec::SmallVec<[SymId; 8]> = self.args(id).into();
                Some(self.fun(name, !neg, &args))
            }
            _ => None,
        }
    }

    /// [`Symbols::flip_sign`] when the result exists already (nothing is created).
    pub fn find_flip_sign(&self, id: SymId) -> Option<SymId> {
        match self.get(id) {
            SymData::Fun { name, neg, .. } => self.find_fun(name, !neg, self.args(id)),
            _ => None,
        }
    }

    /// clingo's total order on symbols (see [`order`]).
    pub fn compare(&self, a: SymId, b: SymId) -> Ordering {
        order(
            TableSym { syms: self, id: a },
            TableSym { syms: self, id: b },
        )
    }

    /// Appends the printed form of `id` (clingo's syntax) to `out`.
    pub fn write(&self, id: SymId, out: &mut String) {
        // Writing to a `String` does not fail.
        let _ = write_symbol(out, TableSym { syms: self, id });
    }

    /// The printed form of `id`.
    pub fn show(&self, id: SymId) -> String {
        let mut s = String::new();
        self.write(id, &mut s);
        s
    }
}

/// clingo's total order on ground terms, whatever their representation (the grounder's table
/// through [`TableSym`], `control::Symbol`): `#inf` < integers < constants (positive before
/// classically negated, then by name; the empty tuple `()` is the constant with the empty name,
/// so the smallest) < strings < functions and tuples (positive before classically negated, then
/// by arity, then name, then arguments left to right) < `#sup`: clingo 5.4 and 5.8 put `-a(1)`
/// after `a(1,1)` and `z(1)`, and `()` before `a` and `"s"`. The one symbol order of the crate.
pub fn order<'s, T: GroundTerm<'s>>(a: T, b: T) -> Ordering {
    if a.identical(b) {
        return Ordering::Equal;
    }
    let (sa, sb) = (a.shape(), b.shape());
    if let (Shape::Number(x), Shape::Number(y)) = (&sa, &sb) {
        return x.cmp(y);
    }
    let (ra, rb) = (rank(&sa), rank(&sb));
    if ra != rb {
        return ra.cmp(&rb);
    }
    match (sa, sb) {
        (Shape::String(x), Shape::String(y)) => x.cmp(y),
        (
            Shape::Function {
                name: na,
                negative: ga,
                args: aa,
            },
            Shape::Function {
                name: nb,
                negative: gb,
                args: ab,
            },
        ) => ga
            .cmp(&gb)
            .then(aa.len().cmp(&ab.len()))
            .then_with(|| na.cmp(nb))
            .then_with(|| {
                aa.zip(ab)
                    .map(|(x, y)| order(x, y))
                    .find(|o| o.is_ne())
                    .unwrap_or(Ordering::Equal)
            }),
        _ => Ordering::Equal,
    }
}

/// Rank of a symbol's type in clingo's order.
fn rank<I: ExactSizeIterator>(shape: &Shape<'_, I>) -> u8 {
    match shape {
        Shape::Inf => 0,
        Shape::Number(_) => 1,
        Shape::Function { args, .. } if args.len() == 0 => 2,
        Shape::String(_) => 3,
        Shape::Function { .. } => 4,
        Shape::Sup => 5,
    }
}

/// A symbol of a table, as the printer and the order read it.
#[derive(Clone, Copy)]
pub struct TableSym<'s> {
    /// The table.
    pub syms: &'s Symbols,
    /// The symbol.
    pub id: SymId,
}

/// The arguments of a [`TableSym`] function.
pub struct TableArgs<'s> {
    syms: &'s Symbols,
    ids: std::slice::Iter<'s, SymId>,
}

impl<'s> Iterator for TableArgs<'s> {
    type Item = TableSym<'s>;
    fn next(&mut self) -> Option<TableSym<'s>> {
        let id = *self.ids.next()?;
        Some(TableSym {
            syms: self.syms,
            id,
        })
    }
    fn size_hint(&self) -> (usize, Option<usize>) {
        self.ids.size_hint()
    }
}

impl ExactSizeIterator for TableArgs<'_> {}

impl<'s> GroundTerm<'s> for TableSym<'s> {
    type Args = TableArgs<'s>;
    fn shape(self) -> Shape<'s, TableArgs<'s>> {
        let syms = self.syms;
        match syms.get(self.id) {
            SymData::Inf => Shape::Inf,
            SymData::Sup => Shape::Sup,
            SymData::Num(n) => Shape::Number(n),
            SymData::Str(s) => Shape::String(syms.names.resolve(s)),
            SymData::Fun { name, neg, .. } => Shape::Function {
                name: syms.names.resolve(name),
                negative: neg,
                args: TableArgs {
                    syms,
                    ids: syms.args(self.id).iter(),
                },
            },
        }
    }
    fn identical(self, other: TableSym<'s>) -> bool {
        self.id == other.id
    }
}

/// A borrowed view of a node, for hashing and lookup before insertion.
#[derive(Clone, Copy, PartialEq, Eq)]
enum KeyRef<'a> {
    Inf,
    Sup,
    Num(i32),
    Str(Sym),
    Fun(Sym, bool, &'a [SymId]),
}

/// The hash of a node: a multiplicative mix of its words (the kind, name and sign in one
/// word, then each argument id), finished by folding the high half into the low one. The
/// keys are small and trusted (the grounder's own ids), so a keyed hasher's per-word cost
/// (foldhash hashed every argument as a separate write) buys nothing here.
#[inline]
fn key_hash(key: &KeyRef<'_>) -> u64 {
    const K: u64 = 0x9e37_79b9_7f4a_7c15;
    #[inline]
    fn mix(h: u64, w: u64) -> u64 {
        (h.rotate_left(23) ^ w).wrapping_mul(K)
    }
    let h = match *key {
        KeyRef::Inf => mix(0, 1),
        KeyRef::Sup => mix(0, 2),
        KeyRef::Num(n) => mix(3, n as u32 as u64),
        KeyRef::Str(s) => mix(4, s.0 as u64),
        KeyRef::Fun(name, neg, args) => {
            let mut h = mix(5 + neg as u64, (name.0 as u64) << 8 | args.len() as u64);
            for a in args {
                h = mix(h, a.0 as u64);
            }
            h
        }
    };
    h ^ (h >> 29)
}

fn key_from<'a>(data: &[SymData], args: &'a [SymId], id: SymId) -> KeyRef<'a> {
    match data[id.0 as usize] {
        SymData::Inf => KeyRef::Inf,
        SymData::Sup => KeyRef::Sup,
        SymData::Num(n) => KeyRef::Num(n),
        SymData::Str(s) => KeyRef::Str(s),
        SymData::Fun {
            name,
            neg,
            start,
            len,
        } => KeyRef::Fun(name, neg, &args[start as usize..(start + len) as usize]),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hash_consing_shares_ids() {
        let mut s = Symbols::new();
        let a = s.fun_str("a", false, &[]);
        let one = s.int(1);
        let f1 = s.fun_str("f", false, &[a, one]);
        let f2 = s.fun_str("f", false, &[a, one]);
        assert_eq!(f1, f2);
        assert_eq!(s.show(f1), "f(a,1)");
        let t = s.fun_str("", false, &[a]);
        assert_eq!(s.show(t), "(a,)");
    }

    #[test]
    fn order_is_clingos() {
        // clingo 5.8.3 sorts t/1 of
        // t(1;a;"s";f(a);(1,2);g(a,b);f(b);#inf;#sup;-a;-1;(a,);h(1,2);f(-a);"b";z)
        // as #inf, -1, 1, a, z, -a, "b", "s", (a,), f(a), f(b), f(-a), (1,2), g(a,b), h(1,2), #sup.
        let mut s = Symbols::new();
        let a = s.fun_str("a", false, &[]);
        let b = s.fun_str("b", false, &[]);
        let na = s.fun_str("a", true, &[]);
        let one = s.int(1);
        let two = s.int(2);
        let expected = vec![
            s.inf(),
            s.int(-1),
            one,
            a,
            s.fun_str("z", false, &[]),
            na,
            s.string("b"),
            s.string("s"),
            s.fun_str("", false, &[a]),
            s.fun_str("f", false, &[a]),
            s.fun_str("f", false, &[b]),
            s.fun_str("f", false, &[na]),
            s.fun_str("", false, &[one, two]),
            s.fun_str("g", false, &[a, b]),
            s.fun_str("h", false, &[one, two]),
            s.sup(),
        ];
        let mut sorted = expected.clone();
        sorted.reverse();
        sorted.sort_by(|&x, &y| s.compare(x, y));
        assert_eq!(sorted, expected);
        // -f(a) sorts after g(a): sign before name.
        let g = s.fun_str("g", false, &[a]);
        let nf = s.fun_str("f", true, &[a]);
        assert_eq!(s.compare(g, nf), Ordering::Less);
        // Sign before arity: clingo 5.4.1 (`X < Y` over t/1 in a program) and clingo 5.8.3
        // (`sorted` in Python) order z(1) < a(1,1) < -a(1) < -z(1,1).
        let z1 = s.fun_str("z", false, &[one]);
        let a11 = s.fun_str("a", false, &[one, one]);
        let na1 = s.fun_str("a", true, &[one]);
        let nz11 = s.fun_str("z", true, &[one, one]);
        let want = vec![z1, a11, na1, nz11];
        let mut got = vec![nz11, na1, a11, z1];
        got.sort_by(|&x, &y| s.compare(x, y));
        assert_eq!(got, want);
        // The empty tuple is the constant with the empty name: clingo 5.4.1 and 5.8.3 answer
        // `x("s") y(()) z w` for `x(X) :- X = #max { (),1 : #true ; "s",1 : #true }.
        // y(X) :- X = #min { (),1 : #true ; a,1 : #true }. z :- () < "s". w :- () < a.`
        // (`clingo o.lp`, `python3 -m clingo o.lp`).
        let unit = s.fun_str("", false, &[]);
        let want = vec![one, unit, a, na, s.string("s"), s.fun_str("", false, &[a])];
        let mut got = want.clone();
        got.reverse();
        got.sort_by(|&x, &y| s.compare(x, y));
        assert_eq!(got, want);
    }
}
