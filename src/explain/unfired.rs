//! Why not, at the source level (issue 32 item 3): the statements of the program that could
//! derive a false atom, each with the first body literal that cannot hold in the answer set;
//! and, for an atom a choice left out, what would break if it were true: the integrity
//! constraints whose body would hold, the choice's own upper bound, the weak constraints and
//! `#minimize`/`#maximize` elements that would cost more.
//!
//! Invariants: everything is read from the statements as written and the answer set's true
//! atoms (`explain::source`); "if it were true" adds the atom and keeps every other atom as
//! it is (consequences through other rules are not followed, and the text says so); a
//! reported violation is an instance whose body holds only with the atom (one of its positive
//! literals is the atom); at most [`MAX_REPORTED`] of each kind are reported.

use super::oracle::ProgramOracle;
use super::source::{self, Bindings, Instance, Lit, World};
use crate::control::Symbol;
use crate::syntax::ast;

/// Most blocked instances or violations reported per statement.
pub const MAX_REPORTED: usize = 4;

/// A statement whose head matches the atom.
#[derive(Clone, Debug)]
pub struct Candidate {
    /// The statement's label (its source location).
    pub label: String,
    /// The statement as written.
    pub statement: String,
    /// The bindings that match its head to the atom.
    pub head: Bindings,
    /// Its instances (bounded): blocked ones with their first failing literal, completed ones
    /// without.
    pub instances: Vec<Instance>,
    /// Whether the head is a choice (an instance whose body holds may still leave it out).
    pub choice: bool,
}

impl Candidate {
    /// As JSON: `label`, `statement`, `bindings`, `blocked` (bindings and blocker).
    pub fn to_json(&self) -> serde_json::Value {
        let blocked: Vec<serde_json::Value> = self
            .instances
            .iter()
            .filter_map(|i| {
                let b = i.blocker.as_ref()?;
                let mut v = b.to_json();
                v["bindings"] = bindings_json(&i.bindings);
                Some(v)
            })
            .collect();
        serde_json::json!({
            "label": self.label,
            "statement": self.statement,
            "bindings": bindings_json(&self.head),
            "blocked": blocked,
        })
    }
}

/// Bindings as a JSON object `{"X": "1"}`.
pub fn bindings_json(b: &Bindings) -> serde_json::Value {
    let mut m = serde_json::Map::new();
    for (n, v) in b {
        m.insert(n.clone(), serde_json::Value::String(v.to_string()));
    }
    serde_json::Value::Object(m)
}

/// The statements whose head matches `atom`, each with its body joined over `world` from the
/// head's bindings.
pub fn candidates(oracle: &ProgramOracle, world: &World, atom: &Symbol) -> Vec<Candidate> {
    let mut out = Vec::new();
    for (i, s) in oracle.labels.statements.iter().enumerate() {
        for (a, condition) in source::head_atoms(s) {
            let mut b = Vec::new();
            if !source::unify_atom(a, atom, &mut b) {
                continue;
            }
            let mut lits: Vec<Lit> = source::body_of(s).iter().map(Lit::of_body).collect();
            lits.extend(condition.iter().map(Lit::of_literal));
            let mut instances = Vec::new();
            source::join(&lits, b.clone(), world, &mut instances);
            let choice = matches!(&s.kind, ast::StatementKind::Rule(r)
                if matches!(r.head, ast::Head::Choice(_)));
            out.push(Candidate {
                label: oracle
                    .labels
                    .by_statement
                    .get(i)
                    .map(|l| l.0.clone())
                    .unwrap_or_else(|| format!("statement {i}")),
                statement: source::statement_text(s),
                head: b,
                instances,
                choice,
            });
            break;
        }
    }
    out
}

/// What would break if the atom held.
#[derive(Clone, Debug)]
pub enum Violation {
    /// An integrity constraint whose body would hold, with its bindings.
    Constraint {
        /// The constraint's label.
        label: String,
        /// The constraint as written.
        statement: String,
        /// The instance.
        bindings: Bindings,
    },
    /// The upper bound of the choice that left the atom out.
    Bound {
        /// The choice's label.
        label: String,
        /// The bound, as text (`<= 1`).
        bound: String,
        /// The atoms that would be chosen.
        chosen: Vec<Symbol>,
    },
    /// A weak constraint or optimize element whose body would hold: its cost.
    Weak {
        /// The weak constraint's label.
        label: String,
        /// The weak constraint as written.
        statement: String,
        /// The instance.
        bindings: Bindings,
        /// `weight@priority`.
        cost: String,
    },
}

impl Violation {
    /// The violation in words.
    pub fn words(&self) -> String {
        match self {
            Violation::Constraint {
                label,
                statement,
                bindings,
            } => format!("the constraint {label} `{statement}`{}", with(bindings)),
            Violation::Bound {
                label,
                bound,
                chosen,
            } => {
                let c: Vec<String> = chosen.iter().map(Symbol::to_string).collect();
                format!(
                    "the bound {bound} of the choice {label}: {} would be chosen ({})",
                    chosen.len(),
                    c.join(", ")
                )
            }
            Violation::Weak {
                label,
                statement,
                bindings,
                cost,
            } => {
                let what = if statement.starts_with(":~") {
                    "weak constraint"
                } else {
                    "optimization"
                };
                format!(
                    "the {what} {label} `{statement}`{}: it would cost {cost} more",
                    with(bindings)
                )
            }
        }
    }

    /// As JSON: `kind` (`constraint`, `bound`, `weak`), `label` and the rest.
    pub fn to_json(&self) -> serde_json::Value {
        match self {
            Violation::Constraint {
                label,
                statement,
                bindings,
            } => serde_json::json!({"kind": "constraint", "label": label,
                "statement": statement, "bindings": bindings_json(bindings)}),
            Violation::Bound {
                label,
                bound,
                chosen,
            } => serde_json::json!({"kind": "bound", "label": label, "bound": bound,
                "chosen": chosen.iter().map(Symbol::to_string).collect::<Vec<_>>()}),
            Violation::Weak {
                label,
                statement,
                bindings,
                cost,
            } => serde_json::json!({"kind": "weak", "label": label, "statement": statement,
                "bindings": bindings_json(bindings), "cost": cost}),
        }
    }
}

/// ` with X=1, Y=2`, or nothing without bindings.
pub fn with(b: &Bindings) -> String {
    if b.is_empty() {
        String::new()
    } else {
        format!(" with {}", source::show_bindings(b))
    }
}

/// What would break if `atom` held too (the rest of `world` unchanged); `choice` is the
/// statement and bindings of the choice that left it out, for its bound.
pub fn if_true(
    oracle: &ProgramOracle,
    world: &World,
    atom: &Symbol,
    choice: Option<&(usize, Bindings)>,
) -> Vec<Violation> {
    let mut with_atom = world.clone();
    with_atom.add(atom.clone());
    let mut out = Vec::new();
    if let Some((stmt, b)) = choice {
        if let Some(v) = bound(oracle, &with_atom, *stmt, b) {
            out.push(v);
        }
    }
    for (i, s) in oracle.labels.statements.iter().enumerate() {
        let label = oracle
            .labels
            .by_statement
            .get(i)
            .map(|l| l.0.clone())
            .unwrap_or_else(|| format!("statement {i}"));
        for (lits, cost) in bodies(s) {
            violations(&label, s, &lits, cost, &with_atom, atom, &mut out);
        }
    }
    out
}

/// How a body that holds costs: weight, priority, and whether the weight counts negated
/// (`#maximize`).
type Cost<'a> = (&'a ast::Term, Option<&'a ast::Term>, bool);

/// The bodies of a statement that can be violated: an integrity constraint's (no cost), a
/// weak constraint's and each `#minimize`/`#maximize` element's condition (with its cost).
fn bodies(s: &ast::Statement) -> Vec<(Vec<Lit<'_>>, Option<Cost<'_>>)> {
    match &s.kind {
        ast::StatementKind::Rule(r) if matches!(r.head, ast::Head::None) => {
            vec![(r.body.iter().map(Lit::of_body).collect(), None)]
        }
        ast::StatementKind::WeakConstraint(w) => vec![(
            w.body.iter().map(Lit::of_body).collect(),
            Some((&w.weight, w.priority.as_ref(), false)),
        )],
        ast::StatementKind::Optimize(o) => o
            .elements
            .iter()
            .map(|e| {
                (
                    e.condition.iter().map(Lit::of_literal).collect(),
                    Some((&e.weight, e.priority.as_ref(), o.maximize)),
                )
            })
            .collect(),
        _ => Vec::new(),
    }
}

/// Pushes the instances of `lits` that hold in `world` only with `atom` (one of their
/// positive literals is it), at most [`MAX_REPORTED`]; with a cost, only those that cost more.
fn violations(
    label: &str,
    s: &ast::Statement,
    lits: &[Lit<'_>],
    cost: Option<Cost<'_>>,
    world: &World,
    atom: &Symbol,
    out: &mut Vec<Violation>,
) {
    let mut instances = Vec::new();
    source::join(lits, Vec::new(), world, &mut instances);
    let mut n = 0;
    for inst in instances.into_iter().filter(|i| i.blocker.is_none()) {
        let uses = lits.iter().any(|l| match l {
            Lit::Pos(a) => source::ground_atom(a, &inst.bindings).as_ref() == Some(atom),
            _ => false,
        });
        if !uses || n == MAX_REPORTED {
            continue;
        }
        let statement = source::statement_text(s);
        let v = match cost {
            None => Violation::Constraint {
                label: label.to_string(),
                statement,
                bindings: inst.bindings,
            },
            Some((w, p, negate)) => {
                let w = source::eval(w, &inst.bindings).and_then(|w| w.as_number());
                let w = match (w, negate) {
                    (Some(w), false) => w,
                    (Some(w), true) => w.saturating_neg(),
                    (None, _) => continue,
                };
                if w <= 0 {
                    continue;
                }
                let p = p
                    .and_then(|p| source::eval(p, &inst.bindings))
                    .map_or("0".to_string(), |p| p.to_string());
                Violation::Weak {
                    label: label.to_string(),
                    statement,
                    cost: format!("{w}@{p}"),
                    bindings: inst.bindings,
                }
            }
        };
        n += 1;
        out.push(v);
    }
}

/// The choice statement `stmt`'s upper bound under `b`, when `world` breaks it.
fn bound(oracle: &ProgramOracle, world: &World, stmt: usize, b: &Bindings) -> Option<Violation> {
    let s = oracle.labels.statements.get(stmt)?;
    let ast::StatementKind::Rule(r) = &s.kind else {
        return None;
    };
    let ast::Head::Choice(c) = &r.head else {
        return None;
    };
    let g = c.upper.as_ref()?;
    let limit = source::eval(&g.term, b)?;
    // The choice's instance: its body's variables only (the elements' own are joined).
    let global = source::body_vars(s);
    let b: Bindings = b
        .iter()
        .filter(|(n, _)| global.contains(n))
        .cloned()
        .collect();
    let b = &b;
    let mut chosen: Vec<Symbol> = Vec::new();
    for e in &c.elements {
        let mut lits = vec![Lit::of_literal(&e.literal)];
        lits.extend(e.condition.iter().map(Lit::of_literal));
        let mut instances = Vec::new();
        source::join(&lits, b.clone(), world, &mut instances);
        for i in instances.iter().filter(|i| i.blocker.is_none()) {
            if let ast::Atom::Symbolic(a) = &e.literal.atom {
                if let Some(x) = source::ground_atom(a, &i.bindings) {
                    if !chosen.contains(&x) {
                        chosen.push(x);
                    }
                }
            }
        }
    }
    let count = Symbol::Number(chosen.len() as i32);
    if source::compare(&count, g.op, &limit) {
        return None;
    }
    let label = oracle.labels.by_statement.get(stmt)?.0.clone();
    Some(Violation::Bound {
        label,
        bound: format!("{} {limit}", source::cmp_words(g.op)),
        chosen,
    })
}
