//! Ground programs in aspif given to [`Control::add`], [`Control::add_source`] or
//! [`Control::load`], as clingo 5.8 reads them there (`ctl.load("prog.aspif")`): the
//! statements join the Control's program through its [`Backend`].
//!
//! Invariants:
//! - Every aspif atom becomes one Control atom. An output statement whose condition is one
//!   positive atom gives that atom its symbol (it is then shown and found by
//!   [`Control::lookup`]); an output with another condition makes a fresh atom with the symbol,
//!   defined by the condition, so the same symbols are shown.
//! - Statements the backend cannot express (projection, heuristics, edges, theory, CR rules)
//!   are an error naming them, and then nothing is added.
//! - As for every backend atom, a later grounding does not see these atoms (the backend's
//!   documented limit).

use super::*;
use crate::ground::program::{BodyRef, ExternalValue, HeadKind, Lit};

impl Control {
    /// Adds the aspif program `bytes` (named `name` in diagnostics) through the backend.
    pub(super) fn add_aspif(&mut self, name: &str, bytes: &[u8]) -> Result<(), Error> {
        let program = match ground::aspif::read_program(bytes) {
            Ok(p) => p,
            Err(e) => {
                let text = String::from_utf8_lossy(bytes).into_owned();
                let at = offset_of(&text, e.line, e.column);
                let message = format!("malformed aspif input: {}", e.kind);
                return Err(self.aspif_error(name, &text, at, message));
            }
        };
        let unsupported = [
            (!program.projections.is_empty(), "#project"),
            (!program.heuristics.is_empty(), "#heuristic"),
            (!program.edges.is_empty(), "#edge"),
            (!program.theory.is_empty(), "theory atoms"),
            (!program.cr_rules.is_empty(), "CR rules"),
        ];
        if let Some((_, what)) = unsupported.iter().find(|(found, _)| *found) {
            let message = format!("unsupported: {what} in an aspif program added to a Control");
            return Err(self.aspif_error(name, "", 0, message));
        }
        let mut symbols = Vec::with_capacity(program.outputs.len());
        for out in &program.outputs {
            match Symbol::parse(&out.symbol) {
                Ok(s) => symbols.push(s),
                Err(e) => {
                    let message = format!("malformed aspif input: output `{}`: {e}", out.symbol);
                    return Err(self.aspif_error(name, "", 0, message));
                }
            }
        }
        let mut b = self.backend()?;
        // aspif atom -> Control atom (0: not made yet).
        let mut map: Vec<AtomId> = vec![0; program.num_atoms as usize + 1];
        let mut conditional = Vec::new();
        for (out, symbol) in program.outputs.iter().zip(&symbols) {
            match out.condition[..] {
                [l] if l > 0 && map[l as usize] == 0 && b.lookup(symbol).is_none() => {
                    map[l as usize] = b.add_atom(Some(symbol));
                }
                _ => conditional.push((out, symbol)),
            }
        }
        for a in map.iter_mut().skip(1).filter(|a| **a == 0) {
            *a = b.add_atom(None);
        }
        let lit = |l: Lit| -> Lit {
            let a = map[l.unsigned_abs() as usize] as Lit;
            if l < 0 {
                -a
            } else {
                a
            }
        };
        let result = (|| -> Result<(), String> {
            for rule in program.rules.iter() {
                let head: Vec<AtomId> = rule.head.iter().map(|&h| map[h as usize]).collect();
                let choice = rule.head_kind == HeadKind::Choice;
                match rule.body {
                    BodyRef::Normal(lits) => {
                        let body: Vec<Lit> = lits.iter().map(|&l| lit(l)).collect();
                        b.add_rule(&head, &body, choice)?;
                    }
                    BodyRef::Weight { lower, lits } => {
                        let body: Vec<(Lit, _)> = lits.iter().map(|&(l, w)| (lit(l), w)).collect();
                        b.add_weight_rule(&head, lower, &body, choice)?;
                    }
                }
            }
            for (out, symbol) in conditional {
                let body: Vec<Lit> = out.condition.iter().map(|&l| lit(l)).collect();
                if b.lookup(symbol).is_some() {
                    return Err(format!(
                        "unsupported: the output `{}` names an atom of the program under a \
                         condition",
                        out.symbol
                    ));
                }
                let a = b.add_atom(Some(symbol));
                b.add_rule(&[a], &body, false)?;
            }
            for m in &program.minimize {
                let lits: Vec<(Lit, _)> = m.lits.iter().map(|&(l, w)| (lit(l), w)).collect();
                b.add_minimize(m.priority, &lits)?;
            }
            for &(a, value) in &program.externals {
                let value = match value {
                    ExternalValue::Free => TruthValue::Free,
                    ExternalValue::True => TruthValue::True,
                    ExternalValue::False | ExternalValue::Release => TruthValue::False,
                };
                b.add_external(map[a as usize], value)?;
            }
            if !program.assumptions.is_empty() {
                let lits: Vec<Lit> = program.assumptions.iter().map(|&l| lit(l)).collect();
                b.add_assume(&lits)?;
            }
            Ok(())
        })();
        result.map_err(|message| self.aspif_error(name, "", 0, message))
    }

    /// The error `message` at byte `at` of the aspif input `name` (`text`, as far as the
    /// diagnostic needs it).
    fn aspif_error(&mut self, name: &str, text: &str, at: u32, message: String) -> Error {
        let file = self.sources.add(name, text);
        let mut d = self.new_diags();
        d.push(Diagnostic::error(Span::new(file, at, at), message));
        self.error(d)
    }
}

/// The byte offset of 1-based `line` and `column` in `text` (clamped to the text).
fn offset_of(text: &str, line: u32, column: u32) -> u32 {
    let start: usize = text
        .split_inclusive('\n')
        .take(line.saturating_sub(1) as usize)
        .map(str::len)
        .sum();
    (start + column.saturating_sub(1) as usize).min(text.len()) as u32
}
