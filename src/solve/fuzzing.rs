//! The body of the `aspif` fuzz target (`fuzz/fuzz_targets/aspif.rs`), kept in the library so
//! that an ordinary test (`tests/ground/aspif_fuzz_corpus.rs`) runs it over the seed corpus and it
//! cannot rot.
//!
//! Invariants checked on arbitrary bytes: the aspif reader returns a program or an error whose
//! line and column lie inside the input, and never panics; a program it accepts can be written
//! back (`aspif::write`) and that text reads again; and a small accepted program can be solved
//! with every model checked by the independent checker (`Config::check_models`), which panics
//! on a wrong model, after its atoms are renumbered densely as `lucent --mode=clasp` does
//! (`GroundProgram::compact_atoms`). Programs with more than [`MAX_ATOMS`] atoms or
//! [`MAX_STATEMENTS`] statements are not solved, to keep each input fast.

use std::time::{Duration, Instant};

use crate::ground::aspif;

use super::{Config, OptMode, Solver};

/// Largest atom number of a program the fuzz body still solves.
pub const MAX_ATOMS: u32 = 10_000;
/// Largest number of statements of a program the fuzz body still solves.
pub const MAX_STATEMENTS: usize = 2_000;

/// Reads `bytes` as aspif and checks the invariants of the module documentation. Returns an
/// error describing a broken invariant (a panic in the code under test propagates).
pub fn check_aspif_bytes(bytes: &[u8]) -> Result<(), String> {
    let lines = bytes.split(|&b| b == b'\n').count() as u32;
    let aspif = match aspif::read(bytes) {
        Ok(a) => a,
        Err(e) => {
            if e.line == 0 || e.column == 0 || e.line > lines.max(1) {
                return Err(format!("error position out of the input: {e}"));
            }
            return Ok(());
        }
    };
    let text = aspif::write(&aspif);
    if let Err(e) = aspif::read(text.as_bytes()) {
        return Err(format!(
            "the writer's text does not read again: {e}\n{text}"
        ));
    }
    let Ok(mut program) = aspif::read_program(bytes) else {
        return Ok(());
    };
    program.compact_atoms();
    let statements = program.rules.len()
        + program.minimize.len()
        + program.outputs.len()
        + program.externals.len()
        + program.edges.len()
        + program.heuristics.len();
    if program.num_atoms > MAX_ATOMS || statements > MAX_STATEMENTS {
        return Ok(());
    }
    for opt_mode in [OptMode::Opt, OptMode::OptN] {
        let config = Config {
            models: 64,
            opt_mode,
            check_models: true,
            deadline: Some(Instant::now() + Duration::from_millis(500)),
            ..Config::default()
        };
        let _ = Solver::new(&program, config).solve();
    }
    Ok(())
}
