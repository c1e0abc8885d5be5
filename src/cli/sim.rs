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

/// One option: its spelling, whether it takes a value, the subcommands it applies to, its help.
struct OptionSpec {
    /// The spelling, e.g. `--seed`.
    name: &'static str,
    /// The value's placeholder in `--help`, or `None` for a flag.
    value: Option<&'static str>,
    /// The subcommands that accept it.
    commands: &'static [&'static str],
    /// One line of help.
    help: &'static str,
}

/// The declarative option table that drives parsing and `--help`.
const OPTIONS: &[OptionSpec] = &[
    OptionSpec {
        name: "--seed",
        value: Some("N"),
        commands: &["generate"],
        help: "seed of the scene and of its noise (default 0)",
    },
    OptionSpec {
        name: "--preset",
        value: Some("P"),
        commands: &["generate"],
        help: "real, simulated (sim) or h1 (default simulated)",
    },
    OptionSpec {
        name: "--objects",
        value: Some("K"),
        commands: &["generate"],
        help: "number of objects, 5 to 9 (default: the preset's range)",
    },
    OptionSpec {
        name: "--risky",
        value: None,
        commands: &["generate"],
        help: "a risky scene as placed, not settled (towers on irregular, small and flat supports: what `lucent classify` looks at)",
    },
    OptionSpec {
        name: "-o",
        value: Some("FILE"),
        commands: &["generate", "act", "step", "render"],
        help: "output file (generate: stdout if absent; act/step: the scene file itself)",
    },
    OptionSpec {
        name: "--holds",
        value: None,
        commands: &["observe", "act"],
        help: "print holds(F,I) facts instead of obs(F,V,I)",
    },
    OptionSpec {
        name: "--error-rate",
        value: Some("P"),
        commands: &["observe", "act"],
        help: "probability of misperceiving a relation (default 0.15)",
    },
    OptionSpec {
        name: "--size-error",
        value: Some("P"),
        commands: &["observe", "act"],
        help: "probability of misreading a size (default 0)",
    },
    OptionSpec {
        name: "--threshold",
        value: Some("T"),
        commands: &["observe", "act"],
        help: "confidence from which an observation is a fact (default 0.5)",
    },
    OptionSpec {
        name: "--failure-rate",
        value: Some("P"),
        commands: &["act"],
        help: "probability that a possible action fails (default 0.15)",
    },
    OptionSpec {
        name: "--seconds",
        value: Some("S"),
        commands: &["step"],
        help: "simulated seconds to step (default 2)",
    },
    OptionSpec {
        name: "--top",
        value: None,
        commands: &["render"],
        help: "render the top view instead of the camera view",
    },
    OptionSpec {
        name: "--labelled",
        value: None,
        commands: &["render"],
        help: "the camera view widened to frame every object, each labelled (as in run reports)",
    },
    OptionSpec {
        name: "--width",
        value: Some("W"),
        commands: &["render"],
        help: "image width (default 320)",
    },
    OptionSpec {
        name: "--height",
        value: Some("H"),
        commands: &["render"],
        help: "image height (default 200)",
    },
    OptionSpec {
        name: "--json",
        value: None,
        commands: &["observe", "truth", "act"],
        help: "print JSON instead of facts",
    },
];

/// The subcommands: name, positional arguments, help.
const COMMANDS: &[(&str, &str, &str)] = &[
    ("generate", "", "generate and settle a scene from a seed"),
    (
        "observe",
        "SCENE",
        "print what the robot perceives, as facts",
    ),
    (
        "truth",
        "SCENE",
        "print the measured relations, stability and occlusion",
    ),
    (
        "act",
        "SCENE ACTION",
        "execute pickup(R,O) or putdown(R,O,L), save the scene, print observations",
    ),
    ("step", "SCENE", "let physics run and save the scene"),
    (
        "render",
        "SCENE",
        "render the camera (or --top) view to PNG",
    ),
];

fn help() -> String {
    let mut out = String::from("Usage: lucent sim COMMAND [ARGS] [OPTIONS]\n\nCommands:\n");
    for (name, args, text) in COMMANDS {
        let _ = writeln!(out, "  {:<22} {text}", format!("{name} {args}"));
    }
    out.push_str("\nOptions:\n");
    for o in OPTIONS {
        let spelled = match o.value {
            Some(v) => format!("{} {v}", o.name),
            None => o.name.to_string(),
        };
        let _ = writeln!(
            out,
            "  {spelled:<22} {} [{}]",
            o.help,
            o.commands.join(", ")
        );
    }
    out.push_str(
        "\nExamples:\n  lucent sim generate --seed 7 --preset real -o scene.json\n  lucent sim observe scene.json\n  lucent sim act scene.json 'pickup(rob1,red_cube)'\n  lucent sim render scene.json -o scene.png\n",
    );
    out
}

/// Parsed arguments of one subcommand.
struct Args {
    /// The subcommand.
    command: String,
    /// Its positional arguments.
    positional: Vec<String>,
    /// Options in command-line order, with their values; the last occurrence wins.
    options: Vec<(&'static str, Option<String>)>,
}

impl Args {
    fn flag(&self, name: &str) -> bool {
        self.options.iter().any(|(n, _)| *n == name)
    }

    fn value(&self, name: &str) -> Option<&str> {
        self.options
            .iter()
            .rev()
            .find(|(n, _)| *n == name)
            .and_then(|(_, v)| v.as_deref())
    }

    fn number<T: std::str::FromStr>(&self, name: &str, default: T) -> Result<T, String> {
        match self.value(name) {
            None => Ok(default),
            Some(v) => v
                .parse()
                .map_err(|_| format!("{name} needs a number, got `{v}`")),
        }
    }

    fn probability(&self, name: &str, default: f64) -> Result<f64, String> {
        let p = self.number(name, default)?;
        if (0.0..=1.0).contains(&p) {
            Ok(p)
        } else {
            Err(format!("{name} needs a probability in [0, 1], got {p}"))
        }
    }
}

fn parse(args: &[String]) -> Result<Args, String> {
    let command = args.first().ok_or("missing command")?.clone();
    if !COMMANDS.iter().any(|(c, _, _)| *c == command) {
        return Err(format!("unknown command `{command}`"));
    }
    let mut parsed = Args {
        command,
        positional: Vec::new(),
        options: Vec::new(),
    };
    let mut rest = args[1..].iter();
    while let Some(arg) = rest.next() {
        if arg.starts_with('-') && arg.len() > 1 {
            let (name, inline) = match arg.split_once('=') {
                Some((n, v)) => (n, Some(v.to_string())),
                None => (arg.as_str(), None),
            };
            let spec = OPTIONS
                .iter()
                .find(|o| o.name == name && o.commands.contains(&parsed.command.as_str()))
                .ok_or_else(|| format!("unknown option `{name}` for `{}`", parsed.command))?;
            let value = match (spec.value, inline) {
                (None, None) => None,
                (None, Some(_)) => return Err(format!("{name} takes no value")),
                (Some(_), Some(v)) => Some(v),
                (Some(v), None) => Some(
                    rest.next()
                        .ok_or_else(|| format!("{name} needs a value {v}"))?
                        .clone(),
                ),
            };
            parsed.options.push((spec.name, value));
        } else {
            parsed.positional.push(arg.clone());
        }
    }
    let wanted = COMMANDS
        .iter()
        .find(|(c, _, _)| *c == parsed.command)
        .map(|(_, a, _)| a.split_whitespace().count())
        .unwrap_or(0);
    if parsed.positional.len() != wanted {
        return Err(format!(
            "`{}` takes {wanted} argument(s), got {}",
            parsed.command,
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
        relation_error: args.probability("--error-rate", 0.15).map_err(usage)?,
        size_error: args.probability("--size-error", 0.0).map_err(usage)?,
        threshold: args.probability("--threshold", 0.5).map_err(usage)?,
        ..ErrorModel::default()
    })
}

fn style(args: &Args) -> FactStyle {
    if args.flag("--holds") {
        FactStyle::Holds
    } else {
        FactStyle::Obs
    }
}

fn json<T: serde::Serialize>(value: &T) -> String {
    serde_json::to_string_pretty(value).expect("reports always serialise") + "\n"
}

fn run_command(args: &Args) -> Result<String, Fail> {
    match args.command.as_str() {
        "generate" => {
            let preset = Preset::parse(args.value("--preset").unwrap_or("simulated"))?;
            let mut config =
                GenerateConfig::new(preset, args.number("--seed", 0u64).map_err(usage)?);
            if args.value("--objects").is_some() {
                config.count = Some(args.number("--objects", 0usize).map_err(usage)?);
            }
            let scene = if args.flag("--risky") {
                crate::vision::scenes::generate_risky(&crate::vision::scenes::RiskyConfig {
                    preset: config.preset,
                    seed: config.seed,
                    count: config.count,
                })?
            } else {
                generate(&config)?
            };
            match args.value("-o") {
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
            if args.flag("--json") {
                Ok(json(&percept))
            } else {
                Ok(percept.to_program(style(args)))
            }
        }
        "truth" => {
            let scene = load(&args.positional[0])?;
            let truth = sim::measure(&scene, &TruthConfig::default());
            if args.flag("--json") {
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
                failure_rate: args.probability("--failure-rate", 0.15).map_err(usage)?,
                perception: error_model(args)?,
                ..ActConfig::default()
            };
            let report = sim::execute(&mut scene, &action, &config)?;
            save(args.value("-o").unwrap_or(path), scene.to_json().as_bytes())?;
            if args.flag("--json") {
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
            let seconds: f32 = args.number("--seconds", 2.0).map_err(usage)?;
            if !(0.0..=60.0).contains(&seconds) {
                return Err(usage(format!("--seconds needs 0 to 60, got {seconds}")));
            }
            let mut world = World::build(&scene);
            world.step_for(seconds);
            world.write_back(&mut scene);
            save(args.value("-o").unwrap_or(path), scene.to_json().as_bytes())?;
            Ok(format!("% stepped {path} for {seconds} s\n"))
        }
        "render" => {
            let scene = load(&args.positional[0])?;
            let out = args
                .value("-o")
                .ok_or_else(|| usage("render needs -o FILE".into()))?;
            let width: u32 = args.number("--width", 320).map_err(usage)?;
            let height: u32 = args.number("--height", 200).map_err(usage)?;
            if !(8..=4096).contains(&width) || !(8..=4096).contains(&height) {
                return Err(usage("image sides must be 8 to 4096 pixels".into()));
            }
            let image = if args.flag("--top") {
                render_top(&scene, width, height)
            } else if args.flag("--labelled") {
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
    if args.is_empty() || args.iter().any(|a| a == "--help" || a == "-h") || args[0] == "help" {
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
