//! `lucent plan FILE.ald [--scene S] [--goal G] [--all] [--max-horizon H] [--fixed N]
//! [--search S] [--check] [--profile P] [-c name=value] [--outf=2]`: the planner of
//! [`crate::plan`] on an AL_d planning problem. FILE is a whole problem (description, initial
//! state and goal) or, with `--scene`, a domain to which the scene's objects and initial state
//! are added: a simulator scene (`.json`, feature `sim`) or facts in the domain's vocabulary
//! (`domains/ra/README.md`, "Scenes as facts"). `--goal` gives the goal as AL_d literals
//! (`on(a, b)`) or in controlled English ("put the pitcher on the red block"). Output: the
//! minimal plan (all distinct minimal plans with `--all`) as text or, with `--outf=2`, JSON
//! `{"plans": [["pickup(rob1,a)", ...]], "length": N, "cr_applied": N, "time": {..}, ..}`.
//!
//! Invariants: files are read here only; bad input (a malformed file, scene or goal, an
//! unknown object) is reported with positions and exit code 65; no plan within the horizon
//! budget and an inconsistent or unstable initial scene are a message and exit 20 (clingo's
//! code for unsatisfiable); a plan found is exit 0.

use std::io::Write;
use std::time::Instant;

use crate::action;
use crate::base::{Diagnostics, SourceMap};
use crate::plan::{plan, PlanConfig, PlanError, Search};

use super::options::{self, opt, Arg, Arity::*, OptionSpec, Verb};

/// `lucent plan`'s command line; `--help` is generated from it.
pub(super) const VERB: Verb = Verb {
    usage: "\
usage: lucent plan FILE.ald [--scene FILE] [--goal GOAL] [--all] [--max-horizon H] [--fixed N]
                   [--search incremental|retranslate] [--check] [--profile NAME]
                   [-c NAME=VALUE]... [--outf=2]

Finds a minimal plan for the goal of an AL_d planning problem (docs/domain.md 4.1-4.2): horizons
0, 1, ..., H are tried in turn (default H = max(9, 2 * objects + 2)) on one multi-shot solver;
plans are ordered by length, then by CR rule applications.
",
    options: OPTIONS,
    epilogue: "",
};

/// The options of `lucent plan`.
#[rustfmt::skip]
const OPTIONS: &[OptionSpec] = &[
    options::HELP,
    opt("scene", None, Value, "FILE", "the objects and initial state: a simulator scene (.json) or facts such as object(a). has_size(a, small). on(a, b). (domains/ra/README.md); FILE is then the domain (e.g. domains/ra/kb_full.ald)", "Options"),
    opt("goal", None, Value, "GOAL", "the goal as AL_d literals (\"on(a, b), in_hand(rob1, c)\") or in controlled English (\"put the pitcher on the red block\"); replaces FILE's goal", "Options"),
    opt("all", None, Flag, "", "print every distinct minimal plan", "Options"),
    opt("max-horizon", None, Value, "H", "the largest horizon tried (default max(9, 2 * objects + 2))", "Options"),
    opt("fixed", None, Value, "N", "the authors' fixed horizon N: every plan reaching the goal by step N", "Options"),
    opt("search", None, Value, "S", "incremental (default: one multi-shot solver) or retranslate (each horizon translated and grounded afresh)", "Options"),
    opt("check", None, Flag, "", "classify each printed plan (optimal, sub-optimal, incorrect; docs/domain.md 4.3)", "Options"),
    opt("profile", None, Value, "NAME", "the description's profile (a switch bundle it declares)", "Options"),
    opt("const", Some('c'), Value, "NAME=VALUE", "set a switch of the description (e.g. -c horizon=3); may be repeated", "Options"),
    opt("outf", None, Value, "N", "0: text (default); 2: JSON", "Options"),
    opt("emit-problem", None, Flag, "", "print the problem (FILE with the scene and goal added) as one AL_d file", "Options"),
];

/// Exit code when there is no plan (clingo's code for unsatisfiable).
const EXIT_NO_PLAN: i32 = 20;

/// Parsed options of `lucent plan`.
#[derive(Default)]
struct Args {
    file: Option<String>,
    scene: Option<String>,
    goal: Option<String>,
    all: bool,
    json: bool,
    check: bool,
    emit: bool,
    max_horizon: Option<usize>,
    config: PlanConfig,
}

/// Reads the command line.
fn parse(args: &[String]) -> Result<Args, String> {
    let mut a = Args::default();
    for arg in options::scan(OPTIONS, args) {
        let (spec, v) = match arg.map_err(|e| e.to_string())? {
            Arg::Option(spec, v) => (spec, v.unwrap_or_default()),
            Arg::Word(w) | Arg::Literal(w) if a.file.is_none() => {
                a.file = Some(w);
                continue;
            }
            Arg::Word(_) | Arg::Literal(_) => return Err("`lucent plan` takes one file".into()),
        };
        match spec.long {
            "all" => a.all = true,
            "check" => a.check = true,
            "emit-problem" => a.emit = true,
            "outf" => a.json = spec.outf(&v)?,
            "max-horizon" => a.max_horizon = Some(spec.number(&v)?),
            "fixed" => a.config.search = Search::Fixed(spec.number(&v)?),
            "search" => {
                a.config.search = Search::from_name(&v)
                    .ok_or_else(|| format!("'--search {v}': expected incremental or retranslate"))?
            }
            "scene" => a.scene = Some(v),
            "goal" => a.goal = Some(v),
            "profile" => a.config.profile = Some(v),
            "const" => {
                let (name, value) = spec.assignment(&v)?;
                a.config
                    .overrides
                    .push((name, super::action::value_of(&value)));
            }
            _ => {} // --help, answered before parsing
        }
    }
    if a.file.is_none() {
        return Err("`lucent plan` needs a file (try --help)".into());
    }
    Ok(a)
}

/// The scene file's facts: a simulator scene (`.json`) or facts.
fn scene_facts(
    sources: &mut SourceMap,
    name: &str,
    text: String,
) -> Result<crate::plan::SceneFacts, String> {
    if name.ends_with(".json") {
        #[cfg(feature = "sim")]
        {
            return crate::sim::Scene::from_json(&text)
                .map(|s| crate::plan::SceneFacts::from_sim(&s))
                .map_err(|e| format!("{name}: {e}"));
        }
        #[cfg(not(feature = "sim"))]
        return Err(format!("{name}: simulator scenes need the `sim` feature"));
    }
    let file = sources.add(name.to_string(), text.clone());
    crate::plan::SceneFacts::parse(file, &text).map_err(|errors| {
        let mut d = Diagnostics::default();
        d.extend(errors);
        d.render(sources)
    })
}

/// The goal as an AL_d statement: literals, or controlled English over the scene's objects.
fn goal_statement(
    goal: &str,
    desc: &action::ast::Description,
) -> Result<action::ast::Statement, String> {
    if let Some(g) = crate::plan::goal_statement(goal) {
        return Ok(g);
    }
    let lexicon = crate::explain::lexicon::Lexicon::ra();
    let checked = action::check(desc, &action::Options::default());
    let objects: Vec<&str> = ["movable", "object"]
        .iter()
        .find_map(|s| checked.sorts.get(*s))
        .map(|s| {
            s.members
                .iter()
                .filter_map(|m| match m {
                    action::check::Member::Sym(n) => Some(n.as_str()),
                    action::check::Member::Int(_) => None,
                })
                .collect()
        })
        .unwrap_or_default();
    let parser = crate::explain::english::Parser::new(&lexicon, &objects);
    match parser.parse(goal) {
        Ok(crate::explain::english::Question::Goal { literals }) => Ok(action::build::goal(
            literals.iter().map(crate::plan::problem::ald_lit).collect(),
        )),
        Ok(q) => Err(format!("`{goal}` is a {} question, not a goal", q.kind())),
        Err(e) => Err(format!("`{goal}`: {}", parser.reply(&e))),
    }
}

/// `lucent plan`.
pub fn run_plan(args: &[String], out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<i32> {
    let a = match super::verb_args(&VERB, args, parse, out, err)? {
        Ok(a) => a,
        Err(code) => return Ok(code),
    };
    let name = a.file.clone().unwrap_or_default();
    let bad = |err: &mut dyn Write, m: &str| -> std::io::Result<i32> {
        if !m.is_empty() {
            writeln!(err, "{}", m.trim_end())?;
        }
        writeln!(
            err,
            "*** ERROR: (lucent): {name}: not a valid AL_d planning problem"
        )?;
        Ok(super::EXIT_INPUT)
    };
    let text = match super::builtin::read_to_string(&name) {
        Ok(t) => t,
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {name}: {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    let mut sources = SourceMap::new();
    let id = sources.add(name.clone(), text);
    let mut read =
        |path: &std::path::Path| super::builtin::read_to_string(path).map_err(|e| e.to_string());
    let parsed = action::load(&mut sources, id, &mut read);
    if parsed.has_errors() {
        let mut d = Diagnostics::default();
        d.extend(parsed.diagnostics);
        return bad(err, &d.render(&sources));
    }
    let mut desc = parsed.description;
    // What the scene and the goal added, as AL_d text for `--emit`.
    let mut added: Vec<(String, String)> = Vec::new();
    if let Some(scene) = &a.scene {
        let text = match super::builtin::read_to_string(scene) {
            Ok(t) => t,
            Err(e) => {
                writeln!(err, "*** ERROR: (lucent): {scene}: {e}")?;
                return Ok(super::EXIT_INPUT);
            }
        };
        let facts = match scene_facts(&mut sources, scene, text) {
            Ok(t) => t,
            Err(m) => return bad(err, &m),
        };
        desc.statements.extend(facts.statements());
        added.push((format!("<scene {scene}>"), facts.to_ald()));
    }
    if let Some(goal) = &a.goal {
        let statement = match goal_statement(goal, &desc) {
            Ok(s) => s,
            Err(m) => return bad(err, &format!("*** ERROR: (lucent): goal {m}")),
        };
        desc.statements
            .retain(|s| !matches!(s.kind, action::ast::StatementKind::Goal { .. }));
        let shown = action::translate::show_statement(&statement.kind);
        added.push(("<goal>".to_string(), format!("{shown}.\n")));
        desc.statements.push(statement);
    }
    if a.emit {
        let path = std::fs::canonicalize(&name).unwrap_or_else(|_| name.clone().into());
        writeln!(out, "include \"{}\".", path.display())?;
        for (name, text) in &added {
            writeln!(out, "% {name}\n{text}")?;
        }
        return Ok(0);
    }
    let mut config = a.config.clone();
    config.all = a.all || matches!(config.search, Search::Fixed(_));
    config.max_horizon = a
        .max_horizon
        .unwrap_or_else(|| crate::plan::default_max_horizon(&desc, &config));
    let start = Instant::now();
    let result = plan(&desc, &sources, &config);
    let seconds = start.elapsed().as_secs_f64();
    match result {
        Ok(found) => {
            let shown = if a.all {
                &found.plans[..]
            } else {
                &found.plans[..1]
            };
            let verdicts: Vec<Option<crate::plan::Verdict>> = shown
                .iter()
                .map(|p| {
                    a.check.then(|| {
                        crate::plan::classify(&desc, &sources, &config, &p.actions, 200_000).ok()
                    })?
                })
                .collect();
            if a.json {
                let plans: Vec<Vec<String>> = shown
                    .iter()
                    .map(|p| p.actions.iter().map(|a| a.to_string()).collect())
                    .collect();
                let mut value = serde_json::json!({
                    "plans": plans,
                    "length": found.length,
                    "cr_applied": found.cr_applied,
                    "cr_rules": shown.iter().map(|p| p.cr_applied.iter().map(|c| c.to_string()).collect::<Vec<_>>()).collect::<Vec<_>>(),
                    "minimal_plans": found.plans.len(),
                    "answer_sets": found.answer_sets,
                    "horizons_tried": found.horizons_tried,
                    "max_horizon": config.max_horizon,
                    "search": match config.search { Search::Incremental => "incremental".to_string(), Search::Retranslate => "retranslate".to_string(), Search::Fixed(n) => format!("fixed({n})") },
                    "time": { "total": seconds },
                });
                if a.check {
                    value["check"] = verdicts
                        .iter()
                        .map(|v| match v {
                            Some(v) => serde_json::json!({
                                "quality": v.quality.name(),
                                "minimal_length": v.minimal.map(|m| m.0),
                                "minimal_cr": v.minimal.map(|m| m.1),
                                "reason": v.reason,
                            }),
                            None => serde_json::Value::Null,
                        })
                        .collect();
                }
                writeln!(out, "{value}")?;
            } else {
                for (p, v) in shown.iter().zip(&verdicts) {
                    writeln!(out, "Plan: {}", p.to_text())?;
                    if !p.cr_applied.is_empty() {
                        let cr: Vec<String> = p.cr_applied.iter().map(|c| c.to_string()).collect();
                        writeln!(out, "  CR rules: {}", cr.join(" "))?;
                    }
                    if let Some(v) = v {
                        writeln!(
                            out,
                            "  Check: {}{}",
                            v.quality.name(),
                            v.reason
                                .as_ref()
                                .map(|r| format!(" ({r})"))
                                .unwrap_or_default()
                        )?;
                    }
                }
                writeln!(out, "Length: {}", found.length)?;
                writeln!(out, "CR applied: {}", found.cr_applied)?;
                writeln!(
                    out,
                    "Plans: {} of {} minimal",
                    shown.len(),
                    found.plans.len()
                )?;
                writeln!(out, "Time: {seconds:.3}s")?;
            }
            Ok(0)
        }
        Err(PlanError::Input(m)) => bad(err, &m),
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {name}: {e}")?;
            Ok(EXIT_NO_PLAN)
        }
    }
}
