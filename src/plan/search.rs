//! The planner's search (docs/domain.md 4.1-4.2) over one multi-shot [`Control`].
//!
//! - [`Search::Incremental`] (default): the description is translated once with
//!   `horizon_mode = incremental` ([`crate::action::parts`]); `base` and `check(0)` are
//!   grounded, then for k = 1, 2, ... one `step(k)` and `check(k)` part each, with only the
//!   external `query(k)` true, so each horizon adds one step to the same solver.
//! - [`Search::Retranslate`]: the description is translated, grounded and solved afresh with
//!   `horizon = k`, `horizon_mode = iterative` for each k (the reference the incremental search
//!   is tested against).
//! - [`Search::Fixed`]: the authors' behaviour (docs/domain.md 4.1, 7.4): one program at horizon n
//!   with `success` and `:- not success`; every trajectory reaching the goal by step n is an
//!   answer set, lengths are not minimized, only CR applications are.
//!
//! Invariants: the first satisfiable horizon is the minimal length, and the solver's
//! cardinality-minimal CR semantics makes its answer sets CR-minimal at that length; plans are
//! action sequences, each once, sorted by length, then CR applications, then text. Before any
//! horizon the initial state is solved alone: no answer set is [`PlanError::InitiallyUnstable`]
//! when dropping the stability constraint restores one (the objects named), else
//! [`PlanError::Inconsistent`].
//!
//! [`Search::Incremental`]: super::Search::Incremental
//! [`Search::Retranslate`]: super::Search::Retranslate
//! [`Search::Fixed`]: super::Search::Fixed

use super::{Plan, PlanConfig, PlanError, Plans};
use crate::action::{self, ast::Description, HorizonMode, Options, Switches};
use crate::base::{Diagnostics, SourceMap};
use crate::control::{
    AtomId, Control, ControlConfig, Model, Part, SolveOptions, Symbol, TruthValue,
};

/// Translates `desc` with the config's switches and `switches`; bad input is
/// `PlanError::Input`.
pub(crate) fn translate(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
    switches: Switches,
) -> Result<action::Translation, PlanError> {
    let options = Options {
        profile: config.profile.clone(),
        overrides: config.overrides.clone(),
        switches,
    };
    let t = action::translate(desc, &options);
    if t.has_errors() {
        let mut d = Diagnostics::default();
        d.extend(t.diagnostics);
        return Err(PlanError::Input(d.render(sources)));
    }
    Ok(t)
}

/// A Control holding `program`, with `models` models per call (0: all).
pub(crate) fn control(
    sources: &SourceMap,
    program: crate::syntax::ast::Program,
    models: usize,
) -> Result<Control, PlanError> {
    let mut cc = ControlConfig::default();
    cc.solve.models = models;
    let mut ctl = Control::with_sources(cc, sources.clone());
    ctl.add_program(program)
        .map_err(|e| PlanError::Input(e.message))?;
    Ok(ctl)
}

/// The `occurs(a, i)` atoms of a Control, looked up by symbol (never by scanning the answer
/// set): a model's plan is read from them alone, which keeps reading a model independent of
/// its size (converting a whole answer set to symbols took as long as solving).
#[derive(Default)]
pub(crate) struct Occurs {
    /// The action terms (the arguments of the `action/1` atoms).
    actions: Vec<Symbol>,
    /// Per step, the atoms `occurs(a, i)` that grounding produced, with the action's index.
    steps: Vec<Vec<(AtomId, usize)>>,
}

impl Occurs {
    /// The actions of `ctl` (read once, after the part that defines `action/1` is grounded).
    pub(crate) fn new(ctl: &Control) -> Occurs {
        let mut actions: Vec<Symbol> = ctl
            .symbolic_atoms()
            .filter(|a| a.symbol.is("action", 1) && !a.symbol.is_negative())
            .map(|a| a.symbol.args()[0].clone())
            .collect();
        actions.sort();
        actions.dedup();
        Occurs {
            actions,
            steps: Vec::new(),
        }
    }

    /// Looks up the atoms `occurs(a, i)` of the steps not yet known, up to step `upto - 1`.
    pub(crate) fn extend(&mut self, ctl: &Control, upto: usize) {
        while self.steps.len() < upto {
            let i = Symbol::number(self.steps.len() as i32);
            let atoms = self
                .actions
                .iter()
                .enumerate()
                .filter_map(|(k, a)| {
                    let s = Symbol::function("occurs", vec![a.clone(), i.clone()]);
                    ctl.lookup(&s).map(|atom| (atom, k))
                })
                .collect();
            self.steps.push(atoms);
        }
    }

    /// The plan of one answer set: the action occurring at each step, in step order (a step
    /// without an action ends the plan), and the applied CR rules.
    pub(crate) fn plan_of(&self, model: &Model<'_>) -> Plan {
        let mut actions = Vec::new();
        for step in &self.steps {
            match step.iter().find(|&&(atom, _)| model.holds(atom)) {
                Some(&(_, k)) => actions.push(self.actions[k].clone()),
                None => break,
            }
        }
        let mut cr_applied = model.cr_applied();
        cr_applied.sort();
        Plan {
            actions,
            cr_applied,
        }
    }
}

/// Orders plans by length, CR applications and text; keeps each action sequence once (with
/// its fewest CR applications).
pub(crate) fn order(mut plans: Vec<Plan>) -> Vec<Plan> {
    plans.sort_by_cached_key(|p| (p.actions.len(), p.cr_applied.len(), p.to_text()));
    // Each action sequence once, at its best (first) position: equal sequences need not be
    // adjacent after the sort (a sequence with more CR applications sorts after other plans).
    let mut seen = std::collections::HashSet::new();
    plans.retain(|p| seen.insert(p.to_text()));
    plans
}

fn query(k: usize) -> Symbol {
    Symbol::function("query", vec![Symbol::number(k as i32)])
}

/// Why the initial state has no answer set: the objects unstable at step 0 when the stability
/// constraint is dropped, or plain inconsistency.
fn diagnose(desc: &Description, sources: &SourceMap, config: &PlanConfig) -> PlanError {
    let Ok(t) = translate(
        desc,
        sources,
        config,
        Switches {
            stability_constraint: Some(false),
            ..Switches::history(0)
        },
    ) else {
        return PlanError::Inconsistent;
    };
    let Ok(mut ctl) = control(sources, t.program, 1) else {
        return PlanError::Inconsistent;
    };
    if ctl.ground(&[Part::base()]).is_err() {
        return PlanError::Inconsistent;
    }
    let solved = ctl.solve_all(&SolveOptions::default());
    let Some(m) = solved.models.first() else {
        return PlanError::Inconsistent;
    };
    // -holds(stable(A), 0)
    let mut unstable: Vec<String> = m
        .atoms
        .iter()
        .filter(|s| s.is_negative() && s.is("holds", 2))
        .filter(|s| s.args()[1].as_number() == Some(0) && s.args()[0].is("stable", 1))
        .map(|s| s.args()[0].args()[0].to_string())
        .collect();
    unstable.sort();
    unstable.dedup();
    if unstable.is_empty() {
        PlanError::Inconsistent
    } else {
        PlanError::InitiallyUnstable(unstable)
    }
}

/// The plans of one solve call over `ctl` (all models, or the first): the one place where
/// models become plans, for every search.
fn collect(ctl: &mut Control, occurs: &Occurs, all: bool) -> Vec<Plan> {
    let mut plans = Vec::new();
    ctl.solve(&SolveOptions::default(), |m| {
        plans.push(occurs.plan_of(m));
        all
    });
    plans
}

/// The initial state alone, translated afresh (horizon 0, no planning module): `Ok` when it
/// has an answer set, else why not (see [`diagnose`]).
fn check_initial(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
) -> Result<(), PlanError> {
    let initial = solve_fresh(desc, sources, config, Switches::history(0), 0, false)?;
    if initial.is_empty() {
        return Err(diagnose(desc, sources, config));
    }
    Ok(())
}

/// The minimal plans found at horizon `length`.
fn found(plans: Vec<Plan>, length: usize, horizons_tried: usize) -> Plans {
    let answer_sets = plans.len();
    let plans = order(plans);
    let least = plans.iter().map(|p| p.cr_applied.len()).min().unwrap_or(0);
    let plans: Vec<Plan> = plans
        .into_iter()
        .filter(|p| p.cr_applied.len() == least)
        .collect();
    Plans {
        plans,
        length,
        cr_applied: least,
        horizons_tried,
        answer_sets,
    }
}

/// The incremental search: one Control, one new step part per horizon.
pub(crate) fn incremental(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
    max_horizon: usize,
) -> Result<Plans, PlanError> {
    let t = translate(
        desc,
        sources,
        config,
        Switches {
            planning: Some(true),
            horizon_mode: Some(HorizonMode::Incremental),
            ..Switches::default()
        },
    )?;
    let mut ctl = control(sources, t.program, if config.all { 0 } else { 1 })?;
    let ground = |ctl: &mut Control, parts: &[Part]| {
        ctl.ground(parts).map_err(|e| PlanError::Input(e.message))
    };
    ground(
        &mut ctl,
        &[
            Part::base(),
            Part::new("check", vec![query(0).args()[0].clone()]),
        ],
    )?;
    let mut occurs = Occurs::new(&ctl);
    // The initial state alone (query(0) false: no goal required).
    if !ctl
        .solve(&SolveOptions::default(), |_| false)
        .is_satisfiable()
    {
        return Err(diagnose(desc, sources, config));
    }
    for k in 0..=max_horizon {
        if k > 0 {
            ctl.release_external(&query(k - 1));
            let t = Symbol::number(k as i32);
            ground(
                &mut ctl,
                &[
                    Part::new("step", vec![t.clone()]),
                    Part::new("check", vec![t]),
                ],
            )?;
            occurs.extend(&ctl, k);
        }
        ctl.assign_external(&query(k), TruthValue::True);
        let plans = collect(&mut ctl, &occurs, config.all);
        if !plans.is_empty() {
            return Ok(found(plans, k, k + 1));
        }
    }
    Err(PlanError::NoPlanWithin(max_horizon))
}

/// Every plan (or the first, without `config.all`) that reaches the goal at horizon `k` in
/// `mode`, each from a fresh grounding.
fn plans_at(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
    k: usize,
    mode: HorizonMode,
) -> Result<Vec<Plan>, PlanError> {
    solve_fresh(
        desc,
        sources,
        config,
        Switches::planning(k, mode),
        k,
        config.all,
    )
}

/// The plans of `desc` translated with `extra` (horizon `horizon`), grounded and solved afresh
/// (all answer sets' plans, or the first one's).
fn solve_fresh(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
    switches: Switches,
    horizon: usize,
    all: bool,
) -> Result<Vec<Plan>, PlanError> {
    let t = translate(desc, sources, config, switches)?;
    let mut ctl = control(sources, t.program, if all { 0 } else { 1 })?;
    ctl.ground(&[Part::base()])
        .map_err(|e| PlanError::Input(e.message))?;
    let mut occurs = Occurs::new(&ctl);
    occurs.extend(&ctl, horizon);
    Ok(collect(&mut ctl, &occurs, all))
}

/// The reference search: every horizon translated and grounded afresh.
pub(crate) fn retranslate(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
    max_horizon: usize,
) -> Result<Plans, PlanError> {
    check_initial(desc, sources, config)?;
    for k in 0..=max_horizon {
        let plans = plans_at(desc, sources, config, k, HorizonMode::Iterative)?;
        if !plans.is_empty() {
            return Ok(found(plans, k, k + 1));
        }
    }
    Err(PlanError::NoPlanWithin(max_horizon))
}

/// The authors' fixed horizon: every plan reaching the goal by step `n` (CR-minimal).
pub(crate) fn fixed(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
    n: usize,
) -> Result<Plans, PlanError> {
    check_initial(desc, sources, config)?;
    let plans = plans_at(desc, sources, config, n, HorizonMode::Fixed)?;
    if plans.is_empty() {
        return Err(PlanError::NoPlanWithin(n));
    }
    let answer_sets = plans.len();
    let plans = order(plans);
    Ok(Plans {
        length: plans[0].actions.len(),
        cr_applied: plans[0].cr_applied.len(),
        horizons_tried: 1,
        answer_sets,
        plans,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::Symbol;

    fn plan(actions: &[&str], cr: usize) -> Plan {
        Plan {
            actions: actions.iter().map(|a| Symbol::parse(a).unwrap()).collect(),
            cr_applied: (0..cr)
                .map(|i| Symbol::parse(&format!("d1x(a,{i})")).unwrap())
                .collect(),
        }
    }

    #[test]
    fn plans_are_ordered_by_length_then_cr_then_text_each_once() {
        let ordered = order(vec![
            plan(&["b", "c"], 0),
            plan(&["a"], 1),
            plan(&["b"], 0),
            plan(&["a"], 0),
            plan(&["b", "c"], 1),
        ]);
        let texts: Vec<(String, usize)> = ordered
            .iter()
            .map(|p| (p.to_text(), p.cr_applied.len()))
            .collect();
        assert_eq!(
            texts,
            vec![
                ("a@0".to_string(), 0),
                ("b@0".to_string(), 0),
                ("b@0; c@1".to_string(), 0)
            ]
        );
    }
}
