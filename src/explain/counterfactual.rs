//! The two questions beyond the paper, which need new solves (docs/domain.md 6 extended by
//! issue 14):
//!
//! - **What if** ⟨action X at step I⟩: the history with X at step I instead of the plan's
//!   action, the later actions kept; if they cannot all be executed any more, the history cut
//!   after X. Re-solved (`history::explain_history`), and the first step at which the beliefs
//!   differ is named: the `on` relations and `in_hand` literals that would have held, instead of
//!   those that did. If X itself could not have been executed, the answer says so and why
//!   (the why-not answer over the original history).
//! - **Why no plan**: the planning problem at horizon H with each goal literal, each
//!   initial-state fact and each `never` constraint behind an assumption atom that switches it
//!   on ([`NoPlan`]). One grounding; a solve under all the assumptions fails, and the solver's
//!   unsatisfiable core (the assumptions its refutation used, `control::Summary::core`) is the
//!   first candidate; it is then shrunk by deletion (an element stays only if the problem
//!   becomes solvable without it; an unsolvable smaller set is replaced by its own core), so the
//!   answer is a *minimal* set of goal literals, observations and constraints that together make
//!   the task impossible. The hypotheses left out of a solve are assumed false (switched off).
//!
//! Invariants: nothing here reads files; every answer comes from solves of the problem, never
//! from the question's wording; a problem that does not translate is a [`HistoryError`].

use super::history::{explain_history, History, HistoryError, Problem};
use super::lexicon::Lexicon;
use super::pattern::{Pattern, SymbolExt};
use super::questions::{answer, Answer, Mode, Session};
use super::verbalize::{ActionForm, Tense, Verbalizer};
use crate::action::{self, AxiomOrigin, HorizonMode, Options, OriginKind, Switches};
use crate::base::Diagnostics;
use crate::control::{Control, ControlConfig, Part, Symbol, TruthValue};
use crate::syntax::ast;

/// What if the robot had done `action` at `step` (default: the step of the plan's action with
/// the same name and object, else step 0)?
pub fn what_if(
    h: &History,
    lexicon: &Lexicon,
    action: &Pattern,
    step: Option<u32>,
    session: &mut Session,
) -> Answer {
    let v = Verbalizer::new(lexicon);
    let simple = |text: String| Answer {
        kind: "what_if",
        text,
        literals: Vec::new(),
        tree: None,
    };
    let step = step.unwrap_or_else(|| {
        h.plan
            .iter()
            .find(|(_, a)| {
                a.name() == action.name() && a.arg(1).map(Pattern::from).as_ref() == action.arg(1)
            })
            .map_or(0, |(i, _)| *i)
    });
    if step > h.last_step {
        return simple(v.template(
            "outside_history",
            &[
                ("step", &step.to_string()),
                ("last", &h.last_step.to_string()),
            ],
        ));
    }
    session.last_step = Some(step);
    let Some(x) = action.to_symbol() else {
        return simple(v.template("no_reason", &[]));
    };
    let action = &x;
    let words = v.action(action, ActionForm::Past);
    let at = v.step(i64::from(step));
    let actions: Vec<Symbol> = h.plan.iter().map(|(_, a)| a.clone()).collect();
    let i = step as usize;
    let mut tried: Vec<Vec<Symbol>> = Vec::new();
    let mut with_rest = actions[..i.min(actions.len())].to_vec();
    with_rest.push(x.clone());
    let cut = with_rest.clone();
    if i + 1 < actions.len() {
        with_rest.extend_from_slice(&actions[i + 1..]);
        tried.push(with_rest);
    }
    tried.push(cut);
    let mut problem = h.problem.clone();
    let mut found = None;
    for (k, acts) in tried.iter().enumerate() {
        // A hypothetical history counts only as the knowledge allows it: one that needs a
        // surprise (an action the robot believes impossible) could not have happened.
        if let Ok(new) = explain_history(&problem.desc, &mut problem.sources, acts, &problem.config)
        {
            if new.surprises.is_empty() {
                found = Some((new, k + 1 < tried.len() || tried.len() == 1));
                break;
            }
        }
    }
    let Some((new, kept_rest)) = found else {
        // X itself cannot be executed there: say why, from the original history.
        let q = super::english::Question::WhyNotAction {
            action: Pattern::from(action),
            step: Some(step),
        };
        let reason = answer(
            &h.scenario(),
            lexicon,
            &q,
            Mode::Concise,
            &mut Session::default(),
        )
        .map(|a| a.text)
        .unwrap_or_default();
        let mut a = simple(v.template(
            "what_if_impossible",
            &[
                ("action", &v.action(action, ActionForm::Base)),
                ("step", &at),
                ("reason", &reason),
            ],
        ));
        a.literals = vec![super::english::occurs(action, step)
            .complement()
            .expect("occurs has a sign")];
        return a;
    };
    // The first step after `step` whose `on` and `in_hand` beliefs differ.
    let shown = |t: &Symbol| -> bool {
        let Some(f) = t.arg(0) else { return false };
        t.name() == Some("holds")
            && !t.is_negative()
            && (f.name() == Some("in_hand")
                || (f.name() == Some("relation") && f.arg(0).and_then(Symbol::name) == Some("on")))
    };
    let last = new.last_step.min(h.last_step);
    let old_lits = h.oracle.true_literals();
    let new_lits = new.oracle.true_literals();
    for s in step + 1..=new.last_step.max(step + 1) {
        let at_s = |lits: &[Symbol]| -> Vec<Symbol> {
            let mut v: Vec<Symbol> = lits
                .iter()
                .filter(|t| shown(t) && super::tree::step_of(t) == Some(s))
                .cloned()
                .collect();
            v.sort();
            v
        };
        let old = at_s(&old_lits);
        let now = at_s(&new_lits);
        let added: Vec<Symbol> = now.iter().filter(|t| !old.contains(t)).cloned().collect();
        let removed: Vec<Symbol> = old.iter().filter(|t| !now.contains(t)).cloned().collect();
        if added.is_empty() && removed.is_empty() && s < last {
            continue;
        }
        if added.is_empty() && removed.is_empty() {
            break;
        }
        let mut text = v.template(
            "what_if",
            &[
                ("action", &words),
                ("step", &at),
                ("later", &v.step(i64::from(s))),
                ("literals", &v.join(&added, Tense::Past)),
                ("old", &v.join(&removed, Tense::Past)),
            ],
        );
        text = text.replace(", instead of .", ".");
        if !kept_rest {
            if let Some((_, next)) = h.plan.iter().find(|(j, _)| *j == step + 1) {
                text.push(' ');
                text.push_str(&v.template(
                    "what_if_stuck",
                    &[("next", &v.action(next, ActionForm::Base))],
                ));
            }
        }
        let mut literals = vec![super::english::occurs(action, step)];
        literals.extend(added);
        return Answer {
            kind: "what_if",
            text,
            literals,
            tree: None,
        };
    }
    let mut a = simple(v.template("what_if_same", &[("action", &words), ("step", &at)]));
    a.literals = vec![super::english::occurs(action, step)];
    a
}

/// One assumption of the why-no-plan problem.
#[derive(Clone, Debug, PartialEq)]
pub enum Hyp {
    /// A goal literal (a fluent).
    Goal(Symbol),
    /// An initial-state fact (`holds(f, 0)` or `hpd`/`obs`), with its statement text.
    Observation(Symbol),
    /// A `never` constraint: its label and one-line text.
    Constraint(String),
}

/// The assumption atom of hypothesis `k`.
const HYP: &str = "lucent_hyp";

/// The why-no-plan problem: the task at a fixed horizon, grounded once, with its goal literals,
/// initial-state facts and `never` constraints behind assumption atoms.
pub struct NoPlan {
    ctl: Control,
    hyps: Vec<Hyp>,
    /// Solve calls made so far.
    pub solves: usize,
    /// The size of the solver's first core (before deletion), once [`NoPlan::minimal_core`] ran.
    pub first_core: Option<usize>,
}

impl NoPlan {
    /// The planning problem of `problem` at `horizon` (with `goal` instead of the description's
    /// goal when it is not empty).
    pub fn new(problem: &Problem, goal: &[Symbol], horizon: usize) -> Result<NoPlan, HistoryError> {
        // One statement: the goal is the conjunction (separate `goal` statements would be
        // alternatives).
        let task = crate::plan::Problem {
            goal: goal.to_vec(),
            ..crate::plan::Problem::new(problem.desc.clone(), problem.sources.clone())
        };
        let desc = task.description();
        let sources = task.sources;
        let options = Options {
            profile: problem.config.profile.clone(),
            overrides: problem.config.overrides.clone(),
            switches: Switches::planning(horizon, HorizonMode::Iterative),
        };
        let t = action::translate(&desc, &options);
        if t.has_errors() {
            let mut d = Diagnostics::default();
            d.extend(t.diagnostics);
            return Err(HistoryError::Input(d.render(&sources)));
        }
        let mut program = t.program;
        let hyps = gate(&mut program, &t.origins);
        let mut ctl = Control::with_sources(ControlConfig::default(), sources);
        ctl.add_program(program)
            .map_err(|e| HistoryError::Input(e.message))?;
        ctl.ground(&[Part::base()])
            .map_err(|e| HistoryError::Input(e.message))?;
        // The assumption atoms are free externals: each call's assumptions set them (an
        // external left false would refute an assumption that it is true).
        for k in 0..hyps.len() {
            ctl.assign_external(&hyp_atom(k), TruthValue::Free);
        }
        Ok(NoPlan {
            ctl,
            hyps,
            solves: 0,
            first_core: None,
        })
    }

    /// The hypotheses, indexed as the sets of the other methods.
    pub fn hypotheses(&self) -> &[Hyp] {
        &self.hyps
    }

    /// Solves with the hypotheses `on` switched on and the others off: `None` when a plan
    /// exists, else the core, a subset of `on` that is unsolvable on its own (the others off).
    pub fn refute(&mut self, on: &[usize]) -> Option<Vec<usize>> {
        self.solves += 1;
        let gates: Vec<Symbol> = (0..self.hyps.len()).map(hyp_atom).collect();
        let gates: Vec<&Symbol> = gates.iter().collect();
        super::unsat::refute_gates(&mut self.ctl, &gates, on)
    }

    /// A minimal set of hypotheses that makes the task impossible: `None` when a plan exists
    /// with all of them; the empty set when none is needed (no plan even without them).
    /// Deletion tries observations first, then constraints, then goal literals, so the answer
    /// keeps the goal when it can.
    pub fn minimal_core(&mut self) -> Option<Vec<usize>> {
        let all: Vec<usize> = (0..self.hyps.len()).collect();
        let mut core = self.refute(&all)?;
        self.first_core = Some(core.len());
        let rank = |h: &Hyp| match h {
            Hyp::Observation(_) => 0,
            Hyp::Constraint(_) => 1,
            Hyp::Goal(_) => 2,
        };
        let mut order = core.clone();
        order.sort_by_key(|&k| (rank(&self.hyps[k]), k));
        for k in order {
            if !core.contains(&k) {
                continue;
            }
            let without: Vec<usize> = core.iter().copied().filter(|&x| x != k).collect();
            if let Some(smaller) = self.refute(&without) {
                core = smaller;
            }
        }
        Some(core)
    }
}

/// The assumption atom of hypothesis `k`.
fn hyp_atom(k: usize) -> Symbol {
    Symbol::function(HYP, vec![Symbol::number(k as i32)])
}

/// Why is there no plan of at most `horizon` steps for the problem (with `goal` instead of the
/// description's goal when it is not empty)? A minimal set of goal literals, observations and
/// constraints that cannot all hold together.
pub fn why_no_plan(
    problem: &Problem,
    lexicon: &Lexicon,
    goal: &[Symbol],
    horizon: usize,
) -> Result<Answer, HistoryError> {
    let v = Verbalizer::new(lexicon);
    let mut np = NoPlan::new(problem, goal, horizon)?;
    // "1 step", "3 steps": the templates say "at most {steps}".
    let h = match horizon {
        1 => "1 step".to_string(),
        n => format!("{n} steps"),
    };
    let Some(core) = np.minimal_core() else {
        return Ok(Answer {
            kind: "no_plan",
            text: v.template("plan_exists", &[("steps", &h)]),
            literals: Vec::new(),
            tree: None,
        });
    };
    if core.is_empty() {
        return Ok(Answer {
            kind: "no_plan",
            text: v.template("no_plan_always", &[("steps", &h)]),
            literals: Vec::new(),
            tree: None,
        });
    }
    let mut reasons = Vec::new();
    let mut literals = Vec::new();
    for &k in &core {
        match &np.hypotheses()[k] {
            Hyp::Goal(g) => {
                reasons.push(format!("the goal that {}", v.fluent(g, Tense::Present)));
                literals.push(g.clone());
            }
            Hyp::Observation(o) => {
                reasons.push(format!("my observation that {}", v.clause(o, Tense::Past)));
                literals.push(o.clone());
            }
            Hyp::Constraint(text) => reasons.push(format!("the constraint {text}")),
        }
    }
    Ok(Answer {
        kind: "no_plan",
        text: v.template(
            "no_plan",
            &[
                ("steps", &h),
                ("reasons", &super::english::join_and(&reasons)),
            ],
        ),
        literals,
        tree: None,
    })
}

/// Puts the goal literals, the initial-state facts and the `never` constraints of a translated
/// planning problem behind assumption atoms `lucent_hyp(k)`, editing the syntax tree:
/// - an initial-state fact `l.` (a history fact whose last argument is step 0) becomes
///   `l :- lucent_hyp(k).`;
/// - a `never` constraint `:- body.` becomes `:- body, lucent_hyp(k).`;
/// - each literal `[-]holds(f, I)` of the goal rule `goal(I) :- ...` becomes
///   `lucent_goal_ok(k, I)`, with `lucent_goal_ok(k, I) :- [-]holds(f, I), step(I).` and
///   `lucent_goal_ok(k, I) :- step(I), not lucent_hyp(k).`;
///
/// and every `lucent_hyp(k)` is declared `#external`.
fn gate(program: &mut ast::Program, origins: &[AxiomOrigin]) -> Vec<Hyp> {
    use crate::syntax::build::{atom, external, head_of, int, neg, pos, rule};
    let sp = crate::base::Span::default();
    let hyp = |n: usize| pos(sp, false, HYP, vec![int(sp, n as i64)]);
    let mut hyps = Vec::new();
    let mut extra = Vec::new();
    for (k, st) in program.statements.iter_mut().enumerate() {
        let Some(o) = origins.get(k) else { continue };
        let ast::StatementKind::Rule(r) = &mut st.kind else {
            continue;
        };
        match o.kind {
            OriginKind::History if r.body.is_empty() => {
                let Some(t) = head_atom(&r.head).and_then(Symbol::from_atom) else {
                    continue;
                };
                if t.args().last() != Some(&Symbol::number(0)) {
                    continue;
                }
                r.body.push(hyp(hyps.len()));
                hyps.push(Hyp::Observation(t));
            }
            OriginKind::Never => {
                r.body.push(hyp(hyps.len()));
                hyps.push(Hyp::Constraint(match &o.label {
                    Some(l) => format!("{l} ({})", o.text),
                    None => o.text.clone(),
                }));
            }
            OriginKind::Planning => {
                let Some(step) = goal_variable(&r.head) else {
                    continue;
                };
                for item in r.body.iter_mut() {
                    let Some(fluent) = goal_fluent(item, &step) else {
                        continue;
                    };
                    let n = hyps.len();
                    hyps.push(Hyp::Goal(fluent));
                    let ok = || {
                        atom(
                            sp,
                            false,
                            "lucent_goal_ok",
                            vec![int(sp, n as i64), step.clone()],
                        )
                    };
                    let step_lit = || pos(sp, false, "step", vec![step.clone()]);
                    let lit = std::mem::replace(
                        item,
                        ast::BodyLiteral::Literal(ast::Literal {
                            span: sp,
                            sign: ast::Sign::Positive,
                            atom: ast::Atom::Symbolic(ok()),
                        }),
                    );
                    extra.push(rule(sp, head_of(sp, ok()), vec![lit, step_lit()]));
                    extra.push(rule(
                        sp,
                        head_of(sp, ok()),
                        vec![step_lit(), neg(sp, false, HYP, vec![int(sp, n as i64)])],
                    ));
                }
            }
            _ => {}
        }
    }
    for k in 0..hyps.len() {
        extra.push(external(
            sp,
            atom(sp, false, HYP, vec![int(sp, k as i64)]),
            Vec::new(),
            None,
        ));
    }
    program.statements.extend(extra);
    hyps
}

/// The atom of a head of one unconditional, positive literal (`-holds(f, 0)`, `goal(I)`).
fn head_atom(head: &ast::Head) -> Option<&ast::SymbolicAtom> {
    let ast::Head::Disjunction(d) = head else {
        return None;
    };
    let [c] = d.as_slice() else { return None };
    let ast::Atom::Symbolic(a) = &c.literal.atom else {
        return None;
    };
    (c.condition.is_empty() && c.literal.sign == ast::Sign::Positive).then_some(a)
}

/// The step variable `I` of the goal rule's head `goal(I)`.
fn goal_variable(head: &ast::Head) -> Option<ast::Term> {
    let a = head_atom(head)?;
    match a.args.as_slice() {
        [args] if a.name.as_str() == "goal" && args.len() == 1 => {
            matches!(args[0].kind, ast::TermKind::Variable(_)).then(|| args[0].clone())
        }
        _ => None,
    }
}

/// The goal fluent of a body literal `[-]holds(f, I)` (`f`, or its complement under `-`).
fn goal_fluent(item: &ast::BodyLiteral, step: &ast::Term) -> Option<Symbol> {
    let ast::BodyLiteral::Literal(l) = item else {
        return None;
    };
    let ast::Atom::Symbolic(a) = &l.atom else {
        return None;
    };
    if l.sign != ast::Sign::Positive || a.name.as_str() != "holds" {
        return None;
    }
    let [args] = a.args.as_slice() else {
        return None;
    };
    let [f, i] = args.as_slice() else { return None };
    if i.kind != step.kind {
        return None;
    }
    let f = Symbol::from_term(f)?;
    if a.negated {
        f.complement()
    } else {
        Some(f)
    }
}
