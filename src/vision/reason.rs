//! Reasoning as a classifier: the classification mode of the robot's knowledge base decides,
//! from the perceived relations and attributes of a scene, whether each object is stable and
//! whether it is occluded, or says that it cannot decide.
//!
//! Classification mode is the knowledge base (KB_full unless the caller gives another) at one
//! step with no planning module, without the planning constraint `never -stable(A)` (P1:
//! stability is the question here), and with `partially_occluded` exempt from the initial
//! closed-world default D0, so that occlusion is known only where a rule decides it. The scene
//! enters as AL_d statements built from values (`action::build`): the objects' sort, their
//! sizes and surfaces, and `initially relation(R, A, B)` for each perceived relation. Learned
//! state constraints join as labelled statements built from their lifted form.
//!
//! Decisions, over every answer set (at most [`MAX_MODELS`]):
//! - **unstable** when every answer set has `-stable(A)`;
//! - **stable** when no answer set has `-stable(A)` and every one gives A a tower height (a
//!   chain of `on` relations joins it to the table, so its supports are known);
//! - **occluded** when every answer set has `occluded(A)`;
//! - **not occluded** when every answer set has `-partially_occluded(A, B)` for every other
//!   object B of the view;
//! - otherwise, or when there is no answer set (perception contradicts the knowledge),
//!   **cannot decide**.
//!
//! Invariants: the decision is a function of the knowledge and the view; nothing is read from
//! files; no program text is printed to be parsed again.

use std::collections::{BTreeMap, BTreeSet};

use crate::action::ast::{Description, Statement, StatementKind};
use crate::action::build::{self, Arg};
use crate::action::translate::Translation;
use crate::action::Options;
use crate::action::{self, Switches};
use crate::base::SourceMap;
use crate::control::{Control, ControlConfig, Part, Symbol};
use crate::learn::term::{Axiom, AxiomKind, Literal};
use crate::sim::{Percept, Relation, Scene, Size, Surface};

/// Answer sets compared per decision; a view with more is "cannot decide" where they differ
/// beyond these.
pub const MAX_MODELS: usize = 16;

/// The labels of the knowledge base's statements that decide the labels (docs/domain.md
/// 2.1.2-2.1.3), the candidates for removal in the learning experiment.
pub const DECIDING: [&str; 5] = ["ST1", "ST2", "ST3", "D1", "OC2"];

/// What the robot perceives of one scene, as values.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct View {
    /// The objects in view with their perceived attributes (`None`: not perceived).
    pub objects: Vec<ViewObject>,
    /// The relations perceived to hold.
    pub relations: Vec<Relation>,
}

/// One perceived object.
#[derive(Clone, Debug, PartialEq)]
pub struct ViewObject {
    /// Its name.
    pub name: String,
    /// Its perceived size.
    pub size: Option<Size>,
    /// Its perceived surface.
    pub surface: Option<Surface>,
}

impl View {
    /// The view of a percept: every object of the scene that is not held, the attributes and
    /// the true relation facts perceived with enough confidence.
    pub fn from_percept(scene: &Scene, percept: &Percept) -> View {
        let mut objects: Vec<ViewObject> = scene
            .ids()
            .map(|id| scene.object(id))
            .filter(|o| scene.in_hand.as_deref() != Some(o.name.as_str()))
            .map(|o| ViewObject {
                name: o.name.clone(),
                size: None,
                surface: None,
            })
            .collect();
        let mut relations = Vec::new();
        for ob in percept.facts().filter(|o| o.value) {
            match &ob.literal {
                crate::sim::Literal::Relation(r) => relations.push(r.clone()),
                crate::sim::Literal::HasSize(o, s) => {
                    if let Some(v) = objects.iter_mut().find(|v| &v.name == o) {
                        v.size = Some(*s);
                    }
                }
                crate::sim::Literal::HasSurface(o, s) => {
                    if let Some(v) = objects.iter_mut().find(|v| &v.name == o) {
                        v.surface = Some(*s);
                    }
                }
                crate::sim::Literal::InHand(..) => {}
            }
        }
        relations.sort();
        relations.dedup();
        View { objects, relations }
    }

    /// The statements that put the view into a description.
    fn statements(&self) -> Vec<Statement> {
        let names: Vec<&str> = self.objects.iter().map(|o| o.name.as_str()).collect();
        let mut out = vec![build::sort("movable", &names), build::sort("unknown", &[])];
        for o in &self.objects {
            let c = Arg::constant(&o.name);
            if let Some(s) = o.size {
                out.push(build::fact(build::lit(
                    false,
                    "has_size",
                    &[c.clone(), Arg::constant(s.name())],
                )));
            }
            if let Some(s) = o.surface {
                out.push(build::fact(build::lit(
                    false,
                    "has_surface",
                    &[c.clone(), Arg::constant(s.name())],
                )));
            }
        }
        let known: BTreeSet<&str> = names.iter().copied().chain(["table"]).collect();
        for r in &self.relations {
            if !known.contains(r.a.as_str()) || !known.contains(r.b.as_str()) {
                continue;
            }
            out.push(build::initially(build::lit(
                false,
                "relation",
                &[
                    Arg::constant(r.rel.name()),
                    Arg::constant(&r.a),
                    Arg::constant(&r.b),
                ],
            )));
        }
        out
    }
}

/// Why classification could not run.
#[derive(Clone, Debug, thiserror::Error, PartialEq, Eq)]
pub enum ReasonError {
    /// The knowledge base (with the view and the learned constraints) does not translate.
    #[error("the knowledge base does not translate: {0}")]
    Translate(String),
    /// Grounding failed.
    #[error("grounding failed: {0}")]
    Ground(String),
}

/// The knowledge used for classification: a knowledge base, the statements removed from it and
/// the state constraints learned.
#[derive(Clone, Debug)]
pub struct Knowledge {
    /// The knowledge base as given.
    base: Description,
    /// The labels removed (with a default, its exceptions go too).
    pub removed: Vec<String>,
    /// Learned state constraints with their labels.
    pub learned: Vec<(String, Axiom)>,
}

impl Knowledge {
    /// KB_full (the knowledge base of `domains/ra/kb_full.ald`, built in).
    pub fn kb_full() -> Knowledge {
        let mut sources = SourceMap::default();
        let file = sources.add("kb_full.ald", action::KB_FULL);
        let parsed = action::parse(file, action::KB_FULL);
        debug_assert!(!parsed.has_errors(), "the built-in knowledge base parses");
        Knowledge::new(parsed.description)
    }

    /// A knowledge base with nothing removed and nothing learned.
    pub fn new(base: Description) -> Knowledge {
        Knowledge {
            base,
            removed: Vec::new(),
            learned: Vec::new(),
        }
    }

    /// The same knowledge without the statements labelled `labels`.
    pub fn without(mut self, labels: &[&str]) -> Knowledge {
        self.removed.extend(labels.iter().map(|l| l.to_string()));
        self
    }

    /// The same knowledge with `learned` state constraints added.
    pub fn with_learned(mut self, learned: Vec<(String, Axiom)>) -> Knowledge {
        self.learned.extend(learned);
        self
    }

    /// The classification-mode description of a view.
    pub fn description(&self, view: &View) -> Description {
        let removed: BTreeSet<&str> = self
            .removed
            .iter()
            .map(String::as_str)
            .chain(["P1"])
            .collect();
        let mut statements: Vec<Statement> = self
            .base
            .statements
            .iter()
            .filter(|s| {
                let label = s.label.as_ref().map(|l| l.text.as_str());
                // Profiles are switch bundles of other modes; they may drop removed labels.
                let of_removed = match &s.kind {
                    StatementKind::Exception { default, .. } => {
                        removed.contains(default.text.as_str())
                    }
                    StatementKind::Profile { .. } => true,
                    _ => false,
                };
                !of_removed && !label.is_some_and(|l| removed.contains(l))
            })
            .cloned()
            .collect();
        for s in &mut statements {
            if let StatementKind::InitialDefault { except } = &mut s.kind {
                if !except.iter().any(|n| n.text == "partially_occluded") {
                    except.push(crate::action::ast::Name {
                        span: Default::default(),
                        text: "partially_occluded".to_string(),
                    });
                }
            }
        }
        statements.extend(view.statements());
        for (label, axiom) in &self.learned {
            if let Some(st) = constraint_statement(label, axiom) {
                statements.push(st);
            }
        }
        Description { statements }
    }

    /// The classification-mode program of a view: one step, no planning module.
    pub fn translation(&self, view: &View) -> Result<Translation, ReasonError> {
        let desc = self.description(view);
        let options = Options {
            switches: Switches::history(0),
            ..Options::default()
        };
        let translation = action::translate(&desc, &options);
        if translation.has_errors() {
            let msgs: Vec<String> = translation
                .diagnostics
                .iter()
                .map(|d| d.message.clone())
                .collect();
            return Err(ReasonError::Translate(msgs.join("; ")));
        }
        Ok(translation)
    }

    /// Classifies every object of the view.
    pub fn classify(&self, view: &View) -> Result<Reasoning, ReasonError> {
        let translation = self.translation(view)?;
        let mut config = ControlConfig::default();
        config.solve.models = MAX_MODELS;
        config.solve.supports = false;
        let mut ctl = Control::new(config);
        ctl.add_program(translation.program)
            .map_err(|e| ReasonError::Ground(e.message))?;
        ctl.ground(&[Part::base()])
            .map_err(|e| ReasonError::Ground(e.message))?;
        let solved = ctl.solve_all(&Default::default());
        let models: Vec<Facts> = solved
            .models
            .iter()
            .map(|m| Facts::read(&m.atoms))
            .collect();
        let names: Vec<&str> = view.objects.iter().map(|o| o.name.as_str()).collect();
        let beliefs = names
            .iter()
            .map(|&name| decide(name, &names, &models))
            .collect();
        let state = solved
            .models
            .first()
            .map(|m| state_of(&m.atoms))
            .unwrap_or_default();
        Ok(Reasoning {
            beliefs,
            models: models.len(),
            state,
        })
    }
}

/// What reasoning concluded about one object (`None`: cannot decide).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Belief {
    /// The object.
    pub name: String,
    /// Stable, unstable, or cannot decide.
    pub stable: Option<bool>,
    /// Occluded, not occluded, or cannot decide.
    pub occluded: Option<bool>,
}

/// The classification of a view.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Reasoning {
    /// One belief per object of the view, in the view's order.
    pub beliefs: Vec<Belief>,
    /// The number of answer sets compared (0: perception contradicts the knowledge).
    pub models: usize,
    /// The step-0 literals of the first answer set in the vocabulary that scene understanding
    /// learns from ([`FEATURE_FLUENTS`], their statics, and the stability and occlusion
    /// literals of either sign), empty without an answer set.
    pub state: Vec<Literal>,
}

/// The fluents whose true step-0 literals describe an object for learning: the perceived
/// relations and the support-derived fluents.
pub const FEATURE_FLUENTS: [&str; 4] = ["relation", "small_base", "irreg_below", "tower_height"];

/// The statics that describe an object for learning.
pub const FEATURE_STATICS: [&str; 2] = ["has_size", "has_surface"];

/// The learner's literals of an answer set (see [`Reasoning::state`]).
fn state_of(atoms: &[Symbol]) -> Vec<Literal> {
    let mut out = Vec::new();
    for s in atoms {
        let name = s.name().unwrap_or("");
        if FEATURE_STATICS.contains(&name) && !s.is_negative() {
            out.extend(crate::learn::kb::literal_of(s));
            continue;
        }
        if name != "holds" || s.args().len() != 2 {
            continue;
        }
        let fluent = &s.args()[0];
        let fname = fluent.name().unwrap_or("");
        let keep = (FEATURE_FLUENTS.contains(&fname) && !s.is_negative())
            || matches!(fname, "stable" | "partially_occluded" | "occluded");
        if keep {
            if let Some(mut l) = crate::learn::kb::literal_of(fluent) {
                l.positive = !s.is_negative();
                out.push(l);
            }
        }
    }
    out.sort();
    out
}

impl Reasoning {
    /// The belief about `name`.
    pub fn belief(&self, name: &str) -> Option<&Belief> {
        self.beliefs.iter().find(|b| b.name == name)
    }
}

/// The step-0 literals of one answer set that decisions read.
#[derive(Default)]
struct Facts {
    unstable: BTreeSet<String>,
    height: BTreeSet<String>,
    occluded: BTreeSet<String>,
    /// Per object A, the B with `-partially_occluded(A, B)`.
    not_occluded_by: BTreeMap<String, BTreeSet<String>>,
}

impl Facts {
    fn read(atoms: &[Symbol]) -> Facts {
        let mut f = Facts::default();
        for s in atoms {
            if s.name() != Some("holds") || s.args().len() != 2 {
                continue;
            }
            let fluent = &s.args()[0];
            let arg = |i: usize| fluent.args().get(i).map(|a| a.to_string());
            match (fluent.name(), s.is_negative()) {
                (Some("stable"), true) => f.unstable.extend(arg(0)),
                (Some("tower_height"), false) => f.height.extend(arg(0)),
                (Some("occluded"), false) => f.occluded.extend(arg(0)),
                (Some("partially_occluded"), true) => {
                    if let (Some(a), Some(b)) = (arg(0), arg(1)) {
                        f.not_occluded_by.entry(a).or_default().insert(b);
                    }
                }
                _ => {}
            }
        }
        f
    }
}

fn decide(name: &str, names: &[&str], models: &[Facts]) -> Belief {
    let undecided = Belief {
        name: name.to_string(),
        stable: None,
        occluded: None,
    };
    if models.is_empty() {
        return undecided;
    }
    let all = |p: &dyn Fn(&Facts) -> bool| models.iter().all(p);
    let stable = if all(&|m| m.unstable.contains(name)) {
        Some(false)
    } else if all(&|m| !m.unstable.contains(name) && m.height.contains(name)) {
        Some(true)
    } else {
        None
    };
    let occluded = if all(&|m| m.occluded.contains(name)) {
        Some(true)
    } else if all(&|m| {
        let none = BTreeSet::new();
        let by = m.not_occluded_by.get(name).unwrap_or(&none);
        names.iter().all(|&b| b == name || by.contains(b))
    }) {
        Some(false)
    } else {
        None
    };
    Belief {
        stable,
        occluded,
        ..undecided
    }
}

/// A learned state constraint as a labelled AL_d statement (`None` for other kinds).
pub fn constraint_statement(label: &str, axiom: &Axiom) -> Option<Statement> {
    matches!(axiom.kind, AxiomKind::Constraint { .. }).then(|| axiom.statement(label))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sim::{Rel, Relation};

    fn obj(name: &str, size: Size, surface: Surface) -> ViewObject {
        ViewObject {
            name: name.into(),
            size: Some(size),
            surface: Some(surface),
        }
    }

    fn rel(rel: Rel, a: &str, b: &str) -> Relation {
        Relation {
            rel,
            a: a.into(),
            b: b.into(),
        }
    }

    /// a (small) on the table with b (large) on it; c (irregular) on the table with d on it;
    /// e on the table, behind a. By hand: b has a small base (SB) so D1 makes it unstable; d
    /// has an irregular object below (IB) so ST1 makes it unstable; a, c, e stand on the table
    /// and nothing says they are unstable, so they are stable. OC2 rules out every occluder
    /// but a for e (e is behind a): e cannot be decided; nothing else is behind anything, so
    /// every other object is not occluded.
    fn view() -> View {
        View {
            objects: vec![
                obj("a", Size::Small, Surface::Flat),
                obj("b", Size::Large, Surface::Flat),
                obj("c", Size::Medium, Surface::Irregular),
                obj("d", Size::Small, Surface::Flat),
                obj("e", Size::Large, Surface::Flat),
            ],
            relations: vec![
                rel(Rel::On, "a", "table"),
                rel(Rel::On, "b", "a"),
                rel(Rel::On, "c", "table"),
                rel(Rel::On, "d", "c"),
                rel(Rel::On, "e", "table"),
                rel(Rel::Behind, "e", "a"),
            ],
        }
    }

    fn decisions(r: &Reasoning) -> Vec<(String, Option<bool>, Option<bool>)> {
        r.beliefs
            .iter()
            .map(|b| (b.name.clone(), b.stable, b.occluded))
            .collect()
    }

    #[test]
    fn kb_full_decides_by_hand() {
        let r = Knowledge::kb_full().classify(&view()).unwrap();
        assert_eq!(r.models, 1);
        let s = |n: &str, st: Option<bool>, oc: Option<bool>| (n.to_string(), st, oc);
        assert_eq!(
            decisions(&r),
            vec![
                s("a", Some(true), Some(false)),
                s("b", Some(false), Some(false)),
                s("c", Some(true), Some(false)),
                s("d", Some(false), Some(false)),
                s("e", Some(true), None),
            ]
        );
    }

    /// Without ST1, d (on the irregular c) is no longer unstable: nothing else derives it.
    /// Without OC2 no occluder is ruled out, so no occlusion is decided.
    #[test]
    fn removing_a_constraint_changes_its_decisions() {
        let r = Knowledge::kb_full()
            .without(&["ST1", "OC2"])
            .classify(&view())
            .unwrap();
        let d = r.belief("d").unwrap();
        assert_eq!(d.stable, Some(true));
        assert!(r.beliefs.iter().all(|b| b.occluded.is_none()));
        assert_eq!(r.belief("b").unwrap().stable, Some(false));
    }

    /// A learned constraint restores what was removed.
    #[test]
    fn a_learned_constraint_decides_again() {
        let st1 = Axiom::parse_ald("-stable(O1) if irreg_below(O1)").unwrap();
        let r = Knowledge::kb_full()
            .without(&["ST1"])
            .with_learned(vec![("L1".into(), st1)])
            .classify(&view())
            .unwrap();
        assert_eq!(r.belief("d").unwrap().stable, Some(false));
    }

    /// An object whose support was not perceived has no tower height: cannot decide.
    #[test]
    fn an_unknown_support_cannot_be_decided() {
        let mut v = view();
        v.relations.retain(|r| !(r.rel == Rel::On && r.a == "e"));
        let r = Knowledge::kb_full().classify(&v).unwrap();
        assert_eq!(r.belief("e").unwrap().stable, None);
    }
}
