//! The H1 experiment (docs/domain.md 7.3): independent learning runs from a fresh `learner`
//! knowledge base against the KB_full oracle, scored strictly and relaxed against the five
//! targets (5.10).
//!
//! Runs share two answer caches ([`Caches`]): the oracle is one program, and the learner's
//! knowledge bases repeat across runs (every run starts from the same one).
//!
//! Invariants: run `i` uses the seed `SplitMix64::new(seed).fork(i)`, so a run's result does
//! not depend on how many runs there are or on the thread count; runs go in parallel with rayon
//! and their results are reported in run order.

use std::sync::Arc;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::action::ast::Value;
use crate::action::{Options, Switches};

use super::episode::{run, LearnConfig, RunReport, World};
use super::kb::{Cache, KbError, KbSpec, KbWorld};
use super::score::{relaxed, strict, Counts};
use super::term::{in_hand, o, r, rel, Axiom, AxiomKind, Literal};
use crate::base::rng::SplitMix64;

/// The five H1 targets in lifted form (docs/domain.md 2.2-2.3, ★T1-★T5: E7, E5, E2, C3, C2).
pub fn targets() -> Vec<Axiom> {
    let pickup = Literal::new("pickup", vec![r(1), o(1)]);
    let putdown = Literal::new("putdown", vec![r(1), o(1), o(2)]);
    vec![
        Axiom::new(
            AxiomKind::Executability,
            pickup.clone(),
            vec![rel("below", o(1), o(2))],
        ),
        Axiom::new(
            AxiomKind::Executability,
            pickup.clone(),
            vec![in_hand(true, r(1), o(2))],
        ),
        Axiom::new(
            AxiomKind::Executability,
            putdown.clone(),
            vec![in_hand(false, r(1), o(1))],
        ),
        Axiom::new(
            AxiomKind::Causal {
                head: in_hand(true, r(1), o(1)),
            },
            pickup,
            vec![],
        ),
        Axiom::new(
            AxiomKind::Causal {
                head: in_hand(false, r(1), o(1)),
            },
            putdown,
            vec![],
        ),
    ]
}

/// The learner's options: the `learner` profile.
pub fn learner_options() -> Options {
    Options::profile(Some("learner"))
}

/// The oracle's options: KB_full with the learner's switches (the code's sorts and sticky
/// support fluents, horizon 1, no planning module) and no axiom dropped.
pub fn oracle_options() -> Options {
    Options {
        profile: None,
        overrides: vec![
            ("table_is_object".into(), Value::Bool(true)),
            ("sticky_support_fluents".into(), Value::Bool(true)),
        ],
        switches: Switches::history(1),
    }
}

/// One run's scores and findings.
#[derive(Clone, Debug, Serialize)]
pub struct RunResult {
    /// Run index.
    pub run: usize,
    /// The learned axioms at the end of the run (short form).
    pub found: Vec<String>,
    /// Strict counts.
    pub strict: Counts,
    /// Relaxed counts.
    pub relaxed: Counts,
    /// Trials run.
    pub trials: usize,
    /// Episodes run.
    pub episodes: usize,
    /// Solver calls of the oracle and the learner (answers found in the caches need none).
    pub solves: usize,
}

/// Precision and recall in percent.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct PrecisionRecall {
    /// Precision, %.
    pub precision: f64,
    /// Recall, %.
    pub recall: f64,
}

impl From<Counts> for PrecisionRecall {
    fn from(c: Counts) -> Self {
        PrecisionRecall {
            precision: c.precision(),
            recall: c.recall(),
        }
    }
}

/// The experiment's result.
#[derive(Clone, Debug, Serialize)]
pub struct H1Result {
    /// Strict precision and recall over all runs.
    pub strict: PrecisionRecall,
    /// Relaxed precision and recall over all runs.
    pub relaxed: PrecisionRecall,
    /// Summed strict counts.
    pub strict_counts: Counts,
    /// Summed relaxed counts.
    pub relaxed_counts: Counts,
    /// The paper's Table 1, for comparison.
    pub paper: PaperH1,
    /// Solver calls over all runs.
    pub solves: usize,
    /// Trials over all runs.
    pub trials: usize,
    /// World steps answered from the caches, and world steps in all.
    pub cache_hits: (usize, usize),
    /// Per run.
    pub runs: Vec<RunResult>,
}

/// The paper's H1 figures (Table 1).
#[derive(Clone, Copy, Debug, Serialize)]
pub struct PaperH1 {
    /// Strict P/R.
    pub strict: PrecisionRecall,
    /// Relaxed P/R.
    pub relaxed: PrecisionRecall,
}

/// Table 1 of the paper.
pub const PAPER: PaperH1 = PaperH1 {
    strict: PrecisionRecall {
        precision: 69.2,
        recall: 78.3,
    },
    relaxed: PrecisionRecall {
        precision: 96.0,
        recall: 95.1,
    },
};

/// The seed of run `i`.
pub fn run_seed(seed: u64, i: usize) -> u64 {
    SplitMix64::new(seed).fork(i as u64).next_u64()
}

/// The answer caches runs share: one for the oracle, one for the learner's knowledge bases.
#[derive(Clone, Debug, Default)]
pub struct Caches {
    /// The oracle's answers.
    pub oracle: Arc<Cache>,
    /// The learner's answers, per set of learned axioms.
    pub learner: Arc<Cache>,
}

/// What plays the world in a learning run (docs/domain.md 5.1: the oracle program or a physics
/// simulator).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Oracle {
    /// KB_full ([`oracle_options`]), the authors' oracle.
    #[default]
    KbFull,
    /// The rapier world (`learn::physics`, feature `sim`).
    Physics,
}

impl Oracle {
    /// `kb_full` or `physics`.
    pub fn name(self) -> &'static str {
        match self {
            Oracle::KbFull => "kb_full",
            Oracle::Physics => "physics",
        }
    }

    /// Parses [`Oracle::name`].
    pub fn parse(text: &str) -> Option<Oracle> {
        [Oracle::KbFull, Oracle::Physics]
            .into_iter()
            .find(|o| o.name() == text)
    }

    /// `Ok` when this build can run it, else the reason.
    pub fn availability(self) -> Result<(), String> {
        match self {
            Oracle::KbFull => Ok(()),
            Oracle::Physics if cfg!(feature = "sim") => Ok(()),
            Oracle::Physics => Err("the physics oracle needs the `sim` feature".into()),
        }
    }
}

/// One run against KB_full, with its report.
pub fn one_run(spec: &KbSpec, config: &LearnConfig, seed: u64) -> Result<RunReport, KbError> {
    one_run_cached(spec, config, seed, &Caches::default())
}

/// One run against `oracle`, with its report.
pub fn one_run_with(
    spec: &KbSpec,
    config: &LearnConfig,
    seed: u64,
    oracle: Oracle,
    caches: &Caches,
) -> Result<RunReport, KbError> {
    match oracle {
        Oracle::KbFull => one_run_cached(spec, config, seed, caches),
        #[cfg(feature = "sim")]
        Oracle::Physics => {
            let world = super::physics::PhysicsWorld::new(super::physics::Catalogue::h1());
            let mut oracle =
                super::kb::CachedWorld::new(world, caches.oracle.clone(), "physics h1");
            learn_against(spec, config, seed, caches, &mut oracle)
        }
        #[cfg(not(feature = "sim"))]
        Oracle::Physics => Err(KbError::Translate(
            Oracle::Physics.availability().unwrap_err(),
        )),
    }
}

/// One run against KB_full sharing answers through `caches`.
pub fn one_run_cached(
    spec: &KbSpec,
    config: &LearnConfig,
    seed: u64,
    caches: &Caches,
) -> Result<RunReport, KbError> {
    let mut oracle = KbWorld::new(
        KbSpec {
            options: oracle_options(),
            ..spec.clone()
        },
        &[],
    )?;
    oracle.need_before = false;
    oracle.read_before = false;
    oracle.use_cache(caches.oracle.clone());
    let mut report = learn_against(spec, config, seed, caches, &mut oracle)?;
    report.solves += oracle.solves;
    Ok(report)
}

/// One run of the learner (a fresh `learner` knowledge base) against `oracle`; the report's
/// `solves` counts the learner's.
fn learn_against(
    spec: &KbSpec,
    config: &LearnConfig,
    seed: u64,
    caches: &Caches,
    oracle: &mut dyn World,
) -> Result<RunReport, KbError> {
    let mut learner = KbWorld::new(
        KbSpec {
            options: learner_options(),
            ..spec.clone()
        },
        &[],
    )?;
    // Under `informative_only` no sample comes from a trial the learner forbids, so its step-0
    // state is never needed there.
    learner.need_before = !config.collect.informative_only;
    learner.use_cache(caches.learner.clone());
    let mut report = run(oracle, &mut learner, config, seed);
    report.solves = learner.solves;
    Ok(report)
}

/// Runs the experiment; `progress` is called after each finished run.
pub fn experiment(
    spec: &KbSpec,
    config: &LearnConfig,
    seed: u64,
    runs: usize,
    progress: &(dyn Fn() + Sync),
) -> Result<H1Result, KbError> {
    let targets = targets();
    let caches = Caches::default();
    let results: Vec<Result<RunResult, KbError>> = (0..runs)
        .into_par_iter()
        .map(|i| {
            let report = one_run_cached(spec, config, run_seed(seed, i), &caches)?;
            let found = report.store.current();
            let r = RunResult {
                run: i,
                found: found.iter().map(Axiom::short).collect(),
                strict: strict(&found, &targets),
                relaxed: relaxed(&found, &targets),
                trials: report.trials,
                episodes: report.episodes.len(),
                solves: report.solves,
            };
            progress();
            Ok(r)
        })
        .collect();
    let runs: Vec<RunResult> = results.into_iter().collect::<Result<_, _>>()?;
    let (mut s, mut x) = (Counts::default(), Counts::default());
    for r in &runs {
        s.add(r.strict);
        x.add(r.relaxed);
    }
    Ok(H1Result {
        strict: s.into(),
        relaxed: x.into(),
        strict_counts: s,
        relaxed_counts: x,
        paper: PAPER,
        solves: runs.iter().map(|r| r.solves).sum(),
        trials: runs.iter().map(|r| r.trials).sum(),
        cache_hits: {
            let (a, b) = (caches.oracle.hits(), caches.learner.hits());
            (a.0 + b.0, a.1 + b.1)
        },
        runs,
    })
}
