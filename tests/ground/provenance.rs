//! Provenance of the grounder (`GroundConfig::provenance`): every ground rule's origins
//! (statement and bindings, or the statement it is an auxiliary of), the body literals that
//! grounding decided, the atom table and the removed rule instances of false atoms. Snapshots
//! of `--text --provenance` on small programs written for these tests, and invariants checked
//! over the grounder corpus (`tests/data/ground`).

use std::path::Path;

use lucent::base::SourceMap;
use lucent::ground::program::{
    AtomStatus, AuxKind, DeadReason, GroundProgram, Provenance, RuleOrigin,
};
use lucent::ground::{text, GroundConfig, Grounding};

use crate::support::ground as ground_support;

fn run(name: &str, src: &str, provenance: bool) -> (Grounding, SourceMap) {
    let config = GroundConfig {
        provenance,
        ..GroundConfig::default()
    };
    ground_support::ground_text(name, src, &config)
}

/// The `--text --provenance` form of `src`.
fn text_of(src: &str) -> String {
    let (g, sources) = run("-", src, true);
    check_invariants("-", &g);
    text::write_text(&g, Some(&sources))
}

/// What the provenance promises, checked on one grounding.
fn check_invariants(name: &str, g: &Grounding) {
    let p = &g.program.provenance;
    let nstmts = g.statement_spans.len() as u32;
    assert_eq!(
        p.num_rules(),
        g.program.rules.len(),
        "{name}: one entry per rule"
    );
    for i in 0..g.program.rules.len() {
        let os = p.origins(i);
        assert!(!os.is_empty(), "{name}: rule {i} has no origin");
        for o in os {
            if let Some(s) = o.rule.stmt() {
                assert!(s < nstmts, "{name}: rule {i}: statement {s} out of range");
            }
            for l in &o.removed {
                let r = p.atom(l.atom).expect("removed atom is in the table");
                let want = if l.positive {
                    AtomStatus::Fact
                } else {
                    AtomStatus::False
                };
                assert_eq!(r.status, want, "{name}: rule {i}: removed {l:?}");
            }
        }
    }
    for (i, r) in p.atoms.iter().enumerate() {
        let a = i as u32 + 1;
        if r.aspif != 0 {
            assert_eq!(p.of_aspif(r.aspif), Some(a), "{name}: aspif lookup");
        }
        if let Some(s) = r.sym {
            assert_eq!(p.of_symbol(s), Some(a), "{name}: symbol lookup");
        }
        // An atom of the program that grounding left to the solver has an aspif number.
        if r.status == AtomStatus::Possible {
            assert_ne!(r.aspif, 0, "{name}: possible atom {a} without a number");
        }
    }
    for d in &p.dead {
        let satisfied = match d.why {
            DeadReason::HeadFact(f) => {
                d.head.contains(&f) && p.atom(f).is_some_and(|r| r.status == AtomStatus::Fact)
            }
            _ => false,
        };
        assert!(
            satisfied
                || d.head
                    .iter()
                    .any(|&h| p.atom(h).is_some_and(|r| r.status == AtomStatus::False)),
            "{name}: dead rule {d:?} heads no false atom and no fact satisfies it"
        );
        assert!(!d.origins.is_empty(), "{name}: dead rule without origin");
    }
}

/// The program without its provenance.
/// `p` without its provenance, the outputs' keys replaced by their positions: provenance
/// makes grounder atoms of its own, so the atom numbers in the keys (`Output::order`) differ;
/// the order they give must not.
fn without_provenance(p: &GroundProgram) -> GroundProgram {
    let mut p = GroundProgram {
        provenance: Provenance::new(),
        ..p.clone()
    };
    for (i, o) in p.outputs.iter_mut().enumerate() {
        o.order = i as u64;
    }
    p
}

#[test]
fn provenance_keeps_the_ground_program_and_its_invariants_over_the_corpus() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/ground");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("tests/data/ground")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "lp"))
        .collect();
    files.sort();
    assert!(files.len() > 10);
    for f in files {
        let name = f.display().to_string();
        let src = std::fs::read_to_string(&f).expect("program");
        let (off, _) = run(&name, &src, false);
        let (on, _) = run(&name, &src, true);
        assert!(
            off.program.provenance.is_empty(),
            "{name}: off records nothing"
        );
        assert_eq!(
            without_provenance(&on.program),
            without_provenance(&off.program),
            "{name}: provenance changed the ground program"
        );
        assert_eq!(on.atom_names(), off.atom_names(), "{name}");
        check_invariants(&name, &on);
    }
}

#[test]
fn duplicate_instances_keep_all_their_origins_and_removed_facts() {
    let (g, _) = run("-", "q(1..3).\np :- q(X).\n", true);
    check_invariants("-", &g);
    let p = &g.program.provenance;
    let i = g
        .program
        .rules
        .iter()
        .position(|r| {
            r.head.len() == 1 && r.body.is_empty_normal() && {
                g.atom_name(r.head[0]).as_deref() == Some("p")
            }
        })
        .expect("p.");
    let os = p.origins(i);
    let texts: Vec<String> = os
        .iter()
        .map(|o| {
            let removed: Vec<String> = o.removed.iter().map(|l| g.removed_text(l)).collect();
            format!(
                "{} {}",
                g.bindings_text(o.rule.bindings()),
                removed.join(",")
            )
        })
        .collect();
    assert_eq!(texts, ["X=1 q(1)", "X=2 q(2)", "X=3 q(3)"]);
    for o in os {
        assert!(matches!(o.rule, RuleOrigin::Statement { stmt: 1, .. }));
    }
}

#[test]
fn aggregate_and_minimize_auxiliaries_name_their_statement() {
    let src = "{ c(1..3) }.\nt(S) :- S = #sum { X : c(X) }, S > 4.\n#minimize { X,Y : c(X), c(Y), X < Y }.\n";
    let (g, _) = run("-", src, true);
    check_invariants("-", &g);
    let p = &g.program.provenance;
    let mut kinds = Vec::new();
    for i in 0..g.program.rules.len() {
        for o in p.origins(i) {
            if let RuleOrigin::Auxiliary { of_stmt, kind, .. } = o.rule {
                kinds.push((of_stmt, kind));
            }
        }
    }
    assert!(kinds.contains(&(1, AuxKind::Aggregate)), "{kinds:?}");
    assert!(kinds.contains(&(2, AuxKind::Minimize)), "{kinds:?}");
    assert!(
        kinds
            .iter()
            .all(|&(s, k)| (s, k) == (1, AuxKind::Aggregate) || (s, k) == (2, AuxKind::Minimize)),
        "{kinds:?}"
    );
}

#[test]
fn false_atoms_are_named_with_the_instances_that_could_derive_them() {
    let (g, _) = run(
        "-",
        "n(1..2).\np(X) :- n(X), not q(X).\nq(1).\nr(X) :- p(X).\ns | t :- p(2).\ns.\n",
        true,
    );
    check_invariants("-", &g);
    let p = &g.program.provenance;
    let status = |t: &str| p.atom(g.find_atom(t).expect(t)).map(|r| r.status);
    assert_eq!(status("q(1)"), Some(AtomStatus::Fact));
    assert_eq!(status("q(2)"), Some(AtomStatus::False));
    assert_eq!(status("t"), Some(AtomStatus::False));
    assert_eq!(status("p(2)"), Some(AtomStatus::Fact));
    // q(2) has no rule; t's only instance was satisfied by the fact s.
    assert_eq!(p.dead_rules_for(g.find_atom("q(2)").unwrap()).count(), 0);
    let t: Vec<_> = p.dead_rules_for(g.find_atom("t").unwrap()).collect();
    assert_eq!(t.len(), 1);
    assert_eq!(g.atom_text(t[0].head[0]), "s");
    // p(1)'s instance failed during instantiation at `not q(1)`, q(1) a fact.
    let p1: Vec<_> = p.dead_rules_for(g.find_atom("p(1)").unwrap()).collect();
    assert_eq!(p1.len(), 1);
    assert_eq!(
        p1[0].why,
        DeadReason::Literal {
            positive: false,
            atom: g.find_atom("q(1)").unwrap()
        }
    );
    assert_eq!(g.bindings_text(p1[0].origins[0].rule.bindings()), "X=1");
}

#[test]
fn text_aggregates() {
    insta::assert_snapshot!(text_of(
        "{ c(1..3) }.\ntotal(S) :- S = #sum { X : c(X) }, S >= 5.\nbig :- #count { X : c(X) } >= 2.\n"
    ));
}

#[test]
fn text_minimize() {
    insta::assert_snapshot!(text_of(
        "d(1..2).\n{ x(X) : d(X) }.\n#minimize { 1,X : x(X) ; 1,X : d(X), not x(X) }.\n#minimize { 2@2 : d(1) }.\n"
    ));
}

#[test]
fn text_duplicates() {
    insta::assert_snapshot!(text_of(
        "q(1..2).\np :- q(X).\np.\n{ a }.\nb :- a, q(X).\nc(1;1).\n"
    ));
}

#[test]
fn text_facts_in_bodies() {
    insta::assert_snapshot!(text_of(
        "edge(1,2). edge(2,3).\n{ on(1..3) }.\nreach(Y) :- edge(X,Y), on(X), not off(Y).\noff(3) :- reach(2), edge(2,3).\n"
    ));
}

#[test]
fn text_false_atoms() {
    insta::assert_snapshot!(text_of(
        "n(1..3).\np(X) :- n(X), not q(X).\nq(2).\nr(X) :- n(X), not p(X).\n{ s }.\nu :- s, r(2).\nv | w :- n(1).\nv.\n:- u.\n"
    ));
}

#[test]
fn text_why_not() {
    insta::assert_snapshot!(text_of(
        "n(1..3).\np(X) :- n(X), not q(X).\nq(2).\ns(1).\nt(X) :- n(X), not not s(X).\nr(X) :- n(X), s(X).\nu(X) :- p(X), v(X).\nv(3).\n"
    ));
}

#[test]
fn text_rules_that_simplification_turns_into_one_fact() {
    // q becomes a fact after the disjunctions are grounded: they die, x and x2 are false, and
    // both rules for p become `p.`, one rule with two origins.
    insta::assert_snapshot!(text_of(
        "r.\nx | q :- r.\nx2 | q :- r.\nq :- r.\np :- not x.\np :- not x2.\n"
    ));
}

#[test]
fn text_choice_rules() {
    insta::assert_snapshot!(text_of(
        "item(a;b;c).\n1 { pick(X) : item(X) } 2.\n{ extra(X) : item(X), X != b } :- pick(a).\n"
    ));
}

#[test]
fn text_cr_rules() {
    insta::assert_snapshot!(text_of(
        "block(b1;b2).\non_table(B) :- block(B), not -on_table(B).\nr(B): -on_table(B) :+ block(B).\nh :+ on_table(b1).\n:- on_table(b2).\n"
    ));
}

#[test]
fn text_conditions_and_negations() {
    insta::assert_snapshot!(text_of(
        "d(1..2).\n{ x(1..2) }.\nall :- x(X) : d(X).\nsome :- not not x(1).\nnone :- not x(_).\ne(X) : x(X) :- all.\n-x(2) :- some.\n"
    ));
}

/// Every rule instance with `head` among its heads, kept or removed, as `statement bindings`
/// (the kept rules' origins, then the removed instances').
fn instances_of(g: &Grounding, head: &str) -> Vec<String> {
    let p = &g.program.provenance;
    let atom = g.find_atom(head).expect(head);
    let aspif = p.atom(atom).expect("in the table").aspif;
    let show = |o: &lucent::ground::program::Origin| {
        let stmt = match o.rule {
            RuleOrigin::Statement { stmt, .. } => stmt.to_string(),
            RuleOrigin::Auxiliary { of_stmt, kind, .. } => format!("{} of {of_stmt}", kind.name()),
            RuleOrigin::Complement => "complement".into(),
        };
        format!("{stmt} {}", g.bindings_text(o.rule.bindings()))
            .trim_end()
            .to_string()
    };
    let mut out: Vec<String> = Vec::new();
    for (i, r) in g.program.rules.iter().enumerate() {
        if aspif != 0 && r.head.contains(&aspif) {
            out.extend(p.origins(i).iter().map(show));
        }
    }
    for d in &p.dead {
        if d.head.contains(&atom) {
            out.extend(d.origins.iter().map(|o| format!("{} (removed)", show(o))));
        }
    }
    out
}

#[test]
fn rule_instances_of_an_atom_that_is_a_fact_keep_their_origins() {
    // `a :- c.` and `p(X) :- q(X).` cannot add anything to facts: the grounder drops them (as
    // gringo does), but their instances keep their statement and bindings as removed rules
    // satisfied by the fact (the explainer may cite them). `r :- s.` is grounded before `r`
    // is known to be a fact (simplification removes it), `u` after.
    let src = "a.\na :- c.\n{c}.\np(1..2).\np(X) :- q(X).\n{q(1..3)}.\n\
               r :- s.\n{s}.\nr :- w.\nw :- not x.\n{u}.\nu :- r.\n";
    let (g, _) = run("-", src, true);
    check_invariants("-", &g);
    assert_eq!(instances_of(&g, "a"), ["0", "1 (removed)"]);
    assert_eq!(instances_of(&g, "p(1)"), ["3", "4 X=1 (removed)"]);
    assert_eq!(instances_of(&g, "p(2)"), ["3", "4 X=2 (removed)"]);
    assert_eq!(instances_of(&g, "p(3)"), ["4 X=3"]);
    assert_eq!(instances_of(&g, "r"), ["8", "6 (removed)"]);
    assert_eq!(instances_of(&g, "u"), ["11", "10 (removed)"]);
    let p = &g.program.provenance;
    for d in p
        .dead
        .iter()
        .filter(|d| matches!(d.why, DeadReason::HeadFact(_)))
    {
        let DeadReason::HeadFact(f) = d.why else {
            unreachable!()
        };
        assert!(d.head.contains(&f));
        assert_eq!(p.atom(f).map(|r| r.status), Some(AtomStatus::Fact));
    }
}
