//! Learned axioms as knowledge, with a strength that decays (DOMAIN.md 5.9 [ours]).
//!
//! A learned axiom starts at strength 1; after each learning episode its strength is multiplied
//! by `e^(-λ)` with `λ = ln 2 / 5` (a half-life of five episodes); learning it again (equal or a
//! version, 5.10) or using it refreshes it to 1; below 0.1 it is removed. Hand-written axioms
//! are not in the store and never decay.
//!
//! The store renders as an AL_d file: one labelled statement per axiom, preceded by a comment
//! with its strength and provenance, so the planner and the explainer load it as ordinary AL_d
//! while the learner reads the strengths back.
//!
//! Invariants: every stored axiom is canonical (5.8) and appears once; labels `L1, L2, …` are
//! never reused within a store.

use super::score;
use super::term::Axiom;

/// The decay rate per episode: `ln 2 / 5`.
pub fn lambda() -> f64 {
    std::f64::consts::LN_2 / 5.0
}

/// Axioms below this strength are removed.
pub const REMOVAL_THRESHOLD: f64 = 0.1;

/// One learned axiom.
#[derive(Clone, Debug, PartialEq)]
pub struct Learned {
    /// The AL_d label (`L3`).
    pub label: String,
    /// The axiom, canonical.
    pub axiom: Axiom,
    /// The current strength in (0, 1].
    pub strength: f64,
    /// The run, episode and trial of the surprise it was learned from.
    pub origin: Origin,
    /// The number of trees that voted for it.
    pub votes: usize,
}

/// Where a learned axiom came from.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Origin {
    /// Episode index within the run.
    pub episode: usize,
    /// The trial (within the episode) that detected the surprise.
    pub trial: usize,
    /// The surprising ground action and the unexpected or extra literals, as text for people.
    pub surprise: String,
}

/// The learned axioms of one knowledge base.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Store {
    /// The axioms, in order of learning.
    pub axioms: Vec<Learned>,
    /// The next label number.
    next_label: usize,
}

/// What [`Store::learn`] did with an axiom.
#[derive(Clone, Debug, PartialEq)]
pub enum Added {
    /// A new axiom with this label.
    New(String),
    /// An existing axiom (equal or a version) was refreshed.
    Refreshed(String),
}

impl Store {
    /// Adds a learned axiom, or refreshes an equal one or a version of it.
    pub fn learn(&mut self, axiom: Axiom, votes: usize, origin: Origin) -> Added {
        let axiom = axiom.canonical();
        if let Some(existing) = self
            .axioms
            .iter_mut()
            .find(|l| score::version(&l.axiom, &axiom))
        {
            existing.strength = 1.0;
            return Added::Refreshed(existing.label.clone());
        }
        self.next_label += 1;
        let label = format!("L{}", self.next_label);
        self.axioms.push(Learned {
            label: label.clone(),
            axiom,
            strength: 1.0,
            origin,
            votes,
        });
        Added::New(label)
    }

    /// Refreshes the axiom with this label (it supported a belief the robot acted on or an
    /// explanation).
    pub fn used(&mut self, label: &str) {
        if let Some(l) = self.axioms.iter_mut().find(|l| l.label == label) {
            l.strength = 1.0;
        }
    }

    /// The end of a learning episode: every axiom decays; the ones below the threshold are
    /// removed and returned.
    pub fn end_episode(&mut self) -> Vec<Learned> {
        let factor = (-lambda()).exp();
        for l in &mut self.axioms {
            l.strength *= factor;
        }
        let (keep, gone): (Vec<Learned>, Vec<Learned>) = self
            .axioms
            .drain(..)
            .partition(|l| l.strength >= REMOVAL_THRESHOLD);
        self.axioms = keep;
        gone
    }

    /// The axioms as they are.
    pub fn current(&self) -> Vec<Axiom> {
        self.axioms.iter().map(|l| l.axiom.clone()).collect()
    }

    /// The store as an AL_d file.
    pub fn to_ald(&self) -> String {
        let mut out = String::from(
            "% Axioms learned by `lucent learn` (DOMAIN.md 5.9): strength, origin, statement.\n",
        );
        for l in &self.axioms {
            out.push_str(&format!(
                "% strength {:.4} votes {} episode {} trial {}: {}\n{}: {}.\n",
                l.strength,
                l.votes,
                l.origin.episode,
                l.origin.trial,
                l.origin.surprise,
                l.label,
                l.axiom.to_ald()
            ));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::super::term::{in_hand, o, r, AxiomKind, Literal};
    use super::*;

    fn c2(extra: bool) -> Axiom {
        let body = if extra {
            vec![in_hand(false, r(1), o(5))]
        } else {
            vec![]
        };
        Axiom::new(
            AxiomKind::Causal {
                head: in_hand(false, r(1), o(1)),
            },
            Literal::new("putdown", vec![r(1), o(1), o(2)]),
            body,
        )
    }

    #[test]
    fn decay_refresh_and_removal() {
        let mut s = Store::default();
        assert_eq!(
            s.learn(c2(false), 60, Origin::default()),
            Added::New("L1".into())
        );
        // After 5 episodes the strength halves: e^(-5 ln2/5) = 0.5.
        for _ in 0..5 {
            assert!(s.end_episode().is_empty());
        }
        assert!((s.axioms[0].strength - 0.5).abs() < 1e-12);
        // Relearning a version refreshes it instead of adding it.
        assert_eq!(
            s.learn(c2(true), 50, Origin::default()),
            Added::Refreshed("L1".into())
        );
        assert_eq!(s.axioms[0].strength, 1.0);
        // 0.5^(n/5) < 0.1 first at n = 17 (0.5^3.4 = 0.0947; 0.5^3.2 = 0.1088 at n = 16).
        for n in 1..=16 {
            assert!(s.end_episode().is_empty(), "episode {n}");
        }
        assert_eq!(s.end_episode().len(), 1);
        assert!(s.axioms.is_empty());
        // Labels are not reused.
        assert_eq!(
            s.learn(c2(false), 60, Origin::default()),
            Added::New("L2".into())
        );
        assert!(s
            .to_ald()
            .contains("L2: putdown(R1, O1, O2) causes -in_hand(R1, O1)."));
    }
}
