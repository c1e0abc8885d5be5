//! The report of a run: per-hypothesis tables as JSON (`h1`..`h4`), markdown with the paper's
//! tables beside ours, and the SVG plots, all from the trial records.
//!
//! Invariants: a pure function of the setup, the hypotheses asked for and the records (any
//! order: they are sorted by id, then seed, first); records of several seeds (a `merge` of
//! runs that differ only in the seed) are pooled, so every count is the sum of the seeds'
//! counts and every mean is over all their trials; every figure carries its 95% bootstrap
//! interval (`interval`); a hypothesis that is not available is the JSON string
//! `"not available: <reason>"` and a markdown paragraph saying so, with no table and no plot.

use serde_json::{json, Value};

use super::{availability, h1, h2, h34, Hypothesis, Record, Setup};

/// One hypothesis in the report.
#[derive(Clone, Debug)]
pub enum Section {
    /// H1's tables.
    H1(Box<h1::Summary>),
    /// H2's tables.
    H2(Box<h2::Summary>),
    /// H3's counts.
    H3(h34::H3Summary),
    /// H4's tables.
    H4(Box<h34::H4Summary>),
    /// Not available in this build, with the reason.
    NotAvailable(Hypothesis, String),
}

/// A run's report.
#[derive(Clone, Debug)]
pub struct Report {
    /// The setup.
    pub setup: Setup,
    /// The seeds whose trials are pooled, ascending (the setup's alone without records).
    pub seeds: Vec<u64>,
    /// The trials aggregated.
    pub trials: usize,
    /// One section per hypothesis asked for, in order.
    pub sections: Vec<Section>,
}

impl Report {
    /// Aggregates `records` for `hypotheses`.
    pub fn new(
        setup: &Setup,
        hypotheses: &[Hypothesis],
        records: &[Record],
    ) -> Result<Report, String> {
        let mut records = records.to_vec();
        records.sort_by(|a, b| (&a.id, a.setup.seed).cmp(&(&b.id, b.setup.seed)));
        let mut seeds: Vec<u64> = records.iter().map(|r| r.setup.seed).collect();
        seeds.sort_unstable();
        seeds.dedup();
        if seeds.is_empty() {
            seeds.push(setup.seed);
        }
        let mut sections = Vec::new();
        for &h in hypotheses {
            if let Err(reason) = availability(h) {
                sections.push(Section::NotAvailable(h, reason));
                continue;
            }
            sections.push(match h {
                Hypothesis::H1 => Section::H1(Box::new(h1::aggregate(&records)?)),
                Hypothesis::H2 => Section::H2(Box::new(h2::aggregate(&records)?)),
                Hypothesis::H3 => Section::H3(h34::aggregate_h3(&records)?),
                Hypothesis::H4 => Section::H4(Box::new(h34::aggregate_h4(&records)?)),
            });
        }
        // Pooled seeds: the setup is named by the least one, whichever run came first.
        let setup = Setup {
            seed: seeds[0],
            ..setup.clone()
        };
        Ok(Report {
            setup,
            seeds,
            trials: records.len(),
            sections,
        })
    }

    /// The `--outf=2` JSON: the setup, the trial count and one key per hypothesis.
    pub fn to_json(&self) -> Value {
        let mut out = json!({ "setup": self.setup, "trials": self.trials });
        if self.seeds != [self.setup.seed] {
            out["seeds"] = json!(self.seeds);
        }
        for s in &self.sections {
            let (key, value) = match s {
                Section::H1(x) => ("h1", serde_json::to_value(x).unwrap_or_default()),
                Section::H2(x) => ("h2", serde_json::to_value(x).unwrap_or_default()),
                Section::H3(x) => ("h3", serde_json::to_value(x).unwrap_or_default()),
                Section::H4(x) => ("h4", serde_json::to_value(x).unwrap_or_default()),
                Section::NotAvailable(h, reason) => {
                    (h.name(), Value::String(format!("not available: {reason}")))
                }
            };
            out[key] = value;
        }
        out
    }

    /// The markdown report.
    pub fn to_markdown(&self) -> String {
        let s = &self.setup;
        let mut out = String::from("# Lucent: the paper's experiments H1-H4\n\n");
        let seeds = match self.seeds.as_slice() {
            [one] => format!("Seed {one}"),
            many => format!(
                "Seeds {} pooled (every count sums the seeds', every mean is over all their \
                 trials)",
                many.iter()
                    .map(u64::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        out.push_str(&format!(
            "{seeds}; H1: {} learning runs of at most {} episodes; H2-H4: {} configurations per \
             preset (real, simulated), {} goals each (docs/domain.md 7.1); {} trials in all. Each \
             table shows our figures beside the paper's.\n\n",
            s.runs, s.episodes, s.configurations, s.goals, self.trials
        ));
        out.push_str(&format!(
            "Intervals: every figure of ours is followed by its 95% interval in brackets, and \
             drawn with it as a whisker in the plots. Method (src/experiment/interval.rs): the \
             percentile bootstrap over the units the figure averages (H1: the learning runs, \
             their counts summed per resample as in the table; H2: the (scene, goal) pairs; H4: \
             the questions, one per trial and type), {} resamples with a fixed seed, so the same \
             records always print the same intervals. They measure the spread over our scenes \
             and runs, not over seeds of the generator.\n\n",
            super::interval::RESAMPLES
        ));
        for section in &self.sections {
            match section {
                Section::H1(x) => out.push_str(&h1::markdown(x)),
                Section::H2(x) => out.push_str(&h2::markdown(x)),
                Section::H3(x) => out.push_str(&h34::markdown_h3(x)),
                Section::H4(x) => out.push_str(&h34::markdown_h4(x)),
                Section::NotAvailable(h, reason) => out.push_str(&format!(
                    "## {}: not available\n\nNot run in this build: {reason}. No figures are \
                     reported for it.\n\n",
                    h.name().to_uppercase()
                )),
            }
        }
        out
    }

    /// The plots, as (file name, SVG text).
    pub fn plots(&self) -> Vec<(String, String)> {
        let mut out = Vec::new();
        for section in &self.sections {
            match section {
                Section::H1(x) => out.push(("h1.svg".into(), h1::plot(x))),
                Section::H2(x) => out.extend(h2::plots(x)),
                Section::H4(x) => out.extend(h34::plots_h4(x)),
                Section::H3(_) | Section::NotAvailable(..) => {}
            }
        }
        out
    }
}
