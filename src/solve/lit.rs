//! Solver variables and literals as dense `u32` newtypes (varisat `lit.rs`, kissat).
//!
//! Invariant: a literal's code is `var << 1 | sign`, where sign 1 means negative; negation flips
//! bit 0, so per-literal tables are indexed by `code()` and per-variable tables by `index()`.

use std::fmt;
use std::ops::Not;

/// A solver variable (an atom, a rule body or an auxiliary), numbered from 0.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Var(u32);

impl Var {
    /// The variable with the given index.
    pub fn new(index: usize) -> Var {
        assert!(
            index < (u32::MAX >> 1) as usize,
            "too many solver variables"
        );
        Var(index as u32)
    }

    /// The index of the variable, for per-variable tables.
    pub fn index(self) -> usize {
        self.0 as usize
    }

    /// The positive literal of this variable.
    pub fn positive(self) -> Lit {
        Lit(self.0 << 1)
    }

    /// The negative literal of this variable.
    pub fn negative(self) -> Lit {
        Lit(self.0 << 1 | 1)
    }
}

impl fmt::Debug for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "x{}", self.0 + 1)
    }
}

/// A literal: a variable or its negation.
#[derive(Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Lit(u32);

impl Lit {
    /// The literal of `var` that is true when the variable has the value `value`.
    pub fn new(var: Var, value: bool) -> Lit {
        if value {
            var.positive()
        } else {
            var.negative()
        }
    }

    /// The literal with the given code.
    pub fn from_code(code: u32) -> Lit {
        Lit(code)
    }

    /// The code `var << 1 | sign`, for per-literal tables.
    pub fn code(self) -> usize {
        self.0 as usize
    }

    /// The variable of the literal.
    pub fn var(self) -> Var {
        Var(self.0 >> 1)
    }

    /// Whether the literal is the negation of its variable.
    pub fn is_neg(self) -> bool {
        self.0 & 1 == 1
    }
}

impl Not for Lit {
    type Output = Lit;
    fn not(self) -> Lit {
        Lit(self.0 ^ 1)
    }
}

impl fmt::Debug for Lit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // DIMACS numbering: variables from 1, a minus sign for negation.
        let n = (self.0 >> 1) as i64 + 1;
        write!(f, "{}", if self.is_neg() { -n } else { n })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literal_encoding() {
        let v = Var::new(5);
        assert_eq!(v.positive().code(), 10);
        assert_eq!(v.negative().code(), 11);
        assert_eq!(!v.positive(), v.negative());
        assert_eq!(v.negative().var(), v);
        assert!(v.negative().is_neg());
        assert_eq!(format!("{:?}", v.negative()), "-6");
        assert_eq!(Lit::new(v, false), v.negative());
    }
}
