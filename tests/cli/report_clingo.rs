//! The printer against clingo 5.4.1's output, recorded from `clingo <args> <file>` on the
//! programs quoted beside each case. Recorded text is kept verbatim except the first line
//! (`clingo version 5.4.1` becomes `lucent version X`) and the times, set to zero (statistics
//! are never compared). Reports are built by hand with the models clingo printed.

use lucent::cli::report::{
    exit_code, write_json, write_text, Consequences, Quiet, Report, ReportModel, Times,
};
use lucent::solve::{EnumMode, Outcome, StopReason};

const R1: &str = "a :- not b. b :- not a. c.";
const R3: &str = "{a;b;c}. :- not a, not b. #minimize{1,a:a; 1,b:b; 2,c:c}. #minimize{1@2,x:a}.";
const R4: &str = "{p(1..6)}. #minimize { 7-X,X : p(X) }. :- #count{X:p(X)} < 2.";

fn model(number: usize, symbols: &[&str], costs: &[i64]) -> ReportModel {
    ReportModel {
        number,
        symbols: symbols.iter().map(|s| s.to_string()).collect(),
        costs: costs.to_vec(),
        ..ReportModel::default()
    }
}

fn report(file: &str, models: Vec<ReportModel>, outcome: Outcome, exhausted: bool) -> Report {
    Report {
        solver: "lucent version X".into(),
        inputs: vec![file.into()],
        number: models.len(),
        models,
        outcome,
        exhausted,
        has_minimize: false,
        optimizing: false,
        enum_mode: EnumMode::Auto,
        stop: None,
        has_cr: false,
        calls: 1,
        times: Times::default(),
        stats: None,
    }
}

fn optimizing(mut r: Report) -> Report {
    r.has_minimize = true;
    r.optimizing = true;
    r
}

fn text(r: &Report, quiet: Quiet) -> String {
    let mut out = Vec::new();
    write_text(&mut out, r, quiet).unwrap();
    String::from_utf8(out).unwrap()
}

fn json(r: &Report, quiet: Quiet) -> String {
    let mut out = Vec::new();
    write_json(&mut out, r, quiet).unwrap();
    let s = String::from_utf8(out).unwrap();
    serde_json::from_str::<serde_json::Value>(&s).expect("the JSON output parses");
    s
}

fn q(models: u8, optimize: u8) -> Quiet {
    Quiet {
        models,
        optimize,
        calls: 0,
    }
}

const SUMMARY_TAIL: &str = "Calls        : 1
Time         : 0.000s (Solving: 0.00s 1st Model: 0.00s Unsat: 0.00s)
CPU Time     : 0.000s
";

#[test]
fn first_model_of_several() {
    // clingo r1.lp   (R1)
    let r = report(
        "r1.lp",
        vec![model(1, &["c", "b"], &[])],
        Outcome::Satisfiable,
        false,
    );
    let expected = "lucent version X\nReading from r1.lp\nSolving...\nAnswer: 1\nc b\nSATISFIABLE\n\nModels       : 1+\n";
    assert_eq!(
        text(&r, Quiet::default()),
        format!("{expected}{SUMMARY_TAIL}")
    );
    assert_eq!(r.exit_code(), 10);
    // clingo -q r1.lp
    let expected =
        "lucent version X\nReading from r1.lp\nSolving...\nSATISFIABLE\n\nModels       : 1+\n";
    assert_eq!(text(&r, q(2, 2)), format!("{expected}{SUMMARY_TAIL}"));
    let _ = R1;
}

#[test]
fn all_models() {
    // clingo -n0 r1.lp   (R1)
    let models = vec![model(1, &["c", "b"], &[]), model(2, &["c", "a"], &[])];
    let r = report("r1.lp", models, Outcome::Satisfiable, true);
    let expected = "lucent version X\nReading from r1.lp\nSolving...\nAnswer: 1\nc b\nAnswer: 2\nc a\nSATISFIABLE\n\nModels       : 2\n";
    assert_eq!(
        text(&r, Quiet::default()),
        format!("{expected}{SUMMARY_TAIL}")
    );
    assert_eq!(r.exit_code(), 30);
}

#[test]
fn unsatisfiable() {
    // clingo r2.lp   (a :- not a.)
    let r = report("r2.lp", vec![], Outcome::Unsatisfiable, true);
    let expected =
        "lucent version X\nReading from r2.lp\nSolving...\nUNSATISFIABLE\n\nModels       : 0\n";
    assert_eq!(
        text(&r, Quiet::default()),
        format!("{expected}{SUMMARY_TAIL}")
    );
    assert_eq!(r.exit_code(), 20);
    // clingo --outf=2 r2.lp
    let expected = r#"{
  "Solver": "lucent version X",
  "Input": [
    "r2.lp"
  ],
  "Call": [
    {

    }
  ],
  "Result": "UNSATISFIABLE",
  "Models": {
    "Number": 0,
    "More": "no"
  },
  "Calls": 1,
  "Time": {
    "Total": 0.000,
    "Solve": 0.000,
    "Model": 0.000,
    "Unsat": 0.000,
    "CPU": 0.000
  }
}
"#;
    assert_eq!(json(&r, Quiet::default()), expected);
}

#[test]
fn optimization_with_improving_models() {
    // clingo r4.lp   (R4), and with -q1 (= -q1,1), -q1,0, -q0,1, -q0,2, -q1,2, -q2,0
    let models = vec![
        model(1, &["p(3)", "p(6)"], &[5]),
        model(2, &["p(4)", "p(6)"], &[4]),
        model(3, &["p(5)", "p(6)"], &[3]),
    ];
    let r = optimizing(report("r4.lp", models, Outcome::Optimum, true));
    let head = "lucent version X\nReading from r4.lp\nSolving...\n";
    let tail = format!(
        "OPTIMUM FOUND\n\nModels       : 3\n  Optimum    : yes\nOptimization : 3\n{SUMMARY_TAIL}"
    );
    let cases = [
        (q(0, 0), "Answer: 1\np(3) p(6)\nOptimization: 5\nAnswer: 2\np(4) p(6)\nOptimization: 4\nAnswer: 3\np(5) p(6)\nOptimization: 3\n"),
        (q(1, 1), "Answer: 3\np(5) p(6)\nOptimization: 3\n"),
        (q(1, 0), "Optimization: 5\nOptimization: 4\nOptimization: 3\nAnswer: 3\np(5) p(6)\n"),
        (q(0, 1), "Answer: 1\np(3) p(6)\nAnswer: 2\np(4) p(6)\nAnswer: 3\np(5) p(6)\nOptimization: 3\n"),
        (q(0, 2), "Answer: 1\np(3) p(6)\nAnswer: 2\np(4) p(6)\nAnswer: 3\np(5) p(6)\n"),
        (q(1, 2), "Answer: 3\np(5) p(6)\n"),
        (q(2, 0), "Optimization: 5\nOptimization: 4\nOptimization: 3\n"),
    ];
    for (quiet, body) in cases {
        assert_eq!(text(&r, quiet), format!("{head}{body}{tail}"), "{quiet:?}");
    }
    assert_eq!(r.exit_code(), 30);
    let _ = R4;
}

#[test]
fn optimization_json() {
    // clingo --outf=2 r3.lp   (R3)
    let r = optimizing(report(
        "r3.lp",
        vec![model(1, &["b"], &[0, 1])],
        Outcome::Optimum,
        true,
    ));
    let expected = r#"{
  "Solver": "lucent version X",
  "Input": [
    "r3.lp"
  ],
  "Call": [
    {
      "Witnesses": [
        {
          "Value": [
            "b"
          ],
          "Costs": [
            0, 1
          ]
        }
      ]
    }
  ],
  "Result": "OPTIMUM FOUND",
  "Models": {
    "Number": 1,
    "More": "no",
    "Optimum": "yes",
    "Optimal": 1,
    "Costs": [
      0, 1
    ]
  },
  "Calls": 1,
  "Time": {
    "Total": 0.000,
    "Solve": 0.000,
    "Model": 0.000,
    "Unsat": 0.000,
    "CPU": 0.000
  }
}
"#;
    assert_eq!(json(&r, Quiet::default()), expected);
    // clingo r3.lp (text)
    let expected = "lucent version X\nReading from r3.lp\nSolving...\nAnswer: 1\nb\nOptimization: 0 1\nOPTIMUM FOUND\n\nModels       : 1\n  Optimum    : yes\nOptimization : 0 1\n";
    assert_eq!(
        text(&r, Quiet::default()),
        format!("{expected}{SUMMARY_TAIL}")
    );
    let _ = R3;
}

#[test]
fn time_limit_during_optimization() {
    // clingo --time-limit=1 -q hard.lp   (a grid maximization that does not finish in 1s;
    // clingo printed 51 models, the last with cost -50; exit code 11)
    let models = (1..=51)
        .map(|i| model(i, &["p(1,1)"], &[1 - i as i64]))
        .collect();
    let mut r = optimizing(report("hard.lp", models, Outcome::Satisfiable, false));
    r.stop = Some(StopReason::TimeLimit);
    let expected = "lucent version X\nReading from hard.lp\nSolving...\nSATISFIABLE\n\nTIME LIMIT   : 1\nModels       : 51+\n  Optimum    : unknown\nOptimization : -50\n";
    assert_eq!(text(&r, q(2, 2)), format!("{expected}{SUMMARY_TAIL}"));
    assert_eq!(r.exit_code(), 11);
    // clingo --outf=2 --time-limit=1 -q hard.lp
    let expected = r#"{
  "Solver": "lucent version X",
  "Input": [
    "hard.lp"
  ],
  "Call": [
    {

    }
  ],
  "Result": "SATISFIABLE",
  "TIME LIMIT": 1,
  "Models": {
    "Number": 51,
    "More": "yes",
    "Optimum": "unknown",
    "Optimal": 0,
    "Costs": [
      -50
    ]
  },
  "Calls": 1,
  "Time": {
    "Total": 0.000,
    "Solve": 0.000,
    "Model": 0.000,
    "Unsat": 0.000,
    "CPU": 0.000
  }
}
"#;
    assert_eq!(json(&r, q(2, 2)), expected);
}

#[test]
fn brave_and_cautious_consequences() {
    // clingo -n0 --enum-mode=brave r1.lp   (R1)
    let mut first = model(1, &["c", "b"], &[]);
    first.consequences = Some(Consequences {
        true_count: 2,
        open: 1,
    });
    let mut second = model(2, &["c", "b", "a"], &[]);
    second.consequences = Some(Consequences {
        true_count: 3,
        open: 0,
    });
    let mut r = report("r1.lp", vec![first, second], Outcome::Satisfiable, true);
    r.enum_mode = EnumMode::Brave;
    let expected = "lucent version X\nReading from r1.lp\nSolving...\nAnswer: 1\nc b\nConsequences: [2;3]\nAnswer: 2\nc b a\nConsequences: [3;3]\nSATISFIABLE\n\nModels       : 2\n  Brave      : yes\nConsequences : 3\n";
    assert_eq!(
        text(&r, Quiet::default()),
        format!("{expected}{SUMMARY_TAIL}")
    );
    // clingo --outf=2 -n0 --enum-mode=brave r1.lp
    let expected = r#"{
  "Solver": "lucent version X",
  "Input": [
    "r1.lp"
  ],
  "Call": [
    {
      "Witnesses": [
        {
          "Value": [
            "c", "b"
          ],
          "Consequences": {
            "True": 2,
            "Open": 1
          }
        },
        {
          "Value": [
            "c", "b", "a"
          ],
          "Consequences": {
            "True": 3,
            "Open": 0
          }
        }
      ]
    }
  ],
  "Result": "SATISFIABLE",
  "Models": {
    "Number": 2,
    "More": "no",
    "Brave": "yes",
    "Consequences": {
      "True": 3,
      "Open": 0
    }
  },
  "Calls": 1,
  "Time": {
    "Total": 0.000,
    "Solve": 0.000,
    "Model": 0.000,
    "Unsat": 0.000,
    "CPU": 0.000
  }
}
"#;
    assert_eq!(json(&r, Quiet::default()), expected);
    // clingo -n1 --enum-mode=cautious r1.lp
    let mut only = model(1, &["c", "b"], &[]);
    only.consequences = Some(Consequences {
        true_count: 1,
        open: 1,
    });
    let mut r = report("r1.lp", vec![only], Outcome::Satisfiable, false);
    r.enum_mode = EnumMode::Cautious;
    let expected = "lucent version X\nReading from r1.lp\nSolving...\nAnswer: 1\nc b\nConsequences: [1;2]\nSATISFIABLE\n\nModels       : 1+\n  Cautious   : unknown\nConsequences : 1+\n";
    assert_eq!(
        text(&r, Quiet::default()),
        format!("{expected}{SUMMARY_TAIL}")
    );
}

#[test]
fn empty_model_stdin_and_several_inputs() {
    // echo '{a}. #show.' | clingo    and    clingo --outf=2 r7.lp (the same program)
    let mut r = report("-", vec![model(1, &[], &[])], Outcome::Satisfiable, false);
    r.inputs.clear();
    let expected = "lucent version X\nReading from stdin\nSolving...\nAnswer: 1\n\nSATISFIABLE\n\nModels       : 1+\n";
    assert_eq!(
        text(&r, Quiet::default()),
        format!("{expected}{SUMMARY_TAIL}")
    );
    let j = json(&r, Quiet::default());
    assert!(j.contains("  \"Input\": [\n    \"stdin\"\n  ],\n"), "{j}");
    assert!(
        j.contains("          \"Value\": [\n            \n          ]\n"),
        "{j}"
    );
    // clingo r1.lp r2.lp   and   clingo --outf=2 r1.lp r2.lp
    r.inputs = vec!["r1.lp".into(), "r2.lp".into()];
    assert!(text(&r, Quiet::default()).contains("\nReading from r1.lp ...\n"));
    assert!(json(&r, Quiet::default()).contains("  \"Input\": [\n    \"r1.lp\",\"r2.lp\"\n  ],\n"));
}

#[test]
fn symbols_are_escaped_in_json() {
    // clingo 5.4.1 prints p("a\"b") as "p(\"a\"b\")" (the backslash is lost); Lucent escapes it.
    let r = report(
        "r5.lp",
        vec![model(1, &["p(\"a\\\"b\")", "p(-3)"], &[])],
        Outcome::Satisfiable,
        false,
    );
    let j = json(&r, Quiet::default());
    assert!(j.contains(r#""p(\"a\\\"b\")", "p(-3)""#), "{j}");
    let value: serde_json::Value = serde_json::from_str(&j).unwrap();
    assert_eq!(
        value["Call"][0]["Witnesses"][0]["Value"][0],
        "p(\"a\\\"b\")"
    );
}

#[test]
fn exit_codes() {
    assert_eq!(exit_code(Outcome::Satisfiable, false, None), 10);
    assert_eq!(exit_code(Outcome::Unsatisfiable, true, None), 20);
    assert_eq!(exit_code(Outcome::Satisfiable, true, None), 30);
    assert_eq!(exit_code(Outcome::Optimum, true, None), 30);
    assert_eq!(
        exit_code(Outcome::Unknown, false, Some(StopReason::TimeLimit)),
        1
    );
    assert_eq!(
        exit_code(Outcome::Satisfiable, false, Some(StopReason::Interrupted)),
        11
    );
}

#[test]
fn interrupted_before_any_model() {
    // clingo --time-limit=1 php.lp   (13 pigeons, 12 holes: no answer within a second; exit 1)
    let mut r = report("php.lp", vec![], Outcome::Unknown, false);
    r.stop = Some(StopReason::TimeLimit);
    let expected = "lucent version X\nReading from php.lp\nSolving...\nUNKNOWN\n\nTIME LIMIT   : 1\nModels       : 0+\n";
    assert_eq!(
        text(&r, Quiet::default()),
        format!("{expected}{SUMMARY_TAIL}")
    );
    assert_eq!(r.exit_code(), 1);
    // timeout -s INT 1 clingo --outf=2 php.lp
    r.stop = Some(StopReason::Interrupted);
    let j = json(&r, Quiet::default());
    let expected = "  \"Result\": \"UNKNOWN\",\n  \"INTERRUPTED\": 1,\n  \"Models\": {\n    \"Number\": 0,\n    \"More\": \"yes\"\n  },\n";
    assert!(j.contains(expected), "{j}");
    assert!(text(&r, Quiet::default()).contains("\n\nINTERRUPTED  : 1\nModels       : 0+\n"));
}
