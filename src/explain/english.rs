//! Controlled English in: questions and requests to the robot (docs/domain.md 6.1) parsed into a
//! structured [`Question`].
//!
//! The words come from the [`Lexicon`](super::lexicon::Lexicon) (data,
//! `domains/ra/lexicon.json`); this module holds only the grammar, a handful of patterns over
//! normalized tokens:
//!
//! ```text
//! request  = goal (["and"] (goal | object on object))*          -> Question::Goal
//!          | describe-phrase                                   -> Question::DescribePlan
//!          | describe-step-phrase (with a step in its {S})      -> DescribeStep
//!          | no-plan-phrase | "why" "can" ("not" "you" | "you" "not") goal   -> WhyNoPlan
//!          | why aux* "believe" ["that"] belief [step]          -> Belief
//!          | why aux* belief [step] | why aux* hold object [step]   -> Belief
//!          | why aux* action [step]   (aux has "not")          -> WhyNotAction
//!          | why aux* action [step]   (aux has no "not")       -> WhyAction
//!          | "what" ["would" "happen"] "if" ["you"] ["have"] action [step] ["instead"] -> WhatIf
//! why      = "why" | "how come" | "what was the reason (for)" | ... (lexicon)
//! aux      = do | be | have | can | could | will | would | you | not   (at most four)
//! goal     = verb [particle] object (["and"] object)* [particle] [on-phrase object]
//! action   = verb [particle] object [particle] [on-phrase object]
//! belief   = object ["be"|"do"] ["not"] (relation object | property)
//! step     = [at|in|on|during] ["the"] ["time"] "step" number | step-phrase | last-phrase
//! object   = ["the"|"your"|"my"] object-word+   (resolved against the scene; "a"/"an" and
//!            commas are dropped by normalization)
//! ```
//!
//! Invariants: parsing never panics and never guesses: a question is either fully understood
//! (every word consumed by the grammar, every object resolved to exactly one scene constant) or
//! answered by [`NotUnderstood`], whose reply ([`Parser::reply`]) names the words or the object
//! that were not understood (for known words in an unknown order, the words after the longest
//! partial match) and lists example questions about the scene's own objects. "Last" is the
//! step [`LAST`], resolved by the answerer against the history. Resolution of a missing step
//! is not the parser's job: the step stays `None` (docs/domain.md 6.1, "missing step").
//!
//! This file holds the [`Question`] type and its program literals ([`holds`], [`occurs`]);
//! `parser` has the [`Parser`] (the scene's objects, normalization, object resolution),
//! `matcher` the backtracking matcher and the question patterns, `phrases` the phrase
//! patterns (goals, actions, objects, literals, steps) and `reply` the [`NotUnderstood`]
//! replies and English lists.

mod matcher;
mod parser;
mod phrases;
mod reply;

use std::fmt;

use super::pattern::{Pattern, SymbolExt};
use crate::control::Symbol;

pub use parser::Parser;
pub use reply::{join_and, join_or, NotUnderstood};

/// A request or question, with its literals as structured terms in the program's syntax.
/// Fluents are given without `holds` and step (`relation(on,pitcher,red_block)`,
/// `-stable(a)`); actions as in `occurs` (`pickup(rob1,green_can)`), with `_` for a target
/// that was not named.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Question {
    /// A task for the planner: reach a state where all these fluents hold.
    Goal {
        /// The goal fluents (`relation(on,X,Y)`, `in_hand(rob1,X)`).
        literals: Vec<Symbol>,
    },
    /// "Describe the plan."
    DescribePlan,
    /// "What did you do at step N / first / last?"
    DescribeStep {
        /// The step ([`LAST`] for the last action of the plan).
        step: u32,
    },
    /// "Why did you ⟨action⟩ [at step N]?"
    WhyAction {
        /// The action pattern.
        action: Pattern,
        /// The step, if named.
        step: Option<u32>,
    },
    /// "Why did you not ⟨action⟩ [at step N]?"
    WhyNotAction {
        /// The action pattern.
        action: Pattern,
        /// The step, if named.
        step: Option<u32>,
    },
    /// "Why did you believe that ⟨literal⟩ [at step N]?"
    Belief {
        /// The fluent or static literal, possibly classically negated (`-stable(a)`).
        literal: Symbol,
        /// Whether the literal is a static (no step).
        is_static: bool,
        /// The step, if named.
        step: Option<u32>,
    },
    /// "Why is there no plan?" or "Why can you not ⟨goal⟩?"
    WhyNoPlan {
        /// The goal fluents named in the question (empty: the current task's goal).
        goal: Vec<Symbol>,
    },
    /// "What if you had ⟨action⟩ [at step N] (instead)?"
    WhatIf {
        /// The action pattern.
        action: Pattern,
        /// The step, if named.
        step: Option<u32>,
    },
}

impl Question {
    /// The question's type as a short name (`goal`, `plan`, `why`, `why_not`, `belief`,
    /// `no_plan`, `what_if`), as in `--outf=2` output.
    pub fn kind(&self) -> &'static str {
        match self {
            Question::Goal { .. } => "goal",
            Question::DescribePlan => "plan",
            Question::DescribeStep { .. } => "plan_step",
            Question::WhyAction { .. } => "why",
            Question::WhyNotAction { .. } => "why_not",
            Question::Belief { .. } => "belief",
            Question::WhyNoPlan { .. } => "no_plan",
            Question::WhatIf { .. } => "what_if",
        }
    }

    /// The step the question names, if any.
    pub fn step(&self) -> Option<u32> {
        match self {
            Question::WhyAction { step, .. }
            | Question::WhyNotAction { step, .. }
            | Question::Belief { step, .. }
            | Question::WhatIf { step, .. } => *step,
            Question::DescribeStep { step } => Some(*step),
            _ => None,
        }
    }
}

/// The step a question names with "last", "at the end", "in the final state": the last step of
/// the history for a belief, the last action's step for a question about actions. The answerer
/// resolves it against the history; the parser has none.
pub const LAST: u32 = u32::MAX;

/// A step in words for [`Question`]'s display: the number, `last`, or `?` when not named.
fn step_text(s: Option<u32>) -> String {
    match s {
        Some(LAST) => "last".to_string(),
        Some(n) => n.to_string(),
        None => "?".to_string(),
    }
}

/// The program literal of a fluent literal at a step: `holds(F, I)`, or `-holds(F, I)` when the
/// fluent is classically negated (`-stable(a)` at 2 is `-holds(stable(a),2)`).
pub fn holds(fluent: &Symbol, step: u32) -> Symbol {
    let positive = fluent.positive();
    let mut t = Symbol::function("holds", vec![positive, Symbol::Number(step as i32)]);
    if fluent.is_negative() {
        t = t.complement().expect("holds/2 has a sign");
    }
    t
}

/// The program literal `occurs(A, I)`.
pub fn occurs(action: &Symbol, step: u32) -> Symbol {
    Symbol::function("occurs", vec![action.clone(), Symbol::Number(step as i32)])
}

impl fmt::Display for Question {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let step = |s: &Option<u32>| step_text(*s);
        let list = |ts: &[Symbol]| {
            ts.iter()
                .map(Symbol::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        };
        match self {
            Question::Goal { literals } => write!(f, "goal {}", list(literals)),
            Question::DescribePlan => write!(f, "describe the plan"),
            Question::DescribeStep { step: s } => write!(f, "describe step {}", step(&Some(*s))),
            Question::WhyAction { action, step: s } => write!(f, "why {action} at {}", step(s)),
            Question::WhyNotAction { action, step: s } => {
                write!(f, "why not {action} at {}", step(s))
            }
            Question::Belief {
                literal,
                is_static,
                step: s,
            } => {
                if *is_static {
                    write!(f, "belief {literal}")
                } else {
                    write!(f, "belief {literal} at {}", step(s))
                }
            }
            Question::WhyNoPlan { goal } if goal.is_empty() => write!(f, "why no plan"),
            Question::WhyNoPlan { goal } => write!(f, "why no plan for {}", list(goal)),
            Question::WhatIf { action, step: s } => write!(f, "what if {action} at {}", step(s)),
        }
    }
}
