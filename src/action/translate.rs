//! The translation of an AL_d description and history to a CR-Prolog syntax tree, Π(D, H) of
//! DOMAIN.md section 3, with a side table saying where every generated statement came from.
//!
//! Invariants:
//! - `origins[k]` describes `program.statements[k]` (same length), and every generated
//!   statement's spans are those of the AL_d statement it came from (declaration-derived rules
//!   use the declaration's span; fixed rules such as inertia carry no source statement).
//! - Every variable of a generated rule is bound by a sort atom or by a positive literal, so the
//!   program is safe; sort atoms come from the checker's [`StatementInfo`].
//! - `h(l, I)` is `holds(f, I)` or `-holds(f, I)`; statics keep their own predicates without a
//!   step; actions occur as `occurs(a, I)`. The step variable never clashes with a variable of
//!   the description.
//! - The translation is only meaningful when checking found no error; with errors it still
//!   returns (never panics), and the caller reports the diagnostics.

use crate::base::{Diagnostic, Span};
use crate::syntax::ast::{
    self, BinaryOp, BodyLiteral, CmpOp, ConditionalLiteral, Dialect, Head, Literal, Program,
    RuleKind, Sign, Signature, StatementKind as K, SymbolicAtom, Term, TermKind,
};

use super::ast::*;
use super::check::{check, Checked, Options, Role};
use super::parts::{self, Time};

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

/// The kinds of origins (DOMAIN.md sections 3.1-3.3).
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

// ---- Tree builders -------------------------------------------------------------------------

fn term(span: Span, kind: TermKind) -> Term {
    Term { span, kind }
}

fn var(span: Span, name: &str) -> Term {
    term(span, TermKind::Variable(name.into()))
}

fn constant(span: Span, name: &str) -> Term {
    term(span, TermKind::Constant(name.into()))
}

fn int(span: Span, n: i64) -> Term {
    term(span, TermKind::Integer(n))
}

fn plus(span: Span, lhs: Term, n: i64) -> Term {
    term(
        span,
        TermKind::Binary {
            op: BinaryOp::Add,
            lhs: Box::new(lhs),
            rhs: Box::new(int(span, n)),
        },
    )
}

/// `name(args)`, or the constant `name` without arguments.
fn function(span: Span, name: &str, args: Vec<Term>) -> Term {
    if args.is_empty() {
        constant(span, name)
    } else {
        term(
            span,
            TermKind::Function {
                name: name.into(),
                args: vec![args],
                trailing_comma: false,
            },
        )
    }
}

fn atom(span: Span, negated: bool, name: &str, args: Vec<Term>) -> SymbolicAtom {
    SymbolicAtom {
        span,
        negated,
        name: name.into(),
        args: vec![args],
    }
}

fn lit(span: Span, sign: Sign, a: SymbolicAtom) -> Literal {
    Literal {
        span,
        sign,
        atom: ast::Atom::Symbolic(a),
    }
}

fn pos(span: Span, negated: bool, name: &str, args: Vec<Term>) -> BodyLiteral {
    BodyLiteral::Literal(lit(span, Sign::Positive, atom(span, negated, name, args)))
}

fn neg(span: Span, negated: bool, name: &str, args: Vec<Term>) -> BodyLiteral {
    BodyLiteral::Literal(lit(span, Sign::Not, atom(span, negated, name, args)))
}

fn compare(span: Span, lhs: Term, op: CmpOp, rhs: Term) -> BodyLiteral {
    BodyLiteral::Literal(Literal {
        span,
        sign: Sign::Positive,
        atom: ast::Atom::Comparison {
            lhs: Box::new(lhs),
            op,
            rhs: Box::new(rhs),
        },
    })
}

fn head_of(span: Span, a: SymbolicAtom) -> Head {
    Head::Disjunction(vec![ConditionalLiteral {
        span,
        literal: lit(span, Sign::Positive, a),
        condition: Vec::new(),
        has_colon: false,
    }])
}

/// One line of AL_d for origins.
fn show_lit(l: &Lit) -> String {
    let mut s = String::new();
    if l.negated {
        s.push('-');
    }
    s.push_str(&show_atom(&l.atom));
    s
}

fn show_atom(a: &Atom) -> String {
    let mut s = a.name.text.clone();
    if !a.args.is_empty() {
        s.push('(');
        for (i, t) in a.args.iter().enumerate() {
            if i > 0 {
                s.push_str(", ");
            }
            crate::syntax::printer::term(&mut s, t);
        }
        s.push(')');
    }
    s
}

fn show_body(b: &[BodyItem]) -> String {
    let mut parts = Vec::new();
    for item in b {
        match item {
            BodyItem::Lit(l) => parts.push(show_lit(l)),
            BodyItem::Compare { lhs, op, rhs, .. } => {
                let mut s = String::new();
                crate::syntax::printer::term(&mut s, lhs);
                s.push_str(match op {
                    CmpOp::Eq => " = ",
                    CmpOp::Ne => " != ",
                    CmpOp::Lt => " < ",
                    CmpOp::Le => " <= ",
                    CmpOp::Gt => " > ",
                    CmpOp::Ge => " >= ",
                });
                crate::syntax::printer::term(&mut s, rhs);
                parts.push(s);
            }
        }
    }
    if parts.is_empty() {
        String::new()
    } else {
        format!(" if {}", parts.join(", "))
    }
}

/// The statement in one line.
pub fn show_statement(kind: &StatementKind) -> String {
    match kind {
        StatementKind::Causal {
            action,
            effect,
            body,
        } => format!(
            "{} causes {}{}",
            show_atom(action),
            show_lit(effect),
            show_body(body)
        ),
        StatementKind::Constraint { head, body } => {
            format!("{}{}", show_lit(head), show_body(body))
        }
        StatementKind::Impossible { action, body } => {
            format!("impossible {}{}", show_atom(action), show_body(body))
        }
        StatementKind::Default { head, body } => {
            format!("normally {}{}", show_lit(head), show_body(body))
        }
        StatementKind::Exception {
            default,
            head,
            body,
        } => format!(
            "exception to {}: {} may be assumed{}",
            default.text,
            show_lit(head),
            show_body(body)
        ),
        StatementKind::Never { lit, body } => format!("never {}{}", show_lit(lit), show_body(body)),
        StatementKind::Goal { body } => format!("goal{}", show_body(body).replacen(" if", "", 1)),
        StatementKind::Observed { lit, step } => {
            let mut s = format!("observed {} at ", show_lit(lit));
            crate::syntax::printer::term(&mut s, step);
            s
        }
        StatementKind::Happened { action, step } => {
            let mut s = format!("happened {} at ", show_atom(action));
            crate::syntax::printer::term(&mut s, step);
            s
        }
        StatementKind::Initially { lit } => format!("initially {}", show_lit(lit)),
        StatementKind::InitialDefault { except } => {
            let names: Vec<&str> = except.iter().map(|n| n.text.as_str()).collect();
            if names.is_empty() {
                "initially normally false".to_string()
            } else {
                format!("initially normally false except {}", names.join(", "))
            }
        }
        StatementKind::Declaration { kind, name, params } => {
            let k = match kind {
                DeclKind::Static => "static",
                DeclKind::Inertial => "inertial fluent",
                DeclKind::Defined { .. } => "defined fluent",
                DeclKind::Action => "action",
            };
            let ps: Vec<&str> = params.iter().map(|p| p.text.as_str()).collect();
            if ps.is_empty() {
                format!("{k} {}", name.text)
            } else {
                format!("{k} {}({})", name.text, ps.join(", "))
            }
        }
        StatementKind::Sort { name, .. } => format!("sort {}", name.text),
        _ => String::new(),
    }
}

// ---- The translator ------------------------------------------------------------------------

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

    /// Sort members, the step range, fluent and action domains.
    fn signature(&mut self) {
        self.time = Time::Fixed;
        let desc = self.desc;
        let c = self.c;
        let horizon = c.int("horizon").unwrap_or(0);
        let none = From {
            kind: OriginKind::Signature,
            statement: None,
            span: Span::default(),
        };
        self.emit(
            &none,
            K::Const(Box::new(ast::ConstDef {
                name: "horizon".into(),
                value: int(Span::default(), horizon),
                kind: ast::ConstKind::Default,
                annotated: false,
            })),
        );
        let sp = Span::default();
        self.time = Time::StepRange;
        self.rule(
            &none,
            head_of(
                sp,
                atom(
                    sp,
                    false,
                    "step",
                    vec![term(
                        sp,
                        TermKind::Interval {
                            lo: Box::new(int(sp, 0)),
                            hi: Box::new(constant(sp, "horizon")),
                        },
                    )],
                ),
            ),
            Vec::new(),
        );
        self.time = Time::Fixed;
        for name in &c.sort_order {
            let info = &c.sorts[name];
            let s = &desc.statements[info.statement];
            let StatementKind::Sort { expr, .. } = &s.kind else {
                continue;
            };
            let from = From {
                kind: OriginKind::Signature,
                statement: Some(info.statement),
                span: s.span,
            };
            for part in &expr.parts {
                match part {
                    SortPart::Set(members) => {
                        for m in members {
                            self.rule(
                                &from,
                                head_of(m.span, atom(m.span, false, name, vec![m.clone()])),
                                Vec::new(),
                            );
                        }
                    }
                    SortPart::Range(lo, hi) => {
                        let t = term(
                            expr.span,
                            TermKind::Interval {
                                lo: Box::new(lo.clone()),
                                hi: Box::new(hi.clone()),
                            },
                        );
                        self.rule(
                            &from,
                            head_of(expr.span, atom(expr.span, false, name, vec![t])),
                            Vec::new(),
                        );
                    }
                    SortPart::Name(other) => {
                        let x = var(other.span, "X");
                        self.rule(
                            &from,
                            head_of(other.span, atom(other.span, false, name, vec![x.clone()])),
                            vec![pos(other.span, false, &other.text, vec![x])],
                        );
                    }
                }
            }
            if expr
                .parts
                .iter()
                .all(|p| matches!(p, SortPart::Set(m) if m.is_empty()))
            {
                self.emit(
                    &from,
                    K::Defined(Signature {
                        negated: false,
                        name: name.clone(),
                        arity: 1,
                    }),
                );
            }
        }
        // Domains of fluents and actions; #defined for statics.
        for name in &c.decl_order {
            let d = &c.decls[name];
            let s = &desc.statements[d.statement];
            let from = From {
                kind: OriginKind::Signature,
                statement: Some(d.statement),
                span: s.span,
            };
            let domain = match d.kind {
                DeclKind::Static => {
                    self.emit(
                        &from,
                        K::Defined(Signature {
                            negated: false,
                            name: name.clone(),
                            arity: d.params.len() as u32,
                        }),
                    );
                    continue;
                }
                DeclKind::Inertial => "inertial_fluent",
                DeclKind::Defined { .. } => "defined_fluent",
                DeclKind::Action => "action",
            };
            let (term, body) = self.generic_instance(s.span, name, &d.params);
            self.rule(
                &from,
                head_of(s.span, atom(s.span, false, domain, vec![term])),
                body,
            );
        }
    }

    /// `f(X1, ..., Xn)` with the sort atoms `s1(X1), ..., sn(Xn)`.
    fn generic_instance(
        &self,
        span: Span,
        name: &str,
        params: &[String],
    ) -> (Term, Vec<BodyLiteral>) {
        let vars: Vec<Term> = (1..=params.len())
            .map(|k| var(span, &format!("X{k}")))
            .collect();
        let body = params
            .iter()
            .zip(&vars)
            .map(|(s, v)| pos(span, false, s, vec![v.clone()]))
            .collect();
        (function(span, name, vars), body)
    }

    fn statement(&mut self, i: usize) {
        let s = &self.desc.statements[i];
        let span = s.span;
        let from = |kind| From {
            kind,
            statement: Some(i),
            span,
        };
        let now = self.step_var(span);
        self.time = Time::Fixed;
        match &s.kind {
            // h(l, I+1) :- occurs(a, I), h(p1, I), ..., sorts, step(I), I < horizon.
            StatementKind::Causal {
                action,
                effect,
                body,
            } => {
                let next = plus(span, now.clone(), 1);
                let head = head_of(effect.span, self.literal_atom(effect, &next));
                let mut b = vec![pos(
                    action.span,
                    false,
                    "occurs",
                    vec![
                        function(action.span, &action.name.text, action.args.clone()),
                        now.clone(),
                    ],
                )];
                self.body(body, &now, &mut b);
                self.sorts(i, span, &mut b);
                b.push(self.step_atom(span));
                b.push(self.before_horizon(span));
                self.time = Time::Before;
                self.rule(&from(OriginKind::CausalLaw), head, b);
            }
            // h(l, I) :- h(p1, I), ..., sorts, step(I).   (statics: no step)
            StatementKind::Constraint { head, body } => {
                let is_static = self.c.role(&head.atom.name.text) == Some(Role::Static);
                let h = head_of(head.span, self.literal_atom(head, &now));
                let mut b = Vec::new();
                self.body(body, &now, &mut b);
                self.sorts(i, span, &mut b);
                if is_static {
                    self.time = Time::Fixed;
                    self.rule(&from(OriginKind::Static), h, b);
                } else {
                    b.push(self.step_atom(span));
                    self.time = Time::Now;
                    self.rule(&from(OriginKind::StateConstraint), h, b);
                }
            }
            // -occurs(a, I) :- h(p1, I), ..., sorts, step(I).
            StatementKind::Impossible { action, body } => {
                let h = head_of(
                    action.span,
                    atom(
                        action.span,
                        true,
                        "occurs",
                        vec![
                            function(action.span, &action.name.text, action.args.clone()),
                            now.clone(),
                        ],
                    ),
                );
                let mut b = Vec::new();
                self.body(body, &now, &mut b);
                self.sorts(i, span, &mut b);
                b.push(self.step_atom(span));
                self.time = Time::Before;
                self.rule(&from(OriginKind::ExecutabilityCondition), h, b);
            }
            // h(l, I) :- h(p1, I), ..., not h(l̄, I), sorts, step(I).
            StatementKind::Default { head, body } => {
                let h = head_of(head.span, self.literal_atom(head, &now));
                let mut b = Vec::new();
                self.body(body, &now, &mut b);
                b.push(self.not_complement(head, &now));
                self.sorts(i, span, &mut b);
                b.push(self.step_atom(span));
                self.time = Time::Now;
                self.rule(&from(OriginKind::Default), h, b);
            }
            // label(Vars, I): h(l̄, I) :+ h(p1, I), ..., sorts, step(I).
            StatementKind::Exception {
                default,
                head,
                body,
            } => {
                let h = head_of(head.span, self.literal_atom(head, &now));
                let mut b = Vec::new();
                self.body(body, &now, &mut b);
                self.sorts(i, span, &mut b);
                b.push(self.step_atom(span));
                let name = s.label.as_ref().unwrap_or(default).text.to_lowercase();
                let mut args: Vec<Term> = self.c.info[i]
                    .var_sorts
                    .iter()
                    .map(|(v, _)| var(span, v))
                    .collect();
                args.push(now.clone());
                let label = function(span, &name, args);
                self.time = Time::Now;
                self.emit(
                    &from(OriginKind::CrException),
                    K::Rule(ast::Rule {
                        head: h,
                        body: b,
                        kind: RuleKind::ConsistencyRestoring {
                            label: Some(Box::new(label)),
                        },
                    }),
                );
            }
            StatementKind::Never { lit: l, body } => match self.c.word("stability_constraint") {
                Some("off") => {}
                // :- h(l, I+1), not h(l, I), h(p1, I+1), ..., sorts, step(I), I < horizon.
                Some("creation_only") => {
                    let next = plus(span, now.clone(), 1);
                    let mut b = vec![BodyLiteral::Literal(lit(
                        l.span,
                        Sign::Positive,
                        self.literal_atom(l, &next),
                    ))];
                    b.push(BodyLiteral::Literal(lit(
                        l.span,
                        Sign::Not,
                        self.literal_atom(l, &now),
                    )));
                    self.body(body, &next, &mut b);
                    self.sorts(i, span, &mut b);
                    b.push(self.step_atom(span));
                    b.push(self.before_horizon(span));
                    self.time = Time::Before;
                    self.rule(&from(OriginKind::Never), Head::None, b);
                }
                // :- h(l, I), h(p1, I), ..., sorts, step(I).
                _ => {
                    let mut b = vec![BodyLiteral::Literal(lit(
                        l.span,
                        Sign::Positive,
                        self.literal_atom(l, &now),
                    ))];
                    self.body(body, &now, &mut b);
                    self.sorts(i, span, &mut b);
                    b.push(self.step_atom(span));
                    self.time = Time::Now;
                    self.rule(&from(OriginKind::Never), Head::None, b);
                }
            },
            // goal(I) :- h(g1, I), ..., sorts, step(I).
            StatementKind::Goal { body } => {
                if !self.planning_on() {
                    return;
                }
                let h = head_of(span, atom(span, false, "goal", vec![now.clone()]));
                let mut b = Vec::new();
                self.body(body, &now, &mut b);
                self.sorts(i, span, &mut b);
                b.push(self.step_atom(span));
                self.time = Time::Now;
                self.rule(&from(OriginKind::Planning), h, b);
            }
            // obs(f, true|false, t).
            StatementKind::Observed { lit: l, step } => {
                let f = function(l.atom.span, &l.atom.name.text, l.atom.args.clone());
                let value = constant(l.span, if l.negated { "false" } else { "true" });
                let h = head_of(span, atom(span, false, "obs", vec![f, value, step.clone()]));
                self.rule(&from(OriginKind::History), h, Vec::new());
            }
            // hpd(a, t).
            StatementKind::Happened { action, step } => {
                let a = function(action.span, &action.name.text, action.args.clone());
                let h = head_of(span, atom(span, false, "hpd", vec![a, step.clone()]));
                self.rule(&from(OriginKind::History), h, Vec::new());
            }
            // h(l, 0).
            StatementKind::Initially { lit: l } => {
                let h = head_of(span, self.literal_atom(l, &int(span, 0)));
                self.rule(&from(OriginKind::History), h, Vec::new());
            }
            // -holds(f(X1..Xn), 0) :- sorts, not known0(f(X1..Xn)), not holds(f(X1..Xn), 0).
            StatementKind::InitialDefault { except } => {
                let c = self.c;
                for name in &c.decl_order {
                    let d = &c.decls[name];
                    if d.kind != DeclKind::Inertial || except.iter().any(|e| &e.text == name) {
                        continue;
                    }
                    let (f, mut b) = self.generic_instance(span, name, &d.params);
                    b.push(neg(span, false, "known0", vec![f.clone()]));
                    b.push(neg(span, false, "holds", vec![f.clone(), int(span, 0)]));
                    let h = head_of(span, atom(span, true, "holds", vec![f, int(span, 0)]));
                    self.rule(&from(OriginKind::History), h, b);
                }
            }
            _ => {}
        }
    }

    fn planning_on(&self) -> bool {
        self.c.flag("planning")
            && self
                .desc
                .statements
                .iter()
                .enumerate()
                .any(|(i, s)| self.c.active[i] && matches!(s.kind, StatementKind::Goal { .. }))
    }

    /// Inertia, CWAs, history and reality checks.
    fn general(&mut self) {
        let sp = Span::default();
        let i = self.step_var(sp);
        let next = plus(sp, i.clone(), 1);
        let f = var(sp, "F");
        let a = var(sp, "A");
        let v = var(sp, "V");
        let from = |kind| From {
            kind,
            statement: None,
            span: sp,
        };
        // holds(F, I+1) :- inertial_fluent(F), holds(F, I), not -holds(F, I+1), I < horizon.
        self.time = Time::Before;
        for negated in [false, true] {
            let h = head_of(
                sp,
                atom(sp, negated, "holds", vec![f.clone(), next.clone()]),
            );
            let b = vec![
                pos(sp, false, "inertial_fluent", vec![f.clone()]),
                pos(sp, negated, "holds", vec![f.clone(), i.clone()]),
                neg(sp, !negated, "holds", vec![f.clone(), next.clone()]),
                self.before_horizon(sp),
            ];
            self.rule(&from(OriginKind::Inertia), h, b);
        }
        // -holds(f(X..), I) :- sorts, step(I), not holds(f(X..), I).   (defined fluents with CWA)
        self.time = Time::Now;
        let c = self.c;
        for name in &c.decl_order {
            let d = &c.decls[name];
            if d.kind != (DeclKind::Defined { cwa: true }) {
                continue;
            }
            let s = &self.desc.statements[d.statement];
            let span = s.span;
            let (ft, mut b) = self.generic_instance(span, name, &d.params);
            let now = self.step_var(span);
            b.push(self.step_atom(span));
            b.push(neg(span, false, "holds", vec![ft.clone(), now.clone()]));
            let h = head_of(span, atom(span, true, "holds", vec![ft, now]));
            self.rule(
                &From {
                    kind: OriginKind::Cwa,
                    statement: Some(d.statement),
                    span,
                },
                h,
                b,
            );
        }
        // -occurs(A, I) :- action(A), step(I), not occurs(A, I).
        self.time = Time::Before;
        let h = head_of(sp, atom(sp, true, "occurs", vec![a.clone(), i.clone()]));
        let b = vec![
            pos(sp, false, "action", vec![a.clone()]),
            self.step_atom(sp),
            neg(sp, false, "occurs", vec![a.clone(), i.clone()]),
        ];
        self.rule(&from(OriginKind::Cwa), h, b);
        // occurs(A, I) :- hpd(A, I).
        let h = head_of(sp, atom(sp, false, "occurs", vec![a.clone(), i.clone()]));
        self.rule(
            &from(OriginKind::History),
            h,
            vec![pos(sp, false, "hpd", vec![a.clone(), i.clone()])],
        );
        // :- obs(F, true, I), -holds(F, I).   :- obs(F, false, I), holds(F, I).
        self.time = Time::Now;
        for (value, negated) in [("true", true), ("false", false)] {
            let b = vec![
                pos(
                    sp,
                    false,
                    "obs",
                    vec![f.clone(), constant(sp, value), i.clone()],
                ),
                pos(sp, negated, "holds", vec![f.clone(), i.clone()]),
            ];
            self.rule(&from(OriginKind::History), Head::None, b);
        }
        // holds(F, 0) :- obs(F, true, 0).   -holds(F, 0) :- obs(F, false, 0).
        // With observations_as_facts, at every step I instead of 0.
        let when = if c.flag("observations_as_facts") {
            self.time = Time::Now;
            i.clone()
        } else {
            self.time = Time::Fixed;
            int(sp, 0)
        };
        for (value, negated) in [("true", false), ("false", true)] {
            let h = head_of(
                sp,
                atom(sp, negated, "holds", vec![f.clone(), when.clone()]),
            );
            let b = vec![pos(
                sp,
                false,
                "obs",
                vec![f.clone(), constant(sp, value), when.clone()],
            )];
            self.rule(&from(OriginKind::History), h, b);
        }
        // known0(F) :- obs(F, V, 0).
        self.time = Time::Fixed;
        let h = head_of(sp, atom(sp, false, "known0", vec![f.clone()]));
        let b = vec![pos(sp, false, "obs", vec![f.clone(), v, int(sp, 0)])];
        self.rule(&from(OriginKind::History), h, b);
        for (name, arity) in [("obs", 3), ("hpd", 2)] {
            self.emit(
                &from(OriginKind::History),
                K::Defined(Signature {
                    negated: false,
                    name: name.into(),
                    arity,
                }),
            );
        }
    }

    /// The planning module of DOMAIN.md 3.3.
    fn planning(&mut self) {
        if !self.planning_on() {
            return;
        }
        let sp = Span::default();
        let i = self.step_var(sp);
        let a = var(sp, "A");
        let from = From {
            kind: OriginKind::Planning,
            statement: None,
            span: sp,
        };
        let mode = self.c.word("horizon_mode").unwrap_or("fixed");
        // In the transition mode one action occurs at every step before the horizon, goal or not.
        let transition = mode == "transition";
        if mode == "iterative" || mode == "incremental" {
            // :- not goal(horizon).   (incremental: `:- query(t), not goal(t).` in check(t))
            self.time = Time::Query;
            self.rule(
                &from,
                Head::None,
                vec![neg(sp, false, "goal", vec![constant(sp, "horizon")])],
            );
        } else if !transition {
            // success :- goal(I).   :- not success.
            self.time = Time::Fixed;
            self.rule(
                &from,
                head_of(sp, atom(sp, false, "success", Vec::new())),
                vec![pos(sp, false, "goal", vec![i.clone()])],
            );
            self.rule(
                &from,
                Head::None,
                vec![neg(sp, false, "success", Vec::new())],
            );
        }
        // occurs(A, I) | -occurs(A, I) :- action(A), step(I), I < horizon, not goal(I).
        let alt = |negated| ConditionalLiteral {
            span: sp,
            literal: lit(
                sp,
                Sign::Positive,
                atom(sp, negated, "occurs", vec![a.clone(), i.clone()]),
            ),
            condition: Vec::new(),
            has_colon: false,
        };
        let mut b = vec![
            pos(sp, false, "action", vec![a.clone()]),
            self.step_atom(sp),
            self.before_horizon(sp),
        ];
        if !transition {
            b.push(neg(sp, false, "goal", vec![i.clone()]));
        }
        self.time = Time::Before;
        self.rule(&from, Head::Disjunction(vec![alt(false), alt(true)]), b);
        // One action per step: `:- #count { A1 : occurs(A1, I) } > 1, step(I), I < horizon.`
        // DOMAIN.md 3.3 writes it pairwise (`:- occurs(A1, I), occurs(A2, I), A1 != A2.`), which
        // has the same answer sets but grounds to |actions|^2 rules per step (6,320 of the 17,000
        // rules of a step with 80 actions); the aggregate is one weight constraint per step.
        let a1 = var(sp, "A1");
        let count = ast::BodyAggregate {
            span: sp,
            function: ast::AggregateFunction::Count,
            lower: None,
            elements: vec![ast::BodyAggregateElement {
                span: sp,
                terms: vec![a1.clone()],
                condition: vec![lit(
                    sp,
                    Sign::Positive,
                    atom(sp, false, "occurs", vec![a1, i.clone()]),
                )],
            }],
            set_syntax: Vec::new(),
            upper: Some(ast::Guard {
                op: CmpOp::Gt,
                term: int(sp, 1),
            }),
        };
        let b = vec![
            BodyLiteral::Aggregate {
                sign: Sign::Positive,
                aggregate: Box::new(count),
            },
            self.step_atom(sp),
            self.before_horizon(sp),
        ];
        self.rule(&from, Head::None, b);
        // something_happened(I) :- occurs(A, I).
        self.rule(
            &from,
            head_of(sp, atom(sp, false, "something_happened", vec![i.clone()])),
            vec![pos(sp, false, "occurs", vec![a, i.clone()])],
        );
        // :- not goal(I), not something_happened(I), step(I), I < horizon.
        let mut b = vec![self.step_atom(sp), self.before_horizon(sp)];
        if !transition {
            b.push(neg(sp, false, "goal", vec![i.clone()]));
        }
        b.push(neg(sp, false, "something_happened", vec![i]));
        self.rule(&from, Head::None, b);
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
        };
        let t = translate(&parsed.description, &options);
        assert!(!t.origins.iter().any(|o| o.kind == OriginKind::Planning));
    }
}
