//! External function calls `@f(...)` through a grounding context
//! (`Control::ground_with_context`, clingo's `Control.ground(parts, context)`).
//!
//! The expected answers are clingo 5.8's, recorded with `python3
//! tests/data/control/functions.py` (its context has the functions of [`Ctx`]; each line is
//! the first model's atoms, sorted). The call counts and the error cases are derived by hand
//! and explained beside them.

use lucent::control::{Context, Control, ControlConfig, Part, Symbol};

/// The test context: the functions of tests/data/control/functions.py, counting calls.
#[derive(Default)]
struct Ctx {
    calls: usize,
}

impl Context for Ctx {
    fn call(&mut self, name: &str, args: &[Symbol]) -> Result<Vec<Symbol>, String> {
        self.calls += 1;
        let num = |s: &Symbol| s.as_number().ok_or_else(|| format!("{s} is no number"));
        Ok(match (name, args) {
            ("inc", [x]) => vec![Symbol::number(num(x)? + 1)],
            ("both", [x]) => vec![Symbol::number(num(x)?), Symbol::number(num(x)? * 10)],
            ("up", [s]) => vec![Symbol::string(
                s.as_str().ok_or("a string expected")?.to_uppercase(),
            )],
            ("none", [_]) => Vec::new(),
            ("pair", [a, b]) => vec![Symbol::tuple(vec![b.clone(), a.clone()])],
            ("zero", []) => vec![Symbol::constant("z")],
            ("fail", _) => return Err("the host failed".into()),
            _ => return Err(format!("no function {name}/{}", args.len())),
        })
    }
}

/// The first model's atoms, sorted, of `program` grounded with a fresh [`Ctx`].
fn answer(program: &str) -> String {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], program).unwrap();
    ctl.ground_with_context(&[Part::base()], &mut Ctx::default())
        .unwrap_or_else(|e| panic!("{program}: {e}"));
    let mut atoms = ctl.solve_all(&Default::default()).models.remove(0).atoms;
    atoms.sort();
    atoms
        .iter()
        .map(|s| s.to_string())
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn calls_in_heads_and_bodies_match_clingo() {
    // (program, clingo 5.8's answer: python3 tests/data/control/functions.py)
    let cases = [
        (
            "p(1..3). q(@inc(X)) :- p(X).",
            "p(1) p(2) p(3) q(2) q(3) q(4)",
        ),
        // A list return gives one instance per symbol, in a head and in an assignment.
        (
            "p(1..2). q(@both(X)) :- p(X).",
            "p(1) p(2) q(1) q(2) q(10) q(20)",
        ),
        (
            "p(1..2). q(Y) :- p(X), Y = @both(X).",
            "p(1) p(2) q(1) q(2) q(10) q(20)",
        ),
        // String arguments and values.
        (
            r#"q(@up("ab")). r(@up(S)) :- S = ("x";"yz")."#,
            r#"q("AB") r("X") r("YZ")"#,
        ),
        // In a body atom and a comparison, once the arguments are bound.
        (
            "p(1). q(X) :- p(X), r(@inc(X)). r(2). s :- p(X), @inc(X) > 1.",
            "s p(1) q(1) r(2)",
        ),
        ("q(X) :- X = @inc(@inc(1)).", "q(3)"),
        // An empty list: no instance.
        ("q(@none(1)). r.", "r"),
        // Several arguments, tuples, calls without arguments.
        ("q(@pair(1, a)). r(@zero). r(@zero()).", "q((a,1)) r(z)"),
        // In a choice element and an aggregate element.
        (
            "p(1..2). { q(@inc(X)) : p(X) } = 2. s(N) :- N = #sum{ @inc(X) : p(X) }.",
            "p(1) p(2) q(2) q(3) s(5)",
        ),
        // `#const` values computed by calls at grounding, one constant from another.
        (
            "#const k = @inc(2). #const m = @inc(k). p(1..k). q(m). r(@zero).",
            "p(1) p(2) p(3) q(4) r(z)",
        ),
    ];
    for (program, expected) in cases {
        assert_eq!(answer(program), expected, "{program}");
    }
}

#[test]
fn calls_in_later_parts_continue_the_grounding() {
    // clingo 5.8: `step(0..2) => at(0) at(1) at(2) at(3)` (tests/data/control/functions.py).
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "at(0).").unwrap();
    ctl.add("step", &["t"], "at(@inc(t)) :- at(t).").unwrap();
    let mut ctx = Ctx::default();
    ctl.ground_with_context(&[Part::base()], &mut ctx).unwrap();
    for t in 0..3 {
        ctl.ground_with_context(&[Part::new("step", vec![Symbol::number(t)])], &mut ctx)
            .unwrap();
    }
    let atoms: Vec<String> = ctl.solve_all(&Default::default()).models[0]
        .atoms
        .iter()
        .map(|s| s.to_string())
        .collect();
    assert_eq!(atoms, ["at(0)", "at(1)", "at(2)", "at(3)"]);
    // One call per step: @inc(0), @inc(1), @inc(2).
    assert_eq!(ctx.calls, 3);
}

#[test]
fn each_distinct_call_is_made_once_per_grounding() {
    // By hand: the recursion derives n(0..5) over six semi-naive rounds, calling @inc(0)
    // .. @inc(5) (@inc(5) = 6 fails `Y < 6`); `m` asks for the same six calls again, which
    // the grounding's cache answers: six calls in all.
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add(
        "base",
        &[],
        "n(0). n(Y) :- n(X), Y = @inc(X), Y < 6. m(@inc(X)) :- n(X).",
    )
    .unwrap();
    let mut ctx = Ctx::default();
    ctl.ground_with_context(&[Part::base()], &mut ctx).unwrap();
    assert_eq!(ctx.calls, 6);
    let model = ctl.solve_all(&Default::default()).models.remove(0);
    assert!(model.contains(&Symbol::parse("n(5)").unwrap()));
    assert!(model.contains(&Symbol::parse("m(6)").unwrap()));
    assert!(!model.contains(&Symbol::parse("n(6)").unwrap()));
}

#[test]
fn closures_are_contexts() {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "q(@twice(21)).").unwrap();
    let mut twice = |_: &str, args: &[Symbol]| -> Result<Vec<Symbol>, String> {
        Ok(vec![Symbol::number(2 * args[0].as_number().unwrap())])
    };
    ctl.ground_with_context(&[Part::base()], &mut twice)
        .unwrap();
    let model = ctl.solve_all(&Default::default()).models.remove(0);
    assert!(model.contains(&Symbol::parse("q(42)").unwrap()));
}

#[test]
fn names_made_by_the_host_are_shown_as_made() {
    // clingo 5.8.3 answers `u(FOO) w(xfoo)` for this program with a context whose `up` returns
    // `Function(name.upper())` and `low` `Function("x" + name)`. The shown term `u(FOO)` does
    // not read back as a ground term (FOO reads as a variable): the model's shown symbols
    // dropped it, silently.
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "u(@up(foo)). w(@low(foo)).").unwrap();
    let mut ctx = |f: &str, args: &[Symbol]| -> Result<Vec<Symbol>, String> {
        let name = args[0].name().unwrap();
        Ok(vec![Symbol::constant(match f {
            "up" => name.to_uppercase(),
            _ => format!("x{name}"),
        })])
    };
    ctl.ground_with_context(&[Part::base()], &mut ctx).unwrap();
    let mut shown = Vec::new();
    ctl.solve(&Default::default(), |m| {
        shown = m.symbols().iter().map(|s| s.to_string()).collect();
        true
    });
    shown.sort();
    assert_eq!(shown, ["u(FOO)", "w(xfoo)"]);
}

/// The error of grounding `program` (with a context or without), rendered.
fn error(program: &str, with_context: bool) -> String {
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], program).unwrap();
    let result = if with_context {
        ctl.ground_with_context(&[Part::base()], &mut Ctx::default())
    } else {
        ctl.ground(&[Part::base()])
    };
    result.expect_err(program).to_string()
}

#[test]
fn unknown_functions_and_host_errors_are_errors_at_the_call() {
    // clingo raises the context's AttributeError for an unknown function and the function's
    // own exception for a failure; here both are diagnostics at the call's position.
    let e = error("p(1). q(@nope(X)) :- p(X).", true);
    assert!(
        e.starts_with(
            "<block>:1:9-17: error: error in external function @nope(1): no function nope/1"
        ),
        "{e}"
    );
    let e = error("q(@fail(\"a\")).", true);
    assert!(
        e.starts_with(
            "<block>:1:3-13: error: error in external function @fail(\"a\"): the host failed"
        ),
        "{e}"
    );
    // A value of the wrong type is the host's error too.
    let e = error("q(@inc(a)).", true);
    assert!(
        e.contains("error in external function @inc(a): a is no number"),
        "{e}"
    );
}

#[test]
fn without_a_context_calls_are_reported() {
    let e = error("p(1). q(@inc(X)) :- p(X).", false);
    assert!(
        e.starts_with("<block>:1:9-16: error: unsupported: external function call without a grounding context"),
        "{e}"
    );
    // The Control stays usable: the same part grounds once a context is given.
    let mut ctl = Control::new(ControlConfig::default());
    ctl.add("base", &[], "q(@inc(1)).").unwrap();
    assert!(ctl.ground(&[Part::base()]).is_err());
    ctl.ground_with_context(&[Part::base()], &mut Ctx::default())
        .unwrap();
    let model = ctl.solve_all(&Default::default()).models.remove(0);
    assert!(model.contains(&Symbol::parse("q(2)").unwrap()));
}

#[test]
fn script_blocks_stay_unsupported() {
    let mut ctl = Control::new(ControlConfig::default());
    let e = ctl
        .add("base", &[], "#script (python)\ndef f(x): return x\n#end.")
        .expect_err("#script")
        .to_string();
    assert!(
        e.contains("#script blocks are not supported by lucent"),
        "{e}"
    );
}
