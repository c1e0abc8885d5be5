//! Theory atoms on the front door (clingo's `Control.theory_atoms` and
//! `PropagateInit.theory_atoms`): the ground theory atoms of everything grounded so far, each
//! with its name term, elements (terms and condition literals) and guard, over the Control's
//! atoms; a propagator maps an atom's literal to a solver literal with
//! `PropagateInit::solver_literal` and watches it.
//!
//! An element's condition is named by one program literal, as clingo's `condition_id`
//! ([`condition_ids`]): 0 when empty, its literal when it has one, and for several literals a
//! number of its own from [`CONDITION_BASE`] `+ 1` (above every atom, as clingo's), counted
//! over the distinct conditions in grounding order. A propagator turns a condition into a
//! solver literal equivalent to the conjunction with `PropagateInit::condition_literal`.
//!
//! Invariant: the atoms are listed in grounding order and keep their program atom (0 for a
//! directive) across solve calls; terms are [`TheoryTerm`]s, printed as clingo 5.8 prints them.

use super::Control;
use crate::ground::program::Lit;
pub use crate::ground::program::{TheoryAtom, TheoryElement, TheoryTerm};
use hashbrown::HashMap;

/// clingo's `TheoryTermType`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TheoryTermType {
    /// `(a, b)`.
    Tuple,
    /// `[a, b]`.
    List,
    /// `{a, b}`.
    Set,
    /// `f(a)` or an operator term.
    Function,
    /// An integer.
    Number,
    /// A constant, string, `#inf` or `#sup`.
    Symbol,
}

impl TheoryTerm {
    /// Its type, as clingo's `TheoryTerm.type`.
    pub fn term_type(&self) -> TheoryTermType {
        match self {
            TheoryTerm::Number(_) => TheoryTermType::Number,
            TheoryTerm::Symbol(_) => TheoryTermType::Symbol,
            TheoryTerm::Function(..) => TheoryTermType::Function,
            TheoryTerm::Tuple(_) => TheoryTermType::Tuple,
            TheoryTerm::Set(_) => TheoryTermType::Set,
            TheoryTerm::List(_) => TheoryTermType::List,
        }
    }

    /// The name of a symbol or function (clingo's `TheoryTerm.name`).
    pub fn name(&self) -> Option<&str> {
        match self {
            TheoryTerm::Symbol(s) | TheoryTerm::Function(s, _) => Some(s),
            _ => None,
        }
    }

    /// The value of a number (clingo's `TheoryTerm.number`).
    pub fn number(&self) -> Option<i32> {
        match self {
            TheoryTerm::Number(n) => Some(*n),
            _ => None,
        }
    }

    /// The arguments of a function or the items of a tuple, set or list.
    pub fn arguments(&self) -> &[TheoryTerm] {
        match self {
            TheoryTerm::Function(_, a)
            | TheoryTerm::Tuple(a)
            | TheoryTerm::Set(a)
            | TheoryTerm::List(a) => a,
            _ => &[],
        }
    }
}

/// Where the numbers of conditions of several literals start (clingo 5.8's `2^28`).
pub const CONDITION_BASE: i32 = 1 << 28;

/// The `condition_id` of every element of `atoms`, atom by atom (see the module documentation).
pub fn condition_ids(atoms: &[TheoryAtom]) -> Vec<Vec<i32>> {
    let mut numbered: HashMap<&[Lit], i32> = HashMap::new();
    atoms
        .iter()
        .map(|a| {
            a.elements
                .iter()
                .map(|e| match e.condition[..] {
                    [] => 0,
                    [l] => l,
                    _ => {
                        let next = CONDITION_BASE + 1 + numbered.len() as i32;
                        *numbered.entry(&e.condition[..]).or_insert(next)
                    }
                })
                .collect()
        })
        .collect()
}

impl Control {
    /// The ground theory atoms (clingo's `theory_atoms`).
    pub fn theory_atoms(&self) -> &[TheoryAtom] {
        &self.program().theory_atoms
    }

    /// A theory atom as clingo 5.8's `str(TheoryAtom)`: condition literals by their atoms'
    /// symbols.
    pub fn theory_atom_text(&self, atom: &TheoryAtom) -> String {
        let mut s = String::new();
        atom.write(&mut s, &mut |l| self.theory_literal_text(l));
        s
    }

    /// A condition literal of a theory element as clingo 5.8 prints it: its atom's symbol
    /// (`#aux(n)` for an atom without one), `not` in front when negative.
    pub fn theory_literal_text(&self, l: crate::ground::program::Lit) -> String {
        let a = l.unsigned_abs();
        let name = self
            .symbol(a)
            .map_or_else(|| format!("#aux({a})"), |s| s.to_string());
        if l < 0 {
            format!("not {name}")
        } else {
            name
        }
    }
}
