//! Multi-shot solving (issue 12): a random program given to one `Solver` in k chunks
//! (`Solver::add_program`) has, after each chunk, the answer sets of the chunks so far taken as
//! one program, and after the last chunk those of the whole program solved at once; the
//! reference is the brute-force enumerator (`solve::brute`).
//!
//! Chunks follow clingo's multi-shot model: all rules of an atom come in one chunk; an atom
//! that exists (is numbered at most the largest atom so far) before the chunk that defines it
//! is declared external until then. Rules, CR rules, minimize statements and external
//! statements are spread over the chunks; externals of the program itself get new values in
//! later chunks (`assign_external`, `release_external` or a new external statement).

use lucent::ground::program::{
    Body, CrRule, ExternalValue, GroundProgram, HeadKind, Minimize, Rule,
};
use lucent::solve::brute::{self, BruteConfig};
use lucent::solve::check;
use lucent::solve::{Config, CrMode, OptMode, SolveError, Solver};
use proptest::prelude::*;

/// The number of cases of a property: `default`, or `PROPTEST_CASES` when set.
fn cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn lit_strategy(n: u32) -> impl Strategy<Value = i32> {
    (1..=n, any::<bool>()).prop_map(|(a, pos)| if pos { a as i32 } else { -(a as i32) })
}

/// Rules over atoms `1..=n`, mostly positive bodies (so that positive loops, also across
/// chunks, are frequent), with choices, weight bodies, disjunctions and constraints.
fn rule_strategy(n: u32) -> impl Strategy<Value = Rule> {
    let lit = prop_oneof![3 => (1..=n).prop_map(|a| a as i32), 2 => lit_strategy(n)];
    (
        any::<u8>(),
        1..=n,
        1..=n,
        prop::collection::vec(lit, 0..4),
        1i64..4,
    )
        .prop_map(|(k, h, g, body, lower)| match k % 10 {
            0 => Rule::choice(&[h], &body),
            1 => Rule {
                head_kind: HeadKind::Disjunction,
                head: vec![h],
                body: Body::Weight {
                    lower,
                    lits: body
                        .iter()
                        .enumerate()
                        .map(|(i, &l)| (l, 1 + (i as i64 + lower) % 3))
                        .collect(),
                },
            },
            2 if !body.is_empty() => Rule::normal(&[], &body[..1]),
            3 => Rule::normal(&[h, g], &body),
            4 => Rule::choice(&[h, g], &body),
            _ => Rule::normal(&[h], &body),
        })
}

/// A program of up to 10 atoms: a few choices, random rules, up to two minimize statements,
/// up to two CR rules (`{r}.` and `h :- r, not b.`), and externals on some atoms.
fn program_strategy(with_cr: bool) -> impl Strategy<Value = GroundProgram> {
    (3u32..9)
        .prop_flat_map(move |n| {
            (
                Just(n),
                prop::collection::vec(1..=n, 0..3),
                prop::collection::vec(rule_strategy(n), 1..12),
                prop::collection::vec(
                    (
                        0i64..2,
                        prop::collection::vec((lit_strategy(n), -2i64..4), 1..4),
                    ),
                    0..3,
                ),
                prop::collection::vec((1..=n, 1..=n), if with_cr { 1..3 } else { 0..1 }),
                prop::collection::vec((1..=n, 0u8..3), 0..3),
            )
        })
        .prop_map(|(n, free, rules, mins, crs, exts)| {
            let mut p = GroundProgram::new();
            p.num_atoms = n;
            for a in free {
                p.rules.push(Rule::choice(&[a], &[]));
            }
            p.rules.extend(rules);
            p.minimize = mins
                .into_iter()
                .map(|(priority, lits)| Minimize { priority, lits })
                .collect();
            for (i, (h, b)) in crs.into_iter().enumerate() {
                let appl = p.new_atom();
                p.rules.push(Rule::choice(&[appl], &[]));
                p.rules
                    .push(Rule::normal(&[h], &[appl as i32, -(b as i32)]));
                p.cr_rules.push(CrRule {
                    appl,
                    label: format!("r{i}"),
                });
            }
            p.externals = exts
                .into_iter()
                .map(|(a, v)| {
                    let values = [
                        ExternalValue::Free,
                        ExternalValue::True,
                        ExternalValue::False,
                    ];
                    (a, values[v as usize % 3])
                })
                .collect();
            p
        })
}

/// Every atom mentioned by a statement of `p` other than an output.
fn mentioned(p: &GroundProgram) -> Vec<u32> {
    let mut v: Vec<u32> = Vec::new();
    for r in p.rules.iter() {
        v.extend_from_slice(r.head);
        match r.body {
            lucent::ground::program::BodyRef::Normal(ls) => {
                v.extend(ls.iter().map(|l| l.unsigned_abs()))
            }
            lucent::ground::program::BodyRef::Weight { lits, .. } => {
                v.extend(lits.iter().map(|(l, _)| l.unsigned_abs()))
            }
        }
    }
    for m in &p.minimize {
        v.extend(m.lits.iter().map(|(l, _)| l.unsigned_abs()));
    }
    v.extend(p.externals.iter().map(|&(a, _)| a));
    v.extend(p.cr_rules.iter().map(|c| c.appl));
    v
}

/// A change of an external's value between two chunks.
#[derive(Clone, Debug)]
enum ExtChange {
    /// Through `Solver::assign_external` (or `release_external`).
    Call(u32, ExternalValue),
    /// Through an external statement of the next chunk.
    Statement(u32, ExternalValue),
}

/// Splits `p` into `k` chunks: the deltas, and the external changes made before each delta.
/// `atom_chunk[a - 1]` proposes a chunk for atom `a`; the atoms of one rule head share the
/// latest chunk proposed for any of them. `picks` places constraints and minimize statements.
fn split(
    p: &GroundProgram,
    k: usize,
    atom_chunk: &[usize],
    picks: &[usize],
    changes: &[(u32, u8, bool)],
) -> Vec<(Vec<ExtChange>, GroundProgram)> {
    let n = p.num_atoms as usize;
    // Union-find over atoms sharing a rule head.
    let mut parent: Vec<usize> = (0..=n).collect();
    fn find(parent: &mut [usize], x: usize) -> usize {
        let mut r = x;
        while parent[r] != r {
            r = parent[r];
        }
        parent[x] = r;
        r
    }
    for r in p.rules.iter() {
        for w in r.head.windows(2) {
            let (a, b) = (
                find(&mut parent, w[0] as usize),
                find(&mut parent, w[1] as usize),
            );
            parent[a] = b;
        }
    }
    let mut class_chunk = vec![0usize; n + 1];
    for a in 1..=n {
        let c = find(&mut parent, a);
        class_chunk[c] = class_chunk[c].max(atom_chunk[(a - 1) % atom_chunk.len()] % k);
    }
    let chunk_of = |parent: &mut [usize], a: u32| class_chunk[find(parent, a as usize)];
    let mut deltas: Vec<GroundProgram> = vec![GroundProgram::new(); k];
    let mut defined_at: Vec<Option<usize>> = vec![None; n + 1];
    for (i, r) in p.rules.iter().enumerate() {
        let c = match r.head.first() {
            Some(&h) => chunk_of(&mut parent, h),
            None => picks[i % picks.len()] % k,
        };
        for &h in r.head {
            defined_at[h as usize] = Some(c);
        }
        deltas[c].rules.push_ref(r);
    }
    for (i, m) in p.minimize.iter().enumerate() {
        deltas[picks[(i + 7) % picks.len()] % k]
            .minimize
            .push(m.clone());
    }
    for c in &p.cr_rules {
        deltas[chunk_of(&mut parent, c.appl)]
            .cr_rules
            .push(c.clone());
    }
    // The program's own externals come in the chunk proposed for their atom.
    for &(a, v) in &p.externals {
        deltas[chunk_of(&mut parent, a)].externals.push((a, v));
    }
    // Number the atoms: each chunk covers every atom mentioned so far; atoms defined later are
    // external until then.
    let mut out = Vec::new();
    let mut top = 0u32;
    let mut declared = vec![false; n + 1];
    for (j, mut d) in deltas.into_iter().enumerate() {
        top = top.max(mentioned(&d).into_iter().max().unwrap_or(0));
        let mut pending: Vec<(u32, ExternalValue)> = Vec::new();
        for a in 1..=top {
            if !declared[a as usize] && defined_at[a as usize].is_some_and(|c| c > j) {
                declared[a as usize] = true;
                let v = if a % 2 == 0 {
                    ExternalValue::Free
                } else {
                    ExternalValue::False
                };
                pending.push((a, v));
            }
        }
        pending.append(&mut d.externals);
        d.externals = pending;
        d.num_atoms = top;
        // Value changes for the program's externals that are never defined, before this chunk.
        let mut ch = Vec::new();
        if j > 0 {
            for &(a, v, by_call) in changes.iter().filter(|c| c.0 as usize <= n) {
                if defined_at[a as usize].is_none()
                    && p.externals.iter().any(|e| e.0 == a)
                    && chunk_of(&mut parent, a) < j
                    && (a as usize + j) % 2 == 0
                {
                    let v = [
                        ExternalValue::Free,
                        ExternalValue::True,
                        ExternalValue::False,
                        ExternalValue::Release,
                    ][v as usize % 4];
                    ch.push(if by_call {
                        ExtChange::Call(a, v)
                    } else {
                        ExtChange::Statement(a, v)
                    });
                }
            }
        }
        out.push((ch, d));
    }
    out
}

/// The answer sets as (atoms without CR application atoms, costs), sorted; with `opt`, only
/// the optimal ones.
fn solver_sets(
    r: &lucent::solve::SolveResult,
    p: &GroundProgram,
    opt: bool,
) -> Vec<(Vec<u32>, Vec<i64>)> {
    let appl: Vec<u32> = p.cr_rules.iter().map(|c| c.appl).collect();
    let mut out: Vec<(Vec<u32>, Vec<i64>)> = r
        .models
        .iter()
        .filter(|m| !opt || m.optimal)
        .map(|m| {
            assert!(
                check::check(p, &m.atoms).is_ok(),
                "model {:?} is not stable",
                m.atoms
            );
            let atoms = m
                .atoms
                .iter()
                .copied()
                .filter(|a| !appl.contains(a))
                .collect();
            (atoms, if opt { m.costs.clone() } else { Vec::new() })
        })
        .collect();
    out.sort();
    out
}

fn brute_sets(p: &GroundProgram, opt: bool) -> Vec<(Vec<u32>, Vec<i64>)> {
    let cfg = BruteConfig {
        optimize: opt,
        cr_mode: CrMode::Cardinality,
    };
    let mut v: Vec<(Vec<u32>, Vec<i64>)> = brute::answer_sets(p, cfg)
        .into_iter()
        .map(|m| (m.atoms, if opt { m.costs } else { Vec::new() }))
        .collect();
    v.sort();
    v
}

/// Runs the chunks through one solver, comparing each step with the brute-force answer sets of
/// the chunks so far, and the end with a fresh solver on the whole program.
fn run_chunks(
    p: &GroundProgram,
    chunks: Vec<(Vec<ExtChange>, GroundProgram)>,
    opt: bool,
    assume: &[i32],
) -> Result<(), TestCaseError> {
    let cfg = Config {
        models: 0,
        opt_mode: if opt { OptMode::OptN } else { OptMode::Ignore },
        ..Config::default()
    };
    let mut so_far = GroundProgram::new();
    let mut s: Option<Solver> = None;
    for (step, (changes, delta)) in chunks.into_iter().enumerate() {
        for c in changes {
            let solver = s.as_mut().expect("changes come after the first chunk");
            match c {
                ExtChange::Call(a, v) => {
                    let r = if v == ExternalValue::Release {
                        solver.release_external(a)
                    } else {
                        solver.assign_external(a, v)
                    };
                    // Released earlier: no longer external.
                    if r.is_ok() {
                        so_far.externals.push((a, v));
                    } else {
                        prop_assert_eq!(r, Err(SolveError::NotExternal(a)));
                    }
                }
                ExtChange::Statement(a, v) => {
                    let mut d = GroundProgram::new();
                    d.externals.push((a, v));
                    let was = solver.is_external(a);
                    solver.add_program(&d).unwrap();
                    if was {
                        so_far.externals.push((a, v));
                    }
                }
            }
        }
        so_far.num_atoms = so_far.num_atoms.max(delta.num_atoms);
        for r in delta.rules.iter() {
            so_far.rules.push_ref(r);
        }
        so_far.minimize.extend(delta.minimize.iter().cloned());
        so_far.cr_rules.extend(delta.cr_rules.iter().cloned());
        // An external statement on an atom completed earlier is ignored (clingo).
        for &(a, v) in &delta.externals {
            let open = match &s {
                None => true,
                Some(sv) => a > sv.program().num_atoms || sv.is_external(a),
            };
            if open {
                so_far.externals.push((a, v));
            }
        }
        match s.as_mut() {
            None => s = Some(Solver::new(&delta, cfg.clone())),
            Some(sv) => sv.add_program(&delta).unwrap(),
        }
        let sv = s.as_mut().expect("made above");
        // Models are marked optimal only when there is something to optimize.
        let opt_now = opt && !so_far.minimize.is_empty();
        let want = brute_sets(&so_far, opt_now);
        let r = sv.solve();
        prop_assert!(r.exhausted);
        prop_assert_eq!(
            solver_sets(&r, sv.program(), opt_now),
            want,
            "step {}",
            step
        );
        // Under assumptions (without optimization: optimal models under assumptions differ).
        if !opt {
            let a: Vec<i32> = assume
                .iter()
                .copied()
                .filter(|l| l.unsigned_abs() <= so_far.num_atoms)
                .collect();
            let r = sv.solve_with(&a);
            prop_assert!(r.exhausted);
            let holds = |m: &[u32], l: i32| m.contains(&l.unsigned_abs()) == (l > 0);
            let all = brute::answer_sets(
                &so_far,
                BruteConfig {
                    optimize: false,
                    cr_mode: CrMode::Cardinality,
                },
            );
            let mut w: Vec<(Vec<u32>, Vec<i64>)> = all
                .into_iter()
                .filter(|m| {
                    let mut full = m.atoms.clone();
                    full.extend(m.applied.iter().copied());
                    a.iter().all(|&l| holds(&full, l))
                })
                .map(|m| (m.atoms, Vec::new()))
                .collect();
            w.sort();
            w.dedup();
            let got = solver_sets(&r, sv.program(), false);
            // CR programs under assumptions: the minimal number of applied CR rules is taken
            // among the answer sets that satisfy the assumptions, which the filter above does
            // not model; compare plain programs only.
            if p.cr_rules.is_empty() {
                prop_assert_eq!(got, w, "step {} under {:?}", step, a);
            }
        }
    }
    // The whole program at once.
    let mut whole = Solver::new(&so_far, cfg);
    let r = whole.solve();
    let sv = s.as_mut().expect("at least one chunk");
    let r2 = sv.solve();
    let opt_now = opt && !so_far.minimize.is_empty();
    prop_assert_eq!(
        solver_sets(&r, &so_far, opt_now),
        solver_sets(&r2, sv.program(), opt_now)
    );
    let _ = p;
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(400), ..ProptestConfig::default() })]

    /// Programs with minimize statements in k chunks: the optimal answer sets and their costs
    /// match at every step.
    #[test]
    fn chunks_with_minimize_match_the_whole_program(
        p in program_strategy(false),
        k in 1usize..5,
        atom_chunk in prop::collection::vec(0usize..5, 1..12),
        picks in prop::collection::vec(0usize..5, 1..12),
        changes in prop::collection::vec((1u32..10, 0u8..4, any::<bool>()), 0..3),
        assume in prop::collection::vec(lit_strategy(10), 0..3),
    ) {
        let chunks = split(&p, k, &atom_chunk, &picks, &changes);
        run_chunks(&p, chunks.clone(), false, &assume)?;
        if !p.minimize.is_empty() {
            run_chunks(&p, chunks, true, &assume)?;
        }
    }

    /// Programs with CR rules in k chunks: the cardinality-minimal CR semantics counts the
    /// application atoms of every chunk.
    #[test]
    fn chunks_with_cr_rules_match_the_whole_program(
        p in program_strategy(true),
        k in 1usize..5,
        atom_chunk in prop::collection::vec(0usize..5, 1..12),
        picks in prop::collection::vec(0usize..5, 1..12),
        changes in prop::collection::vec((1u32..10, 0u8..4, any::<bool>()), 0..3),
    ) {
        let mut p = p;
        p.minimize.clear();
        let chunks = split(&p, k, &atom_chunk, &picks, &changes);
        run_chunks(&p, chunks, false, &[])?;
    }
}

/// `n` queens (atom `r * n + c + 1`), with one CR rule `q1 :+ .` and a minimize statement
/// over the first row when asked.
fn queens(n: u32, cr: bool, minimize: bool) -> GroundProgram {
    let mut p = GroundProgram::new();
    let at = |r: u32, c: u32| (r * n + c + 1) as i32;
    p.num_atoms = n * n;
    for r in 0..n {
        p.rules.push(Rule::choice(
            &(0..n).map(|c| at(r, c) as u32).collect::<Vec<_>>(),
            &[],
        ));
        p.rules.push(Rule::normal(
            &[],
            &(0..n).map(|c| -at(r, c)).collect::<Vec<_>>(),
        ));
    }
    for a in 1..=(n * n) as i32 {
        for b in a + 1..=(n * n) as i32 {
            let (r1, c1, r2, c2) = (
                (a - 1) / n as i32,
                (a - 1) % n as i32,
                (b - 1) / n as i32,
                (b - 1) % n as i32,
            );
            if r1 == r2 || c1 == c2 || r1 + c2 == r2 + c1 || r1 - c1 == r2 - c2 {
                p.rules.push(Rule::normal(&[], &[a, b]));
            }
        }
    }
    if cr {
        let appl = p.new_atom();
        p.rules.push(Rule::choice(&[appl], &[]));
        p.rules.push(Rule::normal(&[1], &[appl as i32]));
        p.cr_rules.push(CrRule {
            appl,
            label: "r".into(),
        });
    }
    if minimize {
        p.minimize.push(Minimize {
            priority: 0,
            lits: (0..n).map(|c| (at(0, c), c as i64)).collect(),
        });
    }
    p
}

/// Calls a solver 10,000 times with changing assumptions and checks that the engine's
/// variables, weight constraints, level-0 assignments and clauses stay bounded: each call's
/// guard and auxiliary variables are recycled, its weight constraints removed, and the learnt
/// clauses kept within the per-call limit.
fn stays_bounded(p: &GroundProgram, config: Config) {
    let mut s = Solver::new(p, config);
    let before = s.engine_size();
    let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut peak = before;
    for _ in 0..10_000 {
        let mut a = Vec::new();
        for _ in 0..2 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let atom = (x % 25) as i32 + 1;
            a.push(if x >> 40 & 1 == 0 { atom } else { -atom });
        }
        s.solve_with(&a);
        let now = s.engine_size();
        peak.vars = peak.vars.max(now.vars);
        peak.weights = peak.weights.max(now.weights);
        peak.level0 = peak.level0.max(now.level0);
        peak.clauses = peak.clauses.max(now.clauses);
        peak.learnts = peak.learnts.max(now.learnts);
    }
    // Variables: the program's, plus those retired and not yet freed (at most a quarter of
    // the variables plus 256 before a pass frees them), plus one call's own.
    assert!(
        peak.vars <= before.vars + 256 + before.vars / 2 + 64,
        "{before:?} -> {peak:?}"
    );
    assert!(peak.weights <= before.weights + 8, "{before:?} -> {peak:?}");
    assert!(
        peak.level0 <= before.level0 + 256 + before.vars / 2 + 64,
        "{before:?} -> {peak:?}"
    );
    // Clauses: the program's (level-0 simplification only removes some), learnt binary ones
    // (counted here) and the guarded ones of calls not yet swept.
    assert!(
        peak.clauses <= 2 * before.clauses + 2000,
        "{before:?} -> {peak:?}"
    );
    assert!(peak.learnts <= 2000, "{before:?} -> {peak:?}");
}

#[test]
fn many_calls_leave_nothing_behind() {
    let one = Config::default();
    stays_bounded(&queens(5, false, false), one.clone());
    stays_bounded(&queens(5, true, false), one.clone());
    stays_bounded(&queens(5, false, true), one.clone());
    stays_bounded(
        &queens(5, true, false),
        Config {
            cr_mode: CrMode::Subset,
            ..one.clone()
        },
    );
    stays_bounded(&queens(5, false, false), Config::all_models());
}
