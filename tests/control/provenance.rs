//! Multi-shot grounding through `control::Control`: the provenance of rules grounded in later
//! parts (origins in the Control's statement ids, bindings and removed literals in its tables)
//! and gringo's redefinition error for a later part that gives rules to an atom an earlier
//! solve call completed. Expected behaviour of clingo 5.8 recorded with its Python API
//! (`ctl.ground` after `ctl.solve`; the commands are written beside each case).

use lucent::control::{Control, ControlConfig, Part, SolveOptions, Symbol};
use lucent::ground::program::{AuxKind, RuleOrigin};

fn sym(s: &str) -> Symbol {
    Symbol::parse(s).unwrap()
}

fn step(t: i32) -> Part {
    Part::new("step", vec![Symbol::number(t)])
}

fn with_provenance() -> ControlConfig {
    let mut config = ControlConfig::default();
    config.ground.provenance = true;
    config
}

fn models(ctl: &mut Control) -> Vec<String> {
    ctl.solve_config_mut().models = 0;
    let mut out: Vec<String> = ctl
        .solve_all(&SolveOptions::default())
        .models
        .iter()
        .map(|m| {
            let mut s: Vec<String> = m.atoms.iter().map(|s| s.to_string()).collect();
            s.sort();
            s.join(" ")
        })
        .collect();
    out.sort();
    out
}

/// The text of statement `id`, its part, its bindings and removed literals, for every origin
/// of the rules whose head is `head`.
fn origins_of(ctl: &Control, head: &str) -> Vec<String> {
    let atom = ctl.lookup(&sym(head)).expect("the head atom exists");
    let program = ctl.program();
    let prov = ctl.provenance();
    let mut out = Vec::new();
    for (i, r) in program.rules.iter().enumerate() {
        if !r.head.contains(&atom) {
            continue;
        }
        for o in prov.origins(i) {
            let id = o.rule.stmt().expect("a statement");
            let st = ctl.statement(id).expect("the statement is kept");
            let text = lucent::syntax::printer::print(&lucent::syntax::ast::Program {
                dialect: Default::default(),
                statements: vec![st.statement.clone()],
            });
            let binds: Vec<String> = o
                .rule
                .bindings()
                .iter()
                .map(|&(n, v)| format!("{}={}", ctl.name_of_id(n), ctl.symbol_of_id(v)))
                .collect();
            let removed: Vec<String> = o
                .removed
                .iter()
                .map(|r| {
                    let rec = prov.atom(r.atom).expect("a grounder atom");
                    let s = ctl.symbol_of_id(rec.sym.expect("a named atom"));
                    if r.positive {
                        s.to_string()
                    } else {
                        format!("not {s}")
                    }
                })
                .collect();
            let kind = match &o.rule {
                RuleOrigin::Auxiliary { kind, .. } => format!("{} of ", kind.name()),
                _ => String::new(),
            };
            let args: Vec<String> = st.part.args.iter().map(|a| a.to_string()).collect();
            out.push(format!(
                "{kind}{} in {}({}) with [{}] removed [{}]",
                text.trim(),
                st.part.name,
                args.join(","),
                binds.join(","),
                removed.join(",")
            ));
        }
    }
    out.sort();
    out
}

const INC: &str = "#program base. q(0). s(1).
#program step(t). q(t) :- q(t-1). r(t,X) :- q(X), X < t, not s(X). c(t) :- #count{ X : q(X) } >= t+1.
";

#[test]
fn rules_of_later_groundings_keep_their_origins() {
    let mut ctl = Control::new(with_provenance());
    ctl.add_source("inc.lp", INC).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    assert_eq!(models(&mut ctl), ["q(0) s(1)"]);
    ctl.ground(&[step(1)]).unwrap();
    ctl.ground(&[step(2)]).unwrap();
    assert_eq!(
        models(&mut ctl),
        ["c(1) c(2) q(0) q(1) q(2) r(1,0) r(2,0) s(1)"]
    );
    assert_eq!(
        origins_of(&ctl, "r(2,0)"),
        ["r(t, X) :- q(X), X < t, not s(X). in step(2) with [X=0] removed [q(0),not s(0)]"]
    );
    assert_eq!(
        origins_of(&ctl, "q(0)"),
        ["q(0). in base() with [] removed []"]
    );
    // c(2) is a fact of step 2 (three q's): the count's statement is named.
    let c2 = origins_of(&ctl, "c(2)");
    assert!(
        c2.iter()
            .all(|o| o.contains("c(t) :- #count") && o.contains("in step(2)")),
        "{c2:?}"
    );
    // Auxiliaries of a later part name their statement too.
    let prov = ctl.provenance();
    let aggregates: Vec<u32> = (0..ctl.program().rules.len())
        .flat_map(|i| prov.origins(i).to_vec())
        .filter_map(|o| match o.rule {
            RuleOrigin::Auxiliary {
                of_stmt,
                kind: AuxKind::Aggregate,
                ..
            } => Some(of_stmt),
            _ => None,
        })
        .collect();
    for id in aggregates {
        let st = ctl.statement(id).unwrap();
        assert_eq!(st.part.name, "step");
    }
    // Every rule has an origin.
    for i in 0..ctl.program().rules.len() {
        assert!(!prov.origins(i).is_empty(), "rule {i} has no origin");
    }
    // The atom table covers the later groundings: q(2) is named and has its aspif atom.
    let q2 = ctl.lookup(&sym("q(2)")).unwrap();
    let g = prov.of_aspif(q2).expect("q(2) is in the atom table");
    assert_eq!(
        ctl.symbol_of_id(prov.atom(g).unwrap().sym.unwrap()),
        sym("q(2)")
    );
}

#[test]
fn statement_ids_of_repeated_parts_are_distinct() {
    // The same part statement grounded for two parameters: two statement ids, two parts.
    let mut ctl = Control::new(with_provenance());
    ctl.add_source("p.lp", "#program step(t). {a(t)}.").unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl.ground(&[step(1)]).unwrap();
    models(&mut ctl);
    ctl.ground(&[step(2)]).unwrap();
    models(&mut ctl);
    assert_eq!(
        origins_of(&ctl, "a(1)"),
        ["{ a(t) }. in step(1) with [] removed []"]
    );
    assert_eq!(
        origins_of(&ctl, "a(2)"),
        ["{ a(t) }. in step(2) with [] removed []"]
    );
}

// clingo 5.8, Python:
//   ctl = Control(["0"]); ctl.add("base", [], BASE); ctl.add("step", ["t"], STEP)
//   ctl.ground([("base", [])]); ctl.solve()
//   ctl.ground([("step", [Number(1)])])  -> RuntimeError: redefinition of atom <'a',1>
//   ctl.solve(on_model=print)             -> the models below (the redefining rules dropped)
#[test]
fn a_completed_atom_gets_no_rules_later() {
    for (base, step_text, error, after) in [
        (
            "{a}.",
            "a :- b. b.",
            "redefinition of atom <'a',1>",
            vec!["a b", "b"],
        ),
        ("{a}.", "a.", "redefinition of atom <'a',1>", vec!["", "a"]),
        (
            "{x;y;z}. {p(1,2)}.",
            "p(1,2) :- x. q :- y.",
            "redefinition of atom <'p(1,2)',1>",
            vec![
                "",
                "p(1,2)",
                "p(1,2) q y",
                "p(1,2) q y z",
                "p(1,2) x",
                "p(1,2) x q y",
                "p(1,2) x q y z",
                "p(1,2) x z",
                "p(1,2) z",
                "q y",
                "q y z",
                "x",
                "x q y",
                "x q y z",
                "x z",
                "z",
            ],
        ),
    ] {
        for provenance in [false, true] {
            let mut config = ControlConfig::default();
            config.ground.provenance = provenance;
            let mut ctl = Control::new(config);
            ctl.add_source("base.lp", base).unwrap();
            ctl.add_source("step.lp", &format!("#program step(t). {step_text}"))
                .unwrap();
            ctl.ground(&[Part::base()]).unwrap();
            models(&mut ctl);
            let e = ctl.ground(&[step(1)]).unwrap_err();
            assert!(e.diagnostics.has_errors());
            assert!(
                e.message.contains(&format!("error: {error}")),
                "{}",
                e.message
            );
            if provenance {
                // The error points at the statement that gave the rule.
                assert!(e.message.starts_with("step.lp:1:"), "{}", e.message);
            }
            let mut got = models(&mut ctl);
            let mut want: Vec<String> = after
                .iter()
                .map(|m| {
                    let mut v: Vec<&str> = m.split_whitespace().collect();
                    v.sort();
                    v.join(" ")
                })
                .collect();
            got.sort();
            want.sort();
            assert_eq!(got, want, "{base} then {step_text}");
        }
    }
}

// clingo 5.8 accepts these (same commands as above): a fact's atom gets rules later (they are
// satisfied), an external gets rules, and parts grounded before one solve call define an atom
// together.
#[test]
fn facts_externals_and_unsolved_steps_may_get_rules() {
    let run = |base: &str, step_text: &str, solve_between: bool| {
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add_source("b", base).unwrap();
        ctl.add_source("s", &format!("#program step(t). {step_text}"))
            .unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        if solve_between {
            models(&mut ctl);
        }
        ctl.ground(&[step(1)]).unwrap();
        models(&mut ctl)
    };
    assert_eq!(run("a.", "a :- b. b.", true), ["a b"]);
    assert_eq!(run("#external a. {c}.", "a :- c.", true), ["", "a c"]);
    assert_eq!(run("{a}.", "a :- b. b.", false), ["a b"]);
    assert_eq!(run("{a}.", "a.", false), ["a"]);
}

// clingo 5.8, Python: ctl.add("base", [], TEXT); ctl.ground([("base", [])]);
// optionally ctl.assign_external(e, VALUE); ctl.solve(assumptions=[lit...], on_model=...).
// An external's value is itself an assumption of every call: assuming true an external whose
// value is false (the default) is unsatisfiable, in clingo as here.
#[test]
fn assumptions_on_externals_as_clingo() {
    use lucent::control::TruthValue::{self, Free, True};
    type Case<'a> = (
        &'a str,
        Option<(&'a str, TruthValue)>,
        &'a [(&'a str, bool)],
        &'a [&'a str],
    );
    let cases: &[Case] = &[
        ("#external e. p :- e.", None, &[("e", true)], &[]),
        ("#external e. p :- e.", None, &[("e", false)], &[""]),
        (
            "#external e. p :- e.",
            Some(("e", Free)),
            &[("e", true)],
            &["e p"],
        ),
        (
            "#external e. p :- e.",
            Some(("e", True)),
            &[("e", true)],
            &["e p"],
        ),
        (
            "#external e. p :- e.",
            Some(("e", True)),
            &[("e", false)],
            &[],
        ),
        (
            "#external e. [free] p :- e.",
            None,
            &[("e", true)],
            &["e p"],
        ),
        ("#external e. [true] p :- e.", None, &[], &["e p"]),
        (
            "#external e. {q}. p :- e, q.",
            Some(("e", Free)),
            &[("e", true), ("p", true)],
            &["e p q"],
        ),
        (
            "#external e. {q}. p :- e, q.",
            Some(("e", Free)),
            &[("p", true)],
            &["e p q"],
        ),
        (
            "#external e(1..2). p :- e(1). :- e(2).",
            Some(("e(1)", Free)),
            &[("e(1)", true)],
            &["e(1) p"],
        ),
        (
            "#external e(1..2). p :- e(1). :- e(2).",
            Some(("e(2)", Free)),
            &[("e(2)", true)],
            &[],
        ),
        ("#external e. p :- not e.", None, &[("e", true)], &[]),
    ];
    for &(text, assign, assumptions, want) in cases {
        let mut ctl = Control::new(ControlConfig::default());
        ctl.add_source("t", text).unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        if let Some((atom, v)) = assign {
            ctl.assign_external(&sym(atom), v);
        }
        let options = SolveOptions {
            assumptions: assumptions.iter().map(|&(s, b)| (sym(s), b)).collect(),
        };
        let mut got: Vec<String> = ctl
            .solve_all(&options)
            .models
            .iter()
            .map(|m| {
                let mut s: Vec<String> = m.atoms.iter().map(|s| s.to_string()).collect();
                s.sort();
                s.join(" ")
            })
            .collect();
        got.sort();
        assert_eq!(got, want, "{text} {assign:?} {assumptions:?}");
    }
}

#[test]
fn a_one_shot_grounding_taken_out_prints_its_provenance_as_the_grounder_does() {
    // `lucent --text --provenance` goes through `Control::take_grounding`; the bindings and
    // removed literals of the text index the grounding's symbol table, which the control had
    // taken over (this panicked in `Interner::resolve` / `Symbols::get`).
    let src = "q(1..3).\np(1).\np(X) :- q(X), not r(X).\n{r(1..3)}.\n";
    let mut ctl = Control::new(with_provenance());
    ctl.add_source("t.lp", src).unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    let g = ctl.take_grounding();
    let got = lucent::ground::text::write_text(&g, Some(ctl.sources()));
    let mut sources = lucent::base::SourceMap::new();
    let id = sources.add("t.lp", src);
    let parsed = lucent::syntax::parse(id, src, lucent::syntax::ast::Dialect::Clingo);
    let config = lucent::ground::GroundConfig {
        provenance: true,
        ..Default::default()
    };
    let direct = lucent::ground::ground(&parsed.program, Some(&sources), &config);
    let want = lucent::ground::text::write_text(&direct, Some(&sources));
    assert!(want.contains("with X=2; grounding proved q(2)"), "{want}");
    assert_eq!(got, want);
}

#[test]
fn a_later_rule_for_an_old_fact_keeps_its_origin() {
    // p(1) is a fact of base; step(1)'s instance `p(1) :- q(1), c.` adds nothing to it (the
    // solver never sees it) but keeps its statement, part and bindings for the explainer.
    let mut ctl = Control::new(with_provenance());
    ctl.add_source(
        "f.lp",
        "#program base. p(1). q(1..2). {c}.\n#program step(t). p(X) :- q(X), c.\n",
    )
    .unwrap();
    ctl.ground(&[Part::base()]).unwrap();
    ctl.ground(&[step(1)]).unwrap();
    let prov = ctl.provenance();
    let g = prov
        .of_aspif(ctl.lookup(&sym("p(1)")).unwrap())
        .expect("p(1) is in the atom table");
    let removed: Vec<String> = prov
        .dead_rules_for(g)
        .flat_map(|d| d.origins.iter())
        .map(|o| {
            let st = ctl.statement(o.rule.stmt().unwrap()).unwrap();
            let binds: Vec<String> = o
                .rule
                .bindings()
                .iter()
                .map(|&(n, v)| format!("{}={}", ctl.name_of_id(n), ctl.symbol_of_id(v)))
                .collect();
            format!("{}{:?} {}", st.part.name, st.part.args, binds.join(","))
        })
        .collect();
    assert_eq!(removed, ["step[Number(1)] X=1"]);
    assert_eq!(
        origins_of(&ctl, "p(2)"),
        ["p(X) :- q(X), c. in step(1) with [X=2] removed [q(2)]"]
    );
}
