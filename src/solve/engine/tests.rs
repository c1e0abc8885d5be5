//! Unit tests of the CDCL engine: pigeonhole refutations, both deletion policies under frequent
//! reductions, weight constraints and shared loop formulas.

use super::*;

fn lits(e: &mut Engine, n: usize) -> Vec<Var> {
    (0..n).map(|_| e.new_var()).collect()
}

#[test]
fn luby_sequence() {
    let got: Vec<u64> = (0..7).map(Engine::luby).collect();
    assert_eq!(got, vec![1, 1, 2, 1, 1, 2, 4]);
}

#[test]
fn failed_assumptions_are_the_ones_the_refutation_uses() {
    // x -> y, y -> -z; w is unrelated. Assuming w, x, z fails on z, because of x.
    let mut e = Engine::new();
    let v = lits(&mut e, 4);
    let (x, y, z, w) = (v[0], v[1], v[2], v[3]);
    e.add_clause(&[x.negative(), y.positive()]);
    e.add_clause(&[y.negative(), z.negative()]);
    let assumptions = [w.positive(), x.positive(), z.positive()];
    assert_eq!(e.search(&assumptions), SearchResult::Unsat);
    let mut failed = e.failed_assumptions().to_vec();
    assert_eq!(failed[0], z.positive(), "the failed assumption comes first");
    failed.sort_by_key(|l| l.code());
    let mut expected = vec![z.positive(), x.positive()];
    expected.sort_by_key(|l| l.code());
    assert_eq!(failed, expected);
    // The core alone is refuted; without x the rest is satisfiable.
    assert_eq!(e.search(&[x.positive(), z.positive()]), SearchResult::Unsat);
    assert_eq!(e.search(&[w.positive(), z.positive()]), SearchResult::Sat);
    // Contradictory assumptions are a core of two; a fact false at level 0 one of one.
    assert_eq!(e.search(&[w.positive(), w.negative()]), SearchResult::Unsat);
    let mut failed = e.failed_assumptions().to_vec();
    failed.sort_by_key(|l| l.code());
    assert_eq!(failed, vec![w.positive(), w.negative()]);
    e.add_clause(&[y.negative()]);
    assert_eq!(e.search(&[w.positive(), y.positive()]), SearchResult::Unsat);
    assert_eq!(e.failed_assumptions(), &[y.positive()]);
}

#[test]
fn pigeonhole_three_in_two_is_unsat() {
    // p(i, j): pigeon i in hole j; each pigeon somewhere, no two share a hole.
    let mut e = Engine::new();
    let v = lits(&mut e, 6);
    let p = |i: usize, j: usize| v[i * 2 + j];
    for i in 0..3 {
        e.add_clause(&[p(i, 0).positive(), p(i, 1).positive()]);
    }
    for j in 0..2 {
        for a in 0..3 {
            for b in a + 1..3 {
                e.add_clause(&[p(a, j).negative(), p(b, j).negative()]);
            }
        }
    }
    assert_eq!(e.search(&[]), SearchResult::Unsat);
}

/// Pigeons into holes as clauses: every pigeon somewhere, no two in one hole.
fn pigeons(e: &mut Engine, pigeons: usize, holes: usize) -> Vec<Var> {
    let v = lits(e, pigeons * holes);
    for i in 0..pigeons {
        let some: Vec<Lit> = (0..holes).map(|j| v[i * holes + j].positive()).collect();
        e.add_clause(&some);
    }
    for j in 0..holes {
        for a in 0..pigeons {
            for b in a + 1..pigeons {
                e.add_clause(&[v[a * holes + j].negative(), v[b * holes + j].negative()]);
            }
        }
    }
    v
}

#[test]
fn both_deletion_policies_stay_sound_under_frequent_reductions() {
    // Reductions every few conflicts delete clauses while others are reasons; the answers
    // must not change: 7 pigeons do not fit in 6 holes (thousands of conflicts), 6 do,
    // and the model found must satisfy every clause.
    for deletion in [Deletion::Sorted, Deletion::Basic] {
        for (first, inc, repeat) in [(20, 5, 3), (50, 0, 0)] {
            let mut e = Engine::new();
            e.settings.deletion = deletion;
            e.settings.reduce = ReduceSchedule::Conflicts { first, inc, repeat };
            e.sched.restarts = Restarts::Luby {
                unit: 16,
                index: 0,
                left: 16,
            };
            pigeons(&mut e, 7, 6);
            assert_eq!(e.search(&[]), SearchResult::Unsat, "{deletion:?}");
            assert!(
                e.sched.reductions > 3,
                "the test needs reductions: {}",
                e.sched.reductions
            );
            let mut e = Engine::new();
            e.settings.deletion = deletion;
            e.settings.reduce = ReduceSchedule::Conflicts { first, inc, repeat };
            let v = pigeons(&mut e, 6, 6);
            assert_eq!(e.search(&[]), SearchResult::Sat, "{deletion:?}");
            for j in 0..6 {
                let in_hole = (0..6)
                    .filter(|&i| e.value(v[i * 6 + j].positive()) == Some(true))
                    .count();
                assert_eq!(in_hole, 1, "{deletion:?}: hole {j}");
            }
        }
    }
}

#[test]
fn phase_switch_lasts_one_search_call() {
    // 6 pigeons in 5 holes take well over 20 conflicts: the switch happens once, in the call
    // that needs them, and the next call starts with the configured phase handling again.
    let mut e = Engine::new();
    e.settings.phase_switch = Some(20);
    pigeons(&mut e, 6, 5);
    assert_eq!(e.search(&[]), SearchResult::Unsat);
    assert!(
        e.stats.conflicts > 20,
        "the test needs conflicts: {}",
        e.stats.conflicts
    );
    assert_eq!(e.stats.phase_switches, 1);
    assert_eq!(e.settings.save_progress, PHASE_SWITCH_PROGRESS);
    assert!(e.settings.sign_from_learnts);
    // The next call starts with the configured values (here left as by a switched call).
    let mut e2 = Engine::new();
    let w = pigeons(&mut e2, 5, 5);
    e2.heur.phase_switched = Some((0, false));
    e2.settings.save_progress = PHASE_SWITCH_PROGRESS;
    e2.settings.sign_from_learnts = true;
    assert_eq!(e2.search(&[]), SearchResult::Sat);
    assert_eq!(
        (e2.settings.save_progress, e2.settings.sign_from_learnts),
        (0, false)
    );
    assert!(w.iter().any(|x| e2.value(x.positive()) == Some(true)));
}

#[test]
fn weight_constraint_propagates() {
    // h <-> 2a + 1b + 1c >= 3, h true, a false: then b and c must be true... 1+1 < 3, so
    // the constraint is unsatisfiable with a false and h true.
    let mut e = Engine::new();
    let v = lits(&mut e, 4);
    let (h, a, b, c) = (v[0], v[1], v[2], v[3]);
    e.add_weight(
        h.positive(),
        &[(a.positive(), 2), (b.positive(), 1), (c.positive(), 1)],
        3,
    );
    e.add_clause(&[h.positive()]);
    assert_eq!(e.search(&[a.negative()]), SearchResult::Unsat);
    assert_eq!(e.search(&[a.positive(), c.negative()]), SearchResult::Sat);
    assert_eq!(e.value(b.positive()), Some(true));
}

/// Opens a decision level and decides `l` (as `search` does).
fn decide(e: &mut Engine, l: Lit) {
    e.asg.trail_lim.push(e.asg.trail.len());
    e.assign(l, Reason::Decision);
    assert!(e.propagate().is_none());
}

#[test]
fn shared_loop_formula_propagates_atoms_and_external_bodies() {
    // Unfounded set {a1, a2} with external bodies b1, b2, b3: the loop nogoods are
    // a1 -> b1 | b2 | b3 and a2 -> b1 | b2 | b3, learnt as one formula (hand-derived).
    let mut e = Engine::new();
    e.settings.shared_loops = true;
    let v = lits(&mut e, 5);
    let (a1, a2) = (v[0].positive(), v[1].positive());
    let (b1, b2, b3) = (v[2].positive(), v[3].positive(), v[4].positive());
    decide(&mut e, !b1);
    decide(&mut e, !b2);
    decide(&mut e, !b3);
    // Every external body false: both atoms false, at the level of the latest body.
    assert!(!e.add_loop_set(&[a1, a2], &[b1, b2, b3]));
    assert_eq!(e.db.loops.live, 1, "one formula, not two clauses");
    assert_eq!(e.value(a1), Some(false));
    assert_eq!(e.value(a2), Some(false));
    assert_eq!(e.level_of(a1), 3);
    let mut r = Vec::new();
    e.reason_lits(a1.var(), &mut r);
    r.sort();
    assert_eq!(r, vec![b1, b2, b3]);
    // Undo b3; making a2 true leaves b3 as the only support: it is implied, with the
    // reason "a2 true, b1 and b2 false".
    e.backtrack(2);
    decide(&mut e, a2);
    assert_eq!(e.value(b3), Some(true));
    let mut r = Vec::new();
    e.reason_lits(b3.var(), &mut r);
    r.sort();
    let mut want = vec![b1, b2, !a2];
    want.sort();
    assert_eq!(r, want);
    // b3 false with a2 true is a conflict.
    e.backtrack(2);
    decide(&mut e, !b3);
    assert!(e.value(a2) == Some(false) && e.value(a1) == Some(false));
    e.backtrack(1);
    e.asg.trail_lim.push(e.asg.trail.len());
    for l in [a1, !b2, !b3] {
        e.assign(l, Reason::Decision);
    }
    assert!(
        e.propagate().is_some(),
        "a1 true and every external body false"
    );
    // At level 0 with b1 false, the formula shrinks to b2 | b3 and keeps propagating.
    e.backtrack(0);
    e.assign(!b1, Reason::Decision);
    assert!(e.propagate().is_none());
    e.simplify();
    assert_eq!(e.db.loops.live, 1);
    decide(&mut e, !b2);
    decide(&mut e, !b3);
    assert_eq!(e.value(a1), Some(false));
    assert_eq!(e.value(a2), Some(false));
}
