//! `lucent learn` (one learning run, docs/domain.md 5.2): the knowledge base is read here (also for
//! `lucent experiment`, `cli::experiment`), everything else is `learn`.
//!
//! Invariants: files are read and written only here; bad AL_d input is a gringo-style
//! diagnostic and exit code 65, a bad command line exit code 1; the results are functions of
//! the seed (the progress bar goes to standard error, and only on a terminal).

use std::io::Write;
use std::time::Instant;

use crate::action;
use crate::base::SourceMap;
use crate::learn::episode::LearnConfig;
use crate::learn::h1;
use crate::learn::kb::KbSpec;

use super::options::{self, opt, Arg, Arity::*, OptionSpec, Verb};

/// `lucent learn`'s command line; `--help` is generated from it.
pub(super) const VERB: Verb = Verb {
    usage: "\
usage: lucent learn [--kb FILE.ald] [--seed N] [--run I] [--episodes N] [-o FILE] [--tables DIR]
                    [--oracle kb_full|physics] [--outf=0|2]

One axiom-learning run (docs/domain.md section 5): random one-step trials against the oracle
(KB_full with the learner's switches), a learner knowledge base with the `learner` profile,
and after each surprise a 100-tree ensemble whose kept axioms join the learner at once.
Prints what was learned, when and from which surprise; -o writes the learned axioms as an
AL_d file with their strengths.
",
    options: OPTIONS,
    epilogue: "",
};

/// The options of `lucent learn`; `lucent experiment` shares the learner's rows.
#[rustfmt::skip]
const OPTIONS: &[OptionSpec] = &[
    options::HELP,
    KB,
    SEED,
    opt("run", None, Value, "I", "run I of `lucent experiment h1 --seed N` (default 0)", "Options"),
    EPISODES,
    opt("output", Some('o'), Value, "FILE", "write the learned axioms as an AL_d file with their strengths", "Options"),
    opt("tables", None, Value, "DIR", "write each episode's feature table (the lifted samples the trees were trained on) to DIR/episode-N.csv: one column per feature, then the label", "Options"),
    CODE_BALANCE,
    CODE_SAMPLES,
    COUNT_EVERY_TRIAL,
    ORACLE,
    opt("outf", None, Value, "N", "0: text (default); 2: JSON", "Options"),
];

/// `--kb`, shared with `lucent experiment`.
#[rustfmt::skip]
pub(super) const KB: OptionSpec = opt("kb", None, Value, "FILE.ald", "the learner's knowledge base, H1's (default domains/ra/scenes/h1.ald)", "Options");
/// `--seed`, shared with `lucent experiment`.
#[rustfmt::skip]
pub(super) const SEED: OptionSpec = opt("seed", None, Value, "N", "the recorded seed (default 0)", "Options");
/// `--episodes`, shared with `lucent experiment`.
#[rustfmt::skip]
pub(super) const EPISODES: OptionSpec = opt("episodes", None, Value, "N", "episodes per learning run (default 10)", "Options");
/// `--code-balance`, shared with `lucent experiment`.
#[rustfmt::skip]
pub(super) const CODE_BALANCE: OptionSpec = opt("code-balance", None, Flag, "", "H1: store capped inconsistent trials with label 0, as the authors' code does", "Options");
/// `--code-samples`, shared with `lucent experiment`.
#[rustfmt::skip]
pub(super) const CODE_SAMPLES: OptionSpec = opt("code-samples", None, Flag, "", "H1: take samples from every trial, as the authors' code does", "Options");
/// `--count-every-trial`, shared with `lucent experiment`.
#[rustfmt::skip]
pub(super) const COUNT_EVERY_TRIAL: OptionSpec = opt("count-every-trial", None, Flag, "", "H1: end a run after 100 quiet trials of any kind (docs/domain.md 5.2 as written); by default only trials whose action the learner takes to be executable count", "Options");
/// `--oracle`, shared with `lucent experiment`.
#[rustfmt::skip]
pub(super) const ORACLE: OptionSpec = opt("oracle", None, Value, "NAME", "H1's oracle: kb_full (default) or physics, the physics world (feature `sim`); `lucent experiment` reasons in H2 and H4 with the axioms learned against it", "Options");

/// The oracle `--oracle` names, if this build has it.
pub(super) fn oracle(spec: &OptionSpec, name: &str) -> Result<h1::Oracle, String> {
    let oracle = h1::Oracle::parse(name)
        .ok_or_else(|| format!("'{} {name}': expected kb_full or physics", spec.spelled()))?;
    oracle.availability()?;
    Ok(oracle)
}

struct Args {
    kb: String,
    seed: u64,
    run: usize,
    episodes: Option<usize>,
    output: Option<String>,
    tables: Option<String>,
    json: bool,
    code_balance: bool,
    code_samples: bool,
    count_every_trial: bool,
    oracle: h1::Oracle,
}

fn parse(args: &[String]) -> Result<Args, String> {
    let mut out = Args {
        kb: "domains/ra/scenes/h1.ald".into(),
        seed: 0,
        run: 0,
        episodes: None,
        output: None,
        tables: None,
        json: false,
        code_balance: false,
        code_samples: false,
        count_every_trial: false,
        oracle: h1::Oracle::KbFull,
    };
    for arg in options::scan(OPTIONS, args) {
        let (spec, v) = match arg.map_err(|e| e.to_string())? {
            Arg::Option(spec, v) => (spec, v.unwrap_or_default()),
            Arg::Word(w) | Arg::Literal(w) => return Err(format!("unknown argument '{w}'")),
        };
        match spec.long {
            "kb" => out.kb = v,
            "seed" => out.seed = spec.number(&v)?,
            "run" => out.run = spec.number(&v)?,
            "episodes" => out.episodes = Some(spec.number(&v)?),
            "output" => out.output = Some(v),
            "tables" => out.tables = Some(v),
            "outf" => out.json = v == "2",
            "code-balance" => out.code_balance = true,
            "code-samples" => out.code_samples = true,
            "count-every-trial" => out.count_every_trial = true,
            "oracle" => out.oracle = oracle(spec, &v)?,
            _ => {} // --help, answered before parsing
        }
    }
    Ok(out)
}

fn config(args: &Args) -> LearnConfig {
    let mut c = LearnConfig::default();
    if let Some(e) = args.episodes {
        c.episodes = e;
    }
    c.collect.balance_fix = !args.code_balance;
    c.collect.informative_only = !args.code_samples;
    c.count_every_trial = args.count_every_trial;
    c
}

/// Reads and parses the knowledge base; diagnostics go to `err`.
pub(super) fn load(path: &str, err: &mut dyn Write) -> std::io::Result<Option<KbSpec>> {
    let text = match super::builtin::read_to_string(path) {
        Ok(t) => t,
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {path}: {e}")?;
            return Ok(None);
        }
    };
    let mut sources = SourceMap::new();
    let file = sources.add(path.to_string(), text);
    let mut read =
        |p: &std::path::Path| super::builtin::read_to_string(p).map_err(|e| e.to_string());
    let parsed = action::load(&mut sources, file, &mut read);
    if parsed.has_errors() {
        let mut diags = crate::base::Diagnostics::default();
        diags.extend(parsed.diagnostics);
        write!(err, "{}", diags.render(&sources))?;
        return Ok(None);
    }
    Ok(Some(KbSpec {
        description: parsed.description,
        options: h1::learner_options(),
        sources,
    }))
}

/// `lucent learn`.
pub fn run_learn(
    args: &[String],
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    let args = match super::verb_args(&VERB, args, parse, out, err)? {
        Ok(a) => a,
        Err(code) => return Ok(code),
    };
    let Some(spec) = load(&args.kb, err)? else {
        return Ok(super::EXIT_INPUT);
    };
    let start = Instant::now();
    let mut learn_config = config(&args);
    // A bar over the episodes: a run ends early once it detects nothing new.
    let progress = super::progress::bar(learn_config.episodes as u64, "episodes");
    progress.set_message("learning");
    let bar = progress.clone();
    learn_config.on_episode =
        crate::learn::episode::EpisodeObserver(Some(std::sync::Arc::new(move |e| {
            bar.set_position(e as u64)
        })));
    let report = h1::one_run_with(
        &spec,
        &learn_config,
        h1::run_seed(args.seed, args.run),
        args.oracle,
        &h1::Caches::default(),
    );
    progress.finish_and_clear();
    let report = match report {
        Ok(r) => r,
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    let found = report.store.current();
    let targets = h1::targets();
    let s = crate::learn::score::strict(&found, &targets);
    let x = crate::learn::score::relaxed(&found, &targets);
    if args.json {
        let episodes: Vec<serde_json::Value> = report
            .episodes
            .iter()
            .map(|e| {
                serde_json::json!({
                    "episode": e.episode,
                    "detected_at": e.detected_at,
                    "surprise": e.surprise,
                    "dataset": e.dataset.map(|d| format!("{d:?}")),
                    "samples": e.samples.0,
                    "positives": e.samples.1,
                    "collect_trials": e.collect_trials,
                    "learned": e.learned.iter().map(|(a, v, new)| serde_json::json!({"axiom": a, "votes": v, "new": new})).collect::<Vec<_>>(),
                    "removed": e.removed,
                })
            })
            .collect();
        let json = serde_json::json!({
            "seed": args.seed,
            "run": args.run,
            "episodes": episodes,
            "learned": report.store.axioms.iter().map(|l| serde_json::json!({
                "label": l.label, "axiom": l.axiom.short(), "ald": l.axiom.to_ald(),
                "strength": l.strength, "votes": l.votes, "episode": l.origin.episode,
                "surprise": l.origin.surprise,
            })).collect::<Vec<_>>(),
            "trials": report.trials,
            "strict": {"precision": s.precision(), "recall": s.recall()},
            "relaxed": {"precision": x.precision(), "recall": x.recall()},
        });
        writeln!(
            out,
            "{}",
            serde_json::to_string_pretty(&json).unwrap_or_default()
        )?;
    } else {
        writeln!(
            out,
            "Learning run {} (seed {}): {} trials",
            args.run, args.seed, report.trials
        )?;
        for e in &report.episodes {
            match e.detected_at {
                None => writeln!(
                    out,
                    "episode {}: no surprise in 100 quiet trials; the run ends",
                    e.episode
                )?,
                Some(t) => {
                    writeln!(
                        out,
                        "episode {}: surprise at trial {t}: {}",
                        e.episode, e.surprise
                    )?;
                    if let Some(d) = e.dataset {
                        writeln!(
                            out,
                            "  {d:?} dataset: {} samples ({} positive) from {} trials",
                            e.samples.0, e.samples.1, e.collect_trials
                        )?;
                    } else {
                        writeln!(out, "  no dataset filled in {} trials", e.collect_trials)?;
                    }
                    for (a, votes, new) in &e.learned {
                        let what = if *new { "learned" } else { "relearned" };
                        writeln!(out, "  {what}: {a}  ({votes} of 100 trees)")?;
                    }
                    for l in &e.removed {
                        writeln!(out, "  removed {l} (strength below 0.1)")?;
                    }
                }
            }
        }
        writeln!(out, "Learned axioms:")?;
        for l in &report.store.axioms {
            writeln!(
                out,
                "  {}: {}  (strength {:.3})",
                l.label,
                l.axiom.short(),
                l.strength
            )?;
        }
        writeln!(
            out,
            "Against the H1 targets: strict P {:.1}% R {:.1}%, relaxed P {:.1}% R {:.1}%",
            s.precision(),
            s.recall(),
            x.precision(),
            x.recall()
        )?;
        writeln!(out, "Time: {:.2}s", start.elapsed().as_secs_f64())?;
    }
    if let Some(dir) = &args.tables {
        if let Err(e) = write_tables(dir, &report.episodes) {
            writeln!(err, "*** ERROR: (lucent): {dir}: {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    }
    if let Some(path) = &args.output {
        if let Err(e) = std::fs::write(path, report.store.to_ald()) {
            writeln!(err, "*** ERROR: (lucent): {path}: {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    }
    Ok(0)
}

/// Writes every episode's feature table as `DIR/episode-N.csv`: a header of the feature
/// literals (short form) and `label`, then one row of 0/1 per sample.
fn write_tables(
    dir: &str,
    episodes: &[crate::learn::episode::EpisodeReport],
) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    for e in episodes {
        let Some((features, table)) = &e.table else {
            continue;
        };
        let quote = |t: String| format!("\"{}\"", t.replace('"', "\"\""));
        let mut text: Vec<String> = vec![features
            .iter()
            .map(|f| quote(f.short()))
            .chain(std::iter::once("label".to_string()))
            .collect::<Vec<_>>()
            .join(",")];
        for (row, label) in table.rows.iter().zip(&table.labels) {
            text.push(
                row.iter()
                    .chain(std::iter::once(label))
                    .map(|&b| if b { "1" } else { "0" })
                    .collect::<Vec<_>>()
                    .join(","),
            );
        }
        let path = std::path::Path::new(dir).join(format!("episode-{}.csv", e.episode));
        std::fs::write(path, text.join("\n") + "\n")?;
    }
    Ok(())
}
