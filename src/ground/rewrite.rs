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

use hashbrown::HashMap;

use crate::base::{Diagnostic, Diagnostics, SourceMap, Span};
use crate::syntax::ast::{self, AggregateFunction, CmpOp, Sign, TermKind};

use super::program::AuxKind;
use super::symbol::{SymId, Symbols};
use super::term::NTerm;
use crate::base::intern::Sym;

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
    /// Where it was written.
    pub span: Span,
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
}

/// `#show` configuration.
#[derive(Clone, Debug, Default)]
pub struct ShowConfig {
    /// `#show.` was written, or a `#show p/n.`: atoms are shown only by signature.
    pub restricted: bool,
    /// Signatures shown by `#show p/n.`.
    pub signatures: Vec<Pred>,
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
    /// `#project p/n.` signatures.
    pub project_sigs: Vec<PredId>,
    /// Predicates declared by `#defined`.
    pub defined: Vec<PredId>,
    /// Spans of the source statements, by statement index.
    pub stmt_spans: Vec<Span>,
    /// SPARC sort memberships, as facts of the sort predicates `#s/1`.
    pub sort_facts: Vec<(PredId, SymId)>,
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
}

/// Per-statement variable table.
#[derive(Default)]
struct Vars {
    names: Vec<String>,
    spans: Vec<Span>,
    map: HashMap<String, u32>,
    fresh: u32,
}

impl Vars {
    fn slot(&mut self, name: &str, span: Span) -> u32 {
        if let Some(&v) = self.map.get(name) {
            return v;
        }
        let v = self.names.len() as u32;
        self.names.push(name.to_string());
        self.spans.push(span);
        self.map.insert(name.to_string(), v);
        v
    }

    fn fresh(&mut self, prefix: &str, span: Span) -> u32 {
        self.fresh += 1;
        let name = format!("#{prefix}{}", self.fresh);
        self.slot(&name, span)
    }
}

/// True when unfolding changes nothing in `t`: no pool, no argument-tuple pool
/// (`f(1,2;3,4)`), no parentheses (unfolding drops them).
fn pool_free_term(t: &ast::Term) -> bool {
    match &t.kind {
        TermKind::Pool(_) | TermKind::Paren(_) => false,
        TermKind::Function { args, .. } => {
            args.len() <= 1 && args.iter().flatten().all(pool_free_term)
        }
        TermKind::Unary { arg, .. } => pool_free_term(arg),
        TermKind::Binary { lhs, rhs, .. } => pool_free_term(lhs) && pool_free_term(rhs),
        TermKind::Interval { lo, hi } => pool_free_term(lo) && pool_free_term(hi),
        TermKind::ScriptCall { .. } => false,
        _ => true,
    }
}

/// [`pool_free_term`] for a literal.
fn pool_free_literal(l: &ast::Literal) -> bool {
    match &l.atom {
        ast::Atom::Symbolic(a) => a.args.len() <= 1 && a.args.iter().flatten().all(pool_free_term),
        ast::Atom::Comparison { lhs, rhs, .. } => pool_free_term(lhs) && pool_free_term(rhs),
        ast::Atom::Boolean(_) => true,
        ast::Atom::Sort { arg, .. } => pool_free_term(arg),
    }
}

/// [`pool_free_term`] for a conditional literal.
fn pool_free_cond(c: &ast::ConditionalLiteral) -> bool {
    pool_free_literal(&c.literal) && c.condition.iter().all(pool_free_literal)
}

/// [`pool_free_term`] for a guard.
fn pool_free_guard(g: &Option<ast::Guard>) -> bool {
    g.as_ref().is_none_or(|g| pool_free_term(&g.term))
}

/// True when [`Rewriter::rule`]'s unfolding would give the rule back unchanged.
fn pool_free_rule(r: &ast::Rule) -> bool {
    let head = match &r.head {
        ast::Head::None => true,
        ast::Head::Disjunction(es) => es.iter().all(pool_free_cond),
        ast::Head::Choice(c) => {
            c.elements.iter().all(pool_free_cond)
                && pool_free_guard(&c.lower)
                && pool_free_guard(&c.upper)
        }
        ast::Head::Aggregate(h) => {
            h.elements.iter().all(|e| {
                e.terms.iter().all(pool_free_term)
                    && pool_free_literal(&e.literal)
                    && e.condition.iter().all(pool_free_literal)
            }) && pool_free_guard(&h.lower)
                && pool_free_guard(&h.upper)
        }
    };
    let kind = match &r.kind {
        ast::RuleKind::Normal => true,
        ast::RuleKind::ConsistencyRestoring { label } => {
            label.as_ref().is_none_or(|l| pool_free_term(l))
        }
    };
    head && kind
        && r.body.iter().all(|b| match b {
            ast::BodyLiteral::Literal(l) => pool_free_literal(l),
            ast::BodyLiteral::Conditional(c) => pool_free_cond(c),
            ast::BodyLiteral::Aggregate { aggregate: a, .. } => {
                a.elements.iter().all(|e| {
                    e.terms.iter().all(pool_free_term) && e.condition.iter().all(pool_free_literal)
                }) && a.set_syntax.iter().all(pool_free_cond)
                    && pool_free_guard(&a.lower)
                    && pool_free_guard(&a.upper)
            }
        })
}

/// Unfolds the pools of a term: every alternative, pool-free.
pub fn unpool_term(t: &ast::Term) -> Vec<ast::Term> {
    let mk = |kind| ast::Term { span: t.span, kind };
    match &t.kind {
        TermKind::Pool(alts) => alts.iter().flat_map(unpool_term).collect(),
        TermKind::Function {
            name,
            args,
            trailing_comma,
        } => {
            let mut out = Vec::new();
            for list in args {
                for combo in unpool_list(list) {
                    out.push(mk(TermKind::Function {
                        name: name.clone(),
                        args: vec![combo],
                        trailing_comma: *trailing_comma,
                    }));
                }
            }
            if args.is_empty() {
                out.push(t.clone());
            }
            out
        }
        TermKind::Unary { op, arg } => unpool_term(arg)
            .into_iter()
            .map(|a| {
                mk(TermKind::Unary {
                    op: *op,
                    arg: Box::new(a),
                })
            })
            .collect(),
        TermKind::Binary { op, lhs, rhs } => {
            let mut out = Vec::new();
            for l in unpool_term(lhs) {
                for r in unpool_term(rhs) {
                    out.push(mk(TermKind::Binary {
                        op: *op,
                        lhs: Box::new(l.clone()),
                        rhs: Box::new(r),
                    }));
                }
            }
            out
        }
        TermKind::Interval { lo, hi } => {
            let mut out = Vec::new();
            for l in unpool_term(lo) {
                for h in unpool_term(hi) {
                    out.push(mk(TermKind::Interval {
                        lo: Box::new(l.clone()),
                        hi: Box::new(h),
                    }));
                }
            }
            out
        }
        TermKind::Paren(inner) => unpool_term(inner),
        _ => vec![t.clone()],
    }
}

/// Unfolds the pools of an argument list into pool-free lists (the cross product).
///
/// Linear in the size of the result: a term without alternatives is pushed onto every prefix
/// in place, and prefixes are copied only when a pool multiplies them (an atom with 2,000,000
/// pool-free arguments is one pass, not 2,000,000 growing copies).
pub fn unpool_list(list: &[ast::Term]) -> Vec<Vec<ast::Term>> {
    product(list.iter().map(unpool_term).collect())
}

/// Unfolds the pools of a literal.
pub fn unpool_literal(l: &ast::Literal) -> Vec<ast::Literal> {
    match &l.atom {
        ast::Atom::Symbolic(a) => unpool_atom(a)
            .into_iter()
            .map(|atom| ast::Literal {
                span: l.span,
                sign: l.sign,
                atom: ast::Atom::Symbolic(atom),
            })
            .collect(),
        ast::Atom::Comparison { lhs, op, rhs } => {
            let mut out = Vec::new();
            for a in unpool_term(lhs) {
                for b in unpool_term(rhs) {
                    out.push(ast::Literal {
                        span: l.span,
                        sign: l.sign,
                        atom: ast::Atom::Comparison {
                            lhs: Box::new(a.clone()),
                            op: *op,
                            rhs: Box::new(b),
                        },
                    });
                }
            }
            out
        }
        _ => vec![l.clone()],
    }
}

/// Unfolds the pools of an atom.
pub fn unpool_atom(a: &ast::SymbolicAtom) -> Vec<ast::SymbolicAtom> {
    let mut out = Vec::new();
    for list in &a.args {
        for combo in unpool_list(list) {
            out.push(ast::SymbolicAtom {
                span: a.span,
                negated: a.negated,
                name: a.name.clone(),
                args: vec![combo],
            });
        }
    }
    if a.args.is_empty() {
        out.push(a.clone());
    }
    out
}

/// Cross product of alternatives, in order (the first choice varies slowest); linear in the
/// size of the result, see [`unpool_list`].
fn product<T: Clone>(choices: Vec<Vec<T>>) -> Vec<Vec<T>> {
    let mut acc: Vec<Vec<T>> = vec![Vec::with_capacity(choices.len())];
    for mut alts in choices {
        if alts.len() == 1 {
            // The common case (no pool here): push onto every prefix in place.
            let a = alts.pop().expect("one alternative");
            if let Some((last, rest)) = acc.split_last_mut() {
                for prefix in rest {
                    prefix.push(a.clone());
                }
                last.push(a);
            }
            continue;
        }
        let mut next = Vec::with_capacity(acc.len() * alts.len());
        if let Some((last, rest)) = alts.split_last() {
            for mut prefix in acc {
                for a in rest {
                    let mut p = prefix.clone();
                    p.push(a.clone());
                    next.push(p);
                }
                prefix.push(last.clone());
                next.push(prefix);
            }
        }
        acc = next;
    }
    acc
}

/// Unfolds pools in body literals: each alternative of a plain literal is a separate rule;
/// inside aggregates and conditions alternatives become separate elements.
fn unpool_body(body: &[ast::BodyLiteral]) -> Vec<Vec<ast::BodyLiteral>> {
    let choices: Vec<Vec<Vec<ast::BodyLiteral>>> = body
        .iter()
        .map(|b| match b {
            ast::BodyLiteral::Literal(l) => unpool_literal(l)
                .into_iter()
                .map(|l| vec![ast::BodyLiteral::Literal(l)])
                .collect(),
            // The literal keeps its pools (alternatives of one conditional literal); the
            // condition's alternatives are further conditional literals of the same rule.
            ast::BodyLiteral::Conditional(c) => vec![unpool_condition(c)
                .into_iter()
                .map(ast::BodyLiteral::Conditional)
                .collect()],
            ast::BodyLiteral::Aggregate { sign, aggregate } => {
                let mut agg = aggregate.clone();
                agg.elements = aggregate
                    .elements
                    .iter()
                    .flat_map(|e| {
                        let conds = product(e.condition.iter().map(unpool_literal).collect());
                        let tuples = unpool_list(&e.terms);
                        let mut out = Vec::new();
                        for t in &tuples {
                            for c in &conds {
                                out.push(ast::BodyAggregateElement {
                                    span: e.span,
                                    terms: t.clone(),
                                    condition: c.clone(),
                                });
                            }
                        }
                        out
                    })
                    .collect();
                agg.set_syntax = aggregate.set_syntax.iter().flat_map(unpool_cond).collect();
                // Alternatives of the guards are separate rules.
                let mut out = Vec::new();
                for lower in unpool_guard(&aggregate.lower) {
                    for upper in unpool_guard(&aggregate.upper) {
                        let mut a = agg.clone();
                        a.lower = lower.clone();
                        a.upper = upper;
                        out.push(vec![ast::BodyLiteral::Aggregate {
                            sign: *sign,
                            aggregate: a,
                        }]);
                    }
                }
                out
            }
        })
        .collect();
    product(choices).into_iter().map(|b| b.concat()).collect()
}

/// Unfolds pools in a conditional literal into several.
fn unpool_cond(c: &ast::ConditionalLiteral) -> Vec<ast::ConditionalLiteral> {
    let conds = product(c.condition.iter().map(unpool_literal).collect());
    let mut out = Vec::new();
    for l in unpool_literal(&c.literal) {
        for cond in &conds {
            out.push(ast::ConditionalLiteral {
                span: c.span,
                literal: l.clone(),
                condition: cond.clone(),
                has_colon: c.has_colon,
            });
        }
    }
    out
}

/// The alternatives of an optional guard.
fn unpool_guard(g: &Option<ast::Guard>) -> Vec<Option<ast::Guard>> {
    match g {
        None => vec![None],
        Some(g) => unpool_term(&g.term)
            .into_iter()
            .map(|term| Some(ast::Guard { op: g.op, term }))
            .collect(),
    }
}

/// Unfolds the pools of a conditional literal's condition only, one literal per alternative.
fn unpool_condition(c: &ast::ConditionalLiteral) -> Vec<ast::ConditionalLiteral> {
    product(c.condition.iter().map(unpool_literal).collect())
        .into_iter()
        .map(|condition| ast::ConditionalLiteral {
            span: c.span,
            literal: c.literal.clone(),
            condition,
            has_colon: c.has_colon,
        })
        .collect()
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
            projections: 0,
        }
    }

    /// The id of a predicate signature.
    pub fn pred(&mut self, name: &str, arity: u32, neg: bool) -> PredId {
        let p = Pred {
            name: self.syms.names.intern(name),
            arity,
            neg,
        };
        if let Some(&id) = self.pred_map.get(&p) {
            return id;
        }
        let id = self.out.preds.len() as PredId;
        self.out.preds.push(p.clone());
        self.pred_map.insert(p, id);
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

    /// Evaluates a ground term (for `#const` values).
    pub fn eval_ground(&mut self, t: &ast::Term) -> Option<SymId> {
        let mut vars = Vars::default();
        let mut extra = Vec::new();
        let n = self.term(t, &mut vars, &mut extra)?;
        if !extra.is_empty() || !vars.names.is_empty() {
            self.diags.push(
                Diagnostic::error(t.span, "constant term expected")
                    .with_snippet(self.snippet(t.span)),
            );
            return None;
        }
        match n.eval(self.syms, &super::term::Binding::new(0)) {
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

    /// Compiles a pool-free term; intervals add binder literals to `extra`.
    fn term(&mut self, t: &ast::Term, vars: &mut Vars, extra: &mut Vec<NLit>) -> Option<NTerm> {
        Some(match &t.kind {
            // clingo reads an integer literal modulo 2^32 (`2147483648` is `-2147483648`,
            // `0x80000000` too), as its arithmetic wraps: the truncating cast does the same.
            TermKind::Integer(n) => NTerm::Sym(self.syms.int(*n as i32)),
            TermKind::String(s) => NTerm::Sym(self.syms.string(s)),
            TermKind::Constant(c) => match self.consts.get(c) {
                Some(&v) => NTerm::Sym(v),
                None => NTerm::Sym(self.syms.fun_str(c, false, &[])),
            },
            TermKind::Variable(v) => NTerm::Var(vars.slot(v, t.span)),
            TermKind::Anonymous => NTerm::Var(vars.fresh("Anon", t.span)),
            TermKind::Infimum => NTerm::Sym(self.syms.inf()),
            TermKind::Supremum => NTerm::Sym(self.syms.sup()),
            TermKind::Function { name, args, .. } => {
                let list = args.first().cloned().unwrap_or_default();
                let mut nargs = Vec::with_capacity(list.len());
                for a in &list {
                    nargs.push(self.term(a, vars, extra)?);
                }
                let name_sym = self.syms.names.intern(name);
                self.fold_fun(name_sym, false, nargs)
            }
            TermKind::ScriptCall { .. } => {
                self.unsupported(t.span, "script calls (@f) are not supported by Lucent");
                return None;
            }
            TermKind::Unary { op, arg } => {
                let a = self.term(arg, vars, extra)?;
                match (op, a) {
                    (ast::UnaryOp::Minus, NTerm::Fun { name, neg, args })
                        if !self.syms.names.resolve(name).is_empty() =>
                    {
                        NTerm::Fun {
                            name,
                            neg: !neg,
                            args,
                        }
                    }
                    (op, a) => self.fold(NTerm::Unary {
                        op: *op,
                        arg: Box::new(a),
                        span: t.span,
                    }),
                }
            }
            TermKind::Binary { op, lhs, rhs } => {
                let l = self.term(lhs, vars, extra)?;
                let r = self.term(rhs, vars, extra)?;
                self.fold(NTerm::Binary {
                    op: *op,
                    lhs: Box::new(l),
                    rhs: Box::new(r),
                    span: t.span,
                })
            }
            TermKind::Interval { lo, hi } => {
                let lo = self.term(lo, vars, extra)?;
                let hi = self.term(hi, vars, extra)?;
                let v = vars.fresh("Range", t.span);
                extra.push(NLit::Interval {
                    pat: NTerm::Var(v),
                    lo,
                    hi,
                });
                NTerm::Var(v)
            }
            TermKind::Pool(alts) if alts.len() == 1 => self.term(&alts[0], vars, extra)?,
            TermKind::Pool(_) => {
                self.unsupported(t.span, "pool in this position");
                return None;
            }
            TermKind::Paren(inner) => self.term(inner, vars, extra)?,
        })
    }

    fn fold_fun(&mut self, name: Sym, neg: bool, args: Vec<NTerm>) -> NTerm {
        if args.iter().all(|a| matches!(a, NTerm::Sym(_))) {
            let vals: Vec<SymId> = args
                .iter()
                .map(|a| match a {
                    NTerm::Sym(s) => *s,
                    _ => unreachable!("checked above"),
                })
                .collect();
            NTerm::Sym(self.syms.fun(name, neg, &vals))
        } else {
            NTerm::Fun { name, neg, args }
        }
    }

    /// Folds ground operations whose value is defined (undefined ones stay, so grounding
    /// reports them where they are used).
    fn fold(&mut self, t: NTerm) -> NTerm {
        if t.is_ground() {
            if let Ok(v) = t.eval(self.syms, &super::term::Binding::new(0)) {
                return NTerm::Sym(v);
            }
        }
        t
    }

    /// The term with the shape of a compiled atom.
    fn atom_term(&mut self, a: &NAtom) -> NTerm {
        self.fold_fun(a.name, a.neg, a.args.clone())
    }

    fn atom(
        &mut self,
        a: &ast::SymbolicAtom,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<NAtom> {
        let list: &[ast::Term] = a.args.first().map_or(&[], Vec::as_slice);
        let mut args = Vec::with_capacity(list.len());
        for t in list {
            args.push(self.term(t, vars, extra)?);
        }
        let pred = self.pred(&a.name, args.len() as u32, a.negated);
        Some(NAtom {
            pred,
            name: self.syms.names.intern(&a.name),
            neg: a.negated,
            args,
            span: a.span,
            sort: false,
        })
    }

    fn literal(
        &mut self,
        l: &ast::Literal,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<NLit> {
        Some(match &l.atom {
            ast::Atom::Symbolic(a) => NLit::Pred {
                sign: l.sign,
                atom: self.atom(a, vars, extra)?,
            },
            ast::Atom::Comparison { lhs, op, rhs } => {
                let op = if l.sign == Sign::Not {
                    negate_cmp(*op)
                } else {
                    *op
                };
                NLit::Cmp {
                    op,
                    lhs: self.term(lhs, vars, extra)?,
                    rhs: self.term(rhs, vars, extra)?,
                }
            }
            ast::Atom::Boolean(b) => NLit::Bool(if l.sign == Sign::Not { !*b } else { *b }),
            ast::Atom::Sort { sort, arg } => {
                let name = format!("#{sort}");
                if !self.sorts.contains(&name) {
                    self.diags.push(
                        Diagnostic::error(l.span, format!("undefined sort #{sort}"))
                            .with_snippet(self.snippet(l.span)),
                    );
                    return None;
                }
                let t = self.term(arg, vars, extra)?;
                let pred = self.pred(&name, 1, false);
                let atom = NAtom {
                    pred,
                    name: self.syms.names.intern(&name),
                    neg: false,
                    args: vec![t],
                    span: l.span,
                    sort: true,
                };
                NLit::Pred { sign: l.sign, atom }
            }
        })
    }

    /// Compiles a condition (list of literals) into `out`.
    fn condition(
        &mut self,
        lits: &[ast::Literal],
        vars: &mut Vars,
        out: &mut Vec<NLit>,
    ) -> Option<()> {
        for l in lits {
            let mut extra = Vec::new();
            let n = self.literal(l, vars, &mut extra)?;
            out.append(&mut extra);
            out.push(n);
        }
        Some(())
    }

    fn guard(
        &mut self,
        g: &ast::Guard,
        left: bool,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<(CmpOp, NTerm)> {
        let op = if left { flip_cmp(g.op) } else { g.op };
        Some((op, self.term(&g.term, vars, extra)?))
    }

    fn body_aggregate(
        &mut self,
        sign: Sign,
        a: &ast::BodyAggregate,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<NLit> {
        let mut guards = Vec::new();
        if let Some(g) = &a.lower {
            guards.push(self.guard(g, true, vars, extra)?);
        }
        if let Some(g) = &a.upper {
            guards.push(self.guard(g, false, vars, extra)?);
        }
        let mut elems = Vec::new();
        for e in &a.elements {
            let mut cond = Vec::new();
            let mut terms = Vec::new();
            for t in &e.terms {
                terms.push(self.term(t, vars, &mut cond)?);
            }
            self.condition(&e.condition, vars, &mut cond)?;
            elems.push(NElem {
                terms,
                cond,
                lit: None,
            });
        }
        for c in &a.set_syntax {
            // `{ l : c }` counts the distinct atoms l (with their conditions).
            let mut cond = Vec::new();
            if !matches!(c.literal.atom, ast::Atom::Symbolic(_)) {
                self.unsupported(c.span, "non-atomic element in a set aggregate");
                return None;
            }
            let mut lits = vec![c.literal.clone()];
            lits.extend(c.condition.iter().cloned());
            self.condition(&lits, vars, &mut cond)?;
            // The tuple is the atom itself, with the variables (and interval variables) of
            // its compiled form.
            let t = cond
                .iter()
                .find_map(|l| match l {
                    NLit::Pred { atom, .. } => Some(self.atom_term(atom)),
                    _ => None,
                })
                .expect("the element literal was compiled");
            elems.push(NElem {
                terms: vec![t],
                cond,
                lit: None,
            });
        }
        Some(NLit::Agg(Box::new(NAgg {
            sign,
            func: a.function,
            guards,
            binder: None,
            elems,
            span: a.span,
        })))
    }

    fn body(
        &mut self,
        body: &[ast::BodyLiteral],
        vars: &mut Vars,
        out: &mut Vec<NLit>,
    ) -> Option<()> {
        for b in body {
            let mut extra = Vec::new();
            let n = match b {
                ast::BodyLiteral::Literal(l)
                    if l.sign != Sign::Positive && has_anonymous_arg(l) =>
                {
                    let p = self.project(l);
                    self.literal(&p, vars, &mut extra)?
                }
                ast::BodyLiteral::Literal(l) => self.literal(l, vars, &mut extra)?,
                ast::BodyLiteral::Aggregate { sign, aggregate } => {
                    self.body_aggregate(*sign, aggregate, vars, &mut extra)?
                }
                ast::BodyLiteral::Conditional(c) => {
                    // l : c holds when every instance of c has l; kept as a guard-less
                    // aggregate with one element that the instantiator treats specially.
                    let mut cond = Vec::new();
                    self.condition(&c.condition, vars, &mut cond)?;
                    let mut alts = Vec::new();
                    for l in unpool_literal(&c.literal) {
                        let mut alt = Vec::new();
                        self.condition(std::slice::from_ref(&l), vars, &mut alt)?;
                        alts.push(alt);
                    }
                    NLit::Agg(Box::new(NAgg {
                        sign: Sign::Positive,
                        func: AggregateFunction::Count,
                        guards: Vec::new(),
                        binder: None,
                        elems: vec![NElem {
                            terms: Vec::new(),
                            cond,
                            lit: Some(alts),
                        }],
                        span: c.span,
                    }))
                }
            };
            out.append(&mut extra);
            out.push(n);
        }
        Some(())
    }

    /// `not p(X,_)` is `not #projN(X)` with `#projN(P) :- p(P,_).` (gringo projects anonymous
    /// variables out of negated atoms the same way).
    fn project(&mut self, l: &ast::Literal) -> ast::Literal {
        let ast::Atom::Symbolic(a) = &l.atom else {
            return l.clone();
        };
        self.projections += 1;
        let name = format!("#proj{}", self.projections);
        let args = a.args.first().cloned().unwrap_or_default();
        let mut head_args = Vec::new();
        let mut body_args = Vec::new();
        let mut lit_args = Vec::new();
        for (i, t) in args.iter().enumerate() {
            if matches!(t.kind, TermKind::Anonymous) {
                body_args.push(t.clone());
            } else {
                let v = ast::Term {
                    span: t.span,
                    kind: TermKind::Variable(format!("#P{i}")),
                };
                head_args.push(v.clone());
                body_args.push(v);
                lit_args.push(t.clone());
            }
        }
        let mk = |name: &str, negated: bool, args: Vec<ast::Term>| ast::SymbolicAtom {
            span: a.span,
            negated,
            name: name.to_string(),
            args: vec![args],
        };
        let rule = ast::Rule {
            head: ast::Head::Disjunction(vec![ast::ConditionalLiteral {
                span: a.span,
                literal: ast::Literal {
                    span: a.span,
                    sign: Sign::Positive,
                    atom: ast::Atom::Symbolic(mk(&name, false, head_args)),
                },
                condition: Vec::new(),
                has_colon: false,
            }]),
            body: vec![ast::BodyLiteral::Literal(ast::Literal {
                span: l.span,
                sign: Sign::Positive,
                atom: ast::Atom::Symbolic(mk(&a.name, a.negated, body_args)),
            })],
            kind: ast::RuleKind::Normal,
        };
        let (index, span) = self.current;
        let role = self.aux_role.replace(AuxKind::Projection);
        self.rule(index, span, &rule);
        self.aux_role = role;
        self.current = (index, span);
        ast::Literal {
            span: l.span,
            sign: l.sign,
            atom: ast::Atom::Symbolic(mk(&name, false, lit_args)),
        }
    }

    fn head_elem(
        &mut self,
        c: &ast::ConditionalLiteral,
        vars: &mut Vars,
        body_extra: &mut Vec<NLit>,
    ) -> Option<NCondLit> {
        let ast::Atom::Symbolic(a) = &c.literal.atom else {
            if let ast::Atom::Boolean(false) = c.literal.atom {
                // `#false` in a head: an empty disjunction element.
                self.unsupported(c.span, "#false in a disjunctive head with other elements");
            } else {
                self.unsupported(c.span, "this head literal");
            }
            return None;
        };
        if c.literal.sign != Sign::Positive {
            self.unsupported(c.span, "default negation in rule heads");
            return None;
        }
        let mut cond = Vec::new();
        let atom = if c.condition.is_empty() {
            self.atom(a, vars, body_extra)?
        } else {
            let at = self.atom(a, vars, &mut cond)?;
            self.condition(&c.condition, vars, &mut cond)?;
            at
        };
        Some(NCondLit {
            atom,
            cond,
            conj: Vec::new(),
        })
    }

    /// A disjunction element written with a colon, `l : c`, read as gringo does: it holds
    /// when `c` and every instance of `l` hold, where `l`'s pools and intervals give the
    /// instances (an undefined instance is left out, so an element without any is `c`).
    fn disj_elem(&mut self, c: &ast::ConditionalLiteral, vars: &mut Vars) -> Option<NCondLit> {
        let mut conj = Vec::new();
        for l in unpool_literal(&c.literal) {
            let ast::Atom::Symbolic(a) = &l.atom else {
                self.unsupported(c.span, "this head literal");
                return None;
            };
            let mut expand = Vec::new();
            let atom = self.atom(a, vars, &mut expand)?;
            conj.push(NHeadLit {
                sign: l.sign,
                atom,
                expand,
            });
        }
        let mut cond = Vec::new();
        self.condition(&c.condition, vars, &mut cond)?;
        Some(NCondLit {
            atom: conj[0].atom.clone(),
            cond,
            conj,
        })
    }

    /// The element `t1,...,tn : a : c` of a head aggregate chooses `a` only for the instances
    /// whose tuple is defined and, for `#sum` and `#sum+`, whose weight `t1` is an integer, as
    /// in clingo. Adds to the element's condition `t = t` for each tuple term with an
    /// operation and `t1+0 = t1+0` for a non-integer sum weight (gringo's own check: clingo
    /// reports `operation undefined: (X+0)`). Returns false when the element can never count.
    fn tuple_checks(
        &mut self,
        func: AggregateFunction,
        terms: &[ast::Term],
        vars: &mut Vars,
        cond: &mut Vec<NLit>,
    ) -> bool {
        let sum = matches!(func, AggregateFunction::Sum | AggregateFunction::SumPlus);
        for (i, t) in terms.iter().enumerate() {
            let mut scratch = Vec::new();
            let Some(nt) = self.term(t, vars, &mut scratch) else {
                return false;
            };
            if !scratch.is_empty() {
                // An interval: always defined, and already a number when it is the weight.
                continue;
            }
            let check = if sum && i == 0 {
                match nt {
                    NTerm::Sym(v) if self.syms.num(v).is_some() => continue,
                    NTerm::Sym(_) => return false,
                    NTerm::Var(_)
                    | NTerm::Fun { .. }
                    | NTerm::Unary { .. }
                    | NTerm::Binary { .. } => {
                        let zero = self.syms.int(0);
                        NTerm::Binary {
                            op: ast::BinaryOp::Add,
                            lhs: Box::new(nt),
                            rhs: Box::new(NTerm::Sym(zero)),
                            span: t.span,
                        }
                    }
                }
            } else if nt.has_operation() {
                nt
            } else {
                continue;
            };
            cond.push(NLit::Cmp {
                op: CmpOp::Eq,
                lhs: check.clone(),
                rhs: check,
            });
        }
        true
    }

    /// Rewrites every statement of `program`.
    pub fn program(&mut self, program: &ast::Program, consts: &[(String, ast::Term)]) {
        // #const: command-line values win over default definitions, [override] wins over both.
        let mut overrides: HashMap<String, SymId> = HashMap::new();
        for (name, t) in consts {
            if let Some(v) = self.eval_ground(t) {
                overrides.insert(name.clone(), v);
            }
        }
        self.const_definitions(program, &overrides);
        for (k, v) in overrides {
            self.consts.entry(k).or_insert(v);
        }
        let lowered;
        let program = if program.dialect == ast::Dialect::Sparc {
            lowered = super::sparc::lower(self, program);
            &lowered
        } else {
            program
        };
        let mut in_base = true;
        for (i, st) in program.statements.iter().enumerate() {
            self.out.stmt_spans.push(st.span);
            if let ast::StatementKind::ProgramPart(p) = &st.kind {
                in_base = p.name == "base";
                if !in_base {
                    self.diags.push(Diagnostic::warning(
                        crate::base::WarningKind::Other,
                        st.span,
                        format!(
                            "program part '{}' is ignored: Lucent grounds only #program base",
                            p.name
                        ),
                    ));
                }
                continue;
            }
            if !in_base {
                continue;
            }
            self.statement(i as u32, st);
        }
    }

    /// Evaluates the `#const` definitions not overridden by `-c`, each after the constants its
    /// value names (`#const a=b. #const b=1.` gives `a` the value 1, as gringo does). A second
    /// definition of a name is gringo's `redefinition of constant` error (the first one
    /// stays); definitions naming each other in a cycle are a `cyclic constant definition`
    /// error and stay unevaluated. A definition naming itself (`#const a=a.`) is no cycle: the
    /// name stays a symbol.
    fn const_definitions(&mut self, program: &ast::Program, overrides: &HashMap<String, SymId>) {
        // The definitions in force, in file order: (statement span, definition).
        let mut defs: Vec<(Span, &ast::ConstDef)> = Vec::new();
        for st in &program.statements {
            let ast::StatementKind::Const(c) = &st.kind else {
                continue;
            };
            if c.kind == ast::ConstKind::Default && overrides.contains_key(&c.name) {
                continue;
            }
            if let Some(&(first, _)) = defs.iter().find(|(_, d)| d.name == c.name) {
                self.diags.push(
                    Diagnostic::error(st.span, "redefinition of constant")
                        .with_snippet(self.snippet(st.span))
                        .with_note(Some(first), "constant also defined here"),
                );
                continue;
            }
            defs.push((st.span, c));
        }
        // deps[i]: the definitions whose names definition i's value mentions.
        let deps: Vec<Vec<usize>> = defs
            .iter()
            .enumerate()
            .map(|(i, (_, d))| {
                let mut names = Vec::new();
                const_names(&d.value, &mut names);
                let mut out: Vec<usize> = names
                    .iter()
                    .filter_map(|n| defs.iter().position(|(_, e)| e.name == *n))
                    .filter(|&j| j != i)
                    .collect();
                out.sort_unstable();
                out.dedup();
                out
            })
            .collect();
        let mut done = vec![false; defs.len()];
        loop {
            let mut progress = false;
            for i in 0..defs.len() {
                if done[i] || deps[i].iter().any(|&j| !done[j]) {
                    continue;
                }
                done[i] = true;
                progress = true;
                if let Some(v) = self.eval_ground(&defs[i].1.value) {
                    self.consts.insert(defs[i].1.name.clone(), v);
                }
            }
            if !progress {
                break;
            }
        }
        // What is left lies on a cycle or depends on one; report each cycle once, at its first
        // definition, with the others as notes (last first, as gringo lists them).
        let left: Vec<usize> = (0..defs.len()).filter(|&i| !done[i]).collect();
        let reach = |from: usize| -> Vec<bool> {
            let mut seen = vec![false; defs.len()];
            let mut stack = vec![from];
            while let Some(k) = stack.pop() {
                for &j in &deps[k] {
                    if !seen[j] {
                        seen[j] = true;
                        stack.push(j);
                    }
                }
            }
            seen
        };
        let reaches: Vec<Vec<bool>> = (0..defs.len())
            .map(|i| if done[i] { Vec::new() } else { reach(i) })
            .collect();
        let mut reported = vec![false; defs.len()];
        for &i in &left {
            if reported[i] || !reaches[i][i] {
                continue;
            }
            let cycle: Vec<usize> = left
                .iter()
                .copied()
                .filter(|&j| reaches[i][j] && reaches[j][i])
                .collect();
            let mut d = Diagnostic::error(defs[i].0, "cyclic constant definition")
                .with_snippet(self.snippet(defs[i].0));
            for &j in cycle.iter().rev().filter(|&&j| j != i) {
                d = d.with_note(
                    Some(defs[j].0),
                    format!("cycle involves definition:\n  {}", self.snippet(defs[j].0)),
                );
            }
            for j in cycle {
                reported[j] = true;
            }
            self.diags.push(d);
        }
    }

    /// The `weight@priority, terms` tuple that weak constraints and `#minimize`/`#maximize`
    /// elements share, as a [`NKind::Minimize`] (priority 0 when omitted); `None` when the
    /// weight or the priority does not compile (a term that does not compile is left out, its
    /// error already reported).
    fn minimize_kind(
        &mut self,
        (weight, priority, terms): (&ast::Term, Option<&ast::Term>, &[ast::Term]),
        maximize: bool,
        vars: &mut Vars,
        extra: &mut Vec<NLit>,
    ) -> Option<NKind> {
        let weight = self.term(weight, vars, extra)?;
        let priority = match priority {
            Some(p) => self.term(p, vars, extra)?,
            None => NTerm::Sym(self.syms.int(0)),
        };
        let terms = terms
            .iter()
            .filter_map(|t| self.term(t, vars, extra))
            .collect();
        Some(NKind::Minimize {
            weight,
            priority,
            terms,
            maximize,
        })
    }

    fn sig_pred(&mut self, s: &ast::Signature) -> PredId {
        self.pred(&s.name, s.arity, s.negated)
    }

    fn statement(&mut self, index: u32, st: &ast::Statement) {
        use ast::StatementKind as K;
        self.current = (index, st.span);
        match &st.kind {
            K::Rule(r) => self.rule(index, st.span, r),
            K::WeakConstraint(w) => {
                for body in unpool_body(&w.body) {
                    let mut vars = Vars::default();
                    let mut out = Vec::new();
                    let mut extra = Vec::new();
                    let cost = (&w.weight, w.priority.as_ref(), &w.terms[..]);
                    let Some(kind) = self.minimize_kind(cost, false, &mut vars, &mut extra) else {
                        continue;
                    };
                    if self.body(&body, &mut vars, &mut out).is_none() {
                        continue;
                    }
                    out.append(&mut extra);
                    self.finish(index, st.span, NHead::None, out, kind, vars);
                }
            }
            K::Optimize(o) => {
                for e in &o.elements {
                    for cond in product(e.condition.iter().map(unpool_literal).collect()) {
                        let mut vars = Vars::default();
                        let mut out = Vec::new();
                        let mut extra = Vec::new();
                        let cost = (&e.weight, e.priority.as_ref(), &e.terms[..]);
                        let Some(kind) =
                            self.minimize_kind(cost, o.maximize, &mut vars, &mut extra)
                        else {
                            continue;
                        };
                        if self.condition(&cond, &mut vars, &mut out).is_none() {
                            continue;
                        }
                        out.append(&mut extra);
                        self.finish(index, e.span, NHead::None, out, kind, vars);
                    }
                }
            }
            K::Show(show) => match &**show {
                ast::Show::Nothing => self.out.show.restricted = true,
                ast::Show::Signature(s) => {
                    self.out.show.restricted = true;
                    let p = self.sig_pred(s);
                    let pred = self.out.preds[p as usize].clone();
                    self.out.show.signatures.push(pred);
                }
                ast::Show::Term { term, body } => {
                    for t in unpool_term(term) {
                        for b in unpool_body(body) {
                            let mut vars = Vars::default();
                            let mut out = Vec::new();
                            let mut extra = Vec::new();
                            let Some(t) = self.term(&t, &mut vars, &mut extra) else {
                                continue;
                            };
                            if self.body(&b, &mut vars, &mut out).is_none() {
                                continue;
                            }
                            out.append(&mut extra);
                            self.finish(index, st.span, NHead::None, out, NKind::Show(t), vars);
                        }
                    }
                }
            },
            K::Defined(s) => {
                let p = self.sig_pred(s);
                self.out.defined.push(p);
            }
            K::Project(project) => match &**project {
                ast::Project::Signature(s) => {
                    let p = self.sig_pred(s);
                    self.out.project_sigs.push(p);
                }
                ast::Project::Atom { atom, body } => {
                    for a in unpool_atom(atom) {
                        for b in unpool_body(body) {
                            let mut vars = Vars::default();
                            let mut out = Vec::new();
                            let mut extra = Vec::new();
                            let Some(a) = self.atom(&a, &mut vars, &mut extra) else {
                                continue;
                            };
                            if self.body(&b, &mut vars, &mut out).is_none() {
                                continue;
                            }
                            // The atom ranges over its predicate's possible atoms and binds the
                            // variables it alone has, as in gringo: `#project p(X).` projects
                            // onto every p/1 atom.
                            out.push(NLit::Pred {
                                sign: Sign::Positive,
                                atom: a.clone(),
                            });
                            out.append(&mut extra);
                            self.finish(index, st.span, NHead::None, out, NKind::Project(a), vars);
                        }
                    }
                }
            },
            K::External(e) => {
                for a in unpool_atom(&e.atom) {
                    for b in unpool_body(&e.body) {
                        let mut vars = Vars::default();
                        let mut out = Vec::new();
                        let mut extra = Vec::new();
                        let Some(a) = self.atom(&a, &mut vars, &mut extra) else {
                            continue;
                        };
                        // The value is a term of the instance (`[X]`); omitted, it is false.
                        let value = match &e.value {
                            Some(t) => match self.term(t, &mut vars, &mut extra) {
                                Some(v) => v,
                                None => continue,
                            },
                            None => NTerm::Sym(self.syms.fun_str("false", false, &[])),
                        };
                        if self.body(&b, &mut vars, &mut out).is_none() {
                            continue;
                        }
                        out.append(&mut extra);
                        self.finish(
                            index,
                            st.span,
                            NHead::None,
                            out,
                            NKind::External(a, value),
                            vars,
                        );
                    }
                }
            }
            K::Heuristic(h) => {
                for a in unpool_atom(&h.atom) {
                    for b in unpool_body(&h.body) {
                        let mut vars = Vars::default();
                        let mut out = Vec::new();
                        let mut extra = Vec::new();
                        let Some(a) = self.atom(&a, &mut vars, &mut extra) else {
                            continue;
                        };
                        let Some(weight) = self.term(&h.weight, &mut vars, &mut extra) else {
                            continue;
                        };
                        let priority = match &h.priority {
                            Some(p) => self.term(p, &mut vars, &mut extra),
                            None => Some(NTerm::Sym(self.syms.int(0))),
                        };
                        let Some(priority) = priority else { continue };
                        let Some(modifier) = self.term(&h.modifier, &mut vars, &mut extra) else {
                            continue;
                        };
                        if self.body(&b, &mut vars, &mut out).is_none() {
                            continue;
                        }
                        out.append(&mut extra);
                        let kind = NKind::Heuristic {
                            atom: a,
                            weight,
                            priority,
                            modifier,
                        };
                        self.finish(index, st.span, NHead::None, out, kind, vars);
                    }
                }
            }
            K::Edge(e) => {
                for from in unpool_term(&e.from) {
                    for to in unpool_term(&e.to) {
                        for b in unpool_body(&e.body) {
                            let mut vars = Vars::default();
                            let mut out = Vec::new();
                            let mut extra = Vec::new();
                            let (Some(u), Some(v)) = (
                                self.term(&from, &mut vars, &mut extra),
                                self.term(&to, &mut vars, &mut extra),
                            ) else {
                                continue;
                            };
                            if self.body(&b, &mut vars, &mut out).is_none() {
                                continue;
                            }
                            out.append(&mut extra);
                            self.finish(index, st.span, NHead::None, out, NKind::Edge(u, v), vars);
                        }
                    }
                }
            }
            K::Include(_) => {
                self.diags.push(Diagnostic::error(
                    st.span,
                    "#include must be resolved before grounding (ground::include::resolve_includes)",
                ));
            }
            K::Script(_) => self.unsupported(st.span, "#script is not supported by Lucent"),
            K::Const(_) | K::ProgramPart(_) | K::Error => {}
            K::Section(_)
            | K::SortDef(_)
            | K::PredicateDecl(_)
            | K::Display(_)
            | K::DisplaySort(_)
            | K::MaxInt(_) => {
                self.unsupported(st.span, "SPARC sections in a clingo-dialect program");
            }
        }
    }

    fn rule(&mut self, index: u32, span: Span, r: &ast::Rule) {
        // Most rules have no pools: no copy then.
        if pool_free_rule(r) {
            self.rule_instance(index, span, &r.head, &r.body, &r.kind);
            return;
        }
        // Unfold pools of the head and body into separate rules.
        let heads: Vec<ast::Head> = match &r.head {
            // A plain element's alternatives are separate rules; an element written with a
            // colon keeps its literal's pools (a conjunction, see `head_elem`) and its
            // condition's alternatives become further elements of the same disjunction.
            ast::Head::Disjunction(elems) => product(
                elems
                    .iter()
                    .map(|e| {
                        if e.has_colon {
                            vec![unpool_condition(e)]
                        } else {
                            unpool_cond(e).into_iter().map(|c| vec![c]).collect()
                        }
                    })
                    .collect(),
            )
            .into_iter()
            .map(|es: Vec<Vec<ast::ConditionalLiteral>>| ast::Head::Disjunction(es.concat()))
            .collect(),
            // Alternatives of the guards are separate rules (each bound must hold).
            ast::Head::Choice(c) => {
                let mut c = c.clone();
                c.elements = c.elements.iter().flat_map(unpool_cond).collect();
                let mut out = Vec::new();
                for lower in unpool_guard(&c.lower) {
                    for upper in unpool_guard(&c.upper) {
                        let mut c = c.clone();
                        c.lower = lower.clone();
                        c.upper = upper;
                        out.push(ast::Head::Choice(c));
                    }
                }
                out
            }
            ast::Head::Aggregate(h) => {
                let mut h = h.clone();
                h.elements = h
                    .elements
                    .iter()
                    .flat_map(|e| {
                        unpool_list(&e.terms)
                            .into_iter()
                            .map(|terms| ast::HeadAggregateElement { terms, ..e.clone() })
                            .collect::<Vec<_>>()
                    })
                    .collect();
                let mut out = Vec::new();
                for lower in unpool_guard(&h.lower) {
                    for upper in unpool_guard(&h.upper) {
                        let mut h = h.clone();
                        h.lower = lower.clone();
                        h.upper = upper;
                        out.push(ast::Head::Aggregate(h));
                    }
                }
                out
            }
            h => vec![h.clone()],
        };
        for head in &heads {
            for body in unpool_body(&r.body) {
                self.rule_instance(index, span, head, &body, &r.kind);
            }
        }
    }

    fn rule_instance(
        &mut self,
        index: u32,
        span: Span,
        head: &ast::Head,
        body: &[ast::BodyLiteral],
        kind: &ast::RuleKind,
    ) {
        let mut vars = Vars::default();
        let mut out = Vec::new();
        let mut extra = Vec::new();
        let kind = match kind {
            ast::RuleKind::Normal => NKind::Rule,
            ast::RuleKind::ConsistencyRestoring { label } => match label {
                None => NKind::Cr(None),
                Some(l) => {
                    let ls = unpool_term(l);
                    let Some(t) = self.term(&ls[0], &mut vars, &mut extra) else {
                        return;
                    };
                    NKind::Cr(Some(t))
                }
            },
        };
        let head_ast = head;
        let head = match head {
            ast::Head::None => NHead::None,
            ast::Head::Disjunction(elems) => {
                // `#false` alone is a constraint; `#true` alone makes the rule void.
                if elems.len() == 1 && elems[0].condition.is_empty() {
                    match elems[0].literal.atom {
                        ast::Atom::Boolean(false) if elems[0].literal.sign == Sign::Positive => {
                            return self.rule_instance(
                                index,
                                span,
                                &ast::Head::None,
                                body,
                                &ast::RuleKind::Normal,
                            );
                        }
                        ast::Atom::Boolean(_) => {
                            self.unsupported(elems[0].span, "this head literal");
                            return;
                        }
                        _ => {}
                    }
                }
                // h | not a :- B.  ==  h :- B, not not a.   (and `not not a` moves as `not a`);
                // likewise a comparison: h | X < 3 :- B.  ==  h :- B, not X < 3.
                let moves = |e: &ast::ConditionalLiteral| {
                    !e.has_colon
                        && (e.literal.sign != Sign::Positive
                            || matches!(e.literal.atom, ast::Atom::Comparison { .. }))
                };
                if elems.iter().any(moves) {
                    let mut keep = Vec::new();
                    let mut nbody = body.to_vec();
                    for e in elems {
                        if moves(e) {
                            let mut l = e.literal.clone();
                            l.sign = negate_sign(l.sign);
                            nbody.push(ast::BodyLiteral::Literal(l));
                        } else {
                            keep.push(e.clone());
                        }
                    }
                    let head = if keep.is_empty() {
                        ast::Head::None
                    } else {
                        ast::Head::Disjunction(keep)
                    };
                    let kind = match &kind {
                        NKind::Cr(_) => {
                            return self.unsupported(span, "default negation in CR rule heads")
                        }
                        _ => ast::RuleKind::Normal,
                    };
                    return self.rule_instance(index, span, &head, &nbody, &kind);
                }
                let mut es = Vec::new();
                for e in elems {
                    // An element with a colon whose literal is false (`#false`, `not #true`) never
                    // holds; gringo reads a comparison there the same way.
                    if e.has_colon
                        && match &e.literal.atom {
                            ast::Atom::Boolean(b) => *b == (e.literal.sign == Sign::Not),
                            ast::Atom::Comparison { .. } => true,
                            _ => false,
                        }
                    {
                        continue;
                    }
                    let e = if e.has_colon {
                        self.disj_elem(e, &mut vars)
                    } else {
                        self.head_elem(e, &mut vars, &mut extra)
                    };
                    let Some(e) = e else {
                        return;
                    };
                    es.push(e);
                }
                NHead::Disj(es)
            }
            ast::Head::Choice(c) => {
                let mut es = Vec::new();
                for e in &c.elements {
                    let Some(e) = self.head_elem(e, &mut vars, &mut extra) else {
                        return;
                    };
                    es.push(e);
                }
                if lower_upper(&c.lower, &c.upper) {
                    // l { e } u :- B.  ==  { e } :- B.  and  :- B, not l #count{ e } u.
                    let agg = ast::BodyAggregate {
                        span: c.span,
                        function: AggregateFunction::Count,
                        lower: c.lower.clone(),
                        elements: Vec::new(),
                        set_syntax: c.elements.iter().flat_map(unpool_cond).collect(),
                        upper: c.upper.clone(),
                    };
                    let mut cbody = body.to_vec();
                    cbody.push(ast::BodyLiteral::Aggregate {
                        sign: Sign::Not,
                        aggregate: Box::new(agg),
                    });
                    let role = self.aux_role.replace(AuxKind::Bound);
                    self.rule_instance(
                        index,
                        span,
                        &ast::Head::None,
                        &cbody,
                        &ast::RuleKind::Normal,
                    );
                    self.aux_role = role;
                }
                NHead::Choice(es)
            }
            ast::Head::Aggregate(h) => {
                // l #f { w,t : a : c } u :- B.  ==  { a : c } :- B.  and
                // :- B, not l #f { w,t,a : a, c } u.
                let mut es = Vec::new();
                let mut elements = Vec::new();
                for e in &h.elements {
                    let ce = ast::ConditionalLiteral {
                        span: e.span,
                        literal: e.literal.clone(),
                        condition: e.condition.clone(),
                        has_colon: !e.condition.is_empty(),
                    };
                    for ce in unpool_cond(&ce) {
                        let Some(mut n) = self.head_elem(&ce, &mut vars, &mut extra) else {
                            return;
                        };
                        if !self.tuple_checks(h.function, &e.terms, &mut vars, &mut n.cond) {
                            continue;
                        }
                        es.push(n);
                        let mut condition = vec![ce.literal.clone()];
                        condition.extend(ce.condition.iter().cloned());
                        let mut terms = e.terms.clone();
                        if let ast::Atom::Symbolic(sa) = &ce.literal.atom {
                            terms.push(atom_as_term(sa));
                        }
                        elements.push(ast::BodyAggregateElement {
                            span: e.span,
                            terms,
                            condition,
                        });
                    }
                }
                if lower_upper(&h.lower, &h.upper) {
                    let agg = ast::BodyAggregate {
                        span: h.span,
                        function: h.function,
                        lower: h.lower.clone(),
                        elements,
                        set_syntax: Vec::new(),
                        upper: h.upper.clone(),
                    };
                    let mut cbody = body.to_vec();
                    cbody.push(ast::BodyLiteral::Aggregate {
                        sign: Sign::Not,
                        aggregate: Box::new(agg),
                    });
                    let role = self.aux_role.replace(AuxKind::Bound);
                    self.rule_instance(
                        index,
                        span,
                        &ast::Head::None,
                        &cbody,
                        &ast::RuleKind::Normal,
                    );
                    self.aux_role = role;
                }
                NHead::Choice(es)
            }
        };
        if self.body(body, &mut vars, &mut out).is_none() {
            return;
        }
        // A choice whose bounds are undefined (say `X+1` with X=a) is dropped with them: the
        // bounds are evaluated in its body as `t = t`.
        let guards: Vec<&ast::Guard> = match head_ast {
            ast::Head::Choice(c) => c.lower.iter().chain(c.upper.iter()).collect(),
            ast::Head::Aggregate(h) => h.lower.iter().chain(h.upper.iter()).collect(),
            _ => Vec::new(),
        };
        for g in guards {
            if let Some(t) = self.term(&g.term, &mut vars, &mut extra) {
                if !matches!(t, NTerm::Sym(_)) {
                    out.push(NLit::Cmp {
                        op: CmpOp::Eq,
                        lhs: t.clone(),
                        rhs: t,
                    });
                }
            }
        }
        out.append(&mut extra);
        self.finish(index, span, head, out, kind, vars);
    }

    /// Plans the body and element conditions, checks safety, and records the statement.
    fn finish(
        &mut self,
        index: u32,
        span: Span,
        mut head: NHead,
        body: Vec<NLit>,
        kind: NKind,
        vars: Vars,
    ) {
        let n = vars.names.len();
        // Global variables: those outside aggregate elements and head conditions.
        let mut global = vec![false; n];
        let mark = |t: &NTerm, g: &mut Vec<bool>| {
            let mut vs = Vec::new();
            t.vars(&mut vs);
            for v in vs {
                g[v as usize] = true;
            }
        };
        for l in &body {
            match l {
                NLit::Agg(a) => a.guards.iter().for_each(|(_, t)| mark(t, &mut global)),
                other => {
                    let mut vs = Vec::new();
                    lit_vars(other, &mut vs);
                    for v in vs {
                        global[v as usize] = true;
                    }
                }
            }
        }
        match &head {
            NHead::Disj(es) | NHead::Choice(es) => {
                for e in es.iter().filter(|e| e.cond.is_empty() && e.conj.is_empty()) {
                    e.atom.args.iter().for_each(|t| mark(t, &mut global));
                }
            }
            NHead::None => {}
        }
        match &kind {
            NKind::Rule | NKind::Cr(None) => {}
            NKind::Cr(Some(t)) | NKind::Show(t) => mark(t, &mut global),
            NKind::Minimize {
                weight,
                priority,
                terms,
                ..
            } => {
                mark(weight, &mut global);
                mark(priority, &mut global);
                terms.iter().for_each(|t| mark(t, &mut global));
            }
            NKind::Project(a) => a.args.iter().for_each(|t| mark(t, &mut global)),
            NKind::External(a, value) => {
                a.args.iter().for_each(|t| mark(t, &mut global));
                mark(value, &mut global);
            }
            NKind::Heuristic {
                atom,
                weight,
                priority,
                modifier,
            } => {
                atom.args.iter().for_each(|t| mark(t, &mut global));
                mark(weight, &mut global);
                mark(priority, &mut global);
                mark(modifier, &mut global);
            }
            NKind::Edge(u, v) => {
                mark(u, &mut global);
                mark(v, &mut global);
            }
        }
        // Global variables occurring only in elements of several aggregates are still local to
        // each; a variable is global iff marked above.
        let mut bound = vec![false; n];
        let mut unsafe_vars: Vec<u32> = Vec::new();
        let body = plan(body, &mut bound, &global, &mut unsafe_vars);
        for (v, g) in global.iter().enumerate() {
            if *g && !bound[v] && !unsafe_vars.contains(&(v as u32)) {
                unsafe_vars.push(v as u32);
            }
        }
        match &mut head {
            NHead::Disj(es) | NHead::Choice(es) => {
                for e in es.iter_mut() {
                    let mut b = bound.clone();
                    let cond = std::mem::take(&mut e.cond);
                    e.cond = plan(cond, &mut b, &global, &mut unsafe_vars);
                    let mut vs = Vec::new();
                    if e.conj.is_empty() {
                        e.atom.args.iter().for_each(|t| t.vars(&mut vs));
                    }
                    for l in &mut e.conj {
                        let mut bl = b.clone();
                        let expand = std::mem::take(&mut l.expand);
                        l.expand = plan(expand, &mut bl, &global, &mut unsafe_vars);
                        let mut lv = Vec::new();
                        l.atom.args.iter().for_each(|t| t.vars(&mut lv));
                        vs.extend(lv.into_iter().filter(|&v| !bl[v as usize]));
                    }
                    for v in vs {
                        if !b[v as usize] && !unsafe_vars.contains(&v) {
                            unsafe_vars.push(v);
                        }
                    }
                }
            }
            NHead::None => {}
        }
        if !unsafe_vars.is_empty() {
            unsafe_vars.sort_by_key(|&v| (vars.spans[v as usize].start, v));
            let mut d =
                Diagnostic::error(span, "unsafe variables in").with_snippet(self.snippet(span));
            for v in unsafe_vars {
                let name = &vars.names[v as usize];
                let shown = if name.starts_with("#Anon") {
                    "_".to_string()
                } else {
                    name.clone()
                };
                d = d.with_note(Some(vars.spans[v as usize]), format!("'{shown}' is unsafe"));
            }
            self.diags.push(d);
            return;
        }
        let var_names = vars
            .names
            .iter()
            .map(|s| self.syms.names.intern(s))
            .collect();
        let globals = (0..n as u32).filter(|&v| global[v as usize]).collect();
        self.out.stmts.push(NStmt {
            stmt: index,
            span,
            head,
            body,
            kind,
            num_vars: n as u32,
            var_names,
            globals,
            aux: self.aux_role,
        });
    }
}

/// The constant names (candidates for `#const` values) in a term.
fn const_names<'t>(t: &'t ast::Term, out: &mut Vec<&'t str>) {
    match &t.kind {
        TermKind::Constant(c) => out.push(c),
        TermKind::Function { args, .. } => args.iter().flatten().for_each(|a| const_names(a, out)),
        TermKind::ScriptCall { args, .. } => args.iter().for_each(|a| const_names(a, out)),
        TermKind::Pool(ts) => ts.iter().for_each(|a| const_names(a, out)),
        TermKind::Unary { arg, .. } | TermKind::Paren(arg) => const_names(arg, out),
        TermKind::Binary { lhs, rhs, .. } => {
            const_names(lhs, out);
            const_names(rhs, out);
        }
        TermKind::Interval { lo, hi } => {
            const_names(lo, out);
            const_names(hi, out);
        }
        TermKind::Integer(_)
        | TermKind::String(_)
        | TermKind::Variable(_)
        | TermKind::Anonymous
        | TermKind::Infimum
        | TermKind::Supremum => {}
    }
}

/// True when an argument of the literal's atom is the anonymous variable.
fn has_anonymous_arg(l: &ast::Literal) -> bool {
    match &l.atom {
        ast::Atom::Symbolic(a) => a
            .args
            .iter()
            .flatten()
            .any(|t| matches!(t.kind, TermKind::Anonymous)),
        _ => false,
    }
}

/// Adds the variables of a literal (for aggregates: of guards and elements) to `out`.
pub fn lit_vars(l: &NLit, out: &mut Vec<u32>) {
    match l {
        NLit::Pred { atom, .. } => atom.args.iter().for_each(|t| t.vars(out)),
        NLit::Cmp { lhs, rhs, .. } => {
            lhs.vars(out);
            rhs.vars(out)
        }
        NLit::Interval { pat, lo, hi } => {
            pat.vars(out);
            lo.vars(out);
            hi.vars(out)
        }
        NLit::Bool(_) => {}
        NLit::Agg(a) => {
            a.guards.iter().for_each(|(_, t)| t.vars(out));
            for e in &a.elems {
                e.terms.iter().for_each(|t| t.vars(out));
                e.cond.iter().for_each(|c| lit_vars(c, out));
                e.lit_lits().for_each(|l| lit_vars(l, out));
            }
        }
    }
}

/// How eagerly a literal should be placed next given the bound variables; `None` when it
/// cannot be evaluated yet. Lower is earlier.
fn readiness(l: &mut NLit, bound: &[bool], global: &[bool], newly: &mut Vec<u32>) -> Option<u32> {
    newly.clear();
    match l {
        NLit::Bool(_) => Some(0),
        NLit::Pred { sign, atom } => {
            if *sign == Sign::Positive {
                for t in &atom.args {
                    if !t.binds(bound, newly) {
                        return None;
                    }
                }
                Some(if newly.is_empty() {
                    1
                } else {
                    10 + newly.len() as u32
                })
            } else if atom.args.iter().all(|t| t.bound_by(bound)) {
                Some(1)
            } else {
                None
            }
        }
        NLit::Cmp { op, lhs, rhs } => {
            let (lb, rb) = (lhs.bound_by(bound), rhs.bound_by(bound));
            if lb && rb {
                Some(1)
            } else if *op == CmpOp::Eq
                && ((rb && lhs.binds(bound, newly)) || (lb && rhs.binds(bound, newly)))
            {
                Some(2)
            } else {
                None
            }
        }
        NLit::Interval { pat, lo, hi } => {
            if lo.bound_by(bound) && hi.bound_by(bound) && pat.binds(bound, newly) {
                Some(3)
            } else {
                None
            }
        }
        NLit::Agg(a) => {
            // Every global variable of the elements must be bound first.
            for e in &a.elems {
                let mut vs = Vec::new();
                e.terms.iter().for_each(|t| t.vars(&mut vs));
                e.cond.iter().for_each(|c| lit_vars(c, &mut vs));
                e.lit_lits().for_each(|l| lit_vars(l, &mut vs));
                if vs.iter().any(|&v| global[v as usize] && !bound[v as usize]) {
                    return None;
                }
            }
            a.binder = None;
            for (i, (op, t)) in a.guards.iter().enumerate() {
                if t.bound_by(bound) {
                    continue;
                }
                if *op == CmpOp::Eq && a.sign == Sign::Positive && a.binder.is_none() {
                    // `X = #agg{...}`, and as in gringo any term matching can bind, such as
                    // the linear `X+1 = #min{...}` (a value it cannot match is skipped).
                    let mut vs = Vec::new();
                    if t.binds(bound, &mut vs) && !vs.is_empty() {
                        a.binder = Some(i);
                        newly.extend(vs);
                        continue;
                    }
                }
                return None;
            }
            Some(if a.binder.is_some() { 50 } else { 40 })
        }
    }
}

/// Orders `lits` so each is evaluable when reached, marking what they bind in `bound`; the
/// variables of literals that can never be placed are added to `unsafe_vars`, and those
/// literals dropped (the statement is then reported and discarded).
pub fn plan(
    mut lits: Vec<NLit>,
    bound: &mut [bool],
    global: &[bool],
    unsafe_vars: &mut Vec<u32>,
) -> Vec<NLit> {
    let mut out = Vec::with_capacity(lits.len());
    let mut newly = Vec::new();
    while !lits.is_empty() {
        let mut best: Option<(u32, usize)> = None;
        for (i, lit) in lits.iter_mut().enumerate() {
            if let Some(score) = readiness(lit, bound, global, &mut newly) {
                if best.is_none_or(|(s, _)| score < s) {
                    best = Some((score, i));
                }
            }
        }
        let Some((_, i)) = best else {
            for l in &lits {
                let mut vs = Vec::new();
                lit_vars(l, &mut vs);
                for v in vs {
                    if !bound[v as usize]
                        && (global[v as usize] || !matches!(l, NLit::Agg(_)))
                        && !unsafe_vars.contains(&v)
                    {
                        unsafe_vars.push(v);
                    }
                }
            }
            return out;
        };
        let mut l = lits.remove(i);
        readiness(&mut l, bound, global, &mut newly);
        for &v in &newly {
            bound[v as usize] = true;
        }
        // Plan aggregate element conditions with the global variables bound so far.
        if let NLit::Agg(a) = &mut l {
            for e in &mut a.elems {
                let mut b = bound.to_vec();
                let cond = std::mem::take(&mut e.cond);
                e.cond = plan(cond, &mut b, global, unsafe_vars);
                let mut vs = Vec::new();
                e.terms.iter().for_each(|t| t.vars(&mut vs));
                // Each alternative of a conditional literal may bind its own local variables.
                for alt in e.lit.iter_mut().flatten() {
                    let mut ba = b.clone();
                    *alt = plan(std::mem::take(alt), &mut ba, global, unsafe_vars);
                    let mut av = Vec::new();
                    alt.iter().for_each(|l| lit_vars(l, &mut av));
                    vs.extend(av.into_iter().filter(|&v| !ba[v as usize]));
                }
                for v in vs {
                    if !b[v as usize] && !unsafe_vars.contains(&v) {
                        unsafe_vars.push(v);
                    }
                }
            }
        }
        out.push(l);
    }
    out
}
