//! The record of one run of the sense-plan-act loop ([`super::act`]): per step what was
//! observed, which observations were doubted, what the robot then believed and which action
//! happened; every plan made; every discrepancy between the predicted and the observed state;
//! and how the run ended. It is saved as JSON (`lucent run --save-history FILE`) so that the
//! explainer can load a run, and it prints as an AL_d history (`observed ... at I.`,
//! `happened ... at I.`).
//!
//! Invariants: literals and actions are kept as the text of ground terms in the domain's
//! vocabulary (`relation(on,a,b)`, `-in_hand(rob1,a)`, `pickup(rob1,a)`), which
//! [`crate::control::Symbol::parse`] reads back; `steps[i].step == i`; an action recorded at step
//! `I` was executed between the observations of steps `I` and `I + 1`; a `Discrepancy` carries
//! the positive observable literals docs/domain.md 5.1 compares (`relation`, `in_hand`), sorted, so
//! `learn::surprise::classify(before, predicted, Some(observed))` consumes it unchanged.
//! The format is written down in `domains/ra/README.md` ("Run histories").

use serde::{Deserialize, Serialize};
use std::fmt::Write;

/// The version of the JSON format; raised when a field changes meaning.
pub const FORMAT_VERSION: u32 = 1;

/// One observation: a fluent literal's value as perceived, with the perceiver's confidence.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Observed {
    /// The fluent, e.g. `relation(on,a,b)` or `in_hand(rob1,a)`.
    pub fluent: String,
    /// Observed true or false.
    pub value: bool,
    /// Confidence in `[0, 1]` (1 for exact senses such as the hand).
    pub confidence: f64,
}

/// What happened at one step.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct StepRecord {
    /// The step number, from 0.
    pub step: u32,
    /// What was perceived at this step (above the confidence threshold; with several looks,
    /// the readings most of them agree on, per perception).
    pub observed: Vec<Observed>,
    /// How many times the robot looked at this step.
    pub looks: u32,
    /// Observed literals the robot doubted to restore consistency (CR rule `doubt`).
    pub doubted: Vec<String>,
    /// The positive fluent literals the robot believed at this step (its initial state when it
    /// planned from here).
    pub belief: Vec<String>,
    /// The action executed at this step (`hpd(a, step)`), if any.
    pub happened: Option<String>,
    /// Why the world says that action failed, if it did.
    pub failure: Option<String>,
}

/// One plan made during the run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PlanRecord {
    /// The step the plan starts at (its first action happens at this step).
    pub step: u32,
    /// Its actions in order.
    pub actions: Vec<String>,
    /// The CR rules its answer set applies (`d1x(a,2)`, steps relative to the plan).
    pub cr_applied: Vec<String>,
    /// Why it was made: `initial`, `discrepancy at step I`, `A not executable in the belief at
    /// step I`, `no plan of at most H steps at step I, looked again`, `goal not confirmed at
    /// step I`.
    pub reason: String,
    /// How many distinct minimal plans there were.
    pub alternatives: usize,
}

/// A mismatch between the predicted and the observed outcome of an action (docs/domain.md 4.4 and
/// 5.1): what the learner consumes.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Discrepancy {
    /// The step at which the action was executed; `observed` is of step + 1.
    pub step: u32,
    /// The action.
    pub action: String,
    /// The positive observable literals believed before the action (step `step`).
    pub before: Vec<String>,
    /// The positive observable literals predicted after it; `None` when the robot's domain says
    /// the action was not executable.
    pub predicted: Option<Vec<String>>,
    /// The positive observable literals observed after it (doubted ones removed).
    pub observed: Vec<String>,
    /// Observed but not predicted, within the compared vocabulary.
    pub unexpected: Vec<String>,
    /// Predicted but not observed, within the compared vocabulary.
    pub extra: Vec<String>,
    /// The world's account of a failed action, if it failed.
    pub failure: Option<String>,
}

/// How a run ended.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Ending {
    /// The robot observed the goal (and confirmed it by looking again).
    GoalObserved,
    /// The planner found no plan within its horizon budget.
    NoPlan {
        /// The horizon budget.
        horizon: usize,
    },
    /// The observations could not be made consistent, even with doubts.
    Inconsistent,
    /// The action budget ran out.
    ActionBudget,
    /// The replanning budget ran out.
    ReplanBudget,
    /// The world refused an action outright (not a failure but an error, e.g. a bad name).
    WorldError(String),
    /// The planning problem is malformed (rendered diagnostics).
    Input(String),
}

impl std::fmt::Display for Ending {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Ending::GoalObserved => write!(f, "the goal was observed"),
            Ending::NoPlan { horizon } => write!(f, "no plan of at most {horizon} steps"),
            Ending::Inconsistent => write!(f, "the observations are inconsistent"),
            Ending::ActionBudget => write!(f, "the action budget ran out"),
            Ending::ReplanBudget => write!(f, "the replanning budget ran out"),
            Ending::WorldError(m) => write!(f, "the world refused an action: {m}"),
            Ending::Input(m) => write!(f, "bad planning problem: {}", m.trim_end()),
        }
    }
}

/// The whole run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct History {
    /// [`FORMAT_VERSION`].
    pub version: u32,
    /// Where the scene came from (`generated simulated seed 7`, a file name, ...).
    pub scene: String,
    /// The movable objects.
    pub objects: Vec<String>,
    /// The statics the robot used (`has_size(a,large)`, ...).
    pub statics: Vec<String>,
    /// The goal, a conjunction of literals.
    pub goal: Vec<String>,
    /// Per step, from 0.
    pub steps: Vec<StepRecord>,
    /// Every plan, in the order made.
    pub plans: Vec<PlanRecord>,
    /// Every discrepancy, in step order.
    pub discrepancies: Vec<Discrepancy>,
    /// How the run ended; `None` while it runs.
    pub ending: Option<Ending>,
    /// Whether the goal holds in the world's ground truth at the end (`None` if the world
    /// cannot tell).
    pub goal_in_truth: Option<bool>,
}

impl History {
    /// An empty history of a run on `scene` towards `goal`.
    pub fn new(
        scene: String,
        objects: Vec<String>,
        statics: Vec<String>,
        goal: Vec<String>,
    ) -> Self {
        History {
            version: FORMAT_VERSION,
            scene,
            objects,
            statics,
            goal,
            steps: Vec::new(),
            plans: Vec::new(),
            discrepancies: Vec::new(),
            ending: None,
            goal_in_truth: None,
        }
    }

    /// The number of plans made after the first.
    pub fn replans(&self) -> usize {
        self.plans.len().saturating_sub(1)
    }

    /// The actions executed, in order.
    pub fn actions(&self) -> Vec<&str> {
        self.steps
            .iter()
            .filter_map(|s| s.happened.as_deref())
            .collect()
    }

    /// True when the run ended with the goal observed and, where the world can tell, true.
    pub fn succeeded(&self) -> bool {
        self.ending == Some(Ending::GoalObserved) && self.goal_in_truth != Some(false)
    }

    /// The history as JSON (pretty-printed).
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a history is plain data")
    }

    /// Reads a history written by [`History::to_json`].
    pub fn from_json(text: &str) -> Result<History, String> {
        let h: History = serde_json::from_str(text).map_err(|e| e.to_string())?;
        if h.version != FORMAT_VERSION {
            return Err(format!(
                "history format version {} (this build reads {FORMAT_VERSION})",
                h.version
            ));
        }
        for (i, s) in h.steps.iter().enumerate() {
            if s.step as usize != i {
                return Err(format!("step record {i} says it is step {}", s.step));
            }
        }
        Ok(h)
    }

    /// The run as an AL_d history: the believed literals of step 0 as `observed ... at 0.`, the
    /// observations of later steps (doubted ones left out) and `happened ... at I.` for every
    /// action executed. Statics and the object sort are not included.
    pub fn to_ald(&self) -> String {
        let mut out = String::new();
        for s in &self.steps {
            let _ = writeln!(out, "% step {}", s.step);
            let mut seen = std::collections::BTreeSet::new();
            for o in &s.observed {
                if s.doubted.contains(&o.fluent) || !seen.insert((&o.fluent, o.value)) {
                    continue;
                }
                let sign = if o.value { "" } else { "-" };
                let _ = writeln!(out, "observed {sign}{} at {}.", o.fluent, s.step);
            }
            if let Some(a) = &s.happened {
                let _ = writeln!(out, "happened {a} at {}.", s.step);
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn json_round_trip_and_version_check() {
        let mut h = History::new(
            "test".into(),
            vec!["a".into()],
            vec!["has_size(a,large)".into()],
            vec!["in_hand(rob1,a)".into()],
        );
        h.steps.push(StepRecord {
            step: 0,
            observed: vec![Observed {
                fluent: "relation(on,a,table)".into(),
                value: true,
                confidence: 0.9,
            }],
            looks: 1,
            happened: Some("pickup(rob1,a)".into()),
            ..StepRecord::default()
        });
        h.ending = Some(Ending::GoalObserved);
        let back = History::from_json(&h.to_json()).unwrap();
        assert_eq!(back, h);
        assert!(h.to_ald().contains("observed relation(on,a,table) at 0."));
        assert!(h.to_ald().contains("happened pickup(rob1,a) at 0."));
        let bumped = h.to_json().replace("\"version\": 1", "\"version\": 99");
        assert!(History::from_json(&bumped).is_err());
        let misnumbered = h.to_json().replace("\"step\": 0", "\"step\": 3");
        assert!(History::from_json(&misnumbered).is_err());
    }
}
