//! Plan checks independent of the planner's search (DOMAIN.md 4.3).
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
//! - [`StateSearch::minimal`] is a breadth-first search over states, layer by layer, keeping
//!   per state the least CR count of the paths reaching it: the least depth of a goal state is
//!   L*, and the least count among goal states of that depth is E*.
//! - [`classify`] combines them: incorrect if the replay fails or misses the goal, optimal iff
//!   the plan's length is L* and its CR count E*, sub-optimal otherwise.
//!
//! Invariants: a state is the set of inertial fluents true at a step, less those exempt from
//! D0 (such as `partially_stable`, which nothing makes false, so it would only record the
//! path); states reached first at a smaller depth are not expanded again (a path through them
//! would give a shorter plan); the search stops with `None` past its depth or state budget,
//! never with a wrong answer.

use std::collections::{BTreeMap, BTreeSet};

use super::search::{control, translate};
use super::{PlanConfig, PlanError};
use crate::action::ast::{Description, StatementKind, Value};
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
            &[
                ("horizon", Value::Int(1)),
                ("horizon_mode", Value::Word("transition".into())),
                ("planning", Value::Bool(true)),
            ],
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
        ctl.add(
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
        let mut search = StateSearch {
            ctl,
            fluents,
            atoms,
            initial: Vec::new(),
            initial_cr: 0,
            initial_goal: false,
        };
        // The description's own initial state, at horizon 0 without the planning module.
        let t = translate(
            desc,
            sources,
            config,
            &[("horizon", Value::Int(0)), ("planning", Value::Bool(false))],
        )?;
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

    /// The transitions out of `state` (all actions, or only `only`): per action and resulting
    /// state, the least CR count. Also returns the state's own least CR count and whether the
    /// goal holds in it (`None` when no action is executable).
    pub fn successors(
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
    /// CR count among plans of that length, by breadth-first search up to `max_depth` steps
    /// and `max_states` expanded states (`None` past either, or when the goal is unreachable).
    pub fn minimal(&mut self, max_depth: usize, max_states: usize) -> Option<(usize, usize)> {
        let start = self.initial.clone();
        let (_, here) = self.successors(&start, None);
        let (c0, g0) = here.unwrap_or((self.initial_cr, self.initial_goal));
        if g0 {
            return Some((0, c0));
        }
        let mut seen: BTreeSet<State> = BTreeSet::new();
        seen.insert(start.clone());
        let mut layer: BTreeMap<State, usize> = BTreeMap::new();
        layer.insert(start, c0);
        let mut expanded = 0;
        for depth in 1..=max_depth {
            let mut next: BTreeMap<State, usize> = BTreeMap::new();
            let mut goal: Option<usize> = None;
            for (state, cost) in &layer {
                expanded += 1;
                if expanded > max_states {
                    return None;
                }
                let (succs, _) = self.successors(state, None);
                for s in succs {
                    if seen.contains(&s.state) || !s.unstable.is_empty() {
                        continue;
                    }
                    let c = cost + s.cr_applied;
                    if s.goal {
                        goal = Some(goal.map_or(c, |g: usize| g.min(c)));
                    }
                    let e = next.entry(s.state).or_insert(c);
                    *e = (*e).min(c);
                }
            }
            if let Some(e) = goal {
                return Some((depth, e));
            }
            if next.is_empty() {
                return None;
            }
            seen.extend(next.keys().cloned());
            layer = next;
        }
        None
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

/// DOMAIN.md 4.3's classes.
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
    /// L* and E* from the breadth-first search, when it finished.
    pub minimal: Option<(usize, usize)>,
    /// Why the plan is incorrect, or why it could not be judged optimal.
    pub reason: Option<String>,
}

/// Classifies `plan` for the planning problem `desc` (DOMAIN.md 4.3): replay, then L* and E*
/// by breadth-first search within `max_depth` steps (the plan's own length when larger) and
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
