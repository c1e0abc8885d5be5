//! Statements: `#const` definitions (with `-c` overrides, in dependency order), then every
//! statement of the program (show, external, minimize, heuristic, edge, projection, CR rules)
//! rewritten; rules go to `rule`.
//!
//! Invariant: statement ids are the statements' indexes in the program, never renumbered.

use super::pool::*;
use super::*;

impl Rewriter<'_> {
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
        self.theory_definitions(program);
        for (k, v) in overrides {
            self.consts.entry(k).or_insert(v);
        }
        let lowered;
        let program = if program.dialect == ast::Dialect::Sparc {
            lowered = crate::ground::sparc::lower(self, program);
            &lowered
        } else {
            program
        };
        // A statement gives one rewritten statement, or a few for pools and bound checks:
        // growing `stmts` by doubling from empty would move every large `NStmt` again at each
        // step. Room for one each and an eighth more (at least 16) avoids most of those moves
        // and over-allocates less than doubling does.
        let n = program.statements.len();
        self.out.stmt_spans.reserve(n);
        self.out.stmts.reserve(n + (n / 8).max(16));
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
            self.note_domains(i as u32, st);
        }
        self.rank_facts();
    }

    /// Evaluates the `#const` definitions not overridden by `-c`, each after the constants its
    /// value names (`#const a=b. #const b=1.` gives `a` the value 1, as gringo does). A second
    /// definition of a name is gringo's `redefinition of constant` error (the first one
    /// stays); definitions naming each other in a cycle are a `cyclic constant definition`
    /// error and stay unevaluated. A definition naming itself (`#const a=a.`) is no cycle: the
    /// name stays a symbol.
    pub(super) fn const_definitions(
        &mut self,
        program: &ast::Program,
        overrides: &HashMap<String, SymId>,
    ) {
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
    pub(super) fn minimize_kind(
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

    pub(super) fn sig_pred(&mut self, s: &ast::Signature) -> PredId {
        self.pred(&s.name, s.arity, s.negated)
    }

    pub(super) fn statement(&mut self, index: u32, st: &ast::Statement) {
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
                    self.out.show.signature_sites.push((p, st.span));
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
                // `#project p/2.` is `#project p(X0,X1).`: every p/2 atom the program can
                // derive is projected, as gringo does.
                ast::Project::Signature(s) => {
                    let args: Vec<ast::Term> = (0..s.arity)
                        .map(|i| ast::Term {
                            span: st.span,
                            kind: ast::TermKind::Variable(ast::Name::new(&format!("X{i}"))),
                        })
                        .collect();
                    let atom = ast::SymbolicAtom {
                        span: st.span,
                        negated: s.negated,
                        name: ast::Name::new(&s.name),
                        args: vec![args],
                    };
                    let project = ast::Project::Atom {
                        atom,
                        body: Vec::new(),
                    };
                    let kind = K::Project(Box::new(project));
                    self.statement(
                        index,
                        &ast::Statement {
                            span: st.span,
                            kind,
                        },
                    );
                }
                ast::Project::Atom { atom, body } => {
                    // The atom ranges over its predicate's possible atoms and binds the
                    // variables it alone has, as in gringo: `#project p(X).` projects
                    // onto every p/1 atom.
                    self.atom_statements(index, st.span, atom, body, true, |_, a, _, _| {
                        Some(NKind::Project(a))
                    });
                }
            },
            K::External(e) => self.external(index, st.span, e),
            K::Heuristic(h) => self.heuristic(index, st.span, h),
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
            K::Const(_) | K::ProgramPart(_) | K::Theory(_) | K::Error => {}
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

    /// One statement per unpooled atom and body of `#project`, `#external` or `#heuristic`:
    /// the atom, then the statement's own terms (`kind` rewrites them and gives the kind, or
    /// `None` to drop the instance), then the body. With `ranges`, the atom also joins the
    /// condition, so that the statement ranges over its predicate's atoms and binds the
    /// variables the atom alone has, as in gringo (emit leaves it out of the condition).
    fn atom_statements(
        &mut self,
        index: u32,
        span: Span,
        atom: &ast::SymbolicAtom,
        body: &[ast::BodyLiteral],
        ranges: bool,
        mut kind: impl FnMut(&mut Self, NAtom, &mut Vars, &mut Vec<NLit>) -> Option<NKind>,
    ) {
        for a in unpool_atom(atom) {
            for b in unpool_body(body) {
                let mut vars = Vars::default();
                let mut out = Vec::new();
                let mut extra = Vec::new();
                let Some(a) = self.atom(&a, &mut vars, &mut extra) else {
                    continue;
                };
                let ranging = ranges.then(|| a.clone());
                let Some(kind) = kind(self, a, &mut vars, &mut extra) else {
                    continue;
                };
                if self.body(&b, &mut vars, &mut out).is_none() {
                    continue;
                }
                if let Some(atom) = ranging {
                    out.push(NLit::Pred {
                        sign: Sign::Positive,
                        atom,
                    });
                }
                out.append(&mut extra);
                self.finish(index, span, NHead::None, out, kind, vars);
            }
        }
    }

    /// `#external a : body. [value]`: one statement per unpooled atom and body.
    fn external(&mut self, index: u32, span: Span, e: &ast::External) {
        self.atom_statements(
            index,
            span,
            &e.atom,
            &e.body,
            false,
            |rw, a, vars, extra| {
                // The value is a term of the instance (`[X]`); omitted, it is false.
                let value = match &e.value {
                    Some(t) => rw.term(t, vars, extra)?,
                    None => NTerm::Sym(rw.syms.fun_str("false", false, &[])),
                };
                Some(NKind::External(a, value))
            },
        );
    }

    /// `#heuristic a : body. [weight@priority, modifier]`: one statement per unpooled atom
    /// and body (and, once per program, a warning on what Lucent's solver follows).
    fn heuristic(&mut self, index: u32, span: Span, h: &ast::Heuristic) {
        // Said once per program: what of the statements Lucent's solver follows.
        if !self
            .diags
            .items()
            .iter()
            .any(|d| d.message.starts_with("#heuristic"))
        {
            self.diags.push(Diagnostic::warning(
                crate::base::WarningKind::Other,
                span,
                "#heuristic: Lucent follows these only under --heuristic=domain, and only \
                 those without a condition (modifiers level, sign, true, false; init \
                 and factor are ignored); they change no answer set, only the order \
                 in which answer sets are found",
            ));
        }
        // As for #project, the atom ranges over its predicate's atoms (so the statement
        // waits for them and binds its own variables, as gringo).
        self.atom_statements(index, span, &h.atom, &h.body, true, |rw, a, vars, extra| {
            let weight = rw.term(&h.weight, vars, extra)?;
            let priority = match &h.priority {
                Some(p) => rw.term(p, vars, extra)?,
                None => NTerm::Sym(rw.syms.int(0)),
            };
            let modifier = rw.term(&h.modifier, vars, extra)?;
            Some(NKind::Heuristic {
                atom: a,
                weight,
                priority,
                modifier,
            })
        });
    }
}

/// The constant names (candidates for `#const` values) in a term.
pub(super) fn const_names<'t>(t: &'t ast::Term, out: &mut Vec<&'t str>) {
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
