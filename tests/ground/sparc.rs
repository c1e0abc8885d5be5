//! SPARC programs: `tests/data/ground/sparc/robots.sp` grounds, and clasp on Lucent's ground
//! program gives the optimal answer sets recorded (from clingo, command in the expected file)
//! for its hand translation `robots.lp`; type errors are reported at the atom.
//!
//! `tests/data/sparc/*.sp` are programs written to SPARC's manual, one construct each; every
//! file lists its answer sets in `%% answer:` lines (derived by hand, the derivation in the
//! file's comments: SPARC itself is not installable here), and `lucent -n0` must give exactly
//! those; each `%% warning:` line must start a line of its standard error (SPARC's warnings,
//! positioned). `tests/data/sparc/errors/*.sp` are SPARC's error cases: each must exit 65 with the
//! positioned diagnostic of its snapshot.
//!
//! Needs clasp; fails (never skips) without it.

use std::collections::BTreeSet;
use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

use lucent::base::SourceMap;
use lucent::ground::{aspif, ground, GroundConfig};
use lucent::syntax::ast::Dialect;
use lucent::syntax::parse;

fn ground_sparc(text: &str) -> (lucent::ground::Grounding, SourceMap) {
    let mut sources = SourceMap::new();
    let id = sources.add("-", text);
    let parsed = parse(id, text, Dialect::Sparc);
    assert!(!parsed.has_errors(), "parse errors");
    let g = ground(&parsed.program, Some(&sources), &GroundConfig::default());
    (g, sources)
}

#[test]
fn robots_optimal_answer_sets() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/ground/sparc");
    let text = std::fs::read_to_string(dir.join("robots.sp")).expect("program");
    let (g, sources) = ground_sparc(&text);
    assert!(
        !g.diagnostics.has_errors(),
        "{}",
        g.diagnostics.render(&sources)
    );
    assert!(!g.program.cr_rules.is_empty());
    let ok = Command::new("sh")
        .args(["-c", "command -v clasp"])
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    assert!(ok, "install clingo: apt-get install -y gringo clasp");
    let mut child = Command::new("clasp")
        .args(["-n0", "--opt-mode=optN", "--outf=2"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("clasp runs");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(aspif::write_program(&g.program).as_bytes())
        .expect("aspif");
    let out = child.wait_with_output().expect("clasp");
    let js: serde_json::Value = serde_json::from_slice(&out.stdout).expect("json");
    let ws: Vec<&serde_json::Value> = js["Call"]
        .as_array()
        .expect("calls")
        .iter()
        .flat_map(|c| c["Witnesses"].as_array().expect("witnesses").iter())
        .collect();
    let cost = |w: &serde_json::Value| -> Vec<i64> {
        w["Costs"]
            .as_array()
            .map(|a| a.iter().map(|c| c.as_i64().expect("cost")).collect())
            .unwrap_or_default()
    };
    let best = ws.iter().map(|w| cost(w)).min().expect("a model");
    let got: BTreeSet<Vec<String>> = ws
        .iter()
        .filter(|w| cost(w) == best)
        .map(|w| {
            let mut v: Vec<String> = w["Value"]
                .as_array()
                .expect("atoms")
                .iter()
                .map(|a| a.as_str().expect("atom").to_string())
                .collect();
            v.sort();
            v
        })
        .collect();
    let exp: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(dir.join("robots.expected.json")).expect("expected"),
    )
    .expect("json");
    let want: BTreeSet<Vec<String>> = exp["models"]
        .as_array()
        .expect("models")
        .iter()
        .map(|m| {
            m.as_array()
                .expect("model")
                .iter()
                .map(|a| a.as_str().expect("atom").to_string())
                .collect()
        })
        .collect();
    assert_eq!(got, want);
}

fn errors(text: &str) -> String {
    let (g, sources) = ground_sparc(text);
    assert!(g.diagnostics.has_errors());
    g.diagnostics.render(&sources)
}

#[test]
fn constant_outside_its_sort() {
    insta::assert_snapshot!(errors(
        "sorts\n#a = {x, y}.\npredicates\np(#a).\nrules\np(z).\n"
    ));
}

#[test]
fn undeclared_predicate_and_wrong_arity() {
    insta::assert_snapshot!(errors(
        "sorts\n#a = {x, y}.\npredicates\np(#a).\nrules\np(x, x).\nq(x) :- p(X).\n"
    ));
}

fn lucent(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("lucent runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The `.sp` files of a directory, sorted by name.
fn programs(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("test directory")
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter(|n| n.ends_with(".sp"))
        .collect();
    names.sort();
    names
}

#[test]
fn manual_programs_give_their_answer_sets() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/sparc");
    let names = programs(&dir);
    assert!(names.len() >= 10, "programs missing: {names:?}");
    for name in names {
        let text = std::fs::read_to_string(dir.join(&name)).expect("program");
        let want: BTreeSet<BTreeSet<String>> = text
            .lines()
            .filter_map(|l| l.strip_prefix("%% answer:"))
            .map(|l| l.split_whitespace().map(str::to_string).collect())
            .collect();
        assert!(!want.is_empty(), "{name}: no %% answer: line");
        let (code, stdout, stderr) = lucent(&dir, &["-n0", "--outf=2", &name]);
        assert!(matches!(code, 10 | 30), "{name}: exit {code}\n{stderr}");
        for w in text.lines().filter_map(|l| l.strip_prefix("%% warning: ")) {
            assert!(
                stderr.lines().any(|l| l.starts_with(w)),
                "{name}: no warning {w}\n{stderr}"
            );
        }
        assert!(
            !stderr.contains("does not occur in any rule head"),
            "{name}: warnings for declared predicates\n{stderr}"
        );
        let js: serde_json::Value = serde_json::from_str(&stdout).expect("json");
        let got: BTreeSet<BTreeSet<String>> = js["Call"]
            .as_array()
            .expect("calls")
            .iter()
            .flat_map(|c| c["Witnesses"].as_array().expect("witnesses").iter())
            .map(|w| {
                w["Value"]
                    .as_array()
                    .expect("atoms")
                    .iter()
                    .map(|a| a.as_str().expect("atom").to_string())
                    .collect()
            })
            .collect();
        assert_eq!(got, want, "{name}");
    }
}

#[test]
fn manual_errors_are_rejected_with_a_position() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/sparc/errors");
    let names = programs(&dir);
    assert!(names.len() >= 10, "programs missing: {names:?}");
    for name in names {
        let (code, _, stderr) = lucent(&dir, &[&name]);
        assert_eq!(code, 65, "{name}: exit {code}\n{stderr}");
        assert!(
            stderr.starts_with(&format!("{name}:")),
            "{name}: no position\n{stderr}"
        );
        insta::assert_snapshot!(name.trim_end_matches(".sp"), stderr);
    }
}

#[test]
fn declared_predicates_get_no_undefined_atom_warning() {
    // q is declared but heads no rule: gringo would warn at q(X); SPARC does not.
    let text = "sorts\n#s = {a}.\npredicates\np(#s).\nq(#s).\nrules\np(X) :- q(X).\n";
    let (g, sources) = ground_sparc(text);
    let rendered = g.diagnostics.render(&sources);
    assert!(
        !rendered.contains("does not occur in any rule head"),
        "{rendered}"
    );
    // The same rules in the clingo dialect do warn (the suppression is SPARC's alone).
    let mut sources = SourceMap::new();
    let clingo = "p(X) :- q(X).";
    let id = sources.add("-", clingo);
    let parsed = parse(id, clingo, Dialect::Clingo);
    let g = ground(&parsed.program, Some(&sources), &GroundConfig::default());
    assert!(g
        .diagnostics
        .render(&sources)
        .contains("does not occur in any rule head"));
}
