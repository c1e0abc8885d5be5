//! Rewriting: from syntax-tree statements to [`NStmt`]s the instantiator can ground.
//!
//! What happens here, in order: `#const` names are replaced by their values; pools are
//! unfolded (in rule heads, bodies and aggregate bounds into separate statements, inside
//! aggregates and conditions into separate elements; as clingo does, the pools of the literal
//! of a conditional element stay within it: a conjunction in a disjunctive head, a
//! disjunction in a conditional body literal); intervals become fresh variables bound by an
//! interval literal; anonymous variables become fresh variables; conditional body literals
//! `l : c` become a guard-less one-element aggregate the instantiator reads as "every
//! instance of `c` has some instance of `l`"; choice bounds and head aggregates become an
//! unbounded choice plus a constraint on a body aggregate; every body (and every element
//! condition) is put in an order in which each literal is evaluable when reached, which is also
//! the safety check.
//!
//! Invariants: a planned body binds every global variable before it is used; a statement that
//! is unsafe is reported (gringo's `unsafe variables in:` with one note per variable) and not
//! produced.
//!
//! Files: `mod` (the rewritten forms `NStmt`, `NLit`, ... and the `Rewriter`'s state),
//! `pool` (unfolding pools), `lower` (terms, literals, aggregates and conditions to their
//! rewritten forms), `statement` (constants and statements other than rules), `rule` (rules,
//! their choice bounds and head aggregates, the safety check per instance), `safety` (the
//! body order that binds every variable before its use), `theory` (theory atoms checked against
//! their definitions, as aggregates the instantiator makes theory atoms of).

mod domains;
mod lower;
mod pool;
mod rule;
mod safety;
mod statement;
mod theory;

pub use domains::UNRANKED;
pub use pool::unpool_term;
pub use safety::{lit_vars, plan, Flags};
pub use theory::{NTheory, Theories};

use hashbrown::HashMap;

use crate::base::{Diagnostic, Diagnostics, SourceMap, Span};
use crate::syntax::ast::{self, AggregateFunction, CmpOp, Sign, TermKind};

use super::program::AuxKind;
use super::symbol::{SymId, Symbols};
use super::term::{NTerm, VarList};
use crate::base::intern::{Interner, Sym};

/// Index of a predicate signature in [`Compiled::preds`].
pub type PredId = u32;

/// A predicate signature.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Pred {
    /// Name.
    pub name: Sym,
    /// Arity.
    pub arity: u32,
    /// Classically negated.
    pub neg: bool,
}

/// A non-ground predicate atom.
#[derive(Clone, Debug)]
pub struct NAtom {
    /// Its predicate.
    pub pred: PredId,
    /// Name (as in the predicate).
    pub name: Sym,
    /// Classical negation.
    pub neg: bool,
    /// Arguments.
    pub args: Vec<NTerm>,
    /// Where it was written.
    pub span: Span,
    /// A SPARC sort atom `#s(t)`: a typing check, placed after the program's own literals.
    pub sort: bool,
}

/// A body literal after rewriting.
#[derive(Clone, Debug)]
pub enum NLit {
    /// A predicate literal with its default-negation sign.
    Pred {
        /// `not`, `not not` or nothing.
        sign: Sign,
        /// The atom.
        atom: NAtom,
    },
    /// A comparison; `=` binds an unbound side that can be matched.
    Cmp {
        /// Relation.
        op: CmpOp,
        /// Left.
        lhs: NTerm,
        /// Right.
        rhs: NTerm,
    },
    /// `pat = lo..hi`, binding the variables of `pat`.
    Interval {
        /// Matched against each value.
        pat: NTerm,
        /// Lower end.
        lo: NTerm,
        /// Upper end.
        hi: NTerm,
    },
    /// `pat = @name(args)`: an external function call (`instantiate::call`), binding the
    /// variables of `pat` to each symbol the grounding context returns for the ground `args`.
    Call {
        /// Matched against each value.
        pat: NTerm,
        /// The function's name.
        name: Sym,
        /// Arguments, ground when the literal is reached.
        args: Vec<NTerm>,
        /// Where the call was written.
        span: Span,
    },
    /// `#true` / `#false`.
    Bool(bool),
    /// A body aggregate.
    Agg(Box<NAgg>),
}

/// A body aggregate.
#[derive(Clone, Debug)]
pub struct NAgg {
    /// Default negation in front.
    pub sign: Sign,
    /// The function.
    pub func: AggregateFunction,
    /// Guards, read as `aggregate op term`.
    pub guards: Vec<(CmpOp, NTerm)>,
    /// Index in `guards` of an `=` guard whose variable the aggregate binds (set by planning).
    pub binder: Option<usize>,
    /// Elements.
    pub elems: Vec<NElem>,
    /// Set when the aggregate stands for a theory atom (`theory`): its guards then only carry
    /// the variables the atom's name and guard need bound.
    pub theory: Option<Box<NTheory>>,
}

/// An aggregate element `terms : cond` (planned condition).
#[derive(Clone, Debug)]
pub struct NElem {
    /// The tuple; its first term is the weight for `#sum`, `#min`, `#max`.
    pub terms: Vec<NTerm>,
    /// The condition, in evaluation order.
    pub cond: Vec<NLit>,
    /// For a conditional body literal `l : cond` (an aggregate with this single element and no
    /// guards): the alternatives of `l` (its pool alternatives), each its interval binders
    /// followed by the literal. An instance of the condition asks for *some* instance of some
    /// alternative (clingo's reading: pools, intervals and variables local to `l` give a
    /// disjunction).
    pub lit: Option<Vec<Vec<NLit>>>,
}

impl NElem {
    /// The literals of a conditional body literal's alternatives (none for other elements).
    pub fn lit_lits(&self) -> impl Iterator<Item = &NLit> {
        self.lit.iter().flatten().flatten()
    }
}

/// A head element `[not] atom : cond`.
#[derive(Clone, Debug)]
pub struct NCondLit {
    /// The atom (for an element with `conj`, the atom of its first literal).
    pub atom: NAtom,
    /// The condition, in evaluation order (empty when unconditional).
    pub cond: Vec<NLit>,
    /// Empty for a plain head atom. For an element written with a colon in a disjunction,
    /// gringo's reading: the element holds when its condition and every literal here holds
    /// (pools and intervals of the written literal are unfolded into this conjunction).
    pub conj: Vec<NHeadLit>,
}

/// One literal of a conditional disjunction element: `[not [not]] atom`, over every solution
/// of `expand` (the interval literals of the written literal, planned after the condition).
#[derive(Clone, Debug)]
pub struct NHeadLit {
    /// `not`, `not not` or nothing.
    pub sign: Sign,
    /// The atom.
    pub atom: NAtom,
    /// Interval binders local to this literal.
    pub expand: Vec<NLit>,
}

impl NCondLit {
    /// Every atom the element can make true (the positive literals of its conjunction).
    pub fn derived_atoms(&self) -> impl Iterator<Item = &NAtom> {
        let plain = self.conj.is_empty().then_some(&self.atom);
        plain.into_iter().chain(
            self.conj
                .iter()
                .filter(|l| l.sign == Sign::Positive)
                .map(|l| &l.atom),
        )
    }
}

/// A statement's head.
#[derive(Clone, Debug)]
pub enum NHead {
    /// No atoms: a constraint, or a directive whose payload is in [`NKind`].
    None,
    /// A disjunction of atoms.
    Disj(Vec<NCondLit>),
    /// An unbounded choice of atoms.
    Choice(Vec<NCondLit>),
}

/// What a statement produces beyond its head.
#[derive(Clone, Debug)]
pub enum NKind {
    /// An ordinary rule or constraint.
    Rule,
    /// A consistency-restoring rule with its optional label.
    Cr(Option<NTerm>),
    /// One minimize element: weight, priority, further terms (weights already negated for
    /// `#maximize`).
    Minimize {
        /// The weight.
        weight: NTerm,
        /// The priority.
        priority: NTerm,
        /// Distinguishing terms.
        terms: Vec<NTerm>,
        /// True for `#maximize`: the weight is negated.
        maximize: bool,
    },
    /// `#show t : body.`
    Show(NTerm),
    /// `#project a : body.`
    Project(NAtom),
    /// `#external a : body. [v]`
    External(NAtom, NTerm),
    /// `#heuristic a : body. [w@p, m]`
    Heuristic {
        /// The atom.
        atom: NAtom,
        /// Weight.
        weight: NTerm,
        /// Priority.
        priority: NTerm,
        /// Modifier.
        modifier: NTerm,
    },
    /// `#edge (u, v) : body.`
    Edge(NTerm, NTerm),
    /// A theory atom in the head (or a theory directive): the body's last literal is the
    /// theory aggregate ([`NAgg::theory`]) whose atom the rule derives.
    Theory,
}

/// A rewritten statement.
#[derive(Clone, Debug)]
pub struct NStmt {
    /// Index of the source statement.
    pub stmt: u32,
    /// Its span.
    pub span: Span,
    /// The head.
    pub head: NHead,
    /// The planned body.
    pub body: Vec<NLit>,
    /// The payload.
    pub kind: NKind,
    /// Number of variable slots.
    pub num_vars: u32,
    /// Name of each slot.
    pub var_names: Vec<Sym>,
    /// Global slots (bound by the body), in slot order.
    pub globals: Vec<u32>,
    /// Set when the rewriting made this statement as part of statement `stmt`'s translation
    /// (the constraint of a choice's bounds, a projection rule): its rules are auxiliaries.
    pub aux: Option<AuxKind>,
    /// For the choice of a bounded choice rule or a `#count`/`#sum` head aggregate: its bounds,
    /// which an instance must be able to reach before it is grounded (see [`HeadGate`]).
    pub gate: Option<Box<HeadGate>>,
}

/// The bounds of a choice rule `l { e } u` or head aggregate `l #f { t : a : c } u`, kept with
/// its unbounded choice. As gringo grounds them, an instance makes its atoms possible only once
/// the elements grounded so far can reach the bounds (the greatest possible count or sum is at
/// least the lower bound, the least at most the upper one). This matters when an element's
/// condition depends on the aggregate's own atoms: `2 { p; q(X) : s(X) } 2. s(1) :- p.` has no
/// answer set under clingo, since `p` alone cannot reach 2, so `p` never becomes possible and
/// neither does `s(1)`; the program's answer set {p, s(1), q(1)} is never grounded.
#[derive(Clone, Debug)]
pub struct HeadGate {
    /// `#sum` (or `#sum+`) rather than `#count`.
    pub sum: bool,
    /// The guards, read as `aggregate op term`.
    pub guards: Vec<(CmpOp, NTerm)>,
    /// The tuple of each head element (parallel to the choice's elements; its first term is
    /// the weight of a `#sum`); `None` for a choice rule, whose tuples are its atoms.
    pub tuples: Option<Vec<Vec<NTerm>>>,
}

/// `#show` configuration.
#[derive(Clone, Debug, Default)]
pub struct ShowConfig {
    /// `#show.` was written, or a `#show p/n.`: atoms are shown only by signature.
    pub restricted: bool,
    /// Signatures shown by `#show p/n.`.
    pub signatures: Vec<Pred>,
    /// The predicate and span of each `#show p/n.`, for gringo's `no atoms over signature
    /// occur in program`.
    pub signature_sites: Vec<(PredId, Span)>,
}

/// The whole rewritten program.
#[derive(Clone, Debug, Default)]
pub struct Compiled {
    /// Predicate signatures.
    pub preds: Vec<Pred>,
    /// Statements.
    pub stmts: Vec<NStmt>,
    /// `#show` configuration.
    pub show: ShowConfig,
    /// Predicates declared by `#defined`.
    pub defined: Vec<PredId>,
    /// Spans of the source statements, by statement index.
    pub stmt_spans: Vec<Span>,
    /// SPARC sort memberships, as facts of the sort predicates `#s/1`.
    pub sort_facts: Vec<(PredId, SymId)>,
    /// The rank of each predicate in clingo's order of domains (`domains`; [`UNRANKED`] for
    /// none), by predicate id; may be shorter than `preds`.
    pub domain_rank: Vec<u32>,
    /// Predicates ranked so far (the next rank).
    pub domains_ranked: u32,
    /// The source statements that are facts over terms that are not values (`p(-1).`,
    /// `p((1,2)).`), increasing: gringo makes their atoms after the other facts'.
    pub late_facts: Vec<u32>,
}

/// Rewriting context over the whole program.
pub struct Rewriter<'a> {
    /// The symbol table.
    pub syms: &'a mut Symbols,
    /// Diagnostics.
    pub diags: &'a mut Diagnostics,
    /// Sources, for snippets.
    pub sources: Option<&'a SourceMap>,
    /// Values of `#const` names.
    pub consts: HashMap<String, SymId>,
    /// The output.
    pub out: Compiled,
    /// Predicate ids.
    pred_map: HashMap<Pred, PredId>,
    /// Spans of unsupported constructs already reported.
    reported: Vec<Span>,
    /// Names (with `#`) of the SPARC sorts defined so far.
    pub sorts: Vec<String>,
    /// The statement being rewritten (index and span), for auxiliary rules.
    current: (u32, Span),
    /// Number of projection predicates made for anonymous variables under negation.
    projections: u32,
    /// Set while rewriting a statement made for another one's translation.
    aux_role: Option<AuxKind>,
    /// The gate of the choice statement being finished (set just before `finish`).
    gate: Option<HeadGate>,
    /// A grounding context supplies external functions: `@f(...)` becomes a call literal
    /// (without one it is reported).
    pub calls: bool,
    /// The context itself, for the calls of `#const` values (evaluated while rewriting, as
    /// clingo evaluates `#const k = @f().` at grounding).
    pub host: Option<&'a mut dyn super::Calls>,
    /// The ids of the tree's names in `syms.names`, direct-mapped by
    /// [`ast::Name::quick_hash`]: a program names few predicates, constants and variables
    /// many times, and a hit costs a hash of the name's bytes and one compare instead of the
    /// interner's probe. Entries stay valid: the interner never forgets a name.
    name_ids: Vec<Option<(ast::Name, Sym)>>,
    /// Predicate ids by signature, direct-mapped likewise (`pred_map` is the full table).
    pred_ids: Vec<Option<(Pred, PredId)>>,
    /// The `#theory` definitions in force (multi-shot: kept from earlier groundings).
    pub theories: Theories,
    /// The predicates of the facts met so far, ranked after the other statements' (`domains`);
    /// those of facts over terms that are not values apart, ranked last.
    facts: Vec<PredId>,
    late_facts: Vec<PredId>,
}

/// Slots of [`Rewriter`]'s name cache (a power of two).
const NAME_SLOTS: usize = 128;
/// Slots of [`Rewriter`]'s predicate cache (a power of two).
const PRED_SLOTS: usize = 64;

/// Per-statement variable table. Names are interned in the symbol table's interner (the
/// statement's `var_names` are those ids), so a variable costs no string of its own.
#[derive(Default)]
struct Vars {
    names: Vec<Sym>,
    spans: Vec<Span>,
    map: HashMap<Sym, u32>,
    fresh: u32,
}

impl Vars {
    fn slot(&mut self, name: Sym, span: Span) -> u32 {
        // Rules have few variables: a scan beats hashing; the map indexes the names only
        // past `SCAN`.
        const SCAN: usize = 16;
        if self.names.len() <= SCAN {
            if let Some(v) = self.names.iter().position(|&n| n == name) {
                return v as u32;
            }
        } else if let Some(&v) = self.map.get(&name) {
            return v;
        }
        let v = self.names.len() as u32;
        self.names.push(name);
        self.spans.push(span);
        if self.names.len() > SCAN {
            if self.map.is_empty() {
                for (i, &n) in self.names.iter().enumerate() {
                    self.map.insert(n, i as u32);
                }
            } else {
                self.map.insert(name, v);
            }
        }
        v
    }

    fn fresh(&mut self, interner: &mut Interner, prefix: &str, span: Span) -> u32 {
        self.fresh += 1;
        let name = interner.intern(&format!("#{prefix}{}", self.fresh));
        self.slot(name, span)
    }
}

/// The default-negation complement of a sign.
fn negate_sign(s: Sign) -> Sign {
    match s {
        Sign::Positive => Sign::Not,
        Sign::Not => Sign::NotNot,
        Sign::NotNot => Sign::Not,
    }
}

/// The complement of a comparison.
pub fn negate_cmp(op: CmpOp) -> CmpOp {
    match op {
        CmpOp::Eq => CmpOp::Ne,
        CmpOp::Ne => CmpOp::Eq,
        CmpOp::Lt => CmpOp::Ge,
        CmpOp::Le => CmpOp::Gt,
        CmpOp::Gt => CmpOp::Le,
        CmpOp::Ge => CmpOp::Lt,
    }
}

/// `t op x` read as `x op' t`.
pub fn flip_cmp(op: CmpOp) -> CmpOp {
    match op {
        CmpOp::Lt => CmpOp::Gt,
        CmpOp::Le => CmpOp::Ge,
        CmpOp::Gt => CmpOp::Lt,
        CmpOp::Ge => CmpOp::Le,
        o => o,
    }
}

/// Turns a symbolic atom into the term with the same shape (`-p(X)` into `-p(X)`).
fn atom_as_term(a: &ast::SymbolicAtom) -> ast::Term {
    let f = ast::Term {
        span: a.span,
        kind: TermKind::Function {
            name: a.name.clone(),
            args: a.args.clone(),
            trailing_comma: false,
        },
    };
    if a.negated {
        ast::Term {
            span: a.span,
            kind: TermKind::Unary {
                op: ast::UnaryOp::Minus,
                arg: Box::new(f),
            },
        }
    } else {
        f
    }
}

/// Rewrites the guards of a choice into those of a `#count` body aggregate.
fn lower_upper(lower: &Option<ast::Guard>, upper: &Option<ast::Guard>) -> bool {
    lower.is_some() || upper.is_some()
}

/// The guards of a head's bounds, each with `true` for the left (lower) one.
fn bounds<'g>(
    lower: &'g Option<ast::Guard>,
    upper: &'g Option<ast::Guard>,
) -> Vec<(&'g ast::Guard, bool)> {
    let left = lower.iter().map(|g| (g, true));
    left.chain(upper.iter().map(|g| (g, false))).collect()
}

impl<'a> Rewriter<'a> {
    /// A rewriter writing into `syms` and `diags`.
    pub fn new(
        syms: &'a mut Symbols,
        diags: &'a mut Diagnostics,
        sources: Option<&'a SourceMap>,
    ) -> Rewriter<'a> {
        Rewriter {
            syms,
            diags,
            sources,
            consts: HashMap::new(),
            out: Compiled::default(),
            pred_map: HashMap::new(),
            reported: Vec::new(),
            sorts: Vec::new(),
            current: (0, Span::default()),
            aux_role: None,
            gate: None,
            calls: false,
            host: None,
            projections: 0,
            name_ids: vec![None; NAME_SLOTS],
            pred_ids: vec![None; PRED_SLOTS],
            theories: Theories::default(),
            facts: Vec::new(),
            late_facts: Vec::new(),
        }
    }

    /// The id of a name of the tree (see `name_ids`).
    #[inline]
    pub fn name_id(&mut self, name: &ast::Name) -> Sym {
        let i = (name.quick_hash() >> (64 - NAME_SLOTS.trailing_zeros())) as usize;
        if let Some((n, sym)) = &self.name_ids[i] {
            if n == name {
                return *sym;
            }
        }
        let sym = self.syms.names.intern(name);
        self.name_ids[i] = Some((name.clone(), sym));
        sym
    }

    /// Multi-shot: continues the predicate table of an earlier rewriting (predicates keep their
    /// ids) and its count of projection predicates (a later `#projN` is another predicate).
    /// `ranks` and `ranked` are the predicates' domain ranks so far ([`Compiled::domain_rank`]).
    pub fn resume(&mut self, preds: Vec<Pred>, projections: u32, ranks: Vec<u32>, ranked: u32) {
        self.out.domain_rank = ranks;
        self.out.domains_ranked = ranked;
        self.pred_map = preds
            .iter()
            .enumerate()
            .map(|(i, p)| (p.clone(), i as PredId))
            .collect();
        self.out.preds = preds;
        self.projections = projections;
    }

    /// Projection predicates made so far (see [`Rewriter::resume`]).
    pub fn projections(&self) -> u32 {
        self.projections
    }

    /// The id of a predicate signature.
    pub fn pred(&mut self, name: &str, arity: u32, neg: bool) -> PredId {
        let name = self.syms.names.intern(name);
        self.pred_of(name, arity, neg)
    }

    /// The id of a predicate signature, when it has one already.
    pub fn find_pred(&self, name: Sym, arity: u32, neg: bool) -> Option<PredId> {
        self.pred_map.get(&Pred { name, arity, neg }).copied()
    }

    /// The id of a predicate signature whose name is interned already.
    pub fn pred_of(&mut self, name: Sym, arity: u32, neg: bool) -> PredId {
        let p = Pred { name, arity, neg };
        let slot =
            (name.0.wrapping_mul(0x9e37_79b9) ^ arity.wrapping_mul(0x85eb_ca6b) ^ neg as u32) >> 7;
        let slot = slot as usize & (PRED_SLOTS - 1);
        if let Some((q, id)) = &self.pred_ids[slot] {
            if *q == p {
                return *id;
            }
        }
        let id = match self.pred_map.get(&p) {
            Some(&id) => id,
            None => {
                let id = self.out.preds.len() as PredId;
                self.out.preds.push(p.clone());
                self.pred_map.insert(p.clone(), id);
                id
            }
        };
        self.pred_ids[slot] = Some((p, id));
        id
    }

    fn snippet(&self, span: Span) -> String {
        match self.sources {
            Some(s) if (span.file.0 as usize) < s.len() => s.get(span.file).slice(span).to_string(),
            _ => String::new(),
        }
    }

    /// Reports an unsupported construct once per span.
    pub fn unsupported(&mut self, span: Span, what: &str) {
        if self.reported.contains(&span) {
            return;
        }
        self.reported.push(span);
        let d = Diagnostic::error(span, format!("unsupported: {what}"));
        let snip = self.snippet(span);
        self.diags.push(if snip.is_empty() {
            d
        } else {
            d.with_snippet(snip)
        });
    }

    /// One external call of a `#const` value (`V = @f(args)`, arguments bound by the calls
    /// before it): `V` bound to the one symbol the host returns; an error otherwise.
    fn const_call(&mut self, l: &NLit, b: &mut super::term::Binding) -> Option<()> {
        let NLit::Call {
            pat: NTerm::Var(v),
            name,
            args,
            span,
        } = l
        else {
            return None;
        };
        let mut vals = Vec::with_capacity(args.len());
        for a in args {
            vals.push(a.eval(self.syms, b).ok()?);
        }
        let text = self.syms.names.resolve(*name).to_string();
        let host = self.host.as_deref_mut()?;
        let message = match host.call(self.syms, &text, &vals) {
            Ok(values) if values.len() == 1 => {
                b.unify(*v, values[0]);
                return Some(());
            }
            Ok(values) => format!(
                "@{text} gave {} symbols for a #const value (one expected)",
                values.len()
            ),
            Err(e) => e,
        };
        self.diags
            .push(Diagnostic::error(*span, message).with_snippet(self.snippet(*span)));
        None
    }

    /// Evaluates a ground term (for `#const` values; external calls `@f(...)` are made with
    /// the grounding context, [`Rewriter::host`]).
    pub fn eval_ground(&mut self, t: &ast::Term) -> Option<SymId> {
        let mut vars = Vars::default();
        let mut extra = Vec::new();
        let n = self.term(t, &mut vars, &mut extra)?;
        let only_calls = extra.iter().all(|l| matches!(l, NLit::Call { .. }));
        let fresh_only = vars.names.len() == extra.len();
        if !only_calls || !fresh_only || (!extra.is_empty() && self.host.is_none()) {
            self.diags.push(
                Diagnostic::error(t.span, "constant term expected")
                    .with_snippet(self.snippet(t.span)),
            );
            return None;
        }
        let mut b = super::term::Binding::new(vars.names.len());
        for l in &extra {
            self.const_call(l, &mut b)?;
        }
        match n.eval(self.syms, &b) {
            Ok(s) => Some(s),
            Err(span) => {
                self.diags.push(
                    Diagnostic::warning(
                        crate::base::WarningKind::OperationUndefined,
                        span,
                        "operation undefined",
                    )
                    .with_snippet(self.snippet(span)),
                );
                None
            }
        }
    }
}
