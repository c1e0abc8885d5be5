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

/// `lucent translate --help`.
const HELP: &str = "\
usage: lucent translate FILE.ald [--profile NAME] [-c NAME=VALUE]...

Translates an AL_d system description and history (grammar/action.ebnf) into a CR-Prolog
program (docs/domain.md section 3) and prints it. Each group of rules is preceded by a comment that
names the AL_d statement it came from (label, kind, text). --profile chooses a switch bundle the
description declares (e.g. tabletop, learner, main2019); -c sets a switch (e.g. -c horizon=3).
";

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
    let mut file = None;
    let mut profile = None;
    let mut consts = Vec::new();
    let mut i = 0;
    while i < args.len() {
        let a = args[i].as_str();
        let value = |i: &mut usize, prefix: &str| -> Option<String> {
            if a.len() > prefix.len() {
                Some(a[prefix.len()..].trim_start_matches('=').to_string())
            } else {
                *i += 1;
                args.get(*i).cloned()
            }
        };
        if a == "--help" || a == "-h" {
            write!(out, "{HELP}")?;
            return Ok(0);
        } else if a.starts_with("--profile") {
            profile = value(&mut i, "--profile");
        } else if a.starts_with("--const") || a.starts_with("-c") {
            let prefix = if a.starts_with("--const") {
                "--const"
            } else {
                "-c"
            };
            match value(&mut i, prefix).and_then(|v| {
                v.split_once('=')
                    .map(|(n, v)| (n.trim().to_string(), v.trim().to_string()))
            }) {
                Some(c) => consts.push(c),
                None => {
                    writeln!(err, "*** ERROR: (lucent): '{a}': expected -c NAME=VALUE")?;
                    return Ok(super::EXIT_USAGE);
                }
            }
        } else if a.starts_with('-') && a != "-" {
            writeln!(
                err,
                "*** ERROR: (lucent): '{a}': unknown option of `lucent translate` (try --help)"
            )?;
            return Ok(super::EXIT_USAGE);
        } else if file.is_none() {
            file = Some(a.to_string());
        } else {
            writeln!(
                err,
                "*** ERROR: (lucent): `lucent translate` takes one file"
            )?;
            return Ok(super::EXIT_USAGE);
        }
        i += 1;
    }
    let Some(name) = file else {
        writeln!(
            err,
            "*** ERROR: (lucent): `lucent translate` needs a file (try --help)"
        )?;
        return Ok(super::EXIT_USAGE);
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
