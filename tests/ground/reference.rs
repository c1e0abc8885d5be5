//! Property: on random stratified normal programs, the grounder's facts are exactly the perfect
//! model computed by the naive reference grounder, and nothing else is left (every derived atom
//! of a stratified program is a fact after simplification).

use std::collections::BTreeSet;

use lucent::ground::reference::{perfect_model, show, to_ast, RAtom, RRule, RTerm};
use lucent::ground::{ground, GroundConfig};
use proptest::prelude::*;

const PREDS: u8 = 4;

/// An atom of predicate `pred` (arity `pred % 3`) over variables from `vars` or constants 0..3.
fn atom(pred: u8, vars: Vec<u8>) -> impl Strategy<Value = RAtom> {
    let arity = (pred % 3) as usize;
    proptest::collection::vec(
        prop_oneof![
            (0..3i32).prop_map(RTerm::Const),
            proptest::sample::select(if vars.is_empty() {
                vec![0u8]
            } else {
                vars.clone()
            })
            .prop_map(RTerm::Var),
        ],
        arity,
    )
    .prop_map(move |args| RAtom { pred, args })
}

fn vars_of(atoms: &[RAtom]) -> Vec<u8> {
    let mut v: Vec<u8> = atoms
        .iter()
        .flat_map(|a| a.args.iter())
        .filter_map(|t| match t {
            RTerm::Var(x) => Some(*x),
            RTerm::Const(_) => None,
        })
        .collect();
    v.sort();
    v.dedup();
    v
}

/// Grounds a term list so that every variable is bound: unbound ones become constants.
fn restrict(a: RAtom, bound: &[u8]) -> RAtom {
    RAtom {
        pred: a.pred,
        args: a
            .args
            .into_iter()
            .map(|t| match t {
                RTerm::Var(v) if !bound.contains(&v) => RTerm::Const(v as i32 % 3),
                t => t,
            })
            .collect(),
    }
}

/// A safe rule with head predicate `head`: positive body over predicates `<= head`, negative
/// over predicates `< head`.
fn rule(head: u8) -> impl Strategy<Value = RRule> {
    let pos_preds = proptest::collection::vec(0..=head, 0..3);
    pos_preds
        .prop_flat_map(move |pp| {
            let pos: Vec<_> = pp.iter().map(|&p| atom(p, vec![0, 1, 2])).collect();
            (pos, proptest::collection::vec(0..head.max(1), 0..2))
        })
        .prop_flat_map(move |(pos, np)| {
            let bound = vars_of(&pos);
            let neg: Vec<_> = if head == 0 {
                Vec::new()
            } else {
                np.iter().map(|&p| atom(p, bound.clone())).collect()
            };
            (Just(pos), neg, atom(head, bound.clone()), Just(bound))
        })
        .prop_map(|(pos, neg, h, bound)| RRule {
            head: restrict(h, &bound),
            neg: neg.into_iter().map(|a| restrict(a, &bound)).collect(),
            pos,
        })
}

fn program() -> impl Strategy<Value = Vec<RRule>> {
    proptest::collection::vec((0..PREDS).prop_flat_map(rule), 1..8)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]
    #[test]
    fn facts_are_the_perfect_model(rules in program()) {
        let expected: BTreeSet<String> = perfect_model(&rules, PREDS).iter().map(show).collect();
        let result = ground(&to_ast(&rules), None, &GroundConfig::default());
        prop_assert!(!result.diagnostics.has_errors(), "{:?}", result.diagnostics.items());
        let facts: BTreeSet<String> = result.facts().into_iter().collect();
        prop_assert_eq!(&facts, &expected);
        // Every remaining rule is a fact rule.
        for r in &result.program.rules {
            prop_assert!(r.body.is_empty_normal(), "{:?}", r);
        }
        let shown: BTreeSet<String> = result.program.outputs.iter().map(|o| o.symbol.clone()).collect();
        prop_assert_eq!(shown, expected);
    }
}

/// A case the property above found (proptest, 2026-12-07): `p3`'s rule is grounded while
/// `p2(0,0)` is still undecided (its rule waits on `p1(1)`, which nothing derives). Every atom
/// is decided by the rules (the perfect model is `p0`, `p2(0,0)`), so what is left must be
/// those two facts and nothing else: before the simplifier derived facts from bodies that hold,
/// `p3` stayed possible, shown under its own literal with no rule left to derive it.
#[test]
fn an_atom_whose_rule_a_later_fact_kills_is_not_shown() {
    let text = "p3 :- not p2(0,0). p1(2) :- p0, p1(1), not p0. p0. p2(0,0) :- p0, not p1(1).";
    let (g, _) = crate::support::ground::ground_text("order.lp", text, &GroundConfig::default());
    let facts: BTreeSet<String> = g.facts().into_iter().collect();
    let expected: BTreeSet<String> = ["p0", "p2(0,0)"].map(String::from).into();
    assert_eq!(facts, expected);
    for r in &g.program.rules {
        assert!(r.body.is_empty_normal(), "{r:?}");
    }
    let shown: BTreeSet<String> = g.program.outputs.iter().map(|o| o.symbol.clone()).collect();
    assert_eq!(shown, expected);
    assert!(g.program.outputs.iter().all(|o| o.condition.is_empty()));
}
