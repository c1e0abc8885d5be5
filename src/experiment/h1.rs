//! H1, learning accuracy (docs/domain.md 7.3, the paper's Table 1): one trial is one learning run
//! of `learn::h1` against the setup's oracle (KB_full, or the physics world with `--oracle
//! physics`, reported under its own name); the table sums the runs' strict and relaxed counts
//! (5.10).
//!
//! Invariants: a trial computes exactly what run `i` of `learn::h1::experiment` computes (same
//! seed, same knowledge bases, same scoring), so the aggregate equals that function's result;
//! the learned axioms are kept in the result as an AL_d file for the H2 and H4 trials that
//! reason "with the learned axioms".

use serde::{Deserialize, Serialize};

use super::interval::{self, Interval};
use super::{Context, Record, Trial, TrialError};
use crate::action::ast::Statement;
use crate::learn::h1::{one_run_with, targets, Oracle, PrecisionRecall, PAPER};
use crate::learn::score::{relaxed, strict, Counts};
use crate::learn::term::Axiom;

/// True positives, false positives and false negatives (`learn::score::Counts` as stored).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Tally {
    /// Found axioms matching a target.
    pub tp: usize,
    /// Found axioms matching no target.
    pub fp: usize,
    /// Targets matched by no found axiom.
    #[serde(rename = "fn")]
    pub fn_: usize,
}

impl From<Counts> for Tally {
    fn from(c: Counts) -> Self {
        Tally {
            tp: c.tp,
            fp: c.fp,
            fn_: c.fn_,
        }
    }
}

impl From<Tally> for Counts {
    fn from(t: Tally) -> Self {
        Counts {
            tp: t.tp,
            fp: t.fp,
            fn_: t.fn_,
        }
    }
}

/// One learning run's result.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RunResult {
    /// Run index.
    pub run: usize,
    /// The learned axioms at the end of the run (short form).
    pub found: Vec<String>,
    /// Strict counts.
    pub strict: Tally,
    /// Relaxed counts.
    pub relaxed: Tally,
    /// Trials run.
    pub trials: usize,
    /// Episodes run.
    pub episodes: usize,
    /// The learned axioms as an AL_d file with their strengths (`lucent learn -o`); left out
    /// of the summary's runs (empty there).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub ald: String,
    /// The learned axioms with their labels, as values (what H2-H4 plan and explain with).
    pub axioms: Vec<(String, Axiom)>,
}

/// Runs learning run `trial.index` with `seed`.
pub fn run_trial(ctx: &Context, trial: &Trial, seed: u64) -> Result<serde_json::Value, TrialError> {
    let oracle = Oracle::parse(&trial.config)
        .ok_or_else(|| TrialError::Input(format!("unknown H1 oracle '{}'", trial.config)))?;
    oracle.availability().map_err(TrialError::NotAvailable)?;
    let report = one_run_with(ctx.kb, &ctx.setup.learn_config(), seed, oracle, &ctx.caches)
        .map_err(|e| TrialError::Input(e.to_string()))?;
    let found: Vec<Axiom> = report.store.current();
    let t = targets();
    let result = RunResult {
        run: trial.index,
        found: found.iter().map(Axiom::short).collect(),
        strict: strict(&found, &t).into(),
        relaxed: relaxed(&found, &t).into(),
        trials: report.trials,
        episodes: report.episodes.len(),
        ald: report.store.to_ald(),
        axioms: report
            .store
            .axioms
            .iter()
            .map(|l| (l.label.clone(), l.axiom.clone()))
            .collect(),
    };
    serde_json::to_value(result).map_err(|e| TrialError::Store(e.to_string()))
}

/// The axioms learned in H1 run `run` (computed and stored if absent: same seed, same
/// result), as AL_d statements labelled as the run labelled them.
pub fn learned_statements(ctx: &Context, run: usize) -> Result<Vec<Statement>, TrialError> {
    let trial = Trial {
        hypothesis: super::Hypothesis::H1,
        config: ctx.setup.oracle.name().into(),
        index: run,
    };
    let (record, _) = ctx.record(&trial)?;
    let r: RunResult = serde_json::from_value(record.result)
        .map_err(|e| TrialError::Store(format!("{}: {e}", trial.id())))?;
    Ok(r.axioms
        .iter()
        .map(|(label, axiom)| axiom.statement(label))
        .collect())
}

/// Table 1: our figures summed over the runs, and the paper's.
#[derive(Clone, Debug, Serialize)]
pub struct Summary {
    /// The oracle the runs learned against (`kb_full`, `physics`).
    pub oracle: String,
    /// Whether a run ended after 100 quiet trials of any kind (docs/domain.md 5.2 as written)
    /// rather than 100 the learner would act in (`LearnConfig::count_every_trial`).
    pub count_every_trial: bool,
    /// Strict precision and recall over all runs, %.
    pub strict: PrecisionRecall,
    /// Relaxed precision and recall over all runs, %.
    pub relaxed: PrecisionRecall,
    /// Summed strict counts.
    pub strict_counts: Tally,
    /// Summed relaxed counts.
    pub relaxed_counts: Tally,
    /// 95% intervals of strict P, strict R, relaxed P, relaxed R (bootstrap over the runs,
    /// each resample's counts summed as the table's are).
    pub intervals: [Option<Interval>; 4],
    /// The paper's Table 1.
    pub paper: crate::learn::h1::PaperH1,
    /// Per run, in run order (without the AL_d text).
    pub runs: Vec<RunResult>,
}

/// Sums the H1 records (other records are ignored).
pub fn aggregate(records: &[Record]) -> Result<Summary, String> {
    let mut runs = Vec::new();
    let mut oracle = Oracle::KbFull;
    let mut count_every_trial = false;
    let (mut s, mut x) = (Counts::default(), Counts::default());
    let mut tallies: Vec<(Tally, Tally)> = Vec::new();
    for r in records.iter().filter(|r| r.id.starts_with("h1-")) {
        oracle = r.setup.oracle;
        count_every_trial = r.setup.count_every_trial;
        let run: RunResult =
            serde_json::from_value(r.result.clone()).map_err(|e| format!("{}: {e}", r.id))?;
        s.add(run.strict.into());
        x.add(run.relaxed.into());
        tallies.push((run.strict, run.relaxed));
        runs.push(RunResult {
            ald: String::new(),
            ..run
        });
    }
    runs.sort_by_key(|r| r.run);
    let ci = |relaxed: bool, recall: bool| {
        interval::bootstrap(&tallies, |sample| {
            let mut c = Counts::default();
            for (st, re) in sample {
                c.add(if relaxed { *re } else { *st }.into());
            }
            let pr: PrecisionRecall = c.into();
            Some(if recall { pr.recall } else { pr.precision })
        })
    };
    Ok(Summary {
        intervals: [
            ci(false, false),
            ci(false, true),
            ci(true, false),
            ci(true, true),
        ],
        oracle: oracle.name().into(),
        count_every_trial,
        strict: s.into(),
        relaxed: x.into(),
        strict_counts: s.into(),
        relaxed_counts: x.into(),
        paper: PAPER,
        runs,
    })
}

/// The markdown section.
pub fn markdown(s: &Summary) -> String {
    let mut out = String::new();
    out.push_str("## H1: learning accuracy (Table 1)\n\n");
    out.push_str(&format!(
        "{} learning runs against {} (docs/domain.md 7.3), scored against the five targets \
         E7, E5, E2, C3, C2 (5.10). Counts summed over the runs: strict TP {} FP {} FN {}, \
         relaxed TP {} FP {} FN {}. A run ends after 100 quiet trials {}.\n\n",
        s.runs.len(),
        match s.oracle.as_str() {
            "physics" =>
                "the physics world (rapier; `learn::physics`: support relations and \
                          the hand observed, no noise), not KB_full",
            _ => "KB_full",
        },
        s.strict_counts.tp,
        s.strict_counts.fp,
        s.strict_counts.fn_,
        s.relaxed_counts.tp,
        s.relaxed_counts.fp,
        s.relaxed_counts.fn_,
        if s.count_every_trial {
            "of any kind (docs/domain.md 5.2 as written, `--count-every-trial`)"
        } else {
            "in which the learner would act, i.e. takes the action to be executable [ours; \
             `--count-every-trial` counts every trial as 5.2 is written]"
        },
    ));
    out.push_str(
        "| scoring | precision (ours) | precision (paper) | recall (ours) | recall (paper) |\n",
    );
    out.push_str("|---|---|---|---|---|\n");
    for (k, (name, ours, paper)) in [
        ("strict", s.strict, s.paper.strict),
        ("relaxed", s.relaxed, s.paper.relaxed),
    ]
    .into_iter()
    .enumerate()
    {
        out.push_str(&format!(
            "| {name} | {} | {:.1} | {} | {:.1} |\n",
            interval::cell(Some(ours.precision), s.intervals[2 * k], 1),
            paper.precision,
            interval::cell(Some(ours.recall), s.intervals[2 * k + 1], 1),
            paper.recall
        ));
    }
    out.push_str("\n![H1 precision and recall](h1.svg)\n\n");
    out.push_str(
        "| run | trials | episodes | strict TP/FP/FN | learned axioms |\n|---|---|---|---|---|\n",
    );
    for r in &s.runs {
        out.push_str(&format!(
            "| {} | {} | {} | {}/{}/{} | {} |\n",
            r.run,
            r.trials,
            r.episodes,
            r.strict.tp,
            r.strict.fp,
            r.strict.fn_,
            r.found.join("; ").replace('|', "\\|")
        ));
    }
    out.push('\n');
    out
}

/// The plot: precision and recall, strict and relaxed, ours beside the paper's.
pub fn plot(s: &Summary) -> String {
    let groups = [
        ("strict P", s.strict.precision, s.paper.strict.precision),
        ("strict R", s.strict.recall, s.paper.strict.recall),
        ("relaxed P", s.relaxed.precision, s.paper.relaxed.precision),
        ("relaxed R", s.relaxed.recall, s.paper.relaxed.recall),
    ]
    .iter()
    .map(|(g, ours, paper)| (g.to_string(), vec![Some(*ours), Some(*paper)]))
    .collect::<Vec<_>>();
    super::svg::bar_chart(&super::svg::Bars {
        title: format!(
            "H1 ({} oracle): learned axioms against the five targets (%)",
            s.oracle
        ),
        series: vec!["ours".into(), "paper".into()],
        errors: s.intervals.iter().map(|i| vec![*i, None]).collect(),
        groups,
        y_max: 100.0,
    })
}
