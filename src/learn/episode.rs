//! Runs, episodes and trials of axiom learning (docs/domain.md 5.2), over any one-step world.
//!
//! A run starts from a fresh learner knowledge base and has at most `episodes` episodes. An
//! episode first looks for a discrepancy (an action type drawn uniformly, a random state and
//! arguments, the oracle and the learner run and compared); after `detect_trials` quiet trials
//! the run ends. A quiet trial counts only when the learner takes its action to be executable
//! (the robot would act) unless `count_every_trial` (5.2 as written). Otherwise the same action type is repeated to collect
//! samples (5.4) until a dataset holds T; the samples are lifted (5.5), the ensemble votes
//! (5.6-5.8), and the kept axioms join the learner's knowledge base at once, with a strength
//! (5.9) that decays after every episode and is refreshed when the axiom is learned again or
//! applies in a trial's answer set (the learner acts on it).
//!
//! Two rules of ours keep an episode finite and informative: collection also ends after a
//! stall, `stall_trials` consecutive trials that add no sample, or longer while a dataset waits
//! for a rare class (five mean gaps between its samples, at most `stall_max`,
//! `Collector::stall_window`); then a dataset whose positives reached the cap is learned from,
//! causal laws first. It never exceeds `max_collect_trials`.
//!
//! Invariants: a run is a function of (seed, oracle, learner's initial knowledge, config); the
//! only randomness is the run's generator and the ensemble's seeds derived from it.

use super::cart::Table;
use super::ensemble::{self, EnsembleParams, Target};
use super::lift::{choose_head, relevant, Algebra, Lifted, Lifter, Signature};
use super::state::{
    generate, ActionType, CollectConfig, Collector, Dataset, OneStep, Outcome, Pools,
};
use super::strength::{Added, Origin, Store};
use super::surprise::classify;
use super::term::{Axiom, AxiomKind, Literal};
use crate::base::rng::SplitMix64;

/// What a world says about one action from one state.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct States {
    /// The step-0 state: at least every positive literal and every literal of either sign that
    /// mentions a constant of the action, which is all that is read of it (5.1 compares
    /// positive literals, 5.5's relevant literals and 5.9's refresh on use mention the action's
    /// constants: every literal of a learned axiom's body holds an action variable). A world
    /// may give the complete state; statics may be included.
    pub before: Vec<Literal>,
    /// The step-1 state (a world may give only its positive literals, all that 5.1 compares),
    /// `None` when the action is not executable.
    pub after: Option<Vec<Literal>>,
    /// The world cannot hold the step-0 state at rest (a physics world in which an object
    /// falls off its support before anything is done): the trial shows nothing about the
    /// action, gives no sample and is no surprise. Knowledge bases never set it.
    pub unrealisable: bool,
}

/// A one-step world: the oracle (KB_full, a physics world) or the learner's knowledge base.
pub trait World {
    /// Runs `action` from the state given by `facts` (step-0 `on` and `in_hand` facts; the
    /// world completes them by its defaults).
    fn step(&mut self, facts: &[Literal], action: &Literal) -> States;
}

/// The learner's knowledge base: a world that takes learned axioms.
pub trait LearnerKb: World {
    /// Replaces the learned axioms (label, axiom) the knowledge base reasons with.
    fn set_learned(&mut self, axioms: &[(String, Axiom)]);
}

/// Settings of a learning run.
#[derive(Clone, Debug)]
pub struct LearnConfig {
    /// Episodes per run.
    pub episodes: usize,
    /// Quiet trials (without a discrepancy) after which the run ends.
    pub detect_trials: usize,
    /// Which quiet trials count towards `detect_trials`: every one (docs/domain.md 5.2 as written),
    /// or [ours, the default] only those the robot would act in, i.e. whose action its
    /// knowledge takes to be executable. The paper's robot stops after "executing a number of
    /// actions without detecting any inconsistency"; a trial whose action the learner already
    /// forbids executes nothing and cannot show a missing effect. Counting every trial ends
    /// about 7% of runs before C2 is seen: once E2 is known only an executable putdown shows
    /// C2's absence, about 2.5% of all trials (docs/bench/h1.md).
    pub count_every_trial: bool,
    /// Bound on the trials of one detection phase (only reached when the learner forbids
    /// almost every action, e.g. after an over-general executability condition).
    pub max_detect_trials: usize,
    /// Collection and class balance.
    pub collect: CollectConfig,
    /// Consecutive trials without a new sample that end collection, at least (see
    /// `Collector::stall_window`).
    pub stall_trials: usize,
    /// While a capped dataset still wants negatives, collection waits this many mean gaps
    /// between them before it ends (`Collector::stall_window`).
    pub stall_factor: f64,
    /// The longest stall window (`Collector::stall_window`).
    pub stall_max: usize,
    /// Hard bound on the trials of one collection.
    pub max_collect_trials: usize,
    /// The ensemble.
    pub ensemble: EnsembleParams,
    /// The state generator's pools.
    pub pools: Pools,
    /// Normalization of converse and symmetric relations in lifting.
    pub algebra: Algebra,
    /// Hears the index of each episode as it starts (a progress bar); nobody by default.
    pub on_episode: EpisodeObserver,
}

/// A listener for the start of each episode, shared across threads.
#[derive(Clone, Default)]
pub struct EpisodeObserver(pub Option<std::sync::Arc<dyn Fn(usize) + Send + Sync>>);

impl std::fmt::Debug for EpisodeObserver {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(if self.0.is_some() {
            "EpisodeObserver(set)"
        } else {
            "EpisodeObserver(none)"
        })
    }
}

impl Default for LearnConfig {
    fn default() -> Self {
        LearnConfig {
            episodes: 10,
            detect_trials: 100,
            count_every_trial: false,
            max_detect_trials: 2000,
            collect: CollectConfig::default(),
            stall_trials: 100,
            stall_factor: 5.0,
            stall_max: 500,
            max_collect_trials: 5000,
            ensemble: EnsembleParams::default(),
            pools: Pools::h1(),
            algebra: Algebra::ra(),
            on_episode: EpisodeObserver::default(),
        }
    }
}

/// One episode's report.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EpisodeReport {
    /// Episode index.
    pub episode: usize,
    /// The trial (of the detection phase) that found the surprise, `None` if none was found.
    pub detected_at: Option<usize>,
    /// The surprising action and what was unexpected or extra, for people.
    pub surprise: String,
    /// The dataset learned from, if any.
    pub dataset: Option<Dataset>,
    /// Samples in it and how many were positive.
    pub samples: (usize, usize),
    /// The lifted feature table the trees were trained on (after [`dedupe_columns`]), with
    /// its feature literals, for inspection (`lucent learn --tables DIR`).
    pub table: Option<(Vec<Literal>, Table)>,
    /// Trials spent collecting.
    pub collect_trials: usize,
    /// The kept axioms (short form) with their votes and whether they were new.
    pub learned: Vec<(String, usize, bool)>,
    /// Labels removed by decay at the end of the episode.
    pub removed: Vec<String>,
}

/// A run's result.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RunReport {
    /// The learned axioms at the end of the run.
    pub store: Store,
    /// One report per episode that ran.
    pub episodes: Vec<EpisodeReport>,
    /// Trials run in all.
    pub trials: usize,
    /// Solver calls of the worlds, when the caller counts them (0 otherwise).
    pub solves: usize,
}

/// The data of one trial that went into a dataset.
#[derive(Clone, Debug)]
struct TrialData {
    action: Literal,
    unexpected: Vec<Literal>,
    relevant: Vec<Literal>,
}

/// Runs one trial: the learner and the oracle on the same state and action. With
/// `skip_uninformative` (collection under `informative_only`), a trial the learner already
/// forbids cannot give a sample, so the oracle is not asked and the outcome is "no surprise,
/// not executable by the learner" (which every dataset declines).
///
/// The learner acts on its answer set when it has one: the learned axioms that apply there
/// are refreshed (5.9, refresh on use).
fn trial(
    oracle: &mut dyn World,
    learner: &mut dyn World,
    store: &mut Store,
    s: &OneStep,
    robot: &str,
    skip_uninformative: bool,
) -> (Outcome, TrialData) {
    let facts = s.facts(robot);
    let l = learner.step(&facts, &s.action);
    if l.after.is_some() && !store.axioms.is_empty() {
        store.used_in(&s.action, &l.before);
    }
    let outcome = if skip_uninformative && l.after.is_none() {
        Outcome::default()
    } else {
        let o = oracle.step(&facts, &s.action);
        if o.unrealisable {
            Outcome {
                void: true,
                ..Outcome::default()
            }
        } else {
            classify(&l.before, l.after.as_deref(), o.after.as_deref())
        }
    };
    let data = TrialData {
        action: s.action.clone(),
        unexpected: outcome.unexpected.clone(),
        relevant: relevant(&l.before, &s.action),
    };
    (outcome, data)
}

fn describe(action: &Literal, o: &Outcome) -> String {
    let list = |ls: &[Literal]| {
        let mut text = ls
            .iter()
            .take(3)
            .map(Literal::short)
            .collect::<Vec<_>>()
            .join(", ");
        if ls.len() > 3 {
            text.push_str(&format!(" and {} more", ls.len() - 3));
        }
        text
    };
    if !o.unexpected.is_empty() {
        format!("{}: unexpected {}", action.short(), list(&o.unexpected))
    } else {
        format!("{}: extra {}", action.short(), list(&o.extra))
    }
}

/// One learning run.
pub fn run(
    oracle: &mut dyn World,
    learner: &mut dyn LearnerKb,
    config: &LearnConfig,
    seed: u64,
) -> RunReport {
    let mut report = RunReport::default();
    let robot = config.pools.robot.clone();
    let root = SplitMix64::new(seed);
    for episode in 0..config.episodes {
        if let Some(hear) = &config.on_episode.0 {
            hear(episode);
        }
        let mut rng = root.fork(episode as u64);
        let mut ep = EpisodeReport {
            episode,
            ..EpisodeReport::default()
        };
        // Detection: until `detect_trials` quiet trials that count (see
        // `LearnConfig::count_every_trial`), at most `max_detect_trials` in all.
        let mut detected = None;
        let mut quiet = 0;
        let mut t = 0;
        while quiet < config.detect_trials && t < config.max_detect_trials {
            let ty = if rng.chance(0.5) {
                ActionType::Pickup
            } else {
                ActionType::Putdown
            };
            let s = generate(&config.pools, ty, &mut rng);
            // Under `informative_only` a trial whose action the learner forbids is no surprise
            // to learn from whatever the oracle says: no dataset takes a sample of it, so an
            // episode it started would collect nothing (a physics world that stacks onto a
            // covered object, which E1 forbids, started five such episodes in run 1 of seed
            // 0). The oracle is asked only when its answer matters: for a trial the learner
            // acts in, or to tell whether a forbidden one is quiet under `count_every_trial`.
            let informative = config.collect.informative_only;
            let skip = informative && !config.count_every_trial;
            let (outcome, data) = trial(oracle, learner, &mut report.store, &s, &robot, skip);
            report.trials += 1;
            let learnable = !informative || outcome.learner_executable;
            if outcome.surprising() && learnable {
                ep.detected_at = Some(t);
                ep.surprise = describe(&s.action, &outcome);
                detected = Some((ty, outcome, data));
                break;
            }
            if outcome.learner_executable || (config.count_every_trial && !outcome.surprising()) {
                quiet += 1;
            }
            t += 1;
        }
        let Some((ty, outcome, data)) = detected else {
            report.episodes.push(ep);
            break;
        };
        // Collection, starting with the surprising trial itself.
        let mut collector = Collector::new(config.collect.clone());
        let mut trials: Vec<TrialData> = vec![data];
        collector.offer(0, &outcome);
        let mut since_last = 0;
        let mut t = 1;
        while collector.full().is_none()
            && t < config.max_collect_trials
            && since_last
                < collector.stall_window(config.stall_trials, config.stall_factor, config.stall_max)
        {
            let s = generate(&config.pools, ty, &mut rng);
            let (outcome, data) = trial(
                oracle,
                learner,
                &mut report.store,
                &s,
                &robot,
                config.collect.informative_only,
            );
            report.trials += 1;
            trials.push(data);
            if collector.offer(t, &outcome).is_empty() {
                since_last += 1;
            } else {
                since_last = 0;
            }
            t += 1;
        }
        ep.collect_trials = t;
        let cap = (0.6 * config.collect.size as f64).round() as usize;
        let which = collector.full().or_else(|| {
            if collector.cl.positives() >= cap {
                Some(Dataset::Cl)
            } else if collector.ec.positives() >= cap {
                Some(Dataset::Ec)
            } else {
                None
            }
        });
        if let Some(which) = which {
            let samples = match which {
                Dataset::Cl => &collector.cl,
                Dataset::Ec => &collector.ec,
            };
            ep.dataset = Some(which);
            ep.samples = (samples.len(), samples.positives());
            let ens_seed = rng.next_u64();
            if let Some((axioms, _, table)) =
                induce(&trials, &samples.items, which, config, ens_seed)
            {
                ep.table = Some(table);
                for (axiom, votes) in axioms {
                    let origin = Origin {
                        episode,
                        trial: ep.detected_at.unwrap_or(0),
                        surprise: ep.surprise.clone(),
                    };
                    let short = axiom.short();
                    let added = report.store.learn(axiom, votes, origin);
                    ep.learned
                        .push((short, votes, matches!(added, Added::New(_))));
                }
            }
        }
        ep.removed = report
            .store
            .end_episode()
            .into_iter()
            .map(|l| l.label)
            .collect();
        let current: Vec<(String, Axiom)> = report
            .store
            .axioms
            .iter()
            .map(|l| (l.label.clone(), l.axiom.clone()))
            .collect();
        learner.set_learned(&current);
        report.episodes.push(ep);
    }
    report
}

/// Kept axioms with their votes, the lifted samples they came from, and the feature table.
type Induced = (Vec<(Axiom, usize)>, Vec<Lifted>, (Vec<Literal>, Table));

/// Lifts a dataset and runs the ensemble: the kept axioms with their votes, and the lifted
/// samples.
fn induce(
    trials: &[TrialData],
    items: &[(usize, bool)],
    which: Dataset,
    config: &LearnConfig,
    seed: u64,
) -> Option<Induced> {
    let signature = Signature {
        robots: vec![config.pools.robot.clone()],
    };
    let mut lifter = Lifter::new(signature, config.algebra.clone());
    let lifted: Vec<Lifted> = items
        .iter()
        .map(|&(t, _)| {
            let d = &trials[t];
            let unexpected: &[Literal] = if which == Dataset::Cl {
                &d.unexpected
            } else {
                &[]
            };
            lifter.lift(unexpected, &d.action, &d.relevant)
        })
        .collect();
    let action = lifted.first()?.action.clone();
    let (kind, labels): (AxiomKind, Vec<bool>) = match which {
        Dataset::Cl => {
            let positives: Vec<Lifted> = lifted
                .iter()
                .zip(items)
                .filter(|(_, (_, label))| *label)
                .map(|(l, _)| l.clone())
                .collect();
            let (head, _) = choose_head(&positives)?;
            let labels = lifted
                .iter()
                .map(|l| l.unexpected.contains(&head))
                .collect();
            (AxiomKind::Causal { head }, labels)
        }
        Dataset::Ec => (
            AxiomKind::Executability,
            items.iter().map(|&(_, l)| l).collect(),
        ),
    };
    let n = lifter.features.len();
    let rows: Vec<Vec<bool>> = lifted
        .iter()
        .map(|l| {
            let mut row = vec![false; n];
            for &f in &l.features {
                row[f] = true;
            }
            row
        })
        .collect();
    let (features, rows) = dedupe_columns(&lifter.features, rows, &config.algebra);
    let table = Table::new(rows, labels);
    let target = Target { kind, action };
    let learned = ensemble::learn(&table, &features, &target, &config.ensemble, seed);
    Some((learned.kept, lifted, (features, table)))
}

/// Keeps one feature of each group of identical columns \[ours\]: the trees cannot tell them
/// apart, and a seeded tie-break between them would split the vote between two spellings of
/// one fact (`below(O1, O2)` and `on(O2, O1)` when every covered object has its cover directly
/// on it). The kept one is the lowest by [`Algebra::rank`], then the first created.
pub fn dedupe_columns(
    features: &[Literal],
    rows: Vec<Vec<bool>>,
    algebra: &Algebra,
) -> (Vec<Literal>, Vec<Vec<bool>>) {
    let column = |f: usize| -> Vec<bool> { rows.iter().map(|r| r[f]).collect() };
    let mut best: std::collections::HashMap<Vec<bool>, usize> = std::collections::HashMap::new();
    for f in 0..features.len() {
        let col = column(f);
        let entry = best.entry(col).or_insert(f);
        if algebra.rank(&features[f]) < algebra.rank(&features[*entry]) {
            *entry = f;
        }
    }
    let mut keep: Vec<usize> = best.into_values().collect();
    keep.sort_unstable();
    let kept_features = keep.iter().map(|&f| features[f].clone()).collect();
    let kept_rows = rows
        .iter()
        .map(|r| keep.iter().map(|&f| r[f]).collect())
        .collect();
    (kept_features, kept_rows)
}

#[cfg(test)]
mod tests {
    use super::super::term::{in_hand, o, r, rel};
    use super::*;

    /// A world that forbids every action, or allows every action and changes nothing.
    struct Still {
        executable: bool,
    }

    impl World for Still {
        fn step(&mut self, facts: &[Literal], _: &Literal) -> States {
            States {
                before: facts.to_vec(),
                after: self.executable.then(|| facts.to_vec()),
                unrealisable: false,
            }
        }
    }

    impl LearnerKb for Still {
        fn set_learned(&mut self, _: &[(String, Axiom)]) {}
    }

    /// Without a surprise a run ends after `detect_trials` quiet trials the learner would act
    /// in; trials whose action it forbids count only under `count_every_trial`, and
    /// `max_detect_trials` bounds the phase.
    #[test]
    fn detection_counts_the_trials_the_learner_acts_in() {
        let config = LearnConfig::default();
        let run_with = |config: &LearnConfig, executable: bool| {
            run(
                &mut Still { executable },
                &mut Still { executable },
                config,
                3,
            )
        };
        let acting = run_with(&config, true);
        assert_eq!((acting.trials, acting.episodes.len()), (100, 1));
        assert_eq!(acting.episodes[0].detected_at, None);
        let forbidding = run_with(&config, false);
        assert_eq!(forbidding.trials, config.max_detect_trials);
        let every = LearnConfig {
            count_every_trial: true,
            ..LearnConfig::default()
        };
        assert_eq!(run_with(&every, false).trials, 100);
    }

    /// Columns: below(O1, O2) and on(O2, O1) identical, -in_hand(R1, O1) and above(O1, O3)
    /// identical, touch(O1, O4) alone. Kept: below (positional before composed), -in_hand (the
    /// hand before relations), touch.
    #[test]
    fn identical_columns_keep_the_preferred_spelling() {
        let features = vec![
            rel("on", o(2), o(1)),
            rel("below", o(1), o(2)),
            rel("above", o(1), o(3)),
            in_hand(false, r(1), o(1)),
            rel("touch", o(1), o(4)),
        ];
        let rows = vec![
            vec![true, true, false, false, true],
            vec![false, false, true, true, true],
            vec![true, true, true, true, false],
        ];
        let (f, rows) = dedupe_columns(&features, rows, &Algebra::ra());
        assert_eq!(
            f,
            vec![
                rel("below", o(1), o(2)),
                in_hand(false, r(1), o(1)),
                rel("touch", o(1), o(4))
            ]
        );
        assert_eq!(rows[0], vec![true, false, true]);
    }
}
