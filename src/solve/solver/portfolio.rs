//! The parallel portfolio (`Config::threads >= 2`): one solver per thread over the same
//! program, built and extended in lockstep (multi-shot steps, externals), diversified search
//! settings (clasp's portfolio idea: restarts, profile, random decisions, sign, seed), learnt
//! clauses exchanged through an `engine::Hub`, and every kind of call run on all threads:
//!
//! - *race* (one model, branch-and-bound optimization, brave/cautious consequences): every
//!   thread runs the whole call; the first to finish answers and stops the others. In
//!   optimization each model's costs are published, and the others adopt a better bound at once
//!   (their search is interrupted and resumes under it); a model is passed on only when it
//!   improves on every model passed on before, so the caller sees a strictly improving
//!   sequence whose last element is optimal once some thread proves the bound unsatisfiable.
//! - *cubes* (enumeration of several or all models, `--opt-mode=enum`, the second phase of
//!   optN): the search space is split on a few atoms (or projection literals) into disjoint
//!   cubes, which the threads take from a queue and solve as assumptions; so every model (every
//!   projection) is found in exactly one cube, hence reported exactly once, and a thread that
//!   finishes early takes the next cube.
//! - optN is a race for the optimum followed by the cubes under the bound `<= optimum`.
//! - CR-Prolog programs run on the main thread alone (their two-level minimization is not
//!   split), with a warning printed once per solver.
//!
//! Invariants: the main solver (thread 0) runs in the caller's thread and is the only one that
//! calls the caller's sink (the sink need not be `Send`); helpers send their models through a
//! channel that the main thread drains whenever its own search reports, and at the end. All
//! solvers receive the same `add_program`, external and output calls in the same order, so the
//! shared variable numbering agrees (checked after every step; sharing stops otherwise).

use super::*;
use crate::solve::engine::Hub;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::mpsc;
use std::sync::{Arc, Mutex};

/// Cube literals: 2^CUBE_VARS cubes.
const CUBE_VARS: usize = 4;
/// No winner yet.
const NO_WINNER: usize = usize::MAX;

/// The best optimization bound found by any thread.
pub(super) struct SharedBound {
    best: Mutex<Option<Vec<i64>>>,
    /// Bumped on every improvement (the engines watch it, `Limits::bound_gen`).
    gen: Arc<AtomicU64>,
}

impl SharedBound {
    /// Offers the costs of a model; true when they improve on the best known.
    fn offer(&self, costs: &[i64]) -> bool {
        if costs.is_empty() {
            return false;
        }
        let mut b = self.best.lock().unwrap_or_else(|e| e.into_inner());
        if b.as_ref().is_some_and(|b| b.as_slice() <= costs) {
            return false;
        }
        *b = Some(costs.to_vec());
        self.gen.fetch_add(1, Ordering::Relaxed);
        true
    }
}

/// The helpers of a portfolio and what the threads share.
pub(super) struct Portfolio {
    /// Solvers 1.. (the main solver is number 0).
    helpers: Vec<Solver>,
    /// The learnt-clause exchange.
    hub: Arc<Hub>,
    /// Set to stop every thread of the current call.
    stop: Arc<AtomicBool>,
    /// The best bound of the current optimization.
    bound: Arc<SharedBound>,
    /// Whether the CR fallback warning was printed.
    warned: bool,
}

/// How a call is spread over the threads.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Mode {
    /// The main thread alone (CR-Prolog programs).
    Single,
    /// First model wins.
    First,
    /// Branch and bound with shared bounds.
    Optimize,
    /// Brave or cautious consequences: the winner's estimates are reported.
    Consequences,
    /// Disjoint cubes from a queue.
    Cubes,
    /// Optimize, then the optimal models by cubes.
    OptN,
}

/// What one thread of a call needs.
struct Job<'a> {
    mode: Mode,
    assumptions: &'a [i32],
    lazy: bool,
    stop: &'a AtomicBool,
    winner: &'a AtomicUsize,
    /// Cubes as shared literal codes.
    cubes: &'a [Vec<u32>],
    next_cube: &'a AtomicUsize,
    /// Models taken so far against the limit (cubes).
    taken: &'a AtomicUsize,
    limit: usize,
    bound: &'a SharedBound,
}

/// What one thread of a call answers.
struct Done {
    result: SolveResult,
    /// Every cube this thread took was exhausted (cubes), or its call was (race).
    exhausted: bool,
    /// The failed caller assumptions, when nothing was found.
    core: Option<Vec<i32>>,
}

/// A helper's model, sent to the main thread.
struct Sent {
    from: usize,
    model: Model,
}

/// The main thread's end of a call: delivers models to the caller's sink.
struct Relay<'a> {
    mode: Mode,
    sink: &'a mut dyn FnMut(&Model, &GroundProgram) -> bool,
    rx: mpsc::Receiver<Sent>,
    stop: Arc<AtomicBool>,
    /// Models delivered (in the current phase).
    delivered: usize,
    /// Costs of the last model delivered in optimization.
    best: Option<Vec<i64>>,
    /// Consequence estimates per thread, delivered for the winner at the end.
    buffered: Vec<Vec<Model>>,
    /// Mark delivered models optimal (optN's second phase).
    optimal: bool,
    /// The caller's sink asked to stop.
    user_stop: bool,
    any_costs: bool,
    start: Instant,
    first_model: Option<std::time::Duration>,
}

impl Relay<'_> {
    /// Delivers (or drops, or buffers) one model; returns whether its thread may go on.
    fn deliver(&mut self, from: usize, mut m: Model, prog: &GroundProgram) -> bool {
        m.thread_id = u32::try_from(from).unwrap_or(u32::MAX);
        if self.user_stop {
            return false;
        }
        match self.mode {
            Mode::Consequences => {
                self.buffered[from].push(m);
                return true;
            }
            Mode::First if self.delivered > 0 => return false,
            Mode::Optimize
                if self
                    .best
                    .as_ref()
                    .is_some_and(|b| b.as_slice() <= &m.costs[..]) =>
            {
                return true;
            }
            _ => {}
        }
        if self.mode == Mode::Optimize {
            self.best = Some(m.costs.clone());
        }
        self.delivered += 1;
        self.any_costs |= !m.costs.is_empty();
        self.first_model.get_or_insert(self.start.elapsed());
        m.number = self.delivered;
        m.optimal = self.optimal;
        if !(self.sink)(&m, prog) {
            self.user_stop = true;
            self.stop.store(true, Ordering::Relaxed);
            return false;
        }
        if self.mode == Mode::First {
            self.stop.store(true, Ordering::Relaxed);
            return false;
        }
        true
    }

    /// Delivers every model the helpers sent so far.
    fn drain(&mut self, prog: &GroundProgram) {
        while let Ok(s) = self.rx.try_recv() {
            self.deliver(s.from, s.model, prog);
        }
    }
}

/// The configuration of thread `k` for a call configured by `base`: thread 0 as configured,
/// the others with other search settings. The variable numbering must agree, so the
/// equivalence setting (`eq`), which changes the translation, is never varied.
pub(super) fn diversify(base: &Config, k: usize) -> Config {
    let mut c = base.clone();
    c.threads = 1;
    c.seed = base.seed.wrapping_add(k as u64 * 7919);
    match k % 4 {
        0 => {}
        1 if matches!(base.profile, SearchProfile::Decision | SearchProfile::Auto) => {
            // The other search profile than thread 0's (`SearchProfile::Complement`): glucose
            // restarts, progress saving and the phase switch where thread 0 has clasp's tweety
            // values; on decision problems the two profiles win different rows, by up to 25
            // times in conflicts. As the second configuration of clasp's portfolio (`clingo
            // --print-portfolio`: `--opt-strat=usc,disjoint`), core-guided optimization beside
            // thread 0's branch and bound.
            c.profile = SearchProfile::Complement;
            c.opt_strategy = OptStrategy::Usc;
        }
        1 => {
            // clasp's "frumpy"-like settings: the fixed profile, Luby restarts, some
            // random decisions; and core-guided optimization, as above.
            c.profile = SearchProfile::Fixed;
            c.restarts = RestartPolicy::Luby(100);
            c.random_freq_permille = 10;
            c.opt_strategy = OptStrategy::Usc;
        }
        2 => {
            c.default_phase_false = !base.default_phase_false;
            c.restarts = RestartPolicy::Luby(256);
        }
        _ => {
            c.profile = SearchProfile::Fixed;
            c.random_freq_permille = 20;
            c.default_phase_false = !base.default_phase_false;
        }
    }
    c
}

impl Portfolio {
    /// The helper solvers (threads `1..`).
    pub(super) fn helpers_mut(&mut self) -> &mut [Solver] {
        &mut self.helpers
    }

    /// How many helpers there are.
    pub(super) fn helpers_len(&self) -> usize {
        self.helpers.len()
    }
}

impl Solver {
    /// A solver for `prog` with `config.threads` threads: this one and its helpers, built in
    /// parallel and connected to one hub.
    pub(super) fn new_portfolio(prog: GroundProgram, config: Config) -> Solver {
        let n = config.threads.clamp(2, 64);
        let mut main_cfg = config.clone();
        main_cfg.threads = 1;
        let (mut main, helpers) = std::thread::scope(|s| {
            let handles: Vec<_> = (1..n)
                .map(|k| {
                    let p = &prog;
                    let c = diversify(&config, k);
                    s.spawn(move || Solver::from_program(p.clone(), c))
                })
                .collect();
            let main = Solver::from_program(prog.clone(), main_cfg);
            let helpers: Vec<Solver> = handles
                .into_iter()
                .map(|h| h.join().expect("building a helper solver does not panic"))
                .collect();
            (main, helpers)
        });
        main.config.threads = config.threads;
        let hub = Arc::new(Hub::new(n));
        let stop = Arc::new(AtomicBool::new(false));
        let bound = Arc::new(SharedBound {
            best: Mutex::new(None),
            gen: Arc::new(AtomicU64::new(0)),
        });
        let mut par = Portfolio {
            helpers,
            hub,
            stop,
            bound,
            warned: false,
        };
        main.link(&par, 0);
        for (k, h) in par.helpers.iter_mut().enumerate() {
            h.engine.connect(Some((par.hub.clone(), k + 1)));
            h.engine.limits.portfolio_stop = Some(par.stop.clone());
            h.engine.limits.bound_gen = Some(par.bound.gen.clone());
            h.shared_bound = Some(par.bound.clone());
        }
        par.check_numbering(&main);
        main.par = Some(Box::new(par));
        main
    }

    /// Connects this solver to the portfolio's hub, stop flag and bound as thread `k`.
    fn link(&mut self, par: &Portfolio, k: usize) {
        self.engine.connect(Some((par.hub.clone(), k)));
        self.engine.limits.portfolio_stop = Some(par.stop.clone());
        self.engine.limits.bound_gen = Some(par.bound.gen.clone());
        self.shared_bound = Some(par.bound.clone());
    }

    /// Runs `f` on every helper (in parallel with each other), for the multi-shot steps that
    /// all solvers take in lockstep; then checks the shared numbering.
    pub(super) fn on_helpers(&mut self, f: &(dyn Fn(&mut Solver) + Sync)) {
        let Some(par) = self.par.as_mut() else {
            return;
        };
        std::thread::scope(|s| {
            for h in par.helpers.iter_mut() {
                s.spawn(move || f(h));
            }
        });
        let par = self.par.take().expect("taken above");
        par.check_numbering(self);
        self.par = Some(par);
    }

    /// Before a branch-and-bound search: adopts the portfolio's best bound when it is better
    /// than this thread's (`bound_guard` tightened to `costs <lex best`).
    /// Returns true when it did.
    pub(super) fn adopt_bound(&mut self, bound_guard: &mut strategies::BoundGuard) -> bool {
        let Some(sb) = self.shared_bound.clone() else {
            return false;
        };
        self.engine.limits.bound_seen = sb.gen.load(Ordering::Relaxed);
        let best = sb.best.lock().unwrap_or_else(|e| e.into_inner()).clone();
        let Some(best) = best else {
            return false;
        };
        if self.best.as_ref().is_some_and(|b| *b <= best) {
            return false;
        }
        self.tighten_bound(bound_guard, &best, false);
        self.best = Some(best);
        true
    }

    /// Core-guided optimization in a portfolio: the bound that the best costs any thread
    /// found put on the level after `fixed` (`i64::MAX` when none, or when they miss the
    /// optima `fixed` of the levels above); the bound news is taken as seen.
    pub(super) fn shared_level_bound(&mut self, fixed: &[i64]) -> i64 {
        let Some(sb) = self.shared_bound.clone() else {
            return i64::MAX;
        };
        self.engine.limits.bound_seen = sb.gen.load(Ordering::Relaxed);
        let best = sb.best.lock().unwrap_or_else(|e| e.into_inner());
        best.as_deref()
            .map_or(i64::MAX, |b| core_guided::level_bound(b, fixed))
    }

    /// How this call is spread over the threads.
    fn mode(&self) -> Mode {
        if !self.cr_lits.is_empty() {
            return Mode::Single;
        }
        if self.config.enum_mode != EnumMode::Auto {
            return Mode::Consequences;
        }
        let optimize = !self.tr.minimize.is_empty() && self.config.opt_mode != OptMode::Ignore;
        match &self.config.opt_mode {
            OptMode::Opt if optimize => Mode::Optimize,
            OptMode::OptN if optimize => Mode::OptN,
            OptMode::Enum(b) if optimize && !b.is_empty() => Mode::Cubes,
            _ if self.config.models == 1 => Mode::First,
            _ => Mode::Cubes,
        }
    }

    /// One solve call on every thread (see the module comment).
    pub(super) fn run_parallel(
        &mut self,
        assumptions: &[i32],
        sink: &mut dyn FnMut(&Model, &GroundProgram) -> bool,
        lazy: bool,
    ) -> SolveResult {
        let mode = self.mode();
        let mut par = self.par.take().expect("a portfolio");
        if mode == Mode::Single {
            if !par.warned {
                par.warned = true;
                eprintln!(
                    "lucent: warning: CR-Prolog programs are solved on one thread; \
                     --parallel-mode ignored"
                );
            }
            self.par = Some(par);
            return self.run_call_one(assumptions, sink, lazy);
        }
        let start = Instant::now();
        let (tx, rx) = mpsc::channel();
        let mut relay = Relay {
            mode,
            sink,
            rx,
            stop: par.stop.clone(),
            delivered: 0,
            best: None,
            buffered: vec![Vec::new(); par.helpers.len() + 1],
            optimal: false,
            user_stop: false,
            any_costs: false,
            start,
            first_model: None,
        };
        let saved = self.config.clone();
        let result = if mode == Mode::OptN {
            self.config.opt_mode = OptMode::Opt;
            relay.mode = Mode::Optimize;
            let first = self.run_phase(&mut par, &mut relay, &tx, assumptions, lazy);
            let best = relay.best.clone();
            match best {
                Some(best) if first.exhausted && !relay.user_stop => {
                    self.config.opt_mode = OptMode::Enum(best);
                    relay.mode = Mode::OptN;
                    relay.delivered = 0;
                    relay.optimal = true;
                    let mut r = self.run_phase(&mut par, &mut relay, &tx, assumptions, lazy);
                    r.stats.choices += first.stats.choices;
                    r.stats.conflicts += first.stats.conflicts;
                    r.stats.restarts += first.stats.restarts;
                    r
                }
                _ => first,
            }
        } else {
            self.run_phase(&mut par, &mut relay, &tx, assumptions, lazy)
        };
        self.config = saved;
        self.par = Some(par);
        let mut result = result;
        result.stats.time = start.elapsed();
        result.stats.first_model = relay.first_model;
        result
    }

    /// One phase of a call: every thread works on `relay.mode`'s job; the answers are merged.
    fn run_phase(
        &mut self,
        par: &mut Portfolio,
        relay: &mut Relay<'_>,
        tx: &mpsc::Sender<Sent>,
        assumptions: &[i32],
        lazy: bool,
    ) -> SolveResult {
        let mode = relay.mode;
        let cubes = if matches!(mode, Mode::Cubes | Mode::OptN) {
            self.make_cubes()
        } else {
            Vec::new()
        };
        par.stop.store(false, Ordering::Relaxed);
        *par.bound.best.lock().unwrap_or_else(|e| e.into_inner()) = None;
        let limit = if matches!(mode, Mode::Cubes | Mode::OptN) {
            self.config.models
        } else {
            0
        };
        let winner = AtomicUsize::new(NO_WINNER);
        let next_cube = AtomicUsize::new(0);
        let taken = AtomicUsize::new(0);
        let job = Job {
            mode,
            assumptions,
            lazy,
            stop: &par.stop,
            winner: &winner,
            cubes: &cubes,
            next_cube: &next_cube,
            taken: &taken,
            limit,
            bound: &par.bound,
        };
        for (k, h) in par.helpers.iter_mut().enumerate() {
            h.config = diversify(&self.config, k + 1);
            if limit > 0 {
                h.config.models = 0;
            }
        }
        let main_models = self.config.models;
        if limit > 0 {
            self.config.models = 0;
        }
        let job = &job;
        let (main_done, helper_done) = std::thread::scope(|s| {
            let handles: Vec<_> = par
                .helpers
                .iter_mut()
                .enumerate()
                .map(|(k, h)| {
                    let tx = tx.clone();
                    s.spawn(move || {
                        let me = k + 1;
                        let mut sink = |m: &Model, _: &GroundProgram| {
                            if !job.admit(m) {
                                return false;
                            }
                            let go = !job.stop.load(Ordering::Relaxed);
                            // The receiver lives until after the scope.
                            let _ = tx.send(Sent {
                                from: me,
                                model: m.clone(),
                            });
                            go && job.mode != Mode::First
                        };
                        h.work(me, job, &mut sink)
                    })
                })
                .collect();
            let mut sink = |m: &Model, prog: &GroundProgram| {
                relay.drain(prog);
                if !job.admit(m) {
                    return false;
                }
                relay.deliver(0, m.clone(), prog) && !job.stop.load(Ordering::Relaxed)
            };
            let main_done = self.work(0, job, &mut sink);
            // The others stop once the main thread is done, except cubes, whose queue ends.
            if mode != Mode::Cubes && mode != Mode::OptN {
                par.stop.store(true, Ordering::Relaxed);
            }
            let helper_done: Vec<Done> = handles
                .into_iter()
                .map(|h| h.join().expect("a portfolio thread does not panic"))
                .collect();
            (main_done, helper_done)
        });
        self.config.models = main_models;
        relay.drain(&self.prog);
        let mut all = vec![main_done];
        all.extend(helper_done);
        let w = winner.load(Ordering::Relaxed);
        if mode == Mode::Consequences && w != NO_WINNER {
            for m in std::mem::take(&mut relay.buffered[w]) {
                if !(relay.sink)(&m, &self.prog) {
                    break;
                }
                relay.delivered += 1;
            }
        }
        self.merge(
            mode,
            relay,
            all,
            w,
            next_cube.load(Ordering::Relaxed) >= cubes.len(),
        )
    }

    /// The merged answer of the threads of one phase.
    fn merge(
        &mut self,
        mode: Mode,
        relay: &Relay<'_>,
        all: Vec<Done>,
        winner: usize,
        queue_empty: bool,
    ) -> SolveResult {
        let mut stats = all[0].result.stats.clone();
        for d in &all[1..] {
            stats.choices += d.result.stats.choices;
            stats.conflicts += d.result.stats.conflicts;
            stats.restarts += d.result.stats.restarts;
            stats.propagations += d.result.stats.propagations;
        }
        let n = relay.delivered;
        let race = !matches!(mode, Mode::Cubes | Mode::OptN);
        let (exhausted, stop, core) = if race {
            match all.get(winner) {
                Some(d) => (d.exhausted, d.result.stop, d.core.clone()),
                None => {
                    // Nobody finished on its own: a limit stopped them all.
                    (false, all.iter().find_map(|d| d.result.stop), None)
                }
            }
        } else {
            let exhausted = queue_empty && all.iter().all(|d| d.exhausted);
            let stop = if exhausted || relay.user_stop || self.limit_reached(n) {
                None
            } else {
                all.iter().find_map(|d| d.result.stop)
            };
            let core = exhausted.then(|| {
                let mut c: Vec<i32> = all.iter().flat_map(|d| d.core.clone()).flatten().collect();
                c.sort_unstable();
                c.dedup();
                c
            });
            (exhausted, stop, core)
        };
        self.core = if n == 0 && exhausted { core } else { None };
        let outcome = match mode {
            Mode::Consequences => all
                .get(winner)
                .map_or(Outcome::Unknown, |d| d.result.outcome),
            _ if n == 0 => {
                if exhausted {
                    Outcome::Unsatisfiable
                } else {
                    Outcome::Unknown
                }
            }
            Mode::Optimize if exhausted && relay.any_costs => Outcome::Optimum,
            Mode::OptN if exhausted => Outcome::Optimum,
            _ => Outcome::Satisfiable,
        };
        let optimum_proven = match mode {
            Mode::Optimize | Mode::OptN => exhausted && n > 0,
            _ => false,
        };
        SolveResult {
            models: Vec::new(),
            outcome,
            exhausted: exhausted && stop.is_none(),
            optimum_proven,
            stop,
            stats,
        }
    }

    /// Whether `n` delivered models reach the model limit.
    fn limit_reached(&self, n: usize) -> bool {
        self.config.models > 0 && n >= self.config.models
    }

    /// Thread `me`'s part of a phase.
    fn work(
        &mut self,
        me: usize,
        job: &Job<'_>,
        sink: &mut dyn FnMut(&Model, &GroundProgram) -> bool,
    ) -> Done {
        self.best = None;
        self.engine.limits.bound_seen = job.bound.gen.load(Ordering::Relaxed);
        if !matches!(job.mode, Mode::Cubes | Mode::OptN) {
            let r = self.run_call_one(job.assumptions, sink, job.lazy);
            let by_peer = r.stop.is_some()
                && job.stop.load(Ordering::Relaxed)
                && !self.engine.limits.interrupted;
            if !by_peer
                && job
                    .winner
                    .compare_exchange(NO_WINNER, me, Ordering::SeqCst, Ordering::SeqCst)
                    .is_ok()
            {
                job.stop.store(true, Ordering::Relaxed);
            }
            return Done {
                exhausted: r.exhausted,
                core: self.core.clone(),
                result: r,
            };
        }
        let mut total: Option<SolveResult> = None;
        let mut exhausted = true;
        let mut core: Vec<i32> = Vec::new();
        loop {
            if job.stop.load(Ordering::Relaxed) {
                exhausted = false;
                break;
            }
            let i = job.next_cube.fetch_add(1, Ordering::SeqCst);
            let Some(cube) = job.cubes.get(i) else {
                break;
            };
            let Some(lits) = cube
                .iter()
                .map(|&c| self.engine.local_lit(c))
                .collect::<Option<Vec<Lit>>>()
            else {
                // A cube this engine cannot name (numbering disagreement): not exhausted.
                exhausted = false;
                continue;
            };
            self.cube = lits;
            let r = self.run_call_one(job.assumptions, sink, job.lazy);
            self.cube.clear();
            // The later cubes of this call keep what the earlier ones learnt.
            self.keep_learnts = true;
            if let Some(c) = &self.core {
                core.extend_from_slice(c);
            }
            let done = r.exhausted;
            total = Some(match total {
                None => r,
                Some(mut t) => {
                    t.stats.choices += r.stats.choices;
                    t.stats.conflicts += r.stats.conflicts;
                    t.stats.restarts += r.stats.restarts;
                    t.stats.propagations += r.stats.propagations;
                    t.stop = r.stop;
                    t
                }
            });
            if !done {
                exhausted = false;
                break;
            }
        }
        self.keep_learnts = false;
        let result = total.unwrap_or_else(|| SolveResult {
            models: Vec::new(),
            outcome: Outcome::Unknown,
            exhausted: true,
            optimum_proven: false,
            stop: None,
            stats: Stats::default(),
        });
        Done {
            result,
            exhausted,
            core: Some(core),
        }
    }

    /// The cubes of a split: all sign combinations of up to `CUBE_VARS` literals that
    /// distinguish answer sets (projection literals when projecting, else atoms), unassigned
    /// at level 0, most active first; as shared literal codes.
    fn make_cubes(&mut self) -> Vec<Vec<u32>> {
        self.engine.backtrack(0);
        let cands: Vec<Lit> = match self.projection() {
            Some(lits) => lits,
            None => (1..=self.prog.num_atoms as usize)
                .map(|a| self.tr.atom_lit[a])
                .collect(),
        };
        let mut picked: Vec<(f64, u32)> = Vec::new();
        let mut seen: HashSet<Var> = HashSet::new();
        for l in cands {
            if self.engine.value(l).is_some() || !seen.insert(l.var()) {
                continue;
            }
            let Some(code) = self.engine.shared_code(l) else {
                continue;
            };
            picked.push((self.engine.split_score(l.var()), code));
        }
        picked.sort_by(|a, b| b.0.total_cmp(&a.0));
        picked.truncate(CUBE_VARS);
        let k = picked.len();
        (0..1usize << k)
            .map(|mask| {
                picked
                    .iter()
                    .enumerate()
                    .map(|(i, &(_, code))| code ^ ((mask >> i) & 1) as u32)
                    .collect()
            })
            .collect()
    }
}

impl Portfolio {
    /// Runs a multi-shot step on every helper (the main solver accepted it already, so they
    /// accept it too).
    pub(super) fn each(&mut self, mut f: impl FnMut(&mut Solver) -> Result<(), SolveError>) {
        for h in &mut self.helpers {
            let r = f(h);
            debug_assert!(r.is_ok(), "a helper refused a step the main solver took");
        }
    }

    /// Turns sharing off when the solvers' shared numberings disagree (they should not).
    fn check_numbering(&self, main: &Solver) {
        let n = main.engine.shared_vars();
        if self.helpers.iter().any(|h| h.engine.shared_vars() != n) {
            self.hub.enabled.store(false, Ordering::Relaxed);
        }
    }
}

impl Job<'_> {
    /// Counts a model against the limit and publishes its costs; false when it is over the
    /// limit (then the threads stop).
    fn admit(&self, m: &Model) -> bool {
        if self.mode == Mode::Optimize {
            self.bound.offer(&m.costs);
        }
        if self.limit == 0 {
            return true;
        }
        let n = self.taken.fetch_add(1, Ordering::SeqCst) + 1;
        if n >= self.limit {
            self.stop.store(true, Ordering::Relaxed);
        }
        n <= self.limit
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ground::program::Rule;

    /// Whether a solver searches with clasp's tweety phase handling (the one setting of that
    /// profile that neither the configured values nor the phase switch give at the start).
    fn tweety(s: &Solver) -> bool {
        s.engine.settings.save_progress == 160 && s.engine.settings.sign_from_learnts
    }

    fn two_threads(rules: Vec<Rule>, atoms: u32) -> Solver {
        let mut p = GroundProgram::new();
        p.num_atoms = atoms;
        p.rules = rules.into();
        Solver::new(
            &p,
            Config {
                threads: 2,
                ..Config::default()
            },
        )
    }

    #[test]
    fn the_second_thread_searches_with_the_other_profile() {
        // Tight: a choice and a rule. Thread 0 has tweety's values, thread 1 the configured ones.
        let tight = two_threads(vec![Rule::choice(&[1], &[]), Rule::normal(&[2], &[1])], 2);
        let helper = &tight.par.as_ref().expect("two threads").helpers[0];
        assert!(tweety(&tight));
        assert!(!tweety(helper));
        // Not tight (1 and 2 support each other): the same.
        let loops = two_threads(
            vec![
                Rule::choice(&[3], &[]),
                Rule::normal(&[1], &[2]),
                Rule::normal(&[2], &[1]),
                Rule::normal(&[1], &[3]),
            ],
            3,
        );
        let helper = &loops.par.as_ref().expect("two threads").helpers[0];
        assert!(tweety(&loops));
        assert!(!tweety(helper));
    }
}
