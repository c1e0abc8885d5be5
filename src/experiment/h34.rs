//! H3, proof-tree checks, and H4, explanation precision and recall (docs/domain.md 7.5, the paper's
//! Tables 4 and 5). A trial is one (scene, goal) pair of a preset, the same pair as H2's trial
//! with that id (`h2::pair`: configuration `index / goals`, goal `index mod goals`, so the
//! paper's 20 configurations with 5 goals each, shared by H2, H3 and H4), planned under KB_full
//! and executed as a history (`explain::history`); the trial's seed draws the questions.
//! - H3 asks the questions and beliefs of `explain::h3::check_history` over that history and
//!   counts what the checks of 7.5 find (re-check, repeats on a path, leaf kinds).
//! - H4 draws the four questions of 7.5 over KB_full's history (the first four
//!   `check_history` asks), takes KB_full's full-mode answers as the truth (6.9: "generated in
//!   full mode from KB_full"), and asks the same questions over the learner profile's own run
//!   (without) and over the learner profile plus the axioms H1 run `configuration mod runs`
//!   learned, as in H2
//!   (with: `RunResult::ald`), scoring each answer's literals against the truth.
//!
//! Invariants: H4's precision and recall are averaged per question type (6.9), per preset and
//! condition, over the questions asked; H3 reports counts, and a failure is listed by trial, so
//! a reader can open it. The domain is read from the context (`cli` loaded it), never from a
//! file; a scene KB_full cannot plan within the budget is counted, not failed.

use std::collections::BTreeSet;

use serde::{Deserialize, Serialize};

use super::interval::{self, Interval};
use super::svg;
use super::{Context, Hypothesis, Record, Trial, TrialError};
use crate::action::ast::Description;
use crate::base::SourceMap;
use crate::control::Symbol;
use crate::explain::english::Question;
use crate::explain::h3::{check_history, ScenePreset};
use crate::explain::history::{explain_history, History, HistoryConfig};
use crate::explain::lexicon::Lexicon;
use crate::explain::questions::{answer, Mode, Session};
use crate::plan::{plan, PlanConfig, PlanError};

/// Why H3 or H4 cannot run in this build, if it cannot (both can).
pub fn availability(_h: Hypothesis) -> Result<(), String> {
    Ok(())
}

/// The planner's horizon budget for the generated scenes (docs/domain.md 7.1 scenes
/// need at most 8).
const MAX_HORIZON: usize = 10;

/// The scene of a trial, loaded against the domain: H2's (scene, goal) pair with the trial's
/// index (`h2::pair`) as a problem over the domain, which is read from the context, never from
/// a file.
fn load_scene(
    ctx: &Context,
    preset: ScenePreset,
    trial: &Trial,
) -> Result<(Description, SourceMap), TrialError> {
    let goals = ctx.setup.goals.max(1);
    let scene = super::h2::pair(
        preset,
        ctx.setup.seed,
        trial.index / goals,
        trial.index % goals,
    );
    let problem = ctx.domain.scene_problem(&scene)?;
    Ok((problem.description(), problem.sources))
}

/// A planned and executed history under a profile (`None`: KB_full): the planner's first
/// minimal plan; when the profile finds none within the budget, the robot did nothing (the
/// history is the initial state alone). `Ok(None)` when KB_full itself has no plan.
fn run_history(
    desc: &Description,
    sources: &SourceMap,
    profile: Option<&str>,
) -> Result<Option<History>, TrialError> {
    // The learner profile turns the planning module off; the planner turns it on.
    let config = PlanConfig {
        max_horizon: MAX_HORIZON,
        profile: profile.map(str::to_string),
        ..PlanConfig::default()
    };
    let actions = match plan(desc, sources, &config) {
        Ok(found) => found.plans[0].actions.clone(),
        Err(PlanError::NoPlanWithin(_)) if profile.is_none() => return Ok(None),
        Err(PlanError::Input(m)) => return Err(TrialError::Input(m)),
        Err(_) if profile.is_some() => Vec::new(),
        Err(e) => return Err(TrialError::Input(e.to_string())),
    };
    let hconfig = HistoryConfig {
        profile: profile.map(str::to_string),
        ..HistoryConfig::default()
    };
    let mut sources = sources.clone();
    match explain_history(desc, &mut sources, &actions, &hconfig) {
        Ok(h) => Ok(Some(h)),
        Err(e) => Err(TrialError::Input(format!("history: {e}"))),
    }
}

fn preset_of(trial: &Trial) -> Result<ScenePreset, TrialError> {
    match trial.config.as_str() {
        "real" => Ok(ScenePreset::Real),
        "simulated" => Ok(ScenePreset::Simulated),
        other => Err(TrialError::Input(format!("unknown preset '{other}'"))),
    }
}

/// Runs one trial of H3 or H4.
pub fn run_trial(
    ctx: &Context,
    h: Hypothesis,
    trial: &Trial,
    seed: u64,
) -> Result<serde_json::Value, TrialError> {
    let preset = preset_of(trial)?;
    let (desc, sources) = load_scene(ctx, preset, trial)?;
    let full = run_history(&desc, &sources, None)?;
    let value = match h {
        Hypothesis::H3 => serde_json::to_value(h3_trial(trial, full.as_ref(), seed)),
        _ => serde_json::to_value(h4_trial(ctx, trial, &desc, &sources, full.as_ref(), seed)?),
    };
    value.map_err(|e| TrialError::Store(e.to_string()))
}

/// H3: the questions and beliefs of `h3::check_history` over KB_full's history, every proof
/// tree checked.
fn h3_trial(trial: &Trial, full: Option<&History>, seed: u64) -> H3Trial {
    let mut t = H3Trial {
        preset: trial.config.clone(),
        ..H3Trial::default()
    };
    let Some(h) = full else {
        t.no_plan = 1;
        return t;
    };
    let report = check_history(&h.scenario(), &h.objects(), seed);
    t.trees = report.trees;
    // `check_tree` names the check that failed first in its message.
    let count = |needle: &str| {
        report
            .failures
            .iter()
            .filter(|f| f.contains(needle))
            .count()
    };
    t.rechecked = report.trees - count("recheck:");
    t.repeats = count("repeats on a path");
    t.bad_leaves = count("not one of docs/domain.md 6.2");
    t.failures = report.failures;
    t
}

/// The answer literals of `questions` asked in order (one session) over a history, converse
/// relations canonicalized (docs/domain.md 6.9); an answer that fails is the empty set.
fn literal_sets(h: &History, questions: &[Question]) -> Vec<BTreeSet<String>> {
    let lexicon = Lexicon::ra();
    let scn = h.scenario();
    let mut session = Session::default();
    questions
        .iter()
        .map(
            |q| match answer(&scn, &lexicon, q, Mode::Full, &mut session) {
                Ok(a) => a.literals.iter().map(canonical).collect(),
                Err(_) => BTreeSet::new(),
            },
        )
        .collect()
}

/// H4: the four questions of docs/domain.md 7.5 (those `h3::check_history` asks first: the plan,
/// why X for a random plan action, why not X with one argument changed, a related belief) drawn
/// over KB_full's history; the truth is KB_full's full-mode answer (6.9); the same questions
/// are asked over the learner profile's own history (without) and over the learner profile
/// plus the axioms H1 run `configuration mod runs` learned (with), and each answer scored.
fn h4_trial(
    ctx: &Context,
    trial: &Trial,
    desc: &Description,
    sources: &SourceMap,
    full: Option<&History>,
    seed: u64,
) -> Result<H4Trial, TrialError> {
    let mut t = H4Trial {
        preset: trial.config.clone(),
        without: Vec::new(),
        with: Vec::new(),
        without_one: Vec::new(),
        removed: None,
    };
    let Some(full) = full else {
        return Ok(t);
    };
    let report = check_history(&full.scenario(), &full.objects(), seed);
    let questions: Vec<Question> = report.asked.into_iter().take(4).collect();
    let truth = literal_sets(full, &questions);
    let run = (trial.index / ctx.setup.goals.max(1)) % ctx.setup.runs.max(1);
    let learned = super::h1::learned_statements(ctx, run)?;
    // Reading "one axiom missing" (7.2): the learner profile plus four of the five targets,
    // the missing one drawn from the trial's seed.
    let k = crate::base::rng::SplitMix64::new(seed)
        .fork(0x4f4e_4500)
        .below(super::h2::TARGETS.len() as u64) as usize;
    t.removed = Some(super::h2::TARGETS[k].to_string());
    for condition in 0..3 {
        let mut d = desc.clone();
        let s = sources.clone();
        match condition {
            1 => d.statements.extend(learned.iter().cloned()),
            2 => d.statements.extend(super::h2::targets_but(k)),
            _ => {}
        }
        let Some(h) = run_history(&d, &s, Some("learner"))? else {
            continue;
        };
        let got = literal_sets(&h, &questions);
        let scores = questions
            .iter()
            .zip(got.iter().zip(&truth))
            .map(|(q, (a, t))| {
                let (p, r) = score(a, t);
                QuestionScore {
                    kind: q.kind().to_string(),
                    question: q.to_string(),
                    precision: 100.0 * p,
                    recall: 100.0 * r,
                }
            })
            .collect();
        match condition {
            0 => t.without = scores,
            1 => t.with = scores,
            _ => t.without_one = scores,
        }
    }
    Ok(t)
}

/// The converse-canonical text of a literal (docs/domain.md 6.9): inside `holds`,
/// `relation(below,A,B)` is `relation(above,B,A)`, `behind` is `front` and `right` is `left`.
pub fn canonical(t: &Symbol) -> String {
    let flip = |f: &Symbol| -> Symbol {
        if let (Some("relation"), [rel, a, b]) = (f.name(), f.args()) {
            let to = match rel.name() {
                Some("below") => Some("above"),
                Some("behind") => Some("front"),
                Some("right") => Some("left"),
                _ => None,
            };
            if let Some(to) = to {
                return Symbol::function(
                    "relation",
                    vec![Symbol::constant(to), b.clone(), a.clone()],
                );
            }
        }
        f.clone()
    };
    match (t.name(), t.args()) {
        (Some("holds"), [f, i]) => {
            let h = Symbol::function("holds", vec![flip(f), i.clone()]);
            if t.is_negative() {
                h.complement().unwrap_or(h)
            } else {
                h
            }
            .to_string()
        }
        _ => t.to_string(),
    }
}

/// Precision and recall of an answer's literals against the truth (docs/domain.md 6.9): an empty
/// answer has precision 1 when the truth is empty too, else 0; an empty truth has recall 1.
pub fn score(answer: &BTreeSet<String>, truth: &BTreeSet<String>) -> (f64, f64) {
    let hit = answer.intersection(truth).count() as f64;
    let p = match (answer.is_empty(), truth.is_empty()) {
        (true, true) => 1.0,
        (true, false) => 0.0,
        _ => hit / answer.len() as f64,
    };
    let r = if truth.is_empty() {
        1.0
    } else {
        hit / truth.len() as f64
    };
    (p, r)
}

/// The four question types of docs/domain.md 6.3-6.6, in the tables' order.
pub const QUERY_TYPES: [&str; 4] = ["plan", "why", "why_not", "belief"];

/// The rows' names in the paper.
const QUERY_NAMES: [&str; 4] = ["Plan description", "Why X?", "Why not X?", "Belief"];

/// One scored answer.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct QuestionScore {
    /// One of [`QUERY_TYPES`].
    pub kind: String,
    /// The question asked.
    pub question: String,
    /// Literal precision, %.
    pub precision: f64,
    /// Literal recall, %.
    pub recall: f64,
}

/// One H4 trial.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct H4Trial {
    /// The preset.
    pub preset: String,
    /// Answers without the learned axioms.
    pub without: Vec<QuestionScore>,
    /// Answers with them.
    pub with: Vec<QuestionScore>,
    /// Reading "one axiom missing": answers without the target `removed` only (empty in
    /// results stored before).
    #[serde(default)]
    pub without_one: Vec<QuestionScore>,
    /// The target missing in `without_one`.
    #[serde(default)]
    pub removed: Option<String>,
}

/// One H3 trial.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct H3Trial {
    /// The preset.
    pub preset: String,
    /// Proof trees built.
    pub trees: usize,
    /// Trees that passed the independent re-check.
    pub rechecked: usize,
    /// Trees with a literal repeated on a path.
    pub repeats: usize,
    /// Trees with a leaf of a kind docs/domain.md 6.2 does not list.
    pub bad_leaves: usize,
    /// Trials whose scene KB_full cannot plan within the horizon budget (no trees).
    #[serde(default)]
    pub no_plan: usize,
    /// What failed, one line each.
    pub failures: Vec<String>,
}

/// H4 figures for one preset and condition: (precision, recall, questions) per query type.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct H4Column {
    /// Per query type of [`QUERY_TYPES`]: mean precision and recall (%), and the count.
    pub rows: Vec<(String, Option<f64>, Option<f64>, usize)>,
    /// Per query type: the 95% intervals of precision and recall (bootstrap over the
    /// questions, one per trial and type).
    pub intervals: Vec<(Option<Interval>, Option<Interval>)>,
}

/// H4's tables.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct H4Summary {
    /// Real scenes, without and with the learned axioms.
    pub real: [H4Column; 2],
    /// Simulated scenes, without and with.
    pub simulated: [H4Column; 2],
    /// Reading "one axiom missing" (without only): real, simulated.
    pub one_missing: [H4Column; 2],
}

/// H3's totals per preset.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct H3Summary {
    /// Per preset: its name and the summed counts (failures listed by trial id).
    pub presets: Vec<H3Trial>,
}

/// The paper's Tables 4 (real) and 5 (simulated): per query type, P w/o, P w/, R w/o, R w/.
pub const PAPER_H4: [[[f64; 4]; 4]; 2] = [
    [
        [74.94, 100.0, 63.25, 100.0],
        [72.22, 94.0, 65.0, 94.0],
        [100.0, 95.92, 68.89, 100.0],
        [95.74, 100.0, 95.74, 100.0],
    ],
    [
        [71.85, 100.0, 59.39, 100.0],
        [66.48, 95.0, 58.5, 95.0],
        [86.79, 95.24, 63.01, 100.0],
        [94.55, 100.0, 91.23, 100.0],
    ],
];

fn mean(v: &[f64]) -> Option<f64> {
    (!v.is_empty()).then(|| v.iter().sum::<f64>() / v.len() as f64)
}

fn column(scores: &[&QuestionScore]) -> H4Column {
    H4Column {
        intervals: QUERY_TYPES
            .iter()
            .map(|k| {
                let of = scores.iter().filter(|s| s.kind == *k);
                let p: Vec<f64> = of.clone().map(|s| s.precision).collect();
                let r: Vec<f64> = of.map(|s| s.recall).collect();
                (interval::mean(&p), interval::mean(&r))
            })
            .collect(),
        rows: QUERY_TYPES
            .iter()
            .map(|k| {
                let of: Vec<&&QuestionScore> = scores.iter().filter(|s| s.kind == *k).collect();
                let p: Vec<f64> = of.iter().map(|s| s.precision).collect();
                let r: Vec<f64> = of.iter().map(|s| s.recall).collect();
                (k.to_string(), mean(&p), mean(&r), of.len())
            })
            .collect(),
    }
}

/// Aggregates the H4 records.
pub fn aggregate_h4(records: &[Record]) -> Result<H4Summary, String> {
    let mut trials = Vec::new();
    for r in records.iter().filter(|r| r.id.starts_with("h4-")) {
        let t: H4Trial =
            serde_json::from_value(r.result.clone()).map_err(|e| format!("{}: {e}", r.id))?;
        trials.push(t);
    }
    let of = |preset: &str, condition: usize| {
        let scores: Vec<&QuestionScore> = trials
            .iter()
            .filter(|t| t.preset == preset)
            .flat_map(|t| match condition {
                0 => &t.without,
                1 => &t.with,
                _ => &t.without_one,
            })
            .collect();
        column(&scores)
    };
    Ok(H4Summary {
        real: [of("real", 0), of("real", 1)],
        simulated: [of("simulated", 0), of("simulated", 1)],
        one_missing: [of("real", 2), of("simulated", 2)],
    })
}

/// Aggregates the H3 records.
pub fn aggregate_h3(records: &[Record]) -> Result<H3Summary, String> {
    let mut presets: Vec<H3Trial> = super::PRESETS
        .iter()
        .map(|p| H3Trial {
            preset: p.to_string(),
            ..Default::default()
        })
        .collect();
    for r in records.iter().filter(|r| r.id.starts_with("h3-")) {
        let t: H3Trial =
            serde_json::from_value(r.result.clone()).map_err(|e| format!("{}: {e}", r.id))?;
        let Some(sum) = presets.iter_mut().find(|p| p.preset == t.preset) else {
            return Err(format!("{}: unknown preset '{}'", r.id, t.preset));
        };
        sum.trees += t.trees;
        sum.rechecked += t.rechecked;
        sum.repeats += t.repeats;
        sum.bad_leaves += t.bad_leaves;
        sum.no_plan += t.no_plan;
        sum.failures
            .extend(t.failures.iter().map(|f| format!("{}: {f}", r.id)));
    }
    Ok(H3Summary { presets })
}

/// The H3 markdown section.
pub fn markdown_h3(s: &H3Summary) -> String {
    let mut out = String::from("## H3: belief tracing (proof-tree checks)\n\n");
    out.push_str(
        "The paper shows H3 through its execution traces; our checks (docs/domain.md 7.5): every \
         tree passes the independent re-check, no literal repeats on a path, every leaf is of a \
         kind 6.2 lists.\n\n| preset | trees | re-check passed | repeats on a path | bad leaves | scenes without a plan |\n|---|---|---|---|---|---|\n",
    );
    for p in &s.presets {
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} |\n",
            p.preset, p.trees, p.rechecked, p.repeats, p.bad_leaves, p.no_plan
        ));
    }
    let failures: Vec<&String> = s.presets.iter().flat_map(|p| &p.failures).collect();
    if !failures.is_empty() {
        out.push_str("\nFailures:\n\n");
        for f in failures {
            out.push_str(&format!("- {f}\n"));
        }
    }
    out.push('\n');
    out
}

/// The H4 markdown section.
pub fn markdown_h4(s: &H4Summary) -> String {
    let mut out = String::from("## H4: explanation accuracy (Tables 4 and 5)\n\n");
    out.push_str(
        "Literal precision and recall in % (docs/domain.md 6.9), averaged per question type, \
         without (w/o) and with (w/) the learned axioms; each cell ours / paper.\n\n",
    );
    for (t, (name, cols)) in [("real", &s.real), ("simulated", &s.simulated)]
        .iter()
        .enumerate()
    {
        out.push_str(&format!(
            "Table {} ({name} scenes):\n\n| query | P w/o | P w/ | R w/o | R w/ | questions |\n|---|---|---|---|---|---|\n",
            4 + t
        ));
        for (q, qname) in QUERY_NAMES.iter().enumerate() {
            let (wo, w) = (&cols[0].rows[q], &cols[1].rows[q]);
            let (wo_i, w_i) = (cols[0].intervals[q], cols[1].intervals[q]);
            let paper = PAPER_H4[t][q];
            out.push_str(&format!(
                "| {qname} | {} / {} | {} / {} | {} / {} | {} / {} | {} |\n",
                interval::cell(wo.1, wo_i.0, 1),
                paper[0],
                interval::cell(w.1, w_i.0, 1),
                paper[1],
                interval::cell(wo.2, wo_i.1, 1),
                paper[2],
                interval::cell(w.2, w_i.1, 1),
                paper[3],
                wo.3 + w.3
            ));
        }
        out.push('\n');
    }
    out.push_str(
        "Readings of the knowledge base \"without\" (docs/domain.md 7.2): *all five missing* \
         (the tables above) or *one missing*, the `learner` profile plus four of the five targets, \
         the missing one drawn per trial from its seed. Precision and recall without the axioms, \
         %:\n\n| preset | query | P all five | P one | P paper | R all five | R one | R paper |\n\
         |---|---|---|---|---|---|---|---|\n",
    );
    for (t, (name, cols, one)) in [
        ("real", &s.real, &s.one_missing[0]),
        ("simulated", &s.simulated, &s.one_missing[1]),
    ]
    .iter()
    .enumerate()
    {
        for (q, qname) in QUERY_NAMES.iter().enumerate() {
            let (all, all_i) = (&cols[0].rows[q], cols[0].intervals[q]);
            let (o, o_i) = (
                one.rows.get(q).cloned().unwrap_or_default(),
                one.intervals.get(q).copied().unwrap_or((None, None)),
            );
            let paper = PAPER_H4[t][q];
            out.push_str(&format!(
                "| {name} | {qname} | {} | {} | {} | {} | {} | {} |\n",
                interval::cell(all.1, all_i.0, 1),
                interval::cell(o.1, o_i.0, 1),
                paper[0],
                interval::cell(all.2, all_i.1, 1),
                interval::cell(o.2, o_i.1, 1),
                paper[2],
            ));
        }
    }
    out.push('\n');
    out.push_str("![H4 real scenes](h4_real.svg)\n\n![H4 simulated scenes](h4_simulated.svg)\n\n");
    out
}

/// The H4 plots: per preset, precision and recall per query type, ours and the paper's.
pub fn plots_h4(s: &H4Summary) -> Vec<(String, String)> {
    [("real", &s.real), ("simulated", &s.simulated)]
        .iter()
        .enumerate()
        .map(|(t, (name, cols))| {
            let mut groups = Vec::new();
            let mut errors = Vec::new();
            for (q, qname) in QUERY_NAMES.iter().enumerate() {
                let paper = PAPER_H4[t][q];
                errors.push(vec![cols[0].intervals[q].0, cols[1].intervals[q].0]);
                errors.push(vec![cols[0].intervals[q].1, cols[1].intervals[q].1]);
                groups.push((
                    format!("{qname} P"),
                    vec![
                        cols[0].rows[q].1,
                        cols[1].rows[q].1,
                        Some(paper[0]),
                        Some(paper[1]),
                    ],
                ));
                groups.push((
                    format!("{qname} R"),
                    vec![
                        cols[0].rows[q].2,
                        cols[1].rows[q].2,
                        Some(paper[2]),
                        Some(paper[3]),
                    ],
                ));
            }
            let svg = svg::bar_chart(&svg::Bars {
                title: format!("H4 ({name} scenes): literal precision and recall (%)"),
                series: vec![
                    "ours w/o".into(),
                    "ours w/".into(),
                    "paper w/o".into(),
                    "paper w/".into(),
                ],
                groups,
                errors,
                y_max: 100.0,
            });
            (format!("h4_{name}.svg"), svg)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn h4_averages_per_query_type_preset_and_condition() {
        let q = |kind: &str, p: f64, r: f64| QuestionScore {
            kind: kind.into(),
            question: String::new(),
            precision: p,
            recall: r,
        };
        let trials = [
            H4Trial {
                preset: "real".into(),
                without: vec![q("plan", 50.0, 100.0), q("why", 0.0, 0.0)],
                with: vec![q("plan", 100.0, 100.0)],
                without_one: vec![],
                removed: None,
            },
            H4Trial {
                preset: "real".into(),
                without: vec![q("plan", 100.0, 50.0)],
                with: vec![],
                without_one: vec![],
                removed: None,
            },
        ];
        let records: Vec<Record> = trials
            .iter()
            .enumerate()
            .map(|(k, t)| Record {
                id: format!("h4-real-{k:04}"),
                setup: super::super::Setup::paper(0),
                trial_seed: 0,
                seconds: 0.0,
                result: serde_json::to_value(t).unwrap(),
            })
            .collect();
        let s = aggregate_h4(&records).unwrap();
        assert_eq!(
            s.real[0].rows[0],
            ("plan".into(), Some(75.0), Some(75.0), 2)
        );
        assert_eq!(s.real[0].rows[1], ("why".into(), Some(0.0), Some(0.0), 1));
        assert_eq!(s.real[0].rows[2].3, 0);
        assert_eq!(
            s.real[1].rows[0],
            ("plan".into(), Some(100.0), Some(100.0), 1)
        );
        assert_eq!(s.simulated[0].rows[0].1, None);
    }
}
