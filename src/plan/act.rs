//! The sense-plan-act loop of docs/domain.md 4.4: perceive, make the observations consistent, plan
//! from what is believed, execute one action, perceive again, compare the predicted with the
//! observed state, and on a mismatch or a failed action record a [`Discrepancy`] and replan from
//! the observed state; until the goal is observed (and confirmed by looking again) or a budget
//! runs out. The world is anything that implements [`World`] (the rapier tabletop in
//! `plan::tabletop`, a scripted double in tests), so this module builds without `sim`.
//!
//! Noisy perception and consistency (the decision, also in ARCHITECTURE.md and
//! `domains/ra/README.md`): before every plan the step's perceived relations are *doubted* in a
//! separate diagnosis solve at horizon 0, without the planning module: each perceived relation
//! `f` holds by default (`holds(f,0) :- seen(f), not -holds(f,0).`) and the CR rule
//! `doubt(f) : -holds(f,0) :+ seen(f).` may drop it; the cardinality-minimal sets of doubts
//! restore consistency (the planning constraint `never -stable(A)` included), ties broken by the
//! lowest total confidence of the doubted readings. Only the rest become the planning problem's
//! `initially` facts. Doubts never enter the planning problem itself, because the planner
//! minimizes length before CR applications and would otherwise doubt an obstacle away to find a
//! shorter plan.
//!
//! What is compared (docs/domain.md 5.1): the prediction is the robot's own domain projected one
//! step (horizon 1, `happened a at 0.`), the observation the next step's belief; a discrepancy is
//! recorded when they differ on `relation(on, X, Y)` (positive) or `in_hand(R, O)`, or when the
//! world reports a failed action. The discrepancy carries all positive observable literals.
//!
//! Three guards before giving up or acting \[ours\]: when the planner finds no plan from a belief,
//! the robot looks again (`RunConfig::relooks` times, fresh perceptions) and plans from the new
//! belief; before each action of an older plan it checks the action against the current
//! belief (the one-step prediction is empty when the domain says it is not executable) and
//! replans instead of executing it; and a look that contradicts the robot's expectation (a
//! discrepancy with the prediction, or the next action not executable in the new belief) is
//! confirmed by `RunConfig::confirm_looks` more looks at the same step, the majority of all of
//! them ([`fuse`]) being believed, before a discrepancy is recorded or the plan given up
//! (docs/domain.md 4.4 lets the robot perceive again; with one look per step a single misreading
//! made plans move objects back and forth, docs/bench/episodes-2026-12-04.md). And when the
//! next action is not executable after a putdown (the object put down now hides another from
//! the camera, which the domain does not predict, and E8 forbids the pickup), later plans
//! prefer a minimal plan without that putdown, so the robot does not repeat it forever.
//!
//! Invariants: nothing here reads files, prints or reads the clock (progress goes to the
//! caller's callback); every plan is made from the belief of the step it starts at; the
//! history's steps are numbered from 0 with one action at most between two steps; a run is
//! a function of the world's behaviour (the sim world is seeded) and the configuration.

use std::collections::{BTreeSet, VecDeque};

use super::history::{Discrepancy, Ending, History, Observed, PlanRecord, StepRecord};
use super::Problem;
use super::{plan, PlanConfig, PlanError};
use crate::action::{ast::Description, Options, Switches};
use crate::base::SourceMap;
use crate::control::{Control, ControlConfig, Part, Symbol};

/// One perceived fluent literal.
#[derive(Clone, Debug, PartialEq)]
pub struct Seen {
    /// The fluent (`relation(on,a,b)`, `in_hand(rob1,a)`).
    pub fluent: Symbol,
    /// Its observed value.
    pub value: bool,
    /// The perceiver's confidence; 1 for exact senses.
    pub confidence: f64,
    /// True for a reading the robot takes as certain (proprioception: the hand), never doubted.
    pub exact: bool,
}

/// What the robot perceives at one look.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Percept {
    /// Static facts (`has_size(a,large)`, `has_surface(a,flat)`).
    pub statics: Vec<Symbol>,
    /// Fluent literals (above the perceiver's confidence threshold).
    pub fluents: Vec<Seen>,
}

/// The world the robot acts in.
pub trait World {
    /// The movable objects' names (the domain's sort `movable`).
    fn objects(&self) -> Vec<String>;
    /// Perceives the current state; `look` counts the looks at the same step (0 first), and a
    /// noisy world draws independent errors per look.
    fn perceive(&mut self, look: u32) -> Percept;
    /// Executes an action; `Ok(None)` if it had its intended effect, `Ok(Some(why))` if it
    /// failed in the world, `Err` if the world cannot even attempt it (a bad name).
    fn execute(&mut self, action: &Symbol) -> Result<Option<String>, String>;
    /// Whether a fluent literal holds in the world's ground truth (`None`: cannot tell).
    fn holds_in_truth(&mut self, literal: &Symbol) -> Option<bool>;
}

/// How the loop runs.
#[derive(Clone, Debug)]
pub struct RunConfig {
    /// The planner's configuration (horizon budget, profile, switches).
    pub plan: PlanConfig,
    /// At most this many actions are executed.
    pub max_actions: usize,
    /// At most this many plans are made (the first included).
    pub max_plans: usize,
    /// Look again when the goal seems to hold, and stop only if the second look agrees.
    pub confirm_goal: bool,
    /// Looks per perception, fused by majority ([`fuse`]); 1 takes each look as it is.
    pub looks: u32,
    /// When the planner finds no plan (or the belief is inconsistent or unstable), look again
    /// this many times at the same step, each a fresh perception, before giving up: a noisy
    /// reading (a cycle of `behind`) can make a reachable goal look unreachable.
    pub relooks: u32,
    /// When a look contradicts what the robot expects (a discrepancy with the prediction, or the
    /// next action of its plan not executable in the new belief), it takes this many more looks
    /// at the same step and believes the majority of all of them ([`fuse`]) before it records a
    /// discrepancy or replans: one misreading in a look otherwise sends the robot after a
    /// belief that the next look flips back. 0 believes each first look as it is.
    pub confirm_looks: u32,
}

impl Default for RunConfig {
    fn default() -> Self {
        RunConfig {
            plan: PlanConfig {
                max_horizon: 12,
                ..PlanConfig::default()
            },
            max_actions: 24,
            max_plans: 12,
            confirm_goal: true,
            looks: 1,
            relooks: 2,
            confirm_looks: 2,
        }
    }
}

/// What the loop reports while it runs, for a progress line.
#[derive(Clone, Debug)]
pub enum Event<'a> {
    /// The robot perceived step `step` (look `look`).
    Perceived {
        /// The step.
        step: u32,
        /// The first look of this perception at that step.
        look: u32,
        /// How many observations it doubted.
        doubted: usize,
    },
    /// A plan was made.
    Planned(&'a PlanRecord),
    /// An action was executed.
    Acted {
        /// The step it was executed at.
        step: u32,
        /// The action.
        action: &'a str,
        /// The world's account of its failure.
        failure: Option<&'a str>,
    },
    /// A discrepancy was recorded.
    Discrepancy(&'a Discrepancy),
}

/// A domain: a parsed AL_d description (KB_full, without objects or state) and its sources.
#[derive(Clone, Debug)]
pub struct Domain {
    /// The description.
    pub description: Description,
    /// The sources it was parsed from (for diagnostics).
    pub sources: SourceMap,
}

/// What the robot believes at one step.
#[derive(Clone, Debug, Default)]
struct Belief {
    /// The observations kept (hard facts of the planning problem), positive fluents.
    kept: Vec<Symbol>,
    /// The observations doubted.
    doubted: Vec<Symbol>,
    /// Every positive `relation`/`in_hand` literal of the chosen diagnosis model.
    closure: BTreeSet<Symbol>,
    /// The statics perceived.
    statics: Vec<Symbol>,
}

/// True for the fluents of the observable vocabulary (docs/domain.md 5.1).
fn observable(f: &Symbol) -> bool {
    f.is("relation", 3) || f.is("in_hand", 2)
}

/// True for the fluents a discrepancy is triggered by: `relation(on, X, Y)` and `in_hand`.
fn compared(f: &Symbol) -> bool {
    f.is("in_hand", 2) || (f.is("relation", 3) && f.args()[0].name() == Some("on"))
}

/// `f` without classical negation, and whether it had one.
fn positive(f: &Symbol) -> (Symbol, bool) {
    match f {
        Symbol::Function {
            name,
            args,
            negative,
        } => (Symbol::function(name.clone(), args.clone()), !negative),
        other => (other.clone(), true),
    }
}

/// A goal literal in the domain's vocabulary: `on(a,b)` (any spatial relation name of arity 2)
/// becomes `relation(on,a,b)`; other literals are kept.
pub fn goal_literal(text: &str) -> Result<Symbol, String> {
    let s = Symbol::parse(text.trim()).map_err(|e| format!("goal `{text}`: {e}"))?;
    let (p, sign) = positive(&s);
    let lifted = match p.name() {
        Some(n) if p.args().len() == 2 && super::scene::RELATIONS.contains(&n) => Symbol::function(
            "relation",
            vec![
                Symbol::constant(n),
                p.args()[0].clone(),
                p.args()[1].clone(),
            ],
        ),
        _ => p,
    };
    if !(lifted.is("relation", 3) || lifted.is("in_hand", 2)) {
        return Err(format!(
            "goal `{text}`: expected on(X,Y), relation(S,X,Y) or in_hand(R,X)"
        ));
    }
    Ok(if sign {
        lifted
    } else {
        match lifted {
            Symbol::Function { name, args, .. } => Symbol::Function {
                name,
                args,
                negative: true,
            },
            other => other,
        }
    })
}

/// The rules of the diagnosis solve besides the `seen(f)` facts: each perceived relation holds
/// at step 0 unless doubted (a doubt costs one CR rule), and what a camera can misread but a
/// tabletop cannot be is excluded: the table rests on nothing, an object rests on one thing at
/// most, two objects do not rest on each other, and an object supports one object at most.
const DIAGNOSIS: &str = "\
known0(F) :- seen(F).
holds(F,0) :- seen(F), not -holds(F,0).
doubt(F) : -holds(F,0) :+ seen(F).
:- holds(relation(on,table,X),0).
:- holds(relation(above,table,X),0).
:- holds(relation(on,X,Y),0), holds(relation(on,X,Z),0), Y != Z.
:- holds(relation(on,X,Y),0), holds(relation(on,Y,X),0).
:- holds(relation(on,X,Y),0), holds(relation(on,Z,Y),0), X != Z, Y != table.
";

/// Fuses several looks at one step: a reading is kept when more than half of the looks saw it,
/// with its mean confidence; exact readings are kept from the first look.
pub fn fuse(looks: &[Percept]) -> Percept {
    let Some(first) = looks.first() else {
        return Percept::default();
    };
    let mut counts: Vec<(Seen, usize)> = Vec::new();
    for p in looks {
        for s in &p.fluents {
            match counts
                .iter_mut()
                .find(|(c, _)| c.fluent == s.fluent && c.value == s.value)
            {
                Some((c, n)) => {
                    c.confidence += s.confidence;
                    *n += 1;
                }
                None => counts.push((s.clone(), 1)),
            }
        }
    }
    let fluents = counts
        .into_iter()
        .filter(|(s, n)| s.exact || 2 * n > looks.len())
        .map(|(mut s, n)| {
            s.confidence /= n as f64;
            s
        })
        .collect();
    Percept {
        statics: first.statics.clone(),
        fluents,
    }
}

/// The runner: the domain, the objects, the goal and the configuration of one run.
struct Runner<'a> {
    domain: &'a Domain,
    objects: Vec<String>,
    goal: Vec<Symbol>,
    config: &'a RunConfig,
}

impl Runner<'_> {
    /// The problem of the domain with the objects, `statics`, the step-0 literals `initially`,
    /// the runner's goal when `with_goal`, and `happened` at step 0.
    fn problem(
        &self,
        statics: &[Symbol],
        initially: &[Symbol],
        with_goal: bool,
        happened: Option<&Symbol>,
    ) -> Problem {
        Problem {
            objects: Some(self.objects.clone()),
            statics: statics.to_vec(),
            initially: initially.to_vec(),
            goal: if with_goal {
                self.goal.clone()
            } else {
                Vec::new()
            },
            happened: happened.map(|a| (a.clone(), 0)).into_iter().collect(),
            ..Problem::new(self.domain.description.clone(), self.domain.sources.clone())
        }
    }

    /// Translates and grounds `problem` at `horizon` without the planning module (with
    /// `diagnosis`, the diagnosis rules and a `seen(f)` fact per doubtable reading), and returns
    /// its answer sets.
    fn solve(
        &self,
        problem: &Problem,
        horizon: usize,
        diagnosis: Option<&[Symbol]>,
    ) -> Result<Vec<crate::control::OwnedModel>, Ending> {
        let options = Options {
            profile: self.config.plan.profile.clone(),
            overrides: self.config.plan.overrides.clone(),
            ..Options::default()
        };
        let t = problem
            .translate(&options, Switches::history(horizon))
            .map_err(Ending::Input)?;
        let mut config = ControlConfig::default();
        // Enough answer sets to choose the doubts among (ties of conflicting readings).
        config.solve.models = 64;
        let mut ctl = Control::with_sources(config, problem.sources.clone());
        let input = |e: crate::control::Error| Ending::Input(e.message);
        ctl.add_program(t.program).map_err(input)?;
        if let Some(seen) = diagnosis {
            let facts: Vec<Symbol> = seen
                .iter()
                .map(|f| Symbol::function("seen", vec![f.clone()]))
                .collect();
            ctl.add_facts(&facts).map_err(input)?;
            // Each perceived relation holds at step 0 unless doubted; a doubt costs one CR rule.
            ctl.add_source("<doubts>", DIAGNOSIS).map_err(input)?;
        }
        ctl.ground(&[Part::base()]).map_err(input)?;
        Ok(ctl.solve_all(&Default::default()).models)
    }

    /// Makes a percept consistent: the diagnosis solve with doubtable observations.
    fn believe(&self, percept: &Percept) -> Result<Belief, Ending> {
        let mut hard = Vec::new();
        let mut soft: Vec<&Seen> = Vec::new();
        for s in percept.fluents.iter().filter(|s| s.value) {
            if s.exact {
                hard.push(s.fluent.clone());
            } else if !soft.iter().any(|o| o.fluent == s.fluent) {
                soft.push(s);
            }
        }
        let problem = self.problem(&percept.statics, &hard, false, None);
        let seen: Vec<Symbol> = soft.iter().map(|s| s.fluent.clone()).collect();
        let models = self.solve(&problem, 0, Some(&seen))?;
        let confidence = |f: &Symbol| {
            soft.iter()
                .find(|s| &s.fluent == f)
                .map_or(1.0, |s| s.confidence)
        };
        // Per model: the positive observable literals at step 0, and the readings it drops
        // (doubted by the CR rule, or overridden by another default or a strict rule).
        let best = models
            .iter()
            .map(|m| {
                let closure: BTreeSet<Symbol> = m
                    .atoms
                    .iter()
                    .filter(|a| {
                        a.is("holds", 2) && !a.is_negative() && a.args()[1].as_number() == Some(0)
                    })
                    .map(|a| a.args()[0].clone())
                    .filter(observable)
                    .collect();
                let doubted: Vec<Symbol> = soft
                    .iter()
                    .map(|s| s.fluent.clone())
                    .filter(|f| !closure.contains(f))
                    .collect();
                let cost: f64 = doubted.iter().map(confidence).sum();
                (m.cr_applied.len(), cost, doubted, closure)
            })
            .min_by(|a, b| {
                a.0.cmp(&b.0)
                    .then(a.1.total_cmp(&b.1))
                    .then_with(|| a.2.cmp(&b.2))
            });
        let Some((_, _, mut doubted, closure)) = best else {
            return Err(Ending::Inconsistent);
        };
        doubted.sort();
        let mut kept = hard;
        kept.extend(
            soft.iter()
                .map(|s| s.fluent.clone())
                .filter(|f| closure.contains(f)),
        );
        kept.sort();
        Ok(Belief {
            kept,
            doubted,
            closure,
            statics: percept.statics.clone(),
        })
    }

    /// The positive observable literals at step 1 after `action` from `belief`, common to all
    /// answer sets; `None` when the domain says the action is not executable there.
    fn predict(
        &self,
        belief: &Belief,
        action: &Symbol,
    ) -> Result<Option<BTreeSet<Symbol>>, Ending> {
        let problem = self.problem(&belief.statics, &belief.kept, false, Some(action));
        let models = self.solve(&problem, 1, None)?;
        let mut common: Option<BTreeSet<Symbol>> = None;
        for m in &models {
            let here: BTreeSet<Symbol> = m
                .atoms
                .iter()
                .filter(|a| {
                    a.is("holds", 2) && !a.is_negative() && a.args()[1].as_number() == Some(1)
                })
                .map(|a| a.args()[0].clone())
                .filter(observable)
                .collect();
            common = Some(match common {
                None => here,
                Some(c) => c.intersection(&here).cloned().collect(),
            });
        }
        Ok(common)
    }

    /// True when every goal literal holds in the belief.
    fn goal_believed(&self, belief: &Belief) -> bool {
        self.goal.iter().all(|g| {
            let (p, sign) = positive(g);
            belief.closure.contains(&p) == sign
        })
    }
}

/// Perceives step `step` with look `look`, records it and returns the belief and the looks it
/// was fused from.
fn observe(
    runner: &Runner,
    world: &mut dyn World,
    history: &mut History,
    step: u32,
    look: u32,
    progress: &mut dyn FnMut(Event),
) -> Result<(Belief, Vec<Percept>), Ending> {
    let n = runner.config.looks.max(1);
    let all: Vec<Percept> = (look..look + n).map(|l| world.perceive(l)).collect();
    let belief = record_belief(runner, history, step, look + n, &all, progress)?;
    Ok((belief, all))
}

/// Looks `config.confirm_looks` more times at step `step` and returns the belief fused from
/// those looks and `earlier` (the looks of the belief being confirmed), with all the looks.
fn confirm(
    runner: &Runner,
    world: &mut dyn World,
    history: &mut History,
    step: u32,
    earlier: &[Percept],
    progress: &mut dyn FnMut(Event),
) -> Result<(Belief, Vec<Percept>), Ending> {
    let look = history.steps[step as usize].looks;
    let mut all = earlier.to_vec();
    let fresh = runner.config.confirm_looks;
    all.extend((look..look + fresh).map(|l| world.perceive(l)));
    let belief = record_belief(runner, history, step, look + fresh, &all, progress)?;
    Ok((belief, all))
}

/// Fuses `all` (looks at step `step`; `looks` were taken at that step in all), believes the
/// result and records it in the history's step.
fn record_belief(
    runner: &Runner,
    history: &mut History,
    step: u32,
    looks: u32,
    all: &[Percept],
    progress: &mut dyn FnMut(Event),
) -> Result<Belief, Ending> {
    let percept = fuse(all);
    let belief = runner.believe(&percept)?;
    if history.steps.len() <= step as usize {
        history.steps.push(StepRecord {
            step,
            ..StepRecord::default()
        });
    }
    let record = &mut history.steps[step as usize];
    record.looks = looks;
    record
        .observed
        .extend(percept.fluents.iter().map(|s| Observed {
            fluent: s.fluent.to_string(),
            value: s.value,
            confidence: s.confidence,
        }));
    record.doubted = belief.doubted.iter().map(Symbol::to_string).collect();
    record.belief = belief.closure.iter().map(Symbol::to_string).collect();
    if history.statics.is_empty() {
        history.statics = belief.statics.iter().map(Symbol::to_string).collect();
    }
    progress(Event::Perceived {
        step,
        look: looks - all.len().min(looks as usize) as u32,
        doubted: belief.doubted.len(),
    });
    Ok(belief)
}

fn texts<'a>(set: impl IntoIterator<Item = &'a Symbol>) -> Vec<String> {
    set.into_iter().map(Symbol::to_string).collect()
}

/// Runs the loop in `world` towards `goal` (literals in the domain's vocabulary, see
/// [`goal_literal`]), reporting progress to `progress`. The history is complete whatever the
/// ending; `scene` names the scene in it.
pub fn run(
    domain: &Domain,
    world: &mut dyn World,
    goal: &[Symbol],
    scene: &str,
    config: &RunConfig,
    progress: &mut dyn FnMut(Event),
) -> History {
    let runner = Runner {
        domain,
        objects: world.objects(),
        goal: goal.to_vec(),
        config,
    };
    let mut history = History::new(
        scene.to_string(),
        runner.objects.clone(),
        Vec::new(),
        texts(goal),
    );
    let ending = run_steps(&runner, world, &mut history, progress);
    history.ending = Some(ending);
    let mut truth = Some(true);
    for g in goal {
        let (p, sign) = positive(g);
        match world.holds_in_truth(&p) {
            Some(v) if v != sign => truth = Some(false),
            None if truth == Some(true) => truth = None,
            _ => {}
        }
    }
    history.goal_in_truth = truth;
    history
}

/// The compared literals (`compared`) believed but not predicted, and predicted but not
/// believed; with no prediction (the action was not executable in the belief) every compared
/// literal believed is unexpected.
fn surprises(belief: &Belief, predicted: Option<&BTreeSet<Symbol>>) -> (Vec<Symbol>, Vec<Symbol>) {
    let unexpected = belief
        .closure
        .iter()
        .filter(|f| compared(f))
        .filter(|f| predicted.is_none_or(|p| !p.contains(*f)))
        .cloned()
        .collect();
    let extra = predicted
        .into_iter()
        .flatten()
        .filter(|f| compared(f) && !belief.closure.contains(*f))
        .cloned()
        .collect();
    (unexpected, extra)
}

fn run_steps(
    runner: &Runner,
    world: &mut dyn World,
    history: &mut History,
    progress: &mut dyn FnMut(Event),
) -> Ending {
    let config = runner.config;
    let mut step: u32 = 0;
    let (mut belief, mut seen) = match observe(runner, world, history, step, 0, progress) {
        Ok(b) => b,
        Err(e) => return e,
    };
    // The step whose belief was confirmed by more looks (`RunConfig::confirm_looks`).
    let mut confirmed: Option<u32> = None;
    // Putdowns after which the next action of the plan was not executable in the (confirmed)
    // belief: a minimal plan without them is preferred, so the robot does not put an object
    // where it just hid another again (the domain cannot predict occlusion).
    let mut tabu: Vec<Symbol> = Vec::new();
    // The action executed last, with its step.
    let mut last_action: Option<(u32, Symbol)> = None;
    let mut pending: VecDeque<Symbol> = VecDeque::new();
    let mut reason = Some("initial".to_string());
    // Looks taken since the last plan because the planner found none.
    let mut relooks = 0;
    loop {
        if runner.goal_believed(&belief) {
            if !config.confirm_goal {
                return Ending::GoalObserved;
            }
            let look = history.steps[step as usize].looks;
            match observe(runner, world, history, step, look, progress) {
                Ok((again, _)) if runner.goal_believed(&again) => return Ending::GoalObserved,
                Ok((again, looks)) => {
                    (belief, seen) = (again, looks);
                    reason = Some(format!("goal not confirmed at step {step}"));
                }
                Err(e) => return e,
            }
        }
        if reason.is_some() || pending.is_empty() {
            if history.plans.len() >= config.max_plans {
                return Ending::ReplanBudget;
            }
            let problem = runner.problem(&belief.statics, &belief.kept, true, None);
            let found = match plan(&problem.description(), &problem.sources, &config.plan) {
                Ok(found) => found,
                Err(
                    e @ (PlanError::NoPlanWithin(_)
                    | PlanError::Inconsistent
                    | PlanError::InitiallyUnstable(_)),
                ) if relooks < config.relooks => {
                    // A noisy reading may be what blocks every plan: look again (fresh noise)
                    // and plan from the new belief before giving up.
                    relooks += 1;
                    let look = history.steps[step as usize].looks;
                    (belief, seen) = match observe(runner, world, history, step, look, progress) {
                        Ok(b) => b,
                        Err(e) => return e,
                    };
                    let why = match e {
                        PlanError::NoPlanWithin(h) => format!("no plan of at most {h} steps"),
                        _ => "no consistent stable state".to_string(),
                    };
                    reason = Some(format!("{why} at step {step}, looked again"));
                    continue;
                }
                Err(PlanError::NoPlanWithin(h)) => return Ending::NoPlan { horizon: h },
                Err(PlanError::Inconsistent | PlanError::InitiallyUnstable(_)) => {
                    return Ending::Inconsistent
                }
                Err(PlanError::Input(m)) => return Ending::Input(m),
            };
            relooks = 0;
            let first = found
                .plans
                .iter()
                .find(|p| !p.actions.iter().any(|a| tabu.contains(a)))
                .unwrap_or(&found.plans[0]);
            let record = PlanRecord {
                step,
                actions: texts(&first.actions),
                cr_applied: texts(&first.cr_applied),
                reason: reason.take().unwrap_or_else(|| "plan used up".into()),
                alternatives: found.plans.len(),
            };
            history.plans.push(record);
            progress(Event::Planned(history.plans.last().expect("just pushed")));
            pending = first.actions.iter().cloned().collect();
            if pending.is_empty() {
                // The planner finds the goal true at step 0 of the belief.
                return Ending::GoalObserved;
            }
        }
        if history.actions().len() >= config.max_actions {
            return Ending::ActionBudget;
        }
        let action = pending.pop_front().expect("a plan with actions left");
        let predicted = match runner.predict(&belief, &action) {
            Ok(p) => p,
            Err(e) => return e,
        };
        let fresh = history
            .plans
            .last()
            .is_some_and(|p| p.step == step && p.actions.len() == pending.len() + 1);
        if predicted.is_none() && !fresh {
            if config.confirm_looks > 0 && confirmed != Some(step) {
                // Before giving up the plan for what one look showed, look again.
                (belief, seen) = match confirm(runner, world, history, step, &seen, progress) {
                    Ok(b) => b,
                    Err(e) => return e,
                };
                confirmed = Some(step);
                pending.push_front(action);
                continue;
            }
            // The rest of an older plan is not executable in what the robot now believes
            // (a reading seen since): replan from the belief instead of acting against it.
            // A fresh plan's first action is executed even so (the planner and the one-step
            // prediction share the domain, so this does not happen; the guard stops a loop).
            pending.clear();
            let last = last_action
                .as_ref()
                .filter(|(i, a)| step.checked_sub(1) == Some(*i) && a.is("putdown", 3))
                .map(|(_, a)| a.clone());
            if let Some(putdown) = last {
                if !tabu.contains(&putdown) {
                    tabu.push(putdown);
                }
            }
            reason = Some(format!(
                "{action} not executable in the belief at step {step}"
            ));
            continue;
        }
        let failure = match world.execute(&action) {
            Ok(f) => f,
            Err(e) => return Ending::WorldError(e),
        };
        let action_text = action.to_string();
        last_action = Some((step, action.clone()));
        {
            let record = &mut history.steps[step as usize];
            record.happened = Some(action_text.clone());
            record.failure = failure.clone();
        }
        progress(Event::Acted {
            step,
            action: &action_text,
            failure: failure.as_deref(),
        });
        let before = belief;
        step += 1;
        (belief, seen) = match observe(runner, world, history, step, 0, progress) {
            Ok(b) => b,
            Err(e) => return e,
        };
        let (mut unexpected, mut extra) = surprises(&belief, predicted.as_ref());
        if config.confirm_looks > 0 && (!unexpected.is_empty() || !extra.is_empty()) {
            // What was seen is not what was expected: look again before believing it.
            (belief, seen) = match confirm(runner, world, history, step, &seen, progress) {
                Ok(b) => b,
                Err(e) => return e,
            };
            confirmed = Some(step);
            (unexpected, extra) = surprises(&belief, predicted.as_ref());
        }
        if failure.is_some() || predicted.is_none() || !unexpected.is_empty() || !extra.is_empty() {
            let d = Discrepancy {
                step: step - 1,
                action: action_text,
                before: texts(&before.closure),
                predicted: predicted.as_ref().map(texts),
                observed: texts(&belief.closure),
                unexpected: texts(&unexpected),
                extra: texts(&extra),
                failure,
            };
            history.discrepancies.push(d);
            progress(Event::Discrepancy(
                history.discrepancies.last().expect("just pushed"),
            ));
            reason = Some(format!("discrepancy at step {}", step - 1));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn goal_literals_are_lifted_to_the_domain_vocabulary() {
        assert_eq!(
            goal_literal("on(a, b)").unwrap().to_string(),
            "relation(on,a,b)"
        );
        assert_eq!(
            goal_literal("-in_hand(rob1,a)").unwrap().to_string(),
            "-in_hand(rob1,a)"
        );
        assert_eq!(
            goal_literal("relation(left,a,b)").unwrap().to_string(),
            "relation(left,a,b)"
        );
        assert!(goal_literal("stable(a)").is_err());
        assert!(goal_literal("on(a,").is_err());
    }
}
