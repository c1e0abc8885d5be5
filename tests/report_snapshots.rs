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
