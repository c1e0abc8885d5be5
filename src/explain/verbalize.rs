//! English out: ground literals, actions and answers in words (docs/domain.md 6.7).
//!
//! The phrases and answer templates are the lexicon's (data); this module fills them: constants
//! become "the" plus their words with a size suffix dropped (`green_can_large` -> "the green
//! can"); fluents are said in the past, present or future tense and statics always in the
//! present; `{be}`, `{have}` and `{can}` take the tense and, for a classically negated literal,
//! a "not" (unless the lexicon gives the negated phrase); literals that share the predicate,
//! sign, step and first argument are merged into one clause ("the red block was below the white
//! block and the green can").
//!
//! Invariants: every function here is total: a literal or action the lexicon has no phrase for is
//! said in the program's syntax ("scene_stable(2) held"), never dropped and never a panic; the
//! output never depends on hash order (groups keep the order of first appearance).

use super::english::join_and;
use super::lexicon::Lexicon;
use super::pattern::{Pattern, SymbolExt};
use crate::control::Symbol;

/// The tense of a clause.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tense {
    /// "was", after execution.
    Past,
    /// "is", for statics and the present state.
    Present,
    /// "will be", for a plan not yet executed.
    Future,
}

/// The form of an action phrase.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ActionForm {
    /// "pick up the green can"
    Base,
    /// "picked up the green can"
    Past,
    /// "will pick up the green can"
    Future,
}

/// Says literals, actions and answers in the words of a lexicon.
#[derive(Clone, Copy, Debug)]
pub struct Verbalizer<'a> {
    lexicon: &'a Lexicon,
    /// Say step 0 as "in the initial state" instead of "at step 0".
    pub initial_state_wording: bool,
}

/// A literal after its program wrapper is taken off.
enum Said<'t> {
    /// A fluent (from `holds`) or a static, with its sign and step.
    Fluent {
        fluent: &'t Symbol,
        negated: bool,
        step: Option<i32>,
        is_static: bool,
    },
    /// An action (from `occurs`), with its sign and step.
    Action { action: &'t Symbol, negated: bool },
}

impl<'a> Verbalizer<'a> {
    /// A verbalizer over a lexicon.
    pub fn new(lexicon: &'a Lexicon) -> Verbalizer<'a> {
        Verbalizer {
            lexicon,
            initial_state_wording: false,
        }
    }

    /// A constant in words: "the green can", "the table", "me"; numbers as digits.
    pub fn object(&self, t: &Symbol) -> String {
        match t {
            Symbol::Number(n) => n.to_string(),
            Symbol::String(s) => s.clone(),
            Symbol::Function { name, args, .. } if args.is_empty() && !name.is_empty() => {
                if let Some(words) = self.lexicon.names.get(name.as_str()) {
                    return words.clone();
                }
                let mut parts: Vec<&str> = name.split('_').filter(|p| !p.is_empty()).collect();
                if parts.len() > 1 && self.lexicon.sizes.contains(parts[parts.len() - 1]) {
                    parts.pop();
                }
                format!("the {}", parts.join(" "))
            }
            t => t.to_string(),
        }
    }

    /// A step phrase: "at step 3" (or "in the initial state" for 0 when asked for).
    pub fn step(&self, step: i64) -> String {
        if step == 0 && self.initial_state_wording {
            return self.lexicon.template("initial_state").to_string();
        }
        self.lexicon
            .template("step")
            .replace("{step}", &step.to_string())
    }

    /// An action phrase ("picked up the green can"); an action the lexicon has no verb for is
    /// said in the program's syntax.
    pub fn action(&self, action: &Symbol, form: ActionForm) -> String {
        self.action_pattern(&Pattern::from(action), form)
    }

    /// An action pattern as a phrase: a question's action whose target was not named
    /// (`putdown(rob1,a,_)`) says the variable as it is written.
    pub fn action_pattern(&self, action: &Pattern, form: ActionForm) -> String {
        for verb in &self.lexicon.verbs {
            let mut bindings = Vec::new();
            if verb.action.subsumes(action, &mut bindings) {
                let template = match form {
                    ActionForm::Past => &verb.past,
                    ActionForm::Base | ActionForm::Future => &verb.base,
                };
                let mut out = template.clone();
                for (var, value) in &bindings {
                    let words = match value.to_symbol() {
                        Some(s) => self.object(&s),
                        None => value.to_string(),
                    };
                    out = out.replace(&format!("{{{var}}}"), &words);
                }
                if form == ActionForm::Future {
                    out = format!("will {out}");
                }
                return out;
            }
        }
        match form {
            ActionForm::Past => format!("did {action}"),
            ActionForm::Base => format!("do {action}"),
            ActionForm::Future => format!("will do {action}"),
        }
    }

    /// Takes the program wrapper off a literal.
    fn unwrap<'t>(&self, lit: &'t Symbol) -> Said<'t> {
        let step = lit.arg(1).and_then(Symbol::as_number);
        match (lit.name(), lit.args().len()) {
            (Some("holds"), 2) => Said::Fluent {
                fluent: &lit.args()[0],
                negated: lit.is_negative(),
                step,
                is_static: false,
            },
            (Some("occurs"), 2) => Said::Action {
                action: &lit.args()[0],
                negated: lit.is_negative(),
            },
            _ => Said::Fluent {
                fluent: lit,
                negated: false,
                step: None,
                is_static: true,
            },
        }
    }

    /// A program literal as a clause: `holds(relation(on,a,b),0)` -> "the a was on the b";
    /// `-occurs(pickup(rob1,a),2)` -> "I did not pick up the a"; statics in the present tense.
    /// The step is not said.
    pub fn clause(&self, lit: &Symbol, tense: Tense) -> String {
        self.clause_with(lit, tense, None, None)
    }

    /// A fluent literal without its `holds` wrapper (`relation(on,a,b)`, `-stable(a)`).
    pub fn fluent(&self, fluent: &Symbol, tense: Tense) -> String {
        let (template, bindings) = self.fluent_template(fluent, false);
        let tense = if self.is_static(fluent) {
            Tense::Present
        } else {
            tense
        };
        self.fill(&template, &bindings, tense, None, None)
    }

    /// A literal as a small clause without its verb, for "I observed ⟨…⟩": "the green can on
    /// the white block"; a literal whose phrase has no `{be}` becomes "that" plus its past
    /// clause.
    pub fn bare(&self, lit: &Symbol) -> String {
        match self.unwrap(lit) {
            Said::Fluent {
                fluent,
                negated,
                is_static,
                ..
            } => {
                let (template, bindings, is_static) =
                    self.fluent_phrase(fluent, negated, is_static);
                if template.contains("{be} ") && !is_static {
                    let t = template.replace("{be} ", "");
                    self.fill(&t, &bindings, Tense::Past, None, None)
                } else {
                    format!("that {}", self.clause(lit, Tense::Past))
                }
            }
            Said::Action { .. } => format!("that {}", self.clause(lit, Tense::Past)),
        }
    }

    /// Whether a fluent or static term is a static of the lexicon.
    fn is_static(&self, fluent: &Symbol) -> bool {
        self.lexicon.properties.iter().any(|p| {
            let mut b = Vec::new();
            p.is_static && p.literal.positive().matches(&fluent.positive(), &mut b)
        })
    }

    /// A fluent's phrase template and bindings ([`Self::fluent_template`]), and whether it is
    /// a static: as its literal says (`is_static`) or as the domain declares it.
    fn fluent_phrase(
        &self,
        fluent: &Symbol,
        negated: bool,
        is_static: bool,
    ) -> (String, Vec<(String, Symbol)>, bool) {
        let (template, bindings) = self.fluent_template(fluent, negated);
        (template, bindings, is_static || self.is_static(fluent))
    }

    /// The clause template of a fluent (sign folded in) and its bindings.
    fn fluent_template(&self, fluent: &Symbol, negated: bool) -> (String, Vec<(String, Symbol)>) {
        let negated = negated ^ fluent.is_negative();
        let positive = fluent.positive();
        if positive.name() == Some("relation") && positive.args().len() == 3 {
            let args = positive.args();
            let name = args[0].name().unwrap_or("");
            let say = self
                .lexicon
                .relations
                .iter()
                .find(|r| r.name == name)
                .map(|r| r.say.clone())
                .unwrap_or_else(|| format!("in relation {} to", args[0]));
            let verb = if negated { "{be_not}" } else { "{be}" };
            return (
                format!("{{X}} {verb} {say} {{Y}}"),
                vec![
                    ("X".to_string(), args[1].clone()),
                    ("Y".to_string(), args[2].clone()),
                ],
            );
        }
        // A property, matched with its own sign first ("-stable(X)" is "unstable"), then
        // through its complement with the verb negated.
        let signed = if negated {
            positive.complement().unwrap_or(positive.clone())
        } else {
            positive.clone()
        };
        for p in &self.lexicon.properties {
            let mut b = Vec::new();
            if p.literal.matches(&signed, &mut b) {
                return (p.say.clone(), b);
            }
        }
        for p in &self.lexicon.properties {
            let mut b = Vec::new();
            if let Some(c) = p.literal.complement() {
                if c.matches(&signed, &mut b) {
                    let t = match &p.negated {
                        Some(n) => n.clone(),
                        None => negate_first_verb(&p.say),
                    };
                    return (t, b);
                }
            }
        }
        let verb = if negated { "{hold_not}" } else { "{hold}" };
        (
            format!("{{X}} {verb}"),
            vec![("X".to_string(), Symbol::String(positive.to_string()))],
        )
    }

    /// Fills a clause template: objects, numbers and verbs in the tense; `subject` replaces
    /// the `{X}` object's words ("it"); `last` replaces the words of the template's last
    /// object (a merged list).
    fn fill(
        &self,
        template: &str,
        bindings: &[(String, Symbol)],
        tense: Tense,
        subject: Option<&str>,
        last: Option<&str>,
    ) -> String {
        let mut out = template.to_string();
        let last_var = last_placeholder(template);
        for (var, value) in bindings {
            let hole = format!("{{{var}}}");
            let words = if var == "X" && subject.is_some() {
                subject.unwrap_or_default().to_string()
            } else if Some(var.as_str()) == last_var.as_deref() && last.is_some() {
                last.unwrap_or_default().to_string()
            } else {
                self.object(value)
            };
            out = out.replace(&hole, &words);
        }
        for (hole, forms) in VERB_FORMS {
            let i = match tense {
                Tense::Past => 0,
                Tense::Present => 1,
                Tense::Future => 2,
            };
            out = out.replace(hole, forms[i]);
        }
        out
    }

    /// A program literal as a clause with an optional subject word ("it").
    fn clause_with(
        &self,
        lit: &Symbol,
        tense: Tense,
        subject: Option<&str>,
        last: Option<&str>,
    ) -> String {
        match self.unwrap(lit) {
            Said::Fluent {
                fluent,
                negated,
                is_static,
                ..
            } => {
                let (template, bindings, is_static) =
                    self.fluent_phrase(fluent, negated, is_static);
                let tense = if is_static { Tense::Present } else { tense };
                self.fill(&template, &bindings, tense, subject, last)
            }
            Said::Action {
                action, negated, ..
            } => {
                let form = match tense {
                    Tense::Past => ActionForm::Past,
                    Tense::Present => ActionForm::Base,
                    Tense::Future => ActionForm::Future,
                };
                if negated {
                    let aux = match tense {
                        Tense::Past => "did not",
                        Tense::Present => "do not",
                        Tense::Future => "will not",
                    };
                    format!("I {aux} {}", self.action(action, ActionForm::Base))
                } else {
                    format!("I {}", self.action(action, form))
                }
            }
        }
    }

    /// Literals as clauses, merging those that share sign, predicate (the relation for
    /// `relation/3`), first argument and step and differ only in their last object: "the red
    /// block was below the white block and the green can". Order of first appearance.
    pub fn clauses(&self, lits: &[Symbol], tense: Tense) -> Vec<String> {
        let mut groups: Vec<(String, Vec<&Symbol>)> = Vec::new();
        for lit in lits {
            let key = self.merge_key(lit);
            match groups.iter_mut().find(|(k, _)| *k == key) {
                Some((_, members)) => {
                    if !members.contains(&lit) {
                        members.push(lit)
                    }
                }
                None => groups.push((key, vec![lit])),
            }
        }
        groups
            .into_iter()
            .map(|(_, members)| {
                if members.len() == 1 {
                    return self.clause(members[0], tense);
                }
                let objects: Vec<String> = members
                    .iter()
                    .map(|m| self.object(last_object(m).unwrap_or(m)))
                    .collect();
                self.clause_with(members[0], tense, None, Some(&join_and(&objects)))
            })
            .collect()
    }

    /// Literals merged and joined: "a", "a and b", "a, b, and c".
    pub fn join(&self, lits: &[Symbol], tense: Tense) -> String {
        join_and(&self.clauses(lits, tense))
    }

    /// The grouping key of a literal for merging: the literal with its last object argument
    /// blanked; literals without such an argument get a key of their own.
    fn merge_key(&self, lit: &Symbol) -> String {
        match self.unwrap(lit) {
            Said::Fluent {
                fluent,
                negated,
                step,
                ..
            } => {
                // Merge over the template's last object when it is not the subject: relations
                // ("below the white block and the green can"), never `in_hand` or statics.
                let (template, _) = self.fluent_template(fluent, negated);
                let last = last_placeholder(&template);
                if fluent.args().is_empty() || last.is_none() || last.as_deref() == Some("X") {
                    return lit.to_string();
                }
                let mut blank = Pattern::from(fluent);
                if let Pattern::Fun { args, .. } = &mut blank {
                    let n = args.len();
                    args[n - 1] = Pattern::Var("_".into());
                }
                format!("{negated}|{blank}|{step:?}")
            }
            Said::Action { .. } => lit.to_string(),
        }
    }

    /// Fills an answer template of the lexicon (one of `lexicon::TEMPLATES`), capitalized.
    pub fn template(&self, name: &str, holes: &[(&str, &str)]) -> String {
        let mut out = self.lexicon.template(name).to_string();
        for (hole, text) in holes {
            out = out.replace(&format!("{{{hole}}}"), text);
        }
        capitalize(&out)
    }

    /// A plan: one sentence per action, in step order ("I picked up the green can. I put the
    /// green can on the table."), past tense after execution, future tense before.
    pub fn plan(&self, actions: &[(u32, Symbol)], executed: bool) -> String {
        let mut sorted: Vec<&(u32, Symbol)> = actions.iter().collect();
        sorted.sort_by_key(|(step, _)| *step);
        let form = if executed {
            ActionForm::Past
        } else {
            ActionForm::Future
        };
        sorted
            .iter()
            .map(|(_, a)| self.template("plan_step", &[("action", &self.action(a, form))]))
            .collect::<Vec<_>>()
            .join(" ")
    }

    /// Why-X (docs/domain.md 6.4): "Because I had to ⟨a_j⟩, and ⟨ℓ⟩." with "it" for ℓ's subject
    /// when it is `a_j`'s object.
    pub fn why_action(&self, later: &Symbol, reason: &Symbol, tense: Tense) -> String {
        let object = later.arg(1);
        let subject = reason_subject(reason);
        let it = (object.is_some() && subject == object).then_some("it");
        let clause = self.clause_with(reason, tense, it, None);
        self.template(
            "why",
            &[
                ("action", &self.action(later, ActionForm::Base)),
                ("literal", &clause),
            ],
        )
    }

    /// Why-X when the action achieves a goal literal directly: "Because I had to get ⟨goal⟩."
    pub fn why_goal(&self, goal: &[Symbol]) -> String {
        let parts: Vec<String> = goal.iter().map(|g| self.bare(g)).collect();
        self.template("why_goal", &[("goal", &join_and(&parts))])
    }

    /// Why-not (docs/domain.md 6.5): "Because ⟨ℓ1⟩[, and ⟨ℓ2⟩]."
    pub fn why_not(&self, lits: &[Symbol], tense: Tense) -> String {
        self.template("why_not", &[("literals", &self.join(lits, tense))])
    }

    /// Why-not with an observation: "Because I observed ⟨ℓ⟩ at step I."
    pub fn why_not_observed(&self, lit: &Symbol, step: i64) -> String {
        self.template(
            "why_not_observed",
            &[("literal", &self.bare(lit)), ("step", &self.step(step))],
        )
    }

    /// Why-not fallback: "Because ⟨A⟩ is not related to the goal."
    pub fn why_not_unrelated(&self, object: &Symbol) -> String {
        self.template("why_not_unrelated", &[("object", &self.object(object))])
    }

    /// Why-not fallback: "Because that action was not part of my plan."
    pub fn why_not_not_planned(&self) -> String {
        self.template("why_not_not_planned", &[])
    }

    /// The action did occur: "I did ⟨X⟩ at step I."
    pub fn did_it(&self, action: &Symbol, step: i64) -> String {
        self.template(
            "did_it",
            &[
                ("action", &self.action(action, ActionForm::Base)),
                ("step", &self.step(step)),
            ],
        )
    }

    /// Belief with an action origin: "Because I ⟨past action⟩ at step J."
    pub fn belief_action(&self, action: &Symbol, step: i64) -> String {
        self.template(
            "belief_action",
            &[
                ("action", &self.action(action, ActionForm::Past)),
                ("step", &self.step(step)),
            ],
        )
    }

    /// Belief with an observation origin: "Because I observed ⟨ℓ⟩ at step J."
    pub fn belief_observed(&self, lit: &Symbol, step: i64) -> String {
        self.template(
            "belief_observed",
            &[("literal", &self.bare(lit)), ("step", &self.step(step))],
        )
    }

    /// Belief in a static: "That is a fact stored in my knowledge base."
    pub fn belief_static(&self) -> String {
        self.template("belief_static", &[])
    }

    /// Belief in a defined fluent: "Because ⟨ℓ1⟩, …, and ⟨ℓk⟩."
    pub fn belief_frontier(&self, lits: &[Symbol], tense: Tense) -> String {
        self.template("belief_frontier", &[("literals", &self.join(lits, tense))])
    }

    /// Belief from an applied CR rule: "Because I assumed that ⟨ℓ⟩, as an exception to the
    /// default that ⟨default⟩; otherwise the goal could not be achieved."
    pub fn belief_assumed(&self, assumed: &Symbol, default: &Symbol, tense: Tense) -> String {
        self.template(
            "belief_assumed",
            &[
                ("literal", &self.clause(assumed, tense)),
                ("default", &self.clause(default, Tense::Present)),
            ],
        )
    }

    /// The literal is not in the answer set: "I did not believe that ⟨Y⟩ at step I."
    pub fn not_believed(&self, lit: &Symbol, step: i64, tense: Tense) -> String {
        self.template(
            "not_believed",
            &[
                ("literal", &self.clause(lit, tense)),
                ("step", &self.step(step)),
            ],
        )
    }
}

/// The tense forms of the template verbs: past, present, future.
const VERB_FORMS: &[(&str, [&str; 3])] = &[
    ("{be_not}", ["was not", "is not", "will not be"]),
    ("{be}", ["was", "is", "will be"]),
    (
        "{have_not}",
        ["did not have", "does not have", "will not have"],
    ),
    ("{have}", ["had", "has", "will have"]),
    ("{can_not}", ["could not", "cannot", "will not be able to"]),
    ("{can}", ["could", "can", "will be able to"]),
    (
        "{hold_not}",
        ["did not hold", "does not hold", "will not hold"],
    ),
    ("{hold}", ["held", "holds", "will hold"]),
];

/// "{X} {be} unstable" -> "{X} {be_not} unstable".
fn negate_first_verb(template: &str) -> String {
    let mut best: Option<(usize, &str)> = None;
    for verb in ["{be}", "{have}", "{can}"] {
        if let Some(i) = template.find(verb) {
            if best.is_none_or(|(j, _)| i < j) {
                best = Some((i, verb));
            }
        }
    }
    match best {
        Some((i, verb)) => {
            let negated = format!("{}_not}}", &verb[..verb.len() - 1]);
            format!(
                "{}{}{}",
                &template[..i],
                negated,
                &template[i + verb.len()..]
            )
        }
        None => format!("it is not so that {template}"),
    }
}

/// The last object placeholder of a template (`{Y}` in "{X} {be} on {Y}").
fn last_placeholder(template: &str) -> Option<String> {
    let mut last = None;
    let mut rest = template;
    while let Some(i) = rest.find('{') {
        let Some(j) = rest[i..].find('}') else { break };
        let name = &rest[i + 1..i + j];
        if name.len() == 1 && name.chars().all(|c| c.is_ascii_uppercase()) {
            last = Some(name.to_string());
        }
        rest = &rest[i + j + 1..];
    }
    last
}

/// The last argument of a literal's fluent (the object a merge lists).
fn last_object(lit: &Symbol) -> Option<&Symbol> {
    let fluent = if lit.name() == Some("holds") {
        lit.arg(0)?
    } else {
        lit
    };
    fluent.args().last()
}

/// The subject object of a literal (`A` of `relation(S, A, B)`, `A` of `in_hand(R, A)`, the
/// first argument otherwise).
fn reason_subject(lit: &Symbol) -> Option<&Symbol> {
    let fluent = if lit.name() == Some("holds") {
        lit.arg(0)?
    } else {
        lit
    };
    match fluent.name() {
        Some("relation") | Some("in_hand") => fluent.arg(1),
        _ => fluent.arg(0),
    }
}

fn capitalize(s: &str) -> String {
    let mut chars = s.chars();
    match chars.next() {
        Some(c) => c.to_uppercase().chain(chars).collect(),
        None => String::new(),
    }
}
