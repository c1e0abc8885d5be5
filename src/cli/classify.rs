//! `lucent classify SCENE.json` and `lucent experiment classify`: scene understanding on the
//! command line. `classify` reads a simulator scene (as `lucent sim` writes it), looks at it
//! (renders the camera image, perceives, crops the regions of interest), trains the classifier
//! on generated scenes unless told not to, and prints each object's stability and occlusion with
//! the source of each decision; `experiment classify` runs the classification experiment and
//! writes its report.
//!
//! Invariants: files are read and written only here; a bad command line exits 1, an unreadable
//! or malformed scene 65; `--outf=2` prints JSON.

use std::io::Write;
use std::path::PathBuf;

use serde_json::json;

use super::options::{self, opt, Arg, Arity::*, OptionSpec, Verb};
use crate::experiment::classify::{self as exp, ClassifyConfig, REMOVED};
use crate::sim::Scene;
use crate::vision::classify::{reason_all, Classifier, System, TrainConfig};
use crate::vision::dataset;
use crate::vision::reason::{Knowledge, View};

/// `lucent classify`'s command line; `--help` is generated from it.
pub(super) const VERB: Verb = Verb {
    usage: "\
usage: lucent classify SCENE.json [--train N] [--seed N] [--why QUESTION]... [--outf=0|2]

Looks at a simulator scene (a file `lucent sim generate --out` writes): renders the camera
image, perceives relations and attributes, and decides for every object whether it is stable
(objects standing on another) and whether it is occluded. Reasoning decides first, with KB_full
less ST1, D1 and OC2 plus the state constraints learned from N generated training scenes; the
CNN (trained on the regions of interest reasoning failed on) decides where reasoning cannot.
Each decision names its source: reasoning, a learned constraint, or the CNN. The scene's own
physics labels are printed beside for comparison.
",
    options: OPTIONS,
    epilogue: "",
};

/// The options of `lucent classify`.
#[rustfmt::skip]
const OPTIONS: &[OptionSpec] = &[
    options::HELP,
    opt("train", None, Value, "N", "training scenes (default 200; 0: reasoning with KB_full only, no training)", "Options"),
    opt("seed", None, Value, "N", "seed of the training scenes and the learner (default 0)", "Options"),
    opt("why", None, Value, "Q", "answer a question about what the robot sees (\"why is the red cube unstable?\", \"why is the mug not occluded?\") from the proof tree of its reasoning, or say that the network decided; may be repeated", "Options"),
    opt("outf", None, Value, "N", "0: a table (default); 2: JSON", "Options"),
];

/// `lucent experiment classify`'s command line; `--help` is generated from it.
pub(super) const EXPERIMENT_VERB: Verb = Verb {
    usage: "\
usage: lucent experiment classify [--sizes 50,100,200,500,1000] [--test N] [--runs N]
                                  [--seed N] [--out DIR] [--outf=0|2]

The classification experiment: accuracy, precision and recall of stability and occlusion on
held-apart test scenes for training sets of the given sizes, for four systems (the CNN alone,
reasoning alone, reasoning with the CNN where it cannot decide, and that with learned state
constraints); the learning of the removed constraints (ST1, D1, OC2) over independent runs,
scored strictly and relaxed; and which constraints of KB_full decide the labels.
",
    options: EXPERIMENT_OPTIONS,
    epilogue: "",
};

/// The options of `lucent experiment classify`.
#[rustfmt::skip]
const EXPERIMENT_OPTIONS: &[OptionSpec] = &[
    options::HELP,
    opt("sizes", None, Value, "LIST", "training-set sizes in scenes (default 50,100,200,500,1000)", "Options"),
    opt("test", None, Value, "N", "test scenes (default 300)", "Options"),
    opt("runs", None, Value, "N", "learning runs (default 20)", "Options"),
    opt("seed", None, Value, "N", "the base seed (default 0)", "Options"),
    opt("out", None, Value, "DIR", "write DIR/classify.md, DIR/classify.json and the SVG plots", "Options"),
    opt("outf", None, Value, "N", "0: markdown (default); 2: JSON", "Options"),
];

/// The classification experiment's command line: its configuration, the report folder and
/// whether to print JSON.
fn parse_experiment(args: &[String]) -> Result<(ClassifyConfig, Option<PathBuf>, bool), String> {
    let mut config = ClassifyConfig::default();
    let (mut dir, mut json) = (None, false);
    for arg in options::scan(EXPERIMENT_OPTIONS, args) {
        let (spec, v) = match arg.map_err(|e| e.to_string())? {
            Arg::Option(spec, v) => (spec, v.unwrap_or_default()),
            Arg::Word(w) | Arg::Literal(w) => return Err(format!("unknown argument '{w}'")),
        };
        match spec.long {
            "sizes" => {
                config.sizes = v
                    .split(',')
                    .map(|x| x.trim().parse::<usize>())
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(|_| format!("'--sizes {v}': expected numbers separated by commas"))?
            }
            "test" => config.test_scenes = spec.number(&v)?,
            "runs" => config.runs = spec.number(&v)?,
            "seed" => {
                config.seed = spec.number(&v)?;
                config.train.seed = config.seed;
            }
            "out" => dir = Some(PathBuf::from(v)),
            "outf" => json = spec.outf(&v)?,
            _ => {} // --help, answered before parsing
        }
    }
    if config.sizes.is_empty() || config.test_scenes == 0 {
        return Err("the experiment needs at least one training size and one test scene".into());
    }
    Ok((config, dir, json))
}

/// `lucent experiment classify ...` (`args` after `classify`).
pub fn run_experiment(
    args: &[String],
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    let (config, dir, json) =
        match super::verb_args(&EXPERIMENT_VERB, args, parse_experiment, out, err)? {
            Ok(a) => a,
            Err(code) => return Ok(code),
        };
    let bar = super::progress::bar(exp::scene_count(&config) as u64, "scenes generated");
    let progress = |line: &str| bar.suspend(|| eprintln!("classify: {line}"));
    let result = exp::run(&config, &progress, &|| bar.inc(1));
    bar.finish_and_clear();
    let result = match result {
        Ok(r) => r,
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    write_result(&result, dir.as_deref(), json, out)?;
    Ok(0)
}

/// Writes the classification experiment's report files into `dir` (if given) and prints it.
pub fn write_result(
    result: &exp::ClassifyResult,
    dir: Option<&std::path::Path>,
    json: bool,
    out: &mut dyn Write,
) -> std::io::Result<()> {
    let markdown = exp::markdown(result);
    let value = serde_json::to_value(result).unwrap_or_default();
    if let Some(dir) = dir {
        std::fs::create_dir_all(dir)?;
        super::write_report_files(dir, "classify", &markdown, &value, exp::plots(result))?;
    }
    super::print_report(out, json, &markdown, &value)
}

/// `lucent classify`'s command line.
struct Args {
    file: Option<String>,
    train: usize,
    seed: u64,
    json: bool,
    questions: Vec<String>,
}

fn parse(args: &[String]) -> Result<Args, String> {
    let mut a = Args {
        file: None,
        train: 200,
        seed: 0,
        json: false,
        questions: Vec::new(),
    };
    for arg in options::scan(OPTIONS, args) {
        let (spec, v) = match arg.map_err(|e| e.to_string())? {
            Arg::Option(spec, v) => (spec, v.unwrap_or_default()),
            Arg::Word(w) | Arg::Literal(w) if a.file.is_none() => {
                a.file = Some(w);
                continue;
            }
            Arg::Word(_) | Arg::Literal(_) => return Err("one scene file, please".into()),
        };
        match spec.long {
            "train" => a.train = spec.number(&v)?,
            "seed" => a.seed = spec.number(&v)?,
            "why" => a.questions.push(v),
            "outf" => a.json = spec.outf(&v)?,
            _ => {} // --help, answered before parsing
        }
    }
    Ok(a)
}

/// `lucent classify SCENE.json ...`.
pub fn run_classify(
    args: &[String],
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    let Args {
        file,
        train,
        seed,
        json,
        questions,
    } = match super::verb_args(&VERB, args, parse, out, err)? {
        Ok(a) => a,
        Err(code) => return Ok(code),
    };
    let Some(file) = file else {
        write!(err, "{}", VERB.help())?;
        return Ok(super::EXIT_USAGE);
    };
    let text = match std::fs::read_to_string(&file) {
        Ok(t) => t,
        Err(e) => {
            writeln!(err, "{file}:1:1: error: cannot read the scene: {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    let scene = match Scene::from_json(&text) {
        Ok(s) => s,
        Err(e) => {
            writeln!(err, "{file}:1:1: error: {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    let config = crate::experiment::classify::classification_dataset();
    let looked = match dataset::labelled_from(&config, scene) {
        Ok(l) => l,
        Err(e) => {
            writeln!(err, "{file}:1:1: error: {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    let (classifier, knowledge_only) = if train == 0 {
        let k = Knowledge::kb_full();
        let c = Classifier::train(System::Reasoning, &k, &[], &TrainConfig::default());
        (c, true)
    } else {
        let base = seed.wrapping_mul(10_000_000);
        let bar = super::progress::bar(train as u64, "training scenes generated");
        let scenes = dataset::generate_with(&config, base..base + train as u64, &|| bar.inc(1));
        bar.finish_and_clear();
        let incomplete = Knowledge::kb_full().without(&REMOVED);
        let reasoned = match reason_all(&incomplete, &scenes) {
            Ok(r) => r,
            Err(e) => {
                writeln!(err, "*** ERROR: (lucent): {e}")?;
                return Ok(super::EXIT_INPUT);
            }
        };
        let tc = TrainConfig {
            seed,
            ..TrainConfig::default()
        };
        (
            Classifier::train(System::ReasoningCnnLearned, &incomplete, &reasoned, &tc),
            false,
        )
    };
    let classifier = match classifier {
        Ok(c) => c,
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    let view = View::from_percept(&looked.scene, &looked.percept);
    let decisions = match crate::vision::classify::explain_scene(&classifier, &view, &looked) {
        Ok(d) => d,
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    let lexicon = crate::explain::lexicon::Lexicon::ra();
    let decided = |object: &str, label: &str| {
        let d = decisions.iter().find(|d| d.name == object)?;
        match label {
            "stability" => d.stable.clone(),
            "occlusion" => Some(d.occluded.clone()),
            _ => None,
        }
    };
    let mut answers = Vec::new();
    for q in &questions {
        let text =
            match crate::explain::scene::why(&classifier.knowledge, &view, q, &lexicon, &decided) {
                Ok(a) => a.text,
                Err(e) => e.to_string(),
            };
        answers.push((q.clone(), text));
    }
    if json {
        let objects: Vec<_> = decisions
            .iter()
            .map(|d| {
                json!({
                    "object": d.name,
                    "stable": d.stable.as_ref().map(|x| json!({"value": x.value, "source": x.source.words()})),
                    "occluded": {"value": d.occluded.value, "source": d.occluded.source.words()},
                    "truth": {"stable": d.true_stable, "occluded": d.true_occluded},
                })
            })
            .collect();
        let learned: Vec<_> = classifier
            .learned
            .iter()
            .map(|(l, a, v)| json!({"label": l, "axiom": a.to_ald(), "votes": v}))
            .collect();
        let value = json!({
            "Solver": "lucent classify",
            "Scene": file,
            "Knowledge": if knowledge_only { "KB_full" } else { "KB_full less ST1, D1, OC2, plus learned" },
            "Learned": learned,
            "Objects": objects,
            "Answers": answers.iter().map(|(q, a)| json!({"question": q, "answer": a})).collect::<Vec<_>>(),
        });
        writeln!(
            out,
            "{}",
            serde_json::to_string_pretty(&value).unwrap_or_default()
        )?;
        return Ok(0);
    }
    for (l, a, v) in &classifier.learned {
        writeln!(out, "learned {l}: {} ({v} votes)", a.to_ald())?;
    }
    writeln!(
        out,
        "{:<24} {:<34} {:<36} physics",
        "object", "stability", "occlusion"
    )?;
    for d in &decisions {
        let st = match &d.stable {
            Some(x) => format!(
                "{} ({})",
                if x.value { "stable" } else { "unstable" },
                x.source.words()
            ),
            None => "on the table".into(),
        };
        let oc = format!(
            "{} ({})",
            if d.occluded.value {
                "occluded"
            } else {
                "visible"
            },
            d.occluded.source.words()
        );
        let truth = format!(
            "{}{}",
            match d.true_stable {
                Some(true) => "stable, ",
                Some(false) => "unstable, ",
                None => "",
            },
            if d.true_occluded {
                "occluded"
            } else {
                "visible"
            }
        );
        writeln!(out, "{:<24} {:<34} {:<36} {truth}", d.name, st, oc)?;
    }
    for (q, a) in &answers {
        writeln!(out, "\n> {q}\n{a}")?;
    }
    Ok(0)
}
