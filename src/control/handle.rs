//! clingo's solve handle on [`Control`]: a solve call whose models are read one at a time
//! ([`SolveHandle`]: `resume`, `model`, `wait`, `get`, `cancel`, iteration), and the shared
//! preparation of every solve call (assumptions to solver literals, the core mapped back).
//!
//! The search runs on a thread of its own that owns the [`Solver`] for the call ([`Search`]);
//! it reports each model through a channel and, in yield mode, then waits for `resume` before
//! searching on, so a reader that stops after the first model of a huge enumeration pays for
//! one model: the search never runs ahead of the reader. Without yield (clingo's `async_`
//! alone) it runs ahead, keeping up to [`QUEUE`] unread models. The reader converts models to
//! symbols on its side with the Control's tables, so the thread needs nothing but the solver.
//!
//! Invariants:
//! - While a search is out, the Control has no solver: [`SolveHandle`] borrows the Control
//!   mutably for its life, and the detached form ([`Control::start_search`]) marks the Control
//!   busy until [`Control::end_search`] gives the solver back; preparing another call while
//!   busy panics with a sentence (the Python package refuses it with a `RuntimeError` first).
//! - Ending a search never leaves its thread running: `end_search` cancels what is unfinished
//!   (the interrupt flag stops a search in progress, the channel one waiting for `resume`) and
//!   joins the thread, so the solver with its learnt clauses is back for the next call.
//! - Without `background` nothing is searched before the first `resume`, `model`, `wait` or
//!   `get`, as clingo: a handle cancelled before then reports an unknown result.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender, SyncSender};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::Duration;

use super::model::Names;
use super::{Control, Model, OwnedModel, SolveOptions, Summary, Symbol};
use crate::solve::{self, Solver};

/// Unread models a search without yield keeps before it waits for its reader.
pub const QUEUE: usize = 64;

/// How a handle's search runs (clingo's `yield_` and `async_`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HandleMode {
    /// The search stops after each model until `resume` (clingo's `yield_`); otherwise it runs
    /// ahead of the reader, up to [`QUEUE`] unread models.
    pub yield_models: bool,
    /// The search starts at once (clingo's `async_`); otherwise at the first request.
    pub background: bool,
}

impl Default for HandleMode {
    /// clingo's `yield_=True`: lazy, one model at a time.
    fn default() -> Self {
        HandleMode {
            yield_models: true,
            background: false,
        }
    }
}

/// What the search thread reports.
enum Event {
    Model(solve::Model),
    Done(Box<Finished>),
}

/// The end of a search: the solver back, the result, the core's solver literals.
struct Finished {
    solver: Solver,
    result: Option<solve::SolveResult>,
    core: Option<Vec<i32>>,
    count: usize,
}

/// A solve call running on its own thread, detached from its Control (see the module
/// documentation); [`SolveHandle`] is the borrowing form. Its models are the solver's
/// ([`solve::Model`]); [`Control::read_model`] reads one with the Control's symbols.
pub struct Search {
    thread: Option<JoinHandle<()>>,
    events: Receiver<Event>,
    go: Sender<bool>,
    mode: HandleMode,
    started: bool,
    current: Option<solve::Model>,
    /// Models received.
    seen: usize,
    /// Set by `cancel`.
    cancelled: Arc<AtomicBool>,
    interrupt: Arc<AtomicBool>,
    /// The caller's assumptions and their solver literals (for the core).
    assumptions: Vec<(Symbol, bool)>,
    lits: Vec<Option<i32>>,
    /// Once finished: the summary and the solver (until `end_search` takes it).
    done: Option<(Summary, Option<Solver>)>,
}

/// The literals of one solve call: the externals' values and the caller's assumptions.
pub(super) struct CallLits {
    /// Solver assumptions (aspif literals).
    pub(super) assumptions: Vec<i32>,
    /// Per caller assumption, its literal (`None`: no such atom).
    pub(super) lits: Vec<Option<i32>>,
}

/// The caller's assumptions that a solver core contains, in the caller's order.
pub(super) fn map_core(
    assumptions: &[(Symbol, bool)],
    lits: &[Option<i32>],
    core: &[i32],
) -> Vec<(Symbol, bool)> {
    assumptions
        .iter()
        .zip(lits)
        .filter(|(_, l)| l.is_some_and(|l| core.contains(&l)))
        .map(|(a, _)| a.clone())
        .collect()
}

/// The summary of a call an assumption of an atom that does not exist made unsatisfiable.
fn impossible(assumption: &(Symbol, bool)) -> Summary {
    Summary {
        outcome: solve::Outcome::Unsatisfiable,
        exhausted: true,
        search_exhausted: true,
        optimum_proven: false,
        stop: None,
        stats: solve::Stats::default(),
        models: 0,
        core: Some(vec![assumption.clone()]),
    }
}

impl Control {
    /// Sets (or removes) what later solve calls tell each lower bound of the costs they prove
    /// (clingo's `on_unsat`): with `--opt-strategy=usc`, once per core, the optima of the
    /// priority levels done and the current level's bound, highest priority first; branch and
    /// bound tells nothing, as clingo's model-guided search. Called on the solving thread.
    pub fn on_lower_bound(&mut self, observer: Option<crate::solve::LowerBoundObserver>) {
        self.lower_observer = observer;
    }

    /// Where a model callback puts clauses for the rest of its solve call (clingo's
    /// `SolveControl.add_clause`): each clause is program literals (`a` true, `-a` false),
    /// added under the call's guard before the search goes on, so it ends with the call.
    /// Clauses left when a call ends are dropped; with `-t N` they reach thread 0 only.
    pub fn model_clauses(&mut self) -> crate::solve::ModelClauses {
        self.model_clauses
            .get_or_insert_with(Default::default)
            .clone()
    }

    /// Prepares a solve call: the pending statements to the solver, the propagators' `init`,
    /// the assumptions as solver literals. `Err` holds the summary of a call that an assumed
    /// atom that does not exist makes unsatisfiable.
    pub(super) fn begin_call(&mut self, options: &SolveOptions) -> Result<CallLits, Box<Summary>> {
        assert!(
            !self.searching,
            "a detached search is running: end it (Control::end_search) before the next call"
        );
        self.prepare();
        let observer = self.lower_observer.clone();
        let clauses = self.model_clauses.clone();
        if let Some(c) = &clauses {
            c.lock().unwrap_or_else(|p| p.into_inner()).clear();
        }
        let solver = self.solver.as_mut().expect("prepared");
        solver.set_lower_bound_observer(observer);
        solver.set_model_clauses(clauses);
        self.init_propagators();
        let mut assumptions = Vec::new();
        self.external_assumptions(&mut assumptions);
        let mut impossible_at = None;
        let mut lits = Vec::with_capacity(options.assumptions.len());
        for (k, (s, positive)) in options.assumptions.iter().enumerate() {
            let lit = self
                .lookup(s)
                .map(|a| if *positive { a as i32 } else { -(a as i32) });
            match lit {
                Some(l) => assumptions.push(l),
                None if *positive => {
                    impossible_at.get_or_insert(k);
                }
                None => {}
            }
            lits.push(lit);
        }
        match impossible_at {
            Some(k) => Err(Box::new(impossible(&options.assumptions[k]))),
            None => Ok(CallLits { assumptions, lits }),
        }
    }

    /// Starts a solve call whose models are read one at a time (clingo's `solve(yield_=True)`):
    /// see [`SolveHandle`]. The handle borrows the Control; dropping it ends the call.
    ///
    /// ```
    /// use lucent::control::{Control, ControlConfig, HandleMode, Part};
    /// let mut ctl = Control::new(ControlConfig::default());
    /// ctl.solve_config_mut().models = 0;
    /// ctl.add("base", &[], "{p(1..40)}.").unwrap(); // 2^40 answer sets
    /// ctl.ground(&[Part::base()]).unwrap();
    /// let mut handle = ctl.solve_handle(&Default::default(), HandleMode::default());
    /// let mut read = 0;
    /// while let Some(m) = handle.next_model() {
    ///     read += 1;
    ///     if read == 3 { break; } // the search stops here
    /// }
    /// let summary = handle.cancel();
    /// assert_eq!(summary.models, 3);
    /// ```
    pub fn solve_handle(&mut self, options: &SolveOptions, mode: HandleMode) -> SolveHandle<'_> {
        let search = self.start_search(options, mode);
        SolveHandle {
            ctl: self,
            search: Some(search),
        }
    }

    /// [`Control::solve_handle`] detached from the Control, for callers that cannot hold a
    /// borrow (the Python package): the solver leaves the Control until
    /// [`Control::end_search`], and the Control must not prepare another call before then.
    pub fn start_search(&mut self, options: &SolveOptions, mode: HandleMode) -> Search {
        let interrupt = self.interrupter().0;
        let (ev_tx, events) = mpsc::sync_channel(if mode.yield_models { 1 } else { QUEUE });
        let (go, go_rx) = mpsc::channel();
        let mut search = Search {
            thread: None,
            events,
            go,
            mode,
            started: false,
            current: None,
            seen: 0,
            cancelled: Arc::new(AtomicBool::new(false)),
            interrupt,
            assumptions: options.assumptions.clone(),
            lits: Vec::new(),
            done: None,
        };
        let call = match self.begin_call(options) {
            Ok(call) => call,
            Err(summary) => {
                search.done = Some((*summary, None));
                return search;
            }
        };
        search.lits = call.lits;
        let solver = self.solver.take().expect("prepared");
        self.searching = true;
        let cancelled = search.cancelled.clone();
        let thread = std::thread::Builder::new()
            .name("lucent-solve".into())
            .spawn(move || run(solver, call.assumptions, mode, ev_tx, go_rx, cancelled))
            .expect("a thread for the search");
        search.thread = Some(thread);
        if mode.background {
            search.started = true;
        }
        search
    }

    /// Ends a detached search: cancels it if unfinished, takes the solver back and answers the
    /// call's summary.
    pub fn end_search(&mut self, mut search: Search) -> Summary {
        search.cancel();
        let (summary, solver) = search.done.take().expect("cancel finishes the search");
        if let Some(solver) = solver {
            self.solver = Some(solver);
            self.searching = false;
        }
        if let Some(t) = search.thread.take() {
            let _ = t.join();
        }
        summary
    }

    /// True while a detached search has the solver ([`Control::start_search`]).
    pub fn is_searching(&self) -> bool {
        self.searching
    }

    /// Reads a model of a detached search with the Control's symbols.
    pub fn read_model<R>(&self, raw: &solve::Model, f: impl FnOnce(&Model<'_>) -> R) -> R {
        f(&Model {
            raw,
            names: self.names(),
            lazy_support: None,
            full: Default::default(),
        })
    }

    pub(super) fn names(&self) -> Names<'_> {
        Names {
            syms: &self.syms,
            atom_sym: &self.atom_sym,
            sym_atom: &self.sym_atom,
        }
    }
}

/// The search thread: waits for the first request unless in the background, then reports each
/// model and, in yield mode, waits for `resume` (true) or the end (false, or the reader gone).
fn run(
    mut solver: Solver,
    assumptions: Vec<i32>,
    mode: HandleMode,
    events: SyncSender<Event>,
    go: Receiver<bool>,
    cancelled: Arc<AtomicBool>,
) {
    if !mode.background && go.recv() != Ok(true) {
        let done = Finished {
            solver,
            result: None,
            core: None,
            count: 0,
        };
        let _ = events.send(Event::Done(Box::new(done)));
        return;
    }
    let mut count = 0;
    let want_supports = solver.config_mut().supports;
    let mut result = solver.for_each_model_lazy(&assumptions, &mut |m, prog| {
        if cancelled.load(Ordering::Relaxed) {
            return false;
        }
        let mut m = m.clone();
        if want_supports {
            m.support = solve::solver::supports(prog, &m.atoms);
        }
        count += 1;
        if events.send(Event::Model(m)).is_err() {
            return false;
        }
        if mode.yield_models {
            go.recv() == Ok(true)
        } else {
            !cancelled.load(Ordering::Relaxed)
        }
    });
    if super::at_model_limit(&mut solver, count) {
        result.exhausted = false;
    }
    let core = if count == 0 {
        solver.core().map(<[i32]>::to_vec)
    } else {
        None
    };
    let done = Finished {
        solver,
        result: Some(result),
        core,
        count,
    };
    let _ = events.send(Event::Done(Box::new(done)));
}

impl Search {
    fn start(&mut self) {
        if !self.started {
            self.started = true;
            let _ = self.go.send(true);
        }
    }

    /// Takes one event into the state; false when none came within `timeout`.
    fn receive(&mut self, timeout: Option<Duration>) -> bool {
        let event = match timeout {
            None => self
                .events
                .recv()
                .map_err(|_| RecvTimeoutError::Disconnected),
            Some(t) => self.events.recv_timeout(t),
        };
        match event {
            Ok(Event::Model(m)) => {
                self.seen += 1;
                self.current = Some(m);
                true
            }
            Ok(Event::Done(f)) => {
                self.finish(*f);
                true
            }
            Err(RecvTimeoutError::Timeout) => false,
            Err(RecvTimeoutError::Disconnected) => {
                panic!("the search thread ended without its result (a panic in the search)")
            }
        }
    }

    fn finish(&mut self, f: Finished) {
        let cancelled = self.cancelled.load(Ordering::Relaxed);
        let summary = match f.result {
            None => Summary {
                outcome: solve::Outcome::Unknown,
                exhausted: false,
                search_exhausted: false,
                optimum_proven: false,
                stop: Some(solve::StopReason::Interrupted),
                stats: solve::Stats::default(),
                models: 0,
                core: None,
            },
            Some(r) => {
                let mut stop = r.stop;
                if cancelled && !r.exhausted {
                    stop = Some(solve::StopReason::Interrupted);
                }
                Summary {
                    outcome: r.outcome,
                    exhausted: r.exhausted,
                    search_exhausted: r.exhausted,
                    optimum_proven: r.optimum_proven,
                    stop,
                    stats: r.stats,
                    models: f.count,
                    core: f.core.map(|c| map_core(&self.assumptions, &self.lits, &c)),
                }
            }
        };
        if summary.stop == Some(solve::StopReason::Interrupted) {
            // As `Control::solve`: a raised flag is lowered when the call it stopped returns.
            self.interrupt.store(false, Ordering::Relaxed);
        }
        self.done = Some((summary, Some(f.solver)));
    }

    /// Discards the current model and lets the search go on (starting it if it has not
    /// started).
    pub fn resume(&mut self) {
        if !self.started {
            self.start();
        } else if self.current.take().is_some() && self.mode.yield_models {
            let _ = self.go.send(true);
        }
    }

    /// Waits up to `timeout` (forever: `None`) for the next result, a model or the end of the
    /// search; true when one is there.
    pub fn wait(&mut self, timeout: Option<Duration>) -> bool {
        self.start();
        if self.current.is_some() || self.done.is_some() {
            return true;
        }
        self.receive(timeout)
    }

    /// Waits for the next result: the current model, or `None` once the search is over.
    pub fn model(&mut self) -> Option<&solve::Model> {
        self.wait(None);
        self.current.as_ref()
    }

    /// clingo's `__next__`: [`Search::resume`], then [`Search::model`].
    pub fn next_model(&mut self) -> Option<&solve::Model> {
        self.resume();
        self.model()
    }

    /// Waits for the next result and answers the call's result so far: the final summary
    /// once the search is over, else (a model is current) satisfiable and not exhausted.
    pub fn get(&mut self) -> Summary {
        self.wait(None);
        match &self.done {
            Some((summary, _)) => summary.clone(),
            None => Summary {
                outcome: solve::Outcome::Satisfiable,
                exhausted: false,
                search_exhausted: false,
                optimum_proven: false,
                stop: None,
                stats: solve::Stats::default(),
                models: self.seen,
                core: None,
            },
        }
    }

    /// True once the search is over.
    pub fn is_finished(&self) -> bool {
        self.done.is_some()
    }

    /// Stops the search (clingo's `cancel`) and waits for its end: the result is interrupted
    /// unless the search was already over.
    pub fn cancel(&mut self) -> Summary {
        if self.done.is_none() {
            self.cancelled.store(true, Ordering::Relaxed);
            self.interrupt.store(true, Ordering::Relaxed);
            // Unblocks a thread waiting for its first request or for `resume`.
            let _ = self.go.send(false);
            self.current = None;
            while self.done.is_none() {
                self.receive(None);
                self.current = None;
            }
            // The flag is lowered even when the search ended on its own meanwhile.
            self.interrupt.store(false, Ordering::Relaxed);
        }
        self.current = None;
        self.done.as_ref().expect("finished").0.clone()
    }
}

impl Drop for Search {
    /// A search dropped without `end_search` stops (its solver is lost to the Control, which
    /// stays busy).
    fn drop(&mut self) {
        if self.done.is_none() {
            self.cancelled.store(true, Ordering::Relaxed);
            self.interrupt.store(true, Ordering::Relaxed);
            let _ = self.go.send(false);
        }
    }
}

/// A solve call read one model at a time (clingo's `SolveHandle`), from
/// [`Control::solve_handle`]; dropping it cancels the search and gives the solver back.
pub struct SolveHandle<'a> {
    ctl: &'a mut Control,
    search: Option<Search>,
}

impl SolveHandle<'_> {
    fn search(&mut self) -> &mut Search {
        self.search.as_mut().expect("present until dropped")
    }

    /// Discards the current model; the search goes on.
    pub fn resume(&mut self) {
        self.search().resume();
    }

    /// Waits up to `timeout` (`None`: forever) for a model or the end; true when one is there.
    pub fn wait(&mut self, timeout: Option<Duration>) -> bool {
        self.search().wait(timeout)
    }

    /// The current model (waiting for it), `None` once the search is over.
    pub fn model(&mut self) -> Option<Model<'_>> {
        let SolveHandle { ctl, search } = self;
        let raw = search.as_mut().expect("present").model()?;
        Some(Model {
            raw,
            names: ctl.names(),
            lazy_support: None,
            full: Default::default(),
        })
    }

    /// The next model (clingo's iteration: `resume`, then `model`).
    pub fn next_model(&mut self) -> Option<Model<'_>> {
        self.search().resume();
        self.model()
    }

    /// The result so far (see [`Search::get`]).
    pub fn get(&mut self) -> Summary {
        self.search().get()
    }

    /// Stops the search and answers the call's summary.
    pub fn cancel(&mut self) -> Summary {
        self.search().cancel()
    }
}

impl Iterator for SolveHandle<'_> {
    type Item = OwnedModel;

    /// The next model, copied ([`SolveHandle::next_model`] borrows it instead).
    fn next(&mut self) -> Option<OwnedModel> {
        self.next_model().map(|m| m.to_owned_model())
    }
}

impl Drop for SolveHandle<'_> {
    fn drop(&mut self) {
        if let Some(search) = self.search.take() {
            self.ctl.end_search(search);
        }
    }
}
