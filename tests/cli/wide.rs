//! Wide atoms and long lines through the real binary: results only, never times (the side-by-side
//! timing is `scripts/bench_wide.sh`). Issue 17: `p(0,1,...,N).` was quadratic in the rewriter's
//! pool unfolding, a rule with 20,000 body literals overflowed the stack, and `--text` searched
//! the facts once per shown atom.

use crate::support::cli as cli_support;

use cli_support::lucent_binary as lucent;

/// The numbers `0..n` joined by `sep`.
fn numbers(n: usize, sep: &str) -> String {
    (0..n).map(|i| i.to_string()).collect::<Vec<_>>().join(sep)
}

#[test]
fn a_wide_atom_is_printed_whole() {
    let n = 50_000;
    let atom = format!("p({})", numbers(n, ","));
    let (code, out, err) = lucent(&[], &format!("{atom}.\nq :- {atom}.\n"));
    assert_eq!(code, 30, "{err}");
    let answer = out
        .lines()
        .skip_while(|l| *l != "Answer: 1")
        .nth(1)
        .unwrap();
    let mut atoms: Vec<&str> = answer.split(' ').collect();
    atoms.sort_unstable();
    assert_eq!(atoms, [atom.as_str(), "q"]);
    // Inside a function term, and in the text form of the ground program.
    let term = format!("p(f({}))", numbers(n, ","));
    let (code, out, _) = lucent(&["--text"], &format!("{term}."));
    assert_eq!(code, 0);
    assert_eq!(out, format!("{term}.\n"));
}

#[test]
fn a_wide_pool_and_a_long_line_of_facts_give_every_atom() {
    let n = 20_000;
    let (code, out, _) = lucent(&["--text"], &format!("q({}).", numbers(n, ";")));
    assert_eq!(code, 0);
    assert_eq!(out.lines().count(), n);
    assert!(out.starts_with("q(0).\nq(1).\n") && out.ends_with(&format!("q({}).\n", n - 1)));
    let facts: String = (0..n).map(|i| format!("r({i}). ")).collect();
    let (code, out, _) = lucent(&["--text"], &facts);
    assert_eq!(code, 0);
    assert_eq!(out.lines().count(), n);
}

#[test]
fn a_rule_with_thousands_of_body_literals_grounds() {
    let n = 5_000;
    let body: Vec<String> = (0..n).map(|i| format!("b({i})")).collect();
    let choices: String = (0..n).map(|i| format!("{{b({i})}}. ")).collect();
    let program = format!("a :- {}.\n{choices}\n:- not a.\n", body.join(","));
    // `a` needs every b(i): exactly one answer set, with all of them.
    let (code, out, err) = lucent(&["-n", "0"], &program);
    assert_eq!(code, 30, "{err}");
    let answer = out
        .lines()
        .skip_while(|l| *l != "Answer: 1")
        .nth(1)
        .unwrap();
    assert_eq!(answer.split(' ').count(), n + 1);
    assert!(out.contains("\nModels       : 1\n"));
}
