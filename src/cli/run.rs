//! `lucent run`: the sense-plan-act loop of [`crate::plan::act`] in the simulated tabletop
//! world, on a scene file or a generated scene (preset and seed), towards a goal given as
//! literals or drawn at random (docs/domain.md 7.1). A progress line per event goes to standard
//! error (and to `--log FILE`); the summary goes to standard output, as text or, with
//! `--outf=2`, as the run's history in JSON (the `--save-history` format).
//!
//! Invariants: files are read and written and the clock is read only here; a bad command line
//! is exit 1, bad input (an unreadable or malformed scene or domain, a goal naming an unknown
//! object) a message and exit 65, never a panic; a run that reaches the goal (observed, and true
//! in the simulator's ground truth) exits 0, any other ending 20 (clingo's "no answer").

use std::io::Write;
use std::time::Instant;

use crate::action;
use crate::base::SourceMap;
use crate::control::Symbol;
use crate::plan::act::{self, Domain, Event, RunConfig};
use crate::plan::history::History;
use crate::plan::tabletop::{act_config, random_goal, SimWorld};
use crate::sim::{self, ErrorModel, GenerateConfig, Preset, Scene};
use crate::vision::classify::Source;
use crate::vision::dataset::DatasetConfig;
use crate::vision::reason::Knowledge;
use crate::vision::see::{train_seer, Seeing, SeenOcclusion};

use super::demo;
use super::options::{self, opt, Arg, Arity::*, OptionSpec, Verb};
use super::run_report::{self, Filming, Frame, Pictured};
use super::KB_FULL;

/// Exit code of a run that did not reach its goal.
const EXIT_NOT_REACHED: i32 = 20;

/// `lucent run`'s command line; `--help` is generated from it.
pub(super) const VERB: Verb = Verb {
    usage: "\
usage: lucent run [DOMAIN.ald] (--scene FILE.json | --preset NAME --seed N) [--goal LITERAL]...
                  [options]

Runs the sense-plan-act loop (docs/domain.md 4.4) in the simulated tabletop world: perceive (with
noise), doubt what is inconsistent, plan a minimal plan, execute one action at a time in the
physics world, perceive again, compare the prediction with the observation, and replan after a
discrepancy or a failed action, until the goal is observed (and confirmed by a second look) or
a budget runs out. DOMAIN.ald defaults to the built-in KB_full (domains/ra/kb_full.ald).
",
    options: OPTIONS,
    epilogue: demo::ROBOT_EXIT_CODES,
};

/// The options of `lucent run`.
#[rustfmt::skip]
const OPTIONS: &[OptionSpec] = &[
    options::HELP,
    opt("scene", None, Value, "FILE", "a scene file (lucent sim generate -o FILE writes one)", "Options"),
    opt("preset", None, Value, "NAME", "generate a scene: real, simulated or h1 (default real)", "Options"),
    opt("seed", None, Value, "N", "the scene's seed (default 0); it also seeds noise and failures", "Options"),
    demo::GOAL,
    opt("goal-seed", None, Value, "N", "the seed of the drawn goal (default: the scene's seed)", "Options"),
    demo::PERCEPTION_NOISE,
    demo::ACTUATION_NOISE,
    opt("threshold", None, Value, "T", "confidence from which a reading is taken (default 0.5)", "Options"),
    opt("max-actions", None, Value, "N", "action budget (default 24)", "Options"),
    opt("max-plans", None, Value, "N", "planning budget, the first plan included (default 12)", "Options"),
    opt("max-horizon", None, Value, "H", "the planner's horizon budget (default 12)", "Options"),
    opt("looks", None, Value, "N", "looks per perception, fused by majority (default 1)", "Options"),
    opt("see-occlusion", None, Value, "N", "decide occlusion from the camera image: reasoning over each look's percept, and where it cannot decide a network trained at the start on N generated scenes (100 takes about 15 s); its decisions become observations of partially_occluded and are listed in the summary", "Options"),
    opt("no-confirm", None, Flag, "", "stop at the first observation of the goal, without looking again", "Options"),
    opt("log", None, Value, "FILE", "write the progress lines and the summary to FILE", "Options"),
    opt("save-history", None, Value, "FILE", "write the run's history as JSON (domains/ra/README.md)", "Options"),
    opt("report", None, Value, "FILE.html", "write a report of the run to open in a browser: the camera picture after every action, the plans and replans in English with their reasons, the discrepancies, and the robot's answers to a few questions about its run with their proof trees (one file, no network)", "Options"),
    opt("outf", None, Value, "N", "0: the text summary (default); 2: the history as JSON", "Options"),
];

/// The parsed command line.
#[derive(Debug, Default)]
pub struct RunArgs {
    /// The domain file; `None` for the built-in KB_full.
    pub domain: Option<String>,
    /// A scene file.
    pub scene: Option<String>,
    /// The preset of a generated scene.
    pub preset: Option<String>,
    /// The seed.
    pub seed: u64,
    /// The goal literals as given.
    pub goals: Vec<String>,
    /// The goal seed.
    pub goal_seed: Option<u64>,
    /// Perception noise.
    pub perception: f64,
    /// Actuation noise.
    pub actuation: f64,
    /// Confidence threshold.
    pub threshold: f64,
    /// The loop's configuration.
    pub config: RunConfig,
    /// `--log FILE`.
    pub log: Option<String>,
    /// `--save-history FILE`.
    pub save: Option<String>,
    /// `--report FILE.html`.
    pub report: Option<String>,
    /// `--outf=2`.
    pub json: bool,
    /// `--see-occlusion N`: train on N scenes and see occlusion from the image.
    pub see: Option<u64>,
}

fn parse(args: &[String]) -> Result<RunArgs, String> {
    let mut out = RunArgs {
        perception: 0.15,
        actuation: 0.15,
        threshold: 0.5,
        ..RunArgs::default()
    };
    for arg in options::scan(OPTIONS, args) {
        match arg.map_err(|e| e.to_string())? {
            Arg::Option(spec, v) => apply(&mut out, spec, v.unwrap_or_default())?,
            Arg::Word(w) | Arg::Literal(w) if out.domain.is_none() => out.domain = Some(w),
            Arg::Word(w) | Arg::Literal(w) => {
                return Err(format!(
                    "`lucent run` takes one domain file, not also `{w}`"
                ))
            }
        }
    }
    if out.scene.is_some() && out.preset.is_some() {
        return Err("--scene and --preset exclude each other".into());
    }
    Ok(out)
}

/// Sets the option `spec` of `lucent run` (or of `lucent demo`, whose options are some of
/// these) to `v`.
pub fn apply(out: &mut RunArgs, spec: &OptionSpec, v: String) -> Result<(), String> {
    match spec.long {
        "scene" => out.scene = Some(v),
        "preset" => out.preset = Some(v),
        "seed" => out.seed = spec.number(&v)?,
        "goal" => out.goals.push(v),
        "goal-seed" => out.goal_seed = Some(spec.number(&v)?),
        "perception-noise" => out.perception = spec.probability(&v)?,
        "actuation-noise" => out.actuation = spec.probability(&v)?,
        "threshold" => out.threshold = spec.probability(&v)?,
        "max-actions" => out.config.max_actions = spec.number(&v)?,
        "max-plans" => out.config.max_plans = spec.number(&v)?,
        "max-horizon" => out.config.plan.max_horizon = spec.number(&v)?,
        "no-confirm" => out.config.confirm_goal = false,
        "looks" => out.config.looks = spec.number(&v)?,
        "see-occlusion" => match spec.number::<u64>(&v)? {
            0 => return Err("--see-occlusion needs at least one training scene".into()),
            n => out.see = Some(n),
        },
        "log" => out.log = Some(v),
        "save-history" => out.save = Some(v),
        "report" => out.report = Some(v),
        "outf" => out.json = spec.outf(&v)?,
        _ => {} // --help, answered before parsing
    }
    Ok(())
}

/// Loads the domain: the file (with its includes) or the built-in KB_full.
pub fn load_domain(path: Option<&str>) -> Result<Domain, String> {
    let mut sources = SourceMap::new();
    let file = match path {
        Some(p) => {
            let text = super::builtin::read_to_string(p).map_err(|e| format!("{p}: {e}"))?;
            sources.add(p.to_string(), text)
        }
        None => sources.add(
            "domains/ra/kb_full.ald (built in)".to_string(),
            KB_FULL.to_string(),
        ),
    };
    let mut read =
        |p: &std::path::Path| super::builtin::read_to_string(p).map_err(|e| e.to_string());
    let parsed = action::load(&mut sources, file, &mut read);
    if parsed.has_errors() {
        let mut d = crate::base::Diagnostics::default();
        d.extend(parsed.diagnostics);
        return Err(format!("{}not a valid AL_d domain", d.render(&sources)));
    }
    Ok(Domain {
        description: parsed.description,
        sources,
    })
}

/// The scene: read from a file or generated.
pub fn load_scene(args: &RunArgs) -> Result<(Scene, String), String> {
    if let Some(path) = &args.scene {
        let text = super::builtin::read_to_string(path).map_err(|e| format!("{path}: {e}"))?;
        let scene = Scene::from_json(&text).map_err(|e| format!("{path}: {e}"))?;
        return Ok((scene, path.clone()));
    }
    let preset =
        Preset::parse(args.preset.as_deref().unwrap_or("real")).map_err(|e| e.to_string())?;
    let scene =
        sim::generate(&GenerateConfig::new(preset, args.seed)).map_err(|e| e.to_string())?;
    Ok((
        scene,
        format!("generated {} seed {}", preset.name(), args.seed),
    ))
}

/// The goal: parsed from the command line, every constant an object of the scene, the table or
/// the robot; or drawn at random.
pub fn goal_of(args: &RunArgs, world: &mut SimWorld) -> Result<Vec<Symbol>, String> {
    if args.goals.is_empty() {
        let seed = args.goal_seed.unwrap_or(args.seed);
        return random_goal(world, seed)
            .map(|g| vec![g])
            .ok_or_else(|| "the scene admits no goal to draw".to_string());
    }
    let mut known: Vec<String> = world.scene.objects.iter().map(|o| o.name.clone()).collect();
    known.push(sim::TABLE.to_string());
    known.push(world.scene.robot.clone());
    let mut goal = Vec::new();
    for text in &args.goals {
        let g = act::goal_literal(text)?;
        let args_of = g.args();
        let names = if g.is("relation", 3) {
            &args_of[1..]
        } else {
            args_of
        };
        for a in names {
            let n = a.to_string();
            if !known.contains(&n) {
                return Err(format!(
                    "goal `{text}`: `{n}` is no object of the scene (objects: {})",
                    known[..known.len() - 2].join(", ")
                ));
            }
        }
        goal.push(g);
    }
    Ok(goal)
}

/// One progress line for an event.
pub fn describe(event: &Event) -> String {
    match event {
        Event::Perceived {
            step,
            look,
            doubted,
        } => {
            let again = if *look > 0 { " (looked again)" } else { "" };
            format!("[step {step}] perceived{again}; {doubted} observation(s) doubted")
        }
        Event::Planned(p) => format!(
            "[step {}] plan of {} action{} ({}): {}",
            p.step,
            p.actions.len(),
            if p.actions.len() == 1 { "" } else { "s" },
            p.reason,
            if p.actions.is_empty() {
                "nothing to do".to_string()
            } else {
                p.actions.join("; ")
            }
        ),
        Event::Acted {
            step,
            action,
            failure,
        } => match failure {
            None => format!("[step {step}] executed {action}"),
            Some(f) => format!("[step {step}] executed {action}: FAILED, {f}"),
        },
        Event::Discrepancy(d) => {
            let mut parts = Vec::new();
            if let Some(f) = &d.failure {
                parts.push(format!("failure: {f}"));
            }
            if !d.unexpected.is_empty() {
                parts.push(format!("unexpected {}", d.unexpected.join(", ")));
            }
            if !d.extra.is_empty() {
                parts.push(format!("missing {}", d.extra.join(", ")));
            }
            format!(
                "[step {}] discrepancy after {}: {}; replanning",
                d.step + 1,
                d.action,
                parts.join("; ")
            )
        }
    }
}

/// The text summary of a run.
pub fn summary(history: &History) -> String {
    let mut out = String::new();
    out.push_str(&format!("Scene: {}\n", history.scene));
    out.push_str(&format!("Goal: {}\n", history.goal.join(", ")));
    out.push_str(&format!("Executed: {}\n", history.actions().join("; ")));
    out.push_str(&format!(
        "Plans: {} ({} replan(s)); discrepancies: {}\n",
        history.plans.len(),
        history.replans(),
        history.discrepancies.len()
    ));
    let ending = history
        .ending
        .as_ref()
        .map_or("unfinished".to_string(), |e| e.to_string());
    let truth = match history.goal_in_truth {
        Some(true) => "holds in the world",
        Some(false) => "does NOT hold in the world",
        None => "cannot be checked in the world",
    };
    out.push_str(&format!("Ending: {ending}; the goal {truth}\n"));
    out.push_str(&format!(
        "Result: {}\n",
        if history.succeeded() {
            "GOAL REACHED"
        } else {
            "GOAL NOT REACHED"
        }
    ));
    out
}

/// The occlusion decisions of a seeing run that came from the image (reasoning's are the
/// robot's own beliefs), one line per look that had any.
fn seen_summary(seen: &[SeenOcclusion]) -> String {
    let mut out = String::new();
    let mut lines: Vec<((u32, u32), Vec<String>)> = Vec::new();
    let (mut from_image, mut agreed, mut reasoned_right) = (0, 0, 0);
    let said = |v: bool| if v { "occluded" } else { "not occluded" };
    for s in seen {
        if s.decision.source != Source::Cnn {
            reasoned_right += usize::from(s.decision.value == s.truth);
            continue;
        }
        from_image += 1;
        agreed += usize::from(s.decision.value == s.truth);
        let what = format!(
            "{} {} (behind {}){}",
            s.object,
            said(s.decision.value),
            if s.behind.is_empty() {
                "nothing perceived".to_string()
            } else {
                s.behind.join(", ")
            },
            if s.decision.value == s.truth {
                String::new()
            } else {
                format!(", the world says {}", said(s.truth))
            }
        );
        match lines.last_mut() {
            Some((key, v)) if *key == (s.step, s.look) => v.push(what),
            _ => lines.push(((s.step, s.look), vec![what])),
        }
    }
    let decided = seen.len() - from_image;
    out.push_str(&format!(
        "Occlusion: {decided} decisions by reasoning ({reasoned_right} as the world says), \
         {from_image} by the network from the image ({agreed} as the world says)\n"
    ));
    for ((step, look), v) in lines {
        out.push_str(&format!("  step {step} look {look}: {}\n", v.join("; ")));
    }
    out
}

/// Runs `act` on `world`, filmed when `film` is set: the history and the pictures.
fn filmed<W: act::World + Pictured>(
    world: &mut W,
    film: bool,
    act: impl FnOnce(&mut dyn act::World) -> History,
) -> (History, Vec<Frame>) {
    if !film {
        return (act(world), Vec::new());
    }
    let mut filming = Filming::new(world);
    let history = act(&mut filming);
    (history, filming.frames)
}

/// Writes the HTML report of a run to `path`, with the run's answers to its own questions.
fn write_report(
    path: &str,
    history: &History,
    frames: &[Frame],
    goal: &[Symbol],
) -> Result<(), String> {
    let lexicon = crate::explain::lexicon::Lexicon::ra();
    let v = crate::explain::verbalize::Verbalizer::new(&lexicon);
    let done = run_report::done_actions(history);
    let questions = run_report::own_questions(history, &done, goal, &v);
    let (answers, unanswered) = match super::explain::ask_run(history, path, &questions) {
        Ok(a) => (a, None),
        Err(m) => (Vec::new(), Some(m)),
    };
    let report = run_report::Report {
        title: format!("Lucent run: {}", history.scene),
        history,
        frames,
        answers: &answers,
        unanswered,
        v,
    };
    std::fs::write(path, report.html()).map_err(|e| format!("cannot write {path}: {e}"))
}

/// `lucent run`.
pub fn run_run(args: &[String], out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<i32> {
    let args = match super::verb_args(&VERB, args, parse, out, err)? {
        Ok(a) => a,
        Err(code) => return Ok(code),
    };
    let input_error = |err: &mut dyn Write, m: String| -> std::io::Result<i32> {
        writeln!(err, "*** ERROR: (lucent): {}", m.trim_end())?;
        Ok(super::EXIT_INPUT)
    };
    let domain = match load_domain(args.domain.as_deref()) {
        Ok(d) => d,
        Err(m) => return input_error(err, m),
    };
    let (scene, name) = match load_scene(&args) {
        Ok(s) => s,
        Err(m) => return input_error(err, m),
    };
    let mut world = SimWorld::new(
        scene,
        act_config(args.perception, args.actuation, args.threshold),
    );
    let goal = match goal_of(&args, &mut world) {
        Ok(g) => g,
        Err(m) => return input_error(err, m),
    };
    let mut log = match &args.log {
        Some(path) => match std::fs::File::create(path) {
            Ok(f) => Some(f),
            Err(e) => return input_error(err, format!("cannot write {path}: {e}")),
        },
        None => None,
    };
    let start = Instant::now();
    let goal_text: Vec<String> = goal.iter().map(Symbol::to_string).collect();
    let head = format!("lucent run: {name}; goal {}", goal_text.join(", "));
    writeln!(err, "{head}")?;
    if let Some(f) = log.as_mut() {
        writeln!(f, "{head}")?;
    }
    let mut seeing = match args.see {
        None => None,
        Some(n) => {
            let dataset = DatasetConfig {
                error: ErrorModel {
                    substitute_share: 0.0,
                    ..world.act.perception.clone()
                },
                ..DatasetConfig::default()
            };
            let started = Instant::now();
            let knowledge = Knowledge::kb_full();
            let bar = super::progress::bar(n, "training scenes generated");
            let trained = train_seer(&knowledge, &dataset, n, args.seed, &|| bar.inc(1));
            bar.finish_and_clear();
            let classifier = match trained {
                Ok(c) => c,
                Err(e) => return input_error(err, format!("training the occlusion network: {e}")),
            };
            let line = format!(
                "seeing occlusion: a network trained in {:.1} s on the {} examples of {n} \
                 generated scenes that reasoning could not decide",
                started.elapsed().as_secs_f64(),
                classifier.trained_on[1]
            );
            writeln!(err, "{line}")?;
            if let Some(f) = log.as_mut() {
                writeln!(f, "{line}")?;
            }
            let inner = SimWorld::new(world.scene.clone(), world.act.clone());
            Some(Seeing::new(inner, classifier, dataset))
        }
    };
    let mut io_error = None;
    let mut on_event = |e: Event| {
        let line = format!("{:7.2}s {}", start.elapsed().as_secs_f64(), describe(&e));
        let mut write = || -> std::io::Result<()> {
            writeln!(err, "{line}")?;
            if let Some(f) = log.as_mut() {
                writeln!(f, "{line}")?;
            }
            Ok(())
        };
        if let Err(e) = write() {
            io_error.get_or_insert(e);
        }
    };
    let film = args.report.is_some();
    let (history, frames) = match seeing.as_mut() {
        Some(s) => filmed(s, film, |w| {
            act::run(&domain, w, &goal, &name, &args.config, &mut on_event)
        }),
        None => filmed(&mut world, film, |w| {
            act::run(&domain, w, &goal, &name, &args.config, &mut on_event)
        }),
    };
    if let Some(e) = io_error {
        return Err(e);
    }
    if let Some(path) = &args.save {
        if let Err(e) = std::fs::write(path, history.to_json()) {
            return input_error(err, format!("cannot write {path}: {e}"));
        }
    }
    if let Some(path) = &args.report {
        if let Err(m) = write_report(path, &history, &frames, &goal) {
            return input_error(err, m);
        }
    }
    let mut text = summary(&history);
    if let Some(s) = &seeing {
        text.push_str(&seen_summary(&s.seen));
    }
    if let Some(f) = log.as_mut() {
        write!(f, "{text}")?;
    }
    if args.json {
        writeln!(out, "{}", history.to_json())?;
    } else {
        write!(out, "{text}")?;
    }
    Ok(if history.succeeded() {
        0
    } else {
        EXIT_NOT_REACHED
    })
}
