//! The order of a model's shown symbols: clingo's, by predicate domain in the order gringo
//! meets the predicates (the statements in program order, a rule's body last to first, then
//! its head, the facts last), then by atom, and the `#show` terms after the atoms, later
//! statements first (src/ground/rewrite/domains.rs).
//!
//! Each expected line was recorded from clingo 5.8.3 with
//! `python3 -c "import clingo,sys; c=clingo.Control(['--warn=none']); c.add('base',[],sys.argv[1]); c.ground([('base',[])]); c.solve(on_model=lambda m: print(m))" PROGRAM`.

use lucent::control::{Control, Part, SolveOptions};

fn shown(text: &str) -> Vec<String> {
    let mut ctl = Control::from_args(&["--warn=none"]).expect("valid arguments");
    ctl.add("base", &[], text).expect("the program parses");
    ctl.ground(&[Part::base()]).expect("the program grounds");
    let mut out = Vec::new();
    ctl.solve(&SolveOptions::default(), |m| {
        out.push(
            m.symbols()
                .iter()
                .map(|s| s.to_string())
                .collect::<Vec<_>>()
                .join(" "),
        );
        true
    });
    out
}

#[test]
fn facts_come_after_the_predicates_of_the_rules() {
    assert_eq!(
        shown("b(3). a(1). b(1). c(X) :- a(X). d(X) :- b(X), not c(X). a(2) :- b(3)."),
        ["a(1) a(2) c(1) c(2) b(3) b(1) d(3)"]
    );
}

#[test]
fn a_body_is_read_conditional_literals_first_then_last_to_first() {
    assert_eq!(
        shown("h :- a; b : c; e. a :- z. b :- z. c :- z. e :- z. z."),
        ["c b e a h z"]
    );
}

#[test]
fn show_terms_come_after_the_atoms_later_statements_first() {
    assert_eq!(
        shown(
            "p(3). o(b). o(a). q(X) :- o(X), p(3). #show q/1. #show o/1. \
             #show t(X) : p(X). #show \"k\"."
        ),
        ["o(b) o(a) q(b) q(a) \"k\" t(3)"]
    );
}

#[test]
fn facts_over_terms_that_are_no_values_come_after_the_other_facts() {
    assert_eq!(
        shown("a. b(1). c(\"s\", (2,x), -d). p(X) :- b(X)."),
        ["b(1) p(1) a c(\"s\",(2,x),-d)"]
    );
}

#[test]
fn facts_over_values_are_made_first() {
    assert_eq!(
        shown("o(-1). o(a). q(X) :- o(X)."),
        ["o(a) o(-1) q(a) q(-1)"]
    );
}
