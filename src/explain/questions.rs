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
//!
//! This file holds the question and answer types, the dispatch ([`answer`]), the resolution of
//! "last" and of a missing step, and the plan and step descriptions (6.3); `action` answers
//! why and why not an action (6.4, 6.5), `belief` why a belief (6.6), and `json` writes answers
//! and proof trees as `--outf=2` JSON.

mod action;
mod belief;
mod json;

use super::build::{BuildConfig, Builder};
use super::english::{occurs, Question, LAST};
use super::lexicon::Lexicon;
use super::pattern::{Pattern, SymbolExt};
use super::tree::{recheck, AxiomKind, LearnedAxiom, Oracle, ProofTree, RecheckError};
use super::verbalize::{ActionForm, Tense, Verbalizer};
use crate::control::Symbol;

pub use json::tree_json;

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

    /// The step a question about `action` is at: the `step` it gave (no note), else the
    /// missing-step rule's; `None` when neither finds one.
    fn given_or_missing_step(
        &self,
        action: &Pattern,
        step: Option<u32>,
    ) -> Option<(u32, Option<String>)> {
        match step {
            Some(s) => Some((s, None)),
            None => self.missing_step(action),
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
}

/// Whether a node is a sort guard (`object(a)`, `action(pickup(rob1,a))`).
fn is_sort(n: &super::tree::Node) -> bool {
    n.rule.as_ref().is_some_and(|r| r.kind == AxiomKind::Sort)
}

/// The object argument of an action (its second argument: the first is the robot).
fn object_arg(action: &Symbol) -> Option<&Symbol> {
    action.arg(1)
}

/// Removes the doubled space and the space before the full stop an empty hole leaves.
fn tidy(s: &str) -> String {
    s.replace("  ", " ").replace(" .", ".")
}
