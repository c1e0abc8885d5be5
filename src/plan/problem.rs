//! The robot layers' planning problem as one typed value: a domain description (the knowledge
//! base, without objects or state), the scene (objects, static facts, the step-0 literals), the
//! goal, the history (actions that happened, literals observed, by step) and learned axioms, all
//! held as values. [`Problem::description`] builds the AL_d syntax tree of the whole problem and
//! [`Problem::translate`] translates it under typed [`Switches`]; nothing is printed as AL_d or
//! clingo text to be parsed again. Also the conversions between answer-set symbols and AL_d
//! literals that planning, learning and explanation share.
//!
//! Invariants: [`ald_term`] and [`Symbol::from_term`] are inverse on ground terms (constants stay
//! constants, integers integers, classical negation is the literal's sign, never a term's);
//! every built statement has the default span and prints (through `action`'s printer) as the text
//! a person would write; diagnostics of a translation are rendered against the problem's sources.

use crate::action::ast::{Atom, Description, Lit, Statement, StatementKind};
use crate::action::build::{self, Arg};
use crate::action::{self, Options, Switches, Translation};
use crate::base::{Diagnostics, SourceMap};
use crate::control::Symbol;
use crate::syntax::ast::{Term, TermKind, UnaryOp};

/// A planning problem, or a history to explain, as values.
#[derive(Clone, Debug, Default)]
pub struct Problem {
    /// The domain: the knowledge base, with or without a scene of its own.
    pub domain: Description,
    /// The sources the domain was parsed from (for diagnostics).
    pub sources: SourceMap,
    /// The movable objects, declared as `sort movable` (with an empty `sort unknown`); `None`
    /// when the domain declares its objects itself.
    pub objects: Option<Vec<String>>,
    /// Static facts (`has_size(a, small)`).
    pub statics: Vec<Symbol>,
    /// The literals true at step 0 (`relation(on, a, table)`, `-in_hand(rob1, a)`).
    pub initially: Vec<Symbol>,
    /// The goal: one conjunction of literals, replacing the domain's goals when not empty.
    pub goal: Vec<Symbol>,
    /// Actions that happened, with their step.
    pub happened: Vec<(Symbol, usize)>,
    /// Literals observed, with their step.
    pub observed: Vec<(Symbol, usize)>,
    /// Further statements, such as learned axioms ([`crate::learn::term::Axiom::statement`]).
    pub axioms: Vec<Statement>,
}

impl Problem {
    /// The problem of `domain` alone.
    pub fn new(domain: Description, sources: SourceMap) -> Problem {
        Problem {
            domain,
            sources,
            ..Problem::default()
        }
    }

    /// The statements the problem adds to its domain, in the order: objects, statics, initial
    /// state, goal, history, axioms.
    pub fn statements(&self) -> Vec<Statement> {
        let mut out = Vec::new();
        if let Some(objects) = &self.objects {
            let names: Vec<&str> = objects.iter().map(String::as_str).collect();
            out.push(build::sort("movable", &names));
            out.push(build::sort("unknown", &[]));
        }
        out.extend(self.statics.iter().map(|s| build::fact(ald_lit(s))));
        out.extend(self.initially.iter().map(|s| build::initially(ald_lit(s))));
        if !self.goal.is_empty() {
            out.push(build::goal(self.goal.iter().map(ald_lit).collect()));
        }
        out.extend(
            self.happened
                .iter()
                .map(|(a, i)| build::happened(ald_lit(a).atom, *i as i64)),
        );
        out.extend(
            self.observed
                .iter()
                .map(|(l, i)| build::observed(ald_lit(l), *i as i64)),
        );
        out.extend(self.axioms.iter().cloned());
        out
    }

    /// The whole problem as one description: the domain (without its goals when the problem
    /// has one) and [`Problem::statements`].
    pub fn description(&self) -> Description {
        let mut desc = self.domain.clone();
        if !self.goal.is_empty() {
            desc.statements
                .retain(|s| !matches!(s.kind, StatementKind::Goal { .. }));
        }
        desc.statements.extend(self.statements());
        desc
    }

    /// The problem translated with `options` and `switches` (overriding the options' own);
    /// `Err` with the diagnostics rendered against the problem's sources.
    pub fn translate(&self, options: &Options, switches: Switches) -> Result<Translation, String> {
        let options = Options {
            switches,
            ..options.clone()
        };
        let t = action::translate(&self.description(), &options);
        if t.has_errors() {
            let mut d = Diagnostics::default();
            d.extend(t.diagnostics);
            return Err(d.render(&self.sources));
        }
        Ok(t)
    }
}

/// A symbol as an AL_d term: constants stay constants (`rob1`), numbers integers, functions
/// nest; a classically negated function keeps its sign as unary minus.
pub fn ald_term(s: &Symbol) -> Term {
    let kind = match s {
        Symbol::Number(n) => TermKind::Integer(i64::from(*n)),
        Symbol::String(t) => TermKind::String(t.clone()),
        Symbol::Function { name, args, .. } if args.is_empty() => {
            TermKind::Constant(name.as_str().into())
        }
        Symbol::Function { name, args, .. } => TermKind::Function {
            name: name.as_str().into(),
            args: vec![args.iter().map(ald_term).collect()],
            trailing_comma: false,
        },
        Symbol::Inf => TermKind::Infimum,
        Symbol::Sup => TermKind::Supremum,
    };
    let t = Term {
        span: Default::default(),
        kind,
    };
    if s.is_negative() {
        Term {
            span: Default::default(),
            kind: TermKind::Unary {
                op: UnaryOp::Minus,
                arg: Box::new(t),
            },
        }
    } else {
        t
    }
}

/// A symbol as an AL_d literal: its name and arguments, classically negated when the symbol
/// is (`-in_hand(rob1, a)`).
pub fn ald_lit(s: &Symbol) -> Lit {
    let args: Vec<Arg> = s.args().iter().map(|a| Arg::Term(ald_term(a))).collect();
    build::lit(s.is_negative(), s.name().unwrap_or(""), &args)
}

/// The ground symbol of an atom (`pickup(rob1, a)`).
pub fn symbol_of_atom(a: &Atom) -> Option<Symbol> {
    let args: Option<Vec<Symbol>> = a.args.iter().map(Symbol::from_term).collect();
    Some(Symbol::function(a.name.text.as_str(), args?))
}

/// The ground symbol of a literal, negative when the literal is classically negated.
pub fn symbol_of_lit(l: &Lit) -> Option<Symbol> {
    let s = symbol_of_atom(&l.atom)?;
    if l.negated {
        s.complement()
    } else {
        Some(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symbols_and_literals_convert_both_ways() {
        for text in [
            "relation(on,a,table)",
            "-in_hand(rob1,b)",
            "has_size(a,small)",
            "p(f(1,-2),\"s\")",
            "c",
        ] {
            let s = Symbol::parse(text).unwrap();
            assert_eq!(symbol_of_lit(&ald_lit(&s)), Some(s.clone()), "{text}");
        }
    }

    #[test]
    fn a_problem_prints_as_a_person_would_write_it() {
        let s = |t: &str| Symbol::parse(t).unwrap();
        let p = Problem {
            objects: Some(vec!["a".into(), "b".into()]),
            statics: vec![s("has_size(a,small)")],
            initially: vec![s("relation(on,a,table)"), s("-in_hand(rob1,b)")],
            goal: vec![s("relation(on,a,b)")],
            happened: vec![(s("pickup(rob1,a)"), 0)],
            observed: vec![(s("-relation(on,a,table)"), 1)],
            ..Problem::default()
        };
        let shown: Vec<String> = p
            .statements()
            .iter()
            .map(|st| action::translate::show_statement(&st.kind))
            .collect();
        assert_eq!(
            shown,
            [
                "sort movable",
                "sort unknown",
                "has_size(a, small)",
                "initially relation(on, a, table)",
                "initially -in_hand(rob1, b)",
                "goal relation(on, a, b)",
                "happened pickup(rob1, a) at 0",
                "observed -relation(on, a, table) at 1",
            ]
        );
    }
}
