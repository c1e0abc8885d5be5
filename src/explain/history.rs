//! Histories to explain (docs/domain.md 6.1, "Program Analyzer"): an AL_d planning problem (a
//! description with its initial state and goal) and the actions that were executed (or are
//! planned), turned into the program the questions are answered over: the description's
//! translation with the actions as `happened` statements, the planning module off, the
//! explanation-only axioms on (`explanation_rule_base`, when the description declares it), at
//! horizon = the number of actions; grounded once with provenance through a [`Control`] and
//! solved for one answer set (CR rules applied minimally, as the solver does).
//!
//! A history without an answer set is repaired when it can be: every executability condition
//! becomes defeasible for the actions that happened (a CR rule per condition, so the solver
//! applies the fewest), and the conditions it had to set aside are the history's
//! [`Surprise`]s: an action that worked although the robot believed it could not.
//!
//! Invariants: nothing here reads files (the caller parsed the description into `sources`);
//! an executed plan need not be minimal, nor reach the goal; a history without an answer set
//! even with surprises allowed (an inconsistent scene) is [`HistoryError::Inconsistent`],
//! never a panic.

use super::oracle::{Labels, ProgramOracle};
use super::pattern::SymbolExt;
use super::questions::Scenario;
use super::tree::LearnedAxiom;
use crate::action::{self, ast::Description, ast::StatementKind, ast::Value, Options};
use crate::action::{AxiomOrigin, OriginKind, Switches};
use crate::base::{Diagnostics, SourceMap};
use crate::control::{Control, ControlConfig, Part, SolveOptions, Symbol, TruthValue};
use crate::learn::strength::{Store, LEARNED_PREFIX};
use crate::syntax::ast;

/// How the history's program is made.
#[derive(Clone, Debug, Default)]
pub struct HistoryConfig {
    /// The description's profile (`tabletop`, `learner`, ...).
    pub profile: Option<String>,
    /// Switch overrides (`horizon` and `planning` are set here).
    pub overrides: Vec<(String, Value)>,
}

/// Why a history could not be explained.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum HistoryError {
    /// The description does not translate or ground; the rendered diagnostics.
    #[error("{0}")]
    Input(String),
    /// The history has no answer set (an action that cannot be executed there, or an
    /// inconsistent initial state).
    #[error("the history has no answer set: {0}")]
    Inconsistent(String),
}

/// A planning problem as given: the description (initial state and goal included), its
/// sources, and the settings; what-if and why-no-plan questions solve it again.
#[derive(Clone, Debug)]
pub struct Problem {
    /// The description, without the history's `happened` statements.
    pub desc: Description,
    /// Its files.
    pub sources: SourceMap,
    /// Profile and switches.
    pub config: HistoryConfig,
}

/// A history with its answer set: the program, the plan, the goal.
pub struct History {
    /// The problem the history belongs to.
    pub problem: Problem,
    /// The ground program with provenance and the answer set.
    pub oracle: ProgramOracle,
    /// The actions with their steps.
    pub plan: Vec<(u32, Symbol)>,
    /// The goal fluents (`relation(on,pitcher,red_block)`), from the description's `goal`.
    pub goal: Vec<Symbol>,
    /// The last step (the number of actions).
    pub last_step: u32,
    /// The objects, computed once from the answer set (see [`History::objects`]).
    objects: Vec<String>,
    /// The learned axioms among the description's files (see [`learned_axioms`]).
    pub learned: Vec<LearnedAxiom>,
    /// The surprises the history needed (empty when it is consistent as given).
    pub surprises: Vec<Surprise>,
    /// The observations it had to take as unexpected changes.
    pub unexpected: Vec<Unexpected>,
    /// The attempts that failed (their steps have no action).
    pub failed: Vec<Failed>,
}

/// An executed action whose executability condition held in the robot's belief: the history
/// is impossible under its knowledge unless the action is taken to have been executable
/// anyway. The least set of such surprises makes the history consistent (see
/// [`explain_history`]); they are the discrepancies the learner starts from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Surprise {
    /// The step of the action.
    pub step: u32,
    /// The action.
    pub action: Symbol,
    /// The executability condition's label (`E11`) or schema name.
    pub label: String,
    /// The condition's AL_d text (`impossible putdown(R, A, B) if has_size(B, small)`).
    pub axiom: String,
    /// The ground body literals that held (`has_size(blue_block,small)`).
    pub because: Vec<Symbol>,
}

impl Surprise {
    /// The surprise in English: "I put the ball on the blue block at step 1 although I
    /// believed I could not (E11: impossible putdown(R, A, B) if has_size(B, small)): the
    /// blue block is small."
    pub fn say(&self, v: &super::verbalize::Verbalizer<'_>) -> String {
        use super::verbalize::{ActionForm, Tense};
        let mut text = format!(
            "I {} {} although I believed I could not ({}: {})",
            v.action(&self.action, ActionForm::Past),
            v.step(i64::from(self.step)),
            self.label,
            self.axiom
        );
        if !self.because.is_empty() {
            text.push_str(&format!(": {}", v.join(&self.because, Tense::Past)));
        }
        text.push('.');
        text
    }

    /// The same difference in a plan the robot's planner made itself (not executed): the
    /// planner's knowledge allowed what the explainer's rule base forbids. "My planner let me
    /// put the ball on the blue block at step 1, but my rule E11 forbids it (impossible
    /// putdown(R, A, B) if has_size(B, small)): the blue block is small."
    pub fn say_planned(&self, v: &super::verbalize::Verbalizer<'_>) -> String {
        use super::verbalize::{ActionForm, Tense};
        let mut text = format!(
            "My planner let me {} {}, but my rule {} forbids it ({})",
            v.action(&self.action, ActionForm::Base),
            v.step(i64::from(self.step)),
            self.label,
            self.axiom
        );
        if !self.because.is_empty() {
            text.push_str(&format!(": {}", v.join(&self.because, Tense::Present)));
        }
        text.push('.');
        text
    }

    /// The surprise as JSON: `{"step", "action", "label", "axiom", "because"}`.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "step": self.step,
            "action": self.action.to_string(),
            "label": self.label,
            "axiom": self.axiom,
            "because": self.because.iter().map(Symbol::to_string).collect::<Vec<_>>(),
        })
    }
}

/// The predicate of the surprise assumptions: `lucent_surprise(K, A, I)` says the executability
/// condition of statement K did not stop action A at step I.
pub const SURPRISE: &str = "lucent_surprise";

/// Makes every executability condition of the translation defeasible for actions that
/// happened: statement K, `-occurs(A, I) :- body.`, gets the extra body literal
/// `not lucent_surprise(K, A, I)`, and the CR rule `lucent_surprise(K, A, I) :+ body,
/// hpd(A, I).` is appended, so the solver applies as few as it can and only when the history
/// is otherwise inconsistent. Returns the statement ids made defeasible.
fn allow_surprises(program: &mut ast::Program, origins: &[AxiomOrigin]) -> Vec<usize> {
    use ast::{Atom, BodyLiteral, ConditionalLiteral, Head, Literal, Sign, SymbolicAtom};
    use ast::{Term, TermKind};
    let mut made = Vec::new();
    let mut extra = Vec::new();
    for (k, st) in program.statements.iter_mut().enumerate() {
        let Some(o) = origins.get(k) else { continue };
        if o.kind != OriginKind::ExecutabilityCondition {
            continue;
        }
        let ast::StatementKind::Rule(rule) = &mut st.kind else {
            continue;
        };
        let Head::Disjunction(h) = &rule.head else {
            continue;
        };
        let [ConditionalLiteral { literal, .. }] = h.as_slice() else {
            continue;
        };
        let Atom::Symbolic(occurs) = &literal.atom else {
            continue;
        };
        if !occurs.negated || occurs.name.as_str() != "occurs" || occurs.args.len() != 1 {
            continue;
        }
        let [action, step] = occurs.args[0].as_slice() else {
            continue;
        };
        let span = st.span;
        let atom = |name: &str, args: Vec<Term>| SymbolicAtom {
            span,
            negated: false,
            name: name.into(),
            args: vec![args],
        };
        let surprise = atom(
            SURPRISE,
            vec![
                Term {
                    span,
                    kind: TermKind::Integer(k as i64),
                },
                action.clone(),
                step.clone(),
            ],
        );
        let mut cr_body = rule.body.clone();
        cr_body.push(BodyLiteral::Literal(Literal {
            span,
            sign: Sign::Positive,
            atom: Atom::Symbolic(atom("hpd", vec![action.clone(), step.clone()])),
        }));
        rule.body.push(BodyLiteral::Literal(Literal {
            span,
            sign: Sign::Not,
            atom: Atom::Symbolic(surprise.clone()),
        }));
        extra.push(ast::Statement {
            span,
            kind: ast::StatementKind::Rule(ast::Rule {
                head: Head::Disjunction(vec![ConditionalLiteral {
                    span,
                    literal: Literal {
                        span,
                        sign: Sign::Positive,
                        atom: Atom::Symbolic(surprise),
                    },
                    condition: Vec::new(),
                    has_colon: false,
                }]),
                body: cr_body,
                kind: ast::RuleKind::ConsistencyRestoring { label: None },
            }),
        });
        made.push(k);
    }
    program.statements.extend(extra);
    made
}

/// The learned axioms in the files of `sources`: every file that `lucent learn` wrote (its
/// statements introduced by `% learned axiom: strength …` comments, read back by
/// `learn::strength::Store::from_ald`), with their labels, strengths and AL_d text. A file
/// whose comments do not read back contributes none (its statements are still axioms, just
/// not cited as learned).
pub fn learned_axioms(sources: &SourceMap) -> Vec<LearnedAxiom> {
    let mut out = Vec::new();
    for k in 0..sources.len() {
        let text = &sources.get(crate::base::FileId(k as u32)).text;
        if !text.contains(LEARNED_PREFIX) {
            continue;
        }
        let Ok(store) = Store::from_ald(text) else {
            continue;
        };
        out.extend(store.axioms.iter().map(|l| LearnedAxiom {
            label: l.label.clone(),
            strength: l.strength,
            text: l.axiom.to_ald(),
        }));
    }
    out
}

impl History {
    /// The RA scenario of the questions over this history (executed: past tense).
    pub fn scenario(&self) -> Scenario<'_> {
        let mut scn = Scenario::ra(
            &self.oracle,
            self.plan.clone(),
            self.goal.clone(),
            self.last_step,
        );
        scn.learned = self.learned.clone();
        scn
    }

    /// The objects the history mentions (for the question parser): the constant arguments of
    /// the true `holds` and `occurs` literals and statics. Computed once, when the history is
    /// made (walking the answer set per question was most of a plan description's time).
    pub fn objects(&self) -> Vec<String> {
        self.objects.clone()
    }

    /// The objects of an answer set (see [`History::objects`]).
    fn objects_of(oracle: &ProgramOracle) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        for lit in oracle.true_literals() {
            if let Some("has_size" | "has_surface" | "object") = lit.name() {
                if let Some(Symbol::Function { name, args, .. }) = lit.arg(0) {
                    if args.is_empty() && !out.iter().any(|o| *name == *o) {
                        out.push(name.to_string());
                    }
                }
            }
        }
        out.sort();
        out
    }
}

/// The goal fluents of a description: the ground literals of its `goal` statements.
pub fn goal_of(desc: &Description) -> Vec<Symbol> {
    let mut out = Vec::new();
    for s in &desc.statements {
        if let StatementKind::Goal { body } = &s.kind {
            out.extend(body.iter().filter_map(|item| match item {
                action::ast::BodyItem::Lit(l) => crate::plan::problem::symbol_of_lit(l),
                action::ast::BodyItem::Compare { .. } => None,
            }));
        }
    }
    out
}

/// The atom that gates the history's facts: an external assigned true, hidden by the oracle.
pub const HISTORY_GATE: &str = "lucent_history_given";

/// The history's facts (`hpd(a,i).`, `holds(f,0).` of `initially`, `obs(...)`) get the body
/// [`HISTORY_GATE`], an external assigned true that the oracle hides (`Labels::hidden`), so they
/// read as facts in proofs. Grounding then decides nothing about the trajectory: a literal that
/// every rule instance would make a fact keeps all its rule instances (the grounder keeps only
/// the fact's rule when a head is a fact, and with the others would go supports a proof tree
/// needs, such as E7 next to E5). For the same reason every `hpd(a, i)` is external (false
/// unless it happened). Statement ids do not change; the declarations are appended.
fn gate_history(program: &mut ast::Program, origins: &[AxiomOrigin], labels: &mut Labels) {
    let gate = Symbol::constant(HISTORY_GATE);
    for (k, st) in program.statements.iter_mut().enumerate() {
        let Some(o) = origins.get(k) else { continue };
        if o.kind != OriginKind::History {
            continue;
        }
        let ast::StatementKind::Rule(rule) = &mut st.kind else {
            continue;
        };
        if !rule.body.is_empty()
            || rule.kind != ast::RuleKind::Normal
            || !matches!(&rule.head, ast::Head::Disjunction(h) if h.len() == 1)
        {
            continue;
        }
        rule.body.push(ast::BodyLiteral::Literal(ast::Literal {
            span: st.span,
            sign: ast::Sign::Positive,
            atom: ast::Atom::Symbolic(ast::SymbolicAtom {
                span: st.span,
                negated: false,
                name: HISTORY_GATE.into(),
                args: vec![Vec::new()],
            }),
        }));
    }
    // The gate, and every action at every step as a possible happening (false unless it
    // happened), so that the action CWA is not a fact and E7 keeps its instances beside it:
    // `#external lucent_history_given.` and `#external hpd(A, I) : action(A), step(I). [false]`.
    use crate::syntax::build::{atom, external, pos, var};
    let sp = crate::base::Span::default();
    let (a, i) = (var(sp, "A"), var(sp, "I"));
    program.statements.push(external(
        sp,
        atom(sp, false, HISTORY_GATE, Vec::new()),
        Vec::new(),
        None,
    ));
    program.statements.push(external(
        sp,
        atom(sp, false, "hpd", vec![a.clone(), i.clone()]),
        vec![
            pos(sp, false, "action", vec![a]),
            pos(sp, false, "step", vec![i]),
        ],
        Some("false"),
    ));
    labels.hidden.push(gate);
}

/// Whether the description declares a switch.
fn declares_switch(desc: &Description, name: &str) -> bool {
    desc.statements
        .iter()
        .any(|s| matches!(&s.kind, StatementKind::Switch { name: n, .. } if n.text == name))
}

/// A run saved by `lucent run` (its `--save-history` file, the JSON `--outf=2` prints) as the
/// planning problem it started from and what happened: a [`Problem`](crate::plan::Problem)
/// without a domain (the movable objects, the statics, what was perceived at step 0 and not
/// doubted as the initial state, the goal) for a description that provides the domain, and the
/// [`Steps`]. Every step keeps its number: an action the world reported as failed is an attempt
/// (the step has no action with an effect), and what the robot perceived (and did not doubt)
/// right after a failed attempt becomes observations of the next step, so the history follows
/// what the world did instead (an object that fell is where it was seen). `Err` names what the
/// run lacks.
pub fn scene_of_run(
    run: &crate::plan::history::History,
) -> Result<(crate::plan::Problem, Steps), String> {
    let first = run
        .steps
        .first()
        .ok_or("the run has no step: nothing was perceived")?;
    let mut problem = crate::plan::Problem {
        objects: Some(run.objects.clone()),
        ..Default::default()
    };
    let parse = |what: &str, t: &str| {
        Symbol::parse(t).map_err(|e| format!("the run's {what} `{t}` is not a ground term: {e}"))
    };
    for st in &run.statics {
        problem.statics.push(parse("static", st)?);
    }
    // The robot's belief after its first look, when the run recorded it: consistent by
    // construction, where the raw readings of a noisy camera may contradict each other.
    // Else the readings it did not doubt.
    let initial: Vec<&String> = if first.belief.is_empty() {
        first
            .observed
            .iter()
            .filter(|o| o.value && !first.doubted.contains(&o.fluent))
            .map(|o| &o.fluent)
            .collect()
    } else {
        first.belief.iter().collect()
    };
    let mut seen = Vec::new();
    for f in initial {
        if seen.contains(&f) {
            continue;
        }
        seen.push(f);
        problem.initially.push(parse("observation", f)?);
    }
    for g in &run.goal {
        problem.goal.push(parse("goal", g)?);
    }
    let mut steps = Steps::default();
    for (k, s) in run.steps.iter().enumerate() {
        let Some(a) = s.happened.as_deref() else {
            break;
        };
        let action = parse("action", a)?;
        match &s.failure {
            None => steps.actions.push(Some(action)),
            Some(why) => {
                steps.actions.push(None);
                steps.failed.push(Failed {
                    step: k as u32,
                    action,
                    why: why.clone(),
                });
                // What the next look saw of the attempted object: whether it is in the hand and
                // what it is on (the fluents the run loop compares with its predictions).
                let object = steps.failed.last().and_then(|f| f.action.arg(1)).cloned();
                if let (Some(next), Some(object)) = (run.steps.get(k + 1), object) {
                    let mut taken: Vec<&str> = Vec::new();
                    for o in &next.observed {
                        if next.doubted.contains(&o.fluent) || taken.contains(&o.fluent.as_str()) {
                            continue;
                        }
                        let f = parse("observation", &o.fluent)?;
                        let about = (f.is("in_hand", 2) && f.arg(1) == Some(&object))
                            || (f.is("relation", 3)
                                && f.arg(0).and_then(Symbol::name) == Some("on")
                                && f.arg(1) == Some(&object));
                        if about {
                            taken.push(&o.fluent);
                            steps.observed.push(((k + 1) as u32, f, o.value));
                        }
                    }
                }
            }
        }
    }
    Ok((problem, steps))
}

/// What happened, step by step, beyond the description's initial state: per step the action
/// that had its effect (`None`: none did, as when an attempt failed), the attempts that failed,
/// and observations of later steps.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Steps {
    /// Per step from 0, the action executed with its effect.
    pub actions: Vec<Option<Symbol>>,
    /// Attempts that failed in the world: step, action, why.
    pub failed: Vec<Failed>,
    /// Observations after step 0: step, fluent, value.
    pub observed: Vec<(u32, Symbol, bool)>,
}

/// An action the robot attempted that did not have its effect.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Failed {
    /// The step.
    pub step: u32,
    /// The action attempted.
    pub action: Symbol,
    /// Why it failed, as the world reported it.
    pub why: String,
}

impl Failed {
    /// "I tried to put the white pitcher on the table at step 1, but the release slipped."
    pub fn say(&self, v: &super::verbalize::Verbalizer<'_>) -> String {
        format!(
            "I tried to {} {}, but {}.",
            v.action(&self.action, super::verbalize::ActionForm::Base),
            v.step(i64::from(self.step)),
            self.why.trim_end_matches('.')
        )
    }

    /// `{"step", "action", "why"}`.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({"step": self.step, "action": self.action.to_string(), "why": self.why})
    }
}

/// An observation the history's knowledge did not predict, taken as it was seen.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unexpected {
    /// The step.
    pub step: u32,
    /// The fluent observed.
    pub fluent: Symbol,
    /// Its observed value.
    pub value: bool,
}

impl Unexpected {
    /// "At step 2 I saw that the white pitcher was not in my hand, which I had not expected."
    pub fn say(&self, v: &super::verbalize::Verbalizer<'_>) -> String {
        let lit = if self.value {
            self.fluent.clone()
        } else {
            match &self.fluent {
                Symbol::Function { name, args, .. } => Symbol::Function {
                    name: name.clone(),
                    args: args.clone(),
                    negative: true,
                },
                other => other.clone(),
            }
        };
        let step = v.step(i64::from(self.step));
        let mut step = step.trim().to_string();
        if let Some(first) = step.get(..1) {
            step = first.to_uppercase() + &step[1..];
        }
        format!(
            "{step} I saw that {}, which I had not expected.",
            v.fluent(&lit, super::verbalize::Tense::Past)
        )
    }

    /// `{"step", "fluent", "value"}`.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({"step": self.step, "fluent": self.fluent.to_string(), "value": self.value})
    }
}

/// The history of `desc` with `actions` (one per step, from step 0) executed, explained.
pub fn explain_history(
    desc: &Description,
    sources: &mut SourceMap,
    actions: &[Symbol],
    config: &HistoryConfig,
) -> Result<History, HistoryError> {
    let steps = Steps {
        actions: actions.iter().cloned().map(Some).collect(),
        ..Steps::default()
    };
    explain_steps(desc, sources, &steps, config)
}

/// The history of `desc` with `steps` (actions, failed attempts, later observations),
/// explained; see [`explain_history`].
/// `sources` holds the description's files.
pub fn explain_steps(
    desc: &Description,
    sources: &mut SourceMap,
    steps: &Steps,
    config: &HistoryConfig,
) -> Result<History, HistoryError> {
    let actions = &steps.actions;
    let problem = Problem {
        desc: desc.clone(),
        sources: sources.clone(),
        config: config.clone(),
    };
    let history = crate::plan::Problem {
        happened: actions
            .iter()
            .enumerate()
            .filter_map(|(i, a)| a.clone().map(|a| (a, i)))
            .collect(),
        observed: steps
            .observed
            .iter()
            .map(|(i, f, v)| {
                let l = if *v {
                    f.clone()
                } else {
                    f.complement().unwrap_or_else(|| f.clone())
                };
                (l, *i as usize)
            })
            .collect(),
        ..crate::plan::Problem::new(desc.clone(), sources.clone())
    };
    let desc = history.description();
    let mut overrides = config.overrides.clone();
    if declares_switch(&desc, "explanation_rule_base") {
        overrides.push(("explanation_rule_base".into(), Value::Bool(true)));
    }
    let options = Options {
        profile: config.profile.clone(),
        overrides,
        switches: Switches::history(actions.len()),
    };
    let t = action::translate(&desc, &options);
    if t.has_errors() {
        let mut d = Diagnostics::default();
        d.extend(t.diagnostics);
        return Err(HistoryError::Input(d.render(sources)));
    }
    let mut labels = Labels::from_origins(&t.origins);
    let mut program = t.program;
    gate_history(&mut program, &t.origins, &mut labels);
    let mut ctl_config = ControlConfig::default();
    ctl_config.ground.provenance = true;
    let solve = |program: ast::Program, sources: &SourceMap| -> Result<_, HistoryError> {
        let mut ctl = Control::with_sources(ctl_config.clone(), sources.clone());
        ctl.add_program(program)
            .map_err(|e| HistoryError::Input(e.message))?;
        ctl.ground(&[Part::base()])
            .map_err(|e| HistoryError::Input(e.message))?;
        ctl.assign_external(&Symbol::constant(HISTORY_GATE), TruthValue::True);
        let mut model = None;
        ctl.solve(&SolveOptions::default(), |m| {
            model = Some(m.raw().clone());
            false
        });
        Ok((ctl, model))
    };
    let mut repaired = (actions.iter().any(Option::is_some) || !steps.observed.is_empty())
        .then(|| program.clone());
    let (mut ctl, mut model) = solve(program, sources)?;
    let mut defeasible = Vec::new();
    if model.is_none() {
        if let Some(mut p) = repaired.take() {
            defeasible = allow_surprises(&mut p, &t.origins);
            allow_unexpected(&mut p);
            labels.hidden_predicates.push(SURPRISE.to_string());
            labels.hidden_predicates.push(UNEXPECTED.to_string());
            (ctl, model) = solve(p, sources)?;
        }
    }
    let Some(model) = model else {
        let plan: Vec<String> = actions
            .iter()
            .enumerate()
            .filter_map(|(i, a)| a.as_ref().map(|a| format!("{a}@{i}")))
            .collect();
        return Err(HistoryError::Inconsistent(if plan.is_empty() {
            "the initial state is inconsistent".into()
        } else {
            format!("the actions {} cannot all be executed", plan.join("; "))
        }));
    };
    let oracle =
        ProgramOracle::new(ctl, model, labels).map_err(|e| HistoryError::Input(e.to_string()))?;
    let surprises = if defeasible.is_empty() {
        Vec::new()
    } else {
        surprises_of(&oracle, &t.origins)
    };
    let mut unexpected: Vec<Unexpected> = oracle
        .true_literals()
        .into_iter()
        .filter(|l| l.is(UNEXPECTED, 3))
        .filter_map(|l| {
            let a = l.args();
            Some(Unexpected {
                step: u32::try_from(a[2].as_number()?).ok()?,
                fluent: a[0].clone(),
                value: a[1].name() == Some("true"),
            })
        })
        .collect();
    unexpected.sort_by_key(|u| (u.step, u.fluent.to_string()));
    Ok(History {
        surprises,
        unexpected,
        failed: steps.failed.clone(),
        learned: learned_axioms(&problem.sources),
        problem,
        objects: History::objects_of(&oracle),
        oracle,
        plan: actions
            .iter()
            .enumerate()
            .filter_map(|(i, a)| a.clone().map(|a| (i as u32, a)))
            .collect(),
        goal: goal_of(&desc),
        last_step: actions.len() as u32,
    })
}

/// The predicate of unexpected observations: `lucent_unexpected(F, V, I)` says fluent F was
/// observed with value V at step I > 0 although the history did not predict it.
pub const UNEXPECTED: &str = "lucent_unexpected";

/// Lets an observation after step 0 set its fluent's value where the history predicted
/// otherwise (a CR rule per value: applied only when needed, as few as possible); inertia
/// then carries the observed value on.
fn allow_unexpected(program: &mut ast::Program) {
    use crate::syntax::build::{atom, compare, constant, cr_rule, head_of, int, pos, rule, var};
    let s = crate::base::Span::default();
    let observed = |value: &str| vec![var(s, "F"), constant(s, value), var(s, "I")];
    // unexpected(F, V, I) :+ obs(F, V, I), I > 0.   for V in true, false
    for value in ["true", "false"] {
        program.statements.push(cr_rule(
            s,
            head_of(s, atom(s, false, UNEXPECTED, observed(value))),
            vec![
                pos(s, false, "obs", observed(value)),
                compare(s, var(s, "I"), ast::CmpOp::Gt, int(s, 0)),
            ],
        ));
    }
    // holds(F, I) :- unexpected(F, true, I).   -holds(F, I) :- unexpected(F, false, I).
    for value in ["true", "false"] {
        program.statements.push(rule(
            s,
            head_of(
                s,
                atom(s, value == "false", "holds", vec![var(s, "F"), var(s, "I")]),
            ),
            vec![pos(s, false, UNEXPECTED, observed(value))],
        ));
    }
}

/// The surprises of a repaired history's answer set: each true `lucent_surprise(K, A, I)`
/// with statement K's label and text, and the body literals of the ground instance of K that
/// would have forbidden A at I.
fn surprises_of(oracle: &ProgramOracle, origins: &[AxiomOrigin]) -> Vec<Surprise> {
    use super::tree::{BodyLiteral, Oracle};
    let mut out = Vec::new();
    for lit in oracle.true_literals() {
        if !lit.is(SURPRISE, 3) {
            continue;
        }
        let args = lit.args();
        let (Some(k), Some(step)) = (args[0].as_number(), args[2].as_number()) else {
            continue;
        };
        let Some(origin) = origins.get(k as usize) else {
            continue;
        };
        let action = args[1].clone();
        let label = origin.label.clone().unwrap_or_else(|| origin.text.clone());
        let head = Symbol::function("occurs", vec![action.clone(), Symbol::number(step)]);
        let forbidden = match head {
            Symbol::Function { name, args, .. } => Symbol::Function {
                name,
                args,
                negative: true,
            },
            other => other,
        };
        let because = oracle
            .rules_for(&forbidden)
            .into_iter()
            .filter(|r| r.label == label)
            .find(|r| {
                r.body.iter().all(|b| match b {
                    BodyLiteral::Pos(t) => oracle.holds(t),
                    BodyLiteral::Not(t) => !oracle.holds(t),
                    BodyLiteral::Test(_) => true,
                })
            })
            .map(|r| {
                r.body
                    .into_iter()
                    .filter_map(|b| match b {
                        BodyLiteral::Pos(t) if !is_sort_atom(&t) => Some(t),
                        _ => None,
                    })
                    .collect()
            })
            .unwrap_or_default();
        out.push(Surprise {
            step: step as u32,
            action,
            label,
            axiom: origin.text.clone(),
            because,
        });
    }
    out.sort_by(|a, b| (a.step, &a.label).cmp(&(b.step, &b.label)));
    out
}

/// Sort and step atoms of a rule body (`robot(rob1)`, `step(1)`), which say nothing about why.
fn is_sort_atom(t: &Symbol) -> bool {
    t.args().len() == 1
        && matches!(
            t.name(),
            Some("robot" | "object" | "location" | "thing" | "step" | "movable" | "height")
        )
}

/// Parses actions written `a@0; b@1` or one per line or `;` (`pickup(rob1,a)`), in step order;
/// an explicit `@i` must be the action's position.
pub fn parse_actions(text: &str) -> Result<Vec<Symbol>, String> {
    let mut out = Vec::new();
    for (k, part) in text
        .split([';', '\n'])
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .enumerate()
    {
        let (a, step) = match part.rsplit_once('@') {
            Some((a, s)) => (a.trim(), Some(s.trim())),
            None => (part, None),
        };
        let sym = Symbol::parse(a)
            .ok()
            .ok_or_else(|| format!("`{part}` is not an action term"))?;
        if let Some(s) = step {
            match s.parse::<usize>() {
                Ok(i) if i == k => {}
                _ => {
                    return Err(format!(
                        "`{part}`: actions must be given for steps 0, 1, ... in order"
                    ))
                }
            }
        }
        out.push(sym);
    }
    Ok(out)
}
