//! The planner (DOMAIN.md 4.1-4.2): a client of [`crate::control::Control`] and
//! [`crate::action::translate`]. It searches the iterative horizon k = 0, 1, ..., H_max: at
//! each k the description is translated with `horizon = k` and `horizon_mode = iterative`
//! (`:- not goal(k)`), grounded and solved; the first satisfiable k is the minimal plan length.
//!
//! Invariants:
//! - Plans are ordered by length, then by the number of CR rules applied (4.2): only plans of
//!   the least length k, and among them only those with the fewest CR applications, are
//!   returned; each distinct action sequence once, sorted by its text.
//! - A plan is the sequence of action terms `a` of `occurs(a, i)` for i = 0..k-1 (the step is
//!   dropped); answer sets that differ only in other atoms give one plan.
//! - Before searching, the scene is solved without the planning module at horizon 0: an
//!   inconsistent scene is [`PlanError::Inconsistent`], not "no plan".
//! - Nothing here reads files or prints: bad input is a [`PlanError::Input`] with the
//!   diagnostics rendered against the caller's sources.
//!
//! Not yet here: one Control grounding a `#program step(t)` part per horizon (the translator
//! has no such mode yet, so each horizon is translated and grounded afresh), the fixed-horizon
//! mode and `initially_unstable` detection.

pub mod act;
pub mod history;
#[cfg(feature = "sim")]
pub mod tabletop;

use std::collections::BTreeMap;

use crate::action::{self, ast::Description, ast::Value, Options};
use crate::base::{Diagnostics, SourceMap};
use crate::control::{Control, ControlConfig, Part, Symbol};

/// What the planner is asked.
#[derive(Clone, Debug)]
pub struct PlanConfig {
    /// The largest horizon tried (H_max).
    pub max_horizon: usize,
    /// A profile of the description (`tabletop`, ...).
    pub profile: Option<String>,
    /// Switch overrides (`horizon` and `horizon_mode` are set by the planner).
    pub overrides: Vec<(String, Value)>,
}

impl Default for PlanConfig {
    fn default() -> Self {
        PlanConfig {
            max_horizon: 10,
            profile: None,
            overrides: Vec::new(),
        }
    }
}

/// One plan: its actions in step order, and the CR rules applied in its answer set.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Plan {
    /// The action terms, one per step (`pickup(rob1,pitcher)`).
    pub actions: Vec<Symbol>,
    /// The labels of the applied CR rules (`d1x(mug,2)`), sorted.
    pub cr_applied: Vec<Symbol>,
}

impl Plan {
    /// The plan as `a@0; b@1; ...`.
    pub fn to_text(&self) -> String {
        self.actions
            .iter()
            .enumerate()
            .map(|(i, a)| format!("{a}@{i}"))
            .collect::<Vec<_>>()
            .join("; ")
    }
}

/// The planner's answer: the minimal plans.
#[derive(Clone, Debug)]
pub struct Plans {
    /// The distinct minimal plans (at least one), sorted by their text.
    pub plans: Vec<Plan>,
    /// Their length (the least horizon with a plan).
    pub length: usize,
    /// The number of CR applications of each of them.
    pub cr_applied: usize,
    /// The horizons tried (0..=length).
    pub horizons_tried: usize,
}

/// Why no plan was returned.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PlanError {
    /// No plan of length at most H.
    NoPlanWithin(usize),
    /// The initial state (with the history) has no answer set.
    Inconsistent,
    /// The description is not a valid planning problem; the rendered diagnostics.
    Input(String),
}

impl std::fmt::Display for PlanError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            PlanError::NoPlanWithin(h) => {
                write!(f, "no_plan_within({h}): no plan of length at most {h}")
            }
            PlanError::Inconsistent => write!(
                f,
                "the scene is inconsistent: its initial state has no answer set"
            ),
            PlanError::Input(m) => write!(f, "{}", m.trim_end()),
        }
    }
}

impl std::error::Error for PlanError {}

/// The answer sets of `desc` at `horizon` with the switches `extra` (on top of the config's).
fn solve_at(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
    extra: &[(&str, Value)],
) -> Result<Vec<crate::control::OwnedModel>, PlanError> {
    let mut overrides = config.overrides.clone();
    overrides.extend(extra.iter().map(|(n, v)| (n.to_string(), v.clone())));
    let options = Options {
        profile: config.profile.clone(),
        overrides,
    };
    let t = action::translate(desc, &options);
    if t.has_errors() {
        let mut d = Diagnostics::default();
        d.extend(t.diagnostics);
        return Err(PlanError::Input(d.render(sources)));
    }
    let mut ctl = Control::with_sources(ControlConfig::default(), sources.clone());
    ctl.add_program(t.program)
        .map_err(|e| PlanError::Input(e.message))?;
    ctl.ground(&[Part::base()])
        .map_err(|e| PlanError::Input(e.message))?;
    Ok(ctl.solve_all(&Default::default()).models)
}

/// The plan of one answer set: the actions of `occurs(a, i)` in step order.
fn plan_of(model: &crate::control::OwnedModel) -> Plan {
    let mut steps = BTreeMap::new();
    for s in &model.atoms {
        if s.is("occurs", 2) && !s.is_negative() {
            if let Some(i) = s.args()[1].as_number() {
                steps.insert(i, s.args()[0].clone());
            }
        }
    }
    let mut cr_applied = model.cr_applied.clone();
    cr_applied.sort();
    Plan {
        actions: steps.into_values().collect(),
        cr_applied,
    }
}

/// Finds the minimal plans of the planning problem `desc` (a description with a history and a
/// goal), trying horizons 0..=`config.max_horizon`. `sources` are used to render diagnostics.
pub fn plan(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
) -> Result<Plans, PlanError> {
    let consistent = solve_at(
        desc,
        sources,
        config,
        &[("horizon", Value::Int(0)), ("planning", Value::Bool(false))],
    )?;
    if consistent.is_empty() {
        return Err(PlanError::Inconsistent);
    }
    for k in 0..=config.max_horizon {
        let models = solve_at(
            desc,
            sources,
            config,
            &[
                ("horizon", Value::Int(k as i64)),
                ("horizon_mode", Value::Word("iterative".into())),
            ],
        )?;
        if models.is_empty() {
            continue;
        }
        let mut plans: Vec<Plan> = models.iter().map(plan_of).collect();
        let least = plans.iter().map(|p| p.cr_applied.len()).min().unwrap_or(0);
        plans.retain(|p| p.cr_applied.len() == least);
        plans.sort_by_key(Plan::to_text);
        plans.dedup_by(|a, b| a.actions == b.actions);
        return Ok(Plans {
            plans,
            length: k,
            cr_applied: least,
            horizons_tried: k + 1,
        });
    }
    Err(PlanError::NoPlanWithin(config.max_horizon))
}
