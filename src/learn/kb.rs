//! One-step worlds over AL_d knowledge bases, through the front door (`control::Control`): the
//! oracle (KB_full) and the learner's knowledge base (the `learner` profile plus the learned
//! axioms, rendered as AL_d statements).
//!
//! The description is translated once per set of learned axioms and grounded once, with the
//! step-0 observations `obs(relation(on, X, L), true, 0)`, `obs(in_hand(R, X), true, 0)` and the
//! action record `hpd(A, 0)` declared external; a trial is one solve under assumptions. The
//! state read back is the observable vocabulary (`relation` and `in_hand`) at steps 0 and 1,
//! through atom numbers looked up once: at step 0 every positive literal and the negative ones
//! that mention a constant of the action (all that 5.1, 5.5 and 5.9 read: see
//! [`States::before`]), at step 1 only the positive literals (all that 5.1 compares), and no
//! step-0 state for the oracle (`read_before`).
//!
//! A trial asks for one answer set (the solver stops at the first cardinality-minimal one) and
//! the program shows no atoms (`#show.`): the observables are read by atom number, so no model
//! is rendered as text. A [`Cache`] shared between runs remembers answers by (knowledge base,
//! step-0 facts, action); the H1 runs share one for the oracle and one for the learner.
//!
//! Invariants: the program a trial solves is exactly the translation of the description (plus
//! the external declarations); a trial never re-grounds; CR rules are applied
//! cardinality-minimally as in docs/domain.md 3.4. The cache assumes what these programs guarantee:
//! a complete step-0 state and deterministic laws give at most one answer set, so an answer is a
//! function of the program text, the facts and the action (observed: no solve of the 4341 of
//! seed 0's run had a second model; docs/bench/h1.md).

// hashbrown's default hasher (foldhash) rather than std's SipHash: interning the ~1000
// literals of each answer was 10% of a learning run's time (docs/bench/h1.md).
use hashbrown::HashMap;
use std::sync::{Arc, Mutex};

use crate::action::{self, ast::Description, Options};
use crate::base::SourceMap;
use crate::control::{AtomId, Control, ControlConfig, Part, SolveOptions, Symbol, TruthValue};

use super::episode::{LearnerKb, States, World};
use super::term::{Axiom, Literal, Term, IN_HAND, RELATION};

/// The external declarations added to the translated program.
const EXTERNALS: &str = "\
#external obs(relation(on, X, Y), true, 0) : object(X), location(Y).
#external obs(in_hand(R, X), true, 0) : robot(R), object(X).
#external hpd(A, 0) : action(A).
#show.
";

/// A knowledge base to run trials against.
#[derive(Clone, Debug)]
pub struct KbSpec {
    /// The loaded description (includes resolved).
    pub description: Description,
    /// Profile and switches.
    pub options: Options,
    /// The sources, for parsing learned axioms and rendering diagnostics.
    pub sources: SourceMap,
}

/// Why a knowledge base could not be built.
#[derive(Clone, Debug, thiserror::Error)]
pub enum KbError {
    /// The description (with the learned axioms) did not translate.
    #[error("the description does not translate: {0}")]
    Translate(String),
    /// Grounding failed.
    #[error("grounding failed: {0}")]
    Ground(String),
}

/// Answers of one-step worlds over knowledge bases, shared between runs and threads: literals
/// are interned, an answer is kept as literal numbers.
#[derive(Debug, Default)]
pub struct Cache {
    /// The tables, behind one lock (two threads contend rarely: a lookup is short).
    inner: Mutex<CacheTables>,
}

/// A cached answer: the step-0 literals, if executable the step-1 literals, and whether the
/// world could not realise the state (`States::unrealisable`).
type Answer = (Vec<u32>, Option<Vec<u32>>, bool);

/// An answer of a [`KbWorld`] as numbers of its observables: the step-0 ones and, if the action
/// is executable, the step-1 ones.
type Indices = (Vec<u32>, Option<Vec<u32>>);

#[derive(Debug, Default)]
struct CacheTables {
    /// Interned literals.
    lits: Vec<Literal>,
    /// Literal to its number.
    ids: HashMap<Literal, u32>,
    /// Knowledge-base keys (program text and reading mode) to their numbers.
    kbs: HashMap<String, u32>,
    /// (knowledge base, sorted facts, action) to the answer.
    answers: HashMap<(u32, Vec<u32>, u32), Answer>,
    /// Lookups that found an answer, and lookups in all.
    hits: usize,
    lookups: usize,
}

impl CacheTables {
    fn intern(&mut self, lit: &Literal) -> u32 {
        if let Some(&i) = self.ids.get(lit) {
            return i;
        }
        let i = self.lits.len() as u32;
        self.lits.push(lit.clone());
        self.ids.insert(lit.clone(), i);
        i
    }

    fn key(&mut self, kb: u32, facts: &[Literal], action: &Literal) -> (u32, Vec<u32>, u32) {
        let mut f: Vec<u32> = facts.iter().map(|l| self.intern(l)).collect();
        f.sort_unstable();
        (kb, f, self.intern(action))
    }
}

impl Cache {
    /// An empty cache.
    pub fn new() -> Arc<Cache> {
        Arc::new(Cache::default())
    }

    /// The number of a knowledge base given by its key text.
    fn kb(&self, key: String) -> u32 {
        let mut t = self.inner.lock().expect("cache lock");
        let n = t.kbs.len() as u32;
        *t.kbs.entry(key).or_insert(n)
    }

    fn get(&self, kb: u32, facts: &[Literal], action: &Literal) -> Option<States> {
        let mut t = self.inner.lock().expect("cache lock");
        t.lookups += 1;
        let key = t.key(kb, facts, action);
        let (before, after, unrealisable) = t.answers.get(&key)?;
        let lits = |ids: &[u32]| -> Vec<Literal> {
            ids.iter().map(|&i| t.lits[i as usize].clone()).collect()
        };
        let states = States {
            before: lits(before),
            after: after.as_deref().map(lits),
            unrealisable: *unrealisable,
        };
        t.hits += 1;
        Some(states)
    }

    fn put(&self, kb: u32, facts: &[Literal], action: &Literal, states: &States) {
        let mut t = self.inner.lock().expect("cache lock");
        let key = t.key(kb, facts, action);
        let before = states.before.iter().map(|l| t.intern(l)).collect();
        let after = states
            .after
            .as_ref()
            .map(|a| a.iter().map(|l| t.intern(l)).collect());
        t.answers.insert(key, (before, after, states.unrealisable));
    }

    /// Stores an answer given as literal numbers from [`Cache::intern_all`].
    fn put_ids(&self, kb: u32, facts: &[Literal], action: &Literal, answer: Answer) {
        let mut t = self.inner.lock().expect("cache lock");
        let key = t.key(kb, facts, action);
        t.answers.insert(key, answer);
    }

    /// The numbers of `lits` in this cache (interned once per knowledge base, so an answer is
    /// stored without hashing its literals).
    fn intern_all<'a>(&self, lits: impl Iterator<Item = &'a Literal>) -> Vec<u32> {
        let mut t = self.inner.lock().expect("cache lock");
        lits.map(|l| t.intern(l)).collect()
    }

    /// Lookups that found an answer, and lookups in all.
    pub fn hits(&self) -> (usize, usize) {
        let t = self.inner.lock().expect("cache lock");
        (t.hits, t.lookups)
    }
}

/// A one-step world over a knowledge base.
pub struct KbWorld {
    /// The knowledge base's description and options.
    spec: KbSpec,
    /// The grounded program.
    ctl: Control,
    /// The observable literals.
    observables: Vec<Observable>,
    /// The constants of the observables, each with its bit in [`Observable::mentions`] (the
    /// first 64; a literal with a later one has every bit set, so it is always read).
    constants: HashMap<String, u32>,
    /// Solve calls so far.
    pub solves: usize,
    /// Whether [`World::step`] computes the step-0 state when the action is not executable
    /// (the learner needs it for relevant literals; the oracle does not).
    pub need_before: bool,
    /// Whether answers carry the step-0 state at all (the oracle's is never read, 5.1).
    pub read_before: bool,
    /// The shared cache, this knowledge base's number in it, and the cache's number of every
    /// observable.
    cache: Option<(Arc<Cache>, u32, Vec<u32>)>,
    /// The learned axioms' text, part of the cache key.
    learned_text: String,
}

/// An observable literal of a knowledge base: `holds(lit, step)` is atom `atom`.
struct Observable {
    atom: AtomId,
    lit: Literal,
    step: u8,
    /// One bit per constant in an entity position of `lit` (see [`KbWorld::constants`]).
    mentions: u64,
}

/// The bits of the constants in the entity positions of `lit`; a constant not in `constants`
/// is added while bits last, else every bit is set.
fn mention_bits(lit: &Literal, constants: &mut HashMap<String, u32>) -> u64 {
    let mut bits = 0u64;
    for i in lit.entity_positions() {
        if let Term::Const(c) = &lit.args[i] {
            let n = constants.len() as u32;
            let b = *constants.entry(c.clone()).or_insert(n);
            bits |= if b < 64 { 1 << b } else { u64::MAX };
        }
    }
    bits
}

/// `Symbol` to the learner's literal (constants and numbers only).
pub fn literal_of(sym: &Symbol) -> Option<Literal> {
    let name = sym.name()?.to_string();
    let args = sym
        .args()
        .iter()
        .map(|a| match a {
            Symbol::Function { name, args, .. } if args.is_empty() => {
                Some(Term::Const(name.to_string()))
            }
            Symbol::Number(n) => Some(Term::Const(n.to_string())),
            _ => None,
        })
        .collect::<Option<Vec<Term>>>()?;
    Some(Literal {
        positive: !sym.is_negative(),
        name,
        args,
    })
}

/// The learner's ground literal as a `Symbol` (its sign ignored).
pub fn symbol_of(lit: &Literal) -> Symbol {
    Symbol::function(
        lit.name.clone(),
        lit.args
            .iter()
            .map(|t| match t {
                Term::Const(c) => Symbol::constant(c.clone()),
                Term::Var(v) => Symbol::constant(v.to_string()),
            })
            .collect(),
    )
}

impl KbWorld {
    /// Translates and grounds the knowledge base with these learned axioms.
    pub fn new(spec: KbSpec, learned: &[(String, Axiom)]) -> Result<KbWorld, KbError> {
        let sources = spec.sources.clone();
        // The learned axioms' text is a cache key only; the statements are built as values.
        let text: String = learned
            .iter()
            .map(|(label, a)| format!("{label}: {}.\n", a.to_ald()))
            .collect();
        let mut description = spec.description.clone();
        description
            .statements
            .extend(learned.iter().map(|(label, axiom)| axiom.statement(label)));
        let translation = action::translate(&description, &spec.options);
        if translation.has_errors() {
            return Err(KbError::Translate(format!("{:?}", translation.diagnostics)));
        }
        let mut config = ControlConfig::default();
        config.solve.models = 1;
        // Answers are read by atom number: no model needs its supporting rules.
        config.solve.supports = false;
        let mut ctl = Control::with_sources(config, sources);
        ctl.add_program(translation.program)
            .map_err(|e| KbError::Ground(e.message))?;
        ctl.add_source("<learn externals>", EXTERNALS)
            .map_err(|e| KbError::Ground(e.message))?;
        ctl.ground(&[Part::base()])
            .map_err(|e| KbError::Ground(e.message))?;
        let mut observables = Vec::new();
        let mut constants = HashMap::new();
        for a in ctl.symbolic_atoms() {
            let s = &a.symbol;
            if s.name() != Some("holds") || s.args().len() != 2 {
                continue;
            }
            let Some(step) = s.args()[1].as_number() else {
                continue;
            };
            let Some(mut lit) = literal_of(&s.args()[0]) else {
                continue;
            };
            if lit.name != RELATION && lit.name != IN_HAND {
                continue;
            }
            lit.positive = !s.is_negative();
            let mentions = mention_bits(&lit, &mut constants);
            observables.push(Observable {
                atom: a.atom,
                lit,
                step: step as u8,
                mentions,
            });
        }
        Ok(KbWorld {
            spec,
            ctl,
            observables,
            constants,
            solves: 0,
            need_before: true,
            read_before: true,
            cache: None,
            learned_text: text,
        })
    }

    /// Shares answers through `cache` from now on (also after [`LearnerKb::set_learned`]).
    pub fn use_cache(&mut self, cache: Arc<Cache>) {
        // The key: everything the answers depend on. The description is the same for every
        // world sharing a cache (one experiment); options, learned axioms and the reading mode
        // tell the knowledge bases apart.
        let key = format!(
            "{:?}|{}|{}|{}",
            self.spec.options, self.need_before, self.read_before, self.learned_text
        );
        let n = cache.kb(key);
        let ids = cache.intern_all(self.observables.iter().map(|o| &o.lit));
        self.cache = Some((cache, n, ids));
    }

    /// Solves under the facts (and the action when `occurs`): the numbers of the last model's
    /// observables read at steps 0 and 1 (step 0: every positive literal and the negative ones
    /// mentioning a constant of the action; step 1: the positive ones), or `None` without an
    /// answer set.
    fn solve(
        &mut self,
        facts: &[Literal],
        action: &Literal,
        occurs: bool,
    ) -> Option<(Vec<u32>, Vec<u32>)> {
        let obs = |l: &Literal| {
            Symbol::function(
                "obs",
                vec![symbol_of(l), Symbol::constant("true"), Symbol::number(0)],
            )
        };
        // The trial's facts and action are set as external values for this call and reset
        // after it. (Assumptions would do the same; at control 6658570 a positive assumption
        // on an external atom made every call unsatisfiable, so values are assigned.)
        let mut set: Vec<Symbol> = facts.iter().map(obs).collect();
        if occurs {
            set.push(Symbol::function(
                "hpd",
                vec![symbol_of(action), Symbol::number(0)],
            ));
        }
        for s in &set {
            self.ctl.assign_external(s, TruthValue::True);
        }
        // The action's constants: a negative step-0 literal is read when it mentions one.
        let wanted_negative: u64 = action
            .args
            .iter()
            .filter_map(|t| match t {
                Term::Const(c) => self.constants.get(c),
                Term::Var(_) => None,
            })
            .fold(0, |bits, &b| bits | if b < 64 { 1 << b } else { u64::MAX });
        let options = SolveOptions::default();
        let observables = &self.observables;
        let read_before = self.read_before;
        let mut last: Option<(Vec<u32>, Vec<u32>)> = None;
        self.solves += 1;
        self.ctl.solve(&options, |m| {
            let (mut s0, mut s1) = (Vec::new(), Vec::new());
            for (i, o) in observables.iter().enumerate() {
                let wanted = if o.step == 0 {
                    read_before && (o.lit.positive || o.mentions & wanted_negative != 0)
                } else {
                    // Step 1: only the positive literals, all that 5.1 compares.
                    o.lit.positive
                };
                if wanted && m.holds(o.atom) {
                    if o.step == 0 {
                        s0.push(i as u32);
                    } else {
                        s1.push(i as u32);
                    }
                }
            }
            last = Some((s0, s1));
            true
        });
        for s in &set {
            self.ctl.assign_external(s, TruthValue::False);
        }
        last
    }

    /// The literals of observables given by number.
    fn literals(&self, indices: &[u32]) -> Vec<Literal> {
        indices
            .iter()
            .map(|&i| self.observables[i as usize].lit.clone())
            .collect()
    }

    /// The knowledge base's spec.
    pub fn spec(&self) -> &KbSpec {
        &self.spec
    }
}

impl World for KbWorld {
    fn step(&mut self, facts: &[Literal], action: &Literal) -> States {
        if let Some((cache, kb, _)) = &self.cache {
            if let Some(s) = cache.get(*kb, facts, action) {
                return s;
            }
        }
        let (before, after) = self.step_uncached(facts, action);
        if let Some((cache, kb, ids)) = &self.cache {
            let number = |v: &[u32]| -> Vec<u32> { v.iter().map(|&i| ids[i as usize]).collect() };
            let answer = (number(&before), after.as_deref().map(number), false);
            cache.put_ids(*kb, facts, action, answer);
        }
        States {
            before: self.literals(&before),
            after: after.map(|a| self.literals(&a)),
            unrealisable: false,
        }
    }
}

/// Any one-step world whose answers are a function of (facts, action), answering through a
/// [`Cache`] (the physics oracle: `learn::physics`).
pub struct CachedWorld<W> {
    /// The world.
    pub inner: W,
    /// The cache and the world's number in it.
    cache: Arc<Cache>,
    kb: u32,
}

impl<W: World> CachedWorld<W> {
    /// `inner` answering through `cache`, under `key` (distinct for distinct worlds).
    pub fn new(inner: W, cache: Arc<Cache>, key: &str) -> CachedWorld<W> {
        let kb = cache.kb(format!("world|{key}"));
        CachedWorld { inner, cache, kb }
    }
}

impl<W: World> World for CachedWorld<W> {
    fn step(&mut self, facts: &[Literal], action: &Literal) -> States {
        if let Some(s) = self.cache.get(self.kb, facts, action) {
            return s;
        }
        let states = self.inner.step(facts, action);
        self.cache.put(self.kb, facts, action, &states);
        states
    }
}

impl KbWorld {
    /// [`World::step`] by solving, as observable numbers.
    fn step_uncached(&mut self, facts: &[Literal], action: &Literal) -> Indices {
        match self.solve(facts, action, true) {
            Some((before, after)) => (before, Some(after)),
            None => {
                let before = if self.need_before {
                    self.solve(facts, action, false)
                        .map(|(b, _)| b)
                        .unwrap_or_default()
                } else {
                    Vec::new()
                };
                (before, None)
            }
        }
    }
}

impl LearnerKb for KbWorld {
    fn set_learned(&mut self, axioms: &[(String, Axiom)]) {
        let (solves, need_before, read_before) = (self.solves, self.need_before, self.read_before);
        let cache = self.cache.take();
        match KbWorld::new(self.spec.clone(), axioms) {
            Ok(w) => {
                *self = w;
                self.solves = solves;
                self.need_before = need_before;
                self.read_before = read_before;
                if let Some((c, _, _)) = cache {
                    self.use_cache(c);
                }
            }
            // The learned axioms are built from the learner's own vocabulary; a failure here is
            // a bug in rendering, not bad input.
            Err(e) => panic!("learned axioms do not load: {e}"),
        }
    }
}
