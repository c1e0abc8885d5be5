//! The four questions of docs/domain.md 6.3-6.6 answered over a ground program and one answer set
//! (an [`Oracle`]), a plan (executed or not) and its goal: plan description, why action X at
//! step I, why not action X at step I, why belief Y at step I; with the missing-step rule and
//! follow-up steps ([`Session`]), concise and full modes, and the answer's literals (docs/domain.md
//! 6.9) beside the English.
//!
//! Invariants: answers are computed from the oracle's rules and model, never from the question's
//! wording; every proof tree an answer uses passed `tree::recheck` (a failed re-check is an
//! error, not an answer); questions about steps outside the history or actions that are not
//! there get an answer that says so, never a panic. Questions that need a new solve (why no
//! plan, what if) and goals are answered by [`AnswerError::NeedsSolver`]: the caller with the
//! planning problem runs them (`explain::counterfactual`, the planner).

use super::build::{normalize, origin_alternative, BuildConfig, Builder};
use super::english::{holds, occurs, Question, LAST};
use super::lexicon::Lexicon;
use super::pattern::{Pattern, SymbolExt};
use super::tree::{
    recheck, AxiomKind, Kind, LearnedAxiom, NodeId, Oracle, ProofTree, RecheckError,
};
use super::verbalize::{ActionForm, Tense, Verbalizer};
use crate::control::Symbol;

/// How much an answer says.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Mode {
    /// The top condition or reason only (the default).
    #[default]
    Concise,
    /// Every condition.
    Full,
}

/// What the questions are about: the program and answer set, the plan and the goal.
pub struct Scenario<'a> {
    /// The ground program (with the explanation-only axioms) and the answer set.
    pub oracle: &'a dyn Oracle,
    /// The plan's actions with their steps.
    pub plan: Vec<(u32, Symbol)>,
    /// The goal fluents (`relation(on,pitcher,red_block)`).
    pub goal: Vec<Symbol>,
    /// The last step of the history.
    pub last_step: u32,
    /// Whether the plan was executed (past tense) or not yet (future tense).
    pub executed: bool,
    /// The robot constant.
    pub robot: Symbol,
    /// Fluent names that are inertial (their beliefs are traced to an origin; the others are
    /// expanded to a frontier of inertial literals and statics).
    pub inertial: Vec<String>,
    /// Tree-building settings.
    pub build: BuildConfig,
    /// The learned axioms of the knowledge base, with their strengths: an answer whose path
    /// uses one says so.
    pub learned: Vec<LearnedAxiom>,
}

impl<'a> Scenario<'a> {
    /// A scenario with the RA domain's settings: robot `rob1`, inertial fluents `relation`,
    /// `in_hand`, `partially_occluded`, `absent`, `partially_stable`.
    pub fn ra(
        oracle: &'a dyn Oracle,
        plan: Vec<(u32, Symbol)>,
        goal: Vec<Symbol>,
        last_step: u32,
    ) -> Self {
        let robot = Symbol::constant("rob1");
        Scenario {
            oracle,
            plan,
            goal,
            last_step,
            executed: true,
            build: BuildConfig {
                agents: vec![robot.clone()],
                ..BuildConfig::default()
            },
            robot,
            learned: Vec::new(),
            inertial: [
                "relation",
                "in_hand",
                "partially_occluded",
                "absent",
                "partially_stable",
            ]
            .iter()
            .map(|s| s.to_string())
            .collect(),
        }
    }
}

/// The context a follow-up question takes its step from.
#[derive(Clone, Debug, Default)]
pub struct Session {
    /// The step of the previous question.
    pub last_step: Option<u32>,
}

/// An answer: its type, its English, its literals, and the proof tree it used.
#[derive(Clone, Debug)]
pub struct Answer {
    /// The question type (`plan`, `why`, `why_not`, `belief`).
    pub kind: &'static str,
    /// The English answer.
    pub text: String,
    /// The answer's ground literals in the program's syntax (docs/domain.md 6.9).
    pub literals: Vec<Symbol>,
    /// The proof tree the answer used, with the answer's path.
    pub tree: Option<ProofTree>,
}

/// A question this module does not answer.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum AnswerError {
    /// The question needs a new solve (why no plan, what if) or is a task for the planner.
    #[error("the question needs the planner or a new solve")]
    NeedsSolver,
    /// A proof tree failed its independent re-check (a bug, reported rather than answered).
    #[error("{0}")]
    Recheck(#[from] RecheckError),
}

/// Answers one question.
pub fn answer(
    scn: &Scenario<'_>,
    lexicon: &Lexicon,
    question: &Question,
    mode: Mode,
    session: &mut Session,
) -> Result<Answer, AnswerError> {
    let v = Verbalizer::new(lexicon);
    let a = Answering { scn, v, mode };
    let question = &a.resolve_last(question);
    let mut answer = match question {
        Question::DescribePlan => Ok(a.plan()),
        Question::DescribeStep { step } => Ok(a.describe_step(*step, session)),
        Question::WhyAction { action, step } => a.why(action, *step, session),
        Question::WhyNotAction { action, step } => a.why_not(action, *step, session),
        Question::Belief {
            literal,
            is_static,
            step,
        } => a.belief(literal, *is_static, *step, session),
        Question::Goal { .. } | Question::WhyNoPlan { .. } | Question::WhatIf { .. } => {
            Err(AnswerError::NeedsSolver)
        }
    }?;
    cite_learned(&mut answer, &a.v);
    Ok(answer)
}

/// Says which learned axioms the answer's path rests on: one sentence per axiom, after the
/// answer ("I used the learned axiom L2 (strength 0.57): impossible pickup(R1, O1) if …").
fn cite_learned(answer: &mut Answer, v: &Verbalizer<'_>) {
    let Some(tree) = &answer.tree else { return };
    let mut cited: Vec<&LearnedAxiom> = Vec::new();
    for &id in &tree.path {
        if let Some(l) = tree.learned_of(id) {
            if !cited.iter().any(|c| c.label == l.label) {
                cited.push(l);
            }
        }
    }
    for l in cited {
        let sentence = v.template(
            "learned_axiom",
            &[
                ("label", &l.label),
                ("strength", &format!("{:.2}", l.strength)),
                ("axiom", &l.text),
            ],
        );
        answer.text.push(' ');
        answer.text.push_str(&sentence);
    }
}

struct Answering<'s, 'a> {
    scn: &'s Scenario<'a>,
    v: Verbalizer<'s>,
    mode: Mode,
}

impl Answering<'_, '_> {
    fn tense(&self) -> Tense {
        if self.scn.executed {
            Tense::Past
        } else {
            Tense::Future
        }
    }

    fn simple(kind: &'static str, text: String) -> Answer {
        Answer {
            kind,
            text,
            literals: Vec::new(),
            tree: None,
        }
    }

    /// A checked proof tree.
    fn tree(&self, literal: &Symbol) -> Result<ProofTree, AnswerError> {
        let mut tree = Builder::new(self.scn.oracle, self.scn.build.clone()).build(literal);
        recheck(&tree, self.scn.oracle)?;
        tree.note_learned(&self.scn.learned);
        Ok(tree)
    }

    fn outside(&self, kind: &'static str, step: u32) -> Option<Answer> {
        (step > self.scn.last_step).then(|| {
            Self::simple(
                kind,
                self.v.template(
                    "outside_history",
                    &[
                        ("step", &step.to_string()),
                        ("last", &self.scn.last_step.to_string()),
                    ],
                ),
            )
        })
    }

    /// docs/domain.md 6.3.
    fn plan(&self) -> Answer {
        Answer {
            kind: "plan",
            text: self.v.plan(&self.scn.plan, self.scn.executed),
            literals: self.scn.plan.iter().map(|(i, a)| occurs(a, *i)).collect(),
            tree: None,
        }
    }

    /// The question with "last" ([`LAST`]) resolved against the history: the last step of the
    /// history for a belief; for an action question the last step at which the plan has such
    /// an action (else the last action's step, for why-not and what-if).
    fn resolve_last(&self, question: &Question) -> Question {
        let last_action = self
            .scn
            .plan
            .iter()
            .map(|(i, _)| *i)
            .max()
            .unwrap_or(self.scn.last_step.saturating_sub(1));
        let last_matching = |action: &Pattern| {
            self.scn
                .plan
                .iter()
                .filter(|(_, a)| {
                    a.name() == action.name()
                        && action.arg(1).and_then(Pattern::to_symbol).as_ref() == object_arg(a)
                })
                .map(|(i, _)| *i)
                .max()
        };
        let mut q = question.clone();
        match &mut q {
            Question::Belief { step, .. } if *step == Some(LAST) => {
                *step = Some(self.scn.last_step);
            }
            Question::WhyAction { action, step } if *step == Some(LAST) => {
                *step = last_matching(action);
            }
            Question::WhyNotAction { step, .. } | Question::WhatIf { step, .. }
                if *step == Some(LAST) =>
            {
                *step = Some(last_action);
            }
            Question::DescribeStep { step } if *step == LAST => *step = last_action,
            _ => {}
        }
        q
    }

    /// What was done at one step: "I picked up the green can at step 0."
    fn describe_step(&self, step: u32, session: &mut Session) -> Answer {
        session.last_step = Some(step);
        if let Some(a) = self.outside("plan_step", step) {
            return a;
        }
        let done: Vec<&Symbol> = self
            .scn
            .plan
            .iter()
            .filter(|(i, _)| *i == step)
            .map(|(_, a)| a)
            .collect();
        if done.is_empty() {
            let text = self
                .v
                .template("nothing_done", &[("step", &self.v.step(i64::from(step)))]);
            return Self::simple("plan_step", text);
        }
        let form = if self.scn.executed {
            ActionForm::Past
        } else {
            ActionForm::Future
        };
        let actions: Vec<String> = done.iter().map(|a| self.v.action(a, form)).collect();
        let said = format!(
            "{} {}",
            super::english::join_and(&actions),
            self.v.step(i64::from(step))
        );
        Answer {
            kind: "plan_step",
            text: self.v.template("plan_step", &[("action", &said)]),
            literals: done.iter().map(|a| occurs(a, step)).collect(),
            tree: None,
        }
    }

    /// The missing-step rule: the plan's actions with the same name and first object (the
    /// robot aside) as the pattern; `(step, note)` with a note when there were several.
    fn missing_step(&self, action: &Pattern) -> Option<(u32, Option<String>)> {
        let key = |a: &Symbol| (a.name().map(str::to_string), object_arg(a).cloned());
        let wanted = (
            action.name().map(str::to_string),
            action.arg(1).and_then(Pattern::to_symbol),
        );
        let mut steps: Vec<u32> = self
            .scn
            .plan
            .iter()
            .filter(|(_, a)| key(a) == wanted)
            .map(|(i, _)| *i)
            .collect();
        steps.sort_unstable();
        let first = *steps.first()?;
        let note = (steps.len() > 1).then(|| {
            let list: Vec<String> = steps.iter().map(|s| self.v.step(i64::from(*s))).collect();
            self.v.template(
                "step_chosen",
                &[("steps", &super::english::join_and(&list))],
            )
        });
        Some((first, note))
    }

    /// The plan's action at a step matching the pattern.
    fn planned(&self, action: &Pattern, step: u32) -> Option<&Symbol> {
        self.scn.plan.iter().find_map(|(i, a)| {
            let mut b = Vec::new();
            (*i == step && action.matches(a, &mut b)).then_some(a)
        })
    }

    /// docs/domain.md 6.4.
    fn why(
        &self,
        action: &Pattern,
        step: Option<u32>,
        session: &mut Session,
    ) -> Result<Answer, AnswerError> {
        let (step, note) = match step {
            Some(s) => (s, None),
            None => match self.missing_step(action) {
                Some(x) => x,
                None => {
                    let text = self.v.template(
                        "not_done",
                        &[
                            (
                                "action",
                                &self
                                    .v
                                    .action_pattern(action, super::verbalize::ActionForm::Base),
                            ),
                            ("step", ""),
                        ],
                    );
                    return Ok(Self::simple("why", tidy(&text)));
                }
            },
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
                            .action_pattern(action, super::verbalize::ActionForm::Base),
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
    fn why_not(
        &self,
        action: &Pattern,
        step: Option<u32>,
        session: &mut Session,
    ) -> Result<Answer, AnswerError> {
        let (step, note) = match step {
            Some(s) => (s, None),
            None => match self.missing_step(action) {
                Some(x) => x,
                None => (session.last_step.unwrap_or(0), None),
            },
        };
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

    /// docs/domain.md 6.6.
    fn belief(
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
                        ("literal", &super::english::join_and(&said)),
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
        let mut todo: Vec<NodeId> = tree
            .node(sr5)
            .children
            .iter()
            .copied()
            .filter(|c| tree.node(*c).step.is_some())
            .collect();
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
                    todo.extend(
                        n.children
                            .iter()
                            .copied()
                            .filter(|c| tree.node(*c).step.is_some()),
                    );
                    continue;
                }
                _ => {}
            }
            let next = n
                .children
                .iter()
                .copied()
                .find(|c| matches!(tree.node(*c).kind, Kind::Observation | Kind::Action))
                .or_else(|| {
                    n.children
                        .iter()
                        .copied()
                        .find(|c| tree.node(*c).step.is_some())
                });
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
        for c in &n.children {
            let lit = &tree.node(*c).literal;
            if seen.contains(lit) {
                continue;
            }
            seen.push(lit.clone());
            self.frontier(tree, *c, out, seen);
        }
    }
}

/// Whether a node is a sort guard (`object(a)`, `action(pickup(rob1,a))`).
fn is_sort(n: &super::tree::Node) -> bool {
    n.rule.as_ref().is_some_and(|r| r.kind == AxiomKind::Sort)
}

/// The object argument of an action (its second argument: the first is the robot).
fn object_arg(action: &Symbol) -> Option<&Symbol> {
    action.arg(1)
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
        let next = n
            .children
            .iter()
            .copied()
            .find(|c| tree.node(*c).step.is_some())
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

/// Removes the doubled space and the space before the full stop an empty hole leaves.
fn tidy(s: &str) -> String {
    s.replace("  ", " ").replace(" .", ".")
}

impl Answer {
    /// The answer as `--outf=2` JSON: `type`, `answer` (the English), `literals` (program
    /// syntax) and, when the answer used one, `tree` (nodes children first, roots, path).
    pub fn to_json(&self) -> serde_json::Value {
        let mut obj = serde_json::json!({
            "type": self.kind,
            "answer": self.text,
            "literals": self.literals.iter().map(Symbol::to_string).collect::<Vec<_>>(),
        });
        if let Some(tree) = &self.tree {
            obj["tree"] = tree_json(tree);
            // The learned axioms the answer's path cites (as its English says).
            let cited: Vec<serde_json::Value> = tree
                .learned
                .iter()
                .filter(|l| {
                    tree.path
                        .iter()
                        .any(|&id| tree.learned_of(id).is_some_and(|x| x.label == l.label))
                })
                .map(learned_json)
                .collect();
            if !cited.is_empty() {
                obj["learned"] = serde_json::Value::Array(cited);
            }
        }
        obj
    }
}

/// A learned axiom as JSON: `label`, `strength`, `axiom` (AL_d).
fn learned_json(l: &LearnedAxiom) -> serde_json::Value {
    serde_json::json!({"label": l.label, "strength": l.strength, "axiom": l.text})
}

/// A proof tree as JSON: `nodes` (index order, children before parents) with `literal`,
/// `step`, `holds`, `kind`, `rule` (the ground rule instance, as text), `children`, `blocked`
/// and `no_evidence`, and `learned` (label, strength, axiom) when the rule instance comes from
/// a learned axiom; `roots`; `path`.
pub fn tree_json(tree: &ProofTree) -> serde_json::Value {
    let nodes: Vec<serde_json::Value> = tree
        .nodes
        .iter()
        .enumerate()
        .map(|(i, n)| {
            let mut node = serde_json::json!({
                "literal": n.literal.to_string(),
                "step": n.step,
                "holds": n.holds,
                "kind": n.kind.words(),
                "rule": n.rule.as_ref().map(|r| r.to_string()),
                "children": n.children.iter().map(|c| c.0).collect::<Vec<_>>(),
                "blocked": n.blocked.iter().map(|r| r.to_string()).collect::<Vec<_>>(),
                "no_evidence": n.no_evidence.iter().map(Symbol::to_string).collect::<Vec<_>>(),
            });
            if let Some(l) = tree.learned_of(NodeId(i as u32)) {
                node["learned"] = learned_json(l);
            }
            node
        })
        .collect();
    serde_json::json!({
        "nodes": nodes,
        "roots": tree.roots.iter().map(|r| r.0).collect::<Vec<_>>(),
        "path": tree.path.iter().map(|r| r.0).collect::<Vec<_>>(),
    })
}
