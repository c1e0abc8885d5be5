//! Why and why not an action (docs/domain.md 6.4, 6.5): the reason an action was done (a
//! condition of a later action's executability condition that held before it and not after,
//! else the goal it achieved) and the reason an action was not done (the satisfied
//! executability conditions of its proof tree, traced down to their origin), with the
//! missing-step rule's note before the answer.
//!
//! Invariants: every proof tree used passed `tree::recheck`, and a why-not tree whose path is
//! then set to the answer's reasons is re-checked before it is returned; an action that was not
//! done (why) or that did occur (why not) gets an answer that says so.

use super::{is_sort, tidy, Answer, AnswerError, Answering, Mode, Session};
use crate::control::Symbol;
use crate::explain::build::{normalize, origin_alternative};
use crate::explain::english::{holds, occurs};
use crate::explain::pattern::{Pattern, SymbolExt};
use crate::explain::tree::{recheck, AxiomKind, Kind, NodeId, ProofTree};

impl Answering<'_, '_> {
    /// docs/domain.md 6.4.
    pub(super) fn why(
        &self,
        action: &Pattern,
        step: Option<u32>,
        session: &mut Session,
    ) -> Result<Answer, AnswerError> {
        let (step, note) = match self.given_or_missing_step(action, step) {
            Some(x) => x,
            None => {
                let text = self.v.template(
                    "not_done",
                    &[
                        (
                            "action",
                            &self.v.action_pattern(
                                action,
                                crate::explain::verbalize::ActionForm::Base,
                            ),
                        ),
                        ("step", ""),
                    ],
                );
                return Ok(Self::simple("why", tidy(&text)));
            }
        };
        if let Some(a) = self.outside("why", step) {
            return Ok(a);
        }
        session.last_step = Some(step);
        if self.planned(action, step).is_none() {
            let text = self.v.template(
                "not_done",
                &[
                    (
                        "action",
                        &self
                            .v
                            .action_pattern(action, crate::explain::verbalize::ActionForm::Base),
                    ),
                    ("step", &self.v.step(i64::from(step))),
                ],
            );
            return Ok(Self::simple("why", text));
        }
        // 1-3: for each later action a_j, its executability conditions grounded at `step`;
        // a body fluent literal that holds at `step` and not at `step + 1` is a reason; the
        // nearest a_j on another object than the queried action's wins, else the nearest of
        // all (the queried action's own follow-up gives the trivia "X was not in my hand").
        let own = self.planned(action, step).and_then(|a| a.arg(1).cloned());
        let mut best: Option<(u32, Symbol, Symbol)> = None;
        let mut best_other: Option<(u32, Symbol, Symbol)> = None;
        for (j, later) in &self.scn.plan {
            if *j <= step {
                continue;
            }
            let head = occurs(later, step).complement().expect("occurs has a sign");
            for rule in self.scn.oracle.rules_for(&head) {
                if rule.kind != AxiomKind::Executability {
                    continue;
                }
                for lit in rule.positive() {
                    if lit.name() != Some("holds") {
                        continue;
                    }
                    let next = at_step(lit, step + 1);
                    if self.scn.oracle.holds(lit) && !self.scn.oracle.holds(&next) {
                        let slot = if own.is_some() && later.arg(1) != own.as_ref() {
                            &mut best_other
                        } else {
                            &mut best
                        };
                        if slot.as_ref().is_none_or(|(bj, _, _)| j < bj) {
                            *slot = Some((*j, later.clone(), lit.clone()));
                        }
                    }
                }
            }
        }
        let (text, literals) = match best_other.or(best) {
            Some((j, later, lit)) => (
                self.v.why_action(&later, &lit, self.tense()),
                vec![lit, occurs(&later, j)],
            ),
            None => {
                // 5: the action achieves a goal literal directly.
                let last = self.scn.last_step;
                let goal: Vec<Symbol> = self.scn.goal.iter().map(|g| holds(g, last)).collect();
                (self.v.why_goal(&goal), goal)
            }
        };
        Ok(Answer {
            kind: "why",
            text: prefix(note, text),
            literals,
            tree: None,
        })
    }

    /// docs/domain.md 6.5.
    pub(super) fn why_not(
        &self,
        action: &Pattern,
        step: Option<u32>,
        session: &mut Session,
    ) -> Result<Answer, AnswerError> {
        let (step, note) = self
            .given_or_missing_step(action, step)
            .unwrap_or((session.last_step.unwrap_or(0), None));
        if let Some(a) = self.outside("why_not", step) {
            return Ok(a);
        }
        session.last_step = Some(step);
        let Some(action) = action.to_symbol() else {
            // A target that was not named: the planned action at that step, if it matches.
            let Some(a) = self.planned(action, step).cloned() else {
                return Ok(Self::simple("why_not", self.v.template("no_reason", &[])));
            };
            return Ok(Answer {
                kind: "why_not",
                text: self.v.did_it(&a, i64::from(step)),
                literals: vec![occurs(&a, step)],
                tree: None,
            });
        };
        let action = &action;
        // 6: the action did occur.
        if self.scn.oracle.holds(&occurs(action, step)) {
            return Ok(Answer {
                kind: "why_not",
                text: prefix(note, self.v.did_it(action, i64::from(step))),
                literals: vec![occurs(action, step)],
                tree: None,
            });
        }
        let root = occurs(action, step)
            .complement()
            .expect("occurs has a sign");
        let mut tree = self.tree(&root)?;
        // 1-4: the satisfied executability conditions, in the tree's preference order (those
        // mentioning the action's objects first).
        let conditions: Vec<NodeId> = tree
            .roots
            .iter()
            .copied()
            .filter(|r| {
                matches!(
                    tree.node(*r).kind,
                    Kind::Axiom {
                        kind: AxiomKind::Executability,
                        ..
                    }
                )
            })
            .collect();
        if conditions.is_empty() {
            // 5: only the action CWA.
            let objects: Vec<&Symbol> = action
                .args()
                .iter()
                .skip(1)
                .filter(|o| o.is_constant())
                .collect();
            let related = objects.iter().any(|o| {
                self.scn.goal.iter().any(|g| mentions(g, o))
                    || self.scn.plan.iter().any(|(_, a)| mentions(a, o))
            });
            let text = match (related, objects.first()) {
                (false, Some(o)) => self.v.why_not_unrelated(o),
                _ => self.v.why_not_not_planned(),
            };
            return Ok(Answer {
                kind: "why_not",
                text: prefix(note, text),
                literals: Vec::new(),
                tree: Some(tree),
            });
        }
        let label_of = |id: &NodeId| match &tree.node(*id).kind {
            Kind::Axiom { label, .. } => Some(label.clone()),
            _ => None,
        };
        let chosen: Vec<NodeId> = match self.mode {
            // The top-ranked axiom with every grounding of it that holds (6.5 step 4: "the red
            // block was below the white block and the green can").
            Mode::Concise => {
                let top = label_of(&conditions[0]);
                conditions
                    .iter()
                    .copied()
                    .filter(|c| label_of(c) == top)
                    .collect()
            }
            Mode::Full => conditions.clone(),
        };
        let inner = root.arg(0).cloned();
        let mut said: Vec<Symbol> = Vec::new();
        let mut observed: Option<(Symbol, u32)> = None;
        let mut path = vec![chosen[0]];
        for (k, cond) in chosen.iter().enumerate() {
            let node = tree.node(*cond).clone();
            let mut seen = Vec::new();
            for c in &node.children {
                let child = tree.node(*c);
                // One alternative per body literal; the sort guard restating the action is
                // not a reason.
                if seen.contains(&child.literal)
                    || inner.as_ref().is_some_and(|i| contains(&child.literal, i))
                    || is_sort(child)
                {
                    continue;
                }
                seen.push(child.literal.clone());
                let labels = &self.scn.build.spatial_labels;
                let normal = normalize(&tree, *c, labels);
                let mut steps = spatial_path(&tree, *c, normal);
                // The normal literal's node on the path: its origin (inertia, a causal law)
                // rather than a spatial conjunction that restates it.
                let parent = if steps.len() >= 2 {
                    steps[steps.len() - 2]
                } else {
                    *cond
                };
                let normal = origin_alternative(&tree, parent, normal, labels);
                if let Some(last) = steps.last_mut() {
                    *last = normal;
                }
                let n = tree.node(normal);
                if k == 0 && path.len() == 1 && child.step.is_some() {
                    path.extend(steps);
                }
                if n.kind == Kind::Observation && n.step == Some(step) && chosen.len() == 1 {
                    observed.get_or_insert((n.literal.clone(), step));
                }
                said.push(n.literal.clone());
            }
        }
        let text = match (&observed, said.len()) {
            (Some((lit, s)), 1) => self.v.why_not_observed(lit, i64::from(*s)),
            _ => self.v.why_not(&said, self.tense()),
        };
        extend_to_leaf(&mut path, &tree);
        tree.path = path;
        recheck(&tree, self.scn.oracle)?;
        Ok(Answer {
            kind: "why_not",
            text: prefix(note, text),
            literals: said,
            tree: Some(tree),
        })
    }
}

/// The same `holds`/`occurs` literal at another step.
fn at_step(lit: &Symbol, step: u32) -> Symbol {
    let mut t = lit.clone();
    if let Symbol::Function { args, .. } = &mut t {
        if let Some(last) = args.last_mut() {
            *last = Symbol::Number(step as i32);
        }
    }
    t
}

fn mentions(t: &Symbol, c: &Symbol) -> bool {
    t == c || t.args().iter().any(|a| mentions(a, c))
}

fn contains(t: &Symbol, inner: &Symbol) -> bool {
    t == inner || t.args().iter().any(|a| contains(a, inner))
}

/// The nodes from `from` (included) down to `to` along first fluent children.
fn spatial_path(tree: &ProofTree, from: NodeId, to: NodeId) -> Vec<NodeId> {
    let mut out = vec![from];
    let mut at = from;
    while at != to {
        let next = tree
            .node(at)
            .children
            .iter()
            .copied()
            .find(|c| *c == to || reaches(tree, *c, to));
        match next {
            Some(n) => {
                out.push(n);
                at = n;
            }
            None => break,
        }
    }
    out
}

fn reaches(tree: &ProofTree, from: NodeId, to: NodeId) -> bool {
    from == to
        || tree
            .node(from)
            .children
            .iter()
            .any(|c| reaches(tree, *c, to))
}

/// Extends a path down to a leaf through first fluent children.
fn extend_to_leaf(path: &mut Vec<NodeId>, tree: &ProofTree) {
    while let Some(&last) = path.last() {
        let n = tree.node(last);
        let next = tree
            .timed_children(last)
            .next()
            .or_else(|| n.children.first().copied());
        match next {
            Some(c) => path.push(c),
            None => break,
        }
    }
}

fn prefix(note: Option<String>, text: String) -> String {
    match note {
        Some(n) => format!("{n} {text}"),
        None => text,
    }
}
