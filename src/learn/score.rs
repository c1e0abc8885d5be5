//! Scoring learned axioms against the targets (docs/domain.md 5.10).
//!
//! Two axioms are **equal** when they are the same up to a sort-preserving renaming of their
//! variables (same literal patterns, same co-occurrence structure). One is a **version** of the
//! other when they share the action and head, and a renaming that fixes the action's and head's
//! variables maps one body into the other (over- or under-specified). Strict scoring counts
//! equality only; relaxed scoring counts equality or version, with TP capped at 5 per run.
//!
//! Invariants: scores are sums of per-run counts; precision and recall are in percent, and an
//! empty denominator gives 0.

use serde::Serialize;

use super::term::{Axiom, Literal, Var};

/// True when `a` and `b` are equal up to renaming.
pub fn equal(a: &Axiom, b: &Axiom) -> bool {
    a.canonical() == b.canonical()
}

/// True when one of `a`, `b` is a version of the other (equality included).
pub fn version(a: &Axiom, b: &Axiom) -> bool {
    let (a, b) = (a.canonical(), b.canonical());
    if a.kind != b.kind || a.action != b.action {
        return false;
    }
    let (small, large) = if a.body.len() <= b.body.len() {
        (&a, &b)
    } else {
        (&b, &a)
    };
    // After canonical renaming, the action's and head's variables have the same names in both.
    let fixed: Vec<Var> = small
        .fixed_part()
        .iter()
        .flat_map(|l| l.vars().collect::<Vec<_>>())
        .collect();
    let mut map: Vec<(Var, Var)> = fixed.iter().map(|v| (*v, *v)).collect();
    map.dedup();
    embeds(&small.body, &large.body, &mut map)
}

/// Backtracking search for an injective, sort-preserving variable map (extending `map`) under
/// which every literal of `small` is a literal of `large`.
fn embeds(small: &[Literal], large: &[Literal], map: &mut Vec<(Var, Var)>) -> bool {
    let Some((first, rest)) = small.split_first() else {
        return true;
    };
    for target in large {
        if target.name != first.name
            || target.positive != first.positive
            || target.args.len() != first.args.len()
        {
            continue;
        }
        let saved = map.len();
        let mut ok = true;
        for (x, y) in first.args.iter().zip(&target.args) {
            match (x.var(), y.var()) {
                (Some(v), Some(w)) => {
                    if v.sort != w.sort {
                        ok = false;
                    } else if let Some(&(_, m)) = map.iter().find(|(k, _)| *k == v) {
                        ok = m == w;
                    } else if map.iter().any(|(_, m)| *m == w) {
                        ok = false;
                    } else {
                        map.push((v, w));
                    }
                }
                (None, None) => ok = x == y,
                _ => ok = false,
            }
            if !ok {
                break;
            }
        }
        if ok && embeds(rest, large, map) {
            return true;
        }
        map.truncate(saved);
    }
    false
}

/// True-positive, false-positive and false-negative counts.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Counts {
    /// Found axioms matching a target.
    pub tp: usize,
    /// Found axioms matching no target.
    pub fp: usize,
    /// Targets matched by no found axiom.
    #[serde(rename = "fn")]
    pub fn_: usize,
}

impl Counts {
    /// Adds another run's counts.
    pub fn add(&mut self, other: Counts) {
        self.tp += other.tp;
        self.fp += other.fp;
        self.fn_ += other.fn_;
    }

    /// Precision in percent.
    pub fn precision(&self) -> f64 {
        percent(self.tp, self.tp + self.fp)
    }

    /// Recall in percent.
    pub fn recall(&self) -> f64 {
        percent(self.tp, self.tp + self.fn_)
    }
}

fn percent(num: usize, den: usize) -> f64 {
    if den == 0 {
        0.0
    } else {
        100.0 * num as f64 / den as f64
    }
}

/// Strict counts of one run.
pub fn strict(found: &[Axiom], targets: &[Axiom]) -> Counts {
    let tp = found
        .iter()
        .filter(|f| targets.iter().any(|t| equal(f, t)))
        .count();
    Counts {
        tp,
        fp: found.len() - tp,
        fn_: targets
            .iter()
            .filter(|t| !found.iter().any(|f| equal(f, t)))
            .count(),
    }
}

/// The relaxed cap on true positives per run.
pub const RELAXED_TP_CAP: usize = 5;

/// Relaxed counts of one run: equal or version; TP capped at 5.
pub fn relaxed(found: &[Axiom], targets: &[Axiom]) -> Counts {
    let matched = found
        .iter()
        .filter(|f| targets.iter().any(|t| version(f, t)))
        .count();
    Counts {
        tp: matched.min(RELAXED_TP_CAP),
        fp: found.len() - matched,
        fn_: targets
            .iter()
            .filter(|t| !found.iter().any(|f| version(f, t)))
            .count(),
    }
}

#[cfg(test)]
mod tests {
    use super::super::term::{in_hand, o, r, rel, AxiomKind};
    use super::*;

    fn pickup() -> Literal {
        Literal::new("pickup", vec![r(1), o(1)])
    }
    fn putdown() -> Literal {
        Literal::new("putdown", vec![r(1), o(1), o(2)])
    }
    fn ec(action: Literal, body: Vec<Literal>) -> Axiom {
        Axiom::new(AxiomKind::Executability, action, body)
    }
    fn cl(action: Literal, head: Literal, body: Vec<Literal>) -> Axiom {
        Axiom::new(AxiomKind::Causal { head }, action, body)
    }

    /// The five H1 targets (docs/domain.md 2.2-2.3: E7, E5, E2, C3, C2).
    fn targets() -> Vec<Axiom> {
        vec![
            ec(pickup(), vec![rel("below", o(1), o(2))]),
            ec(pickup(), vec![in_hand(true, r(1), o(2))]),
            ec(putdown(), vec![in_hand(false, r(1), o(1))]),
            cl(pickup(), in_hand(true, r(1), o(1)), vec![]),
            cl(putdown(), in_hand(false, r(1), o(1)), vec![]),
        ]
    }

    #[test]
    fn equality_and_versions() {
        let t = targets();
        // Renamed existential variable: equal.
        assert!(equal(&ec(pickup(), vec![rel("below", o(1), o(7))]), &t[0]));
        // in_hand(R1, O1) instead of in_hand(R1, O2): the action object is not renamable.
        assert!(!equal(
            &ec(pickup(), vec![in_hand(true, r(1), o(1))]),
            &t[1]
        ));
        assert!(!version(
            &ec(pickup(), vec![in_hand(true, r(1), o(1))]),
            &t[1]
        ));
        // The paper's over-specified example is a version of C2, not equal to it.
        let over = cl(
            putdown(),
            in_hand(false, r(1), o(1)),
            vec![in_hand(false, r(1), o(5))],
        );
        assert!(!equal(&over, &t[4]));
        assert!(version(&over, &t[4]));
        // Another head is no version.
        assert!(!version(
            &cl(putdown(), rel("on", o(1), o(2)), vec![]),
            &t[4]
        ));
        // Under-specified executability condition (empty body) is a version of E7.
        assert!(version(&ec(pickup(), vec![]), &t[0]));
        // Inconsistent variables on the shared literal: below(O2, O1) is not below(O1, O2).
        assert!(!version(
            &ec(
                pickup(),
                vec![rel("below", o(2), o(1)), rel("on", o(2), o(3))]
            ),
            &t[0]
        ));
        // Consistent: below(O1, O3), on(O3, O4) contains a renaming of below(O1, O2).
        assert!(version(
            &ec(
                pickup(),
                vec![rel("below", o(1), o(3)), rel("on", o(3), o(4))]
            ),
            &t[0]
        ));
    }

    /// Hand-made run: found = {E7 renamed, E2 over-specified, C3 exact, a wrong law, and a
    /// second version of E7}.
    /// Strict: TP 2 (E7, C3), FP 3, FN 3 (E5, E2, C2) -> P 40%, R 40%.
    /// Relaxed: matches E7, E2 (version), C3, the E7 version: 4 TP, FP 1 (the wrong law),
    /// FN 2 (E5, C2) -> P 80%, R 66.67%.
    #[test]
    fn strict_and_relaxed_counts_by_hand() {
        let found = vec![
            ec(pickup(), vec![rel("below", o(1), o(9))]),
            ec(
                putdown(),
                vec![in_hand(false, r(1), o(1)), rel("on", o(3), o(2))],
            ),
            cl(pickup(), in_hand(true, r(1), o(1)), vec![]),
            cl(pickup(), rel("on", o(1), o(2)), vec![]),
            ec(
                pickup(),
                vec![rel("below", o(1), o(2)), in_hand(false, r(1), o(1))],
            ),
        ];
        let s = strict(&found, &targets());
        assert_eq!(
            s,
            Counts {
                tp: 2,
                fp: 3,
                fn_: 3
            }
        );
        assert_eq!(s.precision(), 40.0);
        let x = relaxed(&found, &targets());
        assert_eq!(
            x,
            Counts {
                tp: 4,
                fp: 1,
                fn_: 2
            }
        );
        assert_eq!(x.precision(), 80.0);
        assert!((x.recall() - 66.666_666).abs() < 1e-3);
    }

    /// Seven versions of the targets in one run: relaxed TP is capped at 5.
    #[test]
    fn relaxed_tp_cap() {
        let mut found = targets();
        found.push(ec(
            pickup(),
            vec![rel("below", o(1), o(2)), rel("on", o(2), o(3))],
        ));
        found.push(cl(
            putdown(),
            in_hand(false, r(1), o(1)),
            vec![in_hand(false, r(1), o(5))],
        ));
        assert_eq!(
            relaxed(&found, &targets()),
            Counts {
                tp: 5,
                fp: 0,
                fn_: 0
            }
        );
        assert_eq!(
            strict(&found, &targets()),
            Counts {
                tp: 5,
                fp: 2,
                fn_: 0
            }
        );
        let mut total = Counts::default();
        total.add(strict(&found, &targets()));
        total.add(strict(&[], &targets()));
        assert_eq!(
            total,
            Counts {
                tp: 5,
                fp: 2,
                fn_: 5
            }
        );
        assert_eq!(total.recall(), 50.0);
    }
}
