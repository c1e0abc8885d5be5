//! The H1-H4 experiment harness (docs/domain.md 7): trials from a recorded seed, one JSON result
//! per trial in a [`Store`], rayon over trials, and aggregation into the paper's tables
//! (`report`) with SVG plots (`svg`).
//!
//! Invariants:
//! - A trial is `(hypothesis, config, index)` with a stable id ([`Trial::id`]); its seed is a
//!   function of the setup's seed and the trial alone ([`Trial::seed`]), so its result does not
//!   depend on which other trials run, in which order, on how many threads or in which process.
//!   H1 run `i` keeps `learn::h1::run_seed(seed, i)`, the seed `lucent learn` and issue 15's
//!   `experiment h1` use.
//! - A stored result is reused only when its id and its whole [`Setup`] match; otherwise the
//!   trial is computed again and the store overwritten.
//! - Aggregation is a pure function of the results (sorted by id): the in-process run, a resumed
//!   run and `merge` over files written by GNU parallel give the same tables. Timings are the
//!   only values that differ between runs; they sit under keys named `time` or `seconds`, or
//!   ending in `_time`, and in the markdown only in H2's `| Planning time |` rows.
//! - A hypothesis whose pieces are missing is reported as the string `"not available: <reason>"`
//!   and has no trials; nothing here invents a number for it.
//! - Nothing here reads or writes files or prints: `cli` implements [`Store`] over a directory
//!   and draws the progress bar from [`run`]'s callback.

#[cfg(feature = "sim")]
pub(crate) mod classify;
pub(crate) mod h1;
pub mod h2;
pub(crate) mod h34;
pub(crate) mod interval;
pub(crate) mod report;
pub(crate) mod svg;

use std::collections::BTreeMap;
use std::sync::Mutex;
use std::time::Instant;

use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use crate::base::rng::SplitMix64;
use crate::learn::episode::LearnConfig;
use crate::learn::h1::{Caches, Oracle};
use crate::learn::kb::KbSpec;

/// The paper's four hypotheses (docs/domain.md 7.1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum Hypothesis {
    /// Learning accuracy (Table 1).
    H1,
    /// Plan quality with and without the learned axioms (Tables 2 and 3).
    H2,
    /// Proof-tree checks.
    H3,
    /// Explanation precision and recall (Tables 4 and 5).
    H4,
}

impl Hypothesis {
    /// All four, in order.
    pub const ALL: [Hypothesis; 4] = [
        Hypothesis::H1,
        Hypothesis::H2,
        Hypothesis::H3,
        Hypothesis::H4,
    ];

    /// `h1`..`h4`.
    pub fn name(self) -> &'static str {
        match self {
            Hypothesis::H1 => "h1",
            Hypothesis::H2 => "h2",
            Hypothesis::H3 => "h3",
            Hypothesis::H4 => "h4",
        }
    }

    /// Parses `h1`..`h4`.
    pub fn parse(text: &str) -> Option<Hypothesis> {
        Hypothesis::ALL.into_iter().find(|h| h.name() == text)
    }
}

/// Everything a trial's result depends on besides its id; recorded with every result.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Setup {
    /// The recorded seed.
    pub seed: u64,
    /// H1 learning runs (the paper: 20).
    pub runs: usize,
    /// Scene configurations per preset for H2-H4 (the paper: 20).
    pub configurations: usize,
    /// Goals per configuration (the paper: 5).
    pub goals: usize,
    /// Episodes per learning run (docs/domain.md 5.2: 10).
    pub episodes: usize,
    /// Store capped inconsistent trials with label 0, as the authors' code does.
    pub code_balance: bool,
    /// Take samples from every trial, as the authors' code does.
    pub code_samples: bool,
    /// End a learning run after 100 quiet trials of any kind, as docs/domain.md 5.2 is written
    /// (`LearnConfig::count_every_trial`); by default only trials the learner would act in
    /// count.
    #[serde(default)]
    pub count_every_trial: bool,
    /// H1's oracle (KB_full by default; results stored before the field existed are KB_full's).
    #[serde(default)]
    pub oracle: Oracle,
    /// The harness's trial design ([`DESIGN`]); results of another design are not reused (0 for
    /// results stored before the field existed).
    #[serde(default)]
    pub design: u32,
}

/// The current trial design: 1 when H3 and H4 took H2's (scene, goal) pairs (before, one scene
/// per trial was drawn from the trial's seed); 2 when a learning run's detection phase counted
/// only the trials the learner would act in (`LearnConfig::count_every_trial`); 3 when
/// collection waited for rare negatives (`learn::state::Collector::stall_window`).
pub const DESIGN: u32 = 3;

impl Setup {
    /// The paper's sizes with the given seed.
    pub fn paper(seed: u64) -> Setup {
        Setup {
            seed,
            runs: 20,
            configurations: 20,
            goals: 5,
            episodes: LearnConfig::default().episodes,
            code_balance: false,
            code_samples: false,
            count_every_trial: false,
            oracle: Oracle::KbFull,
            design: DESIGN,
        }
    }

    /// The learner's configuration.
    pub fn learn_config(&self) -> LearnConfig {
        let mut c = LearnConfig {
            episodes: self.episodes,
            ..Default::default()
        };
        c.collect.balance_fix = !self.code_balance;
        c.collect.informative_only = !self.code_samples;
        c.count_every_trial = self.count_every_trial;
        c
    }
}

/// The scene presets of H2-H4 (docs/domain.md 7.1), as trial configs.
pub const PRESETS: [&str; 2] = ["real", "simulated"];

/// The config of H1 trials against KB_full (the default oracle); against the physics world it
/// is `physics` ([`Oracle::name`]).
pub const H1_CONFIG: &str = "kb_full";

/// One trial.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Trial {
    /// Which hypothesis.
    pub hypothesis: Hypothesis,
    /// The configuration: the oracle (`kb_full`, `physics`) for H1, a preset of [`PRESETS`] for H2-H4.
    pub config: String,
    /// The run (H1) or `configuration * goals + goal` (H2-H4).
    pub index: usize,
}

impl Trial {
    /// The stable id, `h2-real-0017`; also the result's file name without `.json`.
    pub fn id(&self) -> String {
        format!(
            "{}-{}-{:04}",
            self.hypothesis.name(),
            self.config,
            self.index
        )
    }

    /// Parses an id made by [`Trial::id`].
    pub fn parse_id(id: &str) -> Option<Trial> {
        let (h, rest) = id.split_once('-')?;
        let (config, index) = rest.rsplit_once('-')?;
        let trial = Trial {
            hypothesis: Hypothesis::parse(h)?,
            config: config.to_string(),
            index: index.parse().ok()?,
        };
        let known = match trial.hypothesis {
            Hypothesis::H1 => Oracle::parse(&trial.config).is_some(),
            _ => PRESETS.contains(&trial.config.as_str()),
        };
        known.then_some(trial)
    }

    /// The trial's seed: H1 keeps `learn::h1::run_seed`; the others fork the setup's seed by a
    /// fixed hash (FNV-1a) of the id.
    pub fn seed(&self, setup: &Setup) -> u64 {
        match self.hypothesis {
            Hypothesis::H1 => crate::learn::h1::run_seed(setup.seed, self.index),
            _ => {
                let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
                for b in self.id().bytes() {
                    hash = (hash ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3);
                }
                SplitMix64::new(setup.seed).fork(hash).next_u64()
            }
        }
    }
}

/// Where a hypothesis stands in this build: `Ok` when its trials can run, else the reason.
pub fn availability(h: Hypothesis) -> Result<(), String> {
    match h {
        Hypothesis::H1 => Ok(()),
        Hypothesis::H2 => h2::availability(),
        Hypothesis::H3 | Hypothesis::H4 => h34::availability(h),
    }
}

/// The trials of the given hypotheses (the unavailable ones have none), in id order.
pub fn trials(setup: &Setup, hypotheses: &[Hypothesis]) -> Vec<Trial> {
    let mut out = Vec::new();
    for &h in hypotheses {
        if availability(h).is_err() {
            continue;
        }
        if h == Hypothesis::H1 {
            out.extend((0..setup.runs).map(|index| Trial {
                hypothesis: h,
                config: setup.oracle.name().into(),
                index,
            }));
        } else {
            for preset in PRESETS {
                out.extend((0..setup.configurations * setup.goals).map(|index| Trial {
                    hypothesis: h,
                    config: preset.into(),
                    index,
                }));
            }
        }
    }
    out.sort_by_key(Trial::id);
    out
}

/// A trial's stored result.
#[derive(Clone, Debug, Serialize, Deserialize)]
pub struct Record {
    /// The trial's id.
    pub id: String,
    /// The setup it was computed under.
    pub setup: Setup,
    /// The trial's seed.
    pub trial_seed: u64,
    /// Wall time of the computation, in seconds.
    pub seconds: f64,
    /// The hypothesis' result for this trial.
    pub result: serde_json::Value,
}

/// Where results are kept: `cli` puts them in files, [`MemoryStore`] in memory.
pub trait Store: Sync {
    /// The stored text for `id`, if any.
    fn load(&self, id: &str) -> Option<String>;
    /// Stores `text` for `id`; the store must never expose a half-written text.
    fn save(&self, id: &str, text: &str) -> Result<(), String>;
}

/// A store in memory (a run without `--out`).
#[derive(Debug, Default)]
pub struct MemoryStore {
    /// Texts by id.
    texts: Mutex<BTreeMap<String, String>>,
}

impl Store for MemoryStore {
    fn load(&self, id: &str) -> Option<String> {
        self.texts.lock().ok()?.get(id).cloned()
    }

    fn save(&self, id: &str, text: &str) -> Result<(), String> {
        self.texts
            .lock()
            .map_err(|_| "the result store is poisoned".to_string())?
            .insert(id.to_string(), text.to_string());
        Ok(())
    }
}

/// Why a trial failed.
#[derive(Clone, Debug, thiserror::Error)]
pub enum TrialError {
    /// The knowledge base or a scene could not be used (bad input).
    #[error("{0}")]
    Input(String),
    /// The store refused a result.
    #[error("cannot store a result: {0}")]
    Store(String),
    /// The hypothesis cannot run in this build.
    #[error("not available: {0}")]
    NotAvailable(String),
}

/// The planning domain of H2-H4 as `cli` read it: scenes are AL_d files that include it.
#[derive(Clone, Debug)]
pub struct Domain {
    /// Its absolute path (`domains/ra/kb_full.ald` by default).
    pub path: String,
    /// Its text.
    pub text: String,
}

impl Domain {
    /// The problem of `scene` (with its goal) over this domain, built as values; the domain's
    /// text is parsed (it includes nothing).
    pub fn scene_problem(
        &self,
        scene: &crate::explain::h3::Scene,
    ) -> Result<crate::plan::Problem, TrialError> {
        let mut sources = crate::base::SourceMap::new();
        let file = sources.add(self.path.clone(), self.text.clone());
        let mut read = |p: &std::path::Path| {
            Err(format!(
                "{}: the domain {} cannot include files here",
                p.display(),
                self.path
            ))
        };
        let parsed = crate::action::load(&mut sources, file, &mut read);
        if parsed.has_errors() {
            let mut d = crate::base::Diagnostics::default();
            d.extend(parsed.diagnostics);
            return Err(TrialError::Input(d.render(&sources)));
        }
        Ok(crate::plan::Problem {
            domain: parsed.description,
            sources,
            ..scene.problem(true)
        })
    }
}

/// What trials read: the setup, the inputs loaded by `cli`, and the store.
pub struct Context<'a> {
    /// The setup.
    pub setup: Setup,
    /// The H1 knowledge base (`domains/ra/scenes/h1.ald` by default).
    pub kb: &'a KbSpec,
    /// The planning domain of H2-H4 (KB_full).
    pub domain: &'a Domain,
    /// The results.
    pub store: &'a dyn Store,
    /// Answers of the H1 worlds, shared by the learning runs of this process (an answer is a
    /// function of the knowledge base, the facts and the action: `learn::kb::Cache`), so they
    /// change no result, only the time.
    pub caches: Caches,
}

/// How a trial's result was obtained.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Computed now.
    Computed,
    /// Taken from the store.
    Reused,
}

impl Context<'_> {
    /// The stored record of `trial` when its setup matches.
    pub fn stored(&self, trial: &Trial) -> Option<Record> {
        let text = self.store.load(&trial.id())?;
        let record: Record = serde_json::from_str(&text).ok()?;
        (record.id == trial.id() && record.setup == self.setup).then_some(record)
    }

    /// The record of `trial`: reused from the store, or computed and stored.
    pub fn record(&self, trial: &Trial) -> Result<(Record, Outcome), TrialError> {
        if let Some(r) = self.stored(trial) {
            return Ok((r, Outcome::Reused));
        }
        let start = Instant::now();
        let seed = trial.seed(&self.setup);
        let result = match trial.hypothesis {
            Hypothesis::H1 => h1::run_trial(self, trial, seed)?,
            Hypothesis::H2 => h2::run_trial(self, trial, seed)?,
            h @ (Hypothesis::H3 | Hypothesis::H4) => h34::run_trial(self, h, trial, seed)?,
        };
        let record = Record {
            id: trial.id(),
            setup: self.setup.clone(),
            trial_seed: seed,
            seconds: start.elapsed().as_secs_f64(),
            result,
        };
        let text =
            serde_json::to_string_pretty(&record).map_err(|e| TrialError::Store(e.to_string()))?;
        self.store
            .save(&record.id, &text)
            .map_err(TrialError::Store)?;
        Ok((record, Outcome::Computed))
    }
}

/// Progress of a run, after each finished trial.
#[derive(Clone, Copy, Debug)]
pub struct Progress {
    /// Trials finished (computed or reused).
    pub done: usize,
    /// Of which reused.
    pub reused: usize,
    /// Trials in the run.
    pub total: usize,
}

/// Runs `trials` on rayon, H1 first (H2 and H4 read its learned axioms), and returns their
/// records in id order; `progress` is called after every trial.
pub fn run(
    ctx: &Context,
    trials: &[Trial],
    progress: &(dyn Fn(Progress) + Sync),
) -> Result<Vec<Record>, TrialError> {
    let total = trials.len();
    let done = std::sync::atomic::AtomicUsize::new(0);
    let reused = std::sync::atomic::AtomicUsize::new(0);
    let one = |t: &Trial| -> Result<Record, TrialError> {
        let (record, outcome) = ctx.record(t)?;
        use std::sync::atomic::Ordering::SeqCst;
        let r = if outcome == Outcome::Reused {
            reused.fetch_add(1, SeqCst) + 1
        } else {
            reused.load(SeqCst)
        };
        let d = done.fetch_add(1, SeqCst) + 1;
        progress(Progress {
            done: d,
            reused: r,
            total,
        });
        Ok(record)
    };
    let (first, rest): (Vec<&Trial>, Vec<&Trial>) =
        trials.iter().partition(|t| t.hypothesis == Hypothesis::H1);
    let mut records: Vec<Record> = first.par_iter().map(|t| one(t)).collect::<Result<_, _>>()?;
    let later: Vec<Record> = rest.par_iter().map(|t| one(t)).collect::<Result<_, _>>()?;
    records.extend(later);
    records.sort_by(|a, b| a.id.cmp(&b.id));
    Ok(records)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_round_trip_and_seeds_depend_on_the_trial_only() {
        let setup = Setup::paper(7);
        let all = trials(&setup, &[Hypothesis::H1]);
        assert_eq!(all.len(), 20);
        for t in &all {
            assert_eq!(Trial::parse_id(&t.id()).as_ref(), Some(t));
        }
        assert_eq!(all[3].id(), "h1-kb_full-0003");
        assert_eq!(
            all[3].seed(&setup),
            crate::learn::h1::run_seed(7, 3),
            "H1 keeps the seeds of lucent learn"
        );
        let a = Trial {
            hypothesis: Hypothesis::H2,
            config: "real".into(),
            index: 4,
        };
        let b = Trial {
            index: 5,
            ..a.clone()
        };
        assert_ne!(a.seed(&setup), b.seed(&setup));
        assert_ne!(a.seed(&setup), a.seed(&Setup::paper(8)));
        assert_eq!(Trial::parse_id("h2-nowhere-0001"), None);
        assert_eq!(Trial::parse_id("h9-real-0001"), None);
    }
}
