//! Why a belief (docs/domain.md 6.6): a static is said to hold; a fluent literal that does not
//! hold is answered by its complement's explanation or by "I did not believe"; an inertial
//! literal is traced along its proof tree's path to its origin (an observation, an action's
//! causal law, a closed-world default, or two observations a transitive relation rests on); a
//! defined literal is expanded to the frontier of inertial literals and statics it rests on.
//!
//! Invariants: the step of a belief question without one is the session's step, else the last
//! step at which the literal holds; every tree used passed `tree::recheck`.

use super::{is_sort, tidy, Answer, AnswerError, Answering, Session};
use crate::control::Symbol;
use crate::explain::english::holds;
use crate::explain::pattern::SymbolExt;
use crate::explain::tree::{AxiomKind, Kind, NodeId, ProofTree};
use crate::explain::verbalize::Tense;

impl Answering<'_, '_> {
    /// docs/domain.md 6.6.
    pub(super) fn belief(
        &self,
        literal: &Symbol,
        is_static: bool,
        step: Option<u32>,
        session: &mut Session,
    ) -> Result<Answer, AnswerError> {
        if is_static {
            let text = if self.scn.oracle.holds(literal) {
                self.v.belief_static()
            } else {
                self.v.template(
                    "not_believed",
                    &[
                        ("literal", &self.v.fluent(literal, Tense::Present)),
                        ("step", ""),
                    ],
                )
            };
            return Ok(Answer {
                kind: "belief",
                text: tidy(&text),
                literals: vec![literal.clone()],
                tree: None,
            });
        }
        let step = match step.or(session.last_step) {
            Some(s) => s,
            None => (0..=self.scn.last_step)
                .rev()
                .find(|i| self.scn.oracle.holds(&holds(literal, *i)))
                .unwrap_or(self.scn.last_step),
        };
        if let Some(a) = self.outside("belief", step) {
            return Ok(a);
        }
        session.last_step = Some(step);
        let lit = holds(literal, step);
        if !self.scn.oracle.holds(&lit) {
            let complement = lit.complement().expect("holds has a sign");
            if self.scn.oracle.holds(&complement) {
                let mut a = self.explain_belief(&complement, step)?;
                a.text = format!(
                    "{} {}",
                    self.v.template(
                        "complement_instead",
                        &[("literal", &self.v.clause(&complement, Tense::Past))]
                    ),
                    a.text
                );
                return Ok(a);
            }
            return Ok(Answer {
                kind: "belief",
                text: self.v.not_believed(&lit, i64::from(step), Tense::Past),
                literals: Vec::new(),
                tree: None,
            });
        }
        self.explain_belief(&lit, step)
    }

    fn explain_belief(&self, lit: &Symbol, step: u32) -> Result<Answer, AnswerError> {
        let tree = self.tree(lit)?;
        let fluent_name = lit.arg(0).and_then(Symbol::name).unwrap_or("");
        let inertial = self.scn.inertial.iter().any(|n| n == fluent_name);
        let path = tree.path.clone();
        let Some(&leaf) = path.last() else {
            return Ok(Self::simple("belief", self.v.template("no_reason", &[])));
        };
        let root = tree.node(path[0]);
        if root.kind == Kind::Assumption {
            let default = lit.complement().expect("holds has a sign");
            return Ok(Answer {
                kind: "belief",
                text: self.v.belief_assumed(lit, &default, Tense::Past),
                literals: vec![lit.clone()],
                tree: Some(tree),
            });
        }
        if inertial {
            // A relation derived through transitivity (SR5) rests on two relations: when both
            // trace back to observations of one step, name them all (6.6).
            if let Some(observed) = self.branching_observations(&tree) {
                let step_j = tree.node(observed[0]).step.unwrap_or(step);
                let lits: Vec<Symbol> = observed
                    .iter()
                    .map(|id| tree.node(*id).literal.clone())
                    .collect();
                let said: Vec<String> = lits.iter().map(|l| self.v.bare(l)).collect();
                let text = self.v.template(
                    "belief_observed",
                    &[
                        ("literal", &crate::explain::english::join_and(&said)),
                        ("step", &self.v.step(i64::from(step_j))),
                    ],
                );
                return Ok(Answer {
                    kind: "belief",
                    text,
                    literals: lits,
                    tree: Some(tree),
                });
            }
            // Follow spatial algebra and inertia back to the origin. A causal law on the path
            // is the origin: its action made the literal so, whatever the path says of the
            // action's other preconditions (a pickup's effect rests on where the object was).
            let caused = tree.path.iter().find_map(|id| {
                let n = tree.node(*id);
                let is_law = matches!(
                    &n.kind,
                    Kind::Axiom {
                        kind: AxiomKind::CausalLaw,
                        ..
                    }
                );
                is_law
                    .then(|| {
                        n.children
                            .iter()
                            .copied()
                            .find(|c| tree.node(*c).kind == Kind::Action)
                    })
                    .flatten()
            });
            let leaf = caused.unwrap_or(leaf);
            let leaf_node = tree.node(leaf);
            let (text, literals) = match &leaf_node.kind {
                Kind::Action => {
                    let action = leaf_node
                        .literal
                        .arg(0)
                        .cloned()
                        .unwrap_or(Symbol::Number(0));
                    let j = leaf_node.step.unwrap_or(0);
                    (
                        self.v.belief_action(&action, i64::from(j)),
                        vec![leaf_node.literal.clone()],
                    )
                }
                Kind::Observation => (
                    self.v.belief_observed(
                        &leaf_node.literal,
                        i64::from(leaf_node.step.unwrap_or(step)),
                    ),
                    vec![leaf_node.literal.clone()],
                ),
                Kind::ClosedWorld => {
                    let c = leaf_node
                        .literal
                        .complement()
                        .unwrap_or(leaf_node.literal.clone());
                    (
                        self.v.template(
                            "belief_default",
                            &[("literal", &self.v.clause(&c, Tense::Past))],
                        ),
                        vec![leaf_node.literal.clone()],
                    )
                }
                _ => (
                    self.v
                        .belief_frontier(std::slice::from_ref(&leaf_node.literal), Tense::Past),
                    vec![leaf_node.literal.clone()],
                ),
            };
            return Ok(Answer {
                kind: "belief",
                text,
                literals,
                tree: Some(tree),
            });
        }
        // A defined fluent: expand defined literals (preferred supports) down to inertial
        // literals and statics; that frontier is the answer.
        let mut frontier = Vec::new();
        self.frontier(&tree, path[0], &mut frontier, &mut Vec::new());
        Ok(Answer {
            kind: "belief",
            text: self.v.belief_frontier(&frontier, Tense::Past),
            literals: frontier,
            tree: Some(tree),
        })
    }

    /// The observations a transitive relation on the tree's path rests on: from the first
    /// SR5 node of the path, each of its relation children traced down (preferring an
    /// observation or action child, else the first child with a step) to its origin. `Some`
    /// only when there are at least two origins, all observations of one step.
    fn branching_observations(&self, tree: &ProofTree) -> Option<Vec<NodeId>> {
        let sr5 = tree.path.iter().copied().find(|id| {
            matches!(&tree.node(*id).kind, Kind::Axiom { label, .. } if label.starts_with("SR5"))
        })?;
        let mut out: Vec<NodeId> = Vec::new();
        let mut todo: Vec<NodeId> = tree.timed_children(sr5).collect();
        let mut budget = 10_000;
        while let Some(id) = todo.pop() {
            budget -= 1;
            if budget == 0 {
                return None;
            }
            let n = tree.node(id);
            match &n.kind {
                Kind::Observation => {
                    if !out.contains(&id) {
                        out.push(id);
                    }
                    continue;
                }
                Kind::Action => return None,
                Kind::Axiom { label, .. } if label.starts_with("SR5") => {
                    todo.extend(tree.timed_children(id));
                    continue;
                }
                _ => {}
            }
            let next = n
                .children
                .iter()
                .copied()
                .find(|c| matches!(tree.node(*c).kind, Kind::Observation | Kind::Action))
                .or_else(|| tree.timed_children(id).next());
            match next {
                Some(c) => todo.push(c),
                None => return None,
            }
        }
        let step = tree.node(*out.first()?).step;
        (out.len() >= 2 && out.iter().all(|id| tree.node(*id).step == step)).then(|| {
            out.sort_by_key(|id| tree.node(*id).literal.to_string());
            out
        })
    }

    fn frontier(
        &self,
        tree: &ProofTree,
        id: NodeId,
        out: &mut Vec<Symbol>,
        seen: &mut Vec<Symbol>,
    ) {
        let n = tree.node(id);
        let name = n.literal.arg(0).and_then(Symbol::name).unwrap_or("");
        let is_fluent = n.literal.name() == Some("holds");
        let stop =
            !is_fluent || self.scn.inertial.iter().any(|x| x == name) || n.children.is_empty();
        if stop {
            // Statics are said; sort guards are not.
            if !is_sort(n) && !out.contains(&n.literal) {
                out.push(n.literal.clone());
            }
            return;
        }
        tree.each_unseen_child(id, seen, |c, seen| self.frontier(tree, c, out, seen));
    }
}
