//! Ground theory atoms (clingo's `TheoryAtom`, aspif statement 9): a name term, elements
//! (theory terms with a condition of program literals) and an optional guard, over the
//! program's atom numbering.
//!
//! Invariants:
//! - `atom` is the atom standing for the theory atom in rules, `0` for a directive. A theory
//!   atom that heads no rule is free (neither true nor false by the program, as in clasp):
//!   `GroundProgram::free_theory_atoms` lists them, the solver treats them as free externals,
//!   and the writers print them as theory atoms, never as `#external`.
//! - Elements are distinct and kept in the order of first grounding; a condition lists the
//!   literals still undecided after simplification (an element whose condition is false is
//!   gone).
//! - The printed form ([`TheoryAtom::write`]) is clingo 5.8's `str(TheoryAtom)`: operator terms
//!   in parentheses `(a+b)`, `(-x)`; elements `t1,t2: l1,l2` separated by `;`.

use std::fmt::{self, Write};

use super::{Atom, Lit};

/// A ground theory term.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum TheoryTerm {
    /// An integer.
    Number(i32),
    /// A constant, a string (with its quotes) or `#inf`/`#sup`, as printed.
    Symbol(String),
    /// `name(args)`, or an operator applied to one or two arguments.
    Function(String, Vec<TheoryTerm>),
    /// `(a, b)`.
    Tuple(Vec<TheoryTerm>),
    /// `{a, b}`.
    Set(Vec<TheoryTerm>),
    /// `[a, b]`.
    List(Vec<TheoryTerm>),
}

impl TheoryTerm {
    /// True for a function named by an operator (as opposed to an identifier).
    pub fn is_operator(&self) -> bool {
        matches!(self, TheoryTerm::Function(n, _) if is_operator(n))
    }
}

/// Whether `name` is an operator (it starts with no letter, digit, `_` or `'`).
pub fn is_operator(name: &str) -> bool {
    name.chars()
        .next()
        .is_some_and(|c| !(c.is_ascii_alphanumeric() || c == '_' || c == '\''))
}

fn write_list(f: &mut impl Write, ts: &[TheoryTerm]) -> fmt::Result {
    for (i, t) in ts.iter().enumerate() {
        if i > 0 {
            f.write_char(',')?;
        }
        write!(f, "{t}")?;
    }
    Ok(())
}

impl fmt::Display for TheoryTerm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TheoryTerm::Number(n) => write!(f, "{n}"),
            TheoryTerm::Symbol(s) => f.write_str(s),
            TheoryTerm::Function(op, args) if is_operator(op) && args.len() == 1 => {
                write!(f, "({op}{})", args[0])
            }
            TheoryTerm::Function(op, args) if is_operator(op) && args.len() == 2 => {
                write!(f, "({}{op}{})", args[0], args[1])
            }
            TheoryTerm::Function(name, args) => {
                write!(f, "{name}(")?;
                write_list(f, args)?;
                f.write_char(')')
            }
            TheoryTerm::Tuple(ts) => {
                f.write_char('(')?;
                write_list(f, ts)?;
                if ts.len() == 1 {
                    f.write_char(',')?;
                }
                f.write_char(')')
            }
            TheoryTerm::Set(ts) => {
                f.write_char('{')?;
                write_list(f, ts)?;
                f.write_char('}')
            }
            TheoryTerm::List(ts) => {
                f.write_char('[')?;
                write_list(f, ts)?;
                f.write_char(']')
            }
        }
    }
}

/// One element: terms and condition.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TheoryElement {
    /// The tuple.
    pub terms: Vec<TheoryTerm>,
    /// Program literals that must all hold.
    pub condition: Vec<Lit>,
}

/// A ground theory atom.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct TheoryAtom {
    /// Its program atom; 0 for a directive.
    pub atom: Atom,
    /// The name term: a symbol, or a function of its arguments.
    pub term: TheoryTerm,
    /// The elements.
    pub elements: Vec<TheoryElement>,
    /// The guard: operator and term.
    pub guard: Option<(String, TheoryTerm)>,
}

impl TheoryAtom {
    /// The atom as clingo 5.8 prints it, condition literals named by `lit`.
    pub fn write(&self, out: &mut String, lit: &mut dyn FnMut(Lit) -> String) {
        let _ = write!(out, "&{}{{", self.term);
        for (i, e) in self.elements.iter().enumerate() {
            if i > 0 {
                out.push(';');
            }
            let _ = write_list(out, &e.terms);
            if !e.condition.is_empty() {
                out.push_str(": ");
                for (j, &l) in e.condition.iter().enumerate() {
                    if j > 0 {
                        out.push(',');
                    }
                    out.push_str(&lit(l));
                }
            }
        }
        out.push('}');
        if let Some((op, t)) = &self.guard {
            let _ = write!(out, "{op}{t}");
        }
    }
}
