//! Printing solve results exactly as clingo 5.4 prints them: the text format (`--outf=0`, with
//! `-q` levels, brave and cautious consequences, optimization) and the JSON format
//! (`--outf=2`), plus the exit code.
//!
//! The printer consumes a [`Report`]: a plain view of a [`SolveResult`] plus what the command
//! line knows (inputs, modes, times). `Report::new` fills it from the solver's result; every
//! field is public so the caller can adjust it (e.g. the measured times).
//!
//! Lucent's additions, printed only when the program has CR rules: the line
//! `Applied CR rules: r1 r2(3)` after each answer's atoms (labels sorted, nothing after the
//! colon when none is applied), and the key `"Applied": [ .. ]` in JSON witnesses after
//! `"Value"` (and `"Costs"`).
//!
//! With `--stats` (`Report::stats` set), the counters Lucent keeps follow the time lines in
//! clasp's layout (a subset of clasp's lines) and a `"Stats"` object in JSON (`"Core"` with
//! clingo's names, `"Lucent"` for the rest).
//!
//! Deliberate differences from clingo 5.4: the first line says `lucent version X`; JSON strings
//! are escaped correctly (clingo 5.4 leaves backslashes in symbols unescaped).
//!
//! Invariants: the output depends only on the `Report` and the quiet levels (never the clock);
//! text and JSON print the same models; `exit_code` follows clasp: 10 if a model was found,
//! plus 20 if the search was exhausted, plus 1 if it was interrupted (so 11 is a model found
//! before a time limit, as clingo 5.4 answers; 0 is unknown without interruption).

use std::io::{self, Write};

use crate::ground::program::GroundProgram;
use crate::solve::{Config, EnumMode, Model, OptMode, Outcome, SolveResult, Stats, StopReason};

/// Exit code bit: a model was found.
pub const EXIT_SAT: i32 = 10;
/// Exit code bit: the search space was exhausted.
pub const EXIT_EXHAUSTED: i32 = 20;
/// Exit code bit: the search was interrupted (time limit or signal).
pub const EXIT_INTERRUPTED: i32 = 1;

/// Times shown in the summary, in seconds.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Times {
    /// Wall-clock time of the whole run.
    pub total: f64,
    /// Time spent solving.
    pub solve: f64,
    /// Time until the first model.
    pub first_model: f64,
    /// Time spent proving unsatisfiability (after the last model).
    pub unsat: f64,
    /// Processor time of the whole run.
    pub cpu: f64,
}

/// clasp's `--quiet=<models>,<optimize>,<calls>` levels: 0 print all, 1 print the last, 2 print
/// none.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Quiet {
    /// Which models to print.
    pub models: u8,
    /// Which optimization values to print.
    pub optimize: u8,
    /// Which call results to print (one call per run: not used yet).
    pub calls: u8,
}

impl Quiet {
    /// From the command line's `[models, optimize, calls]` triple.
    pub fn from_levels(levels: [u8; 3]) -> Quiet {
        Quiet {
            models: levels[0],
            optimize: levels[1],
            calls: levels[2],
        }
    }

    /// Whether an item printed at `level` appears in JSON, which is written at the end.
    fn shows(level: u8, last: bool) -> bool {
        level == 0 || (level == 1 && last)
    }
}

/// Brave or cautious consequences after a model: decided shown atoms and still open ones.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Consequences {
    /// Shown atoms known to be consequences.
    pub true_count: usize,
    /// Shown atoms not decided yet.
    pub open: usize,
}

/// One model as printed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ReportModel {
    /// The number printed after `Answer:`.
    pub number: usize,
    /// Shown symbols, in printing order.
    pub symbols: Vec<String>,
    /// Costs, highest priority first; empty without optimization.
    pub costs: Vec<i64>,
    /// Labels of the applied CR rules.
    pub applied: Vec<String>,
    /// Consequence counts (brave and cautious modes only).
    pub consequences: Option<Consequences>,
    /// Known to be optimal.
    pub optimal: bool,
}

/// Everything the printer needs about one run.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// The first line, e.g. `lucent version 0.1.0`.
    pub solver: String,
    /// Input names as given (`-` for standard input); empty means standard input.
    pub inputs: Vec<String>,
    /// The models in the order found.
    pub models: Vec<ReportModel>,
    /// How many models were found (printed after `Models :`); usually `models.len()`.
    pub number: usize,
    /// The overall answer.
    pub outcome: Outcome,
    /// The search space was explored completely.
    pub exhausted: bool,
    /// The program has minimize statements that are not ignored (prints `Optimum`).
    pub has_minimize: bool,
    /// Optimization is running (`--opt-mode=opt|optN`): prints the `Optimization :` summary.
    pub optimizing: bool,
    /// Plain enumeration, brave or cautious consequences.
    pub enum_mode: EnumMode,
    /// Why the search stopped early, if it did.
    pub stop: Option<StopReason>,
    /// The program has CR rules (prints the applied ones).
    pub has_cr: bool,
    /// Number of solve calls.
    pub calls: u32,
    /// Times for the summary.
    pub times: Times,
    /// Search statistics to print (`--stats`), if asked for.
    pub stats: Option<Stats>,
}

/// What the command line knows beyond the solver's result.
#[derive(Clone, Debug, Default)]
pub struct Context {
    /// Input names as given.
    pub inputs: Vec<String>,
    /// The program has minimize statements that are not ignored.
    pub has_minimize: bool,
    /// `--opt-mode` is `opt` or `optN`.
    pub optimizing: bool,
    /// The enumeration mode.
    pub enum_mode: EnumMode,
    /// The program has CR rules.
    pub has_cr: bool,
    /// Number of distinct shown symbols of the program (for brave consequence counts).
    pub shown_total: usize,
    /// Shown symbols that hold in every model (output statements without condition), sorted:
    /// the cautious consequences known before the search.
    pub facts: Vec<String>,
}

impl Context {
    /// The context of solving `program` with `config`, read from `inputs`.
    pub fn for_program(program: &GroundProgram, config: &Config, inputs: Vec<String>) -> Context {
        let has_minimize = !program.minimize.is_empty() && config.opt_mode != OptMode::Ignore;
        let mut symbols: Vec<&str> = program.outputs.iter().map(|o| o.symbol.as_str()).collect();
        symbols.sort_unstable();
        symbols.dedup();
        let mut facts: Vec<String> = program
            .outputs
            .iter()
            .filter(|o| o.condition.is_empty())
            .map(|o| o.symbol.clone())
            .collect();
        facts.sort_unstable();
        facts.dedup();
        Context {
            inputs,
            has_minimize,
            optimizing: has_minimize && matches!(config.opt_mode, OptMode::Opt | OptMode::OptN),
            enum_mode: config.enum_mode,
            has_cr: !program.cr_rules.is_empty(),
            shown_total: symbols.len(),
            facts,
        }
    }
}

impl Report {
    /// A report of `result`. Times come from the solver's statistics (total = solving = CPU);
    /// the caller may overwrite them with measured ones.
    ///
    /// Consequence counts: the solver reports the current consequences as the model's symbols
    /// but not which of them are already decided, so for brave mode the open atoms are the
    /// shown atoms not yet brave, and for cautious mode the current atoms other than shown
    /// facts count as open until the search is exhausted (clasp counts every atom fixed at the
    /// top level as decided, which can be more).
    pub fn new(result: &SolveResult, context: Context) -> Report {
        let n = result.models.len();
        let models = result
            .models
            .iter()
            .enumerate()
            .map(|(i, m)| {
                let last = i + 1 == n;
                let consequences = consequences(m, &context, result.exhausted && last);
                ReportModel {
                    number: m.number,
                    symbols: m.symbols.clone(),
                    costs: m.costs.clone(),
                    applied: m.cr_applied.clone(),
                    consequences,
                    optimal: m.optimal,
                }
            })
            .collect();
        let secs = result.stats.time.as_secs_f64();
        Report {
            solver: format!("lucent version {}", env!("CARGO_PKG_VERSION")),
            inputs: context.inputs,
            models,
            number: n,
            outcome: result.outcome,
            exhausted: result.exhausted,
            has_minimize: context.has_minimize,
            optimizing: context.optimizing,
            enum_mode: context.enum_mode,
            stop: result.stop,
            has_cr: context.has_cr,
            calls: 1,
            times: Times {
                total: secs,
                solve: secs,
                first_model: result.stats.first_model.map_or(0.0, |t| t.as_secs_f64()),
                unsat: result.stats.unsat.as_secs_f64(),
                cpu: secs,
            },
            stats: None,
        }
    }

    /// The report of a run whose input had an error: no call was solved, the result is
    /// `UNKNOWN` with `Models : 0+`, as clingo 5.4 prints it before exiting with 65.
    pub fn input_error(inputs: Vec<String>, times: Times) -> Report {
        Report {
            solver: format!("lucent version {}", env!("CARGO_PKG_VERSION")),
            inputs,
            models: Vec::new(),
            number: 0,
            outcome: Outcome::Unknown,
            exhausted: false,
            has_minimize: false,
            optimizing: false,
            enum_mode: EnumMode::Auto,
            stop: None,
            has_cr: false,
            calls: 1,
            times,
            stats: None,
        }
    }

    /// The process exit code for this report (see [`exit_code`]).
    pub fn exit_code(&self) -> i32 {
        exit_code(self.outcome, self.exhausted, self.stop)
    }
}

fn consequences(model: &Model, context: &Context, final_: bool) -> Option<Consequences> {
    let len = model.symbols.len();
    match context.enum_mode {
        EnumMode::Auto => None,
        EnumMode::Brave if final_ => Some(Consequences {
            true_count: len,
            open: 0,
        }),
        EnumMode::Brave => Some(Consequences {
            true_count: len,
            open: context.shown_total.saturating_sub(len),
        }),
        EnumMode::Cautious if final_ => Some(Consequences {
            true_count: len,
            open: 0,
        }),
        EnumMode::Cautious => {
            let known = model
                .symbols
                .iter()
                .filter(|s| context.facts.binary_search(s).is_ok())
                .count();
            Some(Consequences {
                true_count: known,
                open: len - known,
            })
        }
    }
}

/// The exit code of a solve run, as clasp computes it: 10 if a model was found, plus 20 if the
/// search was exhausted, plus 1 if it was interrupted. So 10 SAT, 20 UNSAT, 30 all models
/// enumerated or optimum proven, 1 interrupted before any model, 11 interrupted after one.
pub fn exit_code(outcome: Outcome, exhausted: bool, stop: Option<StopReason>) -> i32 {
    let mut code = 0;
    if matches!(outcome, Outcome::Satisfiable | Outcome::Optimum) {
        code += EXIT_SAT;
    }
    if exhausted {
        code += EXIT_EXHAUSTED;
    }
    if stop.is_some() {
        code += EXIT_INTERRUPTED;
    }
    code
}

fn result_text(outcome: Outcome) -> &'static str {
    match outcome {
        Outcome::Satisfiable => "SATISFIABLE",
        Outcome::Unsatisfiable => "UNSATISFIABLE",
        Outcome::Unknown => "UNKNOWN",
        Outcome::Optimum => "OPTIMUM FOUND",
    }
}

/// The line clingo adds for a stop; none for the conflict limit (`--solve-limit`: clingo
/// says only UNKNOWN).
fn stop_key(stop: StopReason) -> Option<&'static str> {
    match stop {
        StopReason::TimeLimit => Some("TIME LIMIT"),
        StopReason::Interrupted => Some("INTERRUPTED"),
        StopReason::ConflictLimit => None,
    }
}

fn join<T: ToString>(items: &[T], sep: &str) -> String {
    items
        .iter()
        .map(ToString::to_string)
        .collect::<Vec<_>>()
        .join(sep)
}

/// Writes the whole text output (`--outf=0`) at clingo's default verbosity (`-V1`).
pub fn write_text(out: &mut dyn Write, report: &Report, quiet: Quiet) -> io::Result<()> {
    write_text_verbose(out, report, quiet, 1)
}

/// Writes the whole text output at verbosity `verbose` (`-V`): at 0, as clingo 5.4, no header
/// lines, no `Answer: N` lines and, unless statistics were asked for, no summary after the
/// result line; every other level prints as level 1.
pub fn write_text_verbose(
    out: &mut dyn Write,
    report: &Report,
    quiet: Quiet,
    verbose: u8,
) -> io::Result<()> {
    if verbose == 0 {
        for (i, model) in report.models.iter().enumerate() {
            let last = i + 1 == report.models.len();
            if Quiet::shows(quiet.models, last) {
                write_answer_lines(out, report, model, false)?;
            }
            if Quiet::shows(quiet.optimize, last) {
                write_costs(out, report, model)?;
            }
        }
        if report.stats.is_some() {
            return write_text_summary(out, report);
        }
        return writeln!(out, "{}", result_text(report.outcome));
    }
    write_text_header(out, report)?;
    for model in &report.models {
        write_text_model(out, report, model, quiet)?;
    }
    write_text_last(out, report, quiet)?;
    write_text_summary(out, report)
}

/// What clingo prints on standard output when the input has an error (exit 65): the first two
/// header lines (no `Solving...`), then `UNKNOWN` and the summary (only `UNKNOWN` at `-V0`).
pub fn write_text_input_error(out: &mut dyn Write, report: &Report, verbose: u8) -> io::Result<()> {
    if verbose == 0 {
        return writeln!(out, "{}", result_text(report.outcome));
    }
    writeln!(out, "{}", report.solver)?;
    write_reading_from(out, report)?;
    write_text_summary(out, report)
}

/// `lucent version X`, `Reading from ...`, `Solving...`.
pub fn write_text_header(out: &mut dyn Write, report: &Report) -> io::Result<()> {
    writeln!(out, "{}", report.solver)?;
    write_reading_from(out, report)?;
    writeln!(out, "Solving...")
}

/// `Reading from ...`: `stdin` when no input was named (an explicit `-` is printed as given,
/// as clingo 5.4 does).
fn write_reading_from(out: &mut dyn Write, report: &Report) -> io::Result<()> {
    match report.inputs.as_slice() {
        [] => writeln!(out, "Reading from stdin"),
        [one] => writeln!(out, "Reading from {one}"),
        [first, ..] => writeln!(out, "Reading from {first} ..."),
    }
}

/// What clasp prints when a model is found: the model (quiet level 0) and its costs (level
/// 0), each independently.
pub fn write_text_model(
    out: &mut dyn Write,
    report: &Report,
    model: &ReportModel,
    quiet: Quiet,
) -> io::Result<()> {
    if quiet.models == 0 {
        write_answer(out, report, model)?;
    }
    if quiet.optimize == 0 {
        write_costs(out, report, model)?;
    }
    Ok(())
}

/// What clasp prints when the search ends: the last model (quiet level 1) and its costs (level
/// 1), each independently.
pub fn write_text_last(out: &mut dyn Write, report: &Report, quiet: Quiet) -> io::Result<()> {
    if let Some(model) = report.models.last() {
        if quiet.models == 1 {
            write_answer(out, report, model)?;
        }
        if quiet.optimize == 1 {
            write_costs(out, report, model)?;
        }
    }
    Ok(())
}

/// `Answer: N`, the symbols, the applied CR rules and the consequence counts.
fn write_answer(out: &mut dyn Write, report: &Report, model: &ReportModel) -> io::Result<()> {
    write_answer_lines(out, report, model, true)
}

/// The lines of one answer, with or without the `Answer: N` line (`-V0` leaves it out).
fn write_answer_lines(
    out: &mut dyn Write,
    report: &Report,
    model: &ReportModel,
    numbered: bool,
) -> io::Result<()> {
    if numbered {
        writeln!(out, "Answer: {}", model.number)?;
    }
    writeln!(out, "{}", model.symbols.join(" "))?;
    if report.has_cr {
        let mut line = String::from("Applied CR rules:");
        for label in &model.applied {
            line.push(' ');
            line.push_str(label);
        }
        writeln!(out, "{line}")?;
    }
    if let Some(c) = model.consequences {
        writeln!(
            out,
            "Consequences: [{};{}]",
            c.true_count,
            c.true_count + c.open
        )?;
    }
    Ok(())
}

/// `Optimization: c1 c2`.
fn write_costs(out: &mut dyn Write, report: &Report, model: &ReportModel) -> io::Result<()> {
    if report.has_minimize && !model.costs.is_empty() {
        writeln!(out, "Optimization: {}", join(&model.costs, " "))?;
    }
    Ok(())
}

/// The result line and the statistics summary.
pub fn write_text_summary(out: &mut dyn Write, report: &Report) -> io::Result<()> {
    writeln!(out, "{}", result_text(report.outcome))?;
    writeln!(out)?;
    if let Some(key) = report.stop.and_then(stop_key) {
        writeln!(out, "{key:<12} : 1")?;
    }
    let more = if report.exhausted { "" } else { "+" };
    writeln!(out, "Models       : {}{more}", report.number)?;
    let last = report.models.last();
    if last.is_some() {
        if report.has_minimize && report.enum_mode == EnumMode::Auto {
            writeln!(out, "  Optimum    : {}", optimum_text(report))?;
        }
        match report.enum_mode {
            EnumMode::Auto => {}
            EnumMode::Brave => writeln!(out, "  Brave      : {}", yes_unknown(report.exhausted))?,
            EnumMode::Cautious => {
                writeln!(out, "  Cautious   : {}", yes_unknown(report.exhausted))?
            }
        }
    }
    if let Some(costs) = summary_costs(report) {
        writeln!(out, "Optimization : {}", join(costs, " "))?;
    }
    if let Some(c) = last.and_then(|m| m.consequences) {
        let more = if c.open > 0 { "+" } else { "" };
        writeln!(out, "Consequences : {}{more}", c.true_count)?;
    }
    writeln!(out, "Calls        : {}", report.calls)?;
    let t = &report.times;
    writeln!(
        out,
        "Time         : {:.3}s (Solving: {:.2}s 1st Model: {:.2}s Unsat: {:.2}s)",
        t.total, t.solve, t.first_model, t.unsat
    )?;
    writeln!(out, "CPU Time     : {:.3}s", t.cpu)?;
    if let Some(stats) = &report.stats {
        write_text_stats(out, stats)?;
    }
    Ok(())
}

/// The statistics Lucent keeps, in clasp's `--stats` layout (a subset of clasp's lines, plus
/// `Propagations`, which clasp does not print).
fn write_text_stats(out: &mut dyn Write, stats: &Stats) -> io::Result<()> {
    writeln!(out)?;
    let lines = [
        ("Choices", stats.choices),
        ("Conflicts", stats.conflicts),
        ("Restarts", stats.restarts),
        ("Propagations", stats.propagations),
        ("Lemmas", stats.learnt),
        ("  Loop", stats.loop_nogoods),
    ];
    for (name, value) in lines {
        writeln!(out, "{name:<13}: {value:<8}")?;
    }
    writeln!(out)?;
    writeln!(out, "{:<13}: {:<8}", "Variables", stats.vars)?;
    writeln!(out, "{:<13}: {:<8}", "Constraints", stats.clauses)
}

fn optimum_text(report: &Report) -> &'static str {
    if report.outcome == Outcome::Optimum {
        "yes"
    } else {
        "unknown"
    }
}

fn yes_unknown(exhausted: bool) -> &'static str {
    if exhausted {
        "yes"
    } else {
        "unknown"
    }
}

/// The costs of the summary's `Optimization` line, when there is one.
fn summary_costs(report: &Report) -> Option<&[i64]> {
    let costs = &report.models.last()?.costs;
    (report.has_minimize && report.optimizing && !costs.is_empty()).then_some(costs.as_slice())
}

/// Number of models known to be optimal, for JSON's `Models.Optimal`.
fn optimal_count(report: &Report) -> usize {
    let flagged = report.models.iter().filter(|m| m.optimal).count();
    if flagged == 0 && report.outcome == Outcome::Optimum {
        1
    } else {
        flagged
    }
}

/// A JSON string literal (serde_json does the escaping).
fn json_string(s: &str) -> String {
    serde_json::to_string(s).expect("serializing a string cannot fail")
}

/// `"key": [` newline, items on one line, newline, `]`, in clingo's layout.
fn json_list(out: &mut String, indent: usize, key: &str, items: &[String], sep: &str) {
    let pad = " ".repeat(indent);
    out.push_str(&format!(
        "{pad}\"{key}\": [\n{pad}  {}\n{pad}]",
        items.join(sep)
    ));
}

/// Writes the JSON output (`--outf=2`) in clingo 5.4's layout, with the same keys.
pub fn write_json(out: &mut dyn Write, report: &Report, quiet: Quiet) -> io::Result<()> {
    let mut s = String::with_capacity(1024);
    s.push_str("{\n");
    s.push_str(&format!("  \"Solver\": {},\n", json_string(&report.solver)));
    let inputs: Vec<String> = if report.inputs.is_empty() {
        vec![json_string("stdin")]
    } else {
        report.inputs.iter().map(|i| json_string(i)).collect()
    };
    json_list(&mut s, 2, "Input", &inputs, ",");
    s.push_str(",\n  \"Call\": [\n    {\n");
    let n = report.models.len();
    let shown: Vec<(usize, &ReportModel)> = report
        .models
        .iter()
        .enumerate()
        .filter(|(i, _)| Quiet::shows(quiet.models, i + 1 == n))
        .collect();
    if shown.is_empty() {
        s.push('\n');
    } else {
        s.push_str("      \"Witnesses\": [\n");
        for (k, (i, model)) in shown.iter().enumerate() {
            s.push_str("        {\n");
            let values: Vec<String> = model.symbols.iter().map(|v| json_string(v)).collect();
            json_list(&mut s, 10, "Value", &values, ", ");
            if report.has_minimize
                && !model.costs.is_empty()
                && Quiet::shows(quiet.optimize, i + 1 == n)
            {
                s.push_str(",\n");
                let costs: Vec<String> = model.costs.iter().map(i64::to_string).collect();
                json_list(&mut s, 10, "Costs", &costs, ", ");
            }
            if report.has_cr {
                s.push_str(",\n");
                let applied: Vec<String> = model.applied.iter().map(|l| json_string(l)).collect();
                json_list(&mut s, 10, "Applied", &applied, ", ");
            }
            if let Some(c) = model.consequences {
                s.push_str(&format!(
                    ",\n          \"Consequences\": {{\n            \"True\": {},\n            \"Open\": {}\n          }}",
                    c.true_count, c.open
                ));
            }
            s.push_str("\n        }");
            s.push_str(if k + 1 < shown.len() { ",\n" } else { "\n" });
        }
        s.push_str("      ]\n");
    }
    s.push_str("    }\n  ],\n");
    s.push_str(&format!(
        "  \"Result\": \"{}\",\n",
        result_text(report.outcome)
    ));
    if let Some(key) = report.stop.and_then(stop_key) {
        s.push_str(&format!("  \"{key}\": 1,\n"));
    }
    s.push_str("  \"Models\": {\n");
    s.push_str(&format!("    \"Number\": {},\n", report.number));
    s.push_str(&format!(
        "    \"More\": \"{}\"",
        if report.exhausted { "no" } else { "yes" }
    ));
    if let Some(last) = report.models.last() {
        if report.has_minimize && report.enum_mode == EnumMode::Auto {
            s.push_str(&format!(",\n    \"Optimum\": \"{}\"", optimum_text(report)));
        }
        if let Some(costs) = summary_costs(report) {
            s.push_str(&format!(",\n    \"Optimal\": {},\n", optimal_count(report)));
            let costs: Vec<String> = costs.iter().map(i64::to_string).collect();
            json_list(&mut s, 4, "Costs", &costs, ", ");
        }
        let mode = match report.enum_mode {
            EnumMode::Auto => None,
            EnumMode::Brave => Some("Brave"),
            EnumMode::Cautious => Some("Cautious"),
        };
        if let (Some(mode), Some(c)) = (mode, last.consequences) {
            s.push_str(&format!(
                ",\n    \"{mode}\": \"{}\",\n    \"Consequences\": {{\n      \"True\": {},\n      \"Open\": {}\n    }}",
                yes_unknown(report.exhausted),
                c.true_count,
                c.open
            ));
        }
    }
    s.push_str("\n  },\n");
    s.push_str(&format!("  \"Calls\": {},\n", report.calls));
    let t = &report.times;
    s.push_str(&format!(
        "  \"Time\": {{\n    \"Total\": {:.3},\n    \"Solve\": {:.3},\n    \"Model\": {:.3},\n    \"Unsat\": {:.3},\n    \"CPU\": {:.3}\n  }}",
        t.total, t.solve, t.first_model, t.unsat, t.cpu
    ));
    if let Some(st) = &report.stats {
        // clingo's "Stats" object, with the counters Lucent keeps: "Core" as clingo names
        // them, the rest under "Lucent".
        s.push_str(&format!(
            ",\n  \"Stats\": {{\n    \"Core\": {{\n      \"Choices\": {},\n      \"Conflicts\": {},\n      \"Restarts\": {}\n    }},\n    \"Lucent\": {{\n      \"Propagations\": {},\n      \"Lemmas\": {},\n      \"LoopNogoods\": {},\n      \"Variables\": {},\n      \"Constraints\": {}\n    }}\n  }}",
            st.choices, st.conflicts, st.restarts, st.propagations, st.learnt, st.loop_nogoods, st.vars, st.clauses
        ));
    }
    s.push_str("\n}\n");
    out.write_all(s.as_bytes())
}

/// CPU time (user + system) this process has used so far, in seconds, as clingo's `CPU Time`
/// line reports it. Read from `/proc/self/stat` (fields 14 and 15, in USER_HZ ticks, which Linux
/// fixes at 100 for every architecture it exports them on); `None` where that file is missing or
/// unreadable, and the caller then reports wall time.
pub fn process_cpu_seconds() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The command name (field 2) is parenthesised and may contain spaces: count from the last ')'.
    let rest = &stat[stat.rfind(')')? + 1..];
    let mut fields = rest.split_ascii_whitespace().skip(11);
    let user: u64 = fields.next()?.parse().ok()?;
    let system: u64 = fields.next()?.parse().ok()?;
    Some((user + system) as f64 / 100.0)
}

#[cfg(test)]
mod tests {
    use super::process_cpu_seconds;

    #[cfg(target_os = "linux")]
    #[test]
    fn cpu_time_is_read_and_grows_with_work() {
        let before = process_cpu_seconds().expect("/proc/self/stat is readable on Linux");
        // Spin until the process has used at least two more clock ticks (20 ms of CPU); the
        // loop is bounded by wall time so a broken reader fails instead of hanging.
        let start = std::time::Instant::now();
        let mut x = 0u64;
        while process_cpu_seconds().unwrap() < before + 0.02 {
            for i in 0..100_000u64 {
                x = x.wrapping_mul(6364136223846793005).wrapping_add(i);
            }
            assert!(
                start.elapsed().as_secs() < 30,
                "CPU time did not advance ({x})"
            );
        }
    }
}
