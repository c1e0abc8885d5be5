//! Initial states and goals for the planner in the domain's vocabulary (`domains/ra/README.md`,
//! "Scenes as facts"): a scene written as facts, or (feature `sim`) a simulator scene, turned
//! into AL_d statements (`sort movable = {..}.`, `has_size(..).`, `initially ..`) that are
//! added to a domain description; goals written as AL_d literals.
//!
//! The facts format, one fact per statement, in clingo syntax:
//! - `object(a).` (or `movable(a).`) declares an object; `has_size(a, small).`,
//!   `has_surface(a, irregular).` and `has_shape(a, duck).` give its attributes and declare
//!   it too. Missing attributes default to `large` and `flat`.
//! - `on(a, b).`, `above(a, b).`, ... (any spatial relation of docs/domain.md 1.2),
//!   `relation(on, a, b).`, `in_hand(rob1, a).`, `holds(F, 0).` and `-holds(F, 0).` give the
//!   step-0 state; everything not stated is false (D0).
//!
//! Invariants: the output is AL_d statements built as values ([`SceneFacts::statements`]), added
//! to the domain's description without printing and parsing them again;
//! every problem with the input is a [`Diagnostic`] at the offending fact (unknown predicate,
//! a step other than 0, an object named in a relation but never declared), never a panic.

use std::collections::BTreeMap;

use crate::action::ast::{Lit, Statement};
use crate::action::build::{self, Arg};
use crate::base::{Diagnostic, FileId, Span};
use crate::syntax::ast::{Atom, Head, StatementKind, Term, TermKind};
use crate::syntax::{self, ast::Dialect};

/// The spatial relations of docs/domain.md 1.2.
pub const RELATIONS: [&str; 10] = [
    "above",
    "below",
    "front",
    "behind",
    "left",
    "right",
    "touch",
    "not_touch",
    "far",
    "on",
];

/// A scene: objects with attributes and the step-0 literals.
#[derive(Clone, Debug, Default)]
pub struct SceneFacts {
    /// Objects and their attributes (size, surface, shape), by name.
    pub objects: BTreeMap<String, Attributes>,
    /// Step-0 literals (`relation(on, a, b)`, `-in_hand(rob1, a)`).
    pub initially: Vec<Lit>,
    /// Where each initial literal was written, for diagnostics on unknown objects.
    spans: Vec<(Span, Vec<String>)>,
}

/// An object's attributes.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Attributes {
    /// `small`, `medium` or `large` (default `large`).
    pub size: Option<String>,
    /// `flat` or `irregular` (default `flat`).
    pub surface: Option<String>,
    /// A shape, if given.
    pub shape: Option<String>,
}

fn term_text(t: &Term) -> String {
    let mut s = String::new();
    syntax::printer::term(&mut s, t);
    s.replace(' ', "")
}

/// The AL_d literal `[-]f` of a fluent term `f` (`relation(on, a, b)`); `None` for a term that
/// is not a constant or a function.
fn fluent_lit(negated: bool, f: &Term) -> Option<Lit> {
    match &f.kind {
        TermKind::Constant(c) => Some(build::lit(negated, c.as_str(), &[])),
        TermKind::Function { name, args, .. } if args.len() == 1 => {
            let args: Vec<Arg> = args[0].iter().cloned().map(Arg::Term).collect();
            Some(build::lit(negated, name.as_str(), &args))
        }
        _ => None,
    }
}

/// `[-]relation(r, x, y)`.
fn relation(negated: bool, r: &str, x: &str, y: &str) -> Lit {
    build::lit(
        negated,
        "relation",
        &[Arg::constant(r), Arg::constant(x), Arg::constant(y)],
    )
}

fn name(t: &Term) -> Option<String> {
    match &t.kind {
        TermKind::Constant(c) => Some(c.to_string()),
        _ => None,
    }
}

/// The object names inside a fluent term (`relation(on, a, b)` gives `a`, `b`).
fn names_in(f: &Term, out: &mut Vec<String>) {
    if let TermKind::Function { name, args, .. } = &f.kind {
        let skip = usize::from(name == "relation");
        for a in args.iter().flatten().skip(skip) {
            if let Some(n) = self::name(a) {
                out.push(n);
            }
        }
    }
}

impl SceneFacts {
    /// Reads the facts format from `text` (file `file` of the caller's sources).
    pub fn parse(file: FileId, text: &str) -> Result<SceneFacts, Vec<Diagnostic>> {
        let parsed = syntax::parse(file, text, Dialect::Clingo);
        let mut errors: Vec<Diagnostic> = parsed
            .diagnostics
            .iter()
            .filter(|d| d.is_error())
            .cloned()
            .collect();
        let mut out = SceneFacts::default();
        for st in &parsed.program.statements {
            let bad = |m: &str| Diagnostic::error(st.span, m.to_string());
            let StatementKind::Rule(r) = &st.kind else {
                if !matches!(st.kind, StatementKind::Error) {
                    errors.push(bad("expected a fact"));
                }
                continue;
            };
            let atom = match &r.head {
                Head::Disjunction(d) if d.len() == 1 && r.body.is_empty() => {
                    match &d[0].literal.atom {
                        Atom::Symbolic(a) if a.args.len() <= 1 => a,
                        _ => {
                            errors.push(bad("expected a fact such as on(a, b)."));
                            continue;
                        }
                    }
                }
                _ => {
                    errors.push(bad("expected a fact such as on(a, b)."));
                    continue;
                }
            };
            let args: Vec<&Term> = atom.args.iter().flatten().collect();
            let names: Vec<Option<String>> = args.iter().map(|a| name(a)).collect();
            let neg = atom.negated;
            match (atom.name.as_str(), names.as_slice()) {
                ("object" | "movable", [Some(o)]) if !atom.negated => {
                    out.objects.entry(o.clone()).or_default();
                }
                ("has_size" | "has_surface" | "has_shape", [Some(o), Some(v)]) if !atom.negated => {
                    let a = out.objects.entry(o.clone()).or_default();
                    let slot = match atom.name.as_str() {
                        "has_size" => &mut a.size,
                        "has_surface" => &mut a.surface,
                        _ => &mut a.shape,
                    };
                    *slot = Some(v.clone());
                }
                (r, [Some(x), Some(y)]) if RELATIONS.contains(&r) => {
                    out.push(st.span, relation(neg, r, x, y), vec![x.clone(), y.clone()]);
                }
                ("relation", [Some(r), Some(x), Some(y)]) if RELATIONS.contains(&r.as_str()) => {
                    out.push(st.span, relation(neg, r, x, y), vec![x.clone(), y.clone()]);
                }
                ("in_hand", [Some(r), Some(o)]) => {
                    let l = build::lit(neg, "in_hand", &[Arg::constant(r), Arg::constant(o)]);
                    out.push(st.span, l, vec![o.clone()]);
                }
                ("holds", [_, _]) => {
                    if !matches!(args[1].kind, TermKind::Integer(0)) {
                        errors.push(bad("only the initial state (step 0) can be given"));
                        continue;
                    }
                    let Some(l) = fluent_lit(neg, args[0]) else {
                        errors.push(bad("expected a fluent such as relation(on, a, b)"));
                        continue;
                    };
                    let mut objs = Vec::new();
                    names_in(args[0], &mut objs);
                    out.push(st.span, l, objs);
                }
                _ => errors.push(bad(&format!(
                    "unknown fact `{}`: expected object/1, has_size/2, has_surface/2, a relation \
                     such as on/2, in_hand/2 or holds(F, 0)",
                    text_atom(&atom.name, &args)
                ))),
            }
        }
        // Every object named in the state must be declared (the robot and the table are not
        // objects).
        for (span, objs) in &out.spans {
            for o in objs {
                if o != "table" && o != "rob1" && !out.objects.contains_key(o) {
                    errors.push(Diagnostic::error(
                        *span,
                        format!("unknown object `{o}`: declare it with object({o}). or has_size({o}, S)."),
                    ));
                }
            }
        }
        if errors.is_empty() {
            Ok(out)
        } else {
            Err(errors)
        }
    }

    fn push(&mut self, span: Span, literal: Lit, objects: Vec<String>) {
        self.initially.push(literal);
        self.spans.push((span, objects));
    }

    /// The scene as AL_d statements to add to a domain description: the objects as
    /// `sort movable`, an empty `sort unknown`, each object's size and surface (default
    /// `large`, `flat`) and shape, and an `initially` statement per step-0 literal.
    pub fn statements(&self) -> Vec<Statement> {
        let names: Vec<&str> = self.objects.keys().map(String::as_str).collect();
        let mut out = vec![build::sort("movable", &names), build::sort("unknown", &[])];
        let attribute = |p: &str, o: &str, v: &str| {
            build::fact(build::lit(false, p, &[Arg::constant(o), Arg::constant(v)]))
        };
        for (o, a) in &self.objects {
            out.push(attribute(
                "has_size",
                o,
                a.size.as_deref().unwrap_or("large"),
            ));
            out.push(attribute(
                "has_surface",
                o,
                a.surface.as_deref().unwrap_or("flat"),
            ));
            if let Some(shape) = &a.shape {
                out.push(attribute("has_shape", o, shape));
            }
        }
        out.extend(self.initially.iter().cloned().map(build::initially));
        out
    }

    /// The scene as AL_d text, the statements of [`SceneFacts::statements`] one per line.
    pub fn to_ald(&self) -> String {
        let mut s = String::new();
        let names: Vec<&str> = self.objects.keys().map(String::as_str).collect();
        s.push_str(&format!(
            "sort movable = {{{}}}.\nsort unknown = {{}}.\n",
            names.join(", ")
        ));
        for st in self.statements().iter().skip(2) {
            s.push_str(&crate::action::translate::show_statement(&st.kind));
            s.push_str(".\n");
        }
        s
    }

    /// The scene of the simulator, measured without noise: every object with its size and
    /// surface, the relations that hold and what the robot holds.
    #[cfg(feature = "sim")]
    pub fn from_sim(scene: &crate::sim::Scene) -> SceneFacts {
        let truth = crate::sim::truth::TruthConfig::default();
        let world = crate::sim::World::build(scene);
        let mut out = SceneFacts::default();
        for id in scene.ids() {
            let o = scene.object(id);
            out.objects.insert(
                o.name.clone(),
                Attributes {
                    size: Some(o.size.name().to_string()),
                    surface: Some(o.surface().name().to_string()),
                    shape: None,
                },
            );
        }
        for r in crate::sim::truth::relations(scene, &world, &truth) {
            out.push(
                Span::default(),
                relation(false, r.rel.name(), &r.a, &r.b),
                Vec::new(),
            );
        }
        if let Some(h) = &scene.in_hand {
            let l = build::lit(
                false,
                "in_hand",
                &[Arg::constant(&scene.robot), Arg::constant(h)],
            );
            out.push(Span::default(), l, Vec::new());
        }
        out
    }
}

fn text_atom(name: &str, args: &[&Term]) -> String {
    if args.is_empty() {
        name.to_string()
    } else {
        let a: Vec<String> = args.iter().map(|t| term_text(t)).collect();
        format!("{name}({})", a.join(","))
    }
}

/// A goal written as AL_d literals (`on(a, b)`, `relation(on, a, b), -in_hand(rob1, c)`),
/// as the AL_d statement `goal relation(on, a, b).`; relation names stand for
/// `relation(R, ..)`. `None` when it is not a comma-separated list of literals.
pub fn goal_statement(text: &str) -> Option<Statement> {
    let src = format!("g :- {}.", text.trim().trim_end_matches('.'));
    let parsed = syntax::parse(FileId(0), &src, Dialect::Clingo);
    if parsed.has_errors() {
        return None;
    }
    let [st] = parsed.program.statements.as_slice() else {
        return None;
    };
    let StatementKind::Rule(r) = &st.kind else {
        return None;
    };
    let mut lits = Vec::new();
    for b in &r.body {
        let crate::syntax::ast::BodyLiteral::Literal(l) = b else {
            return None;
        };
        if l.sign != crate::syntax::ast::Sign::Positive {
            return None;
        }
        let Atom::Symbolic(a) = &l.atom else {
            return None;
        };
        let mut args: Vec<Arg> = a.args.iter().flatten().cloned().map(Arg::Term).collect();
        if RELATIONS.contains(&a.name.as_str()) && args.len() == 2 {
            args.insert(0, Arg::constant(a.name.as_str()));
            lits.push(build::lit(a.negated, "relation", &args));
        } else {
            lits.push(build::lit(a.negated, a.name.as_str(), &args));
        }
    }
    if lits.is_empty() {
        return None;
    }
    Some(build::goal(lits))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn facts_become_ald_statements() {
        let s = SceneFacts::parse(
            FileId(0),
            "object(a). has_size(b, small). has_surface(b, irregular).\n\
             on(a, b). holds(relation(above, a, b), 0). -holds(in_hand(rob1, a), 0).",
        )
        .unwrap();
        let ald = s.to_ald();
        assert!(ald.contains("sort movable = {a, b}."), "{ald}");
        assert!(ald.contains("has_size(a, large)."), "{ald}");
        assert!(ald.contains("has_surface(b, irregular)."), "{ald}");
        assert!(ald.contains("initially relation(on, a, b)."), "{ald}");
        assert!(ald.contains("initially relation(above, a, b)."), "{ald}");
        assert!(ald.contains("initially -in_hand(rob1, a)."), "{ald}");
    }

    #[test]
    fn bad_facts_are_positioned_errors() {
        let e = SceneFacts::parse(FileId(0), "object(a).\non(a, ghost).").unwrap_err();
        assert!(e[0].message.contains("unknown object `ghost`"), "{e:?}");
        let e = SceneFacts::parse(FileId(0), "object(a).\nfoo(a).").unwrap_err();
        assert!(e[0].message.contains("unknown fact"), "{e:?}");
        let e = SceneFacts::parse(FileId(0), "object(a).\nholds(in_hand(rob1,a), 3).").unwrap_err();
        assert!(e[0].message.contains("step 0"), "{e:?}");
        assert!(SceneFacts::parse(FileId(0), "on(a,").is_err());
    }

    #[test]
    fn goals_are_literal_lists() {
        let shown =
            |t: &str| goal_statement(t).map(|g| crate::action::translate::show_statement(&g.kind));
        assert_eq!(
            shown("on(a, b)").as_deref(),
            Some("goal relation(on, a, b)")
        );
        assert_eq!(
            shown("in_hand(rob1, a), -on(a, table).").as_deref(),
            Some("goal in_hand(rob1, a), -relation(on, a, table)")
        );
        assert_eq!(shown("put the a on b"), None);
    }
}
