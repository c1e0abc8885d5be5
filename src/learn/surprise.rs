//! Surprises: comparing the learner's predicted successor state with the observed one and
//! classifying the discrepancy (docs/domain.md 5.1, the code's refinement).
//!
//! Only positive step-1 literals of the observable vocabulary (`relation`, `in_hand`) are
//! compared. `unexpected` = observed but not predicted; `extra` = predicted but not observed.
//! When the oracle has a successor, an `extra` literal that already held at step 0 in the
//! learner merely persisted by inertia: it reveals a missing negative effect and moves to
//! `unexpected` as `¬f`. When the oracle has no successor, every predicted literal is `extra`
//! (a missing executability condition).
//!
//! Invariants: the outcome's literal lists are sorted and free of duplicates.

use super::state::Outcome;
use super::term::{Literal, IN_HAND, RELATION};

/// True for a positive literal of the observable vocabulary.
pub fn observable_positive(lit: &Literal) -> bool {
    lit.positive && (lit.name == RELATION || lit.name == IN_HAND)
}

fn positives(state: &[Literal]) -> Vec<Literal> {
    let mut out: Vec<Literal> = state
        .iter()
        .filter(|l| observable_positive(l))
        .cloned()
        .collect();
    out.sort();
    out.dedup();
    out
}

/// Classifies one trial. `learner_before` is the learner's step-0 state; `learner_after` and
/// `oracle_after` are the step-1 states, `None` when there is no successor (the action is not
/// executable there).
pub fn classify(
    learner_before: &[Literal],
    learner_after: Option<&[Literal]>,
    oracle_after: Option<&[Literal]>,
) -> Outcome {
    let predicted = learner_after.map(positives).unwrap_or_default();
    let observed = oracle_after.map(positives).unwrap_or_default();
    let mut unexpected: Vec<Literal> = observed
        .iter()
        .filter(|l| predicted.binary_search(l).is_err())
        .cloned()
        .collect();
    let mut extra: Vec<Literal> = predicted
        .iter()
        .filter(|l| observed.binary_search(l).is_err())
        .cloned()
        .collect();
    if learner_after.is_some() && oracle_after.is_some() {
        // Rule 2: an extra literal that held at step 0 persisted by inertia in the learner only.
        let (persisted, rest): (Vec<Literal>, Vec<Literal>) =
            extra.into_iter().partition(|l| learner_before.contains(l));
        unexpected.extend(persisted.into_iter().map(|l| l.complement()));
        extra = rest;
    }
    unexpected.sort();
    unexpected.dedup();
    Outcome {
        unexpected,
        extra,
        learner_executable: learner_after.is_some(),
        oracle_executable: oracle_after.is_some(),
        void: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn in_hand(o: &str) -> Literal {
        Literal::ground(IN_HAND, &["rob1", o])
    }

    #[test]
    fn missing_positive_effect() {
        // pickup(rob1, red) without C3: the oracle observes in_hand(rob1, red).
        let before = vec![Literal::relation("on", "red", "table")];
        let learner = vec![in_hand("red").complement()];
        let oracle = vec![in_hand("red")];
        let o = classify(&before, Some(&learner), Some(&oracle));
        assert_eq!(o.unexpected, vec![in_hand("red")]);
        assert!(o.extra.is_empty());
    }

    #[test]
    fn missing_negative_effect_moves_to_unexpected() {
        // putdown(rob1, red, table) without C2: in_hand persists by inertia in the learner.
        let before = vec![in_hand("red")];
        let learner = vec![in_hand("red"), Literal::relation("on", "red", "table")];
        let oracle = vec![Literal::relation("on", "red", "table")];
        let o = classify(&before, Some(&learner), Some(&oracle));
        assert_eq!(o.unexpected, vec![in_hand("red").complement()]);
        assert!(o.extra.is_empty());
    }

    #[test]
    fn missing_executability_condition() {
        // pickup of a covered object: the oracle has no successor; every predicted positive
        // literal is extra, negative ones are not compared.
        let before = vec![Literal::relation("on", "blue", "red")];
        let learner = vec![
            Literal::relation("on", "green", "table"),
            in_hand("blue").complement(),
        ];
        let o = classify(&before, Some(&learner), None);
        assert_eq!(o.extra, vec![Literal::relation("on", "green", "table")]);
        assert!(o.unexpected.is_empty());
        assert!(o.learner_executable && !o.oracle_executable);
        // Both sides forbid the action: no surprise.
        assert!(!classify(&before, None, None).surprising());
    }
}
