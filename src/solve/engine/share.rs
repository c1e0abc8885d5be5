//! Learnt-clause exchange between the engines of a portfolio (`solve::portfolio`): each engine
//! exports its short, low-LBD learnt clauses and imports the others' at restarts.
//!
//! The engines solve the same translated program, built by the same steps in the same order, so
//! the variables that the translation creates are created in the same order by every engine:
//! the k-th of them has the *shared id* k everywhere, whatever local index the engine gave it
//! (indices differ once retired variables are reused). Variables a solver makes for one call
//! (guards, bound and CR auxiliaries: `Engine::new_private_var`) have no shared id, and a
//! clause mentioning one is never exported.
//!
//! Invariants:
//! - Only clauses that are consequences of the permanent constraints are exported: learnt
//!   clauses over shared variables. A learnt clause that used a call's constraint mentions the
//!   call's guard (an assumption, never a level-0 fact while in use), hence a private variable.
//!   Assumptions (externals, the caller's, a portfolio cube) sit on decision levels, so clauses
//!   depending on them name them.
//! - Imports happen at decision level 0 only (search start and restarts), where a clause is
//!   simplified against level-0 facts and attached as a learnt clause (or assigned as a unit).
//! - The hub is lock-light: one mutex per engine's inbox, taken once per flush and per import;
//!   an inbox over `INBOX_CAP` words drops what arrives, so a slow reader never stalls writers.

use super::*;
use std::sync::Mutex;

/// No shared id / no local variable.
const NONE: u32 = u32::MAX;
/// Words an inbox may hold before it drops new clauses.
const INBOX_CAP: usize = 1 << 20;
/// Outbox words that trigger a flush outside restarts.
const FLUSH_WORDS: usize = 4096;

/// Which learnt clauses are exported: units always, others up to this length and LBD. Measured
/// on three unsatisfiable rows (colouring, disjunctive colouring, pigeons; conflicts per thread
/// at -t 2 over conflicts at -t 1): LBD <= 3 gave 0.97, 0.98, 0.73; <= 8 gave 0.69, 0.64,
/// 0.63; <= 12 gave 0.72, 0.63, 0.56; <= 30 gave 0.67, 0.59, 0.73.
pub const SHARE_MAX_LEN: usize = 32;
/// See [`SHARE_MAX_LEN`].
pub const SHARE_MAX_LBD: u32 = 8;

/// The exchange between the engines of one portfolio: one inbox per engine, holding clauses
/// over shared literal codes as `[len, lbd, lits...]` records.
#[derive(Debug)]
pub struct Hub {
    inboxes: Vec<Mutex<Vec<u32>>>,
    /// Clauses exported, over all engines (statistics).
    pub exported: AtomicU64,
    /// Clauses imported and kept, over all engines (statistics).
    pub imported: AtomicU64,
    /// Off when the engines' shared numberings disagree (a safety net): nothing is exchanged.
    pub enabled: AtomicBool,
}

impl Hub {
    /// A hub for `n` engines.
    pub fn new(n: usize) -> Hub {
        Hub {
            inboxes: (0..n).map(|_| Mutex::new(Vec::new())).collect(),
            exported: AtomicU64::new(0),
            imported: AtomicU64::new(0),
            enabled: AtomicBool::new(true),
        }
    }
}

use std::sync::atomic::AtomicU64;

/// An engine's connection to a hub.
pub(super) struct Link {
    hub: Arc<Hub>,
    /// This engine's inbox.
    me: usize,
    /// Records waiting to be flushed.
    outbox: Vec<u32>,
    /// Scratch for imports.
    inbox: Vec<u32>,
}

/// The engine's part for clause sharing: the shared numbering and the link.
#[derive(Default)]
pub(super) struct Sharing {
    /// Per variable: its shared id, or `NONE` for private variables.
    id: Vec<u32>,
    /// Per shared id: the local variable index, or `NONE` once retired.
    var_of: Vec<u32>,
    /// The hub, in a portfolio.
    link: Option<Link>,
}

impl Engine {
    /// Creates a variable that is private to this engine (for one call's constraints): clauses
    /// mentioning it are never exported, and it takes no shared id.
    pub fn new_private_var(&mut self) -> Var {
        let v = self.alloc_var();
        self.share_numbering(v, false);
        v
    }

    /// Gives `v` (just allocated) the next shared id, or marks it private.
    pub(super) fn share_numbering(&mut self, v: Var, shared: bool) {
        let s = &mut self.share;
        if s.id.len() <= v.index() {
            s.id.resize(v.index() + 1, NONE);
        }
        if shared {
            s.id[v.index()] = s.var_of.len() as u32;
            s.var_of.push(v.index() as u32);
        } else {
            s.id[v.index()] = NONE;
        }
    }

    /// Forgets the shared id of a retired variable.
    pub(super) fn unshare(&mut self, v: Var) {
        let s = &mut self.share;
        if let Some(&id) = s.id.get(v.index()) {
            if id != NONE {
                s.var_of[id as usize] = NONE;
                s.id[v.index()] = NONE;
            }
        }
    }

    /// How many shared ids were given out (equal in every engine of a portfolio after the
    /// same steps).
    pub fn shared_vars(&self) -> usize {
        self.share.var_of.len()
    }

    /// The shared code (`id << 1 | negative`) of a literal over a shared variable.
    pub fn shared_code(&self, l: Lit) -> Option<u32> {
        let id = self.share.id.get(l.var().index()).copied().unwrap_or(NONE);
        (id != NONE).then_some(id << 1 | l.is_neg() as u32)
    }

    /// The local literal of a shared code, if its variable exists here.
    pub fn local_lit(&self, code: u32) -> Option<Lit> {
        let v = self.share.var_of.get((code >> 1) as usize).copied()?;
        (v != NONE).then(|| Lit::new(Var::new(v as usize), code & 1 == 0))
    }

    /// How good a variable is to split the search on: its activity, then its occurrences.
    pub fn split_score(&self, v: Var) -> f64 {
        self.heur.activity[v.index()] * 1e6 + f64::from(self.heur.occ[v.index()])
    }

    /// Connects this engine to `hub` as its engine number `me` (or disconnects it).
    pub fn connect(&mut self, hub: Option<(Arc<Hub>, usize)>) {
        self.share.link = hub.map(|(hub, me)| Link {
            hub,
            me,
            outbox: Vec::new(),
            inbox: Vec::new(),
        });
    }

    /// Queues a learnt clause for export when it is short, of low LBD and over shared
    /// variables only.
    pub(super) fn export_learnt(&mut self, lits: &[Lit], lbd: u32) {
        let Some(link) = self.share.link.as_mut() else {
            return;
        };
        if lits.len() > 1 && (lits.len() > SHARE_MAX_LEN || lbd > SHARE_MAX_LBD) {
            return;
        }
        let start = link.outbox.len();
        link.outbox.push(lits.len() as u32);
        link.outbox.push(lbd);
        for &l in lits {
            let id = self.share.id.get(l.var().index()).copied().unwrap_or(NONE);
            if id == NONE {
                link.outbox.truncate(start);
                return;
            }
            link.outbox.push(id << 1 | l.is_neg() as u32);
        }
        if link.outbox.len() >= FLUSH_WORDS {
            self.flush_exports();
        }
    }

    /// Hands the queued clauses to the other engines' inboxes.
    pub(super) fn flush_exports(&mut self) {
        let Some(link) = self.share.link.as_mut() else {
            return;
        };
        if link.outbox.is_empty() {
            return;
        }
        if link.hub.enabled.load(Ordering::Relaxed) {
            let mut n = 0u64;
            let mut i = 0;
            while i < link.outbox.len() {
                n += 1;
                i += 2 + link.outbox[i] as usize;
            }
            link.hub.exported.fetch_add(n, Ordering::Relaxed);
            for (k, inbox) in link.hub.inboxes.iter().enumerate() {
                if k == link.me {
                    continue;
                }
                let mut q = inbox.lock().unwrap_or_else(|e| e.into_inner());
                if q.len() + link.outbox.len() <= INBOX_CAP {
                    q.extend_from_slice(&link.outbox);
                }
            }
        }
        link.outbox.clear();
    }

    /// At level 0: flushes this engine's exports and adds the clauses the others sent.
    /// Returns false when an imported clause made the problem inconsistent.
    pub(super) fn exchange(&mut self) -> bool {
        debug_assert_eq!(self.decision_level(), 0);
        self.flush_exports();
        let Some(link) = self.share.link.as_mut() else {
            return true;
        };
        let mut inbox = std::mem::take(&mut link.inbox);
        {
            let mut q = link.hub.inboxes[link.me]
                .lock()
                .unwrap_or_else(|e| e.into_inner());
            std::mem::swap(&mut *q, &mut inbox);
        }
        let enabled = link.hub.enabled.load(Ordering::Relaxed);
        let mut kept = 0u64;
        let mut ok = true;
        let mut c: Vec<Lit> = Vec::new();
        let mut i = 0;
        while enabled && ok && i < inbox.len() {
            let len = inbox[i] as usize;
            let lbd = inbox[i + 1];
            let rec = &inbox[i + 2..i + 2 + len];
            i += 2 + len;
            c.clear();
            let mut satisfied = false;
            for &code in rec {
                let id = (code >> 1) as usize;
                let v = self.share.var_of.get(id).copied().unwrap_or(NONE);
                if v == NONE || self.pool.retired[v as usize] {
                    satisfied = true; // unknown here: skip the clause
                    break;
                }
                let l = Lit::new(Var::new(v as usize), code & 1 == 0);
                match self.val(l) {
                    1 => {
                        satisfied = true;
                        break;
                    }
                    -1 => {}
                    _ => c.push(l),
                }
            }
            if satisfied {
                continue;
            }
            c.sort_unstable();
            c.dedup();
            if c.windows(2).any(|w| w[0] == !w[1]) {
                continue;
            }
            kept += 1;
            match c.len() {
                0 => {
                    self.inconsistent = true;
                    ok = false;
                }
                1 => {
                    self.assign(c[0], Reason::Decision);
                    if self.propagate().is_some() {
                        self.inconsistent = true;
                        ok = false;
                    }
                }
                _ => {
                    self.attach(&c, true, lbd.max(1));
                }
            }
        }
        inbox.clear();
        if let Some(link) = self.share.link.as_mut() {
            link.hub.imported.fetch_add(kept, Ordering::Relaxed);
            link.inbox = inbox;
        }
        ok
    }
}
