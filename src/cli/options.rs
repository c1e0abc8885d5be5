//! The option tables and their one parser: clingo mode's table ([`OPTIONS`]) with the
//! [`Options`] it fills, the [`OptionSpec`] kind every verb's table is made of, [`scan`] that
//! reads any table, and [`Verb`], a verb's table with the text around its generated `--help`.
//!
//! Invariants: a declarative table drives both parsing and `--help` for clingo mode and for each
//! verb (CaDiCaL's `options.hpp` habit), so an option cannot be accepted without being
//! documented; every table is read by [`scan`] with the same rules (long names or unambiguous
//! prefixes, `--name=v`, `--name v`, `-nv`, `--` ends the options). Parsing is pure: it never
//! reads files or prints; errors are [`UsageError`] values (or, for a verb's values, messages)
//! that the caller turns into clingo's `*** ERROR: (lucent): ...` lines and exit code 1. Mode
//! names are parsed by the library types they select (`solve::OptMode::from_name`, ...).

use crate::base::WarningKind;
use crate::solve::{CrMode, EnumMode, Heuristic, OptMode, OptStrategy, Project};
use crate::syntax::ast::Dialect;

/// Whether an option takes a value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Arity {
    /// A flag: `--stats`.
    Flag,
    /// A required value: `--models=N`, `--models N`, `-n N`, `-nN`.
    Value,
    /// An optional value, only as `--opt=value`: `--project`, `--project=show`.
    OptionalValue,
}

/// One row of the option table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OptionSpec {
    /// Long name without dashes.
    pub long: &'static str,
    /// Short alias.
    pub short: Option<char>,
    /// Value arity.
    pub arity: Arity,
    /// Placeholder for the value in `--help`.
    pub value_name: &'static str,
    /// One-line help.
    pub help: &'static str,
    /// Help section.
    pub group: &'static str,
}

/// A table row (`const`, so tables are `static` data).
pub const fn opt(
    long: &'static str,
    short: Option<char>,
    arity: Arity,
    value_name: &'static str,
    help: &'static str,
    group: &'static str,
) -> OptionSpec {
    OptionSpec {
        long,
        short,
        arity,
        value_name,
        help,
        group,
    }
}

use Arity::*;

/// Every option Lucent accepts.
pub const OPTIONS: &[OptionSpec] = &[
    opt("help", Some('h'), Flag, "", "Print this help and exit", "Basic"),
    opt("version", Some('v'), Flag, "", "Print version information and exit", "Basic"),
    opt("mode", None, Value, "<mode>", "Run in {clingo|gringo|clasp} mode [clingo]", "Basic"),
    opt("text", None, Flag, "", "Print the ground program in text form (implies --mode=gringo)", "Basic"),
    opt("output", Some('o'), Value, "<fmt>", "Ground program format in gringo mode: {aspif|intermediate|text} [aspif]", "Basic"),
    opt("dialect", None, Value, "<lang>", "Input language {auto|clingo|sparc} [auto: .sp files are SPARC]", "Basic"),
    opt("profile", None, Value, "<name>", "Profile of an AL_d (.ald) input: a switch bundle it declares, e.g. tabletop", "Basic"),
    opt("show", None, Value, "<sigs>", "Show only atoms of these signatures, as #show p/n. in the program: --show=occurs/2,goal/1 (an AL_d input's plan)", "Basic"),
    opt("models", Some('n'), Value, "<n>", "Compute at most <n> models (0 for all) [1]", "Solving"),
    opt("const", Some('c'), Value, "<id>=<term>", "Replace term occurrences of <id> with <term>", "Grounding"),
    opt("warn", Some('W'), Value, "<warn>", "Enable/disable warnings: none, all, [no-]{atom-undefined|file-included|operation-undefined|variable-unbounded|global-variable|other}", "Grounding"),
    opt("message-limit", None, Value, "<n>", "Print at most <n> messages [20]", "Grounding"),
    opt("provenance", None, Flag, "", "In --text output, show where each ground rule came from (statement, substitution, body literals grounding proved) and why each false atom is false", "Grounding"),
    opt("opt-mode", None, Value, "<mode>", "Optimization {opt|optN|enum|ignore}[,<bound>...] [opt]", "Solving"),
    opt("opt-strategy", None, Value, "<s>", "Optimization strategy {bb|usc}[,<tactics>...]: bb is model-guided branch and bound, usc core-guided with OLL relaxation [bb]", "Solving"),
    opt("enum-mode", Some('e'), Value, "<mode>", "Enumeration {auto|bt|record|brave|cautious} [auto]", "Solving"),
    opt("project", None, OptionalValue, "<mode>", "Project models to shown/projected atoms {show|project|auto} [no]", "Solving"),
    opt("cr", None, Value, "<mode>", "CR-rule semantics {card|subset}: cardinality-minimal applied CR rules, or subset-minimal with prefer/2 [card]", "Solving"),
    opt("time-limit", None, Value, "<s>", "Stop after <s> seconds and answer UNKNOWN [0 = none]", "Solving"),
    opt("parallel-mode", Some('t'), Value, "<n>", "Run a portfolio of <n> threads [1]", "Solving"),
    opt("heuristic", None, Value, "<h>", "Decision heuristic {berkmin|vmtf|vsids|domain|unit|none}: domain follows #heuristic statements without a condition (level, sign, true, false) before VSIDS; the others are VSIDS. Changes search order, never answers", "Solving"),
    opt("seed", None, Value, "<n>", "Seed of the solver's random choices [1]", "Solving"),
    opt("rand-freq", None, Value, "<p>", "Make a random decision with probability <p> in [0.0,1.0] [0.0]", "Solving"),
    opt("check", None, Flag, "", "Verify every reported model with an independent stable-model check", "Solving"),
    opt("outf", None, Value, "<n>", "Output format {0=text|2=json} [0]", "Output"),
    opt("quiet", Some('q'), OptionalValue, "<levels>", "Print {0=all|1=last|2=no} models[,costs[,calls]] [-q: 2,2,2]", "Output"),
    opt("stats", Some('s'), OptionalValue, "<n>", "Print statistics", "Output"),
    opt("verbose", Some('V'), OptionalValue, "<n>", "Verbosity level [1]", "Output"),
];

/// Which pipeline the run drives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Mode {
    /// Ground and solve.
    #[default]
    Clingo,
    /// Ground only; print the ground program.
    Gringo,
    /// Solve a ground program given as aspif.
    Clasp,
}

/// Ground program output format in gringo mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum GroundFormat {
    /// aspif, as `gringo --output=intermediate`.
    #[default]
    Aspif,
    /// Readable rules, as `gringo --text`.
    Text,
}

/// `--outf`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum OutputFormat {
    /// clasp's text output.
    #[default]
    Text,
    /// clingo's JSON output.
    Json,
}

/// Everything the command line said, parsed and validated.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Input files; `-` is standard input; empty means standard input.
    pub files: Vec<String>,
    /// The pipeline to run.
    pub mode: Mode,
    /// Ground program format in gringo mode.
    pub ground_format: GroundFormat,
    /// Input language; `None` is SPARC for `.sp` files, else detected from the text.
    pub dialect: Option<Dialect>,
    /// Number of models to compute, 0 for all.
    pub models: u64,
    /// Whether `-n` was given explicitly (optimization changes the default to all).
    pub models_given: bool,
    /// `-c name=value` definitions, in order.
    pub consts: Vec<(String, String)>,
    /// `--profile`: the profile of AL_d inputs.
    pub profile: Option<String>,
    /// `--show`: signatures to show, as `#show p/n.` statements added to the program.
    pub show: Vec<crate::syntax::ast::Signature>,
    /// Warning kinds switched off.
    pub disabled_warnings: Vec<WarningKind>,
    /// Maximum number of messages printed.
    pub message_limit: usize,
    /// Show provenance comments in text output.
    pub provenance: bool,
    /// Optimization mode, with the bounds of `--opt-mode=enum,b1,b2`.
    pub opt_mode: OptMode,
    /// Optimization strategy (`--opt-strategy`).
    pub opt_strategy: OptStrategy,
    /// Enumeration mode.
    pub enum_mode: EnumMode,
    /// Projection requested.
    pub project: Project,
    /// CR semantics.
    pub cr: CrMode,
    /// Time limit in seconds, if any.
    pub time_limit: Option<f64>,
    /// Number of portfolio threads.
    pub threads: u32,
    /// Random seed.
    pub seed: u64,
    /// Probability of a random decision, in 1/1000 (`--rand-freq`).
    pub rand_freq_permille: u32,
    /// The decision heuristic.
    pub heuristic: Heuristic,
    /// Check every model independently.
    pub check: bool,
    /// Output format.
    pub outf: OutputFormat,
    /// Quiet levels: models, costs, calls (0 = print all, 1 = last, 2 = none).
    pub quiet: [u8; 3],
    /// Statistics level (0 = none).
    pub stats: u8,
    /// Verbosity.
    pub verbose: u8,
    /// `--help` was given.
    pub help: bool,
    /// `--version` was given.
    pub version: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            files: Vec::new(),
            mode: Mode::Clingo,
            ground_format: GroundFormat::Aspif,
            dialect: None,
            models: 1,
            models_given: false,
            consts: Vec::new(),
            profile: None,
            show: Vec::new(),
            disabled_warnings: Vec::new(),
            message_limit: 20,
            provenance: false,
            opt_mode: OptMode::Opt,
            opt_strategy: OptStrategy::Bb,
            enum_mode: EnumMode::Auto,
            project: Project::No,
            cr: CrMode::Cardinality,
            time_limit: None,
            threads: 1,
            seed: 1,
            rand_freq_permille: 0,
            heuristic: Heuristic::Vsids,
            check: false,
            outf: OutputFormat::Text,
            quiet: [0, 0, 0],
            stats: 0,
            verbose: 1,
            help: false,
            version: false,
        }
    }
}

/// A command-line mistake: exit code 1, with clingo 5.4's wording (`In context '<lucent>': ...`
/// or `SyntaxError: ...`).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum UsageError {
    /// An option nobody knows.
    #[error("In context '<lucent>': unknown option: '{0}'")]
    Unknown(String),
    /// An option that needs a value got none.
    #[error("SyntaxError: '{0}' requires a value!")]
    MissingValue(String),
    /// A flag was given a value.
    #[error("SyntaxError: '{0}' does not take a value!")]
    UnexpectedValue(String),
    /// A value that does not fit the option.
    #[error("In context '<lucent>': '{value}' invalid value for: '{option}'")]
    InvalidValue {
        /// The option's long name.
        option: String,
        /// The value given.
        value: String,
    },
}

/// One piece of a command line, as [`scan`] reads it against an option table.
#[derive(Clone, Debug, PartialEq)]
pub enum Arg {
    /// An option of the table with its value: inline (`--name=v`, `-nv`, `-n=v`) or, for
    /// [`Arity::Value`], the next word; `None` for a flag or an optional value not given.
    Option(&'static OptionSpec, Option<String>),
    /// A word that is no option: a file, a subcommand, `-`.
    Word(String),
    /// A word after `--`, which is never an option.
    Literal(String),
}

/// The one parser of every option table (clingo mode's [`OPTIONS`] and each verb's): the
/// command line word by word, an [`Arg`] each, in order. Long options are matched exactly or by
/// an unambiguous prefix (as clingo does), short ones by their letter; an option not in the
/// table, a missing value and a flag given a value are [`UsageError`]s, after which the caller
/// stops.
pub fn scan<'a>(table: &'static [OptionSpec], args: &'a [String]) -> Scan<'a> {
    Scan {
        table,
        args,
        next: 0,
        only_words: false,
    }
}

/// The iterator [`scan`] returns.
pub struct Scan<'a> {
    table: &'static [OptionSpec],
    args: &'a [String],
    next: usize,
    only_words: bool,
}

impl Iterator for Scan<'_> {
    type Item = Result<Arg, UsageError>;

    fn next(&mut self) -> Option<Self::Item> {
        let arg = self.args.get(self.next)?;
        self.next += 1;
        if self.only_words {
            return Some(Ok(Arg::Literal(arg.clone())));
        }
        if arg == "--" {
            self.only_words = true;
            return self.next();
        }
        if arg == "-" || !arg.starts_with('-') {
            return Some(Ok(Arg::Word(arg.clone())));
        }
        Some(self.option(arg))
    }
}

impl Scan<'_> {
    /// The option word `arg` with its value.
    fn option(&mut self, arg: &str) -> Result<Arg, UsageError> {
        let (spec, inline_value, shown) = if let Some(rest) = arg.strip_prefix("--") {
            let (name, value) = match rest.split_once('=') {
                Some((n, v)) => (n, Some(v.to_string())),
                None => (rest, None),
            };
            let spec =
                find_long(self.table, name).ok_or_else(|| UsageError::Unknown(name.to_string()))?;
            (spec, value, name.to_string())
        } else {
            let mut chars = arg[1..].chars();
            let c = chars.next().unwrap_or('-');
            let spec = self
                .table
                .iter()
                .find(|o| o.short == Some(c))
                .ok_or_else(|| UsageError::Unknown(arg.to_string()))?;
            let rest: String = chars.collect();
            let value = (!rest.is_empty()).then(|| rest.trim_start_matches('=').to_string());
            (spec, value, c.to_string())
        };
        let value = match (spec.arity, inline_value) {
            (Flag, Some(_)) => return Err(UsageError::UnexpectedValue(shown)),
            (Flag, None) => None,
            (OptionalValue, v) | (Value, v @ Some(_)) => v,
            (Value, None) => {
                let v = self.args.get(self.next).cloned();
                self.next += 1;
                Some(v.ok_or(UsageError::MissingValue(shown))?)
            }
        };
        Ok(Arg::Option(spec, value))
    }
}

fn find_long(table: &'static [OptionSpec], name: &str) -> Option<&'static OptionSpec> {
    if let Some(spec) = table.iter().find(|o| o.long == name) {
        return Some(spec);
    }
    // clingo accepts unambiguous prefixes of long options.
    let mut candidates = table.iter().filter(|o| o.long.starts_with(name));
    match (candidates.next(), candidates.next()) {
        (Some(spec), None) if !name.is_empty() => Some(spec),
        _ => None,
    }
}

impl OptionSpec {
    /// The option as written in messages: `--seed`.
    pub fn spelled(&self) -> String {
        format!("--{}", self.long)
    }

    /// The verbs' reading of a number value (`'--seed': 'x' is not a number`).
    pub fn number<T: std::str::FromStr>(&self, value: &str) -> Result<T, String> {
        value
            .parse()
            .map_err(|_| format!("'{}': '{value}' is not a number", self.spelled()))
    }

    /// The verbs' reading of a probability, a number in [0, 1].
    #[cfg(feature = "sim")]
    pub fn probability(&self, value: &str) -> Result<f64, String> {
        match value.parse::<f64>() {
            Ok(p) if (0.0..=1.0).contains(&p) => Ok(p),
            _ => Err(format!(
                "'{}': '{value}' is not a probability in [0, 1]",
                self.spelled()
            )),
        }
    }

    /// The verbs' `--outf`: `0` (text, false) or `2` (JSON, true).
    pub fn outf(&self, value: &str) -> Result<bool, String> {
        match value {
            "0" => Ok(false),
            "2" => Ok(true),
            _ => Err(format!("'{}={value}': expected 0 or 2", self.spelled())),
        }
    }

    /// The verbs' `-c NAME=VALUE`, both sides trimmed.
    pub fn assignment(&self, value: &str) -> Result<(String, String), String> {
        let (name, v) = value
            .split_once('=')
            .ok_or_else(|| format!("'-c {value}': expected -c NAME=VALUE"))?;
        Ok((name.trim().to_string(), v.trim().to_string()))
    }
}

/// A verb's command line: the usage text before its options (usage lines, what the verb does),
/// its option table and the text after the options; [`Verb::help`] is its `--help`.
pub struct Verb {
    /// Usage lines and description, ending with a newline.
    pub usage: &'static str,
    /// The options, each verb's table of the same kind as [`OPTIONS`].
    pub options: &'static [OptionSpec],
    /// Text after the options (exit codes, examples), empty or starting with a blank line.
    pub epilogue: &'static str,
}

impl Verb {
    /// True when the command line asks for the help: `--help` or `-h` as a word anywhere, or
    /// the table's `help` option (by a prefix) before anything [`scan`] cannot read.
    pub fn asks_for_help(&self, args: &[String]) -> bool {
        args.iter().any(|a| a == "--help" || a == "-h")
            || scan(self.options, args)
                .map_while(Result::ok)
                .any(|a| matches!(a, Arg::Option(spec, _) if spec.long == "help"))
    }

    /// The `--help` text, with the options rendered from the table.
    pub fn help(&self) -> String {
        self.help_with(|spec| spec.help.to_string())
    }

    /// The `--help` text with `help` giving each option's help text.
    pub fn help_with(&self, help: impl Fn(&OptionSpec) -> String) -> String {
        const WIDTH: usize = 98;
        let left = |spec: &OptionSpec| {
            let mut l = match spec.short {
                Some(c) => format!("  -{c}, --{}", spec.long),
                None => format!("  --{}", spec.long),
            };
            match spec.arity {
                Flag => {}
                Value => l.push_str(&format!(" {}", spec.value_name)),
                OptionalValue => l.push_str(&format!("[={}]", spec.value_name)),
            }
            l
        };
        let column = 2 + self
            .options
            .iter()
            .map(|s| left(s).len())
            .filter(|&n| n <= 26)
            .max()
            .unwrap_or(0);
        let mut out = self.usage.to_string();
        let mut groups: Vec<&str> = Vec::new();
        for spec in self.options {
            if !groups.contains(&spec.group) {
                groups.push(spec.group);
            }
        }
        for group in groups {
            out.push_str(&format!("\n{group}:\n"));
            for spec in self.options.iter().filter(|s| s.group == group) {
                let mut line = left(spec);
                if line.len() + 2 > column {
                    out.push_str(&line);
                    out.push('\n');
                    line.clear();
                }
                for word in help(spec).split_whitespace() {
                    if line.len() < column {
                        line.push_str(&" ".repeat(column - line.len()));
                    } else if line.len() + 1 + word.len() > WIDTH {
                        out.push_str(&line);
                        out.push('\n');
                        line = " ".repeat(column);
                    } else {
                        line.push(' ');
                    }
                    line.push_str(word);
                }
                out.push_str(&line);
                out.push('\n');
            }
        }
        out.push_str(self.epilogue);
        out
    }
}

/// The help option of every verb's table.
pub const HELP: OptionSpec = opt(
    "help",
    Some('h'),
    Flag,
    "",
    "print this help and exit",
    "Options",
);

/// Parses the arguments after the program name.
pub fn parse_args(args: &[String]) -> Result<Options, UsageError> {
    let mut options = Options::default();
    for arg in scan(OPTIONS, args) {
        match arg? {
            // clingo reads a leading integer argument as the number of models.
            Arg::Word(w) if !w.is_empty() && w.bytes().all(|b| b.is_ascii_digit()) => {
                options.models = w.parse().map_err(|_| invalid("models", &w))?;
                options.models_given = true;
            }
            Arg::Word(w) | Arg::Literal(w) => options.files.push(w),
            Arg::Option(spec, value) => apply(&mut options, spec.long, value.as_deref())?,
        }
    }
    Ok(options)
}

fn invalid(option: &str, value: &str) -> UsageError {
    UsageError::InvalidValue {
        option: option.to_string(),
        value: value.to_string(),
    }
}

fn parse_num<T: std::str::FromStr>(option: &str, value: &str) -> Result<T, UsageError> {
    value.trim().parse().map_err(|_| invalid(option, value))
}

fn apply(o: &mut Options, long: &str, value: Option<&str>) -> Result<(), UsageError> {
    let v = value.unwrap_or("");
    match long {
        "help" => o.help = true,
        "version" => o.version = true,
        "mode" => {
            o.mode = match v {
                "clingo" => Mode::Clingo,
                "gringo" => Mode::Gringo,
                "clasp" => Mode::Clasp,
                _ => return Err(invalid(long, v)),
            }
        }
        "text" => {
            o.mode = Mode::Gringo;
            o.ground_format = GroundFormat::Text;
        }
        "output" => {
            o.ground_format = match v {
                "aspif" | "intermediate" => GroundFormat::Aspif,
                "text" => GroundFormat::Text,
                _ => return Err(invalid(long, v)),
            }
        }
        "dialect" => {
            o.dialect = match v {
                "auto" => None,
                _ => Some(Dialect::from_name(v).ok_or_else(|| invalid(long, v))?),
            }
        }
        "models" => {
            o.models = parse_num(long, v)?;
            o.models_given = true;
        }
        "const" => {
            let (name, val) = v.split_once('=').ok_or_else(|| invalid(long, v))?;
            let name = name.trim();
            let starts_lower = name
                .trim_start_matches('_')
                .starts_with(|c: char| c.is_ascii_lowercase());
            if !starts_lower || val.trim().is_empty() {
                return Err(invalid(long, v));
            }
            o.consts.push((name.to_string(), val.trim().to_string()));
        }
        "profile" => o.profile = Some(v.to_string()),
        "show" => {
            for part in v.split(',').map(str::trim).filter(|p| !p.is_empty()) {
                o.show
                    .push(signature(part).ok_or_else(|| UsageError::InvalidValue {
                        option: "show".into(),
                        value: v.to_string(),
                    })?);
            }
        }
        "warn" => apply_warn(o, v)?,
        "message-limit" => o.message_limit = parse_num(long, v)?,
        "provenance" => o.provenance = true,
        "opt-mode" => o.opt_mode = OptMode::from_name(v).ok_or_else(|| invalid(long, v))?,
        "opt-strategy" => {
            o.opt_strategy = OptStrategy::from_name(v).ok_or_else(|| invalid(long, v))?
        }
        "enum-mode" => o.enum_mode = EnumMode::from_name(v).ok_or_else(|| invalid(long, v))?,
        "project" => {
            o.project = match value {
                None => Project::Auto,
                Some(m) => Project::from_name(m).ok_or_else(|| invalid(long, m))?,
            }
        }
        "cr" => o.cr = CrMode::from_name(v).ok_or_else(|| invalid(long, v))?,
        "time-limit" => {
            let secs: f64 = parse_num(long, v)?;
            if !(secs >= 0.0 && secs.is_finite()) {
                return Err(invalid(long, v));
            }
            o.time_limit = if secs == 0.0 { None } else { Some(secs) };
        }
        "parallel-mode" => {
            let n = v.split(',').next().unwrap_or("");
            let threads: u32 = parse_num(long, n)?;
            if !(1..=64).contains(&threads) {
                return Err(invalid(long, v));
            }
            o.threads = threads;
        }
        "heuristic" => o.heuristic = Heuristic::from_name(v).ok_or_else(|| invalid(long, v))?,
        "seed" => o.seed = parse_num(long, v)?,
        "rand-freq" => {
            let p: f64 = parse_num(long, v)?;
            if !(0.0..=1.0).contains(&p) {
                return Err(invalid(long, v));
            }
            o.rand_freq_permille = (p * 1000.0).round() as u32;
        }
        "check" => o.check = true,
        "outf" => {
            o.outf = match v {
                "0" => OutputFormat::Text,
                "2" => OutputFormat::Json,
                _ => return Err(invalid(long, v)),
            }
        }
        "quiet" => {
            // clasp: `-q` alone is `2,2,2`; a missing cost level copies the model level, and
            // a missing call level is 2 (print no call results).
            if value.is_none() {
                o.quiet = [2, 2, 2];
            } else {
                let parts: Vec<&str> = v.split(',').collect();
                if parts.len() > 3 {
                    return Err(invalid(long, v));
                }
                let mut levels = [0u8; 3];
                for (k, part) in parts.iter().enumerate() {
                    levels[k] = parse_num(long, part)?;
                    if levels[k] > 2 {
                        return Err(invalid(long, v));
                    }
                }
                if parts.len() < 2 {
                    levels[1] = levels[0];
                }
                if parts.len() < 3 {
                    levels[2] = 2;
                }
                o.quiet = levels;
            }
        }
        "stats" => {
            o.stats = match value {
                None => 1,
                Some(n) => parse_num(long, n.split(',').next().unwrap_or(""))?,
            }
        }
        "verbose" => {
            o.verbose = match value {
                None => 2,
                Some(n) => parse_num(long, n)?,
            }
        }
        _ => return Err(UsageError::Unknown(long.to_string())),
    }
    Ok(())
}

/// `name/arity` or `-name/arity` as a signature.
fn signature(text: &str) -> Option<crate::syntax::ast::Signature> {
    let (negated, text) = match text.strip_prefix('-') {
        Some(t) => (true, t),
        None => (false, text),
    };
    let (name, arity) = text.rsplit_once('/')?;
    let starts = name.chars().next()?;
    let ok = (starts.is_ascii_lowercase() || starts == '_')
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '\'');
    let arity = arity.parse().ok()?;
    ok.then(|| crate::syntax::ast::Signature {
        negated,
        name: name.to_string(),
        arity,
    })
}

fn apply_warn(o: &mut Options, v: &str) -> Result<(), UsageError> {
    match v {
        "none" => o.disabled_warnings = WarningKind::ALL.to_vec(),
        "all" => o.disabled_warnings.clear(),
        _ => {
            let (off, name) = match v.strip_prefix("no-") {
                Some(name) => (true, name),
                None => (false, v),
            };
            let kind = WarningKind::from_name(name).ok_or_else(|| invalid("warn", v))?;
            o.disabled_warnings.retain(|k| *k != kind);
            if off {
                o.disabled_warnings.push(kind);
            }
        }
    }
    Ok(())
}

/// The verbs beside clingo mode, one line each (every one takes `--help`).
pub const VERBS: &[(&str, &str)] = &[
    (
        "demo",
        "the tabletop task end to end: plan, act in physics, replan, pictures",
    ),
    (
        "run",
        "the sense-plan-act loop on a generated or given scene, with noise",
    ),
    (
        "plan",
        "minimal plans for an AL_d scene's goal (or an English --goal)",
    ),
    ("translate", "an AL_d description as its CR-Prolog program"),
    (
        "explain",
        "answers one question about a history, or why/why-not of any program",
    ),
    (
        "ask",
        "a dialogue of questions about a history or a saved run",
    ),
    (
        "learn",
        "learns missing axioms from surprises (decision trees)",
    ),
    (
        "classify",
        "stability and occlusion of a scene: reasoning, CNN, learned constraints",
    ),
    (
        "experiment",
        "the paper's experiments H1-H4 and scene classification, with reports",
    ),
    (
        "sim",
        "the simulated tabletop world: scenes, pictures, actions",
    ),
];

/// The `--help` text, generated from [`OPTIONS`].
pub fn help_text() -> String {
    let mut out = String::new();
    out.push_str(&format!("lucent version {}\n", env!("CARGO_PKG_VERSION")));
    out.push_str("usage: lucent [number] [options] [files]\n");
    out.push_str("       lucent VERB [--help]      the robot's verbs:\n");
    for (verb, what) in VERBS {
        out.push_str(&format!("         {verb:<12} {what}\n"));
    }
    out.push('\n');
    out.push_str(
        "Grounds and solves answer-set programs (clingo dialect, CR-Prolog rules, SPARC\n",
    );
    out.push_str("sorted programs) with a native grounder and CDCL stable-model solver.\n");
    out.push_str("Reads standard input when no file (or '-') is given.\n");
    let mut groups: Vec<&str> = Vec::new();
    for spec in OPTIONS {
        if !groups.contains(&spec.group) {
            groups.push(spec.group);
        }
    }
    for group in groups {
        out.push_str(&format!("\n{group} Options:\n\n"));
        for spec in OPTIONS.iter().filter(|s| s.group == group) {
            let mut left = format!("  --{}", spec.long);
            match spec.arity {
                Flag => {}
                Value => left.push_str(&format!("={}", spec.value_name)),
                OptionalValue => left.push_str(&format!("[={}]", spec.value_name)),
            }
            if let Some(c) = spec.short {
                left.push_str(&format!(",-{c}"));
            }
            if left.len() < 28 {
                out.push_str(&format!("{left:<28}: {}\n", spec.help));
            } else {
                out.push_str(&format!("{left}\n{:<28}: {}\n", "", spec.help));
            }
        }
    }
    out.push_str("\nExit codes: 10 model found, 20 no model, 30 search exhausted with a model\n");
    out.push_str("(all models or optimum), 11 model found before a time limit, 1 interrupted\n");
    out.push_str("or bad command line (as clingo), 65 input error, 70 a verb this build does\n");
    out.push_str("not have or an I/O failure. `lucent run` and `lucent demo` exit 0 when the\n");
    out.push_str(
        "robot reached its goal and 20 when it did not; the other verbs exit 0 when done.\n",
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(s: &str) -> Vec<String> {
        s.split_whitespace().map(str::to_string).collect()
    }

    #[test]
    fn scan_reads_any_table_the_same_way() {
        #[rustfmt::skip]
        const TABLE: &[OptionSpec] = &[
            HELP,
            opt("goal", None, Value, "G", "a goal", "Options"),
            opt("goal-seed", None, Value, "N", "its seed", "Options"),
            opt("const", Some('c'), Value, "N=V", "a switch", "Options"),
            opt("full", None, Flag, "", "every reason", "Options"),
        ];
        let [_, goal, seed, konst, full] = TABLE else {
            unreachable!()
        };
        let words = args("--goal=on(a,b) x.ald -c n=3 -cm=4 --full --goal-s 7 - -- --full");
        let read: Result<Vec<Arg>, _> = scan(TABLE, &words).collect();
        let some = |s: &str| Some(s.to_string());
        assert_eq!(
            read.unwrap(),
            vec![
                Arg::Option(goal, some("on(a,b)")),
                Arg::Word("x.ald".into()),
                Arg::Option(konst, some("n=3")),
                Arg::Option(konst, some("m=4")),
                Arg::Option(full, None),
                Arg::Option(seed, some("7")),
                Arg::Word("-".into()),
                Arg::Literal("--full".into()),
            ]
        );
        let first_error = |line: &str| scan(TABLE, &args(line)).find_map(Result::err);
        assert_eq!(first_error("--go"), Some(UsageError::Unknown("go".into())));
        assert_eq!(first_error("-x"), Some(UsageError::Unknown("-x".into())));
        assert_eq!(
            first_error("--full=1"),
            Some(UsageError::UnexpectedValue("full".into()))
        );
        assert_eq!(
            first_error("--goal"),
            Some(UsageError::MissingValue("goal".into()))
        );
    }

    #[test]
    fn clingo_style_arguments() {
        let o = parse_args(&args(
            "0 a.lp -c n=3 --outf=2 -q --opt-mode=enum,3,4 -Wno-atom-undefined b.lp",
        ))
        .unwrap();
        assert_eq!(o.models, 0);
        assert_eq!(o.files, vec!["a.lp", "b.lp"]);
        assert_eq!(o.consts, vec![("n".to_string(), "3".to_string())]);
        assert_eq!(o.outf, OutputFormat::Json);
        assert_eq!(o.quiet, [2, 2, 2]);
        assert_eq!(o.opt_mode, OptMode::Enum(vec![3, 4]));
        assert_eq!(o.disabled_warnings, vec![WarningKind::AtomUndefined]);
        let o = parse_args(&args("--quiet=1")).unwrap();
        assert_eq!(o.quiet, [1, 1, 2]);
    }

    #[test]
    fn modes_parse_into_the_librarys_types() {
        let o = parse_args(&args(
            "--enum-mode=bt --cr=subset --heuristic=Domain,2 --dialect=asp --project=auto,3",
        ))
        .unwrap();
        assert_eq!(o.enum_mode, EnumMode::Auto);
        assert_eq!(o.cr, CrMode::Subset);
        assert_eq!(o.heuristic, Heuristic::Domain);
        assert_eq!(o.dialect, Some(Dialect::Clingo));
        assert_eq!(o.project, Project::Auto);
        assert_eq!(o.opt_strategy, OptStrategy::Bb);
        for (text, mode) in [
            ("--project=show", Project::Show),
            ("--project=project,2", Project::Project),
            ("--project", Project::Auto),
        ] {
            assert_eq!(parse_args(&args(text)).unwrap().project, mode, "{text}");
        }
        let o = parse_args(&args("--opt-mode=opt,5 --project=no --dialect=auto")).unwrap();
        assert_eq!(
            (o.opt_mode, o.project, o.dialect),
            (OptMode::Opt, Project::No, None)
        );
        for (text, strategy) in [
            ("--opt-strategy=usc", OptStrategy::Usc),
            ("--opt-strategy=usc,oll,3", OptStrategy::Usc),
            ("--opt-strategy=bb,hier", OptStrategy::Bb),
        ] {
            assert_eq!(
                parse_args(&args(text)).unwrap().opt_strategy,
                strategy,
                "{text}"
            );
        }
        for bad in [
            "--opt-mode=enum,x",
            "--opt-strategy=best",
            "--opt-strategy=usc,fast",
            "--heuristic=best",
            "--project=no,1",
            "--cr=all",
        ] {
            assert!(
                matches!(parse_args(&args(bad)), Err(UsageError::InvalidValue { .. })),
                "{bad}"
            );
        }
    }

    #[test]
    fn separate_and_attached_values() {
        let o = parse_args(&args("-n 5 -W none --mode clasp")).unwrap();
        assert_eq!(o.models, 5);
        assert_eq!(o.disabled_warnings.len(), WarningKind::ALL.len());
        assert_eq!(o.mode, Mode::Clasp);
        let o = parse_args(&args("-n3 --text --time-limit=2.5 --proj")).unwrap();
        assert_eq!(o.models, 3);
        assert_eq!(
            (o.mode, o.ground_format),
            (Mode::Gringo, GroundFormat::Text)
        );
        assert_eq!(o.time_limit, Some(2.5));
        assert_eq!(o.project, Project::Auto);
        let o = parse_args(&args("--seed=7 --rand-freq=0.02")).unwrap();
        assert_eq!((o.seed, o.rand_freq_permille), (7, 20));
    }

    #[test]
    fn usage_errors() {
        assert_eq!(
            parse_args(&args("--foo")),
            Err(UsageError::Unknown("foo".into()))
        );
        assert_eq!(
            parse_args(&args("-n")),
            Err(UsageError::MissingValue("n".into()))
        );
        assert!(matches!(
            parse_args(&args("-n x")),
            Err(UsageError::InvalidValue { .. })
        ));
        assert!(matches!(
            parse_args(&args("--outf=7")),
            Err(UsageError::InvalidValue { .. })
        ));
        assert!(matches!(
            parse_args(&args("--rand-freq=1.5")),
            Err(UsageError::InvalidValue { .. })
        ));
        assert!(matches!(
            parse_args(&args("-c 3=4")),
            Err(UsageError::InvalidValue { .. })
        ));
        assert_eq!(
            parse_args(&args("--check=1")),
            Err(UsageError::UnexpectedValue("check".into()))
        );
    }

    #[test]
    fn help_lists_every_option() {
        let help = help_text();
        for spec in OPTIONS {
            assert!(help.contains(&format!("--{}", spec.long)), "{}", spec.long);
        }
    }
}
