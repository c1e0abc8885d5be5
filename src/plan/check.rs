//! Plan checks independent of the planner's search (docs/domain.md 4.3).
//!
//! [`StateSearch`] holds the one-step transition program of a description: its history
//! removed, translated at horizon 1 with `horizon_mode = transition` (exactly one action at
//! step 0, the goal evaluated at both steps), and the state at step 0 given by externals
//! (`#external init(F) : inertial_fluent(F).  holds(F, 0) :- init(F).`); the D0 default makes
//! every other inertial fluent false. So one grounding serves every state: a transition is a
//! solve call with the state's externals set. CR rules are turned into free choices
//! (`h :- B, cr_appl(l).  {cr_appl(l)} :- B.`) so that each action's own least number of
//! applications can be read from its answer sets, where the solver's cardinality-minimal
//! semantics would minimize across actions.
//!
//! - [`replay`] executes a plan one transition at a time from the description's initial state
//!   and reports where it fails (no answer set for the action: not executable, or an object
//!   would become unstable), whether the goal holds at the end, and its CR count.
//! - [`StateSearch::minimal`] is a best-first search (A*) over states for the least
//!   (length, CR count) in lexicographic order: L* and E*. Each state is expanded by one solve
//!   call, remembered per state ([`StateSearch::stats`] counts them), so replays and searches
//!   over one description share their transitions. The search is ordered by g + h, where h is
//!   a lower bound on the actions still needed ([`Bound`], from the executability conditions
//!   E1, E5 and E7 of KB_full), and nothing with g + h past the depth bound is expanded. With
//!   h = 0 it is the breadth-first search of the first version (kept as
//!   [`StateSearch::minimal_blind`], the reference the tests compare against).
//! - [`classify`] combines them: incorrect if the replay fails or misses the goal, optimal iff
//!   the plan's length is L* and its CR count E*, sub-optimal otherwise.
//!
//! Invariants: a state is the set of inertial fluents true at a step, less those exempt from
//! D0 (such as `partially_stable`, which nothing makes false, so it would only record the
//! path); the search stops with `None` past its depth or state budget, never with a wrong
//! answer. The bound is used only when the description keeps E1, E5 and E7 with KB_full's text
//! and its only actions are `pickup/2` and `putdown/3` (what its argument rests on); each
//! expansion checks it against the transitions just computed (h(s) <= 1 + h(s') on every
//! edge, 0 at goal states), and a violation restarts the search without it.

use std::cmp::Reverse;
use std::collections::{BTreeMap, BTreeSet, BinaryHeap, HashMap};
use std::rc::Rc;

use super::search::{control, translate};
use super::{PlanConfig, PlanError};
use crate::action::ast::{Description, StatementKind};
use crate::action::{HorizonMode, Switches};
use crate::base::SourceMap;
use crate::control::{AtomId, Control, Model, OwnedModel, Part, SolveOptions, Symbol, TruthValue};
use crate::syntax::ast::{self, Atom, Head, Literal, Program, RuleKind, Sign};

/// A state: the inertial fluents that hold, sorted.
pub type State = Vec<Symbol>;

/// One transition out of a state.
#[derive(Clone, Debug)]
pub struct Successor {
    /// The action.
    pub action: Symbol,
    /// The state after it.
    pub state: State,
    /// The least number of CR applications at the new state's step.
    pub cr_applied: usize,
    /// True when the goal holds in the new state.
    pub goal: bool,
    /// Objects unstable in the new state (`-holds(stable(A), 1)`).
    pub unstable: Vec<String>,
}

/// The one-step transition program over externals (see the module docs).
pub struct StateSearch {
    ctl: Control,
    /// The inertial fluents that make up a state.
    fluents: Vec<Symbol>,
    /// The atoms read from a transition's answer sets.
    atoms: Atoms,
    /// The initial state of the description.
    initial: State,
    /// CR applications needed in the initial state.
    initial_cr: usize,
    /// The goal holds in the initial state.
    initial_goal: bool,
    /// A state's fluent by its index in `fluents`.
    index: HashMap<Symbol, usize>,
    /// Full expansions, per state (as a bit set over `fluents`).
    memo: HashMap<Bits, Rc<Expansion>>,
    /// The lower bound of the search, when the description admits it.
    bound: Option<Bound>,
    /// What the searches did.
    stats: SearchStats,
}

/// A state as a bit set over [`StateSearch`]'s fluents.
type Bits = Vec<u64>;

/// An entry of the search's queue: f = (length + bound, CR count), the length (longer first
/// among equal f), the CR count and the state.
type Entry = ((usize, usize), Reverse<usize>, usize, Bits);

/// All transitions out of one state.
#[derive(Debug)]
struct Expansion {
    /// Per action and resulting state, the successor with the least CR count.
    succs: Vec<Successor>,
    /// The resulting states as bit sets, parallel to `succs`.
    keys: Vec<Bits>,
    /// The state's own least CR count and goal (`None`: no action executable).
    here: Option<(usize, bool)>,
}

/// Counters of [`StateSearch`]'s work, for reports.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SearchStats {
    /// Solve calls that expanded a state fully (each state once).
    pub expansions: usize,
    /// Solve calls for one action of a state (replays of states not expanded).
    pub single_actions: usize,
    /// Expansions answered from memory.
    pub reused: usize,
    /// Times the bound was contradicted by a transition and the search restarted without it.
    pub bound_violations: usize,
}

/// How a fluent of the state enters the bound.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Role {
    Other,
    /// `in_hand(R, x)`.
    InHand(usize),
    /// `relation(below, x, b)`: b must be picked up before x can be (E7).
    Below(usize, usize),
    /// `relation(on, x, y)`.
    On(usize, usize),
}

/// A goal literal the bound understands (objects by index).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum GoalLit {
    /// `relation(on, x, y)`.
    On(usize, usize),
    /// `in_hand(R, x)`.
    InHand(usize),
}

/// A lower bound on the actions a state still needs to reach the goal, for descriptions with
/// KB_full's E1, E5 and E7 and only the actions `pickup(R, A)` and `putdown(R, A, L)`.
///
/// The argument, per goal literal (the bound is the largest): `relation(below, x, b)` in the
/// state forbids `pickup(x)` (E7) and only `pickup(b)` makes it false (C4; `pickup(x)` itself
/// is impossible); `relation(on, c, y)`, with `relation(below, y, c)`, forbids putting x on
/// y (E1, unless y is the location E1 exempts) until `pickup(c)`, which needs the objects above
/// c picked up first. Every object in that set M (x aside) is picked up, and since a pickup
/// needs an empty hand (E5) and only a putdown empties it, each is also put down. So
/// `on(x, y)` needs 2|M| + 2 actions (x picked up and put down), one more if the hand holds
/// another object, or 1 if x is held and M is empty, 3 + 2|M| if x is held and M is not;
/// `in_hand(R, x)` needs 2|M| + 1, one more if the hand holds another object.
#[derive(Clone, Debug)]
struct Bound {
    /// Per fluent of the state.
    roles: Vec<Role>,
    /// The goal literals understood.
    goals: Vec<GoalLit>,
    /// The number of objects indexed.
    objects: usize,
    /// The location E1 exempts (`table`), by index.
    exempt: Option<usize>,
}

impl Bound {
    /// The bound for `desc` under `config` (see the type's docs), `None` when its argument
    /// does not apply.
    fn new(
        desc: &Description,
        sources: &SourceMap,
        config: &PlanConfig,
        fluents: &[Symbol],
    ) -> Option<Bound> {
        let checked = crate::action::check(
            desc,
            &crate::action::Options {
                profile: config.profile.clone(),
                overrides: config.overrides.clone(),
                ..Default::default()
            },
        );
        let mut actions: Vec<(String, usize)> = checked
            .decls
            .iter()
            .filter(|(_, d)| d.kind == crate::action::ast::DeclKind::Action)
            .map(|(n, d)| (n.clone(), d.params.len()))
            .collect();
        actions.sort();
        if actions != [("pickup".to_string(), 2), ("putdown".to_string(), 3)] {
            return None;
        }
        let norm = |span: crate::base::Span| -> String {
            let text: String = sources
                .get(span.file)
                .slice(span)
                .chars()
                .filter(|c| !c.is_whitespace())
                .collect();
            text.find("impossible")
                .map(|i| text[i..].to_string())
                .unwrap_or_default()
        };
        let active: Vec<String> = desc
            .statements
            .iter()
            .zip(&checked.active)
            .filter(|(_, a)| **a)
            .map(|(s, _)| norm(s.span))
            .collect();
        let has = |t: &str| active.iter().any(|a| a == t);
        if !has("impossiblepickup(R,A)ifin_hand(R,B).")
            || !has("impossiblepickup(R,A)ifrelation(below,A,B).")
        {
            return None;
        }
        let exempt = if has("impossibleputdown(R,A,B)ifrelation(on,C,B),C!=A,B!=table.") {
            Some(Symbol::constant("table"))
        } else if has("impossibleputdown(R,A,B)ifrelation(on,C,B),C!=A.") {
            None
        } else {
            return None;
        };
        let mut objects: HashMap<Symbol, usize> = HashMap::new();
        let mut id = |s: &Symbol| {
            let n = objects.len();
            *objects.entry(s.clone()).or_insert(n)
        };
        let mut robots = BTreeSet::new();
        let roles: Vec<Role> = fluents
            .iter()
            .map(|f| {
                let a = f.args();
                if f.is("in_hand", 2) {
                    robots.insert(a[0].clone());
                    Role::InHand(id(&a[1]))
                } else if f.is("relation", 3) && a[0].is("below", 0) {
                    Role::Below(id(&a[1]), id(&a[2]))
                } else if f.is("relation", 3) && a[0].is("on", 0) {
                    Role::On(id(&a[1]), id(&a[2]))
                } else {
                    Role::Other
                }
            })
            .collect();
        if robots.len() > 1 {
            return None;
        }
        let mut goals = Vec::new();
        for s in &desc.statements {
            let StatementKind::Goal { body } = &s.kind else {
                continue;
            };
            for item in body {
                let crate::action::ast::BodyItem::Lit(l) = item else {
                    continue;
                };
                let Some(g) = super::problem::symbol_of_atom(&l.atom) else {
                    continue;
                };
                let a = g.args();
                if l.negated {
                    continue;
                }
                if g.is("in_hand", 2) {
                    goals.push(GoalLit::InHand(id(&a[1])));
                } else if g.is("relation", 3) && a[0].is("on", 0) {
                    goals.push(GoalLit::On(id(&a[1]), id(&a[2])));
                }
            }
        }
        let exempt = exempt.map(|t| id(&t));
        Some(Bound {
            roles,
            goals,
            objects: objects.len(),
            exempt,
        })
    }

    /// The bound at the state `bits`.
    fn at(&self, bits: &Bits) -> usize {
        if self.goals.is_empty() {
            return 0;
        }
        let n = self.objects;
        let mut held = None;
        let mut below: Vec<Vec<usize>> = vec![Vec::new(); n];
        let mut on: BTreeSet<(usize, usize)> = BTreeSet::new();
        for (i, r) in self.roles.iter().enumerate() {
            if bits[i / 64] >> (i % 64) & 1 == 0 {
                continue;
            }
            match *r {
                Role::InHand(x) => held = Some(x),
                Role::Below(x, b) => below[x].push(b),
                Role::On(x, y) => {
                    on.insert((x, y));
                }
                Role::Other => {}
            }
        }
        let mut best = 0;
        for g in &self.goals {
            let need = match *g {
                GoalLit::InHand(x) => {
                    if held == Some(x) {
                        0
                    } else {
                        let m: BTreeSet<usize> =
                            below[x].iter().copied().filter(|&b| b != x).collect();
                        2 * m.len() + 1 + usize::from(held.is_some())
                    }
                }
                GoalLit::On(x, y) => {
                    if on.contains(&(x, y)) {
                        0
                    } else {
                        let mut m: BTreeSet<usize> = below[x].iter().copied().collect();
                        if Some(y) != self.exempt {
                            for &c in &below[y] {
                                if c != x && on.contains(&(c, y)) {
                                    m.insert(c);
                                    m.extend(below[c].iter().copied());
                                }
                            }
                        }
                        m.remove(&x);
                        if held == Some(x) {
                            if m.is_empty() {
                                1
                            } else {
                                3 + 2 * m.len()
                            }
                        } else {
                            2 * m.len() + 2 + usize::from(held.is_some())
                        }
                    }
                }
            };
            best = best.max(need);
        }
        best
    }
}

/// An atom of the transition program: its number, or true when grounding made it a fact.
#[derive(Clone, Copy, Debug)]
enum Lit {
    Atom(AtomId),
    Fact,
}

impl Lit {
    fn holds(self, m: &Model<'_>) -> bool {
        match self {
            Lit::Atom(a) => m.holds(a),
            Lit::Fact => true,
        }
    }
}

/// The atoms a transition's answer set is read through, looked up once after grounding.
#[derive(Clone, Debug, Default)]
struct Atoms {
    /// `holds(f, 1)` for the state fluent `fluents[i]`.
    next: Vec<(usize, Lit)>,
    /// `occurs(a, 0)`.
    actions: Vec<(Symbol, Lit)>,
    /// `cr_appl(l)` with the step of `l`.
    cr: Vec<(i32, Lit)>,
    /// `goal(0)` and `goal(1)`.
    goal: [Option<Lit>; 2],
    /// `-holds(stable(a), 1)` with `a`.
    unstable: Vec<(String, Lit)>,
}

impl Atoms {
    fn new(ctl: &Control, fluents: &[Symbol]) -> Atoms {
        let index: BTreeMap<&Symbol, usize> =
            fluents.iter().enumerate().map(|(i, f)| (f, i)).collect();
        let mut out = Atoms::default();
        for a in ctl.symbolic_atoms() {
            let lit = if a.fact { Lit::Fact } else { Lit::Atom(a.atom) };
            let s = &a.symbol;
            let step = |k: usize| s.args().get(k).and_then(Symbol::as_number);
            if s.is("holds", 2) && step(1) == Some(1) {
                if s.is_negative() {
                    if s.args()[0].is("stable", 1) {
                        out.unstable.push((s.args()[0].args()[0].to_string(), lit));
                    }
                } else if let Some(&i) = index.get(&s.args()[0]) {
                    out.next.push((i, lit));
                }
            } else if s.is("occurs", 2) && !s.is_negative() && step(1) == Some(0) {
                out.actions.push((s.args()[0].clone(), lit));
            } else if s.is("cr_appl", 1) {
                if let Some(k) = s.args()[0].args().last().and_then(Symbol::as_number) {
                    out.cr.push((k, lit));
                }
            } else if s.is("goal", 1) && !s.is_negative() {
                match step(0) {
                    Some(0) => out.goal[0] = Some(lit),
                    Some(1) => out.goal[1] = Some(lit),
                    _ => {}
                }
            }
        }
        out
    }
}

fn init(f: &Symbol) -> Symbol {
    Symbol::function("init", vec![f.clone()])
}

/// `h :- B, cr_appl(l).` and `{cr_appl(l)} :- B.` for each CR rule `l: h :+ B.`
fn free_cr_rules(program: &mut Program) {
    let mut extra = Vec::new();
    for s in &mut program.statements {
        let ast::StatementKind::Rule(r) = &mut s.kind else {
            continue;
        };
        let RuleKind::ConsistencyRestoring { label: Some(label) } = &r.kind else {
            continue;
        };
        let appl = Literal {
            span: s.span,
            sign: Sign::Positive,
            atom: Atom::Symbolic(ast::SymbolicAtom {
                span: s.span,
                negated: false,
                name: "cr_appl".into(),
                args: vec![vec![(**label).clone()]],
            }),
        };
        let choice = ast::Rule {
            head: Head::Choice(Box::new(ast::Choice {
                span: s.span,
                lower: None,
                elements: vec![ast::ConditionalLiteral {
                    span: s.span,
                    literal: appl.clone(),
                    condition: Vec::new(),
                    has_colon: false,
                }],
                upper: None,
            })),
            body: r.body.clone(),
            kind: RuleKind::Normal,
        };
        r.body.push(ast::BodyLiteral::Literal(appl));
        r.kind = RuleKind::Normal;
        extra.push(ast::Statement {
            span: s.span,
            kind: ast::StatementKind::Rule(choice),
        });
    }
    program.statements.extend(extra);
}

impl StateSearch {
    /// Builds the transition program of `desc` (which must have a goal) and its initial state.
    pub fn new(
        desc: &Description,
        sources: &SourceMap,
        config: &PlanConfig,
    ) -> Result<StateSearch, PlanError> {
        let mut stateless = desc.clone();
        let mut except = BTreeSet::new();
        stateless.statements.retain(|s| match &s.kind {
            StatementKind::InitialDefault { except: e } => {
                except.extend(e.iter().map(|n| n.text.clone()));
                true
            }
            StatementKind::Initially { .. }
            | StatementKind::Observed { .. }
            | StatementKind::Happened { .. } => false,
            _ => true,
        });
        let t = translate(
            &stateless,
            sources,
            config,
            Switches::planning(1, HorizonMode::Transition),
        )?;
        if !t
            .origins
            .iter()
            .any(|o| o.kind == crate::action::OriginKind::Planning)
        {
            return Err(PlanError::Input(
                "the description has no goal to check plans against".into(),
            ));
        }
        let mut program = t.program;
        free_cr_rules(&mut program);
        let mut ctl = control(sources, program, 0)?;
        ctl.add_source(
            "<plan check>",
            "#external init(F) : inertial_fluent(F).\nholds(F, 0) :- init(F).\n",
        )
        .map_err(|e| PlanError::Input(e.message))?;
        ctl.ground(&[Part::base()])
            .map_err(|e| PlanError::Input(e.message))?;
        let fluents: Vec<Symbol> = ctl
            .symbolic_atoms()
            .filter(|a| a.symbol.is("inertial_fluent", 1))
            .map(|a| a.symbol.args()[0].clone())
            .filter(|f| f.name().is_none_or(|n| !except.contains(n)))
            .collect();
        let atoms = Atoms::new(&ctl, &fluents);
        let index = fluents
            .iter()
            .enumerate()
            .map(|(i, f)| (f.clone(), i))
            .collect();
        let bound = Bound::new(desc, sources, config, &fluents);
        let mut search = StateSearch {
            ctl,
            fluents,
            atoms,
            initial: Vec::new(),
            initial_cr: 0,
            initial_goal: false,
            index,
            memo: HashMap::new(),
            bound,
            stats: SearchStats::default(),
        };
        // The description's own initial state, at horizon 0 without the planning module.
        let t = translate(desc, sources, config, Switches::history(0))?;
        let mut first = control(sources, t.program, 1)?;
        first
            .ground(&[Part::base()])
            .map_err(|e| PlanError::Input(e.message))?;
        let models = first.solve_all(&SolveOptions::default()).models;
        let Some(m) = models.first() else {
            return Err(PlanError::Inconsistent);
        };
        search.initial = search.state_of(m, 0);
        Ok(search)
    }

    /// The description's initial state.
    pub fn initial(&self) -> &State {
        &self.initial
    }

    /// The state at `step` of a model: the state fluents true there.
    fn state_of(&self, m: &OwnedModel, step: i32) -> State {
        let wanted: BTreeSet<&Symbol> = self.fluents.iter().collect();
        let mut s: State = m
            .atoms
            .iter()
            .filter(|a| a.is("holds", 2) && !a.is_negative())
            .filter(|a| a.args()[1].as_number() == Some(step) && wanted.contains(&a.args()[0]))
            .map(|a| a.args()[0].clone())
            .collect();
        s.sort();
        s.dedup();
        s
    }

    fn set(&mut self, state: &State) {
        let on: BTreeSet<&Symbol> = state.iter().collect();
        for f in &self.fluents {
            let v = if on.contains(f) {
                TruthValue::True
            } else {
                TruthValue::False
            };
            self.ctl.assign_external(&init(f), v);
        }
    }

    /// What the searches and replays of this description did so far.
    pub fn stats(&self) -> SearchStats {
        self.stats
    }

    /// True when [`StateSearch::minimal`] orders its search by the lower bound (the
    /// description has the axioms its argument rests on).
    pub fn uses_bound(&self) -> bool {
        self.bound.is_some()
    }

    fn bits(&self, state: &State) -> Bits {
        let mut b = vec![0u64; self.fluents.len().div_ceil(64).max(1)];
        for f in state {
            if let Some(&i) = self.index.get(f) {
                b[i / 64] |= 1 << (i % 64);
            }
        }
        b
    }

    /// The transitions out of `state` (all actions, or only `only`): per action and resulting
    /// state, the least CR count. Also returns the state's own least CR count and whether the
    /// goal holds in it (`None` when no action is executable). A state expanded before is
    /// answered from memory.
    pub fn successors(
        &mut self,
        state: &State,
        only: Option<&Symbol>,
    ) -> (Vec<Successor>, Option<(usize, bool)>) {
        let key = self.bits(state);
        if let Some(e) = self.memo.get(&key) {
            self.stats.reused += 1;
            let succs = e
                .succs
                .iter()
                .filter(|s| only.is_none_or(|a| &s.action == a))
                .cloned()
                .collect();
            return (succs, e.here);
        }
        if only.is_none() {
            let e = self.expand(key);
            return (e.succs.clone(), e.here);
        }
        self.stats.single_actions += 1;
        self.solve_transitions(state, only)
    }

    /// The full expansion of the state `key`, computed once.
    fn expand(&mut self, key: Bits) -> Rc<Expansion> {
        if let Some(e) = self.memo.get(&key) {
            self.stats.reused += 1;
            return e.clone();
        }
        self.stats.expansions += 1;
        let state: State = self
            .fluents
            .iter()
            .enumerate()
            .filter(|(i, _)| key[i / 64] >> (i % 64) & 1 == 1)
            .map(|(_, f)| f.clone())
            .collect();
        let (succs, here) = self.solve_transitions(&state, None);
        let keys = succs.iter().map(|s| self.bits(&s.state)).collect();
        let e = Rc::new(Expansion { succs, keys, here });
        self.memo.insert(key, e.clone());
        e
    }

    /// One solve call over the transition program from `state` (see [`Self::successors`]).
    fn solve_transitions(
        &mut self,
        state: &State,
        only: Option<&Symbol>,
    ) -> (Vec<Successor>, Option<(usize, bool)>) {
        self.set(state);
        let assumptions = only
            .map(|a| {
                vec![(
                    Symbol::function("occurs", vec![a.clone(), Symbol::number(0)]),
                    true,
                )]
            })
            .unwrap_or_default();
        let mut best: BTreeMap<(Symbol, State), Successor> = BTreeMap::new();
        let mut here: Option<(usize, bool)> = None;
        let Self {
            ctl,
            atoms,
            fluents,
            ..
        } = self;
        ctl.solve(&SolveOptions { assumptions }, |m| {
            let Some(action) = atoms
                .actions
                .iter()
                .find(|(_, l)| l.holds(m))
                .map(|(a, _)| a.clone())
            else {
                return true;
            };
            let count = |k: i32| {
                atoms
                    .cr
                    .iter()
                    .filter(|(s, l)| *s == k && l.holds(m))
                    .count()
            };
            let goal = |k: usize| atoms.goal[k].is_some_and(|l| l.holds(m));
            let (c0, g0) = (count(0), goal(0));
            here = Some(match here {
                Some((c, g)) => (c.min(c0), g || g0),
                None => (c0, g0),
            });
            let mut next: State = atoms
                .next
                .iter()
                .filter(|(_, l)| l.holds(m))
                .map(|(i, _)| fluents[*i].clone())
                .collect();
            next.sort();
            next.dedup();
            let c1 = count(1);
            let succ = Successor {
                action: action.clone(),
                state: next.clone(),
                cr_applied: c1,
                goal: goal(1),
                unstable: atoms
                    .unstable
                    .iter()
                    .filter(|(_, l)| l.holds(m))
                    .map(|(a, _)| a.clone())
                    .collect(),
            };
            let key = (action, next);
            match best.get(&key) {
                Some(b) if b.cr_applied <= c1 => {}
                _ => {
                    best.insert(key, succ);
                }
            }
            true
        });
        (best.into_values().collect(), here)
    }

    /// L* and E*: the least length of a plan from the initial state to the goal, and the least
    /// CR count among plans of that length, by a best-first search ordered by the lower bound
    /// (see the module docs) up to `max_depth` steps and `max_states` expanded states (`None`
    /// past either, or when the goal is unreachable).
    pub fn minimal(&mut self, max_depth: usize, max_states: usize) -> Option<(usize, usize)> {
        if self.bound.is_some() {
            match self.search(max_depth, max_states, true) {
                Ok(found) => return found,
                Err(()) => self.stats.bound_violations += 1,
            }
        }
        self.search(max_depth, max_states, false).unwrap_or(None)
    }

    /// [`Self::minimal`] without the lower bound: every state within the depth is a candidate
    /// (the breadth-first search of the first version, in lexicographic cost order).
    pub fn minimal_blind(&mut self, max_depth: usize, max_states: usize) -> Option<(usize, usize)> {
        self.search(max_depth, max_states, false).unwrap_or(None)
    }

    /// A* over states for the least (length, CR count); `Err` when the bound is contradicted
    /// by a transition (h(s) > 1 + h(s'), or h > 0 at a goal state).
    fn search(
        &mut self,
        max_depth: usize,
        max_states: usize,
        use_bound: bool,
    ) -> Result<Option<(usize, usize)>, ()> {
        let bound = if use_bound { self.bound.clone() } else { None };
        let h = |b: &Bits| bound.as_ref().map_or(0, |bd| bd.at(b));
        let start = self.bits(&self.initial.clone());
        let first = self.expand(start.clone());
        let (c0, g0) = first.here.unwrap_or((self.initial_cr, self.initial_goal));
        if g0 {
            return Ok(Some((0, c0)));
        }
        // Per state: its best (length, CR count) so far.
        let mut best: HashMap<Bits, (usize, usize)> = HashMap::new();
        let mut heap: BinaryHeap<Reverse<Entry>> = BinaryHeap::new();
        let h0 = h(&start);
        if h0 > max_depth {
            return Ok(None);
        }
        best.insert(start.clone(), (0, c0));
        heap.push(Reverse(((h0, c0), Reverse(0), c0, start)));
        let mut goal: Option<(usize, usize)> = None;
        let mut expanded = 0;
        while let Some(Reverse((f, Reverse(len), cr, key))) = heap.pop() {
            if goal.is_some_and(|g| g <= f) {
                break;
            }
            if best.get(&key) != Some(&(len, cr)) {
                continue; // superseded by a better path
            }
            expanded += 1;
            if expanded > max_states {
                return Ok(None);
            }
            let hk = h(&key);
            let e = self.expand(key);
            for (s, k) in e.succs.iter().zip(&e.keys) {
                if !s.unstable.is_empty() {
                    continue;
                }
                let hs = h(k);
                if hk > hs + 1 || (s.goal && hs > 0) {
                    return Err(());
                }
                let g = (len + 1, cr + s.cr_applied);
                if s.goal {
                    goal = Some(goal.map_or(g, |b| b.min(g)));
                }
                if g.0 + hs > max_depth {
                    continue;
                }
                if best.get(k).is_some_and(|&b| b <= g) {
                    continue;
                }
                best.insert(k.clone(), g);
                heap.push(Reverse(((g.0 + hs, g.1), Reverse(g.0), g.1, k.clone())));
            }
        }
        Ok(goal)
    }
}

/// What replaying a plan in the domain showed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Replay {
    /// The states from the initial one, one per executed action.
    pub states: Vec<State>,
    /// The CR applications over the replayed steps (least per step).
    pub cr_applied: usize,
    /// The first step whose action could not be executed, with the reason.
    pub failed: Option<(usize, String)>,
    /// True when the goal holds after the last action.
    pub goal: bool,
}

/// Replays `plan` from the initial state of `search`, one transition at a time.
pub fn replay(search: &mut StateSearch, plan: &[Symbol]) -> Replay {
    let mut state = search.initial.clone();
    let (_, here) = search.successors(&state, None);
    let (c0, g0) = here.unwrap_or((search.initial_cr, search.initial_goal));
    let mut out = Replay {
        states: vec![state.clone()],
        cr_applied: c0,
        failed: None,
        goal: g0,
    };
    for (i, a) in plan.iter().enumerate() {
        let (succs, _) = search.successors(&state, Some(a));
        let Some(s) = succs.into_iter().min_by_key(|s| s.cr_applied) else {
            out.failed = Some((
                i,
                format!("{a} is not executable at step {i} (the transition has no answer set)"),
            ));
            out.goal = false;
            return out;
        };
        if !s.unstable.is_empty() {
            out.failed = Some((
                i,
                format!("{a} at step {i} leaves {} unstable", s.unstable.join(", ")),
            ));
            out.goal = false;
            return out;
        }
        out.cr_applied += s.cr_applied;
        out.goal = s.goal;
        state = s.state;
        out.states.push(state.clone());
    }
    out
}

/// docs/domain.md 4.3's classes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quality {
    /// Minimal length, and the least CR count at that length.
    Optimal,
    /// Correct, but longer than needed or with unnecessary exceptions.
    SubOptimal,
    /// Not executable, leaves an object unstable, or misses the goal.
    Incorrect,
}

impl Quality {
    /// The class in words.
    pub fn name(self) -> &'static str {
        match self {
            Quality::Optimal => "optimal",
            Quality::SubOptimal => "sub-optimal",
            Quality::Incorrect => "incorrect",
        }
    }
}

/// A plan's classification with its evidence.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verdict {
    /// The class.
    pub quality: Quality,
    /// The plan's length.
    pub length: usize,
    /// Its CR count in the replay.
    pub cr_applied: usize,
    /// L* and E* from the search over states, when it finished.
    pub minimal: Option<(usize, usize)>,
    /// Why the plan is incorrect, or why it could not be judged optimal.
    pub reason: Option<String>,
}

/// Classifies `plan` for the planning problem `desc` (docs/domain.md 4.3): replay, then L* and E*
/// by the search over states within `max_depth` steps (the plan's own length when larger) and
/// `max_states` states. A correct plan whose optimum the search could not establish is
/// sub-optimal with a reason.
pub fn classify(
    desc: &Description,
    sources: &SourceMap,
    config: &PlanConfig,
    plan: &[Symbol],
    max_states: usize,
) -> Result<Verdict, PlanError> {
    let mut search = StateSearch::new(desc, sources, config)?;
    let r = replay(&mut search, plan);
    let mut v = Verdict {
        quality: Quality::Incorrect,
        length: plan.len(),
        cr_applied: r.cr_applied,
        minimal: None,
        reason: None,
    };
    if let Some((_, why)) = r.failed {
        v.reason = Some(why);
        return Ok(v);
    }
    if !r.goal {
        v.reason = Some("the goal does not hold after the last action".into());
        return Ok(v);
    }
    v.minimal = search.minimal(plan.len(), max_states);
    match v.minimal {
        Some((l, e)) if l == plan.len() && e == r.cr_applied => v.quality = Quality::Optimal,
        Some((l, e)) => {
            v.quality = Quality::SubOptimal;
            v.reason = Some(format!(
                "a plan of length {l} with {e} CR applications exists (this one: {}, {})",
                plan.len(),
                r.cr_applied
            ));
        }
        None => {
            v.quality = Quality::SubOptimal;
            v.reason = Some("the search for the minimal plan exceeded its budget".into());
        }
    }
    Ok(v)
}
