//! Provenance while instantiating: origins of rules (statement and bindings, or auxiliary of
//! a kind), the auxiliary construct being grounded, and dead instances of atoms that end up
//! false.
//!
//! Invariants: with provenance off nothing here records anything; every added rule gets at
//! least one origin (the statement's, or its auxiliary's).

use super::*;

impl Grounder<'_> {
    /// Adds an auxiliary rule of the statement being grounded, recorded as an auxiliary of
    /// `kind` unless a construct (aggregate, condition, ...) or the statement says otherwise.
    pub(super) fn add_aux_rule(&mut self, rule: Rule, kind: AuxKind) -> bool {
        self.add_rule(rule, |g| g.aux_origin(kind))
    }

    pub(super) fn aux_origin(&self, kind: AuxKind) -> Origin {
        let (kind, bindings) = match &self.prov.aux {
            Some((k, b)) => (self.prov.stmt.aux.unwrap_or(*k), b.clone()),
            None => (self.prov.stmt.aux.unwrap_or(kind), Vec::new()),
        };
        Origin {
            rule: RuleOrigin::Auxiliary {
                of_stmt: self.prov.stmt.stmt,
                kind,
                bindings,
            },
            removed: Vec::new(),
        }
    }

    /// The bindings of the statement being grounded under `b` (provenance).
    pub(super) fn bindings(&self, b: &Binding) -> Bindings {
        self.prov
            .stmt
            .names
            .iter()
            .enumerate()
            .filter_map(|(v, name)| {
                let name = (*name)?;
                b.get(v as u32).map(|s| (name.0, s.0))
            })
            .collect()
    }

    /// Enters an auxiliary construct of `kind` (provenance on and none entered yet): returns
    /// what to restore with [`Grounder::leave_aux`].
    pub(super) fn enter_aux(
        &mut self,
        kind: AuxKind,
        b: &Binding,
    ) -> Option<Option<(AuxKind, Bindings)>> {
        if !self.provenance || self.prov.aux.is_some() {
            return None;
        }
        let bindings = self.bindings(b);
        Some(self.prov.aux.replace((kind, bindings)))
    }

    pub(super) fn leave_aux(&mut self, saved: Option<Option<(AuxKind, Bindings)>>) {
        if let Some(s) = saved {
            self.prov.aux = s;
        }
    }

    /// Provenance: an instance of the statement being grounded failed at the body literal
    /// `sym` (`positive`: `sym` cannot be derived; else `not sym` with `sym` a fact). When the
    /// statement's head atoms are known under the bindings so far, the instance is recorded
    /// as a dead rule of those atoms (kept by `simplify` if one ends up false and the literal
    /// is still decided that way). Only the statement's own body counts, not the conditions
    /// of its aggregates; naive components (rounds repeated) record nothing.
    pub(super) fn blocked(&mut self, ctx: &Ctx, positive: bool, sym: SymId, pred: PredId) {
        if self.prov.aux.is_some() || self.naive || self.optimistic {
            return;
        }
        let Some(atoms) = self.prov.stmt.head.take() else {
            return;
        };
        let mut head = Vec::with_capacity(atoms.len());
        for a in &atoms {
            let mut vals: SmallVec<[SymId; 8]> = SmallVec::new();
            for t in &a.args {
                match t.bound_by(&ctx.binding) {
                    true => match t.eval(&mut self.syms, &ctx.binding) {
                        Ok(v) => vals.push(v),
                        Err(_) => break,
                    },
                    false => break,
                }
            }
            if vals.len() != a.args.len() {
                break;
            }
            let s = self.syms.fun(a.name, a.neg, &vals);
            head.push(self.atom_of(s, a.pred).get());
        }
        let complete = head.len() == atoms.len();
        self.prov.stmt.head = Some(atoms);
        if !complete || head.is_empty() {
            return;
        }
        let atom = self.atom_of(sym, pred).get();
        let bindings = self.bindings(&ctx.binding);
        let stmt = self.prov.stmt.stmt;
        let rule = match self.prov.stmt.aux {
            None => RuleOrigin::Statement { stmt, bindings },
            Some(kind) => RuleOrigin::Auxiliary {
                of_stmt: stmt,
                kind,
                bindings,
            },
        };
        self.prov.dead.push(DeadRule {
            head,
            origins: vec![Origin {
                rule,
                removed: Vec::new(),
            }],
            why: DeadReason::Literal { positive, atom },
        });
    }

    /// The origin of an instance of `stmt` (its own rule) under the join state `ctx`: the
    /// statement (or, for a statement the rewriting made, the auxiliary of its kind), the
    /// bindings, and the body literals decided by grounding: a positive literal (or `not not
    /// a`) whose atom is a fact, `not a` whose atom cannot be derived.
    pub(super) fn origin(&mut self, stmt: &NStmt, ctx: &Ctx) -> Origin {
        let bindings = self.bindings(&ctx.binding);
        let rule = match stmt.aux {
            None => RuleOrigin::Statement {
                stmt: stmt.stmt,
                bindings,
            },
            Some(kind) => RuleOrigin::Auxiliary {
                of_stmt: stmt.stmt,
                kind,
                bindings,
            },
        };
        let mut removed = Vec::new();
        for l in &stmt.body {
            let NLit::Pred { sign, atom } = l else {
                continue;
            };
            let Some(sym) = self.atom_sym(atom, &ctx.binding) else {
                continue;
            };
            match sign {
                Sign::Positive | Sign::NotNot => {
                    if let Some(a) = self.find_atom(sym).filter(|&a| self.info(a).fact) {
                        removed.push(RemovedLit {
                            positive: true,
                            atom: a.get(),
                        });
                    }
                }
                Sign::Not => {
                    let kept = self
                        .find_atom(sym)
                        .is_some_and(|a| ctx.body.contains(&-a.lit()));
                    if !kept {
                        let a = self.atom_of(sym, atom.pred);
                        removed.push(RemovedLit {
                            positive: false,
                            atom: a.get(),
                        });
                    }
                }
            }
        }
        Origin { rule, removed }
    }
}
