//! `lucent._lucent`, the native module of the `lucent` Python package (issue 33 item 2): the
//! `Symbol` type and constructors (`symbol.rs`), answer sets (`model.rs`), the native Control
//! with its backend calls (`control.rs`), solve handles (`handle.rs`), Python propagators
//! (`propagator.rs`) and their live views of the solver (`live.rs`), a model's solve control
//! (`solve_control.rs`), theory atoms (`theory.rs`)
//! and the command line in memory for the robot verbs (`run_cli`). python/lucent/__init__.py
//! builds clingo's API on top.
//!
//! Invariant: nothing here prints or panics on bad input; errors are Python exceptions.

// pyo3 0.22's #[pymethods] expansion trips clippy's useless_conversion on every PyResult
// (a false positive of pyo3 0.22 under recent clippy); the code written here has no such conversion.
#![allow(clippy::useless_conversion)]

use pyo3::prelude::*;

// The Rust side allocates through mimalloc, as the `lucent` binary does (`src/mi_alloc.rs`).
#[path = "../../src/mi_alloc.rs"]
mod mi_alloc;

#[global_allocator]
static GLOBAL: mi_alloc::Mi = mi_alloc::Mi;

mod control;
mod handle;
mod live;
mod model;
mod propagator;
mod solve_control;
mod symbol;
mod theory;

/// Runs `lucent ARGS...` in memory: `(exit code, standard output, standard error)`. The robot
/// verbs (`plan`, `explain`) are read from its `--outf=2` JSON by the Python layer.
#[pyfunction]
fn run_cli(args: Vec<String>) -> (i32, String, String) {
    let mut stdin: &[u8] = &[];
    let mut out = Vec::new();
    let mut err = Vec::new();
    let code = lucent::cli::run(&args, &mut stdin, &mut out, &mut err);
    (
        code,
        String::from_utf8_lossy(&out).into_owned(),
        String::from_utf8_lossy(&err).into_owned(),
    )
}

#[pymodule]
fn _lucent(m: &Bound<'_, PyModule>) -> PyResult<()> {
    mi_alloc::purge_at_once();
    symbol::register(m)?;
    m.add_class::<model::Model>()?;
    m.add_class::<control::Control>()?;
    m.add_class::<control::Interrupter>()?;
    m.add_class::<handle::SolveHandle>()?;
    m.add_class::<live::Live>()?;
    m.add_class::<solve_control::SolveControl>()?;
    m.add_function(wrap_pyfunction!(run_cli, m)?)?;
    Ok(())
}
