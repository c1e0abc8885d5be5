//! clingo's incremental mode (`#include <incmode>.`), run on one [`Control`].
//!
//! The loop is clingo's: with the constants `imin` (default 0), `imax` (default none) and
//! `istop` (default `"SAT"`), step 0 grounds `base` and `check(0)`; step `t > 0` releases the
//! external `query(t-1)` and grounds `step(t)` and `check(t)`; after grounding, `query(t)` is
//! assigned true and the program is solved. The loop goes on while `imax` is not reached and
//! either `t < imin` or the last answer is not the one `istop` waits for (`SAT`: satisfiable,
//! `UNSAT`: unsatisfiable, `UNKNOWN`: unknown).
//!
//! Invariant: one Control carries every step (earlier parts are never grounded again); the
//! caller sees each step's start and models through callbacks, so printing stays in `cli`.

use super::{Control, Error, Model, Part, SolveOptions, Summary, Symbol, TruthValue};

/// The loop's result.
#[derive(Clone, Debug)]
pub struct IncSummary {
    /// Solve calls made (one per step).
    pub calls: usize,
    /// Models reported over all calls.
    pub models: usize,
    /// The last call's summary, `None` when no step ran (`imax = 0`).
    pub last: Option<Summary>,
}

/// What stops the loop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Stop {
    Sat,
    Unsat,
    Unknown,
}

/// What the loop reports to its caller.
pub enum Event<'a, 'b> {
    /// Step `t` is about to be solved (clingo prints `Solving...` here).
    Solving(usize),
    /// A model of step `t`.
    Model(usize, &'a Model<'b>),
}

/// Runs the incremental loop, reporting each step and each model to `on` (return false on a
/// model to stop that step's enumeration).
pub fn run(
    control: &mut Control,
    mut on: impl FnMut(Event<'_, '_>) -> bool,
) -> Result<IncSummary, Error> {
    let num = |s: Option<Symbol>| s.and_then(|s| s.as_number());
    let imin = num(control.get_const("imin")).unwrap_or(0).max(0) as usize;
    let imax = num(control.get_const("imax")).map(|n| n.max(0) as usize);
    let istop = match control.get_const("istop") {
        Some(Symbol::String(s)) if s == "UNSAT" => Stop::Unsat,
        Some(Symbol::String(s)) if s == "UNKNOWN" => Stop::Unknown,
        _ => Stop::Sat,
    };
    let mut summary = IncSummary {
        calls: 0,
        models: 0,
        last: None,
    };
    let mut step = 0usize;
    loop {
        if imax.is_some_and(|m| step >= m) {
            break;
        }
        if step > 0 && step >= imin {
            let last = summary.last.as_ref().expect("a step ran");
            let done = match istop {
                Stop::Sat => last.is_satisfiable(),
                Stop::Unsat => last.is_unsatisfiable(),
                Stop::Unknown => last.outcome == crate::solve::Outcome::Unknown,
            };
            if done {
                break;
            }
        }
        let t = Symbol::number(step as i32);
        let mut parts = Vec::new();
        if step > 0 {
            control.release_external(&query(step - 1));
            parts.push(Part::new("step", vec![t.clone()]));
        } else {
            parts.push(Part::base());
        }
        parts.push(Part::new("check", vec![t]));
        control.ground(&parts)?;
        control.assign_external(&query(step), TruthValue::True);
        on(Event::Solving(step));
        let s = control.solve(&SolveOptions::default(), |m| on(Event::Model(step, m)));
        summary.calls += 1;
        summary.models += s.models;
        summary.last = Some(s);
        step += 1;
    }
    Ok(summary)
}

fn query(t: usize) -> Symbol {
    Symbol::function("query", vec![Symbol::number(t as i32)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::ControlConfig;

    fn steps(text: &str) -> Vec<Vec<String>> {
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add_source("inc.lp", text).unwrap();
        assert!(ctl.incmode());
        let mut out = Vec::<Vec<String>>::new();
        run(&mut ctl, |e| {
            match e {
                Event::Solving(_) => out.push(Vec::new()),
                Event::Model(_, m) => {
                    let mut s: Vec<String> = m.symbols().iter().map(|s| s.to_string()).collect();
                    s.sort();
                    out.last_mut().unwrap().push(s.join(" "));
                }
            }
            true
        })
        .unwrap();
        for step in &mut out {
            step.sort();
        }
        out
    }

    #[test]
    fn steps_until_the_goal_is_reached() {
        // A counter reaching 2: step 0 and 1 are unsatisfiable under query(t).
        let out = steps(
            "#include <incmode>.\n#program base. c(0).\n#program step(t). c(t) :- c(t-1).\n\
             #program check(t). :- query(t), not c(2).\n#show c/1.",
        );
        assert_eq!(
            out,
            vec![vec![], vec![], vec!["c(0) c(1) c(2)".to_string()]]
        );
    }

    #[test]
    fn imin_imax_and_istop() {
        let out = steps("#include <incmode>.\n#const imin=3.\n#program base. a.");
        assert_eq!(out.len(), 3);
        let out = steps("#include <incmode>.\n#const imax=2.\n#program base. :- not a.");
        assert_eq!(out.len(), 2);
        let out =
            steps("#include <incmode>.\n#const istop=\"UNSAT\".\n#program step(t). :- t > 1.");
        assert_eq!(out.len(), 3);
    }
}
