//! `lucent sim`: generate, observe, measure, step, act on and render tabletop scenes stored as
//! JSON files.
//!
//! Invariants: this is the only place where the simulator touches files; every failure is a
//! message on standard error and an exit code (0 success, 65 bad input such as a malformed scene,
//! an unknown object or an unreadable file, 1 bad usage), never a panic. A failed action is
//! not a failure of the command: it is reported and observed, and the exit code is 0.

use crate::sim::{
    self, generate, perceive, render_camera, render_top, ActConfig, Action, ErrorModel, FactStyle,
    GenerateConfig, Preset, Scene, TruthConfig, World,
};
use std::fmt::Write as _;

const EXIT_OK: i32 = 0;
const EXIT_INPUT: i32 = 65;
const EXIT_USAGE: i32 = super::EXIT_USAGE;

use super::options::{self, opt, Arg, Arity::*, OptionSpec, Verb};

/// `lucent sim`'s command line: the options of every subcommand in one table (a subcommand's
/// own are listed in [`COMMANDS`]); `--help` is generated from both.
pub(super) const VERB: Verb = Verb {
    usage: "",
    options: OPTIONS,
    epilogue: "
Examples:
  lucent sim generate --seed 7 --preset real -o scene.json
  lucent sim observe scene.json
  lucent sim act scene.json 'pickup(rob1,red_cube)'
  lucent sim render scene.json -o scene.png
",
};

/// The options of `lucent sim`'s subcommands.
#[rustfmt::skip]
const OPTIONS: &[OptionSpec] = &[
    options::HELP,
    opt("seed", None, Value, "N", "seed of the scene and of its noise (default 0)", "Options"),
    opt("preset", None, Value, "P", "real, simulated (sim) or h1 (default simulated)", "Options"),
    opt("objects", None, Value, "K", "number of objects, 5 to 9 (default: the preset's range)", "Options"),
    opt("risky", None, Flag, "", "a risky scene as placed, not settled (towers on irregular, small and flat supports: what `lucent classify` looks at)", "Options"),
    opt("output", Some('o'), Value, "FILE", "output file (generate: stdout if absent; act/step: the scene file itself)", "Options"),
    opt("holds", None, Flag, "", "print holds(F,I) facts instead of obs(F,V,I)", "Options"),
    opt("error-rate", None, Value, "P", "probability of misperceiving a relation (default 0.15)", "Options"),
    opt("size-error", None, Value, "P", "probability of misreading a size (default 0)", "Options"),
    opt("threshold", None, Value, "T", "confidence from which an observation is a fact (default 0.5)", "Options"),
    opt("failure-rate", None, Value, "P", "probability that a possible action fails (default 0.15)", "Options"),
    opt("seconds", None, Value, "S", "simulated seconds to step (default 2)", "Options"),
    opt("top", None, Flag, "", "render the top view instead of the camera view", "Options"),
    opt("labelled", None, Flag, "", "the camera view widened to frame every object, each labelled (as in run reports)", "Options"),
    opt("width", None, Value, "W", "image width (default 320)", "Options"),
    opt("height", None, Value, "H", "image height (default 200)", "Options"),
    opt("json", None, Flag, "", "print JSON instead of facts", "Options"),
];

/// A subcommand: its name, positional arguments, help, and the options it takes.
struct Command {
    name: &'static str,
    args: &'static str,
    help: &'static str,
    options: &'static [&'static str],
}

/// The subcommands.
#[rustfmt::skip]
const COMMANDS: &[Command] = &[
    Command { name: "generate", args: "", help: "generate and settle a scene from a seed", options: &["seed", "preset", "objects", "risky", "output"] },
    Command { name: "observe", args: "SCENE", help: "print what the robot perceives, as facts", options: &["holds", "error-rate", "size-error", "threshold", "json"] },
    Command { name: "truth", args: "SCENE", help: "print the measured relations, stability and occlusion", options: &["json"] },
    Command { name: "act", args: "SCENE ACTION", help: "execute pickup(R,O) or putdown(R,O,L), save the scene, print observations", options: &["output", "holds", "error-rate", "size-error", "threshold", "failure-rate", "json"] },
    Command { name: "step", args: "SCENE", help: "let physics run and save the scene", options: &["output", "seconds"] },
    Command { name: "render", args: "SCENE", help: "render the camera (or --top) view to PNG", options: &["output", "top", "labelled", "width", "height"] },
];

fn help() -> String {
    let mut out = String::from("Usage: lucent sim COMMAND [ARGS] [OPTIONS]\n\nCommands:\n");
    for c in COMMANDS {
        let _ = writeln!(out, "  {:<22} {}", format!("{} {}", c.name, c.args), c.help);
    }
    out + &VERB.help_with(|o| {
        let mut of = COMMANDS.iter().filter(|c| c.options.contains(&o.long));
        match of.next() {
            Some(first) => {
                let names: Vec<&str> = std::iter::once(first).chain(of).map(|c| c.name).collect();
                format!("{} [{}]", o.help, names.join(", "))
            }
            None => o.help.to_string(),
        }
    })
}

/// Parsed arguments of one subcommand.
struct Args {
    /// The subcommand.
    command: &'static Command,
    /// Its positional arguments.
    positional: Vec<String>,
    /// Options in command-line order, with their values; the last occurrence wins.
    options: Vec<(&'static OptionSpec, Option<String>)>,
}

impl Args {
    fn flag(&self, long: &str) -> bool {
        self.options.iter().any(|(o, _)| o.long == long)
    }

    /// The last value of the option `long`, with the option.
    fn option(&self, long: &str) -> Option<(&'static OptionSpec, &str)> {
        self.options
            .iter()
            .rev()
            .find(|(o, _)| o.long == long)
            .and_then(|(o, v)| Some((*o, v.as_deref()?)))
    }

    fn value(&self, long: &str) -> Option<&str> {
        self.option(long).map(|(_, v)| v)
    }

    fn number<T: std::str::FromStr>(&self, long: &str, default: T) -> Result<T, String> {
        self.option(long)
            .map_or(Ok(default), |(spec, v)| spec.number(v))
    }

    fn probability(&self, long: &str, default: f64) -> Result<f64, String> {
        self.option(long)
            .map_or(Ok(default), |(spec, v)| spec.probability(v))
    }
}

fn parse(args: &[String]) -> Result<Args, String> {
    let name = args.first().ok_or("missing command")?;
    let command = COMMANDS
        .iter()
        .find(|c| c.name == name)
        .ok_or_else(|| format!("unknown command `{name}`"))?;
    let mut parsed = Args {
        command,
        positional: Vec::new(),
        options: Vec::new(),
    };
    for arg in options::scan(OPTIONS, &args[1..]) {
        match arg.map_err(|e| e.to_string())? {
            Arg::Option(spec, value) if command.options.contains(&spec.long) => {
                parsed.options.push((spec, value))
            }
            Arg::Option(spec, _) => {
                return Err(format!("{} is no option of `{name}`", spec.spelled()))
            }
            Arg::Word(w) | Arg::Literal(w) => parsed.positional.push(w),
        }
    }
    let wanted = command.args.split_whitespace().count();
    if parsed.positional.len() != wanted {
        return Err(format!(
            "`{name}` takes {wanted} argument(s), got {}",
            parsed.positional.len()
        ));
    }
    Ok(parsed)
}

/// A command failure: the message and the exit code.
struct Fail(
    /// The message.
    String,
    /// The exit code.
    i32,
);

fn usage(message: String) -> Fail {
    Fail(message, EXIT_USAGE)
}

impl From<sim::SimError> for Fail {
    fn from(e: sim::SimError) -> Fail {
        Fail(e.to_string(), EXIT_INPUT)
    }
}

fn load(path: &str) -> Result<Scene, Fail> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| Fail(format!("cannot read {path}: {e}"), EXIT_INPUT))?;
    Scene::from_json(&text).map_err(|e| Fail(format!("{path}: {e}"), EXIT_INPUT))
}

fn save(path: &str, bytes: &[u8]) -> Result<(), Fail> {
    std::fs::write(path, bytes).map_err(|e| Fail(format!("cannot write {path}: {e}"), EXIT_INPUT))
}

fn error_model(args: &Args) -> Result<ErrorModel, Fail> {
    Ok(ErrorModel {
        relation_error: args.probability("error-rate", 0.15).map_err(usage)?,
        size_error: args.probability("size-error", 0.0).map_err(usage)?,
        threshold: args.probability("threshold", 0.5).map_err(usage)?,
        ..ErrorModel::default()
    })
}

fn style(args: &Args) -> FactStyle {
    if args.flag("holds") {
        FactStyle::Holds
    } else {
        FactStyle::Obs
    }
}

fn json<T: serde::Serialize>(value: &T) -> String {
    serde_json::to_string_pretty(value).expect("reports always serialise") + "\n"
}

fn run_command(args: &Args) -> Result<String, Fail> {
    match args.command.name {
        "generate" => {
            let preset = Preset::parse(args.value("preset").unwrap_or("simulated"))?;
            let mut config = GenerateConfig::new(preset, args.number("seed", 0u64).map_err(usage)?);
            if args.value("objects").is_some() {
                config.count = Some(args.number("objects", 0usize).map_err(usage)?);
            }
            let scene = if args.flag("risky") {
                crate::vision::scenes::generate_risky(&crate::vision::scenes::RiskyConfig {
                    preset: config.preset,
                    seed: config.seed,
                    count: config.count,
                })?
            } else {
                generate(&config)?
            };
            match args.value("output") {
                Some(path) => {
                    save(path, scene.to_json().as_bytes())?;
                    Ok(format!(
                        "% wrote {path}: {} objects, preset {}, seed {}\n",
                        scene.objects.len(),
                        scene.preset,
                        scene.seed
                    ))
                }
                None => Ok(scene.to_json() + "\n"),
            }
        }
        "observe" => {
            let scene = load(&args.positional[0])?;
            let percept = perceive(&scene, &error_model(args)?, &TruthConfig::default());
            if args.flag("json") {
                Ok(json(&percept))
            } else {
                Ok(percept.to_program(style(args)))
            }
        }
        "truth" => {
            let scene = load(&args.positional[0])?;
            let truth = sim::measure(&scene, &TruthConfig::default());
            if args.flag("json") {
                return Ok(json(&truth));
            }
            let mut out = format!("% ground truth at step {}\n", scene.step);
            for r in &truth.relations {
                let _ = writeln!(out, "{r}.");
            }
            for s in &truth.stability {
                let _ = writeln!(
                    out,
                    "% {}: {} (moved {:.4} m, turned {:.3} rad)",
                    s.name,
                    if s.stable { "stable" } else { "unstable" },
                    s.displacement,
                    s.rotation
                );
            }
            for o in &truth.occlusion {
                let by: Vec<String> =
                    o.by.iter()
                        .map(|(n, f)| format!("{n} {:.0}%", 100.0 * f))
                        .collect();
                let _ = writeln!(
                    out,
                    "% {}: {:.0}% hidden{}",
                    o.name,
                    100.0 * o.hidden,
                    if by.is_empty() {
                        String::new()
                    } else {
                        format!(" by {}", by.join(", "))
                    }
                );
            }
            Ok(out)
        }
        "act" => {
            let path = &args.positional[0];
            let mut scene = load(path)?;
            let action = Action::parse(&args.positional[1])?;
            let config = ActConfig {
                failure_rate: args.probability("failure-rate", 0.15).map_err(usage)?,
                perception: error_model(args)?,
                ..ActConfig::default()
            };
            let report = sim::execute(&mut scene, &action, &config)?;
            save(
                args.value("output").unwrap_or(path),
                scene.to_json().as_bytes(),
            )?;
            if args.flag("json") {
                return Ok(json(&report));
            }
            let mut out = match &report.failure {
                None => format!("% {} at step {}: succeeded\n", report.action, report.step),
                Some(f) => format!("% {} at step {}: failed: {f}\n", report.action, report.step),
            };
            let _ = writeln!(out, "hpd({},{}).", report.action, report.step);
            out.push_str(&report.percept.to_program(style(args)));
            Ok(out)
        }
        "step" => {
            let path = &args.positional[0];
            let mut scene = load(path)?;
            let seconds: f32 = args.number("seconds", 2.0).map_err(usage)?;
            if !(0.0..=60.0).contains(&seconds) {
                return Err(usage(format!("--seconds needs 0 to 60, got {seconds}")));
            }
            let mut world = World::build(&scene);
            world.step_for(seconds);
            world.write_back(&mut scene);
            save(
                args.value("output").unwrap_or(path),
                scene.to_json().as_bytes(),
            )?;
            Ok(format!("% stepped {path} for {seconds} s\n"))
        }
        "render" => {
            let scene = load(&args.positional[0])?;
            let out = args
                .value("output")
                .ok_or_else(|| usage("render needs -o FILE".into()))?;
            let width: u32 = args.number("width", 320).map_err(usage)?;
            let height: u32 = args.number("height", 200).map_err(usage)?;
            if !(8..=4096).contains(&width) || !(8..=4096).contains(&height) {
                return Err(usage("image sides must be 8 to 4096 pixels".into()));
            }
            let image = if args.flag("top") {
                render_top(&scene, width, height)
            } else if args.flag("labelled") {
                crate::sim::picture(&scene, width, height).image
            } else {
                render_camera(&scene, width, height)
            };
            save(out, &image.to_png()?)?;
            Ok(format!("% wrote {out} ({width}x{height})\n"))
        }
        other => Err(usage(format!("unknown command `{other}`"))),
    }
}

/// Runs `lucent sim ARGS` (the arguments after `sim`) and returns the exit code.
pub fn run(args: &[String]) -> i32 {
    run_with(
        args,
        &mut std::io::stdout().lock(),
        &mut std::io::stderr().lock(),
    )
}

/// Runs `lucent sim ARGS`, writing output and messages to the given streams.
pub fn run_with(
    args: &[String],
    out: &mut dyn std::io::Write,
    err: &mut dyn std::io::Write,
) -> i32 {
    if args.is_empty() || VERB.asks_for_help(args) || args[0] == "help" {
        let _ = write!(out, "{}", help());
        return if args.is_empty() { EXIT_USAGE } else { EXIT_OK };
    }
    let parsed = match parse(args) {
        Ok(p) => p,
        Err(message) => {
            let _ = writeln!(err, "lucent sim: {message}\n(try `lucent sim --help`)");
            return EXIT_USAGE;
        }
    };
    match run_command(&parsed) {
        Ok(text) => {
            let _ = write!(out, "{text}");
            EXIT_OK
        }
        Err(Fail(message, code)) => {
            let _ = writeln!(err, "lucent sim: error: {message}");
            code
        }
    }
}
