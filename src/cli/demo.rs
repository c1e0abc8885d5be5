//! `lucent demo`: the main job, end to end on built-in data.
//!
//! It takes the tabletop domain (`domains/tabletop/tabletop.lp`, compiled into the binary so the
//! demo runs from any directory), grounds it with Lucent's grounder, solves it with Lucent's
//! solver under the default CR-Prolog semantics, checks every answer set independently, and
//! prints the minimal plans as numbered action sequences. Later issues add execution in the
//! simulated world, learning and explanations here.
//!
//! Invariant: the demo is a client of `control::Control` (the library's front door) and of the
//! independent model check, so it exercises exactly what users of the library get; plans are
//! read from `occurs(Action, Step)` atoms as structured terms.

use std::io::Write;
use std::time::Instant;

use crate::control::{Control, ControlConfig, Part, SolveOptions, Symbol};
use crate::solve::{self, Config};
use crate::syntax::ast::Dialect;

/// The built-in program.
const TABLETOP: &str = include_str!("../../domains/tabletop/tabletop.lp");

/// `lucent demo --help`.
const HELP: &str = "\
usage: lucent demo [--program FILE]

Grounds and solves the built-in tabletop task of the robot-assistant domain: the pitcher stands
on the red cube and the robot must hold the red cube. Prints the minimal plans (cardinality-
minimal CR-rule applications, as SPARC computes them), each verified by an independent
stable-model check. With --program, runs the same on another planning program whose answer
sets contain occurs(Action, Step) atoms.
";

/// One plan: `occurs(Action, Step)` atoms of an answer set, as (step, action) sorted by step.
fn plan_of(atoms: &[Symbol]) -> Vec<(i64, Symbol)> {
    let mut steps: Vec<(i64, Symbol)> = atoms
        .iter()
        .filter(|a| a.is("occurs", 2) && !a.is_negative())
        .filter_map(|a| Some((i64::from(a.args()[1].as_number()?), a.args()[0].clone())))
        .collect();
    steps.sort();
    steps
}

/// Runs the demo; returns the exit code.
pub fn run(args: &[String], out: &mut dyn Write, err: &mut dyn Write) -> std::io::Result<i32> {
    let mut name = "domains/tabletop/tabletop.lp (built in)".to_string();
    let mut text = TABLETOP.to_string();
    let mut i = 0;
    while i < args.len() {
        match args[i].as_str() {
            "--help" | "-h" => {
                write!(out, "{HELP}")?;
                return Ok(0);
            }
            "--program" if i + 1 < args.len() => {
                name = args[i + 1].clone();
                match std::fs::read_to_string(&name) {
                    Ok(t) => text = t,
                    Err(e) => {
                        writeln!(err, "lucent demo: cannot read {name}: {e}")?;
                        return Ok(super::EXIT_INPUT);
                    }
                }
                i += 1;
            }
            other => {
                writeln!(
                    err,
                    "lucent demo: unknown argument `{other}` (try `lucent demo --help`)"
                )?;
                return Ok(super::EXIT_USAGE);
            }
        }
        i += 1;
    }

    let start = Instant::now();
    let config = ControlConfig {
        solve: Config {
            models: 0,
            check_models: true,
            ..Config::default()
        },
        dialect: Some(Dialect::Clingo),
        ..ControlConfig::default()
    };
    let mut control = Control::new(config);
    let grounded = control
        .add(&name, &text)
        .and_then(|()| control.ground(&[Part::base()]));
    if let Err(e) = grounded {
        write!(err, "{}", e.message)?;
        return Ok(super::EXIT_INPUT);
    }
    write!(
        err,
        "{}",
        control.take_diagnostics().render(control.sources())
    )?;
    let ground_time = start.elapsed();
    let (num_atoms, num_rules, num_cr) = {
        let p = control.program();
        (p.num_atoms, p.rules.len(), p.cr_rules.len())
    };
    let mut plans: Vec<Vec<(i64, Symbol)>> = Vec::new();
    let mut models: Vec<(usize, Vec<u32>)> = Vec::new();
    let result = control.solve(&SolveOptions::default(), |m| {
        models.push((m.number(), m.raw().atoms.clone()));
        let plan = plan_of(&m.atoms());
        if !plans.contains(&plan) {
            plans.push(plan);
        }
        true
    });
    let total = start.elapsed();
    for (number, atoms) in &models {
        if let Err(why) = solve::check::check(control.program(), atoms) {
            writeln!(
                err,
                "lucent demo: answer set {number} failed the stable-model check: {why}"
            )?;
            return Ok(super::EXIT_UNAVAILABLE);
        }
    }
    plans.sort();

    writeln!(out, "Lucent demo: the robot-assistant tabletop task")?;
    writeln!(out, "  program : {name}")?;
    writeln!(
        out,
        "  task    : the pitcher stands on the red cube; the robot must hold the red cube"
    )?;
    writeln!(
        out,
        "  ground  : {} atoms, {} rules, {} CR rule instances ({:.3}s)",
        num_atoms,
        num_rules,
        num_cr,
        ground_time.as_secs_f64()
    )?;
    match result.outcome {
        solve::Outcome::Unsatisfiable => writeln!(out, "\nNo plan within the horizon.")?,
        solve::Outcome::Unknown => writeln!(out, "\nThe search stopped before an answer.")?,
        _ => {
            let len = plans.first().map_or(0, Vec::len);
            writeln!(
                out,
                "\n{} minimal plan(s) of {} step(s), each answer set checked independently:",
                plans.len(),
                len
            )?;
            for (k, plan) in plans.iter().enumerate() {
                let steps: Vec<String> = plan.iter().map(|(i, a)| format!("{i}: {a}")).collect();
                writeln!(out, "  plan {}: {}", k + 1, steps.join("; "))?;
            }
        }
    }
    writeln!(
        out,
        "\nsolved in {:.3}s ({} conflicts, {} choices); answer sets: {}{}",
        total.as_secs_f64(),
        result.stats.conflicts,
        result.stats.choices,
        result.models,
        if result.exhausted { "" } else { "+" }
    )?;
    Ok(demo_exit_code(result.outcome, plans.len()))
}

/// The demo is a job, not a solver call: it exits 0 when it printed at least one plan, so a shell
/// or `cargo run` treats the main job's success as success. Without a plan it answers with
/// clingo's codes: 20 when the horizon has no plan, 1 (interrupted) when the search stopped
/// before an answer.
fn demo_exit_code(outcome: solve::Outcome, plans: usize) -> i32 {
    match outcome {
        solve::Outcome::Unknown if plans == 0 => super::EXIT_INTERRUPTED,
        _ if plans == 0 => super::EXIT_UNSAT,
        _ => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plans_are_read_from_occurs_atoms() {
        let atoms: Vec<Symbol> = [
            "occurs(pickup(rob1,a),1)",
            "occurs(putdown(rob1,b,table),0)",
            "-occurs(pickup(rob1,b),0)",
            "goal(3)",
        ]
        .iter()
        .map(|s| Symbol::parse(s).unwrap())
        .collect();
        let plan: Vec<(i64, String)> = plan_of(&atoms)
            .into_iter()
            .map(|(i, a)| (i, a.to_string()))
            .collect();
        assert_eq!(
            plan,
            vec![
                (0, "putdown(rob1,b,table)".to_string()),
                (1, "pickup(rob1,a)".to_string())
            ]
        );
    }
}
