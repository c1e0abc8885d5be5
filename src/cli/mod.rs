//! The command line: arguments, clingo-compatible output and exit codes. The only module that
//! does I/O (files, standard streams, the clock).
//!
//! Invariants: every run ends with one of the exit codes of docs/reference.md (10, 20, 30 after
//! solving; 1 interrupted or a bad command line, as clingo 5.4; 65 input or grounding error, after
//! `UNKNOWN` and the summary on standard output as clingo prints them; 70 a verb or stage this
//! build does not provide, or an I/O failure); diagnostics go to
//! standard error in gringo's format, results to standard output. Library modules receive limits
//! as values and never print.

#[cfg(feature = "sim")]
pub mod sim;
pub(crate) mod action;
#[cfg(feature = "sim")]
pub(crate) mod classify;
pub(crate) mod demo;
pub(crate) mod experiment;
pub(crate) mod explain;
mod explain_program;
pub(crate) mod learn;
pub(crate) mod input;
pub(crate) mod options;
pub(crate) mod plan;
mod progress;
mod builtin;
pub mod report;
#[cfg(feature = "sim")]
pub mod run;
#[cfg(feature = "sim")]
pub(crate) mod run_report;

/// KB_full (`domains/ra/kb_full.ald`), built in so that `run`, `demo`, `explain` and `ask` work
/// from any directory, with or without the `sim` feature.
pub const KB_FULL: &str = crate::action::KB_FULL;

use std::io::{Read, Write};
use std::time::{Duration, Instant};

use crate::control::{Control, ControlConfig, Part, SolveOptions};
use crate::ground::{self, GroundProgram};
use crate::solve;

use crate::base::{Diagnostics, SourceMap};
use crate::syntax::ast::Dialect;
use options::{Options, UsageError};

/// Exit code: a model was found.
pub const EXIT_SAT: i32 = 10;
/// Exit code: the search was exhausted without a model.
pub const EXIT_UNSAT: i32 = 20;
/// Exit code: models found and the search exhausted (all enumerated, or optimum proven).
pub const EXIT_EXHAUSTED: i32 = 30;
/// Exit code: interrupted (time limit) before an answer.
pub const EXIT_INTERRUPTED: i32 = 1;
/// Exit code: out of memory.
pub const EXIT_MEMORY: i32 = 33;
/// Exit code: error in the input or during grounding.
pub const EXIT_INPUT: i32 = 65;
/// Exit code: a stage this build does not provide (EX_SOFTWARE).
pub const EXIT_UNAVAILABLE: i32 = 70;
/// Exit code: bad command line (clingo 5.4 and clasp exit 1, the code of an interruption).
pub const EXIT_USAGE: i32 = 1;

/// Runs the command line on the process's arguments and standard streams, and returns the exit
/// code.
///
/// The run happens on a thread with a large stack ([`MAIN_STACK`]): the grounder's join recurses
/// once per body literal, so a rule with 20,000 body literals overflowed the default 8 MiB main
/// stack. The memory is reserved, not committed: only the depth a program reaches is used.
pub fn main() -> i32 {
    std::thread::Builder::new()
        .name("lucent".into())
        .stack_size(MAIN_STACK)
        .spawn(main_on_this_thread)
        .ok()
        .and_then(|t| t.join().ok())
        .unwrap_or(EXIT_UNAVAILABLE)
}

/// Stack size of the thread that runs the command line: 4 GiB of address space, enough for a
/// rule with millions of body literals.
pub const MAIN_STACK: usize = 4 << 30;

fn main_on_this_thread() -> i32 {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let stdin = std::io::stdin();
    // The streams are not locked for the whole run: a worker thread that writes to standard
    // error (a progress bar drawn from rayon's pool) would wait forever on a lock this thread
    // holds while it waits for the workers. Each write takes the lock for its own duration.
    let mut out = std::io::BufWriter::new(std::io::stdout());
    let mut err = std::io::stderr();
    let code = if explain::wants_line_editor(&args) {
        // `lucent ask` on a terminal: a line editor reads the terminal itself.
        explain::run_ask_on_terminal(&args[1..], &mut out, &mut err)
    } else {
        run(&args, &mut stdin.lock(), &mut out, &mut err)
    };
    let _ = out.flush();
    code
}

/// The standard streams of one run, so tests can drive the command line in memory.
pub struct Io<'a> {
    /// Standard input.
    pub stdin: &'a mut dyn Read,
    /// Standard output.
    pub out: &'a mut dyn Write,
    /// Standard error.
    pub err: &'a mut dyn Write,
}

/// Runs the command line with explicit streams and returns the exit code.
pub fn run(args: &[String], stdin: &mut dyn Read, out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    let mut io = Io { stdin, out, err };
    match run_io(args, &mut io) {
        Ok(code) => code,
        Err(e) => {
            // Writing to a closed pipe (e.g. `lucent ... | head`) is not an error of the input,
            // and the reader has gone: stop without a message, as clingo does.
            if e.kind() != std::io::ErrorKind::BrokenPipe {
                let _ = writeln!(io.err, "*** ERROR: (lucent): {e}");
            }
            EXIT_UNAVAILABLE
        }
    }
}

fn run_io(args: &[String], io: &mut Io) -> std::io::Result<i32> {
    match args.first().map(String::as_str) {
        Some("demo") => return demo::run(&args[1..], io.out, io.err),
        Some("translate") => return action::run_translate(&args[1..], io.out, io.err),
        Some("plan") => return plan::run_plan(&args[1..], io.out, io.err),
        #[cfg(feature = "sim")]
        Some("sim") => return Ok(sim::run_with(&args[1..], io.out, io.err)),
        #[cfg(not(feature = "sim"))]
        Some("sim") => {
            writeln!(
                io.err,
                "*** ERROR: (lucent): this build has no simulator (built without the `sim` feature)"
            )?;
            return Ok(EXIT_UNAVAILABLE);
        }
        #[cfg(feature = "sim")]
        Some("run") => return run::run_run(&args[1..], io.out, io.err),
        #[cfg(not(feature = "sim"))]
        Some("run") => {
            writeln!(
                io.err,
                "*** ERROR: (lucent): `lucent run` needs the simulator (built without the `sim` feature)"
            )?;
            return Ok(EXIT_UNAVAILABLE);
        }
        Some("learn") => return learn::run_learn(&args[1..], io.out, io.err),
        #[cfg(feature = "sim")]
        Some("classify") => return classify::run_classify(&args[1..], io.out, io.err),
        Some("experiment") => return experiment::run_experiment(&args[1..], io.out, io.err),
        Some("explain") => return explain::run_explain(&args[1..], io.out, io.err),
        Some("ask") => {
            use std::io::IsTerminal;
            let echo = !std::io::stdin().is_terminal();
            let mut input = std::io::BufReader::new(&mut *io.stdin);
            let mut lines = explain::PlainLines::new(&mut input, echo);
            return explain::run_ask(&args[1..], &mut lines, io.out, io.err);
        }
        _ => {}
    }
    let options = match options::parse_args(args) {
        Ok(o) => o,
        Err(e) => return usage_error(io, &e),
    };
    if options.help {
        write!(io.out, "{}", options::help_text())?;
        return Ok(0);
    }
    if options.version {
        writeln!(io.out, "lucent version {}", env!("CARGO_PKG_VERSION"))?;
        writeln!(
            io.out,
            "A native answer-set solver: grounder, CDCL stable-model solver, CR-Prolog."
        )?;
        writeln!(io.out, "License: MIT")?;
        return Ok(0);
    }
    run_pipeline(&options, io)
}

/// The front of a verb: its help (exit code 0) when the command line asks for it
/// ([`options::Verb::asks_for_help`]), else what `parse` makes of the command line, or
/// `Err(code)` once the usage error is printed as `*** ERROR: (lucent): ...` (exit code
/// [`EXIT_USAGE`]).
pub(crate) fn verb_args<A>(
    verb: &options::Verb,
    args: &[String],
    parse: impl FnOnce(&[String]) -> Result<A, String>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<Result<A, i32>> {
    if verb.asks_for_help(args) {
        write!(out, "{}", verb.help())?;
        return Ok(Err(0));
    }
    match parse(args) {
        Ok(a) => Ok(Ok(a)),
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {e}")?;
            Ok(Err(EXIT_USAGE))
        }
    }
}

/// Prints a report: `value` as pretty JSON with `json`, else `markdown`; shared by `classify`
/// and `experiment`.
pub(crate) fn print_report(
    out: &mut dyn Write,
    json: bool,
    markdown: &str,
    value: &serde_json::Value,
) -> std::io::Result<()> {
    if json {
        writeln!(
            out,
            "{}",
            serde_json::to_string_pretty(value).unwrap_or_default()
        )
    } else {
        write!(out, "{markdown}")
    }
}

/// Writes a report into `dir` as `STEM.md` (`markdown`), `STEM.json` (`value`, pretty, with a
/// final newline) and one file per plot (name, SVG text); shared by `classify` and `experiment`.
pub(crate) fn write_report_files(
    dir: &std::path::Path,
    stem: &str,
    markdown: &str,
    value: &serde_json::Value,
    plots: Vec<(String, String)>,
) -> std::io::Result<()> {
    std::fs::write(dir.join(format!("{stem}.md")), markdown)?;
    std::fs::write(
        dir.join(format!("{stem}.json")),
        serde_json::to_string_pretty(value).unwrap_or_default() + "\n",
    )?;
    for (name, svg) in plots {
        std::fs::write(dir.join(name), svg)?;
    }
    Ok(())
}

fn usage_error(io: &mut Io, e: &UsageError) -> std::io::Result<i32> {
    writeln!(io.err, "*** ERROR: (lucent): {e}")?;
    writeln!(
        io.err,
        "*** Info : (lucent): Try '--help' for usage information"
    )?;
    Ok(EXIT_USAGE)
}

/// A diagnostics collector configured from the options.
fn diagnostics_for(options: &Options) -> Diagnostics {
    let mut diags = Diagnostics::new(options.message_limit);
    for kind in &options.disabled_warnings {
        diags.disable(*kind);
    }
    diags
}

/// Prints the collected diagnostics to standard error.
fn flush_diagnostics(io: &mut Io, diags: &Diagnostics, sources: &SourceMap) -> std::io::Result<()> {
    write!(io.err, "{}", diags.render(sources))
}

/// The dialect of an input: as the options say, or SPARC for `.sp` files, or detected from the
/// text.
fn dialect_of(options: &Options, name: &str, text: &str) -> Dialect {
    match options.dialect {
        Some(dialect) => dialect,
        None if name.ends_with(".sp") => Dialect::Sparc,
        None => crate::syntax::detect_dialect(text),
    }
}

/// Parses `-c name=value` values as terms (through the parser, as `#const name = value.`).
fn const_terms(
    options: &Options,
    io: &mut Io,
) -> std::io::Result<Result<Vec<(String, crate::syntax::ast::Term)>, i32>> {
    let mut out = Vec::new();
    for (name, value) in &options.consts {
        match crate::control::const_term(value) {
            Some(t) => out.push((name.clone(), t)),
            None => {
                return usage_error(
                    io,
                    &UsageError::InvalidValue {
                        option: "const".into(),
                        value: format!("{name}={value}"),
                    },
                )
                .map(Err)
            }
        }
    }
    Ok(Ok(out))
}

/// The solver configuration the options ask for.
fn solve_config(
    options: &Options,
    program: &GroundProgram,
    deadline: Option<Instant>,
) -> solve::Config {
    let optimizing = !program.minimize.is_empty()
        && matches!(options.opt_mode, solve::OptMode::Opt | solve::OptMode::OptN);
    // clingo: with optimization, and for consequences, the default is to search until the end.
    let consequences = options.enum_mode != solve::EnumMode::Auto;
    let models = if !options.models_given && (optimizing || consequences) {
        0
    } else {
        options.models as usize
    };
    solve::Config {
        models,
        opt_mode: options.opt_mode.clone(),
        opt_strategy: options.opt_strategy,
        enum_mode: options.enum_mode,
        cr_mode: options.cr,
        project: options.project,
        deadline,
        seed: options.seed,
        random_freq_permille: options.rand_freq_permille,
        heuristic: options.heuristic,
        check_models: options.check,
        threads: options.threads as usize,
        // Nothing the command line prints reads a model's supports; building them re-scans the
        // rules once per derivation step of each model (40% of a Hamiltonian-cycle run).
        supports: false,
        ..solve::Config::default()
    }
}

/// Prints a solve call's result as clingo does and checks the models with `--check`; returns
/// the exit code.
fn report_result(
    options: &Options,
    io: &mut Io,
    result: &solve::SolveResult,
    context: report::Context,
    original: Option<&GroundProgram>,
    start: Instant,
) -> std::io::Result<i32> {
    let mut rep = report::Report::new(result, context);
    rep.times.total = start.elapsed().as_secs_f64();
    rep.times.cpu = report::process_cpu_seconds().unwrap_or(rep.times.total);
    if options.stats > 0 {
        rep.stats = Some(result.stats.clone());
    }
    let quiet = report::Quiet::from_levels(options.quiet);
    match options.outf {
        options::OutputFormat::Text => {
            report::write_text_verbose(io.out, &rep, quiet, options.verbose)?
        }
        options::OutputFormat::Json => report::write_json(io.out, &rep, quiet)?,
    }
    if let Some(program) = original {
        for model in &result.models {
            if let Err(why) = solve::check::check(program, &model.atoms) {
                writeln!(
                    io.err,
                    "*** ERROR: (lucent): --check: model {} is not a stable model: {why}",
                    model.number
                )?;
                return Ok(EXIT_UNAVAILABLE);
            }
        }
    }
    Ok(rep.exit_code())
}

/// Solves `program` with a solver of its own (`--mode=clasp`) and prints the result; returns
/// the exit code. The solver takes the program (no copy is kept beside it unless `--check`
/// needs the original).
fn solve_and_report(
    options: &Options,
    io: &mut Io,
    program: GroundProgram,
    inputs: Vec<String>,
    start: Instant,
    deadline: Option<Instant>,
) -> std::io::Result<i32> {
    let config = solve_config(options, &program, deadline);
    let context = report::Context::for_program(&program, &config, inputs);
    let original = options.check.then(|| program.clone());
    let mut solver = solve::Solver::from_program(program, config);
    let result = solver.solve();
    report_result(options, io, &result, context, original.as_ref(), start)
}

/// Solves the control's program once and prints the result as clingo does.
fn solve_control(
    options: &Options,
    io: &mut Io,
    control: &mut Control,
    inputs: Vec<String>,
    start: Instant,
    deadline: Option<Instant>,
) -> std::io::Result<i32> {
    let config = solve_config(options, control.program(), deadline);
    let context = report::Context::for_program(control.program(), &config, inputs);
    let original = options.check.then(|| control.program().clone());
    *control.solve_config_mut() = config;
    let mut models = Vec::new();
    let summary = control.solve(&SolveOptions::default(), |m| {
        models.push(m.raw().clone());
        true
    });
    let result = solve::SolveResult {
        models,
        outcome: summary.outcome,
        exhausted: summary.search_exhausted,
        optimum_proven: summary.optimum_proven,
        stop: summary.stop,
        stats: summary.stats,
    };
    report_result(options, io, &result, context, original.as_ref(), start)
}

/// After an error in the input (diagnostics already on standard error), clingo still prints
/// its header, `UNKNOWN` and the summary on standard output (with `--outf=2`, a JSON document
/// with `"Result": "UNKNOWN"`), so a script reading the output gets a complete document; then
/// exits with `code`. `--mode=gringo` prints nothing, as gringo.
fn input_error_report(
    options: &Options,
    io: &mut Io,
    start: Instant,
    code: i32,
) -> std::io::Result<i32> {
    if options.mode == options::Mode::Gringo {
        return Ok(code);
    }
    let total = start.elapsed().as_secs_f64();
    let times = report::Times {
        total,
        cpu: report::process_cpu_seconds().unwrap_or(total),
        ..report::Times::default()
    };
    let rep = report::Report::input_error(options.files.clone(), times);
    match options.outf {
        options::OutputFormat::Text => {
            report::write_text_input_error(io.out, &rep, options.verbose)?
        }
        options::OutputFormat::Json => {
            report::write_json(io.out, &rep, report::Quiet::from_levels(options.quiet))?
        }
    }
    Ok(code)
}

fn run_pipeline(options: &Options, io: &mut Io) -> std::io::Result<i32> {
    let start = Instant::now();
    let deadline = options
        .time_limit
        .map(|secs| start + Duration::from_secs_f64(secs));
    if options.mode == options::Mode::Clasp {
        return run_clasp_mode(options, io, start, deadline);
    }
    if options.mode != options::Mode::Clingo {
        return run_text_pipeline(options, io, start, deadline);
    }
    // As clingo: inputs that are all ground programs in aspif (`gringo enc.lp | lucent`) are
    // solved as `--mode=clasp` solves them. Standard input is read here and handed on.
    let reads_stdin = options.files.is_empty() || options.files.iter().any(|f| f == "-");
    let mut stdin_bytes = Vec::new();
    if reads_stdin {
        // A read error leaves the input empty here; the text pipeline reports it as before.
        let _ = io.stdin.read_to_end(&mut stdin_bytes);
    }
    let is_aspif = |name: &str| match name {
        "-" => crate::ground::aspif::is_aspif(&stdin_bytes),
        file => input::file_is_aspif(file),
    };
    let all_aspif = if options.files.is_empty() {
        is_aspif("-")
    } else {
        options.files.iter().all(|f| is_aspif(f))
    };
    let mut stdin = std::io::Cursor::new(stdin_bytes);
    let mut io = Io {
        stdin: &mut stdin,
        out: &mut *io.out,
        err: &mut *io.err,
    };
    if all_aspif {
        run_clasp_mode(options, &mut io, start, deadline)
    } else {
        run_text_pipeline(options, &mut io, start, deadline)
    }
}

/// Grounds and solves (or only grounds, in gringo mode) the text inputs.
fn run_text_pipeline(
    options: &Options,
    io: &mut Io,
    start: Instant,
    deadline: Option<Instant>,
) -> std::io::Result<i32> {
    let mut diags = diagnostics_for(options);
    let consts = match const_terms(options, io)? {
        Ok(c) => c,
        Err(code) => return Ok(code),
    };
    let mut sources = SourceMap::new();
    let (loaded, load_diags) = input::load(&options.files, io.stdin, &mut sources);
    diags.extend(load_diags);
    let mut config = ControlConfig::default();
    config.ground.consts = consts;
    config.ground.deadline = deadline;
    config.ground.provenance = options.provenance;
    config.ground.message_limit = Some(options.message_limit);
    config.disabled_warnings = options.disabled_warnings.clone();
    let mut control = Control::with_sources(config, sources);
    // All inputs form one program, as gringo reads several files.
    for input in &loaded {
        if input.name.ends_with(".ald") {
            // AL_d: translated to a CR-Prolog syntax tree, then solved like any program.
            if let Some(t) = action::translate_input(
                control.sources_mut(),
                input.file,
                options.profile.as_deref(),
                &options.consts,
                &mut diags,
            ) {
                if let Err(e) = control.add_program(t.program) {
                    diags.extend(e.diagnostics.items().iter().cloned());
                }
            }
            continue;
        }
        let text = &control.sources().get(input.file).text;
        let dialect = dialect_of(options, &input.name, text);
        if let Err(e) = control.add_file(input.file, Some(dialect)) {
            diags.extend(e.diagnostics.items().iter().cloned());
        }
        diags.extend(control.take_diagnostics().items().iter().cloned());
    }
    if !options.show.is_empty() {
        use crate::syntax::ast;
        let statements = options
            .show
            .iter()
            .map(|sig| ast::Statement {
                span: crate::base::Span::default(),
                kind: ast::StatementKind::Show(Box::new(ast::Show::Signature(sig.clone()))),
            })
            .collect();
        let shown = ast::Program {
            dialect: ast::Dialect::Clingo,
            statements,
        };
        if let Err(e) = control.add_program(shown) {
            diags.extend(e.diagnostics.items().iter().cloned());
        }
    }
    if diags.has_errors() {
        flush_diagnostics(io, &diags, control.sources())?;
        writeln!(io.err, "*** ERROR: (lucent): parsing failed")?;
        return input_error_report(options, io, start, EXIT_INPUT);
    }
    flush_diagnostics(io, &diags, control.sources())?;
    let names: Vec<String> = loaded.into_iter().map(|i| i.name).collect();
    if control.incmode() && options.mode != options::Mode::Gringo {
        return run_incmode(options, io, &mut control, names, start, deadline);
    }
    if let Err(e) = control.ground(&[Part::base()]) {
        return grounding_failed(options, io, &control, e, start);
    }
    flush_control_diagnostics(options, io, &mut control)?;
    match options.mode {
        options::Mode::Gringo => {
            let grounding = control.take_grounding();
            match options.ground_format {
                options::GroundFormat::Aspif => {
                    ground::aspif::write_program_to(&grounding.program, &mut *io.out)?
                }
                options::GroundFormat::Text => {
                    let sources = options.provenance.then_some(control.sources());
                    ground::text::write_text_to(&grounding, sources, &mut *io.out)?
                }
            }
            Ok(0)
        }
        // Named as clingo names them: no file given is `stdin`, an explicit `-` stays `-`.
        _ => solve_control(
            options,
            io,
            &mut control,
            options.files.clone(),
            start,
            deadline,
        ),
    }
}

/// Prints the warnings a control collected, with the message limit of the options.
fn flush_control_diagnostics(
    options: &Options,
    io: &mut Io,
    control: &mut Control,
) -> std::io::Result<()> {
    let mut shown = diagnostics_for(options);
    shown.extend(control.take_diagnostics().items().iter().cloned());
    flush_diagnostics(io, &shown, control.sources())
}

/// Prints a failed grounding's diagnostics; returns the exit code.
fn grounding_failed(
    options: &Options,
    io: &mut Io,
    control: &Control,
    e: crate::control::Error,
    start: Instant,
) -> std::io::Result<i32> {
    let mut shown = diagnostics_for(options);
    shown.extend(e.diagnostics.items().iter().cloned());
    flush_diagnostics(io, &shown, control.sources())?;
    writeln!(
        io.err,
        "*** ERROR: (lucent): grounding stopped because of errors"
    )?;
    input_error_report(options, io, start, EXIT_INPUT)
}

/// clingo's incremental mode (`#include <incmode>.`): one `Solving...` and its answers per
/// step, then the last step's result and the totals, as clingo prints them.
fn run_incmode(
    options: &Options,
    io: &mut Io,
    control: &mut Control,
    names: Vec<String>,
    start: Instant,
    deadline: Option<Instant>,
) -> std::io::Result<i32> {
    let config = solve_config(options, control.program(), deadline);
    *control.solve_config_mut() = config;
    let quiet = report::Quiet::from_levels(options.quiet);
    let reading = match names.as_slice() {
        [] => "stdin".to_string(),
        [one] => one.clone(),
        [first, ..] => format!("{first} ..."),
    };
    writeln!(
        io.out,
        "lucent version {}\nReading from {reading}",
        env!("CARGO_PKG_VERSION"),
    )?;
    // Quiet level 0 prints every model, 1 the last model of each step, 2 none.
    let model_text = |m: &crate::control::Model<'_>| {
        let mut text = format!("Answer: {}\n{}\n", m.number(), m.raw().symbols.join(" "));
        if !m.costs().is_empty() {
            let costs: Vec<String> = m.costs().iter().map(i64::to_string).collect();
            text.push_str(&format!("Optimization: {}\n", costs.join(" ")));
        }
        text
    };
    let out = &mut *io.out;
    let mut failed: Option<std::io::Error> = None;
    let mut last_model: Option<String> = None;
    let mut write = |text: &str, failed: &mut Option<std::io::Error>| {
        if failed.is_none() {
            if let Err(e) = out.write_all(text.as_bytes()) {
                *failed = Some(e);
            }
        }
    };
    use crate::control::incmode::{self, Event};
    let result = incmode::run(control, |event| {
        match event {
            Event::Solving(_) => {
                if let Some(t) = last_model.take() {
                    write(&t, &mut failed);
                }
                write("Solving...\n", &mut failed);
            }
            Event::Model(_, m) => match quiet.models {
                0 => write(&model_text(m), &mut failed),
                1 => last_model = Some(model_text(m)),
                _ => {}
            },
        }
        failed.is_none()
    });
    if let Some(t) = last_model.take() {
        write(&t, &mut failed);
    }
    if let Some(e) = failed {
        return Err(e);
    }
    let summary = match result {
        Ok(s) => s,
        Err(e) => return grounding_failed(options, io, control, e, start),
    };
    flush_control_diagnostics(options, io, control)?;
    let (word, code) = match &summary.last {
        Some(s) if s.outcome == solve::Outcome::Optimum => ("OPTIMUM FOUND", EXIT_EXHAUSTED),
        Some(s) if s.is_satisfiable() && s.search_exhausted => ("SATISFIABLE", EXIT_EXHAUSTED),
        Some(s) if s.is_satisfiable() => ("SATISFIABLE", EXIT_SAT),
        Some(s) if s.is_unsatisfiable() => ("UNSATISFIABLE", EXIT_UNSAT),
        _ => ("UNKNOWN", EXIT_INTERRUPTED),
    };
    writeln!(io.out, "{word}\n")?;
    writeln!(io.out, "Models       : {}", summary.models)?;
    writeln!(io.out, "Calls        : {}", summary.calls)?;
    let total = start.elapsed().as_secs_f64();
    writeln!(io.out, "Time         : {total:.3}s")?;
    Ok(code)
}

/// `--mode=clasp`: reads aspif (gringo's output) and solves it.
fn run_clasp_mode(
    options: &Options,
    io: &mut Io,
    start: Instant,
    deadline: Option<Instant>,
) -> std::io::Result<i32> {
    let names = if options.files.is_empty() {
        vec!["-".to_string()]
    } else {
        options.files.clone()
    };
    let mut bytes = Vec::new();
    for name in &names {
        let read = if name == "-" {
            io.stdin.read_to_end(&mut bytes).map(|_| ())
        } else {
            std::fs::read(name).map(|b| bytes.extend(b))
        };
        if read.is_err() {
            writeln!(
                io.err,
                "<cmd>: error: file could not be opened:\n  {name}\n"
            )?;
            return input_error_report(options, io, start, EXIT_INPUT);
        }
    }
    let mut program = match ground::aspif::read_program(&bytes) {
        Ok(p) => p,
        Err(e) => {
            let name = names.join(",");
            // gringo's diagnostic form, `file:line:column: error: message` (the column in bytes).
            let (line, column, kind) = (e.line, e.column, &e.kind);
            writeln!(
                io.err,
                "{name}:{line}:{column}: error: malformed aspif input: {kind}\n"
            )?;
            writeln!(io.err, "*** ERROR: (lucent): reading aspif failed")?;
            return input_error_report(options, io, start, EXIT_INPUT);
        }
    };
    // The text is not needed once read; free it before the solver is built.
    drop(bytes);
    // The solver's per-atom arrays are sized by the largest atom; renumbering sparse atoms
    // keeps memory proportional to the atoms used (what is shown comes from output symbols,
    // so the numbers are not visible).
    program.compact_atoms();
    solve_and_report(options, io, program, options.files.clone(), start, deadline)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_verb_table_is_well_formed_and_its_help_lists_it() {
        let verbs: [(&str, &options::Verb); 6] = [
            ("plan", &plan::VERB),
            ("translate", &action::VERB),
            ("learn", &learn::VERB),
            ("explain", &explain::VERB),
            ("experiment", &experiment::VERB),
            ("demo", &demo::VERB),
        ];
        #[cfg(feature = "sim")]
        let sim_verbs: [(&str, &options::Verb); 4] = [
            ("run", &run::VERB),
            ("sim", &sim::VERB),
            ("classify", &classify::VERB),
            ("experiment classify", &classify::EXPERIMENT_VERB),
        ];
        #[cfg(not(feature = "sim"))]
        let sim_verbs: [(&str, &options::Verb); 0] = [];
        for (name, verb) in verbs.into_iter().chain(sim_verbs) {
            let help = verb.help();
            assert!(verb.options.contains(&options::HELP), "{name}");
            for (i, spec) in verb.options.iter().enumerate() {
                assert!(
                    help.contains(&format!("--{}", spec.long)),
                    "{name}: {spec:?}"
                );
                let earlier = &verb.options[..i];
                assert!(
                    earlier
                        .iter()
                        .all(|o| o.long != spec.long
                            && (spec.short.is_none() || o.short != spec.short)),
                    "{name}: {} twice",
                    spec.long
                );
            }
            for words in [&["--help"][..], &["x", "--hel"], &["-h", "--bogus"]] {
                let words: Vec<String> = words.iter().map(|w| w.to_string()).collect();
                assert!(verb.asks_for_help(&words), "{name}: {words:?}");
            }
        }
    }

    fn run_str(args: &str, stdin: &str) -> (i32, String, String) {
        let args: Vec<String> = args.split_whitespace().map(str::to_string).collect();
        let mut input = stdin.as_bytes();
        let mut out = Vec::new();
        let mut err = Vec::new();
        let code = run(&args, &mut input, &mut out, &mut err);
        (
            code,
            String::from_utf8(out).unwrap(),
            String::from_utf8(err).unwrap(),
        )
    }

    #[test]
    fn usage_error_exits_1() {
        let (code, _, err) = run_str("--bogus", "");
        assert_eq!(code, 1);
        assert!(
            err.starts_with("*** ERROR: (lucent): In context '<lucent>': unknown option: 'bogus'")
        );
    }

    #[test]
    fn help_and_version_exit_0() {
        let (code, out, _) = run_str("--help", "");
        assert_eq!(code, 0);
        assert!(out.contains("--models=<n>,-n"));
        let (code, out, _) = run_str("--version", "");
        assert_eq!(code, 0);
        assert!(out.starts_with("lucent version "));
    }

    #[test]
    fn syntax_error_exits_65_with_gringo_location() {
        let (code, out, err) = run_str("", "p(1)\nq(2).");
        assert_eq!(code, EXIT_INPUT);
        assert!(out.contains("\nUNKNOWN\n"), "{out}");
        assert!(
            err.starts_with("-:2:1-2: error: syntax error, unexpected <IDENTIFIER>"),
            "{err}"
        );
        assert!(err.contains("parsing failed"));
    }

    #[test]
    fn missing_file_exits_65() {
        let (code, _, err) = run_str("/nonexistent/file.lp", "");
        assert_eq!(code, EXIT_INPUT);
        assert!(err.contains("error: file could not be opened"));
    }
}
