//! The solver's public face: enumeration, projection, brave and cautious consequences,
//! lexicographic branch-and-bound optimization, CR-Prolog semantics, assumptions, limits and
//! multi-shot solving (`add_program`, external atoms), all driving one `Engine` so learnt
//! clauses survive between calls.
//!
//! This file holds the solver's state, construction, multi-shot steps, externals and the solve
//! calls; `portfolio` runs them on several threads; `search` has the primitives (next answer set, models,
//! blocking, cost bounds), `minimal` the whole-program minimality check (fallback of `solve::stability`), `strategies` enumeration, optimization and consequences, `cr` the
//! CR-Prolog semantics.
//!
//! Invariants:
//! - Multi-shot model (clingo's): an atom is complete once a step gave it rules, or mentioned it
//!   without declaring it external, or released it; only external atoms (declared, not
//!   released, without rules) may get rules in a later step, all in that one step. Completion
//!   clauses and loop nogoods therefore hold in every later step and carry no step guard. The
//!   values of externals (true, false) are assumptions of each call; free ones are unconstrained.
//! - A step's work is proportional to the step, plus the unfounded-set structures when it
//!   closes positive cycles (`Translation::update_cycles`): a new cycle goes through an atom
//!   the step defines.
//! - Constraints that hold for one call only (blocking clauses, cost bounds, CR bounds) carry a
//!   guard literal that is assumed during the call and fixed false afterwards, so later calls
//!   are unaffected while learnt clauses stay valid (they mention the guard when they used it).
//!   A guard owns the auxiliary variables and weight constraints made for its constraints
//!   (`Scope`); retiring it removes the weight constraints and retires the variables, which the
//!   engine then deletes every clause of and reuses (`Engine::retire_vars`). Nothing of a call
//!   outlives it but learnt clauses that mention none of its variables, so the engine's size
//!   and the cost per call stay flat over any number of calls (tests/solve/multishot.rs,
//!   benches/multishot.rs). Between calls the learnt clauses are reduced to a limit set by the
//!   problem size, as clasp does at the start of each solve call.
//! - Enumeration blocks each model by the negation of its decisions (sound because every
//!   propagation is a consequence of the program), or by its projection with `--project` and
//!   for CR programs (where answer sets are compared on their non-CR atoms).
//! - For non-head-cycle-free programs every candidate is checked to be a minimal model of its
//!   reduct (Gelfond-Lifschitz) with a fresh engine before it is reported; a failed candidate
//!   adds the loop nogoods of the unfounded set the check found, which hold in later steps too
//!   (`minimal`).
//! - Every auxiliary variable (bodies, shifted supports, cost-bound literals) is a function of
//!   the atoms, so decision-based blocking never reports one answer set twice.
//! - Edge directives are acyclicity constraints, checked on each total assignment: a cycle of
//!   true edges adds the clause forbidding its edge conditions together.
//! - Optimization is branch and bound (`strategies`) or core-guided (`core_guided`, clasp's
//!   `usc`), as `Config::opt_strategy` says; both leave the optimum's costs in `best`.
//! - Branch and bound follows clasp's "opt" strategy: after a model with costs `c`, require
//!   `costs <lex c` (as `exists i: sum_j <= c_j for j < i and sum_i <= c_i - 1`); the last model
//!   is optimal when the bound becomes unsatisfiable.

mod core_guided;
mod cr;
pub(crate) use cr::transitive_closure;
mod minimal;
mod outputs;
mod portfolio;
mod propagators;
mod search;
mod settings;
mod strategies;

use super::config::{
    Config, CrMode, EnumMode, Heuristic, OptMode, OptStrategy, Project, RestartPolicy,
    SearchProfile,
};
use super::engine::{Engine, Restarts, SearchResult, Settings};
use super::lit::{Lit, Var};
use super::result::{Model, Outcome, SolveResult, Stats, StopReason};
use super::translate::{max_atom, Translation};
use crate::ground::program::{BodyRef, ExternalValue, GroundProgram, HeadKind, Rule};
use hashbrown::HashSet;
use std::time::Instant;

/// Errors of the multi-shot interface (`Solver::add_program` and the external atoms).
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum SolveError {
    /// A rule for an atom that an earlier step completed: it had rules, or it was mentioned
    /// without being external (so it is false for good), or it was released. As in clingo, only
    /// external atoms may get rules in a later step.
    #[error(
        "atom {0} was completed in an earlier step; only an external atom can get rules later"
    )]
    AtomAlreadyDefined(u32),
    /// `assign_external` or `release_external` on an atom that is not external (unknown,
    /// defined by rules, or released).
    #[error("atom {0} is not an external atom")]
    NotExternal(u32),
}

/// Result of looking for the next answer set.
enum Next {
    /// A total assignment that is an answer set is on the engine's trail.
    Model,
    /// No (further) answer set under the assumptions.
    Exhausted,
    /// A limit was hit.
    Stopped,
}

/// A stable-model solver for one ground program.
pub struct Solver {
    /// The program, including rules added since construction.
    prog: GroundProgram,
    /// Configuration.
    config: Config,
    /// The CDCL engine.
    engine: Engine,
    /// Program-to-engine mapping.
    tr: Translation,
    /// Literals of the CR application atoms, parallel to `prog.cr_rules`.
    cr_lits: Vec<Lit>,
    /// Per atom: whether it is a CR application atom.
    is_cr: Vec<bool>,
    /// Minimality checks done for non-HCF programs.
    minimality_checks: u64,
    /// Costs of the best model of the last branch-and-bound run.
    best: Option<Vec<i64>>,
    /// The guards in use, each with the auxiliary variables and weight constraints made for
    /// it; all of them are retired with the guard (`retire`).
    scopes: Vec<Scope>,
    /// Problem constraints (clauses and weight constraints) after the last step, for the
    /// learnt clause limit of each call.
    problem_size: usize,
    /// Solve calls so far.
    calls: u64,
    /// The caller's assumptions that refuted the last call, when it found no model.
    core: Option<Vec<i32>>,
    /// The helper solvers with `Config::threads >= 2` (`portfolio`).
    par: Option<Box<portfolio::Portfolio>>,
    /// In a portfolio: the best bound any thread found in the current optimization.
    shared_bound: Option<std::sync::Arc<portfolio::SharedBound>>,
    /// Extra assumptions of the next call: a portfolio cube.
    cube: Vec<Lit>,
    /// Skip the learnt-clause limit at the start of the next call (a portfolio's later cubes).
    keep_learnts: bool,
    /// The configuration the engine's settings were last made from (`settings::apply`).
    applied: Config,
    /// The statistics of every call so far, added up.
    total: Stats,
    /// Told each lower bound core-guided optimization proves (`core_guided`).
    lower_observer: Option<LowerBoundObserver>,
    /// Clauses the model callback adds (`set_model_clauses`), and the running call's guard.
    model_clauses: Option<ModelClauses>,
    call_guard: Option<Lit>,
}

/// Clauses (aspif literals) a model callback adds for the rest of its solve call (clingo's
/// `SolveControl.add_clause`): the solver takes them before its next search.
pub type ModelClauses = std::sync::Arc<std::sync::Mutex<Vec<Vec<i32>>>>;

pub use core_guided::LowerBoundObserver;

/// What one guard owns: variables defined for the constraints it guards (cost and CR bounds,
/// their conjunctions), and which of them head a weight constraint.
struct Scope {
    /// The guard.
    guard: Lit,
    /// Auxiliary variables.
    aux: Vec<Var>,
    /// Heads of the weight constraints defining some of `aux`.
    weights: Vec<Lit>,
}

/// Mutable state of one call.
struct Call<'a> {
    /// Models reported so far.
    count: usize,
    /// Models reported in the current phase (optN restarts numbering for the optimal models,
    /// as clasp does); numbers models and is compared against `Config::models`.
    phase_count: usize,
    /// The caller's callback, given each model and the program it is a model of; returns
    /// false to stop.
    sink: &'a mut dyn FnMut(&Model, &GroundProgram) -> bool,
    /// Whether the models reported carry their supports: `Config::supports`, unless the
    /// caller computes them itself on demand (`for_each_model_lazy`).
    with_support: bool,
    /// Set while the model limit does not apply (optN's branch-and-bound phase).
    unlimited: bool,
    /// Set when the callback asked to stop or the model limit was reached.
    done: bool,
    /// Set when a limit stopped the engine.
    stopped: bool,
    /// Projections already reported (CR programs and `--project`), as sorted true atoms.
    seen: HashSet<Vec<u32>>,
    /// Set when the last model's costs were proven optimal.
    optimum: bool,
    /// Whether some model had costs.
    has_costs: bool,
    /// Set when everything was explored.
    exhausted: bool,
    /// When the call started.
    start: Instant,
    /// Time from `start` to the first reported model.
    first_model: Option<std::time::Duration>,
    /// When the last model was reported.
    last_model: Option<Instant>,
}

impl Call<'_> {
    /// Counts a reported model and notes its time.
    fn note_model(&mut self) {
        self.count += 1;
        let now = Instant::now();
        self.first_model.get_or_insert(now - self.start);
        self.last_model = Some(now);
    }
}

impl Solver {
    /// Translates `prog` and prepares a solver (on a copy of `prog`; `from_program` takes the
    /// program instead, which saves the copy when the caller no longer needs it).
    pub fn new(prog: &GroundProgram, config: Config) -> Solver {
        Solver::from_program(prog.clone(), config)
    }

    /// Translates `prog`, which the solver keeps, and prepares a solver.
    pub fn from_program(mut prog: GroundProgram, config: Config) -> Solver {
        if config.threads >= 2 {
            return Solver::new_portfolio(prog, config);
        }
        let mut engine = Engine::new();
        engine.configure(config.var_decay, config.seed);
        engine.settings = Settings::from_config(&config);
        engine.sched.restarts = restart_state(config.restarts);
        prog.num_atoms = max_atom(&prog);
        // As clasp (and `check::external_values`): an external statement on an atom that has
        // a rule in the same program is ignored; the rules define the atom.
        if !prog.externals.is_empty() {
            let mut defined = vec![false; prog.num_atoms as usize + 1];
            for r in &prog.rules {
                for &h in r.head {
                    defined[h as usize] = true;
                }
            }
            prog.externals.retain(|&(a, _)| !defined[a as usize]);
        }
        let tr = Translation::build_with(&prog, &mut engine, config.eq);
        // One entry per external atom, with its value (the last statement decided it).
        prog.externals = tr
            .ext_atoms
            .iter()
            .map(|&a| (a, tr.ext_value[a as usize]))
            .collect();
        let optimizing = !prog.minimize.is_empty() && config.opt_mode != OptMode::Ignore;
        let tweety = match config.profile {
            SearchProfile::Auto => engine.has_unfounded() && !optimizing,
            SearchProfile::Decision => !optimizing,
            SearchProfile::Fixed | SearchProfile::Complement => false,
        };
        let auto_like = matches!(
            config.profile,
            SearchProfile::Auto | SearchProfile::Complement
        );
        if auto_like && !tweety && !optimizing {
            // Decision problems without the tweety values: clasp's phase handling after a
            // long run without a model (`Config::phase_switch`).
            engine.settings.phase_switch = config.phase_switch;
        }
        if tweety {
            // clasp's `tweety` search settings (`SearchProfile`): decision problems under
            // `Decision`, non-tight ones under `Auto`.
            engine.configure(0.92, config.seed);
            engine.sched.restarts = restart_state(RestartPolicy::Luby(60));
            engine.settings.save_progress = 160;
            engine.settings.sign_from_learnts = true;
        }
        if config.heuristic == Heuristic::Domain {
            apply_domain_heuristics(&prog, &tr, &mut engine);
        }
        let cr_lits = prog
            .cr_rules
            .iter()
            .map(|c| tr.atom_lit[c.appl as usize])
            .collect();
        let mut is_cr = vec![false; prog.num_atoms as usize + 1];
        for c in &prog.cr_rules {
            is_cr[c.appl as usize] = true;
        }
        let size = engine.size();
        let problem_size = size.clauses + size.weights;
        Solver {
            prog,
            applied: config.clone(),
            total: Stats::default(),
            config,
            engine,
            tr,
            cr_lits,
            is_cr,
            minimality_checks: 0,
            best: None,
            scopes: Vec::new(),
            problem_size,
            calls: 0,
            core: None,
            par: None,
            shared_bound: None,
            cube: Vec::new(),
            keep_learnts: false,
            lower_observer: None,
            model_clauses: None,
            call_guard: None,
        }
    }

    /// True once a search found the program without answer sets whatever the assumptions and
    /// externals (a conflict at decision level 0; clingo's `is_conflicting`).
    pub fn is_conflicting(&self) -> bool {
        self.engine.is_inconsistent()
    }

    /// The ground program as extended so far.
    pub fn program(&self) -> &GroundProgram {
        &self.prog
    }

    /// The solver's configuration, as the next call reads it.
    pub fn config(&self) -> &Config {
        &self.config
    }

    /// The solver's configuration (mutable between calls, e.g. to change the model count).
    pub fn config_mut(&mut self) -> &mut Config {
        &mut self.config
    }

    /// Adds rules between calls, keeping learnt clauses: `add_program` with a delta made of
    /// `rules` alone.
    pub fn add_rules(&mut self, rules: &[Rule]) -> Result<(), SolveError> {
        let mut delta = GroundProgram::new();
        for r in rules {
            delta.rules.push_ref(r.as_ref());
        }
        self.add_program(&delta)
    }

    /// Adds one step of a multi-shot program (clingo's model), keeping learnt clauses.
    ///
    /// Atoms are numbered as in the programs given before (new atoms above the current
    /// `num_atoms`). Rules may define new atoms and external atoms; an atom that already had
    /// rules, or was mentioned without being external, or was released, is complete and a rule
    /// for it is an error (`SolveError::AtomAlreadyDefined`; nothing is added then). New atoms
    /// without rules and not external are false. External statements declare new externals or
    /// change the value of existing ones (`Release`: false for good); on an atom that gets rules
    /// in the same delta, or that is complete, they are ignored, as clasp does. Minimize
    /// statements (new priority levels or more literals for a level), CR rules (their
    /// application atoms count in the cardinality-minimal semantics with those of earlier
    /// steps), preferences, output statements, projections, edges, assumptions and origins are
    /// added to those of the earlier steps. The work is proportional to the delta, plus the
    /// unfounded-set structures when the delta closes positive cycles (see
    /// `Translation::update_cycles`).
    pub fn add_program(&mut self, delta: &GroundProgram) -> Result<(), SolveError> {
        self.add_program_one(delta)?;
        // The helpers accept what this solver accepted: they hold the same program.
        self.on_helpers(&|h| {
            let _ = h.add_program_one(delta);
        });
        Ok(())
    }

    /// [`Solver::add_program`] on this solver alone.
    fn add_program_one(&mut self, delta: &GroundProgram) -> Result<(), SolveError> {
        let old_n = self.prog.num_atoms;
        for r in delta.rules.iter() {
            if let Some(&h) = r
                .head
                .iter()
                .find(|&&h| h <= old_n && !self.tr.free[h as usize])
            {
                return Err(SolveError::AtomAlreadyDefined(h));
            }
        }
        let new_n = max_atom(delta).max(old_n);
        self.engine.backtrack(0);
        self.tr.grow_atoms(&mut self.engine, new_n as usize);
        self.is_cr.resize(new_n as usize + 1, false);
        self.prog.num_atoms = new_n;
        // The atoms this delta defines: heads of its rules.
        let mut defined: Vec<u32> = delta
            .rules
            .iter()
            .flat_map(|r| r.head.iter().copied())
            .collect();
        defined.sort_unstable();
        defined.dedup();
        let pos_occ_before = defined
            .iter()
            .any(|&a| a <= old_n && self.tr.pos_occ[a as usize]);
        // External statements, in order; the last one on an atom decides.
        let mut completed: Vec<u32> = Vec::new();
        for &(a, v) in &delta.externals {
            let open = a > old_n || self.tr.free[a as usize];
            if !open || defined.binary_search(&a).is_ok() {
                continue;
            }
            if v == ExternalValue::Release {
                if self.tr.free[a as usize] {
                    completed.push(a);
                }
                self.tr.set_external(a, v);
            } else {
                self.tr.set_external(a, v);
            }
        }
        // Defined atoms stop being external.
        for &a in &defined {
            self.tr.set_external(a, ExternalValue::Release);
        }
        let first = self.prog.rules.len();
        for (k, r) in delta.rules.iter().enumerate() {
            self.prog.rules.push_ref(r);
            self.tr.add_rule(&mut self.engine, first + k, r);
        }
        if !delta.provenance.is_empty() || !self.prog.provenance.is_empty() {
            self.prog.provenance.resize_rules(first);
            self.prog.provenance.append(delta.provenance.clone());
            self.prog.provenance.resize_rules(self.prog.rules.len());
        }
        // Completion: the atoms defined now, the released externals, and the new atoms that
        // are not external (false when they have no rule).
        completed.extend_from_slice(&defined);
        completed.extend((old_n + 1..=new_n).filter(|&a| !self.tr.free[a as usize]));
        completed.sort_unstable();
        completed.dedup();
        for &a in &completed {
            if !self.tr.free[a as usize] {
                self.tr.complete(&mut self.engine, a as usize);
            }
        }
        // The program's record of its externals: one entry per atom still external.
        let free = &self.tr.free;
        self.prog.externals.retain(|&(a, _)| free[a as usize]);
        for &(a, _) in &delta.externals {
            if self.tr.free[a as usize] && !self.prog.externals.iter().any(|&(b, _)| b == a) {
                self.prog.externals.push((a, self.tr.ext_value[a as usize]));
            }
        }
        self.sync_external_records();
        for &l in &delta.assumptions {
            let x = self.tr.lit(l);
            self.tr.prog_assumptions.push(x);
            self.prog.assumptions.push(l);
        }
        self.tr.refresh_assumptions();
        // Outputs, minimize, CR rules and the rest.
        self.add_outputs_one(&delta.outputs);
        for m in &delta.minimize {
            let lits: Vec<(Lit, i64)> = m.lits.iter().map(|&(l, w)| (self.tr.lit(l), w)).collect();
            match self
                .tr
                .minimize
                .iter()
                .position(|(pr, _)| *pr <= m.priority)
            {
                Some(k) if self.tr.minimize[k].0 == m.priority => {
                    self.tr.minimize[k].1.extend(lits)
                }
                Some(k) => self.tr.minimize.insert(k, (m.priority, lits)),
                None => self.tr.minimize.push((m.priority, lits)),
            }
            self.prog.minimize.push(m.clone());
        }
        for c in &delta.cr_rules {
            self.cr_lits.push(self.tr.atom_lit[c.appl as usize]);
            self.is_cr[c.appl as usize] = true;
            self.prog.cr_rules.push(c.clone());
        }
        self.prog.prefers.extend(delta.prefers.iter().cloned());
        self.prog
            .projections
            .extend(delta.projections.iter().copied());
        self.prog.edges.extend(delta.edges.iter().cloned());
        self.prog
            .heuristics
            .extend(delta.heuristics.iter().cloned());
        self.prog.theory.extend(delta.theory.iter().cloned());
        self.prog
            .theory_atoms
            .extend(delta.theory_atoms.iter().cloned());
        self.tr.update_cycles(
            &self.prog,
            &mut self.engine,
            &defined,
            first,
            pos_occ_before,
        );
        // The step's rules and minimize statements stand for its constraints (counting its
        // clauses would cost a pass over the engine).
        self.problem_size += delta.rules.len() + delta.minimize.len();
        Ok(())
    }

    /// Keeps the values in `prog.externals` equal to the solver's.
    fn sync_external_records(&mut self) {
        for e in self.prog.externals.iter_mut() {
            e.1 = self.tr.ext_value[e.0 as usize];
        }
    }

    /// Sets the value of an external atom for the following calls (`Free`, `True`, `False`;
    /// `Release` is `release_external`).
    pub fn assign_external(&mut self, atom: u32, value: ExternalValue) -> Result<(), SolveError> {
        self.assign_external_one(atom, value)?;
        if let Some(par) = self.par.as_mut() {
            par.each(|h| h.assign_external_one(atom, value));
        }
        Ok(())
    }

    /// [`Solver::assign_external`] on this solver alone.
    fn assign_external_one(&mut self, atom: u32, value: ExternalValue) -> Result<(), SolveError> {
        if value == ExternalValue::Release {
            return self.release_external_one(atom);
        }
        if atom > self.prog.num_atoms || !self.tr.free[atom as usize] {
            return Err(SolveError::NotExternal(atom));
        }
        self.tr.set_external(atom, value);
        if let Some(e) = self.prog.externals.iter_mut().find(|e| e.0 == atom) {
            e.1 = value;
        }
        self.tr.refresh_assumptions();
        Ok(())
    }

    /// Releases an external atom: it is false from now on and can get no rules.
    pub fn release_external(&mut self, atom: u32) -> Result<(), SolveError> {
        self.release_external_one(atom)?;
        if let Some(par) = self.par.as_mut() {
            par.each(|h| h.release_external_one(atom));
        }
        Ok(())
    }

    /// [`Solver::release_external`] on this solver alone.
    fn release_external_one(&mut self, atom: u32) -> Result<(), SolveError> {
        if atom > self.prog.num_atoms || !self.tr.free[atom as usize] {
            return Err(SolveError::NotExternal(atom));
        }
        self.engine.backtrack(0);
        self.tr.set_external(atom, ExternalValue::Release);
        self.tr.complete(&mut self.engine, atom as usize);
        self.prog.externals.retain(|e| e.0 != atom);
        self.tr.refresh_assumptions();
        Ok(())
    }

    /// Whether `atom` is currently an external atom (declared, not released, without rules).
    pub fn is_external(&self, atom: u32) -> bool {
        atom <= self.prog.num_atoms && self.tr.free[atom as usize]
    }

    fn lit_of(&self, l: i32) -> Lit {
        assert!(
            l != 0 && l.unsigned_abs() <= self.prog.num_atoms,
            "literal {l} does not name an atom of the program"
        );
        self.tr.lit(l)
    }

    /// Solves with the configured options and collects the models.
    ///
    /// With `Config::threads >= 2`, this and every other call runs on a portfolio of that
    /// many solvers that share learnt clauses (`portfolio`).
    ///
    /// ```
    /// use lucent::ground::aspif;
    /// use lucent::solve::{Config, Outcome, Solver};
    /// // A ground program in aspif (gringo's output format): {a; b}. :- a, b.  #minimize{1: not a}.
    /// let text = "asp 1 0 0\n1 1 2 1 2 0 0\n1 0 0 0 2 1 2\n2 0 1 -1 1\n4 1 a 1 1\n4 1 b 1 2\n0\n";
    /// let prog = aspif::read_program(text.as_bytes()).unwrap();
    /// // clasp's default model count: the optimum here, as the program minimizes.
    /// let config = Config { models: Config::AUTO_MODELS, ..Config::default() };
    /// let mut solver = Solver::new(&prog, config);
    /// let result = solver.solve();
    /// assert_eq!(result.outcome, Outcome::Optimum);
    /// assert_eq!(result.models.last().unwrap().symbols, ["a"]);
    /// ```
    pub fn solve(&mut self) -> SolveResult {
        self.solve_with(&[])
    }

    /// Solves under extra assumptions (aspif literals: `a` true or `-a` false).
    pub fn solve_with(&mut self, assumptions: &[i32]) -> SolveResult {
        let mut models = Vec::new();
        let mut r = self.for_each_model(assumptions, &mut |m: &Model| {
            models.push(m.clone());
            true
        });
        r.models = models;
        r
    }

    /// After a call under assumptions ([`Solver::solve_with`], [`Solver::for_each_model`])
    /// that found no answer set and was not stopped: the assumptions (aspif literals, in the
    /// caller's order) that the refutation used, a subset under which the program has no answer
    /// set either (clingo's unsatisfiable core; not minimal). Empty when the program has none
    /// under any assumption. `None` after a call that found a model or was stopped, and after
    /// [`Solver::solve`].
    pub fn core(&self) -> Option<&[i32]> {
        self.core.as_deref()
    }

    /// Solves under extra assumptions, calling `sink` on every model as it is found (return
    /// false to stop). The returned result has an empty model list.
    pub fn for_each_model(
        &mut self,
        assumptions: &[i32],
        sink: &mut dyn FnMut(&Model) -> bool,
    ) -> SolveResult {
        self.run_call(assumptions, &mut |m, _| sink(m), false)
    }

    /// [`Solver::for_each_model`] for callers that read the models' supports rarely: every
    /// model comes without [`Model::support`] (whatever `Config::supports` says), and `sink`
    /// gets the program too, so that it can compute them on demand with `solver::supports` (the
    /// same answer); a caller that reads few of them skips building the rest.
    pub fn for_each_model_lazy(
        &mut self,
        assumptions: &[i32],
        sink: &mut dyn FnMut(&Model, &GroundProgram) -> bool,
    ) -> SolveResult {
        self.run_call(assumptions, sink, true)
    }

    /// One solve call under `assumptions` (see [`Solver::for_each_model`]), on the portfolio's
    /// threads when there are helpers.
    fn run_call(
        &mut self,
        assumptions: &[i32],
        sink: &mut dyn FnMut(&Model, &GroundProgram) -> bool,
        lazy_support: bool,
    ) -> SolveResult {
        self.apply_config();
        let auto = self.config.models == Config::AUTO_MODELS;
        if auto {
            let optimizing =
                !self.prog.minimize.is_empty() && self.config.opt_mode != OptMode::Ignore;
            let consequences = self.config.enum_mode != EnumMode::Auto;
            self.config.models = usize::from(!optimizing && !consequences);
        }
        let r = if self.par.is_some() {
            self.run_parallel(assumptions, sink, lazy_support)
        } else {
            self.run_call_one(assumptions, sink, lazy_support)
        };
        if auto {
            self.config.models = Config::AUTO_MODELS;
        }
        self.total.accumulate(&r.stats);
        // A propagator's volatile variables (`PropagateControl::add_literal`) end with the call.
        self.engine.retire_external_vars();
        r
    }

    /// The statistics of every solve call so far, added up (each call's own are in its
    /// [`SolveResult::stats`]).
    pub fn accumulated_stats(&self) -> &Stats {
        &self.total
    }

    /// One solve call of this solver alone.
    fn run_call_one(
        &mut self,
        assumptions: &[i32],
        sink: &mut dyn FnMut(&Model, &GroundProgram) -> bool,
        lazy_support: bool,
    ) -> SolveResult {
        let start = Instant::now();
        let (d0, c0, r0, p0, l0) = (
            self.engine.stats.decisions,
            self.engine.stats.conflicts,
            self.engine.stats.num_restarts,
            self.engine.stats.propagations,
            self.engine.stats.loop_nogoods,
        );
        self.engine.limits.deadline = self.config.deadline;
        self.engine.limits.conflict_limit = self.config.conflict_limit.map(|n| c0 + n);
        self.engine.limits.interrupt = self.config.interrupt.clone();
        if self.calls > 0 && !std::mem::take(&mut self.keep_learnts) {
            // What earlier calls learnt is kept up to a limit set by the problem size, as clasp
            // sets it at the start of every solve call (`--del-init=3.0,200,40000`).
            let cap = (self.problem_size / 3).clamp(200, 40_000);
            self.engine.limit_learnts(cap);
        }
        self.calls += 1;
        let mut assume: Vec<Lit> = self.tr.assumptions.clone();
        assume.extend(assumptions.iter().map(|&l| self.lit_of(l)));
        assume.extend_from_slice(&self.cube);
        let call_guard = self.new_guard();
        assume.push(call_guard);
        self.call_guard = Some(call_guard);
        let mut call = Call {
            count: 0,
            phase_count: 0,
            unlimited: false,
            sink,
            with_support: self.config.supports && !lazy_support,
            done: false,
            stopped: false,
            seen: HashSet::new(),
            optimum: false,
            has_costs: false,
            exhausted: false,
            start,
            first_model: None,
            last_model: None,
        };
        if self.cr_lits.is_empty() {
            self.run_main(&mut call, &assume, call_guard);
        } else {
            match self.config.cr_mode {
                CrMode::Cardinality => self.run_cr_cardinality(&mut call, &assume, call_guard),
                CrMode::Subset => self.run_cr_subset(&mut call, &assume, call_guard),
            }
        }
        // With no model, the last search ran under `assume` alone (bound and phase guards
        // are added only after a model), so its failed assumptions refute the program.
        self.core = (call.count == 0 && call.exhausted && !call.stopped).then(|| {
            let failed = self.engine.failed_assumptions();
            assumptions
                .iter()
                .copied()
                .filter(|&l| failed.contains(&self.lit_of(l)))
                .collect()
        });
        self.call_guard = None;
        self.retire(call_guard);
        let outcome = if call.count > 0 {
            if call.optimum && call.has_costs {
                Outcome::Optimum
            } else {
                Outcome::Satisfiable
            }
        } else if call.exhausted {
            Outcome::Unsatisfiable
        } else {
            Outcome::Unknown
        };
        let stop = if call.stopped {
            Some(if self.engine.limits.interrupted {
                StopReason::Interrupted
            } else if self.engine.limits.conflict_hit {
                StopReason::ConflictLimit
            } else {
                StopReason::TimeLimit
            })
        } else {
            None
        };
        SolveResult {
            models: Vec::new(),
            outcome,
            exhausted: call.exhausted && !call.stopped,
            optimum_proven: call.optimum,
            stop,
            stats: Stats {
                choices: self.engine.stats.decisions - d0,
                conflicts: self.engine.stats.conflicts - c0,
                restarts: self.engine.stats.num_restarts - r0,
                propagations: self.engine.stats.propagations - p0,
                loop_nogoods: self.engine.stats.loop_nogoods - l0,
                learnt: self.engine.num_learnts() as u64,
                vars: self.engine.num_vars() as u64,
                clauses: self.engine.stats.num_clauses,
                time: start.elapsed(),
                first_model: call.first_model,
                unsat: if call.exhausted && !call.stopped {
                    call.last_model.unwrap_or(start).elapsed()
                } else {
                    std::time::Duration::ZERO
                },
            },
        }
    }

    /// What the engine holds now: variables, clauses, learnt clauses, weight constraints
    /// (for tests and benchmarks that check that calls leave nothing behind).
    pub fn engine_size(&self) -> super::engine::EngineSize {
        self.engine.size()
    }

    /// Number of minimality checks done for non-head-cycle-free programs.
    pub fn minimality_checks(&self) -> u64 {
        self.minimality_checks + self.engine.stability_checks().0
    }

    /// A fresh guard literal (never decided; assumed while its constraints hold).
    fn new_guard(&mut self) -> Lit {
        self.engine.backtrack(0);
        let g = self.engine.new_private_var();
        self.engine.set_decidable(g, false);
        self.scopes.push(Scope {
            guard: g.positive(),
            aux: Vec::new(),
            weights: Vec::new(),
        });
        g.positive()
    }

    /// The scope of `guard`.
    fn scope(&mut self, guard: Lit) -> &mut Scope {
        self.scopes
            .iter_mut()
            .rev()
            .find(|s| s.guard == guard)
            .expect("the guard is in use")
    }

    /// A fresh variable owned by `guard`, retired with it.
    fn aux_var(&mut self, guard: Lit) -> Lit {
        let v = self.engine.new_private_var();
        self.scope(guard).aux.push(v);
        v.positive()
    }

    /// A fresh literal owned by `guard` standing for `sum(w * l) >= bound`.
    fn aux_weight(&mut self, guard: Lit, lits: &[(Lit, i64)], bound: i64) -> Lit {
        let h = self.aux_var(guard);
        self.engine.add_weight(h, lits, bound);
        self.scope(guard).weights.push(h);
        h
    }

    /// A fresh literal owned by `guard` equivalent to the conjunction of `lits` (not entered in
    /// the translation's table of conjunctions, which outlives the guard).
    fn aux_conjunction(&mut self, guard: Lit, lits: &[Lit]) -> Lit {
        match lits {
            [] => self.tr.true_lit(),
            [l] => *l,
            _ => {
                let x = self.aux_var(guard);
                let mut big = vec![x];
                for &l in lits {
                    self.engine.add_clause(&[!x, l]);
                    big.push(!l);
                }
                self.engine.add_clause(&big);
                x
            }
        }
    }

    /// Ends the life of `guard`: it is fixed false, the weight constraints of its scope are
    /// removed, and its variables are retired (the engine deletes every clause that mentions
    /// them at its next level-0 simplification and reuses the variables), so that a call
    /// leaves nothing behind.
    fn retire(&mut self, guard: Lit) {
        self.engine.add_clause(&[!guard]);
        let Some(k) = self.scopes.iter().rposition(|s| s.guard == guard) else {
            return;
        };
        let scope = self.scopes.swap_remove(k);
        for &h in &scope.weights {
            self.engine.remove_weight(h);
        }
        let mut vars = scope.aux;
        vars.push(guard.var());
        self.engine.retire_vars(&vars);
    }
}

/// The engine's initial restart state for a policy.
fn restart_state(policy: RestartPolicy) -> Restarts {
    match policy {
        RestartPolicy::Luby(u) => Restarts::Luby {
            unit: u.max(1),
            index: 0,
            left: u.max(1) as u64,
        },
        RestartPolicy::Glucose => Restarts::Glucose {
            fast: 0.0,
            slow: 0.0,
            since: 0,
            trail: 0.0,
        },
        RestartPolicy::Never => Restarts::Never,
    }
}

/// For every true atom of `atoms` (sorted), one rule index that derives it in a well-founded
/// order: its body holds in the model, its positive body atoms were derived before, and for a
/// disjunctive rule the other head atoms are false when possible.
pub fn supports(p: &GroundProgram, atoms: &[u32]) -> Vec<Option<usize>> {
    let n = p.num_atoms as usize;
    let mut in_m = vec![false; n + 1];
    for &a in atoms {
        in_m[a as usize] = true;
    }
    let holds = |l: i32| -> bool {
        let a = l.unsigned_abs() as usize;
        a <= n && (in_m[a] == (l > 0))
    };
    let mut derived = vec![false; n + 1];
    let mut support: Vec<Option<usize>> = vec![None; n + 1];
    // Atoms of the model not derived yet: once none is left, no pass can change anything.
    let mut open = atoms.iter().filter(|&&a| (a as usize) <= n).count();
    // Repeated passes; each pass derives at least one atom or stops.
    for strict in [true, false] {
        while open > 0 {
            let mut changed = false;
            for (ri, r) in p.rules.iter().enumerate() {
                // Only a rule with a head atom of the model not derived yet can support
                // anything (constraints never): test that before the body.
                let useful = r.head.iter().any(|&h| {
                    let hu = h as usize;
                    hu <= n && in_m[hu] && !derived[hu]
                });
                if !useful {
                    continue;
                }
                let body_ok = match r.body {
                    BodyRef::Normal(ls) => ls
                        .iter()
                        .all(|&l| holds(l) && (l < 0 || derived[l as usize])),
                    BodyRef::Weight { lower, lits } => {
                        let s: i64 = lits
                            .iter()
                            .filter(|&&(l, _)| holds(l) && (l < 0 || derived[l as usize]))
                            .map(|&(_, w)| w)
                            .sum();
                        s >= lower
                    }
                };
                if !body_ok {
                    continue;
                }
                for &h in r.head {
                    let hu = h as usize;
                    if hu > n || !in_m[hu] || derived[hu] {
                        continue;
                    }
                    let exclusive = r.head_kind == HeadKind::Choice
                        || r.head.iter().all(|&o| o == h || !in_m[o as usize]);
                    if strict && !exclusive {
                        continue;
                    }
                    derived[hu] = true;
                    support[hu] = Some(ri);
                    changed = true;
                    open -= 1;
                }
            }
            if !changed {
                break;
            }
        }
    }
    atoms.iter().map(|&a| support[a as usize]).collect()
}

/// The program's unconditional `#heuristic` statements as decision preferences, lower
/// priorities first so a higher one wins: level sets the atom's level, sign its polarity (a
/// positive bias true, a negative false), true and false both (level = bias).
fn apply_domain_heuristics(prog: &GroundProgram, tr: &Translation, engine: &mut Engine) {
    use crate::ground::program::HeuristicModifier as M;
    let mut hs: Vec<&crate::ground::program::Heuristic> = prog
        .heuristics
        .iter()
        .filter(|h| h.condition.is_empty())
        .collect();
    hs.sort_by_key(|h| h.priority);
    for h in hs {
        let Some(&lit) = tr.atom_lit.get(h.atom as usize) else {
            continue;
        };
        let v = lit.var();
        // The sign of `v` that makes the atom true.
        let atom_true = !lit.is_neg();
        let towards = |yes: bool| if yes { atom_true } else { !atom_true };
        match h.modifier {
            M::Level => engine.prefer(v, Some(h.bias), None),
            M::Sign if h.bias != 0 => engine.prefer(v, None, Some(towards(h.bias > 0))),
            M::True => engine.prefer(v, Some(h.bias), Some(towards(true))),
            M::False => engine.prefer(v, Some(h.bias), Some(towards(false))),
            _ => {}
        }
    }
}
