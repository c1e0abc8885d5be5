//! H2, plan quality with and without the learned axioms (DOMAIN.md 7.4, the paper's Tables 2
//! and 3). A trial is one (scene, goal) pair of a preset, planned under both knowledge-base
//! conditions of 7.2 (without: the `learner` profile; with: plus the axioms of H1 run
//! `configuration mod runs`), in the authors' fixed-horizon mode and with our iterative planner,
//! every plan classified optimal, sub-optimal or incorrect against KB_full (4.3).
//!
//! Invariants: Table 2's ratios are with/without per pair, averaged over the pairs where both
//! conditions found a plan (the others are counted, not dropped silently); Table 3's fractions
//! are per trial, averaged over the trials of a condition that found at least one plan.

use serde::{Deserialize, Serialize};

use super::svg;
use super::{Context, Record, Trial, TrialError};

/// Why H2 cannot run in this build, if it cannot.
pub fn availability() -> Result<(), String> {
    Err(
        "the planner's fixed-horizon mode, plan::check (optimal/sub-optimal/incorrect) and \
         the (scene, goal) generator of DOMAIN.md 7.1 are not on main yet"
            .into(),
    )
}

/// Runs one (scene, goal) pair.
pub fn run_trial(
    _ctx: &Context,
    _trial: &Trial,
    _seed: u64,
) -> Result<serde_json::Value, TrialError> {
    Err(TrialError::NotAvailable(
        availability().err().unwrap_or_default(),
    ))
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
    /// The minimal plan length L* found by the independent check.
    pub min_length: Option<usize>,
    /// Without the learned axioms.
    pub without: Condition,
    /// With them.
    pub with: Condition,
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

/// One preset.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct PresetSummary {
    /// Pairs (trials).
    pub pairs: usize,
    /// The authors' fixed-horizon mode.
    pub fixed: ModeSummary,
    /// Our iterative planner.
    pub iterative: ModeSummary,
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

/// The paper's Table 2 (ratio with/without): steps, plans, time; real then simulated.
pub const PAPER_TABLE2: [[f64; 2]; 3] = [[1.17, 1.21], [0.7, 1.1], [0.87, 1.08]];

/// The paper's Table 3: optimal, sub-optimal, incorrect; columns real w/o, real w/, sim w/o,
/// sim w/.
pub const PAPER_TABLE3: [[f64; 4]; 3] = [
    [0.33, 0.89, 0.13, 0.24],
    [0.12, 0.11, 0.44, 0.76],
    [0.55, 0.0, 0.43, 0.0],
];

fn mean(values: &[f64]) -> Option<f64> {
    (!values.is_empty()).then(|| values.iter().sum::<f64>() / values.len() as f64)
}

fn ratio(with: f64, without: f64) -> Option<f64> {
    (without > 0.0).then(|| with / without)
}

fn summarize_mode(pairs: &[&PairResult], mode: impl Fn(&Condition) -> &ModeResult) -> ModeSummary {
    let mut r = Ratios::default();
    let (mut steps, mut plans, mut time) = (Vec::new(), Vec::new(), Vec::new());
    for p in pairs {
        let (wo, w) = (mode(&p.without), mode(&p.with));
        if wo.plans == 0 || w.plans == 0 {
            r.pairs_without_plan += 1;
            continue;
        }
        r.pairs += 1;
        steps.extend(ratio(w.steps, wo.steps));
        plans.extend(ratio(w.plans as f64, wo.plans as f64));
        time.extend(ratio(w.time, wo.time));
    }
    r.steps = mean(&steps);
    r.plans = mean(&plans);
    r.planning_time = mean(&time);
    let fractions = |cond: &dyn Fn(&PairResult) -> &ModeResult| {
        let (mut o, mut s, mut i) = (Vec::new(), Vec::new(), Vec::new());
        for p in pairs {
            let m = cond(p);
            let n = (m.optimal + m.suboptimal + m.incorrect) as f64;
            if n > 0.0 {
                o.push(m.optimal as f64 / n);
                s.push(m.suboptimal as f64 / n);
                i.push(m.incorrect as f64 / n);
            }
        }
        Fractions {
            optimal: mean(&o),
            suboptimal: mean(&s),
            incorrect: mean(&i),
            trials: o.len(),
        }
    };
    ModeSummary {
        ratios: r,
        without: fractions(&|p| mode(&p.without)),
        with: fractions(&|p| mode(&p.with)),
    }
}

/// Aggregates the H2 records.
pub fn aggregate(records: &[Record]) -> Result<Summary, String> {
    let mut pairs = Vec::new();
    for r in records.iter().filter(|r| r.id.starts_with("h2-")) {
        let p: PairResult =
            serde_json::from_value(r.result.clone()).map_err(|e| format!("{}: {e}", r.id))?;
        pairs.push(p);
    }
    let preset = |name: &str| {
        let ps: Vec<&PairResult> = pairs.iter().filter(|p| p.preset == name).collect();
        PresetSummary {
            pairs: ps.len(),
            fixed: summarize_mode(&ps, |c| &c.fixed),
            iterative: summarize_mode(&ps, |c| &c.iterative),
        }
    };
    let by_size = |cond: fn(&PairResult) -> &Condition| {
        pairs
            .iter()
            .filter(|p| cond(p).iterative.plans > 0)
            .map(|p| (p.objects as f64, cond(p).iterative.time))
            .collect()
    };
    Ok(Summary {
        real: preset("real"),
        simulated: preset("simulated"),
        time_by_size: [by_size(|p| &p.without), by_size(|p| &p.with)],
    })
}

fn cell(v: Option<f64>) -> String {
    v.map_or("n/a".into(), |v| format!("{v:.2}"))
}

/// A table row: its name and how to read its value.
type Row<T> = (&'static str, fn(&T) -> Option<f64>);

fn tables(out: &mut String, s: &Summary, mode: &str, pick: fn(&PresetSummary) -> &ModeSummary) {
    let (r, m) = (pick(&s.real), pick(&s.simulated));
    out.push_str(&format!(
        "Table 2 ({mode}), ratio with/without, averaged over the pairs where both conditions \
         found a plan (real {} of {}, simulated {} of {}):\n\n",
        r.ratios.pairs, s.real.pairs, m.ratios.pairs, s.simulated.pairs
    ));
    out.push_str("| measure | real (ours) | real (paper) | simulated (ours) | simulated (paper) |\n|---|---|---|---|---|\n");
    let rows: [Row<Ratios>; 3] = [
        ("Number of steps", |r| r.steps),
        ("Number of plans", |r| r.plans),
        ("Planning time", |r| r.planning_time),
    ];
    for (k, (name, f)) in rows.iter().enumerate() {
        out.push_str(&format!(
            "| {name} | {} | {} | {} | {} |\n",
            cell(f(&r.ratios)),
            PAPER_TABLE2[k][0],
            cell(f(&m.ratios)),
            PAPER_TABLE2[k][1]
        ));
    }
    out.push_str(&format!(
        "\nTable 3 ({mode}), fraction of plans (ours / paper):\n\n\
         | plans | real w/o | real w/ | sim w/o | sim w/ |\n|---|---|---|---|---|\n"
    ));
    let rows: [Row<Fractions>; 3] = [
        ("Optimal", |f| f.optimal),
        ("Sub-optimal", |f| f.suboptimal),
        ("Incorrect", |f| f.incorrect),
    ];
    for (k, (name, f)) in rows.iter().enumerate() {
        let cols = [&r.without, &r.with, &m.without, &m.with];
        let cells: Vec<String> = cols
            .iter()
            .enumerate()
            .map(|(c, fr)| format!("{} / {}", cell(f(fr)), PAPER_TABLE3[k][c]))
            .collect();
        out.push_str(&format!("| {name} | {} |\n", cells.join(" | ")));
    }
    out.push('\n');
}

/// The markdown section.
pub fn markdown(s: &Summary) -> String {
    let mut out = String::from("## H2: plan quality (Tables 2 and 3)\n\n");
    out.push_str(
        "Each (scene, goal) pair is planned without the learned axioms (`learner` profile) and \
         with the axioms one H1 run learned (DOMAIN.md 7.2); plans are classified against \
         KB_full (4.3). The authors' fixed-horizon mode first, then our iterative planner, which \
         by construction returns only minimal plans.\n\n",
    );
    tables(&mut out, s, "fixed horizon", |p| &p.fixed);
    tables(&mut out, s, "iterative planner", |p| &p.iterative);
    out.push_str("![H2 plan quality](h2_quality.svg)\n\n![H2 planning time](h2_time.svg)\n\n");
    out
}

/// The plots: fractions of plans per preset, condition and mode; planning time by scene size.
pub fn plots(s: &Summary) -> Vec<(String, String)> {
    let mut bars = Vec::new();
    for (preset, p) in [("real", &s.real), ("sim", &s.simulated)] {
        for (mode, m) in [("fixed", &p.fixed), ("iter", &p.iterative)] {
            for (cond, f) in [("w/o", &m.without), ("w/", &m.with)] {
                let parts = match (f.optimal, f.suboptimal, f.incorrect) {
                    (Some(a), Some(b), Some(c)) => Some(vec![a, b, c]),
                    _ => None,
                };
                bars.push((format!("{preset} {mode} {cond}"), parts));
            }
        }
    }
    let quality = svg::stacked_chart(&svg::Stacks {
        title: "H2: fraction of plans (optimal, sub-optimal, incorrect)".into(),
        parts: vec!["optimal".into(), "sub-optimal".into(), "incorrect".into()],
        bars,
        y_max: 1.0,
    });
    let time = svg::scatter(&svg::Scatter {
        title: "H2: planning time against scene size (iterative planner)".into(),
        x_label: "objects in the scene".into(),
        y_label: "seconds".into(),
        series: vec![
            ("without learned axioms".into(), s.time_by_size[0].clone()),
            ("with learned axioms".into(), s.time_by_size[1].clone()),
        ],
    });
    vec![
        ("h2_quality.svg".into(), quality),
        ("h2_time.svg".into(), time),
    ]
}

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
