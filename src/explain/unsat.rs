//! Why a program has no answer set: a minimal unsatisfiable subset of its facts and
//! constraints (the question clingo-explaid answers), found with the solver's cores.
//!
//! Technique: the program's text is rewritten once, every statement kept in place, so that
//! each candidate can be switched off by an assumption:
//! - a fact `p(t1,...,tn).` (each alternative of a pool, every instance of an interval) becomes
//!   `{lucent_fact(g,t1,...,tn)}.` and `p(X1,...,Xn) :- lucent_fact(g,X1,...,Xn).`: one
//!   assumption atom per ground fact instance; only facts of the `assume` signatures when any
//!   are given (clingo-explaid's `--assumption-signature`);
//! - an integrity constraint `:- body.` becomes `:- body, lucent_rule(g).` with
//!   `{lucent_rule(g)}.`, and so does a choice rule with `choices` on: one assumption per
//!   statement.
//!
//! The rewritten program is grounded once, on one `Control`. A solve assumes the switched-on
//! candidates true and all others false (removed); when it fails, the solver's core (the
//! assumptions its refutation used, `control::Summary::core`) is kept, its assumed-false part
//! dropped (every later call switches those off too). Deletion-based minimisation then tries
//! each candidate of the core in turn (facts first, then constraints, then choice rules): if the
//! program is still unsatisfiable without it, it goes, and the smaller call's own core replaces
//! the set. The result is minimal: without any one of its members the program (with every
//! candidate outside the set removed) has an answer set. The rules involved are the rules that
//! the set's constraints depend on through rule heads and bodies (by predicate, syntactically),
//! and the bounded choice and aggregate heads reached by them or by the set's facts.
//!
//! Invariants: nothing here reads files; every member of the answer is backed by solver calls
//! over the program, each member's location is its statement's span in the caller's sources;
//! a program that does not ground is an error, never a panic.

use std::collections::BTreeSet;

use crate::base::{SourceMap, Span};
use crate::control::{Control, ControlConfig, Part, SolveOptions, Symbol};
use crate::syntax::ast;
use crate::syntax::build::{atom, fact, head_of, int, pos, rule, var};

/// The assumption atom name of a fact instance.
const FACT: &str = "lucent_fact";
/// The assumption atom name of a constraint or choice rule.
const RULE: &str = "lucent_rule";

/// A predicate signature `[-]name/arity`, as in `--assume edge/2`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Signature {
    /// Classical negation.
    pub negated: bool,
    /// The predicate's name.
    pub name: String,
    /// Its arity.
    pub arity: usize,
}

impl Signature {
    /// Reads `name/arity` or `-name/arity`.
    pub fn parse(text: &str) -> Result<Signature, String> {
        let t = text.trim();
        let (negated, t) = match t.strip_prefix('-') {
            Some(rest) => (true, rest),
            None => (false, t),
        };
        let bad = || format!("'{text}': expected a signature such as edge/2");
        let (name, arity) = t.rsplit_once('/').ok_or_else(bad)?;
        let arity = arity.trim().parse().map_err(|_| bad())?;
        let name = name.trim();
        let ok = name.chars().next().is_some_and(|c| c.is_ascii_lowercase())
            && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if !ok {
            return Err(bad());
        }
        Ok(Signature {
            negated,
            name: name.to_string(),
            arity,
        })
    }
}

/// What may be switched off.
#[derive(Clone, Debug, Default)]
pub struct UnsatConfig {
    /// Only facts of these predicates are candidates; empty: every fact.
    pub assume: Vec<Signature>,
    /// Choice rules are candidates too (one per statement).
    pub choices: bool,
    /// `-c name=value` constants.
    pub consts: Vec<(String, ast::Term)>,
}

/// The kind of a member of the unsatisfiable set.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Member {
    /// A ground fact instance.
    Fact(Symbol),
    /// An integrity constraint.
    Constraint,
    /// A choice rule.
    Choice,
}

/// A candidate: what it is and the statement it comes from (its index in the caller's program,
/// and its span).
#[derive(Clone, Debug)]
pub struct Candidate {
    /// What it is.
    pub member: Member,
    /// The statement's index in the program given to [`why_unsat`].
    pub statement: usize,
    /// The statement's span.
    pub span: Span,
    /// The assumption atom that switches it on.
    assumption: Symbol,
}

/// The answer for an unsatisfiable program.
#[derive(Clone, Debug)]
pub struct Unsat {
    /// The minimal unsatisfiable set, facts first, each group in program order.
    pub members: Vec<Candidate>,
    /// Statements of the rules involved, in program order.
    pub rules: Vec<usize>,
    /// How many candidates there were.
    pub candidates: usize,
    /// The size of the solver's first core, before deletion.
    pub first_core: usize,
    /// Solve calls made.
    pub solves: usize,
}

/// Whether the program has an answer set, and if not, why.
#[derive(Clone, Debug)]
pub enum WhyUnsat {
    /// It has one: nothing to explain.
    Satisfiable,
    /// It has none.
    Unsatisfiable(Unsat),
}

/// Why `program` (over `sources`) has no answer set. `Err` with the grounder's message when it
/// does not ground.
pub fn why_unsat(
    program: &ast::Program,
    sources: &SourceMap,
    config: &UnsatConfig,
) -> Result<WhyUnsat, String> {
    let (guarded, gates) = guard(program, config);
    let mut cc = ControlConfig::default();
    cc.ground.consts = config.consts.clone();
    let mut ctl = Control::with_sources(cc, sources.clone());
    ctl.add_program(guarded)
        .and_then(|()| ctl.ground(&[Part::base()]))
        .map_err(|e| e.message.trim_end().to_string())?;
    let mut cands = candidates(&ctl, program, &gates);
    // Facts first, then constraints, then choice rules; program order within each.
    cands.sort_by_key(|c| (rank(&c.member), c.statement));
    let mut search = Search {
        ctl,
        cands,
        solves: 0,
    };
    let all: Vec<usize> = (0..search.cands.len()).collect();
    let Some(mut core) = search.refute(&all) else {
        return Ok(WhyUnsat::Satisfiable);
    };
    let first_core = core.len();
    for k in core.clone() {
        if !core.contains(&k) {
            continue;
        }
        let without: Vec<usize> = core.iter().copied().filter(|&x| x != k).collect();
        if let Some(smaller) = search.refute(&without) {
            core = smaller;
        }
    }
    core.sort_unstable();
    let members: Vec<Candidate> = core.iter().map(|&k| search.cands[k].clone()).collect();
    let rules = involved_rules(program, &members);
    Ok(WhyUnsat::Unsatisfiable(Unsat {
        members,
        rules,
        candidates: search.cands.len(),
        first_core,
        solves: search.solves,
    }))
}

fn rank(m: &Member) -> u8 {
    match m {
        Member::Fact(_) => 0,
        Member::Constraint => 1,
        Member::Choice => 2,
    }
}

/// The grounded, guarded program and its candidates.
struct Search {
    ctl: Control,
    cands: Vec<Candidate>,
    solves: usize,
}

impl Search {
    /// Solves with the candidates `on` switched on and the others off: `None` when an answer
    /// set exists, else a subset of `on` that is unsatisfiable on its own (the others off).
    fn refute(&mut self, on: &[usize]) -> Option<Vec<usize>> {
        self.solves += 1;
        let gates: Vec<&Symbol> = self.cands.iter().map(|c| &c.assumption).collect();
        refute_gates(&mut self.ctl, &gates, on)
    }
}

/// Solves with the gate atoms `gates[k]` assumed true for `k` in `on` and false for the others:
/// `None` when an answer set exists, else the members of `on` whose gate the solver's core
/// assumes true (assumed-false gates are dropped: switching them off is what the caller's
/// later calls do too); without a core (a stopped search), `on` itself. The deletion searches
/// of `--why-unsat` and of why-no-plan (`counterfactual::NoPlan`) both refute with it.
pub(super) fn refute_gates(
    ctl: &mut Control,
    gates: &[&Symbol],
    on: &[usize],
) -> Option<Vec<usize>> {
    let mut is_on = vec![false; gates.len()];
    for &k in on {
        is_on[k] = true;
    }
    let assumptions: Vec<(Symbol, bool)> = gates
        .iter()
        .zip(&is_on)
        .map(|(g, &b)| ((*g).clone(), b))
        .collect();
    let mut sat = false;
    let summary = ctl.solve(&SolveOptions { assumptions }, |_| {
        sat = true;
        false
    });
    if sat {
        return None;
    }
    Some(match summary.core {
        Some(core) => {
            let used: std::collections::HashSet<&Symbol> = core
                .iter()
                .filter(|(_, value)| *value)
                .map(|(s, _)| s)
                .collect();
            on.iter()
                .copied()
                .filter(|&k| used.contains(gates[k]))
                .collect()
        }
        None => on.to_vec(),
    })
}

/// A gate of the rewritten program: the statement it guards and what it is.
struct Gate {
    statement: usize,
    /// For a fact: the predicate (`negated`, name); `None` for a rule.
    fact: Option<(bool, String)>,
}

/// The program with its candidates behind assumption atoms (module comment), and the gates,
/// indexed by the first argument of their assumption atoms.
fn guard(program: &ast::Program, config: &UnsatConfig) -> (ast::Program, Vec<Gate>) {
    let mut out = ast::Program {
        dialect: program.dialect,
        statements: Vec::with_capacity(program.statements.len() * 2),
    };
    let mut gates = Vec::new();
    for (k, st) in program.statements.iter().enumerate() {
        let sp = st.span;
        let ast::StatementKind::Rule(r) = &st.kind else {
            out.statements.push(st.clone());
            continue;
        };
        if !matches!(r.kind, ast::RuleKind::Normal) {
            out.statements.push(st.clone());
            continue;
        }
        if let Some(a) = fact_atom(r) {
            let mut rest = a.clone();
            rest.args.clear();
            for args in &a.args {
                let wanted = config.assume.is_empty()
                    || config.assume.iter().any(|s| {
                        s.negated == a.negated && s.name == a.name.as_str() && s.arity == args.len()
                    });
                if !wanted {
                    // Alternatives of other predicates stay facts.
                    rest.args.push(args.clone());
                    continue;
                }
                let g = gates.len();
                gates.push(Gate {
                    statement: k,
                    fact: Some((a.negated, a.name.as_str().to_string())),
                });
                let mut gargs = vec![int(sp, g as i64)];
                gargs.extend(args.iter().cloned());
                out.statements
                    .push(choice_of(sp, atom(sp, false, FACT, gargs)));
                let xs: Vec<ast::Term> =
                    (0..args.len()).map(|i| var(sp, &format!("X{i}"))).collect();
                let mut body_args = vec![int(sp, g as i64)];
                body_args.extend(xs.iter().cloned());
                let head = atom(sp, a.negated, a.name.as_str(), xs);
                out.statements.push(rule(
                    sp,
                    head_of(sp, head),
                    vec![pos(sp, false, FACT, body_args)],
                ));
            }
            if !rest.args.is_empty() {
                out.statements.push(fact(sp, rest));
            }
            continue;
        }
        let gated = match r.head {
            ast::Head::None => true,
            ast::Head::Choice(_) => config.choices,
            _ => false,
        };
        if !gated {
            out.statements.push(st.clone());
            continue;
        }
        let g = gates.len();
        gates.push(Gate {
            statement: k,
            fact: None,
        });
        let mut r2 = r.clone();
        r2.body.push(pos(sp, false, RULE, vec![int(sp, g as i64)]));
        out.statements.push(ast::Statement {
            span: sp,
            kind: ast::StatementKind::Rule(r2),
        });
        out.statements.push(choice_of(
            sp,
            atom(sp, false, RULE, vec![int(sp, g as i64)]),
        ));
    }
    (out, gates)
}

/// The atom of a fact: a normal rule without body whose head is one unconditional atom.
fn fact_atom(r: &ast::Rule) -> Option<&ast::SymbolicAtom> {
    let ast::Head::Disjunction(d) = &r.head else {
        return None;
    };
    let [c] = d.as_slice() else { return None };
    let ast::Atom::Symbolic(a) = &c.literal.atom else {
        return None;
    };
    (r.body.is_empty() && c.condition.is_empty() && c.literal.sign == ast::Sign::Positive)
        .then_some(a)
}

/// `{a}.`
fn choice_of(sp: Span, a: ast::SymbolicAtom) -> ast::Statement {
    let element = ast::ConditionalLiteral {
        span: sp,
        literal: ast::Literal {
            span: sp,
            sign: ast::Sign::Positive,
            atom: ast::Atom::Symbolic(a),
        },
        condition: Vec::new(),
        has_colon: false,
    };
    ast::Statement {
        span: sp,
        kind: ast::StatementKind::Rule(ast::Rule {
            head: ast::Head::Choice(Box::new(ast::Choice {
                span: sp,
                lower: None,
                elements: vec![element],
                upper: None,
            })),
            body: Vec::new(),
            kind: ast::RuleKind::Normal,
        }),
    }
}

/// The candidates of the grounded program: one per ground assumption atom.
fn candidates(ctl: &Control, program: &ast::Program, gates: &[Gate]) -> Vec<Candidate> {
    let mut out = Vec::new();
    for sa in ctl.symbolic_atoms() {
        let s = &sa.symbol;
        let Some(name) = s.name() else { continue };
        if name != FACT && name != RULE {
            continue;
        }
        let Some(g) = s.args().first().and_then(Symbol::as_number) else {
            continue;
        };
        let Some(gate) = usize::try_from(g).ok().and_then(|g| gates.get(g)) else {
            continue;
        };
        let statement = &program.statements[gate.statement];
        let member = match (&gate.fact, name == FACT) {
            (Some((negated, pred)), true) => {
                let f = Symbol::function(pred.as_str(), s.args()[1..].to_vec());
                Member::Fact(if *negated {
                    f.complement().unwrap_or(f)
                } else {
                    f
                })
            }
            (None, false) => match &statement.kind {
                ast::StatementKind::Rule(r) if matches!(r.head, ast::Head::None) => {
                    Member::Constraint
                }
                _ => Member::Choice,
            },
            _ => continue,
        };
        out.push(Candidate {
            member,
            statement: gate.statement,
            span: statement.span,
            assumption: s.clone(),
        });
    }
    out
}

/// A predicate: classical negation, name, arity.
type Pred = (bool, String, usize);

/// Predicates of the atoms in a literal.
fn literal_preds(l: &ast::Literal, out: &mut BTreeSet<Pred>) {
    if let ast::Atom::Symbolic(a) = &l.atom {
        for args in &a.args {
            out.insert((a.negated, a.name.as_str().to_string(), args.len()));
        }
    }
}

/// Predicates of a rule's head and of its body.
fn rule_preds(r: &ast::Rule) -> (BTreeSet<Pred>, BTreeSet<Pred>) {
    let mut head = BTreeSet::new();
    let mut body = BTreeSet::new();
    match &r.head {
        ast::Head::None => {}
        ast::Head::Disjunction(d) => {
            for c in d {
                literal_preds(&c.literal, &mut head);
                c.condition.iter().for_each(|l| literal_preds(l, &mut body));
            }
        }
        ast::Head::Choice(c) => {
            for e in &c.elements {
                literal_preds(&e.literal, &mut head);
                e.condition.iter().for_each(|l| literal_preds(l, &mut body));
            }
        }
        ast::Head::Aggregate(a) => {
            for e in &a.elements {
                literal_preds(&e.literal, &mut head);
                e.condition.iter().for_each(|l| literal_preds(l, &mut body));
            }
        }
        ast::Head::Theory(a) => {
            for e in &a.elements {
                e.condition.iter().for_each(|l| literal_preds(l, &mut body));
            }
        }
    }
    for b in &r.body {
        match b {
            ast::BodyLiteral::Literal(l) => literal_preds(l, &mut body),
            ast::BodyLiteral::Conditional(c) => {
                literal_preds(&c.literal, &mut body);
                c.condition.iter().for_each(|l| literal_preds(l, &mut body));
            }
            ast::BodyLiteral::Aggregate { aggregate, .. } => {
                for e in &aggregate.elements {
                    e.condition.iter().for_each(|l| literal_preds(l, &mut body));
                }
                for c in &aggregate.set_syntax {
                    literal_preds(&c.literal, &mut body);
                    c.condition.iter().for_each(|l| literal_preds(l, &mut body));
                }
            }
            ast::BodyLiteral::Theory { atom, .. } => {
                for e in &atom.elements {
                    e.condition.iter().for_each(|l| literal_preds(l, &mut body));
                }
            }
        }
    }
    (head, body)
}

/// The rules (not facts, not the members) the members depend on (module comment).
fn involved_rules(program: &ast::Program, members: &[Candidate]) -> Vec<usize> {
    let rules: Vec<(usize, &ast::Rule)> = program
        .statements
        .iter()
        .enumerate()
        .filter_map(|(k, s)| match &s.kind {
            ast::StatementKind::Rule(r) if fact_atom(r).is_none() => Some((k, r)),
            _ => None,
        })
        .filter(|(k, _)| !members.iter().any(|m| m.statement == *k))
        .collect();
    let preds: Vec<_> = rules.iter().map(|(_, r)| rule_preds(r)).collect();
    let mut wanted = BTreeSet::new();
    let mut fact_preds = BTreeSet::new();
    for m in members {
        match &m.member {
            Member::Fact(f) => {
                fact_preds.insert((
                    f.is_negative(),
                    f.name().unwrap_or_default().to_string(),
                    f.args().len(),
                ));
            }
            _ => {
                if let ast::StatementKind::Rule(r) = &program.statements[m.statement].kind {
                    wanted.extend(rule_preds(r).1);
                }
            }
        }
    }
    let mut chosen = vec![false; rules.len()];
    loop {
        let mut grew = false;
        for (i, (_, r)) in rules.iter().enumerate() {
            if chosen[i] {
                continue;
            }
            let (head, body) = &preds[i];
            let feeds = head.iter().any(|p| wanted.contains(p));
            // A bounded choice or aggregate head constrains its own atoms: it counts when its
            // body reads the set's facts or the predicates the constraints read.
            let bounded = match &r.head {
                ast::Head::Choice(c) => c.lower.is_some() || c.upper.is_some(),
                ast::Head::Aggregate(_) => true,
                _ => false,
            };
            let reads = bounded
                && body
                    .iter()
                    .any(|p| fact_preds.contains(p) || wanted.contains(p));
            if feeds || reads {
                chosen[i] = true;
                wanted.extend(body.iter().cloned());
                wanted.extend(head.iter().cloned());
                grew = true;
            }
        }
        if !grew {
            break;
        }
    }
    rules
        .iter()
        .zip(chosen)
        .filter(|(_, c)| *c)
        .map(|((k, _), _)| *k)
        .collect()
}

/// A statement's text on one line (runs of white space as one space).
pub fn statement_text(sources: &SourceMap, span: Span) -> String {
    if (span.file.0 as usize) >= sources.len() {
        return String::new();
    }
    sources
        .get(span.file)
        .slice(span)
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

impl Unsat {
    /// The answer in words: the set, each member with its location, then the rules involved.
    pub fn text(&self, program: &ast::Program, sources: &SourceMap) -> String {
        let count = |pick: fn(&Member) -> bool, one: &str, many: &str| {
            let n = self.members.iter().filter(|m| pick(&m.member)).count();
            match n {
                0 => None,
                1 => Some(format!("1 {one}")),
                n => Some(format!("{n} {many}")),
            }
        };
        let parts: Vec<String> = [
            count(|m| matches!(m, Member::Fact(_)), "fact", "facts"),
            count(|m| *m == Member::Constraint, "constraint", "constraints"),
            count(|m| *m == Member::Choice, "choice rule", "choice rules"),
        ]
        .into_iter()
        .flatten()
        .collect();
        let mut t = String::from("UNSATISFIABLE: the program has no answer set.\n");
        if self.members.is_empty() {
            t.push_str(
                "It has none even without all of its facts and constraints that could be \
                 switched off: its rules alone admit no answer set.\n",
            );
        } else {
            t.push_str(&format!(
                "A minimal unsatisfiable subset ({}; without any one of them there is an \
                 answer set):\n",
                parts.join(", ")
            ));
        }
        for m in &self.members {
            let loc = sources.location(m.span);
            match &m.member {
                Member::Fact(f) => t.push_str(&format!("  fact {f}  ({loc})\n")),
                Member::Constraint => t.push_str(&format!(
                    "  constraint `{}`  ({loc})\n",
                    statement_text(sources, m.span)
                )),
                Member::Choice => t.push_str(&format!(
                    "  choice rule `{}`  ({loc})\n",
                    statement_text(sources, m.span)
                )),
            }
        }
        if !self.rules.is_empty() {
            t.push_str("Rules involved:\n");
            for &k in &self.rules {
                let span = program.statements[k].span;
                t.push_str(&format!(
                    "  `{}`  ({})\n",
                    statement_text(sources, span),
                    sources.location(span)
                ));
            }
        }
        t.trim_end().to_string()
    }

    /// The answer as JSON: `{type: "why_unsat", answer, literals, members: [{kind, atom?, text,
    /// location}], rules: [{text, location}], stats: {candidates, first_core, solves}}`.
    pub fn to_json(&self, program: &ast::Program, sources: &SourceMap) -> serde_json::Value {
        let members: Vec<serde_json::Value> = self
            .members
            .iter()
            .map(|m| {
                let mut v = serde_json::json!({
                    "kind": match m.member {
                        Member::Fact(_) => "fact",
                        Member::Constraint => "constraint",
                        Member::Choice => "choice",
                    },
                    "text": statement_text(sources, m.span),
                    "location": sources.location(m.span),
                });
                if let Member::Fact(f) = &m.member {
                    v["atom"] = f.to_string().into();
                }
                v
            })
            .collect();
        let rules: Vec<serde_json::Value> = self
            .rules
            .iter()
            .map(|&k| {
                let span = program.statements[k].span;
                serde_json::json!({
                    "text": statement_text(sources, span),
                    "location": sources.location(span),
                })
            })
            .collect();
        let literals: Vec<String> = self
            .members
            .iter()
            .filter_map(|m| match &m.member {
                Member::Fact(f) => Some(f.to_string()),
                _ => None,
            })
            .collect();
        serde_json::json!({
            "type": "why_unsat",
            "answer": self.text(program, sources),
            "literals": literals,
            "members": members,
            "rules": rules,
            "stats": {
                "candidates": self.candidates,
                "first_core": self.first_core,
                "solves": self.solves,
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn run(text: &str, config: &UnsatConfig) -> WhyUnsat {
        let mut sources = SourceMap::new();
        let id = sources.add("t.lp", text);
        let parse = crate::syntax::parse(id, text, ast::Dialect::Clingo);
        why_unsat(&parse.program, &sources, config).unwrap()
    }

    fn facts(w: &WhyUnsat) -> Vec<String> {
        match w {
            WhyUnsat::Satisfiable => vec!["sat".into()],
            WhyUnsat::Unsatisfiable(u) => u
                .members
                .iter()
                .map(|m| match &m.member {
                    Member::Fact(f) => f.to_string(),
                    Member::Constraint => format!("constraint {}", m.statement),
                    Member::Choice => format!("choice {}", m.statement),
                })
                .collect(),
        }
    }

    #[test]
    fn a_satisfiable_program_has_nothing_to_explain() {
        let w = run("a. b :- a.", &UnsatConfig::default());
        assert_eq!(facts(&w), ["sat"]);
    }

    /// By hand: `:- p(X), q(X).` fails only for X = 2, which needs p(2) and q(2); the pool and
    /// the interval give one candidate per instance.
    #[test]
    fn the_set_is_the_facts_and_constraint_that_clash() {
        let w = run(
            "p(1..3). q(2;4). r(5).\n:- p(X), q(X).\n:- r(6).\n",
            &UnsatConfig::default(),
        );
        assert_eq!(facts(&w), ["p(2)", "q(2)", "constraint 3"]);
    }

    /// By hand: with only `q/1` assumed, p's facts stay facts and are not named.
    #[test]
    fn signatures_restrict_the_candidates() {
        let config = UnsatConfig {
            assume: vec![Signature::parse("q/1").unwrap()],
            ..UnsatConfig::default()
        };
        let w = run("p(1..3). q(2;4).\n:- p(X), q(X).\n", &config);
        assert_eq!(facts(&w), ["q(2)", "constraint 2"]);
        let WhyUnsat::Unsatisfiable(u) = w else {
            panic!()
        };
        assert_eq!(u.candidates, 3);
    }

    /// By hand: `-a.` and `a :- b.` with `b.` clash through the implicit `:- a, -a.`, which no
    /// assumption guards: the two facts are the set.
    #[test]
    fn classical_negation_facts_are_candidates() {
        let w = run("-a. b. a :- b. c.\n", &UnsatConfig::default());
        assert_eq!(facts(&w), ["-a", "b"]);
    }

    /// By hand: with the choice rule a candidate, `1 { a; b } 1.` and both constraints are
    /// needed (without the choice nothing is chosen; without `:- a.` a is chosen); without
    /// `--assume-choices` the rule is no candidate and the two constraints are the set.
    #[test]
    fn choice_rules_are_candidates_on_request() {
        let text = "1 { a; b } 1.\n:- a.\n:- b.\n";
        let with = UnsatConfig {
            choices: true,
            ..UnsatConfig::default()
        };
        assert_eq!(
            facts(&run(text, &with)),
            ["constraint 1", "constraint 2", "choice 0"]
        );
        assert_eq!(
            facts(&run(text, &UnsatConfig::default())),
            ["constraint 1", "constraint 2"]
        );
    }

    /// By hand: `a :- not a.` has no answer set whatever is switched off; the set is empty and
    /// the text says the rules alone are to blame.
    #[test]
    fn rules_alone_may_be_unsatisfiable() {
        let mut sources = SourceMap::new();
        let text = "b.\na :- not a, b.\n";
        let id = sources.add("t.lp", text);
        let parse = crate::syntax::parse(id, text, ast::Dialect::Clingo);
        let w = why_unsat(&parse.program, &sources, &UnsatConfig::default()).unwrap();
        // b is needed: without it the rule's body fails and the empty set is an answer set.
        assert_eq!(facts(&w), ["b"]);
        let w = run("a :- not a.\n", &UnsatConfig::default());
        let WhyUnsat::Unsatisfiable(u) = &w else {
            panic!("{w:?}")
        };
        assert!(u.members.is_empty());
        let mut sources = SourceMap::new();
        sources.add("t.lp", "a :- not a.\n");
        assert!(u
            .text(&ast::Program::default(), &sources)
            .contains("its rules alone admit no answer set"));
    }

    #[test]
    fn signatures_are_parsed_or_refused() {
        assert_eq!(
            Signature::parse("-edge/2").unwrap(),
            Signature {
                negated: true,
                name: "edge".into(),
                arity: 2
            }
        );
        for bad in ["edge", "Edge/2", "edge/x", "/2"] {
            assert!(Signature::parse(bad).is_err(), "{bad}");
        }
    }
}
