//! Host functions for external function calls: a term `@f(args)` in a program calls the
//! function `f` of the grounding context passed to [`Control::ground_with_context`]
//! (clingo's `Control.ground(parts, context)`), once its arguments are ground, in heads and
//! bodies alike.
//!
//! ```
//! use lucent::control::{Context, Control, ControlConfig, Part, Symbol};
//! struct Inc;
//! impl Context for Inc {
//!     fn call(&mut self, name: &str, args: &[Symbol]) -> Result<Vec<Symbol>, String> {
//!         match (name, args) {
//!             ("inc", [x]) => Ok(vec![Symbol::number(x.as_number().ok_or("a number")? + 1)]),
//!             _ => Err(format!("no function {name}/{}", args.len())),
//!         }
//!     }
//! }
//! let mut ctl = Control::new(ControlConfig::default());
//! ctl.add("base", &[], "p(1..2). q(@inc(X)) :- p(X).").unwrap();
//! ctl.ground_with_context(&[Part::base()], &mut Inc).unwrap();
//! let m = ctl.solve_all(&Default::default()).models.remove(0);
//! assert!(m.contains(&Symbol::parse("q(3)").unwrap()));
//! ```
//!
//! Invariants:
//! - A function returns the symbols the call stands for: one for a plain value, several for
//!   several instances (clingo's list return), none for no instance.
//! - Each distinct call is made once per grounding (`ground::instantiate::call` caches).
//! - An error (an unknown function, the host's failure) is a diagnostic at the call with the
//!   host's message, and the grounding fails as a grounding with errors does. Without a
//!   context, [`Control::ground`] reports every call as needing one.

use super::*;
use crate::ground::Calls;

/// The functions a grounding can call (clingo's grounding context).
pub trait Context {
    /// The symbols of `@name(args)`; `Err` with a message for an unknown function or a
    /// failure.
    fn call(&mut self, name: &str, args: &[Symbol]) -> Result<Vec<Symbol>, String>;
}

impl<F: FnMut(&str, &[Symbol]) -> Result<Vec<Symbol>, String>> Context for F {
    fn call(&mut self, name: &str, args: &[Symbol]) -> Result<Vec<Symbol>, String> {
        self(name, args)
    }
}

/// A [`Context`] seen by the grounder: symbols converted between the grounder's table and
/// [`Symbol`] values.
pub(super) struct Adapter<'c, 'd>(pub(super) &'c mut (dyn Context + 'd));

impl Calls for Adapter<'_, '_> {
    fn call(
        &mut self,
        syms: &mut Symbols,
        name: &str,
        args: &[SymId],
    ) -> Result<Vec<SymId>, String> {
        let args: Vec<Symbol> = args.iter().map(|&a| Symbol::from_table(syms, a)).collect();
        let values = self.0.call(name, &args)?;
        Ok(values.iter().map(|s| s.intern_in(syms)).collect())
    }
}
