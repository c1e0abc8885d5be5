//! Snapshots (insta) of the printer on reports built from solver results: Lucent's own
//! additions (applied CR rules), which clingo cannot produce, and `Report::new`.

use std::time::Duration;

use lucent::cli::report::{write_json, write_text, Context, Quiet, Report};
use lucent::solve::{EnumMode, Model, Outcome, SolveResult, Stats};

fn cr_result() -> SolveResult {
    // Two answer sets of a CR-Prolog program under `--cr=subset`: one applies r1, the other
    // r2(3) and r3; both optimal under a user minimize.
    let model = |number, symbols: &[&str], applied: &[&str]| Model {
        number,
        symbols: symbols.iter().map(|s| s.to_string()).collect(),
        costs: vec![2],
        cr_applied: applied.iter().map(|s| s.to_string()).collect(),
        optimal: true,
        ..Model::default()
    };
    SolveResult {
        models: vec![
            model(1, &["p", "ab(1)"], &["r1"]),
            model(2, &["q", "s(\"x y\")"], &["r2(3)", "r3"]),
        ],
        outcome: Outcome::Optimum,
        exhausted: true,
        optimum_proven: true,
        stop: None,
        stats: Stats {
            time: Duration::from_millis(12),
            ..Stats::default()
        },
    }
}

fn context() -> Context {
    Context {
        inputs: vec!["ra.lp".into()],
        has_minimize: true,
        optimizing: true,
        enum_mode: EnumMode::Auto,
        has_cr: true,
        shown_total: 5,
        facts: vec!["p".into()],
    }
}

fn report() -> Report {
    let mut r = Report::new(&cr_result(), context());
    r.solver = "lucent version X".into();
    r
}

#[test]
fn cr_text() {
    let mut out = Vec::new();
    write_text(&mut out, &report(), Quiet::default()).unwrap();
    insta::assert_snapshot!(String::from_utf8(out).unwrap());
}

#[test]
fn cr_json() {
    let mut out = Vec::new();
    write_json(&mut out, &report(), Quiet::default()).unwrap();
    let text = String::from_utf8(out).unwrap();
    let value: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(value["Call"][0]["Witnesses"][1]["Applied"][0], "r2(3)");
    insta::assert_snapshot!(text);
}

#[test]
fn without_cr_rules_nothing_is_added() {
    let mut context = context();
    context.has_cr = false;
    let r = Report::new(&cr_result(), context);
    let mut out = Vec::new();
    write_text(&mut out, &r, Quiet::default()).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(!text.contains("Applied"), "{text}");
    let mut out = Vec::new();
    write_json(&mut out, &r, Quiet::default()).unwrap();
    assert!(!String::from_utf8(out).unwrap().contains("Applied"));
    assert_eq!(r.exit_code(), 30);
    assert_eq!(r.number, 2);
}

#[test]
fn brave_consequences_from_a_result() {
    let mut result = cr_result();
    result.models.truncate(1);
    result.exhausted = false;
    result.outcome = Outcome::Satisfiable;
    let mut context = context();
    context.enum_mode = EnumMode::Brave;
    context.has_minimize = false;
    context.has_cr = false;
    let mut r = Report::new(&result, context);
    r.solver = "lucent version X".into();
    let mut out = Vec::new();
    write_text(&mut out, &r, Quiet::default()).unwrap();
    insta::assert_snapshot!(String::from_utf8(out).unwrap());
}

#[test]
fn context_from_program_and_config() {
    use lucent::ground::program::{CrRule, GroundProgram, Minimize, Output};
    use lucent::solve::{Config, OptMode};
    let mut p = GroundProgram::new();
    let a = p.new_atom();
    p.outputs = vec![
        Output::new("a".into(), vec![a as i32]),
        Output::new("a".into(), vec![]),
        Output::new("b".into(), vec![]),
    ];
    p.minimize.push(Minimize {
        priority: 0,
        lits: vec![(a as i32, 1)],
    });
    p.cr_rules.push(CrRule {
        appl: a,
        label: "r".into(),
    });
    let c = Context::for_program(&p, &Config::default(), vec!["x.lp".into()]);
    assert!(c.has_minimize && c.optimizing && c.has_cr);
    assert_eq!(c.shown_total, 2);
    assert_eq!(c.facts, vec!["a".to_string(), "b".to_string()]);
    let config = Config {
        opt_mode: OptMode::Enum(vec![]),
        ..Config::default()
    };
    let c = Context::for_program(&p, &config, vec![]);
    assert!(c.has_minimize && !c.optimizing);
    let config = Config {
        opt_mode: OptMode::Ignore,
        ..Config::default()
    };
    assert!(!Context::for_program(&p, &config, vec![]).has_minimize);
}

#[test]
fn cautious_counts_shown_facts_as_decided() {
    // As clingo -n1 --enum-mode=cautious on `a :- not b. b :- not a. c.`: after the first model
    // {b, c}, c (a fact) is decided and b is open: `Consequences: [1;2]`.
    let mut result = cr_result();
    result.models = vec![Model {
        number: 1,
        symbols: vec!["b".into(), "c".into()],
        ..Model::default()
    }];
    result.exhausted = false;
    result.outcome = Outcome::Satisfiable;
    let context = Context {
        enum_mode: EnumMode::Cautious,
        shown_total: 3,
        facts: vec!["c".into()],
        ..Context::default()
    };
    let r = Report::new(&result, context);
    let mut out = Vec::new();
    write_text(&mut out, &r, Quiet::default()).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(text.contains("\nb c\nConsequences: [1;2]\n"), "{text}");
    assert!(text.contains("\nConsequences : 1+\n"), "{text}");
}

#[test]
fn statistics_when_asked_for() {
    let mut r = report();
    r.stats = Some(Stats {
        choices: 3,
        conflicts: 1,
        restarts: 0,
        vars: 9,
        clauses: 12,
        ..Stats::default()
    });
    let mut out = Vec::new();
    write_text(&mut out, &r, Quiet::default()).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains(
            "CPU Time     : 0.012s\n\nChoices      : 3       \nConflicts    : 1       \n"
        ),
        "{text}"
    );
    let mut out = Vec::new();
    write_json(&mut out, &r, Quiet::default()).unwrap();
    let value: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(value["Stats"]["Core"]["Choices"], 3);
    assert_eq!(value["Stats"]["Lucent"]["Constraints"], 12);
}

#[test]
fn first_model_and_unsat_times_come_from_the_result() {
    // The solver's times (given here, not measured) reach clasp's `Time` line and the JSON
    // `Time` object: 1st Model is the time to the first model, Unsat the time after the last.
    let mut r = cr_result();
    r.stats.time = Duration::from_millis(963);
    r.stats.first_model = Some(Duration::from_millis(550));
    r.stats.unsat = Duration::from_millis(410);
    let rep = Report::new(&r, context());
    let mut out = Vec::new();
    write_text(&mut out, &rep, Quiet::default()).unwrap();
    let text = String::from_utf8(out).unwrap();
    assert!(
        text.contains("Time         : 0.963s (Solving: 0.96s 1st Model: 0.55s Unsat: 0.41s)"),
        "{text}"
    );
    let mut out = Vec::new();
    write_json(&mut out, &rep, Quiet::default()).unwrap();
    let value: serde_json::Value = serde_json::from_slice(&out).unwrap();
    assert_eq!(value["Time"]["Model"], 0.55);
    assert_eq!(value["Time"]["Unsat"], 0.41);
}
