//! `lucent demo`: the robot's main job end to end. A tabletop scene is generated in the physics
//! world; the robot looks at it (with the paper's 15% perception error), is given a goal, plans
//! a minimal plan with the AL_d knowledge base KB_full (built in), says the plan in English,
//! executes it one action at a time in rapier (with 15% manipulation failures), notices
//! discrepancies, replans, and stops when it sees the goal. Pictures of the camera view before
//! and after are written as PNG files to a directory the demo names.
//!
//! Invariants: the demo is a client of the same library paths as `lucent run` (`plan::act`,
//! `plan::tabletop`, `explain::verbalize`); it is deterministic for its seed; it exits 0 when
//! the goal was reached, 20 when not, 65 for bad input, 1 for a bad command line. Built without
//! the `sim` feature it plans the built-in tabletop task of docs/domain.md 4.5 instead and says so.

use std::io::Write;

use crate::action;
use crate::base::SourceMap;
use crate::plan::{plan, PlanConfig};

use super::options::{self, opt, Arity::*, OptionSpec, Verb};
use super::KB_FULL;

/// The tabletop task of docs/domain.md 4.5 (it includes `../kb_full.ald`).
const H1_SCENE: &str = include_str!("../../domains/ra/scenes/h1.ald");
const TABLETOP_TASK: &str = include_str!("../../domains/ra/scenes/tabletop_task.ald");

/// `lucent demo`'s command line; `--help` is generated from it.
pub(super) const VERB: Verb = Verb {
    usage: "\
usage: lucent demo [--seed N] [--preset real|simulated] [--goal LITERAL]... [--out DIR]
                   [--perception-noise P] [--actuation-noise P]

The robot at work in the simulated tabletop world: a generated scene (default: preset real,
seed 3), a goal (drawn at random unless given), perception with 15% errors, a minimal plan
from the built-in knowledge base KB_full, the plan in English, execution in the physics world
with 15% manipulation failures, replanning after every discrepancy, until the robot sees the
goal; then the robot answers questions about its own run. Writes to DIR (default lucent-demo/)
the labelled camera views before and after (before.png, after.png), the run (run.json, for
`lucent ask --run DIR/run.json`) and report.html, the whole run with a picture after every
action, the plans in English and the answers with their proof trees, to open in a browser.
For more control (scene files, budgets, histories) use `lucent run`.
",
    options: OPTIONS,
    epilogue: ROBOT_EXIT_CODES,
};

/// The end of `lucent demo --help` and `lucent run --help`.
pub(super) const ROBOT_EXIT_CODES: &str = "
Exit code: 0 when the goal was reached, 20 when not, 65 for bad input, 1 for a bad command line.
";

/// The options of `lucent demo`: `--out` and some of `lucent run`'s, which `cli::run::apply`
/// sets.
#[rustfmt::skip]
const OPTIONS: &[OptionSpec] = &[
    options::HELP,
    opt("seed", None, Value, "N", "the scene's seed (default 3); it also seeds noise and failures", "Options"),
    opt("preset", None, Value, "NAME", "the scene's preset: real or simulated (default real)", "Options"),
    GOAL,
    opt("out", None, Value, "DIR", "the folder for the pictures, run.json and report.html (default lucent-demo)", "Options"),
    PERCEPTION_NOISE,
    ACTUATION_NOISE,
];

/// `--goal`, shared with `lucent run`.
#[rustfmt::skip]
pub(super) const GOAL: OptionSpec = opt("goal", None, Value, "LITERAL", "a goal literal: on(X,Y), relation(S,X,Y) or in_hand(rob1,X); repeat for a conjunction; without it a goal is drawn (docs/domain.md 7.1)", "Options");
/// `--perception-noise`, shared with `lucent run`.
#[rustfmt::skip]
pub(super) const PERCEPTION_NOISE: OptionSpec = opt("perception-noise", None, Value, "P", "probability that a perceived relation is wrong (default 0.15)", "Options");
/// `--actuation-noise`, shared with `lucent run`.
#[rustfmt::skip]
pub(super) const ACTUATION_NOISE: OptionSpec = opt("actuation-noise", None, Value, "P", "probability that an action slips (default 0.15)", "Options");

/// The plans of the built-in tabletop task, for builds without the simulator.
#[cfg_attr(feature = "sim", allow(dead_code))]
fn plan_only(out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<i32> {
    let mut sources = SourceMap::new();
    let file = sources.add(
        "domains/ra/scenes/tabletop_task.ald (built in)".to_string(),
        TABLETOP_TASK.to_string(),
    );
    let mut read = |p: &std::path::Path| {
        if p.ends_with("kb_full.ald") {
            Ok(KB_FULL.to_string())
        } else if p.ends_with("h1.ald") {
            Ok(H1_SCENE.to_string())
        } else {
            Err(format!("{} is not built in", p.display()))
        }
    };
    let parsed = action::load(&mut sources, file, &mut read);
    writeln!(
        out,
        "This build has no simulator (built without the `sim` feature): planning the tabletop \
         task of docs/domain.md 4.5 only."
    )?;
    match plan(&parsed.description, &sources, &PlanConfig::default()) {
        Ok(found) => {
            for p in &found.plans {
                writeln!(out, "Plan: {}", p.to_text())?;
            }
            Ok(0)
        }
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {e}")?;
            Ok(super::EXIT_UNSAT)
        }
    }
}

/// Runs the demo; returns the exit code.
pub fn run(args: &[String], out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<i32> {
    if VERB.asks_for_help(args) {
        write!(out, "{}", VERB.help())?;
        return Ok(0);
    }
    #[cfg(feature = "sim")]
    {
        simulated::run(args, out, err)
    }
    #[cfg(not(feature = "sim"))]
    {
        if let Some(a) = args.first() {
            writeln!(
                err,
                "*** ERROR: (lucent): `{a}`: this build of the demo takes no options"
            )?;
            return Ok(super::EXIT_USAGE);
        }
        plan_only(out, err)
    }
}

#[cfg(feature = "sim")]
mod simulated {
    use std::io::Write;
    use std::path::Path;
    use std::time::Instant;

    use crate::cli::options::{self, Arg};
    use crate::cli::run::{apply, describe, goal_of, load_domain, RunArgs};
    use crate::cli::run_report::{self, Filming};
    use crate::control::Symbol;
    use crate::explain::lexicon::Lexicon;
    use crate::explain::verbalize::{Tense, Verbalizer};
    use crate::plan::act::{self, Event, RunConfig};
    use crate::plan::tabletop::{act_config, SimWorld};
    use crate::sim::{self, GenerateConfig, Preset};

    /// The demo's scene seed: a real-preset scene where the first plan meets a discrepancy.
    const SEED: u64 = 3;

    fn picture(scene: &sim::Scene, path: &Path) -> Result<(), String> {
        let png = sim::picture(scene, 640, 480)
            .image
            .to_png()
            .map_err(|e| e.to_string())?;
        std::fs::write(path, png).map_err(|e| format!("cannot write {}: {e}", path.display()))
    }

    /// The demo's command line: the run's settings and the output folder.
    fn parse(args: &[String]) -> Result<(RunArgs, String), String> {
        let mut run = RunArgs {
            seed: SEED,
            perception: 0.15,
            actuation: 0.15,
            threshold: 0.5,
            ..RunArgs::default()
        };
        let mut dir = "lucent-demo".to_string();
        for arg in options::scan(super::OPTIONS, args) {
            match arg.map_err(|e| e.to_string())? {
                Arg::Option(spec, v) if spec.long == "out" => dir = v.unwrap_or_default(),
                Arg::Option(spec, v) => apply(&mut run, spec, v.unwrap_or_default())?,
                Arg::Word(w) | Arg::Literal(w) => {
                    return Err(format!("unknown argument `{w}` (try `lucent demo --help`)"))
                }
            }
        }
        Ok((run, dir))
    }

    pub fn run(args: &[String], out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<i32> {
        let (run, dir) = match parse(args) {
            Ok(x) => x,
            Err(m) => {
                writeln!(err, "*** ERROR: (lucent): {m}")?;
                return Ok(super::super::EXIT_USAGE);
            }
        };
        let start = Instant::now();
        let input = |err: &mut dyn Write, m: String| -> std::io::Result<i32> {
            writeln!(err, "*** ERROR: (lucent): {m}")?;
            Ok(super::super::EXIT_INPUT)
        };
        let domain = load_domain(None).expect("the built-in KB_full is valid");
        let preset = match Preset::parse(run.preset.as_deref().unwrap_or("real")) {
            Ok(p) => p,
            Err(e) => return input(err, e.to_string()),
        };
        let scene = match sim::generate(&GenerateConfig::new(preset, run.seed)) {
            Ok(s) => s,
            Err(e) => return input(err, e.to_string()),
        };
        let mut world = SimWorld::new(scene, act_config(run.perception, run.actuation, 0.5));
        let goal = match goal_of(&run, &mut world) {
            Ok(g) => g,
            Err(m) => return input(err, m),
        };
        if let Err(e) = std::fs::create_dir_all(&dir) {
            return input(err, format!("cannot create {dir}: {e}"));
        }
        let before = Path::new(&dir).join("before.png");
        let after = Path::new(&dir).join("after.png");
        if let Err(m) = picture(&world.scene, &before) {
            return input(err, m);
        }
        let lexicon = Lexicon::ra();
        let v = Verbalizer::new(&lexicon);
        let say = |text: &str, tense: Tense| {
            Symbol::parse(text).map_or(text.to_string(), |t| v.fluent(&t, tense))
        };

        writeln!(out, "Lucent demo: the robot assistant at the table")?;
        writeln!(
            out,
            "Scene   : {} objects ({} preset, seed {}): {}",
            world.scene.objects.len(),
            preset.name(),
            run.seed,
            world
                .scene
                .objects
                .iter()
                .map(|o| o.name.as_str())
                .collect::<Vec<_>>()
                .join(", ")
        )?;
        writeln!(
            out,
            "Picture : {} (the camera view before)",
            before.display()
        )?;
        let goal_text: Vec<String> = goal.iter().map(Symbol::to_string).collect();
        let goal_words: Vec<String> = goal_text.iter().map(|g| say(g, Tense::Future)).collect();
        writeln!(
            out,
            "Goal    : {} ({})",
            goal_text.join(", "),
            goal_words.join("; ")
        )?;
        writeln!(
            out,
            "Noise   : {:.0}% perception errors, {:.0}% manipulation failures\n",
            100.0 * run.perception,
            100.0 * run.actuation
        )?;
        let mut lines: Vec<String> = Vec::new();
        let mut filming = Filming::new(&mut world);
        let history = act::run(
            &domain,
            &mut filming,
            &goal,
            &format!("generated {} seed {}", preset.name(), run.seed),
            &RunConfig::default(),
            &mut |e| match &e {
                Event::Perceived { .. } => (),
                Event::Planned(p) => {
                    let steps: Vec<(u32, Symbol)> = p
                        .actions
                        .iter()
                        .enumerate()
                        .filter_map(|(k, a)| Some((k as u32, Symbol::parse(a).ok()?)))
                        .collect();
                    lines.push(describe(&e));
                    lines.push(format!("          In English: {}", v.plan(&steps, false)));
                }
                _ => lines.push(describe(&e)),
            },
        );
        for l in &lines {
            writeln!(out, "{l}")?;
        }
        let frames = std::mem::take(&mut filming.frames);
        if let Err(m) = picture(&world.scene, &after) {
            return input(err, m);
        }
        let done = run_report::done_actions(&history);
        writeln!(out)?;
        // The robot explains its own run: the run is saved beside the pictures (so the user can
        // go on with `lucent ask --run`), a few questions are asked over it, and the report
        // shows it all.
        let saved = Path::new(&dir).join("run.json");
        let questions = run_report::own_questions(&history, &done, &goal, &v);
        let asked = std::fs::write(&saved, history.to_json())
            .map_err(|e| format!("cannot write {}: {e}", saved.display()))
            .and_then(|()| {
                super::super::explain::ask_run(&history, &saved.to_string_lossy(), &questions)
            });
        match &asked {
            Ok(answers) if !answers.is_empty() => {
                // The first answer describes what was done, failed attempts included.
                writeln!(out, "What I did: {}", answers[0].1.text)?;
                writeln!(out, "\nAsked about my run:")?;
                for (q, a) in &answers[1..] {
                    writeln!(out, "  Q: {q}\n  A: {}", a.text)?;
                }
                writeln!(out, "  (ask more: lucent ask --run {})\n", saved.display())?;
            }
            _ => {
                writeln!(out, "What I did: {}", v.plan(&done, true))?;
                if let Err(m) = &asked {
                    writeln!(out, "(I could not explain my run: {m})")?;
                }
            }
        }
        let report_path = Path::new(&dir).join("report.html");
        let (answers, unanswered) = match asked {
            Ok(a) => (a, None),
            Err(m) => (Vec::new(), Some(m)),
        };
        let report = run_report::Report {
            title: format!("Lucent demo: {} preset, seed {}", preset.name(), run.seed),
            history: &history,
            frames: &frames,
            answers: &answers,
            unanswered,
            v,
        };
        if let Err(e) = std::fs::write(&report_path, report.html()) {
            return input(err, format!("cannot write {}: {e}", report_path.display()));
        }
        write!(out, "{}", super::super::run::summary(&history))?;
        writeln!(out, "Picture : {} (the camera view after)", after.display())?;
        writeln!(
            out,
            "Report  : {} (the run with pictures and proof trees; open it in a browser)",
            report_path.display()
        )?;
        writeln!(
            out,
            "Time    : {:.1}s. Try `lucent run --help` for scene files, budgets and saved histories.",
            start.elapsed().as_secs_f64()
        )?;
        Ok(if history.succeeded() {
            0
        } else {
            super::super::EXIT_UNSAT
        })
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_built_in_tabletop_task_has_its_four_plans() {
        let mut out = Vec::new();
        let mut err = Vec::new();
        assert_eq!(
            super::plan_only(&mut out, &mut err).unwrap(),
            0,
            "{}",
            String::from_utf8_lossy(&err)
        );
        let text = String::from_utf8(out).unwrap();
        assert_eq!(text.matches("Plan: ").count(), 4, "{text}");
    }
}
