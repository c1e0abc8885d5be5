//! External function calls during instantiation: the literal `V = @f(args)` the rewriting
//! makes of each `@f(args)` (gringo's script literal) asks the grounding context, through the
//! [`Calls`] trait, for the symbols of `f` at the ground arguments, and binds `V` to each in
//! turn (a function returning several symbols gives several instances, as clingo's list
//! return does; none gives no instance).
//!
//! Invariants:
//! - A function is called once per grounding for each distinct name and arguments: results
//!   are cached for the grounding (the semi-naive and naive rounds evaluate a body many
//!   times), so a host function is asked no more often than the program has distinct calls.
//! - A call whose arguments are undefined (`@f(1/0)`) is not made; the operation is reported
//!   as undefined, as for any term.
//! - A failing call (the host's error, an unknown function) is an error at the call's span,
//!   and grounding stops ([`StopReason::Error`]): nothing is derived from a call that has no
//!   value.

use hashbrown::Equivalent;

use super::*;

/// The host side of external function calls: clingo's grounding context, over the grounder's
/// symbol table (`control::Context` is the public face, over `control::Symbol`).
pub trait Calls {
    /// The symbols of `@name(args)`: interned into `syms`, in the order they are to be used;
    /// `Err` with the host's message when the function is unknown or fails.
    fn call(
        &mut self,
        syms: &mut Symbols,
        name: &str,
        args: &[SymId],
    ) -> Result<Vec<SymId>, String>;
}

/// The cache of one grounding's calls: (name, arguments) to the symbols returned.
pub(super) type CallCache = HashMap<(Sym, Vec<SymId>), Vec<SymId>>;

/// A borrowed cache key (hashes as the owned `(Sym, Vec<SymId>)`).
#[derive(Hash)]
struct Key<'k>(Sym, &'k [SymId]);

impl Equivalent<(Sym, Vec<SymId>)> for Key<'_> {
    fn equivalent(&self, key: &(Sym, Vec<SymId>)) -> bool {
        self.0 == key.0 && self.1 == key.1.as_slice()
    }
}

impl<'a> Grounder<'a> {
    /// Lets `@f(...)` call `calls` during this grounding.
    pub fn set_calls(&mut self, calls: &'a mut (dyn Calls + 'a)) {
        self.calls = Some(calls);
    }

    /// The symbols of `@name(args)` under `b`; `None` when an argument is undefined or the
    /// call failed (reported, grounding stopped).
    pub(super) fn call(
        &mut self,
        name: Sym,
        args: &[NTerm],
        span: Span,
        b: &Binding,
    ) -> Option<SmallVec<[SymId; 2]>> {
        let mut vals: SmallVec<[SymId; 4]> = SmallVec::new();
        for t in args {
            vals.push(self.eval(t, b)?);
        }
        if let Some(r) = self.call_cache.get(&Key(name, &vals)) {
            return Some(r.iter().copied().collect());
        }
        let text = self.syms.names.resolve(name).to_string();
        let result = match self.calls.as_deref_mut() {
            Some(calls) => calls.call(&mut self.syms, &text, &vals),
            None => Err("no grounding context supplies functions".to_string()),
        };
        match result {
            Ok(values) => {
                let out = values.iter().copied().collect();
                self.call_cache.insert((name, vals.to_vec()), values);
                Some(out)
            }
            Err(message) => {
                let shown: Vec<String> = vals.iter().map(|&v| self.syms.show(v)).collect();
                let d = Diagnostic::error(
                    span,
                    format!(
                        "error in external function @{text}({}): {message}",
                        shown.join(",")
                    ),
                );
                let s = self.snippet(span);
                self.diags
                    .push(if s.is_empty() { d } else { d.with_snippet(s) });
                self.stopped = Some(StopReason::Error);
                None
            }
        }
    }
}
