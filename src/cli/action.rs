//! AL_d inputs on the command line: `lucent translate FILE.ald [--profile P] [-c name=value]`
//! prints the CR-Prolog translation, and `lucent FILE.ald` grounds and solves it like any
//! other program (the pipeline in `cli::mod` calls [`translate_input`]).
//!
//! Invariants: files are read here (the `action` module gets a reader); bad AL_d input is
//! reported with gringo-style positions and exit code 65; `-c name=value` sets an AL_d switch
//! of that name when there is one (the value read as an integer, `true`/`false`/`on`/`off`, or a
//! word) and stays a grounding constant as well.

use std::io::Write;

use crate::action::{self, ast::Value, Options, Translation};
use crate::base::{Diagnostics, FileId, SourceMap};

use super::options::{self, opt, Arg, Arity::*, OptionSpec, Verb};

/// `lucent translate`'s command line; `--help` is generated from it.
pub(super) const VERB: Verb = Verb {
    usage: "\
usage: lucent translate FILE.ald [--profile NAME] [-c NAME=VALUE]...

Translates an AL_d system description and history (grammar/action.ebnf) into a CR-Prolog
program (docs/domain.md section 3) and prints it. Each group of rules is preceded by a comment that
names the AL_d statement it came from (label, kind, text).
",
    options: OPTIONS,
    epilogue: "",
};

/// The options of `lucent translate`.
#[rustfmt::skip]
const OPTIONS: &[OptionSpec] = &[
    options::HELP,
    opt("profile", None, Value, "NAME", "a switch bundle the description declares (e.g. tabletop, learner, main2019)", "Options"),
    opt("const", Some('c'), Value, "NAME=VALUE", "set a switch (e.g. -c horizon=3); may be repeated", "Options"),
];

/// `lucent translate`'s command line: the file, the profile and the switches.
struct Args {
    file: String,
    profile: Option<String>,
    consts: Vec<(String, String)>,
}

fn parse(args: &[String]) -> Result<Args, String> {
    let (mut file, mut profile, mut consts) = (None, None, Vec::new());
    for arg in options::scan(OPTIONS, args) {
        match arg.map_err(|e| e.to_string())? {
            Arg::Option(spec, v) => {
                let v = v.unwrap_or_default();
                match spec.long {
                    "profile" => profile = Some(v),
                    "const" => consts.push(spec.assignment(&v)?),
                    _ => {} // --help, answered before parsing
                }
            }
            Arg::Word(w) | Arg::Literal(w) if file.is_none() => file = Some(w),
            Arg::Word(_) | Arg::Literal(_) => {
                return Err("`lucent translate` takes one file".into())
            }
        }
    }
    let file = file.ok_or("`lucent translate` needs a file (try --help)")?;
    Ok(Args {
        file,
        profile,
        consts,
    })
}

/// Reads an AL_d switch value as written on the command line.
pub fn value_of(text: &str) -> Value {
    match text {
        "true" | "on" => Value::Bool(true),
        "false" | "off" => Value::Bool(false),
        _ => match text.parse::<i64>() {
            Ok(n) => Value::Int(n),
            Err(_) => Value::Word(text.to_string()),
        },
    }
}

/// Parses (with includes), checks and translates the AL_d file `file` of `sources`; the
/// diagnostics go to `diags`. Returns `None` when there are errors.
pub fn translate_input(
    sources: &mut SourceMap,
    file: FileId,
    profile: Option<&str>,
    consts: &[(String, String)],
    diags: &mut Diagnostics,
) -> Option<Translation> {
    let mut read =
        |path: &std::path::Path| super::builtin::read_to_string(path).map_err(|e| e.to_string());
    let parsed = action::load(sources, file, &mut read);
    let parse_errors = parsed.has_errors();
    diags.extend(parsed.diagnostics);
    if parse_errors {
        return None;
    }
    let options = Options {
        profile: profile.map(str::to_string),
        overrides: consts
            .iter()
            .map(|(n, v)| (n.clone(), value_of(v)))
            .collect(),
        ..Options::default()
    };
    let translation = action::translate(&parsed.description, &options);
    let errors = translation.has_errors();
    diags.extend(translation.diagnostics.clone());
    (!errors).then_some(translation)
}

/// Prints the program with one comment line per group of statements of the same origin.
pub fn print_with_origins(t: &Translation, sources: &SourceMap) -> String {
    let mut out = String::new();
    let mut last: Option<(Option<usize>, action::OriginKind)> = None;
    for (st, origin) in t.program.statements.iter().zip(&t.origins) {
        let key = (origin.statement, origin.kind);
        if last != Some(key) {
            out.push_str("\n% ");
            if let Some(label) = &origin.label {
                out.push_str(label);
                out.push_str(": ");
            }
            out.push_str(origin.kind.name());
            if origin.statement.is_some() && !origin.text.is_empty() {
                out.push_str(": ");
                out.push_str(&origin.text);
            }
            if let Some(span) = origin.span {
                out.push_str(" (");
                out.push_str(&sources.location(span));
                out.push(')');
            }
            out.push('\n');
            last = Some(key);
        }
        crate::syntax::printer::statement(&mut out, &st.kind);
        out.push('\n');
    }
    out
}

/// `lucent translate`.
pub fn run_translate(
    args: &[String],
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    let Args {
        file: name,
        profile,
        consts,
    } = match super::verb_args(&VERB, args, parse, out, err)? {
        Ok(a) => a,
        Err(code) => return Ok(code),
    };
    let mut sources = SourceMap::new();
    let mut diags = Diagnostics::default();
    let (loaded, load_diags) = super::input::load(
        std::slice::from_ref(&name),
        &mut std::io::empty(),
        &mut sources,
    );
    diags.extend(load_diags);
    let translation = match loaded.first() {
        Some(input) => translate_input(
            &mut sources,
            input.file,
            profile.as_deref(),
            &consts,
            &mut diags,
        ),
        None => None,
    };
    write!(err, "{}", diags.render(&sources))?;
    match translation {
        Some(t) if !diags.has_errors() => {
            write!(out, "{}", print_with_origins(&t, &sources))?;
            Ok(0)
        }
        _ => {
            writeln!(err, "*** ERROR: (lucent): translating failed")?;
            Ok(super::EXIT_INPUT)
        }
    }
}
