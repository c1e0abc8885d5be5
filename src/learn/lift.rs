//! Relevant literals and lifting to variables (docs/domain.md 5.5), and the choice of a causal
//! law's head.
//!
//! Relevant literals: the step-0 literals of the observable vocabulary (positive `relation`,
//! `in_hand` of either sign) that contain a constant of the ground action, one hop only.
//!
//! Lifting (the code's heuristic, made deterministic): variables get a sort prefix and an index
//! in order of first appearance over the action, the unexpected literals, then the relevant
//! literals sorted canonically. (docs/domain.md lists the unexpected literal before the action; we
//! put the action first \[ours\] so that its variables are the same in every sample of a dataset,
//! label 0 samples included; for the heads of the H1 targets both orders agree.) A literal with a constant that has no variable yet is matched,
//! with that constant as a wildcard, against the features already in the vocabulary; a match
//! lends its variable at that position, otherwise the next free index is taken. The wildcard
//! never matches a variable of the lifted action (those name the action's own constants), so
//! "some object not in hand" becomes one feature `-in_hand(R1, O5)` distinct from the action
//! object's `-in_hand(R1, O1)`.
//!
//! Normalization \[ours\]: with [`Algebra`], a converse (`above(B, A)` for `below(A, B)`) or a
//! symmetric relation is written in one form (the first argument the smaller variable), so the
//! trees do not split votes between two spellings of one state fact.
//!
//! Invariants: the vocabulary only grows; a feature's index never changes; lifting a sample is
//! a function of the sample and the vocabulary before it.

use std::collections::HashMap;

use super::term::{Literal, Sort, Term, Var, IN_HAND, RELATION};

/// Which constants are the robot (sort `R`); every other entity is an object (sort `O`).
#[derive(Clone, Debug, Default)]
pub struct Signature {
    /// The robot constants.
    pub robots: Vec<String>,
}

impl Signature {
    /// The sort of a constant in an entity position.
    pub fn sort_of(&self, constant: &str) -> Sort {
        if self.robots.iter().any(|r| r == constant) {
            Sort::Robot
        } else {
            Sort::Object
        }
    }
}

/// Facts of the relation algebra used to normalize lifted literals \[ours\].
#[derive(Clone, Debug, Default)]
pub struct Algebra {
    /// Converse pairs `(S1, S2)`: `rel(S1, A, B)` iff `rel(S2, B, A)`; listed once per pair, the
    /// first name being the one kept when the second argument is the smaller variable.
    pub converse: Vec<(String, String)>,
    /// Symmetric relations: `rel(S, A, B)` iff `rel(S, B, A)`.
    pub symmetric: Vec<String>,
    /// Composed relations (`on` = above + touch), the most specific spelling of a fact.
    pub composed: Vec<String>,
}

impl Algebra {
    /// The RA domain's algebra (docs/domain.md 2.1.1: SR2 and SR3 over `complement`).
    pub fn ra() -> Algebra {
        Algebra {
            converse: [("below", "above"), ("behind", "front"), ("left", "right")]
                .iter()
                .map(|(a, b)| (a.to_string(), b.to_string()))
                .collect(),
            symmetric: ["touch", "not_touch", "far"]
                .iter()
                .map(|s| s.to_string())
                .collect(),
            composed: vec!["on".to_string()],
        }
    }

    /// The preference among features that no sample tells apart (lower is kept) \[ours\]: the
    /// hand fluent, then positional relations, then distance relations, then composed ones
    /// (`on(B, A)` says more than `below(A, B)`; when the data cannot tell them apart, the
    /// weaker statement is the one they support).
    pub fn rank(&self, lit: &Literal) -> u8 {
        if lit.name == IN_HAND {
            return 0;
        }
        let Some(Term::Const(name)) = lit.args.first().filter(|_| lit.name == RELATION) else {
            return 4;
        };
        if self.converse.iter().any(|(a, b)| a == name || b == name) {
            1
        } else if self.symmetric.contains(name) {
            2
        } else if self.composed.contains(name) {
            3
        } else {
            4
        }
    }

    /// The name of relation `name` with its arguments swapped: itself for a symmetric relation,
    /// the other of its pair for a converse; `None` for any other relation.
    pub fn other_name(&self, name: &str) -> Option<String> {
        if self.symmetric.iter().any(|s| s == name) {
            return Some(name.to_string());
        }
        self.converse.iter().find_map(|(x, y)| {
            if x == name {
                Some(y.clone())
            } else if y == name {
                Some(x.clone())
            } else {
                None
            }
        })
    }

    /// The normal form of a lifted relation literal: if the arguments are variables out of
    /// order (second smaller), a converse or symmetric relation is flipped.
    pub fn normalize(&self, lit: &Literal) -> Literal {
        if lit.name != RELATION || lit.args.len() != 3 {
            return lit.clone();
        }
        let (Some(a), Some(b)) = (lit.args[1].var(), lit.args[2].var()) else {
            return lit.clone();
        };
        let Term::Const(name) = &lit.args[0] else {
            return lit.clone();
        };
        let Some(flipped_name) = self.other_name(name) else {
            return lit.clone();
        };
        // Keep the form whose first argument is the smaller variable; for converses with equal
        // variables (never in practice) keep the first name of the pair.
        let keep = if a != b {
            a < b
        } else {
            self.converse.iter().any(|(x, _)| x == name) || self.symmetric.contains(name)
        };
        if keep {
            lit.clone()
        } else {
            Literal {
                positive: lit.positive,
                name: RELATION.to_string(),
                args: vec![Term::Const(flipped_name), Term::Var(b), Term::Var(a)],
            }
        }
    }
}

/// The relevant literals of a step-0 state for a ground action: observable literals (positive
/// `relation`, `in_hand` of either sign) that mention a constant of the action.
pub fn relevant(state: &[Literal], action: &Literal) -> Vec<Literal> {
    let constants: Vec<&Term> = action.args.iter().collect();
    let mut out: Vec<Literal> = state
        .iter()
        .filter(|l| (l.name == RELATION && l.positive) || l.name == IN_HAND)
        .filter(|l| {
            l.entity_positions()
                .any(|i| constants.contains(&&l.args[i]))
        })
        .cloned()
        .collect();
    out.sort();
    out.dedup();
    out
}

/// A sample after lifting.
#[derive(Clone, Debug, PartialEq)]
pub struct Lifted {
    /// The lifted unexpected (or extra) literals.
    pub unexpected: Vec<Literal>,
    /// The lifted action.
    pub action: Literal,
    /// The vocabulary indices of the lifted relevant literals, sorted, once each.
    pub features: Vec<usize>,
}

/// The global vocabulary of lifted features of one dataset.
#[derive(Clone, Debug, Default)]
pub struct Lifter {
    /// Robot/object sorts of constants.
    pub signature: Signature,
    /// Normalization of converse and symmetric relations.
    pub algebra: Algebra,
    /// The features, in order of creation.
    pub features: Vec<Literal>,
    /// Feature index by literal.
    index: HashMap<Literal, usize>,
    /// The largest index used so far per sort (robot, object), over all samples.
    max_index: [u32; 2],
}

fn slot(sort: Sort) -> usize {
    match sort {
        Sort::Robot => 0,
        Sort::Object => 1,
    }
}

impl Lifter {
    /// An empty vocabulary.
    pub fn new(signature: Signature, algebra: Algebra) -> Lifter {
        Lifter {
            signature,
            algebra,
            ..Lifter::default()
        }
    }

    /// Lifts one sample: its unexpected literals, its ground action and its relevant literals.
    pub fn lift(
        &mut self,
        unexpected: &[Literal],
        action: &Literal,
        relevant: &[Literal],
    ) -> Lifted {
        let mut names: HashMap<String, Var> = HashMap::new();
        let mut next = [0u32; 2];
        // The action and the unexpected literals name their constants in order of appearance.
        let fixed = |lit: &Literal,
                     names: &mut HashMap<String, Var>,
                     next: &mut [u32; 2],
                     sig: &Signature| {
            for i in lit.entity_positions() {
                if let Term::Const(c) = &lit.args[i] {
                    if !names.contains_key(c) {
                        let sort = sig.sort_of(c);
                        next[slot(sort)] += 1;
                        names.insert(
                            c.clone(),
                            Var {
                                sort,
                                index: next[slot(sort)],
                            },
                        );
                    }
                }
            }
        };
        for lit in std::iter::once(action).chain(unexpected.iter()) {
            fixed(lit, &mut names, &mut next, &self.signature);
        }
        let action_vars: Vec<Var> = action
            .entity_positions()
            .filter_map(|i| match &action.args[i] {
                Term::Const(c) => names.get(c).copied(),
                Term::Var(v) => Some(*v),
            })
            .collect();
        for s in [Sort::Robot, Sort::Object] {
            self.max_index[slot(s)] = self.max_index[slot(s)].max(next[slot(s)]);
        }
        let lifted_unexpected: Vec<Literal> = unexpected
            .iter()
            .map(|l| self.name_all(l, &names))
            .collect();
        let lifted_action = self.name_all(action, &names);
        let mut sorted: Vec<&Literal> = relevant.iter().collect();
        sorted.sort();
        let mut features = Vec::new();
        for lit in sorted {
            // Each constant without a variable is resolved in argument order.
            let positions: Vec<usize> = lit.entity_positions().collect();
            for &i in &positions {
                let Term::Const(c) = &lit.args[i] else {
                    continue;
                };
                if names.contains_key(c) {
                    continue;
                }
                let sort = self.signature.sort_of(c);
                let var = self
                    .match_vocabulary(lit, i, &names, &action_vars)
                    .unwrap_or_else(|| {
                        self.max_index[slot(sort)] += 1;
                        Var {
                            sort,
                            index: self.max_index[slot(sort)],
                        }
                    });
                names.insert(c.clone(), var);
            }
            let lifted = self.algebra.normalize(&self.name_all(lit, &names));
            let id = match self.index.get(&lifted) {
                Some(&id) => id,
                None => {
                    self.features.push(lifted.clone());
                    self.index.insert(lifted, self.features.len() - 1);
                    self.features.len() - 1
                }
            };
            features.push(id);
        }
        features.sort_unstable();
        features.dedup();
        Lifted {
            unexpected: lifted_unexpected,
            action: lifted_action,
            features,
        }
    }

    /// Replaces every named constant in entity positions by its variable.
    fn name_all(&self, lit: &Literal, names: &HashMap<String, Var>) -> Literal {
        let mut out = lit.clone();
        for i in lit.entity_positions() {
            if let Term::Const(c) = &lit.args[i] {
                if let Some(v) = names.get(c) {
                    out.args[i] = Term::Var(*v);
                }
            }
        }
        out
    }

    /// The variable that a vocabulary feature has at position `pos`, for the first feature (in
    /// creation order) that matches `lit` with position `pos` as a wildcard, the named
    /// constants as their variables, and other unnamed constants anything. A variable of the
    /// action never matches the wildcard.
    fn match_vocabulary(
        &self,
        lit: &Literal,
        pos: usize,
        names: &HashMap<String, Var>,
        action_vars: &[Var],
    ) -> Option<Var> {
        let probe = self.name_all(lit, names);
        // Both spellings of a converse or symmetric literal are tried against the normalized
        // vocabulary: the feature may have been stored flipped.
        self.features.iter().find_map(|f| {
            if f.name != probe.name
                || f.positive != probe.positive
                || f.args.len() != probe.args.len()
            {
                return None;
            }
            let direct = matches_at(f, &probe, pos, action_vars);
            if direct.is_some() {
                return direct;
            }
            let flipped = flip(f, &self.algebra)?;
            matches_at(&flipped, &probe, pos, action_vars)
        })
    }
}

/// The stored feature spelled the other way round, if its relation is converse or symmetric.
fn flip(f: &Literal, algebra: &Algebra) -> Option<Literal> {
    if f.name != RELATION || f.args.len() != 3 {
        return None;
    }
    let Term::Const(name) = &f.args[0] else {
        return None;
    };
    let other = algebra.other_name(name)?;
    Some(Literal {
        positive: f.positive,
        name: f.name.clone(),
        args: vec![Term::Const(other), f.args[2].clone(), f.args[1].clone()],
    })
}

fn matches_at(feature: &Literal, probe: &Literal, pos: usize, action_vars: &[Var]) -> Option<Var> {
    let mut found = None;
    for (i, (ft, pt)) in feature.args.iter().zip(&probe.args).enumerate() {
        if i == pos {
            let v = ft.var()?;
            if action_vars.contains(&v) {
                return None;
            }
            found = Some(v);
        } else {
            match pt {
                // Another unnamed constant: it will be resolved on its own.
                Term::Const(_) if probe.entity_positions().contains(&i) => {
                    ft.var()?;
                }
                other => {
                    if ft != other {
                        return None;
                    }
                }
            }
        }
    }
    found
}

/// The causal-law head: the most frequent lifted unexpected literal; ties go to the one sharing
/// the most variables with the lifted action, then to the smallest literal.
pub fn choose_head(samples: &[Lifted]) -> Option<(Literal, Literal)> {
    let mut counts: HashMap<(&Literal, &Literal), usize> = HashMap::new();
    for s in samples {
        for u in &s.unexpected {
            *counts.entry((u, &s.action)).or_insert(0) += 1;
        }
    }
    counts
        .into_iter()
        .max_by(|((ua, aa), ca), ((ub, ab), cb)| {
            let shared =
                |u: &Literal, a: &Literal| u.vars().filter(|v| a.vars().any(|w| w == *v)).count();
            ca.cmp(cb)
                .then(shared(ua, aa).cmp(&shared(ub, ab)))
                .then(ub.cmp(ua))
                .then(ab.cmp(aa))
        })
        .map(|((u, a), _)| (u.clone(), a.clone()))
}

#[cfg(test)]
mod tests {
    use super::super::term::{in_hand, o, r, rel};
    use super::*;

    fn sig() -> Signature {
        Signature {
            robots: vec!["rob1".into()],
        }
    }

    fn g(name: &str, args: &[&str]) -> Literal {
        Literal::ground(name, args)
    }

    fn not_in_hand(o: &str) -> Literal {
        g(IN_HAND, &["rob1", o]).complement()
    }

    #[test]
    fn relevant_literals_mention_an_action_constant() {
        let state = vec![
            Literal::relation("on", "red", "green"),
            Literal::relation("on", "blue", "table"),
            Literal::relation("on", "green", "table"),
            Literal::relation("on", "red", "green").complement(),
            not_in_hand("blue"),
            g("has_size", &["red", "large"]),
        ];
        let action = g("pickup", &["rob1", "red"]);
        // One hop: on(green, table) does not mention red; the robot is an action constant, so
        // -in_hand(rob1, blue) is relevant; negative relations and statics are not observable.
        assert_eq!(
            relevant(&state, &action),
            vec![not_in_hand("blue"), Literal::relation("on", "red", "green")]
        );
    }

    /// docs/domain.md 5.5: the action and the unexpected literal first, then the relevant literals
    /// sorted; a new constant reuses the variable of a matching vocabulary feature.
    #[test]
    fn lifting_example_reuse_across_samples() {
        let mut lifter = Lifter::new(sig(), Algebra::default());
        // Sample 1: pickup(rob1, red) with red on green; in_hand(rob1, red) was unexpected.
        let s1 = lifter.lift(
            &[g(IN_HAND, &["rob1", "red"])],
            &g("pickup", &["rob1", "red"]),
            &[Literal::relation("on", "red", "green"), not_in_hand("red")],
        );
        assert_eq!(s1.unexpected, vec![in_hand(true, r(1), o(1))]);
        assert_eq!(s1.action, Literal::new("pickup", vec![r(1), o(1)]));
        // Sorted: relation(...) < in_hand? Literals sort by sign first: -in_hand (negative)
        // comes before positive relation. -in_hand(rob1, red) -> -in_hand(R1, O1); then
        // on(red, green): green is new, no feature relation(on, O1, _) yet -> O2.
        assert_eq!(
            lifter.features,
            vec![in_hand(false, r(1), o(1)), rel("on", o(1), o(2))]
        );
        assert_eq!(s1.features, vec![0, 1]);
        // Sample 2: pickup(rob1, blue) with blue on the table: on(O1, _) matches feature 1, so
        // the table takes O2 as green did.
        let s2 = lifter.lift(
            &[g(IN_HAND, &["rob1", "blue"])],
            &g("pickup", &["rob1", "blue"]),
            &[Literal::relation("on", "blue", "table")],
        );
        assert_eq!(s2.features, vec![1]);
        // Sample 3: something is on the action object: on(_, O1) matches nothing -> O3.
        let s3 = lifter.lift(
            &[],
            &g("pickup", &["rob1", "green"]),
            &[Literal::relation("on", "red", "green")],
        );
        assert_eq!(s3.action, Literal::new("pickup", vec![r(1), o(1)]));
        assert_eq!(lifter.features[2], rel("on", o(3), o(1)));
        assert_eq!(s3.features, vec![2]);
    }

    /// "Some object not in hand" collapses onto one variable, distinct from the action object.
    #[test]
    fn lifting_example_role_collapse() {
        let mut lifter = Lifter::new(sig(), Algebra::default());
        let s = lifter.lift(
            &[not_in_hand("red")],
            &g("putdown", &["rob1", "red", "green"]),
            &[
                not_in_hand("blue"),
                not_in_hand("duck"),
                g(IN_HAND, &["rob1", "red"]),
            ],
        );
        assert_eq!(s.unexpected, vec![in_hand(false, r(1), o(1))]);
        assert_eq!(s.action, Literal::new("putdown", vec![r(1), o(1), o(2)]));
        // -in_hand(rob1, blue): no feature yet -> O3; -in_hand(rob1, duck) matches
        // -in_hand(R1, O3) -> O3 (collapsed); in_hand(rob1, red) is fully named.
        assert_eq!(
            lifter.features,
            vec![in_hand(false, r(1), o(3)), in_hand(true, r(1), o(1))]
        );
        assert_eq!(s.features, vec![0, 1]);
        // The paper's over-specified example uses exactly such a feature: -in_hand(R1, O5).
    }

    #[test]
    fn converse_normalization() {
        let mut lifter = Lifter::new(sig(), Algebra::ra());
        let s = lifter.lift(
            &[],
            &g("pickup", &["rob1", "red"]),
            &[
                Literal::relation("above", "green", "red"),
                Literal::relation("below", "red", "green"),
                Literal::relation("touch", "green", "red"),
                Literal::relation("touch", "red", "green"),
            ],
        );
        // above(green, red) -> above(O2, O1), normalized to below(O1, O2), the same feature as
        // the literal below(red, green); both touch spellings become touch(O1, O2).
        assert_eq!(
            lifter.features,
            vec![rel("below", o(1), o(2)), rel("touch", o(1), o(2))]
        );
        assert_eq!(s.features, vec![0, 1]);
    }

    #[test]
    fn head_choice() {
        let mk = |u: Vec<Literal>| Lifted {
            unexpected: u,
            action: Literal::new("putdown", vec![r(1), o(1), o(2)]),
            features: vec![],
        };
        let a = in_hand(false, r(1), o(1));
        let b = rel("on", o(3), o(4));
        let samples = vec![
            mk(vec![a.clone(), b.clone()]),
            mk(vec![b.clone()]),
            mk(vec![a.clone()]),
        ];
        // Two each: a shares R1 and O1 with the action, b nothing.
        assert_eq!(choose_head(&samples).unwrap().0, a);
        let samples = vec![mk(vec![b.clone()]), mk(vec![b.clone()]), mk(vec![a])];
        assert_eq!(choose_head(&samples).unwrap().0, b);
    }
}
