//! H2 diagnostics (issue 34): one (scene, goal) pair's plans in the order the planner returns
//! them, each judged against KB_full as the trial judges it, with what the trial's records do
//! not keep: the plan itself, its CR count, the first step that fails and why, and whether the
//! goal holds at the end when the steps that cannot be executed are skipped (the robot tries
//! them and nothing changes). `examples/h2_trace.rs` prints these as JSON lines and
//! `scripts/h2_readings.py` computes the other readings of "optimal", "incorrect" and "plans"
//! from them (docs/experiments/gaps.md).
//!
//! Invariants: the plans are produced by the trial's own code (`mode_plans`, the same options,
//! horizon and cap) and classified by its `Judge`, so the verdicts are the trial's; fixed-mode
//! answer sets are listed in the solver's order, duplicates kept (the trial counts distinct
//! plans).

use serde::Serialize;

use super::{
    judge_and_learner, mode_plans, shared_overrides, Judge, Search, Statement, TrialError,
    FIXED_HORIZON, TARGETS,
};
use crate::action::{Options, Switches};
use crate::experiment::Domain;
use crate::explain::h3::{Goal, Scene};
use crate::plan;

/// One plan as the planner returned it.
#[derive(Clone, Debug, Serialize)]
pub struct PlanTrace {
    /// Its actions in step order, as text.
    pub actions: Vec<String>,
    /// The trial's verdict (docs/domain.md 4.3): optimal, sub-optimal or incorrect.
    pub quality: &'static str,
    /// CR applications over its replay against KB_full (up to the failing step).
    pub cr_applied: usize,
    /// The first step that cannot be executed or leaves an object unstable, with the reason.
    pub failed: Option<(usize, String)>,
    /// The goal holds after the last action when the steps that cannot be executed are skipped
    /// (no change); false when a step leaves an object unstable.
    pub goal_if_skipped: bool,
}

/// One condition in one mode.
#[derive(Clone, Debug, Serialize)]
pub struct ModeTrace {
    /// `without` (all five targets missing), `with` (the learned axioms) or `without_E7` ...
    /// (only that target missing).
    pub condition: String,
    /// `fixed` or `iterative`.
    pub mode: String,
    /// The horizon (fixed mode).
    pub horizon: Option<usize>,
    /// The plans, in the planner's order (fixed: one per answer set).
    pub plans: Vec<PlanTrace>,
    /// The fixed mode's enumeration stopped at the cap.
    pub capped: bool,
    /// Why there was no plan.
    pub error: Option<String>,
}

/// One pair.
#[derive(Clone, Debug, Serialize)]
pub struct PairTrace {
    /// The goal, as in the trial's record.
    pub goal_text: String,
    /// Objects in the scene.
    pub objects: usize,
    /// Objects in the initial state with something on them.
    pub covered: usize,
    /// The goal's object has something on it in the initial state.
    pub goal_object_covered: bool,
    /// L* and E*, when a correct plan needed them.
    pub min_length: Option<usize>,
    /// E*.
    pub min_cr: Option<usize>,
    /// Every condition and mode traced.
    pub modes: Vec<ModeTrace>,
}

/// Traces `scene` (with its goal) without and with `learned`, in the fixed mode at `horizon`
/// (the trial's [`FIXED_HORIZON`] by default) and with the iterative planner; with `one_missing`
/// also the iterative planner under each one-missing knowledge base.
pub fn trace_pair(
    domain: &Domain,
    name: &str,
    scene: &Scene,
    learned: &[Statement],
    horizon: Option<usize>,
    one_missing: bool,
) -> Result<PairTrace, TrialError> {
    let problem = domain.scene_problem(scene)?;
    let (plain, sources) = (problem.description(), problem.sources.clone());
    let taught = crate::plan::Problem {
        axioms: learned.to_vec(),
        ..problem.clone()
    };
    let (mut judge, learner) = judge_and_learner(name, &plain, &sources)?;
    let horizon = horizon.unwrap_or(FIXED_HORIZON);
    let mut kbs = vec![
        ("without".to_string(), plain.clone(), sources.clone()),
        ("with".to_string(), taught.description(), taught.sources),
    ];
    if one_missing {
        for (k, label) in TARGETS.iter().enumerate() {
            let p = crate::plan::Problem {
                axioms: super::targets_but(k),
                ..problem.clone()
            };
            kbs.push((format!("without_{label}"), p.description(), p.sources));
        }
    }
    let mut modes = Vec::new();
    for (condition, desc, srcs) in &kbs {
        let searches: &[Search] = if condition.starts_with("without_") {
            &[Search::Incremental]
        } else {
            &[Search::Fixed(horizon), Search::Incremental]
        };
        for &search in searches {
            let (_, plans, capped, error) = mode_plans(desc, srcs, &learner, search);
            let plans = plans.iter().map(|p| trace_plan(&mut judge, p)).collect();
            modes.push(ModeTrace {
                condition: condition.clone(),
                mode: match search {
                    Search::Fixed(_) => "fixed".into(),
                    _ => "iterative".into(),
                },
                horizon: match search {
                    Search::Fixed(n) => Some(n),
                    _ => None,
                },
                plans,
                capped,
                error,
            });
        }
    }
    let least = judge.minimal.and_then(|(m, _)| m);
    let covered = scene
        .objects
        .iter()
        .filter(|o| {
            scene
                .objects
                .iter()
                .any(|p| scene.support(&p.name) == Some(&o.name))
        })
        .count();
    let goal_object = match &scene.goal {
        Goal::On(x, _) | Goal::InHand(x) => x.clone(),
    };
    Ok(PairTrace {
        goal_text: match &scene.goal {
            Goal::On(x, y) => format!("relation(on, {x}, {y})"),
            Goal::InHand(x) => format!("in_hand(rob1, {x})"),
        },
        objects: scene.objects.len(),
        covered,
        goal_object_covered: scene
            .objects
            .iter()
            .any(|p| scene.support(&p.name) == Some(goal_object.as_str())),
        min_length: least.map(|(l, _)| l),
        min_cr: least.map(|(_, e)| e),
        modes,
    })
}

/// The learned axioms of an H1 run's stored record, as H2 trials read them
/// (`h1::learned_statements`).
pub fn learned_of(record: &crate::experiment::Record) -> Result<Vec<Statement>, TrialError> {
    let r: crate::experiment::h1::RunResult = serde_json::from_value(record.result.clone())
        .map_err(|e| TrialError::Store(format!("{}: {e}", record.id)))?;
    Ok(r.axioms
        .iter()
        .map(|(label, axiom)| axiom.statement(label))
        .collect())
}

/// One plan judged as the trial judges it, with its replay's details.
fn trace_plan(judge: &mut Judge, plan: &[crate::control::Symbol]) -> PlanTrace {
    let quality = judge.quality(plan).name();
    let r = plan::replay(&mut judge.truth, plan);
    // The same plan with the steps that cannot be executed skipped.
    let mut state = judge.truth.initial().clone();
    let mut goal = r.states.len() == 1 && r.goal;
    let mut unstable = false;
    if !plan.is_empty() {
        goal = false;
        for a in plan {
            let (succs, _) = judge.truth.successors(&state, Some(a));
            if let Some(s) = succs.into_iter().min_by_key(|s| s.cr_applied) {
                if !s.unstable.is_empty() {
                    unstable = true;
                    break;
                }
                goal = s.goal;
                state = s.state;
            }
        }
    }
    PlanTrace {
        actions: plan.iter().map(|a| a.to_string()).collect(),
        quality,
        cr_applied: r.cr_applied,
        failed: r.failed,
        goal_if_skipped: goal && !unstable,
    }
}

/// The CR-Prolog program the fixed mode solves for `scene` at `horizon`, without the targets
/// (`learned` empty) or with `learned`, as text (`syntax::printer`), to compare the solver's
/// enumeration with another solver's.
pub fn fixed_program(
    domain: &Domain,
    scene: &Scene,
    learned: &[Statement],
    horizon: usize,
) -> Result<String, TrialError> {
    let problem = domain.scene_problem(scene)?;
    let problem = crate::plan::Problem {
        axioms: learned.to_vec(),
        ..problem
    };
    let mut options = Options {
        profile: Some("learner".into()),
        overrides: shared_overrides(),
        switches: Switches {
            planning: Some(true),
            ..Switches::default()
        },
    };
    options.switches.horizon = Some(horizon);
    options.switches.horizon_mode = Some(crate::action::HorizonMode::Fixed);
    let t = crate::action::translate(&problem.description(), &options);
    if t.has_errors() {
        return Err(TrialError::Input("the program has errors".into()));
    }
    Ok(crate::syntax::printer::print(&t.program))
}
