//! `lucent plan FILE.ald [--all] [--max-horizon H] [--profile P] [-c name=value] [--outf=2]`:
//! the planner of [`crate::plan`] on an AL_d planning problem (description, initial state and
//! goal), printing the minimal plan (or all distinct minimal plans with `--all`) as text or,
//! with `--outf=2`, as JSON `{"plans": [["pickup(rob1,a)", ...]], "length": N, "cr_applied": N}`.
//!
//! Invariants: files are read here only; bad input is reported with positions and exit code
//! 65; no plan within the horizon budget and an inconsistent scene are a message and exit 20
//! (clingo's code for unsatisfiable); a plan found is exit 0.

use std::io::Write;

use crate::action;
use crate::base::SourceMap;
use crate::plan::{plan, PlanConfig, PlanError};

/// `lucent plan --help`.
const HELP: &str = "\
usage: lucent plan FILE.ald [--all] [--max-horizon H] [--profile NAME] [-c NAME=VALUE]... [--outf=2]

Finds a minimal plan for the goal of an AL_d planning problem (DOMAIN.md 4.1-4.2): horizons
0, 1, ..., H are tried in turn (default H = 10); plans are ordered by length, then by CR rule
applications. --all prints every distinct minimal plan; --outf=2 prints JSON.
";

/// Exit code when there is no plan (clingo's code for unsatisfiable).
const EXIT_NO_PLAN: i32 = 20;

/// `lucent plan`.
pub fn run_plan(args: &[String], out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<i32> {
    let mut file = None;
    let mut all = false;
    let mut json = false;
    let mut config = PlanConfig::default();
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
        } else if a == "--all" {
            all = true;
        } else if a.starts_with("--outf") {
            match value(&mut i, "--outf").as_deref() {
                Some("2") => json = true,
                Some("0") => json = false,
                v => {
                    writeln!(
                        err,
                        "*** ERROR: (lucent): '--outf={}': expected 0 or 2",
                        v.unwrap_or("")
                    )?;
                    return Ok(super::EXIT_USAGE);
                }
            }
        } else if a.starts_with("--max-horizon") {
            match value(&mut i, "--max-horizon").and_then(|v| v.parse().ok()) {
                Some(h) => config.max_horizon = h,
                None => {
                    writeln!(
                        err,
                        "*** ERROR: (lucent): '{a}': expected --max-horizon H (a number)"
                    )?;
                    return Ok(super::EXIT_USAGE);
                }
            }
        } else if a.starts_with("--profile") {
            config.profile = value(&mut i, "--profile");
        } else if a.starts_with("-c") {
            match value(&mut i, "-c").and_then(|v| {
                v.split_once('=')
                    .map(|(n, v)| (n.trim().to_string(), super::action::value_of(v.trim())))
            }) {
                Some(c) => config.overrides.push(c),
                None => {
                    writeln!(err, "*** ERROR: (lucent): '{a}': expected -c NAME=VALUE")?;
                    return Ok(super::EXIT_USAGE);
                }
            }
        } else if a.starts_with('-') {
            writeln!(
                err,
                "*** ERROR: (lucent): '{a}': unknown option of `lucent plan` (try --help)"
            )?;
            return Ok(super::EXIT_USAGE);
        } else if file.is_none() {
            file = Some(a.to_string());
        } else {
            writeln!(err, "*** ERROR: (lucent): `lucent plan` takes one file")?;
            return Ok(super::EXIT_USAGE);
        }
        i += 1;
    }
    let Some(name) = file else {
        writeln!(
            err,
            "*** ERROR: (lucent): `lucent plan` needs a file (try --help)"
        )?;
        return Ok(super::EXIT_USAGE);
    };
    let text = match std::fs::read_to_string(&name) {
        Ok(t) => t,
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {name}: {e}")?;
            return Ok(super::EXIT_INPUT);
        }
    };
    let mut sources = SourceMap::new();
    let id = sources.add(name.clone(), text);
    let mut read =
        |path: &std::path::Path| std::fs::read_to_string(path).map_err(|e| e.to_string());
    let parsed = action::load(&mut sources, id, &mut read);
    if parsed.has_errors() {
        let mut d = crate::base::Diagnostics::default();
        d.extend(parsed.diagnostics);
        write!(err, "{}", d.render(&sources))?;
        writeln!(
            err,
            "*** ERROR: (lucent): {name}: not a valid AL_d planning problem"
        )?;
        return Ok(super::EXIT_INPUT);
    }
    match plan(&parsed.description, &sources, &config) {
        Ok(found) => {
            let shown = if all {
                &found.plans[..]
            } else {
                &found.plans[..1]
            };
            if json {
                let plans: Vec<Vec<String>> = shown
                    .iter()
                    .map(|p| p.actions.iter().map(|a| a.to_string()).collect())
                    .collect();
                let value = serde_json::json!({
                    "plans": plans,
                    "length": found.length,
                    "cr_applied": found.cr_applied,
                });
                writeln!(out, "{value}")?;
            } else {
                for p in shown {
                    writeln!(out, "Plan: {}", p.to_text())?;
                }
                writeln!(out, "Length: {}", found.length)?;
                writeln!(out, "CR applied: {}", found.cr_applied)?;
                writeln!(
                    out,
                    "Plans: {} of {} minimal",
                    shown.len(),
                    found.plans.len()
                )?;
            }
            Ok(0)
        }
        Err(PlanError::Input(m)) => {
            writeln!(err, "{}", m.trim_end())?;
            writeln!(
                err,
                "*** ERROR: (lucent): {name}: not a valid AL_d planning problem"
            )?;
            Ok(super::EXIT_INPUT)
        }
        Err(e) => {
            writeln!(err, "*** ERROR: (lucent): {name}: {e}")?;
            Ok(EXIT_NO_PLAN)
        }
    }
}
