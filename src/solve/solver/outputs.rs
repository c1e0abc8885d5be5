//! Output statements added to a solver (a later grounding's, the backend's) and the order
//! models list them in.
//!
//! Invariant: `prog.outputs` and `tr.output_lits` stay aligned and ordered by
//! `Output::order` (clingo's order of domains), equal keys in the order added; a model lists
//! its shown symbols in that order.

use super::*;

impl Solver {
    /// Adds output statements (e.g. for atoms introduced by `add_rules`).
    pub fn add_outputs(&mut self, outputs: &[crate::ground::program::Output]) {
        self.add_outputs_one(outputs);
        if let Some(par) = self.par.as_mut() {
            par.each(|h| {
                h.add_outputs_one(outputs);
                Ok(())
            });
        }
    }

    /// [`Solver::add_outputs`] on this solver alone.
    pub(super) fn add_outputs_one(&mut self, outputs: &[crate::ground::program::Output]) {
        self.engine.backtrack(0);
        let before = self.prog.outputs.len();
        for o in outputs {
            let lits: Vec<Lit> = o.condition.iter().map(|&l| self.lit_of(l)).collect();
            let c = self.tr.conjunction(&mut self.engine, &lits);
            self.tr.output_lits.push(c);
            self.prog.outputs.push(o.clone());
        }
        // Models list the outputs in the order of their keys (`Output::order`: clingo's order
        // of domains); a later grounding's outputs may belong before earlier ones.
        let added = &self.prog.outputs[before.saturating_sub(1)..];
        if added.windows(2).any(|w| w[0].order > w[1].order) {
            let mut both: Vec<_> = std::mem::take(&mut self.prog.outputs)
                .into_iter()
                .zip(std::mem::take(&mut self.tr.output_lits))
                .collect();
            both.sort_by_key(|(o, _)| o.order);
            (self.prog.outputs, self.tr.output_lits) = both.into_iter().unzip();
        }
    }
}
