//! Non-ground terms after rewriting (no pools, intervals or `#const` names left), their
//! evaluation under a variable binding with clingo's arithmetic, and matching against ground
//! symbols.
//!
//! Invariants:
//! - Variables are dense slots `0..num_vars` of their rule; a [`Binding`] holds one optional
//!   symbol per slot and a trail, so matching can be undone in LIFO order.
//! - Arithmetic is clingo's: 32-bit integers with wrap-around (integer literals too are read
//!   modulo 2^32, so `2147483648` is `-2147483648`), `/` truncates toward zero, `\` is
//!   the remainder with the dividend's sign, `**` with a negative exponent is 0 (undefined for a
//!   base of 0), `~` is bitwise complement; an operation on a non-integer, or division by zero,
//!   is *undefined*: evaluation returns the span of the offending term and the caller drops the
//!   rule instance with an `operation undefined` warning (checked against clingo 5.8.3).
//!   `-2147483648 / -1` (and `\ -1`), where clingo itself dies of SIGFPE, wrap like
//!   two's-complement hardware would: `-2147483648` and `0`.
//! - Matching inverts the linear forms `X+c`, `c+X`, `X-c`, `c-X`, `-X`, `c*X` and `X*c` on
//!   integers, as gringo binds `X` in `p(X+1)`.

use crate::base::Span;
use crate::syntax::ast::{BinaryOp, UnaryOp};

use super::symbol::{SymData, SymId, Symbols};
use crate::base::intern::Sym;

/// A rewritten, possibly non-ground term.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum NTerm {
    /// A ground symbol.
    Sym(SymId),
    /// A variable slot.
    Var(u32),
    /// A function term with at least one variable or operation below it.
    Fun {
        /// Name (empty for tuples).
        name: Sym,
        /// Classical negation.
        neg: bool,
        /// Arguments.
        args: Vec<NTerm>,
    },
    /// A unary operation.
    Unary {
        /// The operator.
        op: UnaryOp,
        /// The operand.
        arg: Box<NTerm>,
        /// Where it was written (for `operation undefined`).
        span: Span,
    },
    /// A binary operation.
    Binary {
        /// The operator.
        op: BinaryOp,
        /// Left operand.
        lhs: Box<NTerm>,
        /// Right operand.
        rhs: Box<NTerm>,
        /// Where it was written.
        span: Span,
    },
}

/// A partial assignment of symbols to variable slots, with an undo trail.
#[derive(Clone, Debug, Default)]
pub struct Binding {
    /// Value of each slot.
    pub values: Vec<Option<SymId>>,
    /// Slots bound since the start, in binding order.
    trail: Vec<u32>,
}

impl Binding {
    /// A binding with `n` unbound slots.
    pub fn new(n: usize) -> Binding {
        Binding {
            values: vec![None; n],
            trail: Vec::new(),
        }
    }

    /// Makes the binding `n` unbound slots, keeping its vectors' memory.
    pub fn reset(&mut self, n: usize) {
        self.values.clear();
        self.values.resize(n, None);
        self.trail.clear();
    }

    /// The value of slot `v`.
    pub fn get(&self, v: u32) -> Option<SymId> {
        self.values[v as usize]
    }

    /// Matches slot `v` against `s`: true when it holds `s`, or when it was unbound and now
    /// holds `s` (bound with [`Binding::bind`]).
    #[inline]
    pub fn unify(&mut self, v: u32, s: SymId) -> bool {
        match self.get(v) {
            Some(x) => x == s,
            None => {
                self.bind(v, s);
                true
            }
        }
    }

    /// Binds an unbound slot.
    pub fn bind(&mut self, v: u32, s: SymId) {
        debug_assert!(self.values[v as usize].is_none());
        self.values[v as usize] = Some(s);
        self.trail.push(v);
    }

    /// A mark to undo to.
    pub fn mark(&self) -> usize {
        self.trail.len()
    }

    /// Unbinds every slot bound after `mark`.
    pub fn undo(&mut self, mark: usize) {
        while self.trail.len() > mark {
            let v = self.trail.pop().expect("trail longer than mark");
            self.values[v as usize] = None;
        }
    }
}

/// A set of variable slots asked which are known (bound): what [`NTerm::bound_by`] and
/// [`NTerm::binds`] read.
pub trait Known {
    /// Whether slot `v` is known.
    fn knows(&self, v: u32) -> bool;
}

impl Known for [bool] {
    #[inline]
    fn knows(&self, v: u32) -> bool {
        self[v as usize]
    }
}

impl Known for VarSet {
    #[inline]
    fn knows(&self, v: u32) -> bool {
        self.contains(v)
    }
}

impl Known for Binding {
    #[inline]
    fn knows(&self, v: u32) -> bool {
        self.get(v).is_some()
    }
}

/// A short list of variable slots, each once, in the order found: what [`NTerm::vars`] and the
/// rewriter's safety planning collect per literal. Kept on the stack up to 8 slots (a rule's
/// literal has a handful of variables), so collecting allocates nothing: the rewriter and the
/// grounder made some 150 such vectors a call in the learner-loop benchmark.
pub type VarList = smallvec::SmallVec<[u32; 8]>;

/// Where [`NTerm::binds`] adds the slots a match binds (each once).
pub trait Newly {
    /// Adds slot `v`, if not there yet.
    fn add(&mut self, v: u32);
}

impl Newly for VarList {
    #[inline]
    fn add(&mut self, v: u32) {
        if !self.contains(&v) {
            self.push(v);
        }
    }
}

impl Newly for VarSet {
    #[inline]
    fn add(&mut self, v: u32) {
        self.insert(v);
    }
}

/// A set of variable slots as bits (one word for rules of up to 64 variables). Meant to be
/// kept and [`VarSet::reset`] for the next rule, so that it allocates once.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct VarSet {
    words: Vec<u64>,
}

impl VarSet {
    /// Makes the set empty, with room for slots `0..n`.
    pub fn reset(&mut self, n: usize) {
        self.words.clear();
        self.words.resize(n.div_ceil(64).max(1), 0);
    }

    /// Removes every slot (the room stays).
    #[inline]
    pub fn clear(&mut self) {
        if let [w] = &mut self.words[..] {
            *w = 0;
            return;
        }
        self.words.iter_mut().for_each(|w| *w = 0);
    }

    /// Whether slot `v` is in the set.
    #[inline]
    pub fn contains(&self, v: u32) -> bool {
        self.words[v as usize / 64] >> (v % 64) & 1 != 0
    }

    /// Adds slot `v`.
    #[inline]
    pub fn insert(&mut self, v: u32) {
        self.words[v as usize / 64] |= 1 << (v % 64);
    }

    /// Whether the set is empty.
    #[inline]
    pub fn is_empty(&self) -> bool {
        if let [w] = &self.words[..] {
            return *w == 0;
        }
        self.words.iter().all(|&w| w == 0)
    }

    /// Whether the sets share a slot (both made with the same room).
    #[inline]
    pub fn intersects(&self, other: &VarSet) -> bool {
        if let ([a], [b]) = (&self.words[..], &other.words[..]) {
            return a & b != 0;
        }
        self.words.iter().zip(&other.words).any(|(a, b)| a & b != 0)
    }

    /// Adds the slots of `other` (made with the same room).
    pub fn union_with(&mut self, other: &VarSet) {
        self.words
            .iter_mut()
            .zip(&other.words)
            .for_each(|(a, b)| *a |= b);
    }
}

/// The variables of a list of terms as bit sets of one width (that of a [`VarSet`] for the
/// same rule), and whether each term is a pattern (no operation below it): made once per rule
/// body, so that asking whether a term is bound, or what matching it binds, costs a few word
/// operations instead of a walk over the term (`instantiate`'s join order asks it many times).
#[derive(Clone, Debug, Default)]
pub struct TermVars {
    /// Words per term.
    width: usize,
    /// The variables of term `i`: `words[i * width..(i + 1) * width]`.
    words: Vec<u64>,
    /// Whether term `i` is a pattern.
    pattern: Vec<bool>,
}

impl TermVars {
    /// Empties the list, for terms over slots `0..n`.
    pub fn reset(&mut self, n: usize) {
        self.width = n.div_ceil(64).max(1);
        self.words.clear();
        self.pattern.clear();
    }

    /// The number of terms.
    pub fn len(&self) -> usize {
        self.pattern.len()
    }

    /// Adds term `t` (its number is the previous [`TermVars::len`]).
    pub fn push(&mut self, t: &NTerm) {
        let start = self.words.len();
        self.words.resize(start + self.width, 0);
        let pattern = t.mark_vars(&mut self.words[start..]);
        self.pattern.push(pattern);
    }

    /// [`NTerm::bound_by`] for term `i`.
    #[inline]
    pub fn bound_in(&self, i: usize, bound: &VarSet) -> bool {
        if let [b] = &bound.words[..] {
            return self.words[i] & !b == 0;
        }
        let w = self.width;
        self.words[i * w..(i + 1) * w]
            .iter()
            .zip(&bound.words)
            .all(|(t, b)| t & !b == 0)
    }

    /// [`NTerm::binds`] for term `i`, which is `t`: a pattern binds its unbound variables;
    /// other terms are walked.
    #[inline]
    pub fn binds_in(&self, i: usize, t: &NTerm, bound: &VarSet, out: &mut VarSet) -> bool {
        if !self.pattern[i] {
            return t.binds(bound, out);
        }
        if let ([b], [o]) = (&bound.words[..], &mut out.words[..]) {
            *o |= self.words[i] & !b;
            return true;
        }
        let w = self.width;
        for ((o, t), b) in out
            .words
            .iter_mut()
            .zip(&self.words[i * w..(i + 1) * w])
            .zip(&bound.words)
        {
            *o |= t & !b;
        }
        true
    }
}

/// Evaluation failed: the span of the undefined operation.
pub type Undefined = Span;

fn int_of(syms: &Symbols, s: SymId, span: Span) -> Result<i32, Undefined> {
    syms.num(s).ok_or(span)
}

/// clingo's integer power: negative exponents give 0, except that `0 ** -n` is undefined.
fn ipow(base: i32, exp: i32) -> Option<i32> {
    if exp < 0 {
        return if base == 0 { None } else { Some(0) };
    }
    // Squaring, wrapping at 32 bits: `3 ** 2000000000` costs 31 steps, not two billion.
    Some(base.wrapping_pow(exp as u32))
}

/// Applies a binary operator to integers as clingo does; `None` when undefined.
pub fn binary_int(op: BinaryOp, a: i32, b: i32) -> Option<i32> {
    Some(match op {
        BinaryOp::Add => a.wrapping_add(b),
        BinaryOp::Sub => a.wrapping_sub(b),
        BinaryOp::Mul => a.wrapping_mul(b),
        BinaryOp::Div => {
            if b == 0 {
                return None;
            }
            a.wrapping_div(b)
        }
        BinaryOp::Mod => {
            if b == 0 {
                return None;
            }
            a.wrapping_rem(b)
        }
        BinaryOp::Pow => return ipow(a, b),
        BinaryOp::BitAnd => a & b,
        BinaryOp::BitOr => a | b,
        BinaryOp::BitXor => a ^ b,
    })
}

impl NTerm {
    /// True when no variable occurs in the term.
    pub fn is_ground(&self) -> bool {
        match self {
            NTerm::Sym(_) => true,
            NTerm::Var(_) => false,
            NTerm::Fun { args, .. } => args.iter().all(NTerm::is_ground),
            NTerm::Unary { arg, .. } => arg.is_ground(),
            NTerm::Binary { lhs, rhs, .. } => lhs.is_ground() && rhs.is_ground(),
        }
    }

    /// True when evaluating the term applies an operator (and so may be undefined).
    pub fn has_operation(&self) -> bool {
        match self {
            NTerm::Sym(_) | NTerm::Var(_) => false,
            NTerm::Fun { args, .. } => args.iter().any(|a| a.has_operation()),
            NTerm::Unary { .. } | NTerm::Binary { .. } => true,
        }
    }

    /// Adds the variable slots of the term to `out`.
    pub fn vars(&self, out: &mut VarList) {
        match self {
            NTerm::Sym(_) => {}
            NTerm::Var(v) => {
                if !out.contains(v) {
                    out.push(*v)
                }
            }
            NTerm::Fun { args, .. } => args.iter().for_each(|a| a.vars(out)),
            NTerm::Unary { arg, .. } => arg.vars(out),
            NTerm::Binary { lhs, rhs, .. } => {
                lhs.vars(out);
                rhs.vars(out)
            }
        }
    }

    /// True when every variable of the term is known in `bound` (a `[bool]` by slot, a
    /// [`VarSet`] or a [`Binding`]).
    pub fn bound_by<K: Known + ?Sized>(&self, bound: &K) -> bool {
        match self {
            NTerm::Sym(_) => true,
            NTerm::Var(v) => bound.knows(*v),
            NTerm::Fun { args, .. } => args.iter().all(|a| a.bound_by(bound)),
            NTerm::Unary { arg, .. } => arg.bound_by(bound),
            NTerm::Binary { lhs, rhs, .. } => lhs.bound_by(bound) && rhs.bound_by(bound),
        }
    }

    /// When matching the term against a symbol with the variables in `bound` known: false if
    /// it cannot be matched (an operation over an unknown variable that cannot be inverted),
    /// otherwise true, and the variables the match binds are added to `out`. The one place
    /// that says which terms a match can invert: the rewriter's safety check and the
    /// instantiator's join order both ask it.
    pub fn binds<K: Known + ?Sized, O: Newly>(&self, bound: &K, out: &mut O) -> bool {
        match self {
            NTerm::Sym(_) => true,
            NTerm::Var(v) => {
                if !bound.knows(*v) {
                    out.add(*v);
                }
                true
            }
            NTerm::Fun { args, .. } => args.iter().all(|a| a.binds(bound, out)),
            _ if self.bound_by(bound) => true,
            NTerm::Unary {
                op: UnaryOp::Minus,
                arg,
                ..
            } => arg.binds(bound, out),
            NTerm::Binary {
                op: BinaryOp::Add | BinaryOp::Sub | BinaryOp::Mul,
                lhs,
                rhs,
                ..
            } => {
                if lhs.bound_by(bound) {
                    rhs.binds(bound, out)
                } else if rhs.bound_by(bound) {
                    lhs.binds(bound, out)
                } else {
                    false
                }
            }
            _ => false,
        }
    }

    /// Sets the bits of the term's variables in `bits` (a [`VarSet`]'s words); true when the
    /// term is a pattern (constants, variables and functions of patterns).
    pub fn mark_vars(&self, bits: &mut [u64]) -> bool {
        match self {
            NTerm::Sym(_) => true,
            NTerm::Var(v) => {
                bits[*v as usize / 64] |= 1 << (v % 64);
                true
            }
            NTerm::Fun { args, .. } => {
                let mut pattern = true;
                for a in args {
                    pattern &= a.mark_vars(bits);
                }
                pattern
            }
            NTerm::Unary { arg, .. } => {
                arg.mark_vars(bits);
                false
            }
            NTerm::Binary { lhs, rhs, .. } => {
                lhs.mark_vars(bits);
                rhs.mark_vars(bits);
                false
            }
        }
    }

    /// Evaluates a term whose variables are all bound.
    pub fn eval(&self, syms: &mut Symbols, b: &Binding) -> Result<SymId, Undefined> {
        match self {
            NTerm::Sym(s) => Ok(*s),
            NTerm::Var(v) => Ok(b.get(*v).expect("evaluated an unbound variable")),
            NTerm::Fun { name, neg, args } => {
                let mut vals = smallvec::SmallVec::<[SymId; 8]>::new();
                for a in args {
                    // Constants and variables (most arguments) without a call.
                    vals.push(match a {
                        NTerm::Sym(s) => *s,
                        NTerm::Var(v) => b.get(*v).expect("evaluated an unbound variable"),
                        _ => a.eval(syms, b)?,
                    });
                }
                Ok(syms.fun(*name, *neg, &vals))
            }
            NTerm::Unary { op, arg, span } => {
                let v = arg.eval(syms, b)?;
                match op {
                    UnaryOp::Minus => match syms.get(v) {
                        SymData::Num(n) => Ok(syms.int(n.wrapping_neg())),
                        _ => syms.flip_sign(v).ok_or(*span),
                    },
                    UnaryOp::BitNot => {
                        let n = int_of(syms, v, *span)?;
                        Ok(syms.int(!n))
                    }
                    UnaryOp::Abs => {
                        let n = int_of(syms, v, *span)?;
                        Ok(syms.int(n.wrapping_abs()))
                    }
                }
            }
            NTerm::Binary { op, lhs, rhs, span } => {
                let l = lhs.eval(syms, b)?;
                let r = rhs.eval(syms, b)?;
                let l = int_of(syms, l, *span)?;
                let r = int_of(syms, r, *span)?;
                let v = binary_int(*op, l, r).ok_or(*span)?;
                Ok(syms.int(v))
            }
        }
    }

    /// The value of a term made of integers, variables bound to integers and defined integer
    /// operations, computed without creating symbols; `None` for any other term (including an
    /// undefined operation), which the caller then evaluates with [`NTerm::eval`].
    pub fn eval_int(&self, syms: &Symbols, b: &Binding) -> Option<i32> {
        match self {
            NTerm::Sym(s) => syms.num(*s),
            NTerm::Var(v) => syms.num(b.get(*v)?),
            NTerm::Unary { op, arg, .. } => {
                let n = arg.eval_int(syms, b)?;
                Some(match op {
                    UnaryOp::Minus => n.wrapping_neg(),
                    UnaryOp::BitNot => !n,
                    UnaryOp::Abs => n.wrapping_abs(),
                })
            }
            NTerm::Binary { op, lhs, rhs, .. } => {
                binary_int(*op, lhs.eval_int(syms, b)?, rhs.eval_int(syms, b)?)
            }
            NTerm::Fun { .. } => None,
        }
    }

    /// [`NTerm::matches`] with constants and variables (most arguments of an atom) matched
    /// inline, without a call.
    #[inline(always)]
    pub fn matches_arg(&self, syms: &mut Symbols, sym: SymId, b: &mut Binding) -> bool {
        match self {
            NTerm::Sym(x) => *x == sym,
            NTerm::Var(v) => b.unify(*v, sym),
            _ => self.matches(syms, sym, b),
        }
    }

    /// Matches the term against `sym`, binding unbound variables; on failure the binding may
    /// hold partial bindings, which the caller undoes to its mark. An undefined operation is a
    /// failed match.
    pub fn matches(&self, syms: &mut Symbols, sym: SymId, b: &mut Binding) -> bool {
        match self {
            NTerm::Sym(s) => *s == sym,
            NTerm::Var(v) => b.unify(*v, sym),
            NTerm::Fun { name, neg, args } => match syms.get(sym) {
                SymData::Fun {
                    name: n2,
                    neg: g2,
                    len,
                    ..
                } if n2 == *name && g2 == *neg && len as usize == args.len() => {
                    for (i, a) in args.iter().enumerate() {
                        let s = syms.args(sym)[i];
                        if !a.matches_arg(syms, s, b) {
                            return false;
                        }
                    }
                    true
                }
                _ => false,
            },
            _ => {
                if self.bound_by(b) {
                    return match self.eval(syms, b) {
                        Ok(v) => v == sym,
                        Err(_) => false,
                    };
                }
                // -X against a function symbol: X is the symbol with the sign flipped.
                if let NTerm::Unary {
                    op: UnaryOp::Minus,
                    arg,
                    ..
                } = self
                {
                    if syms.num(sym).is_none() {
                        return match syms.flip_sign(sym) {
                            Some(t) => arg.matches(syms, t, b),
                            None => false,
                        };
                    }
                }
                let Some(n) = syms.num(sym) else {
                    return false;
                };
                match self {
                    NTerm::Unary {
                        op: UnaryOp::Minus,
                        arg,
                        ..
                    } => {
                        let t = syms.int(n.wrapping_neg());
                        arg.matches(syms, t, b)
                    }
                    NTerm::Binary { op, lhs, rhs, .. } => {
                        let (known, unknown, known_left) = if lhs.bound_by(b) {
                            (lhs, rhs, true)
                        } else {
                            (rhs, lhs, false)
                        };
                        let Ok(k) = known.eval(syms, b) else {
                            return false;
                        };
                        let Some(k) = syms.num(k) else {
                            return false;
                        };
                        let (n, k) = (n as i64, k as i64);
                        // Solve n = known op x (or x op known) for x.
                        let x = match (op, known_left) {
                            (BinaryOp::Add, _) => n - k,
                            (BinaryOp::Sub, true) => k - n,
                            (BinaryOp::Sub, false) => n + k,
                            (BinaryOp::Mul, _) => {
                                if k == 0 || n % k != 0 {
                                    return false;
                                }
                                n / k
                            }
                            _ => return false,
                        };
                        let Ok(x) = i32::try_from(x) else {
                            return false;
                        };
                        let t = syms.int(x);
                        unknown.matches(syms, t, b)
                    }
                    _ => false,
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arithmetic_as_clingo() {
        // clingo 5.8.3: 7/2=3, -7/2=-3, 7/-2=-3, 7\2=1, -7\2=-1, 7\-2=1, 2**-1=0, 0**-1 undefined,
        // ~5=-6, 2147483647+1=-2147483648.
        assert_eq!(binary_int(BinaryOp::Div, -7, 2), Some(-3));
        assert_eq!(binary_int(BinaryOp::Div, 7, -2), Some(-3));
        assert_eq!(binary_int(BinaryOp::Mod, -7, 2), Some(-1));
        assert_eq!(binary_int(BinaryOp::Mod, 7, -2), Some(1));
        assert_eq!(binary_int(BinaryOp::Div, 1, 0), None);
        assert_eq!(binary_int(BinaryOp::Pow, 2, -1), Some(0));
        assert_eq!(binary_int(BinaryOp::Pow, 0, -1), None);
        assert_eq!(binary_int(BinaryOp::Pow, 2, 3), Some(8));
        assert_eq!(binary_int(BinaryOp::Pow, -1, 5), Some(-1));
        assert_eq!(binary_int(BinaryOp::Add, i32::MAX, 1), Some(i32::MIN));
        assert_eq!(binary_int(BinaryOp::BitXor, 5, 3), Some(6));
        // clingo 5.8.3: 2147483647*2=-2, 2**40=0, (-2)**31=-2147483648, 3**4=81.
        assert_eq!(binary_int(BinaryOp::Mul, i32::MAX, 2), Some(-2));
        assert_eq!(binary_int(BinaryOp::Pow, 2, 40), Some(0));
        assert_eq!(binary_int(BinaryOp::Pow, -2, 31), Some(i32::MIN));
        assert_eq!(binary_int(BinaryOp::Pow, 3, 4), Some(81));
        assert_eq!(binary_int(BinaryOp::Pow, -1, i32::MAX), Some(-1));
        // clingo 5.8.3 dies of SIGFPE on -2147483648/-1 and -2147483648\-1; we decide the
        // two's-complement results instead of an error: the quotient wraps to -2147483648,
        // the remainder is 0.
        assert_eq!(binary_int(BinaryOp::Div, i32::MIN, -1), Some(i32::MIN));
        assert_eq!(binary_int(BinaryOp::Mod, i32::MIN, -1), Some(0));
    }

    #[test]
    fn linear_terms_invert() {
        let mut syms = Symbols::new();
        let one = syms.int(1);
        let span = Span::default();
        // X+1 matched against 3 binds X=2.
        let t = NTerm::Binary {
            op: BinaryOp::Add,
            lhs: Box::new(NTerm::Var(0)),
            rhs: Box::new(NTerm::Sym(one)),
            span,
        };
        let mut b = Binding::new(1);
        let three = syms.int(3);
        assert!(t.matches(&mut syms, three, &mut b));
        assert_eq!(b.get(0), Some(syms.int(2)));
        // 2*X against 3 fails.
        let two = syms.int(2);
        let t = NTerm::Binary {
            op: BinaryOp::Mul,
            lhs: Box::new(NTerm::Sym(two)),
            rhs: Box::new(NTerm::Var(0)),
            span,
        };
        let mut b = Binding::new(1);
        assert!(!t.matches(&mut syms, three, &mut b));
    }
}
