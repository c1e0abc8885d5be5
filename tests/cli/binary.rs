//! Command-line tests: exit codes, output sections and diagnostic format, through the real
//! binary. Expected outputs are derived from docs/reference.md (exit codes) and from gringo's
//! diagnostic format (`file:line:col-col: error: message`).

use crate::support::cli as cli_support;

use cli_support::lucent_binary as lucent;

#[test]
fn help_lists_options_and_exits_0() {
    let (code, out, _) = lucent(&["--help"], "");
    assert_eq!(code, 0);
    for option in [
        "--models",
        "--const",
        "--outf",
        "--opt-mode",
        "--time-limit",
        "--mode",
    ] {
        assert!(out.contains(option), "--help lacks {option}");
    }
}

#[test]
fn version_exits_0() {
    let (code, out, _) = lucent(&["--version"], "");
    assert_eq!(code, 0);
    assert!(out.starts_with("lucent version "));
}

/// clingo 5.4: `clingo --bogus; echo $?` prints
/// `*** ERROR: (clingo): In context '<clingo>': unknown option: 'bogus'` and
/// `*** Info : (clingo): Try '--help' for usage information` on standard error, nothing on
/// standard output, and exits 1 (so do `clasp --bogus` and `gringo --bogus`).
#[test]
fn unknown_option_is_a_usage_error() {
    let (code, out, err) = lucent(&["--bogus"], "");
    assert_eq!(code, 1);
    assert!(out.is_empty());
    assert_eq!(
        err,
        "*** ERROR: (lucent): In context '<lucent>': unknown option: 'bogus'\n\
         *** Info : (lucent): Try '--help' for usage information\n"
    );
    // clingo 5.4: `clingo -Q` says `unknown option: '-Q'`.
    let (code, _, err) = lucent(&["-Q"], "");
    assert_eq!(code, 1);
    assert!(
        err.contains("In context '<lucent>': unknown option: '-Q'"),
        "{err}"
    );
}

/// clingo 5.4: `clingo -n many` prints
/// `*** ERROR: (clingo): In context '<clingo>': 'many' invalid value for: 'models'`, exit 1;
/// `clingo -n` prints `*** ERROR: (clingo): SyntaxError: 'n' requires a value!`, exit 1;
/// `clingo --text=1` prints `*** ERROR: (clingo): SyntaxError: 'text' does not take a value!`.
#[test]
fn bad_value_is_a_usage_error() {
    let (code, _, err) = lucent(&["-n", "many"], "");
    assert_eq!(code, 1);
    assert!(err.contains(
        "*** ERROR: (lucent): In context '<lucent>': 'many' invalid value for: 'models'"
    ));
    let (code, _, err) = lucent(&["-n"], "");
    assert_eq!(code, 1);
    assert!(
        err.contains("*** ERROR: (lucent): SyntaxError: 'n' requires a value!"),
        "{err}"
    );
    let (code, _, err) = lucent(&["--text=1"], "");
    assert_eq!(code, 1);
    assert!(
        err.contains("*** ERROR: (lucent): SyntaxError: 'text' does not take a value!"),
        "{err}"
    );
}

/// The lines of `out` with the times (which depend on the clock) cut off.
fn without_times(out: &str) -> String {
    out.lines()
        .filter(|l| !l.starts_with("Time ") && !l.starts_with("CPU Time"))
        .map(|l| format!("{l}\n"))
        .collect()
}

/// clingo 5.4: `echo 'p(1)' | clingo; echo $?` prints the syntax error on standard error and
/// on standard output
/// `clingo version 5.4.1`, `Reading from stdin`, `UNKNOWN`, ``, `Models       : 0+`,
/// `Calls        : 1`, the two time lines; exit 65. The same for a grounding error
/// (`echo 'p(X) :- q.' | clingo`) and a missing file (`clingo /nonexistent.lp` reads
/// `Reading from /nonexistent.lp`).
#[test]
fn input_error_prints_unknown_and_the_summary() {
    let expected = "lucent version 0.1.0\nReading from stdin\nUNKNOWN\n\nModels       : 0+\n\
                    Calls        : 1\n";
    for program in ["p(1)", "p(X) :- q."] {
        let (code, out, err) = lucent(&[], program);
        assert_eq!(code, 65, "{program}");
        assert_eq!(without_times(&out), expected, "{program}");
        assert!(out.contains("\nTime         : "));
        assert!(out.contains("\nCPU Time     : "));
        assert!(err.contains("error: "));
    }
    let (code, out, _) = lucent(&["/nonexistent/program.lp"], "");
    assert_eq!(code, 65);
    assert!(
        out.starts_with("lucent version 0.1.0\nReading from /nonexistent/program.lp\nUNKNOWN\n")
    );
}

/// clingo 5.4: `echo 'p(1)' | clingo --outf=2` prints a JSON document with `"Input": ["stdin"]`,
/// `"Call": [{}]`, `"Result": "UNKNOWN"`, `"Models": {"Number": 0, "More": "yes"}`,
/// `"Calls": 1` and the times; exit 65.
#[test]
fn input_error_in_json_is_a_document_with_unknown() {
    let (code, out, _) = lucent(&["--outf=2"], "p(1)");
    assert_eq!(code, 65);
    let js: serde_json::Value = serde_json::from_str(&out).expect("a JSON document");
    assert_eq!(js["Result"], "UNKNOWN");
    assert_eq!(js["Input"], serde_json::json!(["stdin"]));
    assert_eq!(js["Models"]["Number"], 0);
    assert_eq!(js["Models"]["More"], "yes");
    assert_eq!(js["Calls"], 1);
}

/// clingo 5.4 at `-V0`: `echo '{a;b}.' | clingo -V0 -n0` prints the models without header or
/// `Answer:` lines and then only the result: ``, `b`, `a`, `a b` (in its order), `SATISFIABLE`;
/// `echo 'p(1)' | clingo -V0` prints only `UNKNOWN` (exit 65); with `--stats` the summary follows.
#[test]
fn verbosity_0_prints_models_and_result_only() {
    let (code, out, _) = lucent(&["-V0", "-n0"], "{a;b}.");
    assert_eq!(code, 30);
    let mut lines: Vec<&str> = out.lines().collect();
    assert_eq!(lines.pop(), Some("SATISFIABLE"));
    lines.sort_unstable();
    assert_eq!(lines, ["", "a", "a b", "b"]);
    let (code, out, _) = lucent(&["-V0"], ":- not a.");
    assert_eq!((code, out.as_str()), (20, "UNSATISFIABLE\n"));
    let (code, out, _) = lucent(&["-V0"], "p(1)");
    assert_eq!((code, out.as_str()), (65, "UNKNOWN\n"));
    let (_, out, _) = lucent(&["-V0", "--stats"], "a.");
    assert!(
        out.starts_with("a\nSATISFIABLE\n\nModels       : 1\n"),
        "{out}"
    );
}

/// clingo 5.4: `echo a. | clingo` prints `Reading from stdin`, and `echo a. | clingo -` prints
/// `Reading from -`; with `--outf=2` the input is `"stdin"` and `"-"`.
#[test]
fn standard_input_is_announced_as_clingo_does() {
    let (_, out, _) = lucent(&[], "a.");
    assert!(
        out.starts_with("lucent version 0.1.0\nReading from stdin\nSolving...\n"),
        "{out}"
    );
    let (_, out, _) = lucent(&["-"], "a.");
    assert!(
        out.starts_with("lucent version 0.1.0\nReading from -\nSolving...\n"),
        "{out}"
    );
    let (_, out, _) = lucent(&["--outf=2"], "a.");
    let js: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(js["Input"], serde_json::json!(["stdin"]));
}

/// A minimize statement whose only element has a condition holding a literal and its negation,
/// or an atom that only such a rule derives: gringo keeps it (`echo '{a}. #minimize{1:a,not a}.'
/// | gringo -t` prints `:~not a,a.[1@0]`), so clingo 5.4 answers
/// `echo '{a}. #minimize{1:a,not a}.' | clingo` with `Optimization: 0` and `OPTIMUM FOUND`
/// (exit 30), and so for `{a}. b :- a, not a. c :- b. #minimize{1:c}.`. Without such an element
/// (`b. #minimize{1:b,not b}.`, where `not b` is false) clingo says `SATISFIABLE`.
#[test]
fn minimize_simplified_away_is_an_optimum_of_0() {
    for program in [
        "{a}. #minimize{1:a,not a}.",
        "{a}. b :- a, not a. c :- b. #minimize{1:c}.",
    ] {
        let (code, out, _) = lucent(&[], program);
        assert_eq!(code, 30, "{program}");
        assert!(
            out.contains("\nOptimization: 0\nOPTIMUM FOUND\n"),
            "{program}: {out}"
        );
        assert!(out.contains("\nOptimization : 0\n"), "{program}: {out}");
    }
    // Two priorities, one of them simplified away: clingo prints `Optimization: 0 0`.
    let (_, out, _) = lucent(&[], "{a}. #minimize{1@2:a,not a; 1@1:a}.");
    assert!(
        out.contains("\nOptimization: 0 0\nOPTIMUM FOUND\n"),
        "{out}"
    );
    let (code, out, _) = lucent(&[], "b. #minimize{1:b,not b}.");
    assert_eq!(code, 30);
    assert!(
        out.contains("\nSATISFIABLE\n") && !out.contains("Optimization"),
        "{out}"
    );
}

#[test]
fn missing_file_is_an_input_error() {
    let (code, _, err) = lucent(&["/nonexistent/program.lp"], "");
    assert_eq!(code, 65);
    assert!(err.contains("<cmd>: error: file could not be opened:\n  /nonexistent/program.lp"));
}

/// The sorted answer sets in clasp's text output (each as its sorted atoms).
fn answer_sets(out: &str) -> Vec<Vec<String>> {
    let lines: Vec<&str> = out.lines().collect();
    let mut models: Vec<Vec<String>> = lines
        .iter()
        .enumerate()
        .filter(|(_, l)| l.starts_with("Answer:"))
        .map(|(i, _)| {
            let mut atoms: Vec<String> = lines[i + 1]
                .split_whitespace()
                .map(str::to_string)
                .collect();
            atoms.sort();
            atoms
        })
        .collect();
    models.sort();
    models
}

#[test]
fn project_atom_ranges_over_its_predicate() {
    // `#project q(X,Y) : p(X).` binds Y from q/2's atoms as gringo does: the four answer sets
    // of {q(1,1); q(1,2)} stay four (clingo 5.8.3: `clingo 0 --project` on this program).
    let prog = "p(1). {q(1,1..2)}. {r}. #project q(X,Y) : p(X).";
    let (code, out, _) = lucent(&["0", "--project"], prog);
    assert_eq!(code, 30);
    let want: Vec<Vec<&str>> = vec![
        vec!["p(1)"],
        vec!["p(1)", "q(1,1)"],
        vec!["p(1)", "q(1,1)", "q(1,2)"],
        vec!["p(1)", "q(1,2)"],
    ];
    assert_eq!(answer_sets(&out), want);
}

#[test]
fn project_signature_projects_every_atom_of_the_predicate() {
    // `#project p/1.` is `#project p(X).`: four projections of the eight answer sets, each
    // shown once (clingo 5.8.3: `clingo 0 --project` on this program gives these four, c with
    // the first answer set of each projection; the test compares the p/1 part only).
    let prog = "{p(1..2); c}. #project p/1. #show p/1. #show c/0.";
    let (code, out, _) = lucent(&["0", "--project"], prog);
    assert_eq!(code, 30);
    let mut projected: Vec<Vec<String>> = answer_sets(&out)
        .into_iter()
        .map(|s| s.into_iter().filter(|a| *a != "c").collect())
        .collect();
    projected.sort();
    let want: Vec<Vec<&str>> = vec![vec![], vec!["p(1)"], vec!["p(1)", "p(2)"], vec!["p(2)"]];
    assert_eq!(projected, want);
    // The ground program says what it projects, as gringo's text output does.
    let (code, out, _) = lucent(&["--text"], prog);
    assert_eq!(code, 0);
    assert!(
        out.contains("#project p(1).") && out.contains("#project p(2)."),
        "{out}"
    );
}

#[test]
fn show_option_adds_show_statements() {
    // `--show=q/0,-r/1` is `#show q/0. #show -r/1.` in the program: the only answer set
    // {p(1), q, -r(1), s} is shown as `q -r(1)` (derived by hand from clingo's #show semantics).
    let prog = "p(1). q :- p(1). -r(1). s.";
    let (code, out, _) = lucent(&["--show=q/0,-r/1"], prog);
    assert_eq!(code, 30);
    assert_eq!(answer_sets(&out), vec![vec!["-r(1)", "q"]]);
    let (code, _, err) = lucent(&["--show=q"], prog);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("invalid value for: 'show'"), "{err}");
}

#[test]
fn heuristic_statements_are_followed_under_domain() {
    // What #heuristic statements Lucent follows is said once; the answers stay those of the
    // program without them ({a;b}. has four answer sets, by hand).
    let prog = "{a;b}. #heuristic a. [1,true] #heuristic b. [1,false]";
    let (code, out, err) = lucent(&["0"], prog);
    assert_eq!(code, 30);
    assert_eq!(answer_sets(&out).len(), 4);
    assert_eq!(err.matches("#heuristic:").count(), 1, "{err}");
    // Under --heuristic=domain the first answer follows them (recorded from clingo 5.4.1:
    // `clingo --heuristic=domain` on each program, its first answer).
    let cases = [
        (
            "{a;b;c}. #heuristic a. [1,true] #heuristic b. [1,false] #heuristic c. [1,sign]",
            vec!["a", "c"],
        ),
        (
            "{a;b;c}. #heuristic a. [1,false] #heuristic b. [1,true] #heuristic c. [-1,sign]",
            vec!["b"],
        ),
        (
            "1{p(1..5)}1. #heuristic p(4). [2,true] #heuristic p(2). [1,true]",
            vec!["p(4)"],
        ),
    ];
    for (prog, first) in cases {
        let (code, out, _) = lucent(&["--heuristic=domain"], prog);
        assert_eq!(code, 10, "{prog}");
        assert_eq!(answer_sets(&out), vec![first], "{prog}");
    }
}

#[test]
fn external_value_is_a_term_of_the_instance() {
    // `[X]` takes each instance's value; values other than true, false, free and release leave
    // the instance out (clingo 5.8.3: `clingo 0` on this program gives these two answer sets).
    let prog = "d(true;false;free;release;7). #external e(X) : d(X). [X]";
    let (code, out, _) = lucent(&["0"], prog);
    assert_eq!(code, 30);
    let d = ["d(7)", "d(false)", "d(free)", "d(release)", "d(true)"];
    let mut one: Vec<&str> = d.to_vec();
    one.push("e(true)");
    let mut two = one.clone();
    two.push("e(free)");
    two.sort();
    one.sort();
    let mut want = vec![one, two];
    want.sort();
    assert_eq!(answer_sets(&out), want);
}

/// The ground program of `a :- not b. b :- not a.` in aspif, as `gringo` (clingo 5.4.1's) prints
/// it: `printf 'a :- not b.\nb :- not a.\n' | gringo`. Its answer sets are {a} and {b}.
const CHOICE_ASPIF: &str = "asp 1 0 0\n1 0 1 1 0 1 -2\n1 0 1 2 0 1 -1\n4 1 b 1 1\n4 1 a 1 2\n0\n";

/// clingo 5.8 solves an input that is a ground program in aspif (`gringo enc.lp | clingo`,
/// `clingo prog.aspif`): `python3 -m clingo prog.aspif 0` prints the answers b and a. Lucent reads
/// such inputs as `--mode=clasp` does, from standard input and from files.
#[test]
fn aspif_input_is_solved_as_a_ground_program() {
    let (code, out, err) = lucent(&["0"], CHOICE_ASPIF);
    assert_eq!(code, 30, "{err}");
    assert_eq!(answer_sets(&out), [["a"], ["b"]]);
    let dir = std::env::temp_dir().join(format!("lucent-aspif-input-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("choice.aspif");
    std::fs::write(&file, CHOICE_ASPIF).unwrap();
    let path = file.to_str().unwrap();
    let (code, out, err) = lucent(&[path, "0"], "");
    assert_eq!(code, 30, "{err}");
    assert_eq!(answer_sets(&out), [["a"], ["b"]]);
    let (code, clasp_out, _) = lucent(&["--mode=clasp", path, "0"], "");
    assert_eq!(code, 30);
    assert_eq!(answer_sets(&clasp_out), answer_sets(&out));
    std::fs::remove_dir_all(&dir).unwrap();
    // A malformed ground program is reported as aspif, with its position.
    let (code, _, err) = lucent(&[], "asp 1 0 0\n1 0 1 1 0\n");
    assert_eq!(code, 65);
    assert!(
        err.contains("-:2:10: error: malformed aspif input"),
        "{err}"
    );
}

/// Only a first line `asp` and three integers makes an input aspif: a program that starts with
/// an atom named `asp` is read as text.
#[test]
fn text_starting_with_asp_is_still_text() {
    let (code, out, err) = lucent(&["0"], "asp(1). asp :- asp(1).\n");
    assert_eq!(code, 30, "{err}");
    assert_eq!(answer_sets(&out), [["asp", "asp(1)"]]);
    let (code, _, err) = lucent(&[], "asp 1 0\n");
    assert_eq!(code, 65);
    assert!(err.contains("syntax error"), "{err}");
}

#[test]
fn consequences_stop_at_the_model_limit() {
    // clingo 5.4.1: `clingo -e cautious 1 cq.lp` on this program prints one answer (`d c`,
    // `Consequences: [1;2]`) and SATISFIABLE; Lucent went on to the next approximation.
    let prog = "1{a;b;c}1. d. e :- a. e :- b.";
    let (code, out, _) = lucent(&["-e", "cautious", "1"], prog);
    assert_eq!(code, 10, "{out}");
    assert_eq!(out.matches("Answer:").count(), 1, "{out}");
    // Without -n, every approximation until the consequences are known (exit 30).
    let (code, out, _) = lucent(&["-e", "cautious"], prog);
    assert_eq!(code, 30, "{out}");
}

#[test]
fn a_first_approximation_is_clasps() {
    // clingo 5.4.1: `clingo cq1.lp -e cautious 1` prints one answer, empty (`Consequences:
    // [0;0]`), and `clingo cq1.lp -e brave 1` one answer `a b c`: clasp decides the shown atoms
    // false first for cautious consequences and true first for brave ones. Lucent's first
    // cautious approximation was the model with every atom true.
    let prog = "{a;b}. c :- a, b.";
    for (mode, want) in [("cautious", ""), ("brave", "a b c")] {
        let (code, out, _) = lucent(&["-e", mode, "1"], prog);
        assert_eq!(code, 10, "{out}");
        let answer = out.lines().skip_while(|l| !l.starts_with("Answer:")).nth(1);
        assert_eq!(answer, Some(want), "{mode}: {out}");
    }
}

#[test]
fn shown_signatures_without_atoms_are_reported() {
    // `echo PROG | clingo 0` (clingo 5.4.1) reports the two signatures no statement mentions
    // (s/1 occurs in a body, p/1 in a head), by signature:
    //   -:1:1-11: info: no atoms over signature occur in program:\n  q/1
    //   -:1:12-23: info: no atoms over signature occur in program:\n  -r/0
    // besides `atom does not occur in any rule head` for s(1).
    let prog = "#show q/1. #show -r/0. #show. {p(1)}. #show p/1. x :- s(1). #show s/1.";
    let (_, _, err) = lucent(&["0"], prog);
    let want = "-:1:1-11: info: no atoms over signature occur in program:\n  q/1\n\n\
                -:1:12-23: info: no atoms over signature occur in program:\n  -r/0\n";
    assert!(err.contains(want), "{err}");
    assert_eq!(err.matches("no atoms over signature").count(), 2, "{err}");
    let (_, _, err) = lucent(&["0", "-Wno-atom-undefined"], prog);
    assert!(!err.contains("no atoms over signature"), "{err}");
}
