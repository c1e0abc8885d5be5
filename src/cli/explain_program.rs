//! `lucent explain PROGRAM.lp` over any clingo program: reading the program (files, `-c`
//! constants) for `--why`/`--why-not` and `--why-unsat`; an oracle over each of the first
//! `--models N` answer sets and their answers as one; the `--why-unsat` answer (a minimal
//! unsatisfiable subset of facts and constraints, `explain::unsat`), as text or with `--outf=2`
//! as JSON; an unsatisfiable program asked `--why`/`--why-not` is pointed to `--why-unsat`.
//!
//! Invariants: files are read here only; bad files and bad signatures are diagnostics with exit
//! 65 (constants: usage, exit 1); an unsatisfiable program exits 20, as clingo's UNSAT.

use std::io::Write;

use crate::base::SourceMap;
use crate::control::{Control, ControlConfig, Part, SolveOptions};
use crate::explain::oracle::{Labels, ProgramOracle};
use crate::explain::questions::Answer;
use crate::explain::unsat::{why_unsat, Signature, UnsatConfig, WhyUnsat};
use crate::syntax::ast;

/// A clingo program read from the command line's files, with its `-c` constants.
pub(super) struct Loaded {
    pub sources: SourceMap,
    pub program: ast::Program,
    pub consts: Vec<(String, ast::Term)>,
}

/// Reads and parses `files` (`.sp`: SPARC) and the `-c` overrides; `Err(code)` after the
/// error was written.
pub(super) fn load_program(
    files: &[String],
    overrides: &[(String, String)],
    err: &mut dyn Write,
) -> std::io::Result<Result<Loaded, i32>> {
    let mut sources = SourceMap::new();
    let mut program = ast::Program::default();
    let mut diags = crate::base::Diagnostics::default();
    for name in files {
        let text = match super::builtin::read_to_string(name) {
            Ok(t) => t,
            Err(e) => {
                writeln!(err, "*** ERROR: (lucent): {name}: {e}")?;
                return Ok(Err(super::EXIT_INPUT));
            }
        };
        let dialect = if name.ends_with(".sp") {
            ast::Dialect::Sparc
        } else {
            ast::Dialect::Clingo
        };
        let id = sources.add(name.clone(), text.clone());
        let parse = crate::syntax::parse(id, &text, dialect);
        diags.extend(parse.diagnostics);
        program.dialect = parse.program.dialect;
        program.statements.extend(parse.program.statements);
    }
    if diags.has_errors() {
        write!(err, "{}", diags.render(&sources))?;
        writeln!(err, "*** ERROR: (lucent): parsing failed")?;
        return Ok(Err(super::EXIT_INPUT));
    }
    let mut consts = Vec::new();
    for (n, v) in overrides {
        match crate::control::const_term(v) {
            Some(t) => consts.push((n.clone(), t)),
            None => {
                writeln!(
                    err,
                    "*** ERROR: (lucent): '-c {n}={v}': not a constant value"
                )?;
                return Ok(Err(super::EXIT_USAGE));
            }
        }
    }
    Ok(Ok(Loaded {
        sources,
        program,
        consts,
    }))
}

/// What `--why`/`--why-not` says about a program without an answer set.
pub(super) fn say_unsat(json: bool, out: &mut dyn Write) -> std::io::Result<i32> {
    let text = "UNSATISFIABLE: the program has no answer set to explain. \
                `--why-unsat` names a minimal set of its facts and constraints that cannot \
                hold together.";
    if json {
        let v = serde_json::json!({
            "type": "unsatisfiable",
            "answer": text,
            "literals": [],
            "see": "--why-unsat",
        });
        writeln!(out, "{v}")?;
    } else {
        writeln!(out, "{text}")?;
    }
    Ok(super::EXIT_UNSAT)
}

/// `lucent explain PROGRAM.lp --why-unsat [--assume SIG]... [--assume-choices]`.
pub(super) fn run_why_unsat(
    files: &[String],
    overrides: &[(String, String)],
    assume: &[String],
    choices: bool,
    json: bool,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> std::io::Result<i32> {
    let mut signatures = Vec::new();
    for s in assume {
        match Signature::parse(s) {
            Ok(sig) => signatures.push(sig),
            Err(m) => {
                writeln!(err, "*** ERROR: (lucent): --assume {m}")?;
                return Ok(super::EXIT_INPUT);
            }
        }
    }
    let loaded = match load_program(files, overrides, err)? {
        Ok(l) => l,
        Err(code) => return Ok(code),
    };
    let config = UnsatConfig {
        assume: signatures,
        choices,
        consts: loaded.consts,
    };
    match why_unsat(&loaded.program, &loaded.sources, &config) {
        Err(m) => {
            writeln!(err, "{m}")?;
            writeln!(err, "*** ERROR: (lucent): grounding stopped")?;
            Ok(super::EXIT_INPUT)
        }
        Ok(WhyUnsat::Satisfiable) => {
            let text = "SATISFIABLE: the program has an answer set; `--why ATOM` explains \
                        an atom of it.";
            if json {
                let v = serde_json::json!({"type": "why_unsat", "answer": text, "literals": []});
                writeln!(out, "{v}")?;
            } else {
                writeln!(out, "{text}")?;
            }
            Ok(0)
        }
        Ok(WhyUnsat::Unsatisfiable(u)) => {
            if json {
                writeln!(out, "{}", u.to_json(&loaded.program, &loaded.sources))?;
            } else {
                writeln!(out, "{}", u.text(&loaded.program, &loaded.sources))?;
            }
            Ok(super::EXIT_UNSAT)
        }
    }
}

/// Grounds the program once per answer set (each with provenance, so each oracle owns its
/// Control) and returns an oracle over each of the first `models` answer sets (0: all); empty
/// when the program has none. `Err(code)` after the error was written.
pub(super) fn oracles(
    files: &[String],
    overrides: &[(String, String)],
    models: usize,
    err: &mut dyn Write,
) -> std::io::Result<Result<Vec<ProgramOracle>, i32>> {
    let loaded = match load_program(files, overrides, err)? {
        Ok(l) => l,
        Err(code) => return Ok(Err(code)),
    };
    let labels = Labels::from_program(&loaded.program, &|s| loaded.sources.location(s.span));
    let ground = || -> Result<Control, String> {
        let mut config = ControlConfig::default();
        // Every answer set is offered; the callback below stops after `models`.
        config.solve.models = 0;
        config.ground.provenance = true;
        config.ground.consts = loaded.consts.clone();
        let mut ctl = Control::with_sources(config, loaded.sources.clone());
        ctl.add_program(loaded.program.clone())
            .and_then(|()| ctl.ground(&[Part::base()]))
            .map_err(|e| e.message.trim_end().to_string())?;
        Ok(ctl)
    };
    let mut ctl = match ground() {
        Ok(c) => c,
        Err(m) => {
            writeln!(err, "{m}")?;
            writeln!(err, "*** ERROR: (lucent): grounding stopped")?;
            return Ok(Err(super::EXIT_INPUT));
        }
    };
    let mut found = Vec::new();
    ctl.solve(&SolveOptions::default(), |m| {
        found.push(m.raw().clone());
        models == 0 || found.len() < models
    });
    let mut out = Vec::with_capacity(found.len());
    let mut first = Some(ctl);
    for model in found {
        // The grounding is deterministic: a second Control numbers atoms as the first.
        let ctl = match first.take() {
            Some(c) => c,
            None => match ground() {
                Ok(c) => c,
                Err(m) => {
                    writeln!(err, "*** ERROR: (lucent): {m}")?;
                    return Ok(Err(super::EXIT_UNAVAILABLE));
                }
            },
        };
        match ProgramOracle::new(ctl, model, labels.clone()) {
            Ok(o) => out.push(o),
            Err(e) => {
                writeln!(err, "*** ERROR: (lucent): {e}")?;
                return Ok(Err(super::EXIT_UNAVAILABLE));
            }
        }
    }
    Ok(Ok(out))
}

/// The answers in several answer sets as one: text `Answer k:` then each answer; JSON
/// `{type, answer, literals, answers: [per answer set]}`; the tree is the first answer's.
pub(super) fn per_model(answers: &[Answer]) -> (Answer, serde_json::Value) {
    let mut text = String::new();
    let mut literals = Vec::new();
    for (k, a) in answers.iter().enumerate() {
        if k > 0 {
            text.push_str("\n\n");
        }
        text.push_str(&format!("Answer {}:\n{}", k + 1, a.text));
        for l in &a.literals {
            if !literals.contains(l) {
                literals.push(l.clone());
            }
        }
    }
    let all = Answer {
        kind: answers.first().map_or("why", |a| a.kind),
        text,
        literals,
        tree: answers.first().and_then(|a| a.tree.clone()),
    };
    let mut json = all.to_json();
    json["answers"] = answers.iter().map(Answer::to_json).collect();
    (all, json)
}
