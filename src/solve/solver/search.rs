//! The solver's search primitives: the next answer set (search, the minimality check of
//! non-head-cycle-free candidates in `minimal`, edge acyclicity), models and their costs, reporting, blocking
//! of found models and cost bounds.
//!
//! Invariants: every reported model passed the stability check (per component, or the
//! whole-program minimality check) when the program is not head-cycle-free; a blocked model (by its decisions, or its projection) is never reported
//! again in the same call; constraints of one call hang on that call's guard.

use super::*;
use crate::solve::stability::Minimality;

impl Solver {
    // ------------------------------------------------------------------ search primitives

    /// Finds the next answer set under `assume`.
    pub(super) fn next(&mut self, assume: &[Lit]) -> Next {
        self.next_from(assume, false)
    }

    /// [`Solver::next`]; with `resume`, the first search goes on from the current assignment
    /// (after `block` added the clause excluding the last model's decisions in search).
    pub(super) fn next_from(&mut self, assume: &[Lit], resume: bool) -> Next {
        let mut resume = resume && !self.take_model_clauses();
        loop {
            match self.engine.search_from(assume, std::mem::take(&mut resume)) {
                SearchResult::Unsat => return Next::Exhausted,
                SearchResult::Unknown => return Next::Stopped,
                SearchResult::Sat => {
                    if let Some(cycle) = self.edge_cycle() {
                        // Acyclicity (edge directives): forbid this cycle's edges together.
                        self.engine.add_clause(&cycle);
                        continue;
                    }
                    // The component checks (`solve::stability`) verified every head cycle
                    // during propagation; the whole-program check is the fallback when one
                    // was cut short (a limit) or a relevant variable stayed unassigned.
                    if !self.tr.non_hcf || self.engine.stability_verified() {
                        return Next::Model;
                    }
                    match self.is_minimal() {
                        Minimality::Minimal => return Next::Model,
                        Minimality::Smaller(smaller) => self.learn_unfounded(&smaller),
                        Minimality::Stopped => {
                            self.engine.limits.interrupted =
                                self.engine.limits.interrupted
                                    || self.config.interrupt.as_ref().is_some_and(|f| {
                                        f.load(std::sync::atomic::Ordering::Relaxed)
                                    });
                            return Next::Stopped;
                        }
                    }
                }
            }
        }
    }

    /// Sets (or removes) where the model callback puts clauses for the rest of its call.
    pub fn set_model_clauses(&mut self, clauses: Option<ModelClauses>) {
        self.model_clauses = clauses;
    }

    /// Adds the clauses the model callback left, under the call's guard (so they end with
    /// the call); true when there were any (the engine is back at level 0). Literals that name
    /// no atom of the program were refused by the caller; any left are dropped with their
    /// clause.
    fn take_model_clauses(&mut self) -> bool {
        let (Some(queue), Some(guard)) = (&self.model_clauses, self.call_guard) else {
            return false;
        };
        let clauses = std::mem::take(&mut *queue.lock().unwrap_or_else(|p| p.into_inner()));
        let n = self.prog.num_atoms;
        let mut added = false;
        for c in clauses {
            if c.iter().any(|&l| l == 0 || l.unsigned_abs() > n) {
                continue;
            }
            let mut lits: Vec<Lit> = c.iter().map(|&l| self.lit_of(l)).collect();
            lits.push(!guard);
            self.engine.add_clause(&lits);
            added = true;
        }
        added
    }

    /// When the edges (aspif edge directives) whose conditions hold contain a cycle, the
    /// clause excluding that cycle: the negations of the cycle's edge conditions.
    pub(super) fn edge_cycle(&mut self) -> Option<Vec<Lit>> {
        if self.prog.edges.is_empty() {
            return None;
        }
        let holds = |e: &Engine, l: Lit| e.value(l) == Some(true);
        let mut active: Vec<(i32, i32, Vec<Lit>)> = Vec::new();
        for ed in &self.prog.edges {
            let lits: Vec<Lit> = ed.condition.iter().map(|&l| self.tr.lit(l)).collect();
            if lits.iter().all(|&l| holds(&self.engine, l)) {
                active.push((ed.from, ed.to, lits));
            }
        }
        // Depth-first search for a back edge, remembering the edge used to reach each node.
        let mut nodes: Vec<i32> = active.iter().flat_map(|e| [e.0, e.1]).collect();
        nodes.sort_unstable();
        nodes.dedup();
        let idx = |n: i32| nodes.binary_search(&n).expect("node of an active edge");
        let mut out: Vec<Vec<usize>> = vec![Vec::new(); nodes.len()];
        for (k, e) in active.iter().enumerate() {
            out[idx(e.0)].push(k);
        }
        let mut state = vec![0u8; nodes.len()];
        let mut via: Vec<Option<usize>> = vec![None; nodes.len()];
        for root in 0..nodes.len() {
            if state[root] != 0 {
                continue;
            }
            let mut stack: Vec<(usize, usize)> = vec![(root, 0)];
            state[root] = 1;
            while let Some(&mut (v, ref mut k)) = stack.last_mut() {
                if *k < out[v].len() {
                    let ek = out[v][*k];
                    *k += 1;
                    let w = idx(active[ek].1);
                    if state[w] == 1 {
                        // Cycle: w -> ... -> v -> w.
                        let mut edges = vec![ek];
                        let mut x = v;
                        while x != w {
                            let e = via[x].expect("nodes on the stack were reached by an edge");
                            edges.push(e);
                            x = idx(active[e].0);
                        }
                        let mut clause: Vec<Lit> = edges
                            .iter()
                            .flat_map(|&e| active[e].2.iter().map(|&l| !l))
                            .collect();
                        clause.sort();
                        clause.dedup();
                        return Some(clause);
                    }
                    if state[w] == 0 {
                        state[w] = 1;
                        via[w] = Some(ek);
                        stack.push((w, 0));
                    }
                } else {
                    state[v] = 2;
                    stack.pop();
                }
            }
        }
        None
    }

    pub(super) fn true_atoms(&self) -> Vec<u32> {
        (1..=self.prog.num_atoms)
            .filter(|&a| self.engine.value(self.tr.atom_lit[a as usize]) == Some(true))
            .collect()
    }

    pub(super) fn costs(&self) -> Vec<i64> {
        self.tr
            .minimize
            .iter()
            .map(|(_, lits)| {
                lits.iter()
                    .filter(|&&(l, _)| self.engine.value(l) == Some(true))
                    .map(|&(_, w)| w)
                    .sum()
            })
            .collect()
    }

    /// Builds the model on the trail; its supports only `with_support`.
    pub(super) fn model(&self, number: usize, optimal: bool, with_support: bool) -> Model {
        let atoms = self.true_atoms();
        let mut symbols = Vec::new();
        let mut shown: HashSet<&str> = HashSet::new();
        for (o, &l) in self.prog.outputs.iter().zip(&self.tr.output_lits) {
            if self.engine.value(l) == Some(true) && shown.insert(o.symbol.as_str()) {
                symbols.push(o.symbol.clone());
            }
        }
        let mut cr_applied: Vec<String> = self
            .prog
            .cr_rules
            .iter()
            .zip(&self.cr_lits)
            .filter(|(_, &l)| self.engine.value(l) == Some(true))
            .map(|(c, _)| c.label.clone())
            .collect();
        cr_applied.sort();
        let support = if with_support {
            supports(&self.prog, &atoms)
        } else {
            Vec::new()
        };
        Model {
            number,
            symbols,
            atoms,
            costs: self.costs(),
            cr_applied,
            support,
            optimal,
            thread_id: 0,
        }
    }

    /// Reports the model on the trail unless its projection was seen; returns false when the
    /// call must stop.
    pub(super) fn report(&mut self, call: &mut Call<'_>, optimal: bool, dedup: bool) -> bool {
        let mut m = self.model(call.phase_count + 1, optimal, call.with_support);
        if self.config.check_models {
            if let Err(v) = crate::solve::check::check(&self.prog, &m.atoms) {
                panic!("internal error: the solver found a model that is not stable: {v:?}");
            }
        }
        if dedup {
            let key: Vec<u32> = m
                .atoms
                .iter()
                .copied()
                .filter(|&a| !self.is_cr[a as usize])
                .collect();
            if !call.seen.insert(key) {
                return true;
            }
        }
        call.note_model();
        call.phase_count += 1;
        m.number = call.phase_count;
        if !m.costs.is_empty() {
            call.has_costs = true;
        }
        if !(call.sink)(&m, &self.prog) {
            call.done = true;
            return false;
        }
        if !call.unlimited && self.config.models > 0 && call.phase_count >= self.config.models {
            call.done = true;
            return false;
        }
        true
    }

    /// The literals to block on for projected enumeration, if any.
    pub(super) fn projection(&self) -> Option<Vec<Lit>> {
        let project = self.config.project;
        if project.is_on() {
            let onto_projections = match project {
                Project::Project => true,
                Project::Auto => !self.prog.projections.is_empty(),
                _ => false,
            };
            if onto_projections {
                return Some(
                    self.prog
                        .projections
                        .iter()
                        .map(|&a| self.tr.atom_lit[a as usize])
                        .collect(),
                );
            }
            return Some(self.tr.output_lits.clone());
        }
        if !self.cr_lits.is_empty() {
            return Some(
                (1..=self.prog.num_atoms as usize)
                    .filter(|&a| !self.is_cr[a])
                    .map(|a| self.tr.atom_lit[a])
                    .collect(),
            );
        }
        None
    }

    /// Adds the clause excluding the current model (under `guard`). Returns true when the
    /// search may resume from the assignment this leaves (decision-based blocking, added by
    /// backtracking only to the clause's second-highest level), false when it restarted.
    pub(super) fn block(&mut self, guard: Lit, projection: &Option<Vec<Lit>>) -> bool {
        let mut c = vec![!guard];
        match projection {
            Some(lits) => {
                for &l in lits {
                    match self.engine.value(l) {
                        Some(true) => c.push(!l),
                        Some(false) => c.push(l),
                        None => {}
                    }
                }
            }
            None => {
                for d in self.engine.decisions_on_trail() {
                    if d != guard {
                        c.push(!d);
                    }
                }
                return self.engine.add_clause_resuming(&c);
            }
        }
        self.engine.add_clause(&c);
        false
    }

    /// Adds `guard -> costs <lex bound` (or `<=lex` when `inclusive`), comparing the first
    /// `bound.len()` levels.
    pub(super) fn add_cost_bound(&mut self, guard: Lit, bound: &[i64], inclusive: bool) {
        let k = bound.len().min(self.tr.minimize.len());
        if k == 0 {
            return;
        }
        self.engine.backtrack(0);
        // Bounds from the command line may be anything; the sums they bound stay within
        // +-2^62 (see `aspif::WEIGHT_SUM_MAX`), so saturating at the ends of i64 keeps the
        // meaning.
        let mut bound = bound[..k].to_vec();
        if inclusive {
            bound[k - 1] = bound[k - 1].saturating_add(1);
        }
        let levels: Vec<Vec<(Lit, i64)>> = self.tr.minimize[..k]
            .iter()
            .map(|(_, l)| l.clone())
            .collect();
        let mut at_most = Vec::new();
        let mut below = Vec::new();
        for (i, lits) in levels.iter().enumerate() {
            let neg: Vec<(Lit, i64)> = lits.iter().map(|&(l, w)| (l, -w)).collect();
            // sum <= c  <=>  -sum >= -c. The last level is only ever bounded strictly, so it
            // gets no `at_most` literal (one weight constraint less to propagate: half of
            // them for a single level).
            if i + 1 < k {
                let a = self.aux_weight(guard, &neg, bound[i].saturating_neg());
                at_most.push(a);
            }
            let b = self.aux_weight(guard, &neg, bound[i].saturating_sub(1).saturating_neg());
            below.push(b);
        }
        let mut big = vec![!guard];
        for i in 0..k {
            // g_i <-> a_0 and ... and a_{i-1} and b_i; a full equivalence keeps every auxiliary
            // variable a function of the atoms, which decision-based blocking relies on.
            let mut conj = at_most[..i].to_vec();
            conj.push(below[i]);
            let g = self.aux_conjunction(guard, &conj);
            big.push(g);
        }
        self.engine.add_clause(&big);
    }
}
