//! The rules each AL_d statement translates to (docs/domain.md 3.1): the signature (sort members,
//! steps, fluent and action domains), causal laws, state constraints, executability
//! conditions, defaults and their CR exceptions, `never` constraints, the goal, and the history
//! entries (observations, happened actions, the initial state and its defaults). Every rule is
//! emitted with the statement it came from as its origin.

use super::*;

impl Translator<'_> {
    /// Sort members, the step range, fluent and action domains.
    pub(super) fn signature(&mut self) {
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
    pub(super) fn generic_instance(
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

    pub(super) fn statement(&mut self, i: usize) {
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
}
