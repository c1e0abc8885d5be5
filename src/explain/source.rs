//! The program as written, evaluated over an answer set, for the generic `--why`/`--why-not`
//! (issue 32): statements matched against ground atoms, bodies joined over the answer set's
//! true atoms, body aggregates evaluated to their value and the elements that make it up.
//! Grounding removes what it decides (an aggregate it evaluated, the instances whose body
//! could never hold) and adds internal atoms; this module reads the source statement instead,
//! so an explanation can name what the user wrote.
//!
//! Invariants: evaluation reads only the statements and the [`World`] (the answer set's true
//! atoms, possibly with one atom added to ask "what if it held"); terms it cannot evaluate
//! (pools, intervals, script calls, unbound arithmetic) make a literal unknown, never a panic;
//! every join is bounded ([`MAX_INSTANCES`] completed or blocked instances).

use std::collections::{HashMap, HashSet};

use crate::control::Symbol;
use crate::syntax::ast::{
    self, AggregateFunction, BinaryOp, CmpOp, Sign, SymbolicAtom, Term, TermKind, UnaryOp,
};
use crate::syntax::printer;

/// Most instances a join reports (completed and blocked together).
pub const MAX_INSTANCES: usize = 64;

/// Variable values: (variable name, value), in the order they were bound.
pub type Bindings = Vec<(String, Symbol)>;

/// The atoms that hold: an answer set's true atoms, indexed by predicate.
#[derive(Clone, Debug, Default)]
pub struct World {
    set: HashSet<Symbol>,
    by_pred: HashMap<(String, usize, bool), Vec<Symbol>>,
}

fn pred_key(s: &Symbol) -> Option<(String, usize, bool)> {
    match s {
        Symbol::Function {
            name,
            args,
            negative,
        } => Some((name.as_str().to_string(), args.len(), *negative)),
        _ => None,
    }
}

impl World {
    /// The world where exactly `atoms` hold.
    pub fn new(atoms: impl IntoIterator<Item = Symbol>) -> World {
        let mut w = World::default();
        for a in atoms {
            w.add(a);
        }
        w
    }

    /// Makes `atom` hold too.
    pub fn add(&mut self, atom: Symbol) {
        if self.set.insert(atom.clone()) {
            if let Some(k) = pred_key(&atom) {
                self.by_pred.entry(k).or_default().push(atom);
            }
        }
    }

    /// Whether `atom` holds.
    pub fn holds(&self, atom: &Symbol) -> bool {
        self.set.contains(atom)
    }

    fn of_pred(&self, a: &SymbolicAtom, arity: usize) -> &[Symbol] {
        self.by_pred
            .get(&(a.name.as_str().to_string(), arity, a.negated))
            .map(Vec::as_slice)
            .unwrap_or(&[])
    }
}

fn lookup<'b>(b: &'b Bindings, name: &str) -> Option<&'b Symbol> {
    b.iter().find(|(n, _)| n == name).map(|(_, v)| v)
}

/// The value of `t` under `b`, when it is ground and evaluates.
pub fn eval(t: &Term, b: &Bindings) -> Option<Symbol> {
    match &t.kind {
        TermKind::Integer(i) => i32::try_from(*i).ok().map(Symbol::Number),
        TermKind::String(s) => Some(Symbol::string(s.clone())),
        TermKind::Constant(c) => Some(Symbol::constant(c.as_str())),
        TermKind::Variable(v) => lookup(b, v.as_str()).cloned(),
        TermKind::Infimum => Some(Symbol::Inf),
        TermKind::Supremum => Some(Symbol::Sup),
        TermKind::Paren(x) => eval(x, b),
        TermKind::Function { name, args, .. } if args.len() == 1 => {
            let vals = args[0]
                .iter()
                .map(|a| eval(a, b))
                .collect::<Option<Vec<_>>>()?;
            Some(if name.as_str().is_empty() {
                Symbol::tuple(vals)
            } else {
                Symbol::function(name.as_str(), vals)
            })
        }
        TermKind::Unary { op, arg } => {
            let v = eval(arg, b)?;
            match (op, v) {
                (UnaryOp::Minus, Symbol::Number(n)) => n.checked_neg().map(Symbol::Number),
                (UnaryOp::Abs, Symbol::Number(n)) => n.checked_abs().map(Symbol::Number),
                (UnaryOp::BitNot, Symbol::Number(n)) => Some(Symbol::Number(!n)),
                (UnaryOp::Minus, s @ Symbol::Function { .. }) => s.complement(),
                _ => None,
            }
        }
        TermKind::Binary { op, lhs, rhs } => {
            let (l, r) = (eval(lhs, b)?.as_number()?, eval(rhs, b)?.as_number()?);
            let v = match op {
                BinaryOp::Add => l.checked_add(r),
                BinaryOp::Sub => l.checked_sub(r),
                BinaryOp::Mul => l.checked_mul(r),
                BinaryOp::Div => (r != 0).then(|| l.checked_div(r)).flatten(),
                BinaryOp::Mod => (r != 0).then(|| l.checked_rem(r)).flatten(),
                BinaryOp::Pow => u32::try_from(r).ok().and_then(|e| l.checked_pow(e)),
                BinaryOp::BitAnd => Some(l & r),
                BinaryOp::BitOr => Some(l | r),
                BinaryOp::BitXor => Some(l ^ r),
            };
            v.map(Symbol::Number)
        }
        _ => None,
    }
}

fn unify_in(t: &Term, s: &Symbol, b: &mut Bindings) -> bool {
    match &t.kind {
        TermKind::Anonymous => true,
        TermKind::Variable(v) => match lookup(b, v.as_str()) {
            Some(x) => x == s,
            None => {
                b.push((v.as_str().to_string(), s.clone()));
                true
            }
        },
        TermKind::Paren(x) => unify_in(x, s, b),
        TermKind::Function { name, args, .. } if args.len() == 1 => match s {
            Symbol::Function {
                name: n,
                args: sa,
                negative: false,
            } if n.as_str() == name.as_str() && sa.len() == args[0].len() => {
                args[0].iter().zip(sa).all(|(t, s)| unify_in(t, s, b))
            }
            _ => false,
        },
        _ => eval(t, b).as_ref() == Some(s),
    }
}

/// Matches the atom `a` (any alternative of a pool) against the ground atom `s`.
pub fn unify_atom(a: &SymbolicAtom, s: &Symbol, b: &mut Bindings) -> bool {
    let Symbol::Function {
        name,
        args,
        negative,
    } = s
    else {
        return false;
    };
    if name.as_str() != a.name.as_str() || *negative != a.negated {
        return false;
    }
    a.args.iter().any(|alt| {
        let mark = b.len();
        let ok = alt.len() == args.len() && alt.iter().zip(args).all(|(t, s)| unify_in(t, s, b));
        if !ok {
            b.truncate(mark);
        }
        ok
    })
}

/// The ground atom `a` under `b`, when every argument evaluates (first alternative of a pool).
pub fn ground_atom(a: &SymbolicAtom, b: &Bindings) -> Option<Symbol> {
    let args = a
        .args
        .first()
        .map(|alt| alt.iter().map(|t| eval(t, b)).collect::<Option<Vec<_>>>())
        .unwrap_or(Some(Vec::new()))?;
    let s = Symbol::function(a.name.as_str(), args);
    if a.negated {
        s.complement()
    } else {
        Some(s)
    }
}

/// `t` as text, bound variables written as their values.
pub fn show_term(t: &Term, b: &Bindings) -> String {
    if let Some(v) = eval(t, b) {
        return v.to_string();
    }
    match &t.kind {
        TermKind::Function { name, args, .. } if args.len() == 1 => {
            let inner: Vec<String> = args[0].iter().map(|a| show_term(a, b)).collect();
            format!("{name}({})", inner.join(","))
        }
        _ => {
            let mut s = String::new();
            printer::term(&mut s, t);
            s
        }
    }
}

/// The atom `a` as text, bound variables written as their values.
pub fn show_atom(a: &SymbolicAtom, b: &Bindings) -> String {
    let neg = if a.negated { "-" } else { "" };
    match a.args.first() {
        Some(alt) if !alt.is_empty() => {
            let inner: Vec<String> = alt.iter().map(|t| show_term(t, b)).collect();
            format!("{neg}{}({})", a.name, inner.join(","))
        }
        _ => format!("{neg}{}", a.name),
    }
}

pub fn cmp_words(op: CmpOp) -> &'static str {
    match op {
        CmpOp::Eq => "=",
        CmpOp::Ne => "!=",
        CmpOp::Lt => "<",
        CmpOp::Le => "<=",
        CmpOp::Gt => ">",
        CmpOp::Ge => ">=",
    }
}

pub fn compare(l: &Symbol, op: CmpOp, r: &Symbol) -> bool {
    match op {
        CmpOp::Eq => l == r,
        CmpOp::Ne => l != r,
        CmpOp::Lt => l < r,
        CmpOp::Le => l <= r,
        CmpOp::Gt => l > r,
        CmpOp::Ge => l >= r,
    }
}

/// One body literal, as the join sees it.
#[derive(Clone, Copy, Debug)]
pub enum Lit<'a> {
    /// A positive atom (also `not not a`).
    Pos(&'a SymbolicAtom),
    /// A default-negated atom.
    Neg(&'a SymbolicAtom),
    /// A comparison `l op r`.
    Cmp(&'a Term, CmpOp, &'a Term),
    /// A body aggregate, default-negated when the flag is set.
    Agg(&'a ast::BodyAggregate, bool),
    /// Anything the join does not evaluate (conditional literals, `#true`, sorts): taken as
    /// holding.
    Other,
}

impl<'a> Lit<'a> {
    /// The join's view of a plain literal.
    pub fn of_literal(l: &'a ast::Literal) -> Lit<'a> {
        match (&l.atom, l.sign) {
            (ast::Atom::Symbolic(a), Sign::Not) => Lit::Neg(a),
            (ast::Atom::Symbolic(a), _) => Lit::Pos(a),
            (ast::Atom::Comparison { lhs, op, rhs }, Sign::Positive) => Lit::Cmp(lhs, *op, rhs),
            _ => Lit::Other,
        }
    }

    /// The join's view of a body literal.
    pub fn of_body(l: &'a ast::BodyLiteral) -> Lit<'a> {
        match l {
            ast::BodyLiteral::Literal(l) => Lit::of_literal(l),
            ast::BodyLiteral::Aggregate { sign, aggregate } => {
                Lit::Agg(aggregate, *sign == Sign::Not)
            }
            ast::BodyLiteral::Conditional(_) | ast::BodyLiteral::Theory { .. } => Lit::Other,
        }
    }
}

/// Why a body instance does not hold: its first literal that fails.
#[derive(Clone, Debug, PartialEq)]
pub enum Blocker {
    /// A positive atom that does not hold.
    False(Symbol),
    /// A positive atom with free variables that no true atom matches (as text, `r(1,_)`).
    NoMatch(String),
    /// `not a` with `a` true.
    Holds(Symbol),
    /// A comparison that is false (as text, bound variables as their values).
    Test(String),
    /// An aggregate whose bound is not met (or met, under `not`).
    Aggregate(Box<AggregateEval>, bool),
}

impl Blocker {
    /// The blocker in words ("r(1) does not hold").
    pub fn words(&self) -> String {
        match self {
            Blocker::False(a) => format!("{a} does not hold"),
            Blocker::NoMatch(p) => format!("no atom {p} holds"),
            Blocker::Holds(a) => format!("not {a} fails, as {a} holds"),
            Blocker::Test(t) => format!("{t} is false"),
            Blocker::Aggregate(e, false) => format!("{} is false: {}", e.text, e.tally()),
            Blocker::Aggregate(e, true) => format!("not {} fails: {}", e.text, e.tally()),
        }
    }

    /// The blocker as JSON: `literal` (text) and `reason`.
    pub fn to_json(&self) -> serde_json::Value {
        let (literal, reason) = match self {
            Blocker::False(a) => (a.to_string(), "false"),
            Blocker::NoMatch(p) => (p.clone(), "no_match"),
            Blocker::Holds(a) => (format!("not {a}"), "holds"),
            Blocker::Test(t) => (t.clone(), "false"),
            Blocker::Aggregate(e, neg) => {
                let mut v = serde_json::json!({
                    "literal": if *neg { format!("not {}", e.text) } else { e.text.clone() },
                    "reason": if *neg { "holds" } else { "false" },
                });
                v["aggregate"] = e.to_json();
                return v;
            }
        };
        serde_json::json!({"literal": literal, "reason": reason})
    }
}

/// One instance the join reached: complete (every literal holds) or blocked.
#[derive(Clone, Debug)]
pub struct Instance {
    /// The variable values.
    pub bindings: Bindings,
    /// The first failing literal, `None` when the body holds.
    pub blocker: Option<Blocker>,
}

/// Joins `lits` over `world` from bindings `b`: positive atoms first, in order, then the other
/// literals once ground; pushes each completed or blocked instance on `out`, at most
/// [`MAX_INSTANCES`] in all.
pub fn join(lits: &[Lit<'_>], b: Bindings, world: &World, out: &mut Vec<Instance>) {
    let mut order: Vec<usize> = (0..lits.len())
        .filter(|&i| matches!(lits[i], Lit::Pos(_)))
        .collect();
    order.extend((0..lits.len()).filter(|&i| !matches!(lits[i], Lit::Pos(_))));
    step(lits, &order, b, world, out);
}

fn step(
    lits: &[Lit<'_>],
    order: &[usize],
    mut b: Bindings,
    world: &World,
    out: &mut Vec<Instance>,
) {
    if out.len() >= MAX_INSTANCES {
        return;
    }
    let Some((&i, rest)) = order.split_first() else {
        out.push(Instance {
            bindings: b,
            blocker: None,
        });
        return;
    };
    let block = |b: Bindings, blocker: Blocker, out: &mut Vec<Instance>| {
        out.push(Instance {
            bindings: b,
            blocker: Some(blocker),
        })
    };
    match lits[i] {
        Lit::Pos(a) => {
            if let Some(g) = ground_atom(a, &b) {
                if world.holds(&g) {
                    step(lits, rest, b, world, out);
                } else {
                    block(b, Blocker::False(g), out);
                }
                return;
            }
            let arity = a.args.first().map_or(0, Vec::len);
            let mut any = false;
            for s in world.of_pred(a, arity) {
                if out.len() >= MAX_INSTANCES {
                    return;
                }
                let mut nb = b.clone();
                if unify_atom(a, s, &mut nb) {
                    any = true;
                    step(lits, rest, nb, world, out);
                }
            }
            if !any {
                let text = show_atom(a, &b);
                block(b, Blocker::NoMatch(text), out);
            }
        }
        Lit::Neg(a) => {
            let arity = a.args.first().map_or(0, Vec::len);
            let hit = world.of_pred(a, arity).iter().find(|s| {
                let mut nb = b.clone();
                unify_atom(a, s, &mut nb)
            });
            match hit {
                Some(s) => block(b, Blocker::Holds(s.clone()), out),
                None => step(lits, rest, b, world, out),
            }
        }
        Lit::Cmp(l, op, r) => {
            if let TermKind::Variable(v) = &l.kind {
                if op == CmpOp::Eq && lookup(&b, v.as_str()).is_none() {
                    if let Some(x) = eval(r, &b) {
                        b.push((v.as_str().to_string(), x));
                        return step(lits, rest, b, world, out);
                    }
                }
            }
            match (eval(l, &b), eval(r, &b)) {
                (Some(x), Some(y)) if !compare(&x, op, &y) => {
                    let text = format!("{x} {} {y}", cmp_words(op));
                    block(b, Blocker::Test(text), out);
                }
                _ => step(lits, rest, b, world, out),
            }
        }
        Lit::Agg(agg, negated) => match aggregate(agg, &b, world) {
            Some(e) if e.holds == negated => {
                block(b, Blocker::Aggregate(Box::new(e), negated), out)
            }
            _ => step(lits, rest, b, world, out),
        },
        Lit::Other => step(lits, rest, b, world, out),
    }
}

/// One element of an aggregate that counts: its tuple and the atoms of its condition that hold.
#[derive(Clone, Debug, PartialEq)]
pub struct Element {
    /// The element's tuple (`Q` = `ann`), as values.
    pub tuple: Vec<Symbol>,
    /// The condition's atoms that hold for it.
    pub atoms: Vec<Symbol>,
}

/// A body aggregate evaluated over a world.
#[derive(Clone, Debug, PartialEq)]
pub struct AggregateEval {
    /// The aggregate as written, bound variables as their values (`#count{Q: likes(Q,bob)} >= 3`).
    pub text: String,
    /// Its value.
    pub value: Symbol,
    /// Whether its bounds are met.
    pub holds: bool,
    /// The elements that count, one per distinct tuple.
    pub elements: Vec<Element>,
}

impl AggregateEval {
    /// The value and its elements in words ("3, from likes(ann,bob), likes(carl,bob)").
    pub fn tally(&self) -> String {
        if self.elements.is_empty() {
            return format!("its value is {}, from no element", self.value);
        }
        let atoms: Vec<String> = self
            .elements
            .iter()
            .map(|e| {
                let a: Vec<String> = e.atoms.iter().map(Symbol::to_string).collect();
                if a.is_empty() {
                    let t: Vec<String> = e.tuple.iter().map(Symbol::to_string).collect();
                    format!("({})", t.join(","))
                } else {
                    a.join(" and ")
                }
            })
            .collect();
        format!("its value is {}, from {}", self.value, atoms.join(", "))
    }

    /// As JSON: `aggregate`, `value`, `holds`, `elements` (`tuple`, `atoms`).
    pub fn to_json(&self) -> serde_json::Value {
        let elements: Vec<serde_json::Value> = self
            .elements
            .iter()
            .map(|e| {
                serde_json::json!({
                    "tuple": e.tuple.iter().map(Symbol::to_string).collect::<Vec<_>>(),
                    "atoms": e.atoms.iter().map(Symbol::to_string).collect::<Vec<_>>(),
                })
            })
            .collect();
        serde_json::json!({
            "aggregate": self.text,
            "value": self.value.to_string(),
            "holds": self.holds,
            "elements": elements,
        })
    }
}

fn lit_text(l: &ast::Literal, b: &Bindings) -> String {
    let sign = match l.sign {
        Sign::Positive => "",
        Sign::Not => "not ",
        Sign::NotNot => "not not ",
    };
    match &l.atom {
        ast::Atom::Symbolic(a) => format!("{sign}{}", show_atom(a, b)),
        ast::Atom::Comparison { lhs, op, rhs } => format!(
            "{sign}{} {} {}",
            show_term(lhs, b),
            cmp_words(*op),
            show_term(rhs, b)
        ),
        _ => {
            let mut s = String::new();
            printer::statement(
                &mut s,
                &ast::StatementKind::Rule(ast::Rule {
                    head: ast::Head::None,
                    body: vec![ast::BodyLiteral::Literal(l.clone())],
                    kind: ast::RuleKind::Normal,
                }),
            );
            s.trim_start_matches(":-")
                .trim()
                .trim_end_matches('.')
                .to_string()
        }
    }
}

/// Evaluates the body aggregate `agg` under `b` over `world`: its elements' conditions joined,
/// one element per distinct tuple. `None` when a guard or a tuple does not evaluate.
pub fn aggregate(agg: &ast::BodyAggregate, b: &Bindings, world: &World) -> Option<AggregateEval> {
    let mut elements: Vec<Element> = Vec::new();
    let mut texts = Vec::new();
    let mut add = |tuple: Vec<Symbol>, atoms: Vec<Symbol>| {
        if !elements.iter().any(|e| e.tuple == tuple) {
            elements.push(Element { tuple, atoms });
        }
    };
    for e in &agg.elements {
        let lits: Vec<Lit> = e.condition.iter().map(Lit::of_literal).collect();
        let mut out = Vec::new();
        join(&lits, b.clone(), world, &mut out);
        for inst in out.into_iter().filter(|i| i.blocker.is_none()) {
            let tuple = e
                .terms
                .iter()
                .map(|t| eval(t, &inst.bindings))
                .collect::<Option<Vec<_>>>()?;
            let atoms = positive_atoms(&e.condition, &inst.bindings);
            add(tuple, atoms);
        }
        let terms: Vec<String> = e.terms.iter().map(|t| show_term(t, b)).collect();
        let cond: Vec<String> = e.condition.iter().map(|l| lit_text(l, b)).collect();
        texts.push(if cond.is_empty() {
            terms.join(",")
        } else {
            format!("{}: {}", terms.join(","), cond.join(", "))
        });
    }
    for c in &agg.set_syntax {
        let mut lits: Vec<Lit> = vec![Lit::of_literal(&c.literal)];
        lits.extend(c.condition.iter().map(Lit::of_literal));
        let mut out = Vec::new();
        join(&lits, b.clone(), world, &mut out);
        for inst in out.into_iter().filter(|i| i.blocker.is_none()) {
            let mut all = vec![c.literal.clone()];
            all.extend(c.condition.iter().cloned());
            let atoms = positive_atoms(&all, &inst.bindings);
            let tuple = atoms.first().cloned().into_iter().collect();
            add(tuple, atoms);
        }
        let cond: Vec<String> = c.condition.iter().map(|l| lit_text(l, b)).collect();
        let lit = lit_text(&c.literal, b);
        texts.push(if cond.is_empty() {
            lit
        } else {
            format!("{lit}: {}", cond.join(", "))
        });
    }
    let weights = || elements.iter().map(|e| e.tuple.first().cloned());
    let value = match agg.function {
        AggregateFunction::Count => Symbol::Number(elements.len() as i32),
        AggregateFunction::Sum | AggregateFunction::SumPlus => {
            let mut s: i32 = 0;
            for w in weights() {
                let w = w.and_then(|w| w.as_number()).unwrap_or(0);
                if agg.function == AggregateFunction::Sum || w > 0 {
                    s = s.checked_add(w)?;
                }
            }
            Symbol::Number(s)
        }
        AggregateFunction::Min => weights().flatten().min().unwrap_or(Symbol::Sup),
        AggregateFunction::Max => weights().flatten().max().unwrap_or(Symbol::Inf),
    };
    let mut holds = true;
    let mut text = String::new();
    if let Some(g) = &agg.lower {
        let t = eval(&g.term, b)?;
        holds &= compare(&t, g.op, &value);
        text.push_str(&format!("{t} {} ", cmp_words(g.op)));
    }
    let name = match agg.function {
        AggregateFunction::Count => "#count",
        AggregateFunction::Sum => "#sum",
        AggregateFunction::SumPlus => "#sum+",
        AggregateFunction::Min => "#min",
        AggregateFunction::Max => "#max",
    };
    text.push_str(&format!("{name}{{{}}}", texts.join("; ")));
    if let Some(g) = &agg.upper {
        let t = eval(&g.term, b)?;
        holds &= compare(&value, g.op, &t);
        text.push_str(&format!(" {} {t}", cmp_words(g.op)));
    }
    Some(AggregateEval {
        text,
        value,
        holds,
        elements,
    })
}

fn positive_atoms(lits: &[ast::Literal], b: &Bindings) -> Vec<Symbol> {
    lits.iter()
        .filter_map(|l| match (&l.atom, l.sign) {
            (ast::Atom::Symbolic(a), Sign::Positive | Sign::NotNot) => ground_atom(a, b),
            _ => None,
        })
        .collect()
}

/// The body literals of a statement (rules and weak constraints), empty for other kinds.
pub fn body_of(s: &ast::Statement) -> &[ast::BodyLiteral] {
    match &s.kind {
        ast::StatementKind::Rule(r) => &r.body,
        ast::StatementKind::WeakConstraint(w) => &w.body,
        _ => &[],
    }
}

/// The statement as clingo source (one line).
pub fn statement_text(s: &ast::Statement) -> String {
    let mut out = String::new();
    printer::statement(&mut out, &s.kind);
    out
}

/// Bindings as text: `N=1, C=green`.
pub fn show_bindings(b: &Bindings) -> String {
    b.iter()
        .map(|(n, v)| format!("{n}={v}"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The atoms a rule statement can derive, each with its element's condition: its head
/// literals (a disjunction's, a choice's elements), empty for constraints and other statements.
pub fn head_atoms(s: &ast::Statement) -> Vec<(&SymbolicAtom, &[ast::Literal])> {
    let ast::StatementKind::Rule(r) = &s.kind else {
        return Vec::new();
    };
    let lits: Vec<&ast::ConditionalLiteral> = match &r.head {
        ast::Head::Disjunction(h) => h.iter().collect(),
        ast::Head::Choice(c) => c.elements.iter().collect(),
        _ => Vec::new(),
    };
    lits.into_iter()
        .filter_map(|c| match (&c.literal.atom, c.literal.sign) {
            (ast::Atom::Symbolic(a), Sign::Positive) => Some((a, c.condition.as_slice())),
            _ => None,
        })
        .collect()
}

/// The statement's body aggregates, with their default negation.
pub fn body_aggregates(s: &ast::Statement) -> Vec<(&ast::BodyAggregate, bool)> {
    body_of(s)
        .iter()
        .filter_map(|l| match l {
            ast::BodyLiteral::Aggregate { sign, aggregate } => {
                Some((aggregate.as_ref(), *sign == Sign::Not))
            }
            _ => None,
        })
        .collect()
}

/// Adds the variables of `t` to `out`.
pub fn term_vars(t: &Term, out: &mut Vec<String>) {
    match &t.kind {
        TermKind::Variable(v) if !out.iter().any(|x| x == v.as_str()) => {
            out.push(v.as_str().to_string());
        }
        TermKind::Function { args, .. } => args.iter().flatten().for_each(|a| term_vars(a, out)),
        TermKind::Unary { arg, .. } | TermKind::Paren(arg) => term_vars(arg, out),
        TermKind::Binary { lhs, rhs, .. } => {
            term_vars(lhs, out);
            term_vars(rhs, out);
        }
        TermKind::Interval { lo, hi } => {
            term_vars(lo, out);
            term_vars(hi, out);
        }
        TermKind::Pool(ts) => ts.iter().for_each(|a| term_vars(a, out)),
        _ => {}
    }
}

/// The variables of the plain literals of a statement's body (its global variables, for a
/// rule without body aggregates).
pub fn body_vars(s: &ast::Statement) -> Vec<String> {
    let mut out = Vec::new();
    for l in body_of(s) {
        let ast::BodyLiteral::Literal(l) = l else {
            continue;
        };
        match &l.atom {
            ast::Atom::Symbolic(a) => a.args.iter().flatten().for_each(|t| term_vars(t, &mut out)),
            ast::Atom::Comparison { lhs, rhs, .. } => {
                term_vars(lhs, &mut out);
                term_vars(rhs, &mut out);
            }
            _ => {}
        }
    }
    out
}
