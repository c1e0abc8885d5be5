//! The fixed schemas of docs/domain.md 3.2-3.3, generated once per program rather than per AL_d
//! statement: inertia, closed-world assumptions, history and reality checks, and the planning
//! module (only with a goal and the `planning` switch on). Their origins name the schema.

use super::*;

impl Translator<'_> {
    pub(super) fn planning_on(&self) -> bool {
        self.c.flag("planning")
            && self
                .desc
                .statements
                .iter()
                .enumerate()
                .any(|(i, s)| self.c.active[i] && matches!(s.kind, StatementKind::Goal { .. }))
    }

    /// Inertia, CWAs, history and reality checks.
    pub(super) fn general(&mut self) {
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

    /// The planning module of docs/domain.md 3.3.
    pub(super) fn planning(&mut self) {
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
        // docs/domain.md 3.3 writes it pairwise (`:- occurs(A1, I), occurs(A2, I), A1 != A2.`),
        // which has the same answer sets but grounds to |actions|^2 rules per step (6,320 of the
        // 17,000 rules of a step with 80 actions); the aggregate is one weight constraint per step.
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
