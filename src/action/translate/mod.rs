//! The translation of an AL_d description and history to a CR-Prolog syntax tree, Π(D, H) of
//! docs/domain.md section 3, with a side table saying where every generated statement came from.
//!
//! Invariants:
//! - `origins[k]` describes `program.statements[k]` (same length), and every generated
//!   statement's spans are those of the AL_d statement it came from (declaration-derived rules
//!   use the declaration's span; fixed rules such as inertia carry no source statement).
//! - Every variable of a generated rule is bound by a sort atom or by a positive literal, so the
//!   program is safe; sort atoms come from the checker's `StatementInfo`.
//! - `h(l, I)` is `holds(f, I)` or `-holds(f, I)`; statics keep their own predicates without a
//!   step; actions occur as `occurs(a, I)`. The step variable never clashes with a variable of
//!   the description.
//! - The translation is only meaningful when checking found no error; with errors it still
//!   returns (never panics), and the caller reports the diagnostics.

use crate::base::{Diagnostic, Span};
use crate::syntax::ast::{
    self, BodyLiteral, CmpOp, ConditionalLiteral, Dialect, Head, Literal, Program, RuleKind, Sign,
    Signature, StatementKind as K, SymbolicAtom, Term, TermKind,
};

use super::ast::*;
use super::check::{check, Checked, Role};
use super::parts::{self, Time};
use super::switches::Options;

/// Where a generated statement came from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AxiomOrigin {
    /// What kind of AL_d statement or translation schema produced it.
    pub kind: OriginKind,
    /// The AL_d statement's label (`C1`), if it has one.
    pub label: Option<String>,
    /// The AL_d statement's index in the description, for schemas of one statement.
    pub statement: Option<usize>,
    /// The AL_d statement's span (file and bytes), when there is one.
    pub span: Option<Span>,
    /// The AL_d statement in one line (`putdown(R, A, L) causes relation(on, A, L)`), or the
    /// schema's name (`inertia`).
    pub text: String,
}

/// The kinds of origins (docs/domain.md sections 3.1-3.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OriginKind {
    /// Sort members, the step range, fluent and action domains, `#defined` declarations.
    Signature,
    /// A static fact or rule.
    Static,
    /// `a causes l if p`.
    CausalLaw,
    /// `l if p`.
    StateConstraint,
    /// `impossible a if p`.
    ExecutabilityCondition,
    /// `normally l if p`.
    Default,
    /// `exception to D: l may be assumed if p`, as a CR rule.
    CrException,
    /// `never l`.
    Never,
    /// The inertia axioms.
    Inertia,
    /// Closed-world assumptions (defined fluents, actions).
    Cwa,
    /// Observations, happened actions, initial state, reality checks, D0.
    History,
    /// Goal, success, generation, one action per step, no idle step.
    Planning,
}

impl OriginKind {
    /// The kind in words.
    pub fn name(self) -> &'static str {
        match self {
            OriginKind::Signature => "signature",
            OriginKind::Static => "static",
            OriginKind::CausalLaw => "causal law",
            OriginKind::StateConstraint => "state constraint",
            OriginKind::ExecutabilityCondition => "executability condition",
            OriginKind::Default => "default",
            OriginKind::CrException => "CR exception",
            OriginKind::Never => "never constraint",
            OriginKind::Inertia => "inertia",
            OriginKind::Cwa => "CWA",
            OriginKind::History => "history",
            OriginKind::Planning => "planning",
        }
    }
}

/// The translated program with its origins.
#[derive(Clone, Debug, Default)]
pub struct Translation {
    /// The CR-Prolog program (clingo dialect with `:+` rules).
    pub program: Program,
    /// One origin per statement of `program`.
    pub origins: Vec<AxiomOrigin>,
    /// Errors of checking (the program is meaningless when there are any).
    pub diagnostics: Vec<Diagnostic>,
    /// The switch values used.
    pub checked: Checked,
}

impl Translation {
    /// True when checking reported an error.
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(Diagnostic::is_error)
    }
}

/// Checks and translates `desc` under `options`.
pub fn translate(desc: &Description, options: &Options) -> Translation {
    let checked = check(desc, options);
    let mut t = Translator {
        desc,
        c: &checked,
        out: Vec::new(),
        origins: Vec::new(),
        times: Vec::new(),
        time: Time::Fixed,
        step: step_variable(desc),
    };
    t.run();
    let diagnostics = checked.diagnostics.clone();
    let Translator {
        mut out,
        mut origins,
        times,
        step,
        ..
    } = t;
    if checked.word("horizon_mode") == Some("incremental") {
        (out, origins) = parts::split(out, origins, &times, &step);
    }
    Translation {
        program: Program {
            dialect: Dialect::Clingo,
            statements: out,
        },
        origins,
        diagnostics,
        checked,
    }
}

/// A step variable name used by no statement of the description.
fn step_variable(desc: &Description) -> String {
    let mut used = std::collections::BTreeSet::new();
    let mut note = |t: &Term| {
        let mut vs = Vec::new();
        super::check::term_vars(t, &mut vs);
        for (v, _) in vs {
            used.insert(v.to_string());
        }
    };
    for s in &desc.statements {
        for_each_term(&s.kind, &mut note);
    }
    let mut name = "I".to_string();
    while used.contains(&name) {
        name.push('\'');
    }
    name
}

/// Calls `f` on every term of a statement.
fn for_each_term(kind: &StatementKind, f: &mut dyn FnMut(&Term)) {
    let atom = |a: &Atom, f: &mut dyn FnMut(&Term)| a.args.iter().for_each(&mut *f);
    let body = |b: &[BodyItem], f: &mut dyn FnMut(&Term)| {
        for item in b {
            match item {
                BodyItem::Lit(l) => l.atom.args.iter().for_each(&mut *f),
                BodyItem::Compare { lhs, rhs, .. } => {
                    f(lhs);
                    f(rhs)
                }
            }
        }
    };
    match kind {
        StatementKind::Causal {
            action,
            effect,
            body: b,
        } => {
            atom(action, f);
            atom(&effect.atom, f);
            body(b, f);
        }
        StatementKind::Constraint { head, body: b }
        | StatementKind::Default { head, body: b }
        | StatementKind::Exception { head, body: b, .. }
        | StatementKind::Never { lit: head, body: b } => {
            atom(&head.atom, f);
            body(b, f);
        }
        StatementKind::Impossible { action, body: b } => {
            atom(action, f);
            body(b, f);
        }
        StatementKind::Goal { body: b } => body(b, f),
        _ => {}
    }
}

mod schemas;
mod show;
mod statements;

use crate::syntax::build::*;
pub use show::show_statement;

struct Translator<'d> {
    desc: &'d Description,
    c: &'d Checked,
    out: Vec<ast::Statement>,
    origins: Vec<AxiomOrigin>,
    /// When each statement of `out` applies (for the incremental mode's parts).
    times: Vec<Time>,
    /// The time of the statements being emitted.
    time: Time,
    /// The step variable.
    step: String,
}

/// The origin of the statement being translated.
struct From {
    kind: OriginKind,
    statement: Option<usize>,
    span: Span,
}

impl<'d> Translator<'d> {
    fn emit(&mut self, from: &From, kind: K) {
        let (label, text) = match from.statement {
            Some(i) => {
                let s = &self.desc.statements[i];
                (
                    s.label.as_ref().map(|l| l.text.clone()),
                    show_statement(&s.kind),
                )
            }
            None => (None, from.kind.name().to_string()),
        };
        self.origins.push(AxiomOrigin {
            kind: from.kind,
            label,
            statement: from.statement,
            span: from.statement.map(|_| from.span),
            text,
        });
        self.out.push(ast::Statement {
            span: from.span,
            kind,
        });
        self.times.push(self.time);
    }

    fn rule(&mut self, from: &From, head: Head, body: Vec<BodyLiteral>) {
        self.emit(
            from,
            K::Rule(ast::Rule {
                head,
                body,
                kind: RuleKind::Normal,
            }),
        );
    }

    fn step_var(&self, span: Span) -> Term {
        var(span, &self.step)
    }

    /// `step(I)`
    fn step_atom(&self, span: Span) -> BodyLiteral {
        pos(span, false, "step", vec![self.step_var(span)])
    }

    /// `I < horizon`
    fn before_horizon(&self, span: Span) -> BodyLiteral {
        compare(
            span,
            self.step_var(span),
            CmpOp::Lt,
            constant(span, "horizon"),
        )
    }

    /// `h(l, T)` for a fluent literal, the static literal itself, or a sort atom.
    fn literal_atom(&self, l: &Lit, at: &Term) -> SymbolicAtom {
        let span = l.span;
        match self.c.role(&l.atom.name.text) {
            Some(Role::Fluent) => atom(
                span,
                l.negated,
                "holds",
                vec![
                    function(span, &l.atom.name.text, l.atom.args.clone()),
                    at.clone(),
                ],
            ),
            Some(Role::Action) => atom(
                span,
                l.negated,
                "occurs",
                vec![
                    function(span, &l.atom.name.text, l.atom.args.clone()),
                    at.clone(),
                ],
            ),
            _ => atom(span, l.negated, &l.atom.name.text, l.atom.args.clone()),
        }
    }

    fn body(&self, items: &[BodyItem], at: &Term, out: &mut Vec<BodyLiteral>) {
        for item in items {
            match item {
                BodyItem::Lit(l) => out.push(BodyLiteral::Literal(lit(
                    l.span,
                    Sign::Positive,
                    self.literal_atom(l, at),
                ))),
                BodyItem::Compare { span, lhs, op, rhs } => {
                    out.push(compare(*span, lhs.clone(), *op, rhs.clone()))
                }
            }
        }
    }

    /// The sort atoms of statement `i`.
    fn sorts(&self, i: usize, span: Span, out: &mut Vec<BodyLiteral>) {
        let info = &self.c.info[i];
        for (v, sorts) in &info.var_sorts {
            for s in sorts {
                // A sort condition written in the body (`positional(S1)`) is not repeated.
                let written = out.iter().any(|b| match b {
                    BodyLiteral::Literal(Literal {
                        sign: Sign::Positive,
                        atom: ast::Atom::Symbolic(a),
                        ..
                    }) => {
                        !a.negated
                            && a.name == *s
                            && matches!(a.args.as_slice(), [args] if matches!(
                                args.as_slice(),
                                [Term { kind: TermKind::Variable(x), .. }] if x == v
                            ))
                    }
                    _ => false,
                });
                if !written {
                    out.push(pos(span, false, s, vec![var(span, v)]));
                }
            }
        }
        for (t, s) in &info.term_sorts {
            out.push(pos(span, false, s, vec![t.clone()]));
        }
    }

    /// The complement of a literal's fluent atom at `at`, default-negated: `not h(l̄, T)`.
    fn not_complement(&self, l: &Lit, at: &Term) -> BodyLiteral {
        let mut a = self.literal_atom(l, at);
        a.negated = !a.negated;
        BodyLiteral::Literal(lit(l.span, Sign::Not, a))
    }

    fn run(&mut self) {
        self.signature();
        for i in 0..self.desc.statements.len() {
            if self.c.active[i] {
                self.statement(i);
            }
        }
        self.general();
        self.planning();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::FileId;

    fn translate_text(text: &str) -> Translation {
        let parsed = super::super::parse(FileId(0), text);
        assert!(!parsed.has_errors(), "{:?}", parsed.diagnostics);
        translate(&parsed.description, &Options::default())
    }

    const SMALL: &str = "sort s = {a, b}. inertial fluent f(s). defined fluent g(s). \
                         action go(s). C1: go(I) causes f(I). S1: g(X) if f(X). \
                         E1: impossible go(X) if f(X). goal f(a).";

    #[test]
    fn the_step_variable_avoids_the_descriptions_variables() {
        let t = translate_text(SMALL);
        assert!(!t.has_errors(), "{:?}", t.diagnostics);
        let printed = crate::syntax::print(&t.program);
        assert!(
            printed.contains(
                "holds(f(I), I' + 1) :- occurs(go(I), I'), s(I), step(I'), I' < horizon."
            ),
            "{printed}"
        );
    }

    #[test]
    fn every_statement_has_an_origin_of_its_kind() {
        let t = translate_text(SMALL);
        assert_eq!(t.program.statements.len(), t.origins.len());
        let kind_of = |label: &str| -> Vec<OriginKind> {
            t.origins
                .iter()
                .filter(|o| o.label.as_deref() == Some(label))
                .map(|o| o.kind)
                .collect()
        };
        assert_eq!(kind_of("C1"), vec![OriginKind::CausalLaw]);
        assert_eq!(kind_of("S1"), vec![OriginKind::StateConstraint]);
        assert_eq!(kind_of("E1"), vec![OriginKind::ExecutabilityCondition]);
        let c1 = t
            .origins
            .iter()
            .find(|o| o.label.as_deref() == Some("C1"))
            .unwrap();
        assert_eq!(c1.text, "go(I) causes f(I)");
        assert_eq!(c1.statement, Some(4));
        // Spans of generated statements are the AL_d statement's.
        let k = t
            .origins
            .iter()
            .position(|o| o.label.as_deref() == Some("C1"))
            .unwrap();
        assert_eq!(Some(t.program.statements[k].span), c1.span);
        for kind in [
            OriginKind::Inertia,
            OriginKind::Cwa,
            OriginKind::History,
            OriginKind::Planning,
            OriginKind::Signature,
        ] {
            assert!(t.origins.iter().any(|o| o.kind == kind), "{kind:?}");
        }
    }

    #[test]
    fn no_planning_module_without_a_goal_or_when_switched_off() {
        let t = translate_text("sort s = {a}. inertial fluent f(s). action go(s).");
        assert!(!t.origins.iter().any(|o| o.kind == OriginKind::Planning));
        let parsed = super::super::parse(FileId(0), SMALL);
        let options = Options {
            profile: None,
            overrides: vec![("planning".into(), Value::Bool(false))],
            ..Options::default()
        };
        let t = translate(&parsed.description, &options);
        assert!(!t.origins.iter().any(|o| o.kind == OriginKind::Planning));
    }
}
