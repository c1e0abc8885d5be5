//! H2, plan quality with and without the learned axioms (docs/domain.md 7.4, the paper's Tables 2
//! and 3). A trial is one (scene, goal) pair of a preset, planned under both knowledge-base
//! conditions of 7.2 (without: the `learner` profile; with: plus the axioms of H1 run
//! `configuration mod runs`), in the authors' fixed-horizon mode and with our iterative planner,
//! every plan classified optimal, sub-optimal or incorrect against KB_full (4.3).
//!
//! A pair is [`pair`]: configuration `c` of a preset is `explain::h3::generate(preset, s)` with
//! `s` derived from the setup's seed, the preset and `c`; its goal 0 is the generated one and
//! goals 1.. are drawn from the same scene by 7.1's rule ([`draw_goal`]), so the five goals of a
//! configuration share one initial state. Both conditions plan with the `learner` profile's
//! switches (`table_is_object`, `sticky_support_fluents`) and the planning module on; the
//! ground truth is KB_full under the same two switches, the H1 oracle's. Plans are judged by
//! `plan::check`: a replay per distinct plan and one breadth-first search per pair for L* and
//! E* (4.3).
//!
//! Invariants: Table 2's ratios are with/without per pair, averaged over the pairs where both
//! conditions found a plan (the others are counted, not dropped silently); Table 3's fractions
//! are per trial, averaged over the trials of a condition that found at least one plan. The
//! fixed-horizon mode keeps at most [`FIXED_CAP`] answer sets per solve (the enumeration order
//! is the solver's, deterministic per program); a capped count says so (`capped`).

use std::collections::{BTreeSet, HashMap};
use std::time::Instant;

use serde::{Deserialize, Serialize};

use super::interval::{self, Interval};
use super::svg;
use super::{Context, Domain, Record, Trial, TrialError};
use crate::action::ast::{Description, Statement, Value};
use crate::action::{self, HorizonMode, Options, Switches};
use crate::base::rng::SplitMix64;
use crate::base::SourceMap;
use crate::control::{Control, ControlConfig, Part, SolveOptions, Symbol};
use crate::explain::h3::{generate, Goal, Scene, ScenePreset};
use crate::plan::check::{State, Successor};
use crate::plan::{self, replay, PlanConfig, Search, StateSearch};

/// The authors' horizon (docs/domain.md 7.4: 9 by default).
pub const FIXED_HORIZON: usize = 9;

/// Answer sets kept per fixed-horizon solve.
pub const FIXED_CAP: usize = 50;

/// States the breadth-first search for L* and E* may expand per pair.
pub const SEARCH_STATES: usize = 2_000;

/// The five H1 targets in `learn::h1::targets` order (E7, E5, E2, C3, C2), by KB_full label.
pub const TARGETS: [&str; 5] = ["E7", "E5", "E2", "C3", "C2"];

/// The H1 targets other than target `k`, as statements (labelled `kept_<label>`, so the
/// `learner` profile's drops of the KB_full labels do not remove them): the knowledge base of
/// the "one axiom missing" reading of 7.2 is the `learner` profile plus these.
pub fn targets_but(k: usize) -> Vec<Statement> {
    crate::learn::h1::targets()
        .iter()
        .zip(TARGETS)
        .enumerate()
        .filter(|(j, _)| *j != k)
        .map(|(_, (a, label))| a.statement(&format!("kept_{label}")))
        .collect()
}

/// Why H2 cannot run in this build, if it cannot.
pub fn availability() -> Result<(), String> {
    Ok(())
}

/// The preset of a trial config.
fn preset_of(config: &str) -> Option<ScenePreset> {
    ScenePreset::ALL.into_iter().find(|p| p.name() == config)
}

/// The seed of configuration `configuration` of `preset` under the setup's seed.
fn configuration_seed(seed: u64, preset: ScenePreset, configuration: usize) -> u64 {
    let purpose = ((preset as u64 + 1) << 32) | configuration as u64;
    SplitMix64::new(seed ^ 0x4832_5041_4952_5300)
        .fork(purpose)
        .next_u64()
}

/// The height of `x` in `scene`'s initial state (1 on the table).
fn level(scene: &Scene, x: &str) -> usize {
    let mut n = 0;
    let mut at = x.to_string();
    while at != "table" && n <= scene.objects.len() {
        n += 1;
        at = scene.support(&at).unwrap_or("table").to_string();
    }
    n
}

/// A goal for `scene` by docs/domain.md 7.1's rule: with probability 0.2 `in_hand(rob1, X)`, else
/// `on(X, Y)` with X movable, Y the table or an object with a flat top that is not small,
/// Y != X, not already true, and Y's tower low enough that X would stand at level 4 at most.
pub fn draw_goal(scene: &Scene, rng: &mut SplitMix64) -> Goal {
    let names: Vec<String> = scene.objects.iter().map(|o| o.name.clone()).collect();
    if rng.chance(0.2) {
        return Goal::InHand(rng.pick(&names).clone());
    }
    let mut pairs: Vec<(String, String)> = Vec::new();
    for x in &names {
        let mut places = vec!["table".to_string()];
        places.extend(
            scene
                .objects
                .iter()
                .filter(|o| o.surface == "flat" && o.size != "small" && o.name != *x)
                .map(|o| o.name.clone()),
        );
        for y in places {
            let already = scene.support(x) == Some(y.as_str());
            let high = y != "table" && level(scene, &y) + 1 > 4;
            if !already && !high {
                pairs.push((x.clone(), y));
            }
        }
    }
    let (x, y) = rng.pick(&pairs).clone();
    Goal::On(x, y)
}

/// The (scene, goal) pair of `preset`, configuration `configuration`, goal `goal`: goal 0 is
/// the generated scene's own; later goals are drawn by [`draw_goal`], each different from the
/// earlier ones when the scene allows it.
pub fn pair(preset: ScenePreset, seed: u64, configuration: usize, goal: usize) -> Scene {
    let cseed = configuration_seed(seed, preset, configuration);
    let mut scene = generate(preset, cseed);
    let mut goals = vec![scene.goal.clone()];
    let mut rng = SplitMix64::new(cseed).fork(0x474f_414c);
    while goals.len() <= goal {
        let mut g = draw_goal(&scene, &mut rng);
        for _ in 0..20 {
            if !goals.contains(&g) {
                break;
            }
            g = draw_goal(&scene, &mut rng);
        }
        goals.push(g);
    }
    scene.goal = goals.swap_remove(goal);
    scene
}

/// The switches both conditions and the ground truth share: the `learner` profile's sorts and
/// sticky support fluents (the planner turns the planning module on itself).
fn shared_overrides() -> Vec<(String, Value)> {
    vec![
        ("table_is_object".into(), Value::Bool(true)),
        ("sticky_support_fluents".into(), Value::Bool(true)),
    ]
}

/// A plan as action terms, from a model's `occurs(a, i)` atoms in step order.
fn plan_of(atoms: &[Symbol]) -> Vec<Symbol> {
    let mut steps: Vec<(i32, Symbol)> = atoms
        .iter()
        .filter(|s| s.is("occurs", 2) && !s.is_negative())
        .filter_map(|s| Some((s.args()[1].as_number()?, s.args()[0].clone())))
        .collect();
    steps.sort();
    steps.into_iter().map(|(_, a)| a).collect()
}

/// The authors' fixed horizon: the first [`FIXED_CAP`] answer sets at horizon `n` (CR-minimal),
/// their plans, and whether the cap cut the enumeration.
fn fixed_plans(
    desc: &Description,
    sources: &SourceMap,
    options: &Options,
    n: usize,
) -> Result<(usize, Vec<Vec<Symbol>>, bool), String> {
    let mut options = options.clone();
    options.switches.horizon = Some(n);
    options.switches.horizon_mode = Some(HorizonMode::Fixed);
    let t = action::translate(desc, &options);
    if t.has_errors() {
        let mut d = crate::base::Diagnostics::default();
        d.extend(t.diagnostics);
        return Err(d.render(sources));
    }
    let mut cc = ControlConfig::default();
    cc.solve.models = 0;
    let mut ctl = Control::with_sources(cc, sources.clone());
    ctl.add_program(t.program).map_err(|e| e.message)?;
    ctl.ground(&[Part::base()]).map_err(|e| e.message)?;
    let mut plans = Vec::new();
    let mut count = 0;
    let summary = ctl.solve(&SolveOptions::default(), |m| {
        count += 1;
        plans.push(plan_of(&m.atoms_named("occurs", 2)));
        count < FIXED_CAP
    });
    let capped = count >= FIXED_CAP && !summary.exhausted;
    Ok((count, plans, capped))
}

/// Judges plans against the ground truth (KB_full): each plan replayed by `plan::check`; L*
/// and E* found once per pair, by `plan::check`'s breadth-first search within
/// [`SEARCH_STATES`] states, else by the iterative planner over KB_full (its least length and
/// least CR count).
struct Judge<'a> {
    /// The transition program of the truth.
    truth: StateSearch,
    /// The truth as a planning problem (for the planner's fallback).
    desc: &'a Description,
    sources: &'a SourceMap,
    /// L* and E*, once known, and how they were found.
    minimal: Option<(Option<(usize, usize)>, MinimalBy)>,
    /// The initial state's least CR count and goal, once known (`plan::replay` of no action).
    start: Option<(usize, bool)>,
    /// Transitions met in replays: (state, action) to the successor with the least CR count
    /// (`None`: not executable). The plans of one pair share their initial state and most of
    /// their prefixes.
    transitions: HashMap<(State, Symbol), Option<Successor>>,
}

/// How L* and E* were found.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MinimalBy {
    /// No correct plan needed them.
    #[default]
    NotNeeded,
    /// `plan::check`'s breadth-first search over states.
    Search,
    /// The search ran out of states; the iterative planner over KB_full.
    Planner,
}

impl Judge<'_> {
    fn minimal(&mut self, depth: usize) -> Option<(usize, usize)> {
        if let Some((m, _)) = self.minimal {
            return m;
        }
        // A correct plan of length `depth` exists, so L* <= depth: the search to that depth
        // finds L* unless its state budget runs out.
        let found = match self.truth.minimal(depth, SEARCH_STATES) {
            Some(m) => (Some(m), MinimalBy::Search),
            None => {
                let config = PlanConfig {
                    max_horizon: depth,
                    overrides: shared_overrides(),
                    all: true,
                    ..PlanConfig::default()
                };
                let m = plan::plan(self.desc, self.sources, &config)
                    .ok()
                    .map(|p| (p.length, p.cr_applied));
                (m, MinimalBy::Planner)
            }
        };
        self.minimal = Some(found);
        found.0
    }

    /// `plan::replay`'s verdict (executable, no object unstable, goal at the end) and CR count,
    /// with the transitions remembered across the plans of the pair.
    fn replay(&mut self, plan: &[Symbol]) -> (bool, usize) {
        let (c0, g0) = *self.start.get_or_insert_with(|| {
            let r = replay(&mut self.truth, &[]);
            (r.cr_applied, r.goal)
        });
        let mut state = self.truth.initial().clone();
        let (mut cr, mut goal) = (c0, g0);
        for a in plan {
            let key = (state, a.clone());
            let next = match self.transitions.get(&key) {
                Some(n) => n.clone(),
                None => {
                    let (succs, _) = self.truth.successors(&key.0, Some(a));
                    let n = succs.into_iter().min_by_key(|s| s.cr_applied);
                    self.transitions.insert(key, n.clone());
                    n
                }
            };
            let Some(s) = next else {
                return (false, cr);
            };
            if !s.unstable.is_empty() {
                return (false, cr);
            }
            cr += s.cr_applied;
            goal = s.goal;
            state = s.state;
        }
        (goal, cr)
    }

    fn quality(&mut self, plan: &[Symbol]) -> plan::Quality {
        let (correct, cr_applied) = self.replay(plan);
        if !correct {
            return plan::Quality::Incorrect;
        }
        match self.minimal(plan.len()) {
            Some((l, e)) if l == plan.len() && e == cr_applied => plan::Quality::Optimal,
            _ => plan::Quality::SubOptimal,
        }
    }
}

/// The plans of one condition in one mode, in the order the planner returns them (answer sets
/// in the solver's order in fixed mode, duplicates kept): (answer sets, plans, capped, error).
type ModePlans = (usize, Vec<Vec<Symbol>>, bool, Option<String>);

/// Plans one condition in one mode ([`ModePlans`]).
fn mode_plans(
    desc: &Description,
    sources: &SourceMap,
    options: &Options,
    mode: Search,
) -> ModePlans {
    match mode {
        Search::Fixed(n) => match fixed_plans(desc, sources, options, n) {
            Ok((count, plans, capped)) => (count, plans, capped, None),
            Err(e) => (0, Vec::new(), false, Some(e)),
        },
        _ => {
            let config = PlanConfig {
                max_horizon: plan::default_max_horizon(
                    desc,
                    &PlanConfig {
                        profile: options.profile.clone(),
                        overrides: options.overrides.clone(),
                        ..PlanConfig::default()
                    },
                ),
                profile: options.profile.clone(),
                overrides: options.overrides.clone(),
                search: mode,
                all: true,
            };
            match plan::plan(desc, sources, &config) {
                Ok(p) => {
                    let actions: Vec<Vec<Symbol>> =
                        p.plans.iter().map(|p| p.actions.clone()).collect();
                    (actions.len(), actions, false, None)
                }
                Err(e) => (0, Vec::new(), false, Some(e.to_string())),
            }
        }
    }
}

/// Plans one condition in one mode and classifies its distinct plans.
fn run_mode(
    desc: &Description,
    sources: &SourceMap,
    options: &Options,
    mode: Search,
    judge: &mut Judge,
) -> ModeResult {
    let start = Instant::now();
    let (answer_sets, plans, capped, error) = mode_plans(desc, sources, options, mode);
    let time = start.elapsed().as_secs_f64();
    let distinct: BTreeSet<Vec<Symbol>> = plans.into_iter().collect();
    let mut out = ModeResult {
        plans: answer_sets,
        steps: 0.0,
        time,
        capped,
        error,
        ..ModeResult::default()
    };
    if distinct.is_empty() {
        out.plans = 0;
        return out;
    }
    let mut steps = 0usize;
    for p in &distinct {
        steps += p.len();
        match judge.quality(p) {
            plan::Quality::Optimal => out.optimal += 1,
            plan::Quality::SubOptimal => out.suboptimal += 1,
            plan::Quality::Incorrect => {
                out.incorrect += 1;
                if out.example_incorrect.is_none() {
                    out.example_incorrect = Some(
                        p.iter()
                            .enumerate()
                            .map(|(i, a)| format!("{a}@{i}"))
                            .collect::<Vec<_>>()
                            .join("; "),
                    );
                }
            }
        }
    }
    out.steps = steps as f64 / distinct.len() as f64;
    out
}

/// Plans `scene` (with its goal) under both conditions, without and with `learned` (the
/// axioms of an H1 run, as statements), with the iterative planner and, when `fixed`,
/// in the authors' fixed-horizon mode; every distinct plan is classified against KB_full.
/// `name` names the scene in diagnostics.
pub fn plan_pair(
    domain: &Domain,
    name: &str,
    scene: &Scene,
    learned: &[Statement],
    fixed: bool,
) -> Result<PairResult, TrialError> {
    plan_pair_with(domain, name, scene, learned, fixed, None)
}

/// The judge of a pair (the ground truth is the knowledge base without learned axioms, `plain`)
/// and the options every planner of the pair runs with (the learner's profile, planning on);
/// shared by the trial and its trace (`trace::trace_pair`).
fn judge_and_learner<'a>(
    name: &str,
    plain: &'a Description,
    sources: &'a SourceMap,
) -> Result<(Judge<'a>, Options), TrialError> {
    let truth_config = PlanConfig {
        overrides: shared_overrides(),
        ..PlanConfig::default()
    };
    let truth = StateSearch::new(plain, sources, &truth_config)
        .map_err(|e| TrialError::Input(format!("{name}: ground truth: {e}")))?;
    let judge = Judge {
        truth,
        desc: plain,
        sources,
        minimal: None,
        start: None,
        transitions: HashMap::new(),
    };
    let learner = Options {
        profile: Some("learner".into()),
        overrides: shared_overrides(),
        switches: Switches {
            planning: Some(true),
            ..Switches::default()
        },
    };
    Ok((judge, learner))
}

/// [`plan_pair`], and with `fixed_one = Some(k)` also the reading "one axiom missing" in the
/// fixed mode at horizon [`FIXED_HORIZON`]: the `learner` profile plus the targets other than
/// `TARGETS[k]` (one target per pair, as H4 draws it, since a fixed-horizon solve costs as much
/// as the other conditions together).
pub fn plan_pair_with(
    domain: &Domain,
    name: &str,
    scene: &Scene,
    learned: &[Statement],
    fixed: bool,
    fixed_one: Option<usize>,
) -> Result<PairResult, TrialError> {
    let problem = domain.scene_problem(scene)?;
    let (plain, sources) = (problem.description(), problem.sources.clone());
    let one_missing: Vec<(Description, SourceMap)> = (0..TARGETS.len())
        .map(|k| {
            let p = crate::plan::Problem {
                axioms: targets_but(k),
                ..problem.clone()
            };
            (p.description(), p.sources)
        })
        .collect();
    let taught_problem = crate::plan::Problem {
        axioms: learned.to_vec(),
        ..problem
    };
    let (taught, taught_sources) = (taught_problem.description(), taught_problem.sources);
    let (mut judge, learner) = judge_and_learner(name, &plain, &sources)?;
    let mut condition = |desc: &Description, sources: &SourceMap| Condition {
        fixed: if fixed {
            run_mode(
                desc,
                sources,
                &learner,
                Search::Fixed(FIXED_HORIZON),
                &mut judge,
            )
        } else {
            ModeResult::default()
        },
        iterative: run_mode(desc, sources, &learner, Search::Incremental, &mut judge),
    };
    let without = condition(&plain, &sources);
    let with = condition(&taught, &taught_sources);
    // Reading "one axiom missing" (7.2): the iterative planner without target k only.
    let without_one: Vec<ModeResult> = one_missing
        .iter()
        .map(|(d, s)| run_mode(d, s, &learner, Search::Incremental, &mut judge))
        .collect();
    // Reading "one axiom missing" in the authors' fixed mode, for the drawn target only.
    let fixed_one = fixed_one.filter(|&k| k < TARGETS.len()).map(|k| {
        let (d, s) = &one_missing[k];
        let m = run_mode(d, s, &learner, Search::Fixed(FIXED_HORIZON), &mut judge);
        (TARGETS[k].to_string(), m)
    });
    // Reading "horizon L* + 1": the authors' fixed mode at one step above the least plan, so
    // that a minimal plan and one step of detour are the only lengths.
    let least = judge.minimal.and_then(|(m, _)| m).map(|(l, _)| l);
    let fixed_near = least.map(|l| {
        let mut near = |d: &Description, s: &SourceMap| {
            run_mode(d, s, &learner, Search::Fixed(l + 1), &mut judge)
        };
        vec![near(&plain, &sources), near(&taught, &taught_sources)]
    });
    Ok(PairResult {
        preset: scene.preset.name().into(),
        configuration: 0,
        goal: 0,
        objects: scene.objects.len(),
        goal_text: match &scene.goal {
            Goal::On(x, y) => format!("relation(on, {x}, {y})"),
            Goal::InHand(x) => format!("in_hand(rob1, {x})"),
        },
        min_length: judge.minimal.and_then(|(m, _)| m).map(|(l, _)| l),
        min_cr: judge.minimal.and_then(|(m, _)| m).map(|(_, e)| e),
        min_by: judge.minimal.map(|(_, by)| by).unwrap_or_default(),
        without,
        with,
        without_one,
        fixed_near: fixed_near.unwrap_or_default(),
        fixed_one,
    })
}

/// Runs one (scene, goal) pair.
pub fn run_trial(ctx: &Context, trial: &Trial, seed: u64) -> Result<serde_json::Value, TrialError> {
    let preset = preset_of(&trial.config)
        .ok_or_else(|| TrialError::Input(format!("unknown preset '{}'", trial.config)))?;
    let goals = ctx.setup.goals.max(1);
    let (configuration, goal) = (trial.index / goals, trial.index % goals);
    if ctx.setup.runs == 0 {
        return Err(TrialError::Input(
            "H2 plans with the axioms of an H1 run: it needs --runs 1 or more".into(),
        ));
    }
    let learned = super::h1::learned_statements(ctx, configuration % ctx.setup.runs)?;
    let scene = pair(preset, ctx.setup.seed, configuration, goal);
    let name = format!("<h2 {}>", trial.id());
    // The target missing in the fixed-horizon "one missing" reading, drawn as H4 draws its own.
    let k = SplitMix64::new(seed)
        .fork(0x4f4e_4500)
        .below(TARGETS.len() as u64) as usize;
    let mut result = plan_pair_with(ctx.domain, &name, &scene, &learned, true, Some(k))?;
    result.configuration = configuration;
    result.goal = goal;
    serde_json::to_value(result).map_err(|e| TrialError::Store(e.to_string()))
}

/// One planning mode's outcome for one condition.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct ModeResult {
    /// Plans returned (answer sets at the horizon in fixed mode, distinct minimal plans in
    /// iterative mode); 0 when there was none.
    pub plans: usize,
    /// Their mean number of steps (actions).
    pub steps: f64,
    /// Planning time, in seconds.
    pub time: f64,
    /// Plans classified optimal.
    pub optimal: usize,
    /// Plans classified sub-optimal.
    pub suboptimal: usize,
    /// Plans classified incorrect.
    pub incorrect: usize,
    /// Fixed mode: the enumeration stopped at [`FIXED_CAP`] answer sets.
    #[serde(default)]
    pub capped: bool,
    /// Why no plan was returned (no plan within the horizon, an inconsistent scene).
    #[serde(default)]
    pub error: Option<String>,
    /// One incorrect plan, for the reader.
    #[serde(default)]
    pub example_incorrect: Option<String>,
}

/// One condition (without or with the learned axioms).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Condition {
    /// The authors' fixed-horizon mode.
    pub fixed: ModeResult,
    /// Our iterative planner.
    pub iterative: ModeResult,
}

/// One trial's result.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PairResult {
    /// The preset.
    pub preset: String,
    /// The configuration (scene) index.
    pub configuration: usize,
    /// The goal index.
    pub goal: usize,
    /// Objects in the scene.
    pub objects: usize,
    /// The goal, as AL_d literals.
    pub goal_text: String,
    /// The minimal plan length L* (when a correct plan needed it).
    pub min_length: Option<usize>,
    /// The least CR count E* among plans of length L*.
    #[serde(default)]
    pub min_cr: Option<usize>,
    /// How L* and E* were found.
    #[serde(default)]
    pub min_by: MinimalBy,
    /// Without the learned axioms.
    pub without: Condition,
    /// With them.
    pub with: Condition,
    /// Reading "one axiom missing": the iterative planner without target `TARGETS[k]` only
    /// (the `learner` profile plus the other four), per k; empty in results stored before.
    #[serde(default)]
    pub without_one: Vec<ModeResult>,
    /// Reading "horizon L* + 1": the fixed mode at horizon L* + 1, without and with the learned
    /// axioms; empty when L* is unknown or in results stored before.
    #[serde(default)]
    pub fixed_near: Vec<ModeResult>,
    /// Reading "one axiom missing" in the fixed mode at horizon [`FIXED_HORIZON`]: the missing
    /// target (drawn per trial from its seed) and the result; `None` in results stored before.
    #[serde(default)]
    pub fixed_one: Option<(String, ModeResult)>,
}

/// Table 2 for one preset and mode: ratios with/without, averaged over pairs.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Ratios {
    /// Number of steps.
    pub steps: Option<f64>,
    /// Number of plans.
    pub plans: Option<f64>,
    /// Planning time.
    pub planning_time: Option<f64>,
    /// 95% intervals of the three (bootstrap over the pairs, `interval`).
    pub steps_ci: Option<Interval>,
    /// Of the number of plans.
    pub plans_ci: Option<Interval>,
    /// Of the planning time.
    pub ci_planning_time: Option<Interval>,
    /// Pairs where both conditions found a plan (the ratios' denominators).
    pub pairs: usize,
    /// Pairs left out because a condition found no plan.
    pub pairs_without_plan: usize,
}

/// Table 3 for one preset, mode and condition: fractions of plans, averaged over trials.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Fractions {
    /// Optimal.
    pub optimal: Option<f64>,
    /// Sub-optimal.
    pub suboptimal: Option<f64>,
    /// Incorrect.
    pub incorrect: Option<f64>,
    /// 95% intervals of the three (bootstrap over the trials, `interval`).
    pub optimal_ci: Option<Interval>,
    /// Of the sub-optimal fraction.
    pub suboptimal_ci: Option<Interval>,
    /// Of the incorrect fraction.
    pub incorrect_ci: Option<Interval>,
    /// Trials with at least one plan.
    pub trials: usize,
}

/// One preset and mode.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct ModeSummary {
    /// Table 2.
    pub ratios: Ratios,
    /// Table 3, without the learned axioms.
    pub without: Fractions,
    /// Table 3, with them.
    pub with: Fractions,
}

/// Why fixed-horizon plans with the learned axioms are mostly sub-optimal: their length
/// against the minimal one, over the pairs where that condition found a plan and L* is known.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct FixedLengths {
    /// Pairs counted.
    pub pairs: usize,
    /// Mean over those pairs of the mean length of their distinct fixed-horizon plans.
    pub mean_steps: Option<f64>,
    /// Mean L*.
    pub mean_min_length: Option<f64>,
    /// Pairs whose least plan needs a CR exception (E* > 0).
    pub exception_pairs: usize,
    /// Pairs whose enumeration stopped at [`FIXED_CAP`] answer sets.
    pub capped: usize,
}

/// One preset.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct PresetSummary {
    /// Pairs (trials).
    pub pairs: usize,
    /// Fixed horizon, with the learned axioms: plan lengths against L*.
    #[serde(default)]
    pub fixed_lengths: FixedLengths,
    /// The authors' fixed-horizon mode.
    pub fixed: ModeSummary,
    /// Our iterative planner.
    pub iterative: ModeSummary,
    /// Other readings of the paper's conditions (7.2) and horizon.
    pub readings: Readings,
}

/// H2's tables.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Summary {
    /// The `real` preset.
    pub real: PresetSummary,
    /// The `simulated` preset.
    pub simulated: PresetSummary,
    /// Planning time against scene size: (objects, seconds) per pair, iterative mode, without
    /// and with the learned axioms.
    #[serde(skip)]
    pub time_by_size: [Vec<(f64, f64)>; 2],
}

mod report;
pub use report::*;
pub mod trace;

#[cfg(test)]
mod tests {
    use super::*;

    fn mode(plans: usize, steps: f64, time: f64, o: usize, s: usize, i: usize) -> ModeResult {
        ModeResult {
            plans,
            steps,
            time,
            optimal: o,
            suboptimal: s,
            incorrect: i,
            ..ModeResult::default()
        }
    }

    #[test]
    fn ratios_and_fractions_by_hand() {
        let a = PairResult {
            preset: "real".into(),
            without: Condition {
                fixed: mode(4, 2.0, 1.0, 1, 1, 2),
                iterative: mode(1, 2.0, 1.0, 1, 0, 0),
            },
            with: Condition {
                fixed: mode(2, 3.0, 0.5, 2, 0, 0),
                iterative: mode(1, 3.0, 1.0, 1, 0, 0),
            },
            ..Default::default()
        };
        let b = PairResult {
            with: Condition {
                fixed: mode(0, 0.0, 0.1, 0, 0, 0),
                ..a.with.clone()
            },
            ..a.clone()
        };
        let records: Vec<Record> = [a, b]
            .iter()
            .enumerate()
            .map(|(k, p)| Record {
                id: format!("h2-real-{k:04}"),
                setup: super::super::Setup::paper(0),
                trial_seed: 0,
                seconds: 0.0,
                result: serde_json::to_value(p).unwrap(),
            })
            .collect();
        let s = aggregate(&records).unwrap();
        let f = &s.real.fixed;
        // Only pair a has plans in both conditions: steps 3/2, plans 2/4, time 0.5/1.
        assert_eq!(f.ratios.pairs, 1);
        assert_eq!(f.ratios.pairs_without_plan, 1);
        assert_eq!(f.ratios.steps, Some(1.5));
        assert_eq!(f.ratios.plans, Some(0.5));
        assert_eq!(f.ratios.planning_time, Some(0.5));
        // Without: both trials have 1 optimal, 1 sub-optimal, 2 incorrect of 4.
        assert_eq!(f.without.optimal, Some(0.25));
        assert_eq!(f.without.incorrect, Some(0.5));
        assert_eq!(f.without.trials, 2);
        // With: only pair a has plans, both optimal.
        assert_eq!(f.with.optimal, Some(1.0));
        assert_eq!(f.with.trials, 1);
        assert_eq!(s.simulated.pairs, 0);
        assert_eq!(s.simulated.fixed.with.optimal, None);
    }
}
