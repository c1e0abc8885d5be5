//! The command line: arguments, clingo-compatible output and exit codes. The only module that
//! does I/O (files, standard streams, the clock).
//!
//! Invariants: every run ends with one of the exit codes of REFERENCE.md (10, 20, 30 after
//! solving; 1 interrupted; 65 input or grounding error; 128 usage error); diagnostics go to
//! standard error in gringo's format, results to standard output. Library modules receive limits
//! as values and never print.

#[cfg(feature = "sim")]
pub mod sim;
pub mod input;
pub mod options;
pub mod report;

use std::io::{Read, Write};

use crate::base::{Diagnostics, SourceMap};
use crate::syntax::ast::{Dialect, Program};
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
/// Exit code: bad command line.
pub const EXIT_USAGE: i32 = 128;

/// Runs the command line on the process's arguments and standard streams, and returns the exit
/// code.
pub fn main() -> i32 {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let stdin = std::io::stdin();
    let stdout = std::io::stdout();
    let stderr = std::io::stderr();
    let mut out = std::io::BufWriter::new(stdout.lock());
    let mut err = stderr.lock();
    let code = run(&args, &mut stdin.lock(), &mut out, &mut err);
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
            // Writing to a closed pipe (e.g. `lucent ... | head`) is not an error of the input.
            let _ = writeln!(io.err, "*** ERROR: (lucent): {e}");
            EXIT_UNAVAILABLE
        }
    }
}

fn run_io(args: &[String], io: &mut Io) -> std::io::Result<i32> {
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
        options::DialectChoice::Clingo => Dialect::Clingo,
        options::DialectChoice::Sparc => Dialect::Sparc,
        options::DialectChoice::Auto if name.ends_with(".sp") => Dialect::Sparc,
        options::DialectChoice::Auto => crate::syntax::detect_dialect(text),
    }
}

/// The parsed inputs of a run.
pub struct Parsed {
    /// Every input file's text, for diagnostics.
    pub sources: SourceMap,
    /// One syntax tree per input, in command-line order.
    pub programs: Vec<Program>,
    /// The inputs' names as given.
    pub names: Vec<String>,
}

/// Reads and parses every input. On errors, prints the diagnostics and returns the exit code.
fn read_and_parse(
    options: &Options,
    io: &mut Io,
    diags: &mut Diagnostics,
) -> std::io::Result<Result<Parsed, i32>> {
    let mut sources = SourceMap::new();
    let (loaded, load_diags) = input::load(&options.files, io.stdin, &mut sources);
    diags.extend(load_diags);
    let mut programs = Vec::new();
    for input in &loaded {
        let text = &sources.get(input.file).text;
        let dialect = dialect_of(options, &input.name, text);
        let parse = crate::syntax::parse(input.file, text, dialect);
        diags.extend(parse.diagnostics);
        programs.push(parse.program);
    }
    if diags.has_errors() {
        flush_diagnostics(io, diags, &sources)?;
        writeln!(io.err, "*** ERROR: (lucent): parsing failed")?;
        return Ok(Err(EXIT_INPUT));
    }
    let names = loaded.into_iter().map(|i| i.name).collect();
    Ok(Ok(Parsed {
        sources,
        programs,
        names,
    }))
}

fn run_pipeline(options: &Options, io: &mut Io) -> std::io::Result<i32> {
    let mut diags = diagnostics_for(options);
    if options.mode == options::Mode::Clasp {
        writeln!(
            io.err,
            "*** ERROR: (lucent): --mode=clasp needs the solver, which this build does not have yet"
        )?;
        return Ok(EXIT_UNAVAILABLE);
    }
    let parsed = match read_and_parse(options, io, &mut diags)? {
        Ok(p) => p,
        Err(code) => return Ok(code),
    };
    flush_diagnostics(io, &diags, &parsed.sources)?;
    writeln!(
        io.err,
        "*** ERROR: (lucent): this build cannot ground or solve yet; {} input(s) parsed, nothing was solved",
        parsed.programs.len()
    )?;
    Ok(EXIT_UNAVAILABLE)
}

#[cfg(test)]
mod tests {
    use super::*;

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
    fn usage_error_exits_128() {
        let (code, _, err) = run_str("--bogus", "");
        assert_eq!(code, EXIT_USAGE);
        assert!(err.starts_with("*** ERROR: (lucent): 'bogus': unknown option"));
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
        assert!(out.is_empty());
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
