//! Learned axioms as knowledge, with a strength that decays (docs/domain.md 5.9 \[ours\]).
//!
//! A learned axiom starts at strength 1; after each learning episode its strength is multiplied
//! by `e^(-λ)` with `λ = ln 2 / 5` (a half-life of five episodes); learning it again (equal or a
//! version, 5.10) or using it refreshes it to 1; below 0.1 it is removed. Hand-written axioms
//! are not in the store and never decay.
//!
//! The store renders as an AL_d file: one labelled statement per axiom, preceded by a comment
//! `% learned axiom: strength S votes V episode E trial T: surprise`, so the planner and the
//! explainer load it as ordinary AL_d, and [`Store::from_ald`] reads labels, strengths and
//! provenance back (an explanation citing rule `L3` looks it up there to say it is learned).
//! Use is detected by matching: an axiom is used when it applies to the action in the state the
//! robot acted on ([`Store::used_in`]).
//!
//! Invariants: every stored axiom is canonical (5.8) and appears once; labels `L1, L2, …` are
//! never reused within a store.

use super::score;
use super::term::{Axiom, Literal};

/// The decay rate per episode: `ln 2 / 5`.
pub fn lambda() -> f64 {
    std::f64::consts::LN_2 / 5.0
}

/// The comment that introduces a learned statement in the file [`Store::to_ald`] writes; the
/// explainer and the planner recognize learned axioms by it (through [`Store::from_ald`]).
pub const LEARNED_PREFIX: &str = "% learned axiom: ";

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
    /// explanation); false when no stored axiom has it.
    pub fn used(&mut self, label: &str) -> bool {
        match self.axioms.iter_mut().find(|l| l.label == label) {
            Some(l) => {
                l.strength = 1.0;
                true
            }
            None => false,
        }
    }

    /// Refreshes every axiom that applies to `action` in the complete `state` the robot acted
    /// on (a causal law supporting its effect, an executability condition forbidding the
    /// action; see [`Axiom::fires`]); returns their labels.
    pub fn used_in(&mut self, action: &Literal, state: &[Literal]) -> Vec<String> {
        let mut out = Vec::new();
        for l in &mut self.axioms {
            if l.axiom.fires(action, state) {
                l.strength = 1.0;
                out.push(l.label.clone());
            }
        }
        out
    }

    /// The stored axiom with this label.
    pub fn get(&self, label: &str) -> Option<&Learned> {
        self.axioms.iter().find(|l| l.label == label)
    }

    /// Reads a store back from the file [`Store::to_ald`] writes: every statement `Ln: axiom.`
    /// with the comment line before it giving its strength, votes and origin. The error names
    /// the first line that does not fit.
    pub fn from_ald(text: &str) -> Result<Store, String> {
        let mut store = Store::default();
        let mut pending: Option<(f64, usize, Origin)> = None;
        for (i, line) in text.lines().enumerate() {
            let line = line.trim();
            let bad = |what: &str| format!("line {}: {what}: {line}", i + 1);
            if line.is_empty() {
                continue;
            }
            if let Some(meta) = line.strip_prefix(LEARNED_PREFIX) {
                // The fields hold no colon; the surprise after the first one may.
                let (fields, surprise) = meta.split_once(':').unwrap_or((meta, ""));
                let surprise = surprise.trim();
                let words: Vec<&str> = fields.split_whitespace().collect();
                let number = |key: &str| -> Option<&str> {
                    let at = words.iter().position(|w| *w == key)?;
                    words.get(at + 1).copied()
                };
                let parsed = (|| {
                    Some((
                        number("strength")?.parse::<f64>().ok()?,
                        number("votes")?.parse::<usize>().ok()?,
                        Origin {
                            episode: number("episode")?.parse().ok()?,
                            trial: number("trial")?.parse().ok()?,
                            surprise: surprise.to_string(),
                        },
                    ))
                })();
                pending = Some(parsed.ok_or_else(|| bad("malformed strength comment"))?);
                continue;
            }
            if line.starts_with('%') {
                continue;
            }
            let (label, rest) = line
                .split_once(": ")
                .ok_or_else(|| bad("expected `Ln: statement.`"))?;
            let statement = rest
                .strip_suffix('.')
                .ok_or_else(|| bad("missing final period"))?;
            let axiom = Axiom::parse_ald(statement).ok_or_else(|| bad("not a learned axiom"))?;
            let (strength, votes, origin) = pending
                .take()
                .ok_or_else(|| bad("statement without a strength comment"))?;
            if let Some(n) = label
                .strip_prefix('L')
                .and_then(|n| n.parse::<usize>().ok())
            {
                store.next_label = store.next_label.max(n);
            }
            store.axioms.push(Learned {
                label: label.to_string(),
                axiom: axiom.canonical(),
                strength,
                origin,
                votes,
            });
        }
        Ok(store)
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

    /// The axioms with their labels (`L3`), as AL_d statements to add to a description.
    pub fn statements(&self) -> Vec<crate::action::ast::Statement> {
        self.axioms
            .iter()
            .map(|l| l.axiom.statement(&l.label))
            .collect()
    }

    /// The store as an AL_d file.
    pub fn to_ald(&self) -> String {
        let mut out = String::from(
            "% Axioms learned by `lucent learn` (docs/domain.md 5.9): strength, origin, \
             statement.\n",
        );
        for l in &self.axioms {
            out.push_str(&format!(
                "{LEARNED_PREFIX}strength {:.4} votes {} episode {} trial {}: {}\n{}: {}.\n",
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
    use super::super::term::{in_hand, o, r, rel, AxiomKind, Literal};
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

    /// Refresh on use: after two episodes both axioms are at e^(-2 ln2/5) = 0.5^0.4 = 0.757858;
    /// picking up the duck applies C3 (refreshed to 1) and not E7, which needs the duck below
    /// something (`below(O1, O2)` with O1 = duck; only the cube is below anything), so E7 keeps
    /// 0.757858.
    #[test]
    fn refresh_on_use() {
        let mut s = Store::default();
        let c3 = Axiom::new(
            AxiomKind::Causal {
                head: in_hand(true, r(1), o(1)),
            },
            Literal::new("pickup", vec![r(1), o(1)]),
            vec![],
        );
        let e7 = Axiom::new(
            AxiomKind::Executability,
            Literal::new("pickup", vec![r(1), o(1)]),
            vec![rel("below", o(1), o(2))],
        );
        s.learn(c3, 100, Origin::default());
        s.learn(e7, 90, Origin::default());
        s.end_episode();
        s.end_episode();
        assert!((s.axioms[0].strength - 0.757858).abs() < 1e-6);
        let state = vec![
            Literal::relation("on", "yellow_duck", "red_cube_large"),
            Literal::relation("below", "red_cube_large", "yellow_duck"),
        ];
        let pick = Literal::ground("pickup", &["rob1", "yellow_duck"]);
        assert_eq!(s.used_in(&pick, &state), vec!["L1".to_string()]);
        assert_eq!(s.axioms[0].strength, 1.0);
        assert!((s.axioms[1].strength - 0.757858).abs() < 1e-6);
        assert!(s.used("L2"));
        assert!(!s.used("L9"));
        assert_eq!(s.axioms[1].strength, 1.0);
    }

    #[test]
    fn the_file_reads_back() {
        let mut s = Store::default();
        let origin = Origin {
            episode: 3,
            trial: 7,
            surprise: "putdown(rob1, blue_ball, table): unexpected -in_hand(rob1, blue_ball)"
                .into(),
        };
        s.learn(c2(false), 60, origin.clone());
        s.learn(
            Axiom::new(
                AxiomKind::Executability,
                Literal::new("pickup", vec![r(1), o(1)]),
                vec![rel("below", o(1), o(2))],
            ),
            94,
            Origin::default(),
        );
        s.end_episode();
        let text = s.to_ald();
        assert!(text.contains("% learned axiom: strength 0.8706 votes 60 episode 3 trial 7: "));
        let back = Store::from_ald(&text).unwrap();
        assert_eq!(back.axioms.len(), 2);
        assert_eq!(back.axioms[0].axiom, s.axioms[0].axiom);
        assert_eq!(back.axioms[1].axiom, s.axioms[1].axiom);
        assert_eq!(back.axioms[0].origin, origin);
        assert_eq!(back.get("L2").map(|l| l.votes), Some(94));
        // 0.5^0.2 = 0.870551, written with four decimals.
        assert!((back.axioms[0].strength - 0.8706).abs() < 1e-12);
        // Labels continue after the highest one read.
        let mut back = back;
        assert_eq!(
            back.learn(c2(true).rename(&|v| v), 1, Origin::default()),
            Added::Refreshed("L1".into())
        );
        let err = Store::from_ald("L1: pickup(R1, O1) causes in_hand(R1, O1).\n").unwrap_err();
        assert!(err.contains("line 1"), "{err}");
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
