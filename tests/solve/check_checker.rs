//! The stable-model checker on hand-derived cases. Each case says why the candidate is or is
//! not a stable model (the reduct and its least or minimal models, worked out by hand).

use lucent::ground::program::{
    Atom, Body, BodyRef, Edge, ExternalValue, GroundProgram, HeadKind, Lit, Rule, Weight,
};
use lucent::solve::check::{check, Violation};

fn weight(head: &[Atom], lower: Weight, lits: &[(Lit, Weight)]) -> Rule {
    Rule {
        head_kind: HeadKind::Disjunction,
        head: head.to_vec(),
        body: Body::Weight {
            lower,
            lits: lits.to_vec(),
        },
    }
}

fn program(num_atoms: u32, rules: Vec<Rule>) -> GroundProgram {
    GroundProgram {
        num_atoms,
        rules: rules.into(),
        ..Default::default()
    }
}

#[test]
fn even_negative_loop() {
    // a :- not b.  b :- not a.   (a = 1, b = 2)
    let p = program(
        2,
        vec![Rule::normal(&[1], &[-2]), Rule::normal(&[2], &[-1])],
    );
    // {a}: the reduct is {a.}; its least model is {a}.
    assert_eq!(check(&p, &[1]), Ok(()));
    assert_eq!(check(&p, &[2]), Ok(()));
    // {}: the body of the first rule holds, its head does not.
    assert_eq!(check(&p, &[]), Err(Violation::RuleViolated { rule: 0 }));
    // {a, b}: both rules are removed by the reduct; nothing is derived.
    assert_eq!(
        check(&p, &[1, 2]),
        Err(Violation::Unsupported { atoms: vec![1, 2] })
    );
}

#[test]
fn odd_loop_has_no_stable_model() {
    // a :- not a.  {} violates the rule; {a} has the empty reduct.
    let p = program(1, vec![Rule::normal(&[1], &[-1])]);
    assert_eq!(check(&p, &[]), Err(Violation::RuleViolated { rule: 0 }));
    assert_eq!(
        check(&p, &[1]),
        Err(Violation::Unsupported { atoms: vec![1] })
    );
}

#[test]
fn positive_loop_is_unfounded() {
    // a :- b.  b :- a.  {a, b} is a model but the least model of the (same) reduct is {}.
    let p = program(2, vec![Rule::normal(&[1], &[2]), Rule::normal(&[2], &[1])]);
    assert_eq!(check(&p, &[]), Ok(()));
    assert_eq!(
        check(&p, &[1, 2]),
        Err(Violation::Unsupported { atoms: vec![1, 2] })
    );
    // c. a :- b. b :- a, c.  still unfounded with a fact in the loop's body.
    let p = program(
        3,
        vec![
            Rule::normal(&[3], &[]),
            Rule::normal(&[1], &[2]),
            Rule::normal(&[2], &[1, 3]),
        ],
    );
    assert_eq!(check(&p, &[3]), Ok(()));
    assert_eq!(
        check(&p, &[1, 2, 3]),
        Err(Violation::Unsupported { atoms: vec![1, 2] })
    );
}

#[test]
fn choice_rules() {
    // {a}.  b :- a.   (a = 1, b = 2)
    let p = program(2, vec![Rule::choice(&[1], &[]), Rule::normal(&[2], &[1])]);
    // The reduct of {a, b} is {a. b :- a.}: least model {a, b}.
    assert_eq!(check(&p, &[1, 2]), Ok(()));
    // The reduct of {} drops the choice (a is false): least model {}.
    assert_eq!(check(&p, &[]), Ok(()));
    // {b}: the choice contributes nothing for a, so b is not derived.
    assert_eq!(
        check(&p, &[2]),
        Err(Violation::Unsupported { atoms: vec![2] })
    );
    // {a}: b :- a is violated.
    assert_eq!(check(&p, &[1]), Err(Violation::RuleViolated { rule: 1 }));
    // A choice with a false negative body literal supports nothing: {a} :- not b. b.
    let p = program(2, vec![Rule::choice(&[1], &[-2]), Rule::normal(&[2], &[])]);
    assert_eq!(check(&p, &[2]), Ok(()));
    assert_eq!(
        check(&p, &[1, 2]),
        Err(Violation::Unsupported { atoms: vec![1] })
    );
}

#[test]
fn weight_bodies() {
    // {a; b}.  c :- 2 { a = 1, b = 1, not d = 1 }.   (a = 1, b = 2, c = 3, d = 4)
    let p = program(
        4,
        vec![
            Rule::choice(&[1, 2], &[]),
            weight(&[3], 2, &[(1, 1), (2, 1), (-4, 1)]),
        ],
    );
    // {a, c}: `not d` is true, so the reduct's bound is 2 - 1 = 1 over {a = 1, b = 1}; a gives c.
    assert_eq!(check(&p, &[1, 3]), Ok(()));
    assert_eq!(check(&p, &[1, 2, 3]), Ok(()));
    // {c}: the body weighs 1 < 2, and the reduct needs one of a, b: c is unsupported.
    assert_eq!(
        check(&p, &[3]),
        Err(Violation::Unsupported { atoms: vec![3] })
    );
    // {a}: the body weighs 2, so c must hold.
    assert_eq!(check(&p, &[1]), Err(Violation::RuleViolated { rule: 1 }));
}

#[test]
fn weight_body_negative_literal_on_the_head() {
    // a :- 1 { not a = 1 }.  Like a :- not a: no stable model.
    let p = program(1, vec![weight(&[1], 1, &[(-1, 1)])]);
    assert_eq!(check(&p, &[]), Err(Violation::RuleViolated { rule: 0 }));
    assert_eq!(
        check(&p, &[1]),
        Err(Violation::Unsupported { atoms: vec![1] })
    );
}

#[test]
fn weight_bodies_do_not_support_themselves() {
    // a :- 1 { b = 1 }.  b :- 1 { a = 1 }.  {a, b} is unfounded.
    let p = program(
        2,
        vec![weight(&[1], 1, &[(2, 1)]), weight(&[2], 1, &[(1, 1)])],
    );
    assert_eq!(check(&p, &[]), Ok(()));
    assert_eq!(
        check(&p, &[1, 2]),
        Err(Violation::Unsupported { atoms: vec![1, 2] })
    );
    // a :- 3 { b = 2, c = 2 }.  b.  {c} :- b.  {a, b, c}: 2 + 2 >= 3; {a, b}: 2 < 3.
    let p = program(
        3,
        vec![
            weight(&[1], 3, &[(2, 2), (3, 2)]),
            Rule::normal(&[2], &[]),
            Rule::choice(&[3], &[2]),
        ],
    );
    assert_eq!(check(&p, &[1, 2, 3]), Ok(()));
    assert_eq!(check(&p, &[2]), Ok(()));
    assert_eq!(
        check(&p, &[1, 2]),
        Err(Violation::Unsupported { atoms: vec![1] })
    );
}

#[test]
fn constraints() {
    // {a}.  :- a.
    let p = program(1, vec![Rule::choice(&[1], &[]), Rule::normal(&[], &[1])]);
    assert_eq!(check(&p, &[]), Ok(()));
    assert_eq!(check(&p, &[1]), Err(Violation::RuleViolated { rule: 1 }));
}

#[test]
fn disjunction_is_minimal() {
    // a | b.
    let p = program(2, vec![Rule::normal(&[1, 2], &[])]);
    assert_eq!(check(&p, &[1]), Ok(()));
    assert_eq!(check(&p, &[2]), Ok(()));
    assert_eq!(check(&p, &[]), Err(Violation::RuleViolated { rule: 0 }));
    // {a, b} is a model of the reduct {a | b.}, but so is {b} (the search finds one of them).
    match check(&p, &[1, 2]) {
        Err(Violation::NotMinimal { smaller }) => assert!(smaller == [1] || smaller == [2]),
        other => panic!("{other:?}"),
    }
    // a | b.  a :- b.  The reduct's models inside {a, b} are {a} and {a, b}: only {a} is stable.
    let p = program(
        2,
        vec![Rule::normal(&[1, 2], &[]), Rule::normal(&[1], &[2])],
    );
    assert_eq!(check(&p, &[1]), Ok(()));
    assert_eq!(
        check(&p, &[1, 2]),
        Err(Violation::NotMinimal { smaller: vec![1] })
    );
}

#[test]
fn disjunction_with_head_cycle() {
    // p | q.  p :- q.  q :- p.  Every model of the reduct contains both: {p, q} is stable
    // (the program is not head-cycle-free, so shifting would wrongly reject it).
    let p = program(
        2,
        vec![
            Rule::normal(&[1, 2], &[]),
            Rule::normal(&[1], &[2]),
            Rule::normal(&[2], &[1]),
        ],
    );
    assert_eq!(check(&p, &[1, 2]), Ok(()));
    assert_eq!(check(&p, &[1]), Err(Violation::RuleViolated { rule: 2 }));
}

#[test]
fn disjunction_with_negation_in_the_body() {
    // a | b :- not c.  c :- not a, not b.   (a = 1, b = 2, c = 3)
    let p = program(
        3,
        vec![Rule::normal(&[1, 2], &[-3]), Rule::normal(&[3], &[-1, -2])],
    );
    // {c}: the first rule is removed by the reduct (c is true); c. remains.
    assert_eq!(check(&p, &[3]), Ok(()));
    assert_eq!(check(&p, &[1]), Ok(()));
    assert_eq!(check(&p, &[2]), Ok(()));
    assert!(matches!(
        check(&p, &[1, 2]),
        Err(Violation::NotMinimal { .. })
    ));
}

#[test]
fn externals() {
    let mut p = program(1, vec![]);
    p.externals.push((1, ExternalValue::Free));
    assert_eq!(check(&p, &[]), Ok(()));
    assert_eq!(check(&p, &[1]), Ok(()));
    // A later statement for the same atom wins: now it must be true.
    p.externals.push((1, ExternalValue::True));
    assert_eq!(check(&p, &[1]), Ok(()));
    assert_eq!(
        check(&p, &[]),
        Err(Violation::ExternalValue {
            atom: 1,
            value: ExternalValue::True
        })
    );
    // Released: an ordinary atom without rules, so it cannot be true.
    p.externals.push((1, ExternalValue::Release));
    assert_eq!(check(&p, &[]), Ok(()));
    assert_eq!(
        check(&p, &[1]),
        Err(Violation::Unsupported { atoms: vec![1] })
    );
}

#[test]
fn externals_with_rules_are_defined_by_their_rules() {
    // #external a. [true]   a :- b.   {b}.   (a = 1, b = 2)  As clasp: the rule defines a, the
    // external statement is ignored, so {} and {a, b} are the stable models and {a} is not.
    for value in [
        ExternalValue::Free,
        ExternalValue::True,
        ExternalValue::False,
    ] {
        let mut p = program(2, vec![Rule::normal(&[1], &[2]), Rule::choice(&[2], &[])]);
        p.externals.push((1, value));
        assert_eq!(check(&p, &[]), Ok(()), "{value:?}");
        assert_eq!(check(&p, &[1, 2]), Ok(()), "{value:?}");
        assert_eq!(
            check(&p, &[1]),
            Err(Violation::Unsupported { atoms: vec![1] }),
            "{value:?}"
        );
    }
}

#[test]
fn assumptions_and_unknown_atoms() {
    let mut p = program(2, vec![Rule::choice(&[1, 2], &[])]);
    p.assumptions = vec![1, -2];
    assert_eq!(check(&p, &[1]), Ok(()));
    assert_eq!(check(&p, &[1, 2]), Err(Violation::Assumption(-2)));
    assert_eq!(check(&p, &[3]), Err(Violation::UnknownAtom(3)));
    assert_eq!(check(&p, &[0]), Err(Violation::UnknownAtom(0)));
}

#[test]
fn atoms_above_num_atoms_do_not_panic() {
    // A program breaking its invariant (atom 5 with num_atoms = 1): atoms above num_atoms are
    // false. a :- not x5.  x5 :- x4.  x5 | x3 :- a.  with a = 1: {a} violates the last rule.
    let p = program(
        1,
        vec![
            Rule::normal(&[1], &[-5]),
            Rule::normal(&[5], &[4]),
            Rule::normal(&[5, 3], &[1]),
        ],
    );
    assert_eq!(check(&p, &[1]), Err(Violation::RuleViolated { rule: 2 }));
    let mut p = program(1, vec![Rule::normal(&[1], &[-5])]);
    p.externals.push((7, ExternalValue::True));
    assert!(check(&p, &[1]).is_err());
}

#[test]
fn edges_must_be_acyclic() {
    // {a; b}.  #edge (1,2) : a.  #edge (2,1) : b.  Both edges together form a cycle.
    let mut p = program(2, vec![Rule::choice(&[1, 2], &[])]);
    p.edges.push(Edge {
        from: 1,
        to: 2,
        condition: vec![1],
    });
    p.edges.push(Edge {
        from: 2,
        to: 1,
        condition: vec![2],
    });
    assert_eq!(check(&p, &[1]), Ok(()));
    assert_eq!(check(&p, &[2]), Ok(()));
    assert!(matches!(check(&p, &[1, 2]), Err(Violation::Cycle { .. })));
}

mod against_definition {
    //! The checker against the definition read literally: X is stable iff X is a model of P
    //! and no Y strictly inside X is a model of the reduct P^X (all subsets tried).

    use super::*;
    use proptest::prelude::*;

    fn holds(x: &[bool], l: Lit) -> bool {
        x[l.unsigned_abs() as usize] == (l > 0)
    }

    fn body_holds(x: &[bool], body: BodyRef<'_>) -> bool {
        match body {
            BodyRef::Normal(lits) => lits.iter().all(|&l| holds(x, l)),
            BodyRef::Weight { lower, lits } => {
                lits.iter()
                    .filter(|(l, _)| holds(x, *l))
                    .map(|(_, w)| w)
                    .sum::<Weight>()
                    >= lower
            }
        }
    }

    /// Whether Y is a model of P^X: positive literals evaluated in Y, negative ones in X.
    fn models_reduct(p: &GroundProgram, x: &[bool], y: &[bool]) -> bool {
        let reduct_holds = |l: Lit| if l > 0 { y[l as usize] } else { holds(x, l) };
        p.rules.iter().all(|r| {
            let body = match r.body {
                BodyRef::Normal(lits) => lits.iter().all(|&l| reduct_holds(l)),
                BodyRef::Weight { lower, lits } => {
                    lits.iter()
                        .filter(|(l, _)| reduct_holds(*l))
                        .map(|(_, w)| w)
                        .sum::<Weight>()
                        >= lower
                }
            };
            !body
                || match r.head_kind {
                    HeadKind::Disjunction => r.head.iter().any(|&h| y[h as usize]),
                    HeadKind::Choice => r.head.iter().all(|&h| !x[h as usize] || y[h as usize]),
                }
        })
    }

    fn stable(p: &GroundProgram, x: &[bool]) -> bool {
        let n = p.num_atoms as usize;
        let model = p.rules.iter().all(|r| {
            r.head_kind == HeadKind::Choice
                || !body_holds(x, r.body)
                || r.head.iter().any(|&h| x[h as usize])
        });
        if !model {
            return false;
        }
        let inside: Vec<usize> = (1..=n).filter(|&a| x[a]).collect();
        (0u32..(1 << inside.len()) - 1).all(|mask| {
            let mut y = vec![false; n + 1];
            for (i, &a) in inside.iter().enumerate() {
                y[a] = mask >> i & 1 == 1;
            }
            !models_reduct(p, x, &y)
        })
    }

    fn arb_rule(n: u32) -> impl Strategy<Value = Rule> {
        let atom = 1..=n;
        let lit = (1..=n as i32, any::<bool>()).prop_map(|(a, neg)| if neg { -a } else { a });
        let head = proptest::collection::vec(atom, 0..3);
        let normal = proptest::collection::vec(lit.clone(), 0..3).prop_map(Body::Normal);
        let weighted = (0..4i64, proptest::collection::vec((lit, 0..3i64), 0..4))
            .prop_map(|(lower, lits)| Body::Weight { lower, lits });
        let body = prop_oneof![3 => normal, 1 => weighted];
        (head, body, any::<bool>()).prop_map(|(head, body, is_choice)| Rule {
            head_kind: if is_choice {
                HeadKind::Choice
            } else {
                HeadKind::Disjunction
            },
            head,
            body,
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(400))]
        #[test]
        fn checker_matches_definition(rules in proptest::collection::vec(arb_rule(5), 1..7)) {
            let p = program(5, rules);
            for mask in 0u32..32 {
                let x: Vec<bool> = (0..=5).map(|a| a > 0 && mask >> (a - 1) & 1 == 1).collect();
                let atoms: Vec<Atom> = (1..=5).filter(|&a| x[a as usize]).collect();
                prop_assert_eq!(check(&p, &atoms).is_ok(), stable(&p, &x), "candidate {:?}", atoms);
            }
        }
    }
}
