//! Theory atoms (`#theory`, `&name{...}`) grounded and solved without a propagator, against
//! clingo 5.8 run live (`python3 -m clingo`, and its Python API for the theory atoms): the same
//! answer sets (a theory atom that heads no rule is free, one with rules is an ordinary atom),
//! and the same ground theory atoms as clingo's `str(TheoryAtom)` prints them. The tests fail,
//! saying how to install it, when clingo 5.8 is missing.

use super::diff_random_py::{answer_sets, clingo_answer_sets};
use crate::support::cli::lucent_in_process;
use crate::support::ground::ground_text;
use lucent::ground::GroundConfig;
use std::process::Command;

/// Programs with theory atoms in bodies, heads and directives, guards, operators of several
/// priorities and associativities, element conditions over local variables and non-facts.
const PROGRAMS: &[&str] = &[
    // Body atoms (free), a head atom, a directive, a guard, a negated body atom.
    "#theory t { term { + : 1, binary, left; - : 2, unary }; &a/0 : term, body; \
     &b/0 : term, head; &c/1 : term, {<=, =}, term, any; &d/0 : term, directive }.
     {p}. q :- &a{p : p; 1+2, X : X = 3}.
     &b{x} :- p.
     &c(1){ -x : p } <= 3+4.
     &d { 1 }.
     r :- not &c(2){}.",
    // The same atom in a head and a body: an ordinary atom then.
    "#theory t { term { }; &b/0 : term, any }. {p}. &b{} :- p. q :- &b{}.",
    // Element conditions with local variables over atoms that are not facts.
    "#theory t { term { }; &a/0 : term, body }. {p(1..3)}. q :- &a{ X : p(X) }.
     r :- not &a{ X : p(X) }, p(1).",
    // A difference-logic shaped theory; head atoms derived under a choice.
    "#theory dl { term { - : 1, binary, left }; constant { - : 0, unary };
       &diff/0 : term, {<=}, constant, any }.
     node(1..3). {e(X,Y)} :- node(X), node(Y), X < Y.
     &diff{ x(X) - x(Y) } <= -1 :- e(X,Y).
     ok :- &diff{ x(1) - x(3) } <= -1.",
    // Operator priorities, associativity, tuples, sets, lists, strings, #sup.
    "#theory t { term { + : 1, binary, left; * : 2, binary, left; - : 3, unary;
       ^ : 4, binary, right }; &c/0 : term, {=}, term, body }.
     q :- &c{ f(X,Y) : X = 1, Y = 2; (1,); (); (a,b); [1,2]; {x,y}; \"s\"; #sup; 1+2*3;
       (1+2)*3; 1*2+3; 2^3^4; (2^3)^4; - - x; -(1) } = 3.",
];

/// The theory atoms clingo 5.8 grounds for `program`, as `str(TheoryAtom)`, sorted.
fn clingo_theory_atoms(program: &str) -> Vec<String> {
    let script = "import sys, clingo\n\
                  ctl = clingo.Control()\n\
                  ctl.add('base', [], sys.stdin.read())\n\
                  ctl.ground([('base', [])])\n\
                  for a in ctl.theory_atoms: print(str(a))\n";
    use std::io::Write;
    let mut child = Command::new("python3")
        .args(["-c", script])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("python3 is needed (apt-get install -y python3): {e}"));
    let mut stdin = child.stdin.take().expect("stdin");
    stdin.write_all(program.as_bytes()).expect("program");
    drop(stdin);
    let out = child.wait_with_output().expect("python3");
    assert!(
        out.status.success(),
        "clingo 5.8 is needed (`python3 -m pip install clingo`): {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut v: Vec<String> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(str::to_owned)
        .collect();
    v.sort();
    v
}

/// Lucent's ground theory atoms, printed as clingo 5.8 prints them, sorted.
fn lucent_theory_atoms(program: &str) -> Vec<String> {
    let (g, _) = ground_text("t.lp", program, &GroundConfig::default());
    let names = g.atom_names();
    let mut v: Vec<String> = g
        .program
        .theory_atoms
        .iter()
        .map(|t| {
            let mut s = String::new();
            t.write(&mut s, &mut |l| {
                let a = l.unsigned_abs() as usize;
                let n = names[a - 1].clone().unwrap_or_else(|| format!("#aux({a})"));
                if l < 0 {
                    format!("not {n}")
                } else {
                    n
                }
            });
            s
        })
        .collect();
    v.sort();
    v
}

#[test]
fn answer_sets_are_clingos() {
    for p in PROGRAMS {
        assert_eq!(answer_sets(&[], p), clingo_answer_sets(&[], p), "{p}");
    }
}

#[test]
fn ground_theory_atoms_are_clingos() {
    for p in PROGRAMS {
        assert_eq!(lucent_theory_atoms(p), clingo_theory_atoms(p), "{p}");
    }
}

/// Misuses as clingo 5.8 reports them (`clingo FILE`, first error line with its place).
#[test]
fn misuse_is_reported_as_clingo_does() {
    let cases: &[(&str, &str)] = &[
        (
            "q :- &foo{}.",
            "t.lp:1:6-12: error: no definition found for theory atom:",
        ),
        (
            "#theory t{term{}; &h/0: term, head}. q :- &h{}.",
            "t.lp:1:43-47: error: theory body atom used in head:",
        ),
        (
            "#theory t{term{}; &b/0: term, body}. &b{}.",
            "t.lp:1:38-42: error: theory head atom used in body:",
        ),
        (
            "#theory t{term{}; &d/0: term, directive}. &d{} :- q. q.",
            "t.lp:1:43-47: error: theory directive used with body:",
        ),
        (
            "#theory t{term{}; &d/0: term, directive}. q :- &d{}.",
            "t.lp:1:48-52: error: theory directive used in body:",
        ),
        (
            "#theory t{term{+:1,binary,left}; &b/0: term, body}. q :- &b{1*2}.",
            "t.lp:1:18-19: error: syntax error, unexpected <NUMBER>, expecting :",
        ),
        (
            "#theory t{term{ + : 1, binary, left}; &b/0: term, body}. q :- &b{1*2}.",
            "t.lp:1:63-70: error: missing definition for operator:",
        ),
        (
            "#theory t{term{}; &b/0: term, {<}, term, body}. q :- &b{1} > 2.",
            "t.lp:1:54-63: error: unexpected operator:",
        ),
        (
            "#theory t{term{}; &b/1: term, body}. q :- &b{1}.",
            "t.lp:1:43-48: error: no definition found for theory atom:",
        ),
        (
            "#theory t{term{}; &b/0: term, body}. q :- &b{1} = 2.",
            "t.lp:1:43-52: error: unexpected guard:",
        ),
    ];
    let dir = std::env::temp_dir().join(format!("lucent-theory-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("t.lp");
    for (program, first) in cases {
        std::fs::write(&file, program).unwrap();
        let path = file.to_str().unwrap();
        let (code, _, err) = lucent_in_process(&[path], "");
        assert_eq!(code, 65, "{program}: {err}");
        let line = err.lines().next().unwrap_or("");
        assert_eq!(line.replace(path, "t.lp"), *first, "{program}: {err}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Lucent's aspif (`lucent --mode=gringo`, theory atoms as `9` statements) solved by clingo 5.8
/// and read back by Lucent gives clingo's answer sets of the source program.
#[test]
fn aspif_output_solves_as_the_source() {
    for p in PROGRAMS {
        let (code, aspif, err) = lucent_in_process(&["--mode=gringo"], p);
        assert_eq!(code, 0, "{err}");
        assert!(aspif
            .lines()
            .any(|l| l.starts_with("9 5 ") || l.starts_with("9 6 ")));
        let expected = clingo_answer_sets(&[], p);
        assert_eq!(clingo_answer_sets(&[], &aspif), expected, "{p}\n{aspif}");
        assert_eq!(
            answer_sets(&["--mode=clasp"], &aspif),
            expected,
            "{p}\n{aspif}"
        );
    }
}
