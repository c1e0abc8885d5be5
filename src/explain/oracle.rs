//! The adapter from the front door to proof trees: a [`ProgramOracle`] answers the
//! [`Oracle`] questions of `explain::tree` from a [`Control`] that grounded its program once
//! with provenance on, and one of its answer sets.
//!
//! What it gives the tree builder and the re-check:
//! - **Rule instances** with their body literals in program syntax. A ground rule has one
//!   instance per origin (`Provenance::origins`): its ground body plus the body literals that
//!   grounding decided and removed for that origin (facts, `not a` with `a` false), put back so
//!   a proof reaches the facts (E10's `has_surface(mug,irregular)`, the sort atoms). A CR rule
//!   `h :- b, appl.` is shown as `h :- b.` of kind [`AxiomKind::CrRule`], applied when its
//!   application atom is true. Auxiliary atoms (aggregates, conditions) are named
//!   `#aux(N)` with N the aspif atom, so their rules can be followed too.
//! - **Atoms grounding proved false** stay nameable: `rules_for` also returns the removed
//!   instances (`Provenance::dead_rules_for`), each with the body literal that killed it (and
//!   its origin's removed literals), so "why not" trees explain them.
//! - **Labels and kinds** per statement id from the caller ([`Labels`]): for an AL_d
//!   translation, from `action::AxiomOrigin` ([`Labels::from_origins`]); for any program, the
//!   statement's source location ([`Labels::from_program`]).
//! - **Truth**: an atom with an aspif number is true when the model has it; an atom without one
//!   is true when grounding made it a fact, false otherwise.
//!
//! Invariants: every rule instance returned has a head the caller asked for and a body read off the ground program and provenance, never off
//! a tree; the oracle owns its Control, so it can be kept and queried as long as needed.

// hashbrown with its default hasher (foldhash): the maps are keyed by every atom of the
// ground program, and SipHash was a fifth of `explain --why` on reachability (perf).
use hashbrown::{HashMap, HashSet};

use super::pattern::SymbolExt;
use super::tree::{AxiomKind, BodyLiteral, Oracle, RuleInstance};
use crate::action::{AxiomOrigin, OriginKind};
use crate::control::{Control, Symbol};
use crate::ground::program::{AuxKind, BodyRef, DeadReason, GAtom, HeadKind, RuleOrigin};
use crate::solve;
use crate::syntax::ast;

/// A statement's label and kind, indexed by statement id (the index of the statement in the
/// program the Control grounded).
#[derive(Clone, Debug, Default)]
pub struct Labels {
    /// `(label, kind)` per statement id.
    pub by_statement: Vec<(String, AxiomKind)>,
    /// Body atoms the caller added to its program and that proofs do not show (the gate of
    /// the history's facts, see `explain::history`).
    pub hidden: Vec<Symbol>,
    /// Predicates whose default-negated body literals proofs do not show (the surprise
    /// assumptions of a repaired history, see `explain::history`).
    pub hidden_predicates: Vec<String>,
    /// The statements as written, by statement id (any program's, for explanations at the
    /// source level, `explain::source`); empty for an AL_d translation.
    pub statements: Vec<ast::Statement>,
}

impl Labels {
    /// Labels of an AL_d translation: the statement's label (`E7`) or, for schemas without
    /// one, the schema's name (`inertia`, `CWA`); kinds from the origin's kind.
    pub fn from_origins(origins: &[AxiomOrigin]) -> Labels {
        let by_statement = origins
            .iter()
            .map(|o| {
                let kind = match o.kind {
                    OriginKind::Signature => AxiomKind::Sort,
                    OriginKind::Static => AxiomKind::Fact,
                    OriginKind::CausalLaw => AxiomKind::CausalLaw,
                    OriginKind::StateConstraint => AxiomKind::StateConstraint,
                    OriginKind::ExecutabilityCondition => AxiomKind::Executability,
                    OriginKind::Default => AxiomKind::Default,
                    OriginKind::CrException => AxiomKind::CrRule,
                    OriginKind::Never => AxiomKind::StateConstraint,
                    OriginKind::Inertia => AxiomKind::Inertia,
                    OriginKind::Cwa => AxiomKind::ClosedWorld,
                    OriginKind::History => AxiomKind::History,
                    OriginKind::Planning => AxiomKind::Planning,
                };
                let label = match (&o.label, o.kind) {
                    (Some(l), _) => l.clone(),
                    (None, OriginKind::Cwa) if o.statement.is_none() => "action CWA".into(),
                    (None, k) => match o.text.split(':').next() {
                        Some(t) if !t.trim().is_empty() && t.len() < 24 => t.trim().to_string(),
                        _ => k.name().to_string(),
                    },
                };
                (label, kind)
            })
            .collect();
        Labels {
            by_statement,
            hidden: Vec::new(),
            hidden_predicates: Vec::new(),
            statements: Vec::new(),
        }
    }

    /// Labels of any program: each statement's source location (`file:line:col`, from
    /// `locate`), kind [`AxiomKind::Fact`] for a fact (a rule without body) and
    /// [`AxiomKind::Rule`] otherwise.
    pub fn from_program(
        program: &ast::Program,
        locate: &dyn Fn(&ast::Statement) -> String,
    ) -> Self {
        let by_statement = program
            .statements
            .iter()
            .map(|s| {
                let fact = matches!(&s.kind, ast::StatementKind::Rule(r) if r.body.is_empty()
                    && matches!(r.kind, ast::RuleKind::Normal)
                    && matches!(&r.head, ast::Head::Disjunction(h) if h.len() == 1));
                let kind = if fact {
                    AxiomKind::Fact
                } else {
                    AxiomKind::Rule
                };
                (locate(s), kind)
            })
            .collect();
        Labels {
            by_statement,
            hidden: Vec::new(),
            hidden_predicates: Vec::new(),
            statements: program.statements.clone(),
        }
    }

    fn get(&self, origin: &RuleOrigin) -> (String, AxiomKind) {
        match origin {
            RuleOrigin::Statement { stmt, .. } => self
                .by_statement
                .get(*stmt as usize)
                .cloned()
                .unwrap_or_else(|| (format!("statement {stmt}"), AxiomKind::Rule)),
            RuleOrigin::Auxiliary { of_stmt, kind, .. } => {
                let (label, k) = self
                    .by_statement
                    .get(*of_stmt as usize)
                    .cloned()
                    .unwrap_or_else(|| (format!("statement {of_stmt}"), AxiomKind::Rule));
                (format!("{label} ({})", kind.name()), k)
            }
            RuleOrigin::Complement => ("complement".into(), AxiomKind::Rule),
        }
    }
}

/// Why an oracle could not be made.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum OracleError {
    /// The Control was grounded without provenance.
    #[error("the program was grounded without provenance")]
    NoProvenance,
}

/// Where a rule instance comes from.
#[derive(Clone, Copy, Debug)]
pub(super) enum Source {
    /// Ground rule `rule`, its origin number `origin` (or the rule without origins).
    Ground { rule: u32, origin: u32 },
    /// Dead rule `index` of the provenance, its origin `origin`.
    Dead { index: u32, origin: u32 },
}

/// An [`Oracle`] over a Control's ground program with provenance and one answer set (every
/// grounding's rules: `Control::provenance` numbers statements over all groundings, so labels
/// must too; `explain` grounds once).
pub struct ProgramOracle {
    pub(super) ctl: Control,
    pub(super) model: solve::Model,
    pub(super) labels: Labels,
    /// Symbol of each aspif atom (index = atom); auxiliary atoms get `#aux(N)`.
    pub(super) atom_term: Vec<Option<Symbol>>,
    /// Aspif atom of each term.
    pub(super) term_atom: HashMap<Symbol, u32>,
    /// Symbol of each grounder atom (index = g - 1); `None` for auxiliaries.
    pub(super) g_term: Vec<Option<Symbol>>,
    /// Grounder atom of each term.
    pub(super) term_g: HashMap<Symbol, GAtom>,
    /// Rule instances by head: a ground rule's under its aspif head atom, a rule grounding
    /// removed under [`DEAD`] | its grounder head atom (keyed by number, not by term: hashing
    /// and cloning a term per rule head was most of this constructor's time).
    heads: HashMap<u64, Vec<Source>>,
    /// The application atom of each CR rule (by rule index).
    pub(super) cr_appl: HashMap<u32, u32>,
    /// The labels of the applied CR rules.
    applied_labels: Vec<Symbol>,
}

/// The key bit of [`ProgramOracle::heads`] for rules grounding removed.
const DEAD: u64 = 1 << 32;

/// The aspif atom of an internal `#aux(N)` term.
fn aux_id(t: &Symbol) -> Option<u32> {
    match (t.name(), t.args()) {
        (Some("#aux"), [Symbol::Number(n)]) => u32::try_from(*n).ok(),
        _ => None,
    }
}

fn aux_term(atom: u32) -> Symbol {
    Symbol::function("#aux", vec![Symbol::Number(atom as i32)])
}

impl ProgramOracle {
    /// An oracle over `ctl` (grounded once, with provenance) and `model`, one of its answer
    /// sets, with the statements' labels.
    pub fn new(ctl: Control, model: solve::Model, labels: Labels) -> Result<Self, OracleError> {
        let prog = ctl.program();
        let prov = &prog.provenance;
        if prov.is_empty() {
            return Err(OracleError::NoProvenance);
        }
        let num_atoms = prog.num_atoms.max(ctl.num_atoms()) as usize;
        let mut atom_term: Vec<Option<Symbol>> = vec![None; num_atoms + 1];
        let mut term_atom = HashMap::new();
        for a in ctl.symbolic_atoms() {
            let t = a.symbol.clone();
            if let Some(slot) = atom_term.get_mut(a.atom as usize) {
                *slot = Some(t.clone());
            }
            term_atom.insert(t, a.atom);
        }
        let mut g_term = Vec::with_capacity(prov.atoms.len());
        let mut term_g = HashMap::new();
        for g in 1..=prov.atoms.len() as GAtom {
            let rec = prov.atom(g);
            // An atom of the ground program has its term already; the others are converted.
            let t = match rec.map(|r| r.aspif) {
                Some(a) if a != 0 => atom_term.get(a as usize).cloned().flatten(),
                _ => None,
            }
            .or_else(|| rec.and_then(|r| r.sym).map(|s| ctl.symbol_of_id(s)));
            if let Some(t) = &t {
                term_g.insert(t.clone(), g);
            }
            g_term.push(t);
        }
        let cr_atoms: HashSet<u32> = prog.cr_rules.iter().map(|c| c.appl).collect();
        let mut heads: HashMap<u64, Vec<Source>> = HashMap::new();
        let mut cr_appl = HashMap::new();
        for (i, r) in prog.rules.iter().enumerate() {
            if r.head.is_empty() {
                continue;
            }
            if let BodyRef::Normal(lits) = r.body {
                if let Some(&l) = lits
                    .iter()
                    .find(|&&l| l > 0 && cr_atoms.contains(&(l as u32)))
                {
                    cr_appl.insert(i as u32, l as u32);
                }
            }
            let n = prov.origins(i).len().max(1) as u32;
            for &h in r.head {
                if cr_atoms.contains(&h) {
                    continue;
                }
                let e = heads.entry(h as u64).or_default();
                for origin in 0..n {
                    e.push(Source::Ground {
                        rule: i as u32,
                        origin,
                    });
                }
            }
        }
        for (i, d) in prov.dead.iter().enumerate() {
            if matches!(d.why, DeadReason::Literal { .. }) {
                for &h in &d.head {
                    if let Some(Some(_)) = g_term.get(h as usize - 1) {
                        let e = heads.entry(DEAD | h as u64).or_default();
                        for origin in 0..d.origins.len().max(1) as u32 {
                            e.push(Source::Dead {
                                index: i as u32,
                                origin,
                            });
                        }
                    }
                }
            }
        }
        let applied_labels = model
            .cr_applied
            .iter()
            .map(|l| Symbol::from_cr_label(l))
            .collect();
        Ok(ProgramOracle {
            ctl,
            model,
            labels,
            atom_term,
            term_atom,
            g_term,
            term_g,
            heads,
            cr_appl,
            applied_labels,
        })
    }

    /// The Control (its program and provenance).
    pub fn control(&self) -> &Control {
        &self.ctl
    }

    /// The answer set.
    pub fn model(&self) -> &solve::Model {
        &self.model
    }

    /// Every true literal with a name (the answer set as terms).
    pub fn true_literals(&self) -> Vec<Symbol> {
        let mut out: Vec<Symbol> = self
            .model
            .atoms
            .iter()
            .filter_map(|&a| self.atom_term.get(a as usize).cloned().flatten())
            .collect();
        out.extend(self.g_facts_without_atom());
        out
    }

    fn g_facts_without_atom(&self) -> impl Iterator<Item = Symbol> + '_ {
        let prov = &self.ctl.program().provenance;
        prov.atoms.iter().enumerate().filter_map(|(i, r)| {
            (r.aspif == 0 && r.status == crate::ground::program::AtomStatus::Fact)
                .then(|| self.g_term[i].clone())
                .flatten()
        })
    }

    /// The labels of the applied CR rules (`d1x(mug,2)`).
    pub fn applied_labels(&self) -> &[Symbol] {
        &self.applied_labels
    }

    fn g_literal(&self, positive: bool, g: GAtom) -> Option<BodyLiteral> {
        let t = self.g_term.get((g as usize).checked_sub(1)?)?.clone()?;
        Some(if positive {
            BodyLiteral::Pos(t)
        } else {
            BodyLiteral::Not(t)
        })
    }

    fn atom_literal(&self, lit: i32) -> BodyLiteral {
        let a = lit.unsigned_abs();
        let t = self
            .atom_term
            .get(a as usize)
            .cloned()
            .flatten()
            .unwrap_or_else(|| aux_term(a));
        if lit > 0 {
            BodyLiteral::Pos(t)
        } else {
            BodyLiteral::Not(t)
        }
    }

    pub(super) fn instance(&self, head: &Symbol, src: Source) -> Option<RuleInstance> {
        let prog = self.ctl.program();
        let prov = &prog.provenance;
        match src {
            Source::Ground { rule, origin } => {
                let r = prog.rules.get(rule as usize);
                let origins = prov.origins(rule as usize);
                let o = origins.get(origin as usize);
                // The choice rule `{appl}.` of a CR rule is never a support of a named atom.
                if let Some(o) = o {
                    if matches!(
                        o.rule,
                        RuleOrigin::Auxiliary {
                            kind: AuxKind::CrApplication,
                            ..
                        }
                    ) {
                        return None;
                    }
                }
                let appl = self.cr_appl.get(&rule).copied();
                let mut body: Vec<BodyLiteral> = Vec::new();
                match r.body {
                    BodyRef::Normal(lits) => {
                        for &l in lits {
                            if appl == Some(l.unsigned_abs()) && l > 0 {
                                continue;
                            }
                            body.push(self.atom_literal(l));
                        }
                    }
                    BodyRef::Weight { lower, lits } => {
                        let text: Vec<String> = lits
                            .iter()
                            .map(|&(l, w)| {
                                let b = self.atom_literal(l);
                                let s = match b {
                                    BodyLiteral::Pos(t) => t.to_string(),
                                    BodyLiteral::Not(t) => format!("not {t}"),
                                    BodyLiteral::Test(s) => s,
                                };
                                format!("{w}:{s}")
                            })
                            .collect();
                        body.push(BodyLiteral::Test(format!(
                            "#sum{{{}}} >= {lower}",
                            text.join("; ")
                        )));
                    }
                }
                if let Some(o) = o {
                    for rl in &o.removed {
                        if let Some(b) = self.g_literal(rl.positive, rl.atom) {
                            if !body.contains(&b) {
                                body.push(b);
                            }
                        }
                    }
                }
                body.retain(|b| match b {
                    BodyLiteral::Pos(t) => !self.labels.hidden.contains(t),
                    BodyLiteral::Not(t) => !t
                        .name()
                        .is_some_and(|n| self.labels.hidden_predicates.iter().any(|h| h == n)),
                    BodyLiteral::Test(_) => true,
                });
                let (label, mut kind) = match o {
                    Some(o) => self.labels.get(&o.rule),
                    None => ("rule".into(), AxiomKind::Rule),
                };
                if appl.is_some() {
                    kind = AxiomKind::CrRule;
                }
                if r.head_kind == HeadKind::Choice
                    && matches!(kind, AxiomKind::Fact | AxiomKind::Sort | AxiomKind::Rule)
                {
                    kind = AxiomKind::Choice;
                }
                Some(RuleInstance {
                    label,
                    kind,
                    rule: Some(rule),
                    head: head.clone(),
                    body,
                })
            }
            Source::Dead { index, origin } => {
                let d = prov.dead.get(index as usize)?;
                let DeadReason::Literal { positive, atom } = d.why else {
                    return None;
                };
                let mut body = vec![self.g_literal(positive, atom)?];
                let o = d.origins.get(origin as usize);
                if let Some(o) = o {
                    for rl in &o.removed {
                        if let Some(b) = self.g_literal(rl.positive, rl.atom) {
                            if !body.contains(&b) {
                                body.push(b);
                            }
                        }
                    }
                }
                let (label, kind) = match o {
                    Some(o) => self.labels.get(&o.rule),
                    None => ("rule".into(), AxiomKind::Rule),
                };
                Some(RuleInstance {
                    label,
                    kind,
                    rule: None,
                    head: head.clone(),
                    body,
                })
            }
        }
    }
}

impl ProgramOracle {
    /// The source statement of a rule instance and its variable values: for a ground rule, its
    /// first origin with the instance's label (bindings from the provenance); for a removed
    /// instance, the statement with that label, bound by matching its head with the
    /// instance's. `None` without source statements (an AL_d translation).
    pub(super) fn origin_of(&self, r: &RuleInstance) -> Option<(usize, super::source::Bindings)> {
        let prov = &self.ctl.program().provenance;
        if let Some(i) = r.rule {
            for o in prov.origins(i as usize) {
                if !matches!(o.rule, RuleOrigin::Statement { .. })
                    || self.labels.get(&o.rule).0 != r.label
                {
                    continue;
                }
                let stmt = o.rule.stmt()? as usize;
                if stmt >= self.labels.statements.len() {
                    return None;
                }
                let mut b: super::source::Bindings = o
                    .rule
                    .bindings()
                    .iter()
                    .map(|&(n, v)| (self.ctl.name_of_id(n).to_string(), self.ctl.symbol_of_id(v)))
                    .collect();
                // Variables local to a head element (a choice's `C` in `{color(N,C) : color(C)}`)
                // are not among the statement's bindings: the head binds them.
                let s = &self.labels.statements[stmt];
                super::source::head_atoms(s)
                    .iter()
                    .any(|(a, _)| super::source::unify_atom(a, &r.head, &mut b));
                return Some((stmt, b));
            }
        }
        let stmt = self
            .labels
            .by_statement
            .iter()
            .position(|(l, _)| *l == r.label)?;
        let s = self.labels.statements.get(stmt)?;
        let mut b = Vec::new();
        super::source::head_atoms(s)
            .iter()
            .any(|(a, _)| super::source::unify_atom(a, &r.head, &mut b));
        Some((stmt, b))
    }
}

impl Oracle for ProgramOracle {
    fn holds(&self, literal: &Symbol) -> bool {
        if let Some(&a) = self.term_atom.get(literal) {
            return self.model.holds(a);
        }
        if literal.name() == Some("#aux") {
            if let Some(n) = literal.arg(0).and_then(Symbol::as_number) {
                return self.model.holds(n as u32);
            }
        }
        match self.term_g.get(literal) {
            Some(&g) => self
                .ctl
                .program()
                .provenance
                .atom(g)
                .is_some_and(|r| r.status == crate::ground::program::AtomStatus::Fact),
            None => false,
        }
    }

    fn rules_for(&self, head: &Symbol) -> Vec<RuleInstance> {
        // The ground rules (under the aspif atom), then the rules grounding removed.
        let ground = self
            .term_atom
            .get(head)
            .copied()
            .or_else(|| aux_id(head))
            .and_then(|a| self.heads.get(&(a as u64)));
        let dead = self
            .term_g
            .get(head)
            .and_then(|&g| self.heads.get(&(DEAD | g as u64)));
        let mut out: Vec<RuleInstance> = Vec::new();
        for &s in ground.into_iter().chain(dead).flatten() {
            if let Some(r) = self.instance(head, s) {
                if !out.contains(&r) {
                    out.push(r);
                }
            }
        }
        out
    }

    fn applied(&self, rule: &RuleInstance) -> bool {
        rule.kind == AxiomKind::CrRule
            && rule
                .rule
                .and_then(|r| self.cr_appl.get(&r))
                .is_some_and(|&a| self.model.holds(a))
    }
}
