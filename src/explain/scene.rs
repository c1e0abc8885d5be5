//! Why the robot believes what it sees (feature `sim`): belief questions about a looked-at
//! scene ("why is the red cube unstable?", "why is the mug not occluded?") answered from the
//! proof tree over the classification-mode answer set of `vision::reason`, naming a learned
//! state constraint as answers name learned action axioms. A label that reasoning could not
//! decide was decided by the network; the answer says so instead of inventing a reason.
//!
//! Invariants: the program explained is the one `vision::reason::Knowledge::classify` solves
//! (same description, same options), grounded here with provenance; nothing is read from
//! files.

use super::english::{Parser, Question};
use super::lexicon::Lexicon;
use super::oracle::{Labels, ProgramOracle};
use super::questions::{self, Answer, Mode, Scenario, Session};
use super::tree::LearnedAxiom;
use crate::control::{Control, ControlConfig, Part, Symbol};
use crate::vision::classify::{Decision, Source};
use crate::vision::reason::{Knowledge, View};

/// Why a scene question got no answer.
#[derive(Clone, Debug, thiserror::Error, PartialEq, Eq)]
pub enum SceneWhyError {
    /// The question is not understood (the reply says what was not).
    #[error("{0}")]
    NotUnderstood(String),
    /// The question is not about a belief.
    #[error("ask why something is stable, unstable, occluded or not occluded")]
    NotABelief,
    /// The knowledge does not translate or ground.
    #[error("{0}")]
    Knowledge(String),
    /// Perception contradicts the knowledge: there is no answer set to explain.
    #[error("what I perceived contradicts my knowledge; I have no beliefs to explain")]
    NoAnswerSet,
    /// The answer failed.
    #[error("{0}")]
    Answer(String),
}

/// A scene question's answer: the English and, when reasoning decided, the proof tree's
/// answer.
#[derive(Clone, Debug)]
pub struct SceneAnswer {
    /// The English answer.
    pub text: String,
    /// The answer over the proof tree (absent when the network decided).
    pub answer: Option<Answer>,
}

/// Answers `question` about the view under `knowledge`; `decided` gives, per object and
/// label, the classifier's decision, so a label the network decided is answered as such.
pub fn why(
    knowledge: &Knowledge,
    view: &View,
    question: &str,
    lexicon: &Lexicon,
    decided: &dyn Fn(&str, &str) -> Option<Decision>,
) -> Result<SceneAnswer, SceneWhyError> {
    let names: Vec<&str> = view.objects.iter().map(|o| o.name.as_str()).collect();
    let parser = Parser::new(lexicon, &names);
    let q = parser
        .parse(question)
        .map_err(|e| SceneWhyError::NotUnderstood(parser.reply(&e)))?;
    let Question::Belief { literal, .. } = &q else {
        return Err(SceneWhyError::NotABelief);
    };
    let fluent = literal.name().unwrap_or("");
    let object = literal
        .args()
        .first()
        .map(|a| a.to_string())
        .unwrap_or_default();
    let label = match fluent {
        "stable" => "stability",
        "occluded" | "partially_occluded" => "occlusion",
        _ => "",
    };
    if let Some(d) = decided(&object, label) {
        if d.source == Source::Cnn || d.source == Source::Prior {
            let said = match (label, d.value) {
                ("stability", true) => "stable",
                ("stability", false) => "unstable",
                (_, true) => "occluded",
                (_, false) => "not occluded",
            };
            let how = if d.source == Source::Cnn {
                "my network judged it from the camera image"
            } else {
                "I could not tell, so I took what is most often true"
            };
            return Ok(SceneAnswer {
                text: format!(
                    "My knowledge could not decide whether the {} is {}; {how}: {said}.",
                    object.replace('_', " "),
                    if label == "stability" {
                        "stable"
                    } else {
                        "occluded"
                    }
                ),
                answer: None,
            });
        }
    }
    let by_reasoning = matches!(
        decided(&object, label).map(|d| d.source),
        Some(Source::Reasoning | Source::Learned(_))
    );
    let said = object.replace('_', " ");
    if by_reasoning && fluent == "stable" && !literal.is_negative() {
        return Ok(SceneAnswer {
            text: format!(
                "Because nothing I know makes the {said} unstable: it stands on {}.",
                support_chain(view, &object)
            ),
            answer: None,
        });
    }
    if by_reasoning && fluent == "occluded" && literal.is_negative() {
        return Ok(SceneAnswer {
            text: format!(
                "Because the {said} is behind no other object, and {} an object is hidden \
                 only by an object it is behind.",
                occlusion_rules(knowledge)
            ),
            answer: None,
        });
    }
    let translation = knowledge
        .translation(view)
        .map_err(|e| SceneWhyError::Knowledge(e.to_string()))?;
    let labels = Labels::from_origins(&translation.origins);
    let mut config = ControlConfig::default();
    config.solve.models = 1;
    config.ground.provenance = true;
    let mut ctl = Control::new(config);
    ctl.add_program(translation.program)
        .map_err(|e| SceneWhyError::Knowledge(e.message))?;
    ctl.ground(&[Part::base()])
        .map_err(|e| SceneWhyError::Knowledge(e.message))?;
    let solved = ctl.solve_all(&Default::default());
    let Some(model) = solved.models.into_iter().next() else {
        return Err(SceneWhyError::NoAnswerSet);
    };
    let oracle = ProgramOracle::new(ctl, model.raw, labels)
        .map_err(|e| SceneWhyError::Knowledge(e.to_string()))?;
    let mut scn = Scenario::ra(&oracle, Vec::new(), Vec::new(), 0);
    scn.learned = knowledge
        .learned
        .iter()
        .map(|(label, a)| LearnedAxiom {
            label: label.clone(),
            strength: 1.0,
            text: a.to_ald(),
        })
        .collect();
    let answer = questions::answer(&scn, lexicon, &q, Mode::Concise, &mut Session::default())
        .map_err(|e| SceneWhyError::Answer(e.to_string()))?;
    Ok(SceneAnswer {
        text: answer.text.clone(),
        answer: Some(answer),
    })
}

/// The literal a scene question asks about, for tests and JSON (`-stable(red_cube)`).
pub fn asked_literal(answer: &SceneAnswer) -> Option<&Symbol> {
    answer.answer.as_ref().and_then(|a| a.literals.first())
}

/// "the red box, which stands on the table" for an object's perceived supports, with the
/// attributes that matter for stability.
fn support_chain(view: &View, object: &str) -> String {
    let mut parts = Vec::new();
    let mut at = object.to_string();
    for _ in 0..view.objects.len() + 1 {
        let Some(r) = view
            .relations
            .iter()
            .find(|r| r.rel == crate::sim::Rel::On && r.a == at)
        else {
            break;
        };
        let below = r.b.clone();
        let what = match view.objects.iter().find(|o| o.name == below) {
            Some(o) => {
                let size = o.size.map_or("", |s| s.name());
                let surface = o.surface.map_or("", |s| s.name());
                format!("the {} ({size}, {surface})", below.replace('_', " "))
            }
            None => format!("the {}", below.replace('_', " ")),
        };
        parts.push(what);
        if below == "table" {
            break;
        }
        at = below;
    }
    if parts.is_empty() {
        "something I did not see".into()
    } else {
        parts.join(", which stands on ")
    }
}

/// The rules that rule out occluders: OC2 when the knowledge has it, and the learned
/// constraints with the head `-partially_occluded`, as "OC2 says" or "my learned constraint L1
/// says".
fn occlusion_rules(knowledge: &Knowledge) -> String {
    let mut rules = Vec::new();
    if !knowledge.removed.iter().any(|r| r == "OC2") {
        rules.push("OC2".to_string());
    }
    for (label, a) in &knowledge.learned {
        if a.head()
            .is_some_and(|h| h.name == "partially_occluded" && !h.positive)
        {
            rules.push(format!("my learned constraint {label} ({})", a.to_ald()));
        }
    }
    match rules.len() {
        0 => "I assume that".into(),
        _ => format!("{} says", rules.join(" and ")),
    }
}
