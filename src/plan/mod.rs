//! The planner (docs/domain.md 4): a client of [`crate::control::Control`] and
//! [`mod@crate::action::translate`].
//!
//! - [`plan`] finds the minimal plans of an AL_d planning problem (a description with an
//!   initial state and a goal): `search` grounds one new step part per horizon on one
//!   multi-shot Control (clingo's incmode), or reproduces the authors' fixed horizon.
//! - `problem`: the typed [`Problem`] value (domain, scene, goal, history, learned axioms)
//!   that plan, learn, explain and experiment build and translate, never as text.
//! - `scene` reads initial states written as facts (or simulator scenes) and goals as
//!   literals, as AL_d statements for a domain description.
//! - `check` replays a plan one transition at a time against the domain (the one-step
//!   program with the current state as the initial state) and classifies it as optimal,
//!   sub-optimal or incorrect (4.3), with the minimal length and CR count found by a search
//!   over states (A* under a lower bound drawn from E1, E5 and E7, transitions computed once
//!   per state), not by the planner's search.
//! - `act`, `history` and `tabletop` (feature `sim`): the sense-plan-act loop, its record and
//!   the simulated world it runs in.
//! - `physics` (feature `sim`) draws planning tasks from generated scenes (docs/domain.md 7.1) and
//!   replays plans in the rapier world without noise (actions succeed, goal measured, every
//!   object stable).
//!
//! Invariants:
//! - Plans are ordered by length, then by the number of CR rules applied (4.2): in the
//!   iterative modes only plans of the least length k, and among them only those with the
//!   fewest CR applications, are returned; each distinct action sequence once.
//! - A plan is the sequence of action terms `a` of `occurs(a, i)` for i = 0..k-1; answer sets
//!   that differ only in other atoms give one plan.
//! - An initial state without answer set is an error, not "no plan":
//!   [`PlanError::InitiallyUnstable`] or [`PlanError::Inconsistent`].
//! - Nothing here reads files, prints or reads the clock: bad input is a [`PlanError::Input`]
//!   with the diagnostics rendered against the caller's sources.

pub mod act;
pub(crate) mod check;
pub mod history;
#[cfg(feature = "sim")]
pub mod physics;
pub(crate) mod problem;
pub(crate) mod scene;
pub(crate) mod search;
#[cfg(feature = "sim")]
pub mod tabletop;

use crate::action::{self, ast::Description, ast::Value, Options};
use crate::base::SourceMap;
use crate::control::Symbol;

pub use check::{classify, replay, Quality, Replay, StateSearch, Verdict};
pub use problem::Problem;
pub use scene::{goal_statement, SceneFacts};

/// How the horizon is searched.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Search {
    /// Horizons 0, 1, ... on one Control, one `step(k)` part each (default).
    #[default]
    Incremental,
    /// Horizons 0, 1, ..., each translated and grounded afresh (the reference).
    Retranslate,
    /// The authors' fixed horizon n (docs/domain.md 4.1, 7.4): every plan reaching the goal by step
    /// n, lengths not minimized.
    Fixed(usize),
}

impl Search {
    /// The horizon search `lucent plan --search` names: `incremental`, `retranslate`.
    pub fn from_name(name: &str) -> Option<Search> {
        match name {
            "incremental" => Some(Search::Incremental),
            "retranslate" => Some(Search::Retranslate),
            _ => None,
        }
    }
}

/// What the planner is asked.
#[derive(Clone, Debug)]
pub struct PlanConfig {
    /// The largest horizon tried (H_max); see [`default_max_horizon`].
    pub max_horizon: usize,
    /// A profile of the description (`tabletop`, ...).
    pub profile: Option<String>,
    /// Switch overrides (`horizon` and `horizon_mode` are set by the planner).
    pub overrides: Vec<(String, Value)>,
    /// How the horizon is searched.
    pub search: Search,
    /// All distinct minimal plans (true) or the first one found.
    pub all: bool,
}

impl Default for PlanConfig {
    fn default() -> Self {
        PlanConfig {
            max_horizon: 10,
            profile: None,
            overrides: Vec::new(),
            search: Search::Incremental,
            all: true,
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

/// The planner's answer.
#[derive(Clone, Debug)]
pub struct Plans {
    /// The distinct plans (at least one), by length, CR applications and text; in the
    /// iterative modes all of them minimal.
    pub plans: Vec<Plan>,
    /// The length of the first plan (in the iterative modes, the least horizon with a plan).
    pub length: usize,
    /// The number of CR applications of the first plan.
    pub cr_applied: usize,
    /// The horizons solved.
    pub horizons_tried: usize,
    /// The answer sets behind the plans (the fixed mode's "number of plans", docs/domain.md 7.4).
    pub answer_sets: usize,
}

/// Why no plan was returned.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum PlanError {
    /// No plan of length at most H.
    NoPlanWithin(usize),
    /// The initial state (with the history) has no answer set.
    Inconsistent,
    /// The initial state has unstable objects (docs/domain.md 2.5), named here.
    InitiallyUnstable(Vec<String>),
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
            PlanError::InitiallyUnstable(objects) => write!(
                f,
                "initially_unstable({}): the initial scene has unstable objects, so no plan \
                 can keep every object stable",
                objects.join(", ")
            ),
            PlanError::Input(m) => write!(f, "{}", m.trim_end()),
        }
    }
}

impl std::error::Error for PlanError {}

/// docs/domain.md 4.1's default H_max: max(9, 2·|object| + 2), the objects being the members of the
/// sort `object` (or `movable` when there is no `object` sort) under `config`'s switches.
pub fn default_max_horizon(desc: &Description, config: &PlanConfig) -> usize {
    let checked = action::check(
        desc,
        &Options {
            profile: config.profile.clone(),
            overrides: config.overrides.clone(),
            ..Options::default()
        },
    );
    let objects = ["object", "movable"]
        .iter()
        .find_map(|s| checked.sorts.get(*s))
        .map_or(0, |s| s.members.len());
    (2 * objects + 2).max(9)
}

/// Finds the minimal plans of the planning problem `desc` (a description with an initial state
/// and a goal), trying horizons 0..=`config.max_horizon` (or, in [`Search::Fixed`], the plans
/// of the fixed horizon). `sources` are used to render diagnostics.
pub fn plan(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
) -> Result<Plans, PlanError> {
    match config.search {
        Search::Incremental => search::incremental(desc, sources, config, config.max_horizon),
        Search::Retranslate => search::retranslate(desc, sources, config, config.max_horizon),
        Search::Fixed(n) => search::fixed(desc, sources, config, n),
    }
}
