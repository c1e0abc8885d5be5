//! `lucent experiment h1|h2|h3|h4|all`, `lucent experiment trial ID` and `lucent experiment
//! merge DIR`: the H1-H4 harness of [`crate::experiment`] on the command line, with the result
//! files, the job list for GNU parallel or a Slurm array, the report files and the progress bar.
//!
//! Invariants: files are read and written only here. A run directory holds `run.json` (the
//! setup, the hypotheses, and the absolute paths of the H1 knowledge base and the H2-H4
//! domain), `results/<id>.json` (one per trial, written under a temporary name and renamed, so
//! a killed run never leaves half a file),
//! and the report (`report.md`, `report.json`, the SVG plots). Bad AL_d input is a gringo-style
//! diagnostic and exit 65, a bad command line exit 1; missing trials in `merge` are named and
//! exit 65. The progress bar goes to standard error, only on a terminal; one summary line
//! (trials computed and reused, wall time) always goes to standard error.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

use serde_json::{json, Value};

use super::learn;
use super::options::{self, opt, Arg, Arity::*, OptionSpec, Verb};
use crate::experiment::report::Report;
use crate::experiment::{
    self, Context, Domain, Hypothesis, MemoryStore, Progress, Setup, Store, Trial,
};

/// `lucent experiment`'s command line; `--help` is generated from it.
pub(super) const VERB: Verb = Verb {
    usage: "\
usage: lucent experiment h1|h2|h3|h4|all [OPTIONS]
       lucent experiment classify [OPTIONS]   (scene understanding; `classify --help`)
       lucent experiment trial ID --out DIR
       lucent experiment merge DIR [DIR...] [--out OUT] [--outf=0|2]

The paper's experiments (docs/domain.md 7): H1 learning accuracy (Table 1), H2 plan quality
(Tables 2 and 3), H3 proof-tree checks, H4 explanation precision and recall (Tables 4 and 5).
Trials run in parallel (rayon); every table is printed beside the paper's, every figure with
its 95% bootstrap interval. A hypothesis whose pieces this build lacks is reported as \"not
available: <reason>\". `merge` of several run directories (one per seed, same setup otherwise)
pools their trials into one report, written to OUT when given.
",
    options: OPTIONS,
    epilogue: "",
};

/// The options of `lucent experiment`, the learner's shared with `lucent learn`.
#[rustfmt::skip]
const OPTIONS: &[OptionSpec] = &[
    options::HELP,
    learn::SEED,
    opt("runs", None, Value, "N", "H1 learning runs (default 20)", "Options"),
    opt("configurations", None, Value, "N", "scene configurations per preset for H2-H4 (default 20)", "Options"),
    opt("goals", None, Value, "N", "goals per configuration (default 5)", "Options"),
    learn::EPISODES,
    learn::KB,
    opt("domain", None, Value, "FILE.ald", "the H2-H4 domain that generated scenes include (default domains/ra/kb_full.ald)", "Options"),
    learn::CODE_BALANCE,
    learn::CODE_SAMPLES,
    learn::COUNT_EVERY_TRIAL,
    learn::ORACLE,
    opt("out", None, Value, "DIR", "keep one result file per trial in DIR/results (a rerun reuses them) and write DIR/report.md, DIR/report.json and the SVG plots", "Options"),
    opt("emit-jobs", None, Value, "FILE", "with --out: write one `lucent experiment trial ID --out DIR` line per trial to FILE (for `parallel < FILE` or a Slurm array) and run nothing; then `lucent experiment merge DIR` makes the report", "Options"),
    opt("outf", None, Value, "N", "0: the markdown report (default); 2: JSON, one key per hypothesis", "Options"),
    opt("no-classify", None, Flag, "", "`all` without the classification experiment (which `all` otherwise runs after H1-H4, with --seed and --runs, writing DIR/classify.md; with --outf=2 it prints a second JSON document, the classification result)", "Options"),
];

/// The parsed command line.
struct Args {
    hypotheses: Vec<Hypothesis>,
    setup: Setup,
    kb: String,
    domain: String,
    out: Option<PathBuf>,
    emit_jobs: Option<PathBuf>,
    json: bool,
    no_classify: bool,
}

/// What the run directory's `run.json` records.
fn run_file(setup: &Setup, hypotheses: &[Hypothesis], kb: &str, domain: &str) -> Value {
    json!({
        "setup": setup,
        "hypotheses": hypotheses.iter().map(|h| h.name()).collect::<Vec<_>>(),
        "kb": kb,
        "domain": domain,
    })
}

/// The absolute form of `path` when it exists (job lines run from any directory).
fn absolute(path: &str) -> String {
    std::fs::canonicalize(path)
        .map(|p| p.display().to_string())
        .unwrap_or_else(|_| path.to_string())
}

/// Reads the H2-H4 domain.
fn read_domain(path: &str, err: &mut dyn Write) -> std::io::Result<Option<Domain>> {
    match super::builtin::read_to_string(path) {
        Ok(text) => Ok(Some(Domain {
            path: path.to_string(),
            text,
        })),
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {path}: {e}")?;
            Ok(None)
        }
    }
}

fn parse(args: &[String]) -> Result<(Args, Vec<String>), String> {
    let mut out = Args {
        hypotheses: Vec::new(),
        setup: Setup::paper(0),
        kb: "domains/ra/scenes/h1.ald".into(),
        domain: "domains/ra/kb_full.ald".into(),
        out: None,
        emit_jobs: None,
        json: false,
        no_classify: false,
    };
    let mut positional = Vec::new();
    for arg in options::scan(OPTIONS, args) {
        let (spec, v) = match arg.map_err(|e| e.to_string())? {
            Arg::Option(spec, v) => (spec, v.unwrap_or_default()),
            Arg::Word(w) | Arg::Literal(w) => {
                positional.push(w);
                continue;
            }
        };
        match spec.long {
            "seed" => out.setup.seed = spec.number(&v)?,
            "runs" => out.setup.runs = spec.number(&v)?,
            "configurations" => out.setup.configurations = spec.number(&v)?,
            "goals" => out.setup.goals = spec.number(&v)?,
            "episodes" => out.setup.episodes = spec.number(&v)?,
            "kb" => out.kb = v,
            "domain" => out.domain = v,
            "code-balance" => out.setup.code_balance = true,
            "code-samples" => out.setup.code_samples = true,
            "count-every-trial" => out.setup.count_every_trial = true,
            "oracle" => out.setup.oracle = learn::oracle(spec, &v)?,
            "out" => out.out = Some(PathBuf::from(v)),
            "no-classify" => out.no_classify = true,
            "emit-jobs" => out.emit_jobs = Some(PathBuf::from(v)),
            "outf" => out.json = spec.outf(&v)?,
            _ => {} // --help, answered before parsing
        }
    }
    Ok((out, positional))
}

/// Results as files `DIR/results/<id>.json`.
struct DirStore {
    dir: PathBuf,
}

impl DirStore {
    fn new(run_dir: &Path) -> std::io::Result<DirStore> {
        let dir = run_dir.join("results");
        std::fs::create_dir_all(&dir)?;
        Ok(DirStore { dir })
    }

    /// Every stored text, by id.
    fn all(&self) -> std::io::Result<Vec<(String, String)>> {
        let mut out = Vec::new();
        for entry in std::fs::read_dir(&self.dir)? {
            let path = entry?.path();
            let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
                continue;
            };
            if let Some(id) = name.strip_suffix(".json") {
                if !id.starts_with('.') {
                    out.push((id.to_string(), std::fs::read_to_string(&path)?));
                }
            }
        }
        out.sort();
        Ok(out)
    }
}

impl Store for DirStore {
    fn load(&self, id: &str) -> Option<String> {
        std::fs::read_to_string(self.dir.join(format!("{id}.json"))).ok()
    }

    fn save(&self, id: &str, text: &str) -> Result<(), String> {
        // A name no other writer uses, then an atomic rename: a killed process leaves at most
        // a temporary file, and two processes computing the same trial write the same text.
        let tmp = self.dir.join(format!(
            ".{id}.{}.{:?}.tmp",
            std::process::id(),
            std::thread::current().id()
        ));
        let target = self.dir.join(format!("{id}.json"));
        std::fs::write(&tmp, text)
            .and_then(|()| std::fs::rename(&tmp, &target))
            .map_err(|e| format!("{}: {e}", target.display()))
    }
}

fn error(err: &mut dyn Write, message: &str, code: i32) -> std::io::Result<i32> {
    writeln!(err, "*** ERROR: (lucent): {message}")?;
    Ok(code)
}

/// `lucent experiment`.
pub fn run_experiment(
    args: &[String],
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    // `experiment classify --help` is classify's own help.
    #[cfg(feature = "sim")]
    if args.first().map(String::as_str) == Some("classify") {
        return super::classify::run_experiment(&args[1..], out, err);
    }
    if args.is_empty() || VERB.asks_for_help(args) {
        write!(out, "{}", VERB.help())?;
        return Ok(if args.is_empty() {
            super::EXIT_USAGE
        } else {
            0
        });
    }
    let (mut parsed, positional) = match parse(args) {
        Ok(p) => p,
        Err(e) => return error(err, &e, super::EXIT_USAGE),
    };
    match positional.first().map(String::as_str) {
        Some("merge") => {
            let dirs: Vec<&Path> = positional[1..].iter().map(Path::new).collect();
            match dirs.as_slice() {
                [] => {
                    return error(
                        err,
                        "usage: lucent experiment merge DIR [DIR...] [--out OUT]",
                        super::EXIT_USAGE,
                    )
                }
                [dir] if parsed.out.is_none() => return merge(dir, parsed.json, out, err),
                _ => return merge_seeds(&dirs, parsed.out.as_deref(), parsed.json, out, err),
            }
        }
        Some("trial") => {
            let ([_, id], Some(dir)) = (positional.as_slice(), parsed.out.as_deref()) else {
                return error(
                    err,
                    "usage: lucent experiment trial ID --out DIR",
                    super::EXIT_USAGE,
                );
            };
            return trial(id, dir, err);
        }
        _ => {}
    }
    for p in &positional {
        match p.as_str() {
            "all" => parsed.hypotheses.extend(Hypothesis::ALL),
            _ => match Hypothesis::parse(p) {
                Some(h) => parsed.hypotheses.push(h),
                None => {
                    return error(
                        err,
                        &format!("unknown experiment '{p}' (h1, h2, h3, h4, all, trial, merge)"),
                        super::EXIT_USAGE,
                    )
                }
            },
        }
    }
    parsed.hypotheses.sort();
    parsed.hypotheses.dedup();
    if parsed.hypotheses.is_empty() {
        return error(
            err,
            "which experiment? (h1, h2, h3, h4 or all)",
            super::EXIT_USAGE,
        );
    }
    let kb_path = absolute(&parsed.kb);
    let Some(kb) = super::learn::load(&kb_path, err)? else {
        return Ok(super::EXIT_INPUT);
    };
    let domain_path = absolute(&parsed.domain);
    let Some(domain) = read_domain(&domain_path, err)? else {
        return Ok(super::EXIT_INPUT);
    };
    let trials = experiment::trials(&parsed.setup, &parsed.hypotheses);
    if let Some(dir) = &parsed.out {
        std::fs::create_dir_all(dir)?;
        let run = run_file(&parsed.setup, &parsed.hypotheses, &kb_path, &domain_path);
        std::fs::write(
            dir.join("run.json"),
            serde_json::to_string_pretty(&run).unwrap_or_default() + "\n",
        )?;
    }
    if let Some(jobs) = &parsed.emit_jobs {
        let Some(dir) = &parsed.out else {
            return error(err, "--emit-jobs needs --out DIR", super::EXIT_USAGE);
        };
        return emit_jobs(jobs, dir, &trials, err);
    }
    let memory = MemoryStore::default();
    let dir_store = match &parsed.out {
        Some(d) => Some(DirStore::new(d)?),
        None => None,
    };
    let store: &dyn Store = match &dir_store {
        Some(d) => d,
        None => &memory,
    };
    let ctx = Context {
        setup: parsed.setup.clone(),
        kb: &kb,
        domain: &domain,
        store,
        caches: Default::default(),
    };
    let start = Instant::now();
    let bar = super::progress::bar(trials.len() as u64, "trials");
    let reused = std::sync::atomic::AtomicUsize::new(0);
    let progress = |p: Progress| {
        reused.store(p.reused, std::sync::atomic::Ordering::SeqCst);
        bar.set_position(p.done as u64);
        bar.set_message(format!("({} reused)", p.reused));
    };
    let records = match experiment::run(&ctx, &trials, &progress) {
        Ok(r) => r,
        Err(e) => return error(err, &e.to_string(), super::EXIT_INPUT),
    };
    bar.finish_and_clear();
    let secs = start.elapsed().as_secs_f64();
    let reused = reused.into_inner();
    writeln!(
        err,
        "experiment: {} trials, {} computed, {reused} reused, {secs:.1} s",
        records.len(),
        records.len() - reused
    )?;
    let report = match Report::new(&parsed.setup, &parsed.hypotheses, &records) {
        Ok(r) => r,
        Err(e) => return error(err, &e, super::EXIT_INPUT),
    };
    #[cfg(feature = "sim")]
    let classify = if positional.iter().any(|p| p == "all") && !parsed.no_classify {
        let config = crate::experiment::classify::ClassifyConfig {
            seed: parsed.setup.seed,
            runs: parsed.setup.runs,
            ..Default::default()
        };
        let bar = super::progress::bar(
            crate::experiment::classify::scene_count(&config) as u64,
            "scenes generated",
        );
        let progress = |line: &str| bar.suspend(|| eprintln!("classify: {line}"));
        let result = crate::experiment::classify::run(&config, &progress, &|| bar.inc(1));
        bar.finish_and_clear();
        match result {
            Ok(r) => Some(r),
            Err(e) => return error(err, &e, super::EXIT_INPUT),
        }
    } else {
        None
    };
    let code = finish(&report, parsed.out.as_deref(), parsed.json, Some(secs), out)?;
    #[cfg(feature = "sim")]
    if let Some(result) = classify {
        super::classify::write_result(&result, parsed.out.as_deref(), parsed.json, out)?;
    }
    Ok(code)
}

/// Writes the report files (with `dir`) and prints the report.
fn finish(
    report: &Report,
    dir: Option<&Path>,
    json: bool,
    secs: Option<f64>,
    out: &mut dyn Write,
) -> std::io::Result<i32> {
    let mut value = report.to_json();
    // `lucent experiment h1` of issue 15 printed H1's keys at the top: kept for that command.
    if let [Hypothesis::H1] = report_hypotheses(report).as_slice() {
        if let Some(Value::Object(h1)) = value.get("h1").cloned() {
            for (k, v) in h1 {
                value[k.as_str()] = v;
            }
        }
        value["seed"] = report.setup.seed.into();
    }
    if let Some(s) = secs {
        value["time"] = s.into();
    }
    let markdown = report.to_markdown();
    if let Some(dir) = dir {
        super::write_report_files(dir, "report", &markdown, &value, report.plots())?;
    }
    super::print_report(out, json, &markdown, &value)?;
    if !json {
        if let Some(s) = secs {
            writeln!(out, "Wall time: {s:.1} s")?;
        }
    }
    Ok(0)
}

fn report_hypotheses(report: &Report) -> Vec<Hypothesis> {
    use crate::experiment::report::Section;
    report
        .sections
        .iter()
        .map(|s| match s {
            Section::H1(_) => Hypothesis::H1,
            Section::H2(_) => Hypothesis::H2,
            Section::H3(_) => Hypothesis::H3,
            Section::H4(_) => Hypothesis::H4,
            Section::NotAvailable(h, _) => *h,
        })
        .collect()
}

/// Quotes a word for a POSIX shell.
fn shell_quote(s: &str) -> String {
    if !s.is_empty()
        && s.chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./=:,+@".contains(c))
    {
        s.to_string()
    } else {
        format!("'{}'", s.replace('\'', "'\\''"))
    }
}

/// `--emit-jobs FILE`: one command line per trial, H1 first.
fn emit_jobs(
    jobs: &Path,
    dir: &Path,
    trials: &[Trial],
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    let exe = std::env::current_exe()?;
    let dir = std::fs::canonicalize(dir)?;
    let (exe, dir) = (
        shell_quote(&exe.display().to_string()),
        shell_quote(&dir.display().to_string()),
    );
    let mut ordered: Vec<&Trial> = trials.iter().collect();
    ordered.sort_by_key(|t| (t.hypothesis, t.id()));
    let mut text = String::new();
    for t in ordered {
        text.push_str(&format!("{exe} experiment trial {} --out {dir}\n", t.id()));
    }
    std::fs::write(jobs, text)?;
    writeln!(
        err,
        "experiment: {} jobs written to {}; run them (e.g. `parallel < {}`), then \
         `lucent experiment merge {}`",
        trials.len(),
        jobs.display(),
        jobs.display(),
        dir
    )?;
    Ok(0)
}

/// Reads `DIR/run.json`: setup, hypotheses, knowledge-base and domain paths.
fn read_run(dir: &Path) -> Result<(Setup, Vec<Hypothesis>, String, String), String> {
    let path = dir.join("run.json");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
    let v: Value = serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?;
    let setup: Setup = serde_json::from_value(v["setup"].clone())
        .map_err(|e| format!("{}: setup: {e}", path.display()))?;
    let hypotheses = v["hypotheses"]
        .as_array()
        .map(|a| {
            a.iter()
                .filter_map(|h| h.as_str().and_then(Hypothesis::parse))
                .collect()
        })
        .unwrap_or_default();
    let kb = v["kb"].as_str().unwrap_or_default().to_string();
    let domain = v["domain"].as_str().unwrap_or_default().to_string();
    Ok((setup, hypotheses, kb, domain))
}

/// `lucent experiment trial ID --out DIR`: one job of the list.
fn trial(id: &str, dir: &Path, err: &mut dyn Write) -> std::io::Result<i32> {
    let Some(trial) = Trial::parse_id(id) else {
        return error(err, &format!("'{id}' is not a trial id"), super::EXIT_USAGE);
    };
    let (setup, _, kb_path, domain_path) = match read_run(dir) {
        Ok(r) => r,
        Err(e) => return error(err, &e, super::EXIT_INPUT),
    };
    let Some(kb) = super::learn::load(&kb_path, err)? else {
        return Ok(super::EXIT_INPUT);
    };
    let Some(domain) = read_domain(&domain_path, err)? else {
        return Ok(super::EXIT_INPUT);
    };
    let store = DirStore::new(dir)?;
    let ctx = Context {
        setup,
        kb: &kb,
        domain: &domain,
        store: &store,
        caches: Default::default(),
    };
    match ctx.record(&trial) {
        Ok(_) => Ok(0),
        Err(e) => error(err, &format!("{id}: {e}"), super::EXIT_INPUT),
    }
}

/// A run directory's setup, hypotheses and complete records (every wanted trial, else the
/// error names the missing ones).
type RunRecords = (Setup, Vec<Hypothesis>, Vec<experiment::Record>);

/// Reads the records of one run directory.
fn read_records(dir: &Path) -> Result<RunRecords, String> {
    let (setup, hypotheses, _, _) = read_run(dir)?;
    let store = DirStore::new(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let mut records = Vec::new();
    let all = store
        .all()
        .map_err(|e| format!("{}: {e}", dir.join("results").display()))?;
    for (id, text) in all {
        match serde_json::from_str::<experiment::Record>(&text) {
            Ok(r) if r.id == id && r.setup == setup => records.push(r),
            Ok(_) => {}
            Err(e) => {
                return Err(format!(
                    "{}: {e}",
                    dir.join(format!("results/{id}.json")).display()
                ))
            }
        }
    }
    let wanted = experiment::trials(&setup, &hypotheses);
    let missing: Vec<String> = wanted
        .iter()
        .map(Trial::id)
        .filter(|id| !records.iter().any(|r| &r.id == id))
        .collect();
    if !missing.is_empty() {
        let shown: Vec<&str> = missing.iter().take(10).map(String::as_str).collect();
        return Err(format!(
            "{} of {} trials have no result in {}: {}{}",
            missing.len(),
            wanted.len(),
            dir.join("results").display(),
            shown.join(", "),
            if missing.len() > 10 { ", ..." } else { "" }
        ));
    }
    records.retain(|r| wanted.iter().any(|t| t.id() == r.id));
    Ok((setup, hypotheses, records))
}

/// `lucent experiment merge DIR DIR... [--out OUT]`: one report over the trials of several
/// runs that differ only in their seed (pooled: every figure is over all their trials).
fn merge_seeds(
    dirs: &[&Path],
    to: Option<&Path>,
    json: bool,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    let mut first: Option<(Setup, Vec<Hypothesis>)> = None;
    let mut records = Vec::new();
    for dir in dirs {
        let (setup, hypotheses, recs) = match read_records(dir) {
            Ok(r) => r,
            Err(e) => return error(err, &e, super::EXIT_INPUT),
        };
        if let Some((s, h)) = &first {
            let same = Setup {
                seed: s.seed,
                ..setup.clone()
            };
            if &same != s || h != &hypotheses {
                return error(
                    err,
                    &format!(
                        "{}: its setup or hypotheses differ from {}'s beyond the seed",
                        dir.display(),
                        dirs[0].display()
                    ),
                    super::EXIT_INPUT,
                );
            }
            if records
                .iter()
                .any(|q: &experiment::Record| q.setup.seed == setup.seed)
            {
                return error(
                    err,
                    &format!("{}: seed {} is merged twice", dir.display(), setup.seed),
                    super::EXIT_INPUT,
                );
            }
        } else {
            first = Some((setup, hypotheses));
        }
        records.extend(recs);
    }
    let Some((setup, hypotheses)) = first else {
        return error(err, "merge needs a run directory", super::EXIT_USAGE);
    };
    let report = match Report::new(&setup, &hypotheses, &records) {
        Ok(r) => r,
        Err(e) => return error(err, &e, super::EXIT_INPUT),
    };
    writeln!(
        err,
        "experiment: {} trials of {} runs merged",
        records.len(),
        dirs.len()
    )?;
    if let Some(to) = to {
        std::fs::create_dir_all(to)?;
    }
    finish(&report, to, json, None, out)
}

/// `lucent experiment merge DIR`: the report from the result files.
fn merge(dir: &Path, json: bool, out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<i32> {
    let (setup, hypotheses, records) = match read_records(dir) {
        Ok(r) => r,
        Err(e) => return error(err, &e, super::EXIT_INPUT),
    };
    let report = match Report::new(&setup, &hypotheses, &records) {
        Ok(r) => r,
        Err(e) => return error(err, &e, super::EXIT_INPUT),
    };
    writeln!(err, "experiment: {} trials merged", records.len())?;
    finish(&report, Some(dir), json, None, out)
}
