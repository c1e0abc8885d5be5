//! Differential test against clingo: every program in `tests/data/solve/` is grounded by
//! `gringo --output=intermediate`, read with `ground::aspif`, solved by Lucent, and its sorted
//! answer sets (for programs with `#minimize`/`#maximize`: the optimal ones, with the optimum)
//! are compared with `clingo -n0 --outf=2` (`--opt-mode=optN`). Model order and statistics are
//! never compared. Fails, never skips, when clingo is missing.

use lucent::ground::aspif;
use lucent::solve::{Config, OptMode, Solver};
use std::path::Path;
use std::process::Command;

const INSTALL: &str = "install clingo: apt-get install -y gringo clasp";

fn run(cmd: &str, args: &[&str]) -> Vec<u8> {
    let out = Command::new(cmd)
        .args(args)
        .output()
        .unwrap_or_else(|e| panic!("{INSTALL} ({cmd}: {e})"));
    out.stdout
}

type Answers = (Vec<Vec<String>>, Option<Vec<i64>>);

fn clingo_answers(file: &str) -> Answers {
    let json = run("clingo", &["-n0", "--outf=2", "--opt-mode=optN", file]);
    let v: serde_json::Value =
        serde_json::from_slice(&json).expect("clingo writes JSON with --outf=2");
    let optimum: Option<Vec<i64>> = v["Models"]["Costs"].as_array().map(|c| {
        c.iter()
            .map(|x| x.as_i64().expect("integer cost"))
            .collect()
    });
    let mut sets = Vec::new();
    for call in v["Call"].as_array().into_iter().flatten() {
        for w in call["Witnesses"].as_array().into_iter().flatten() {
            let costs: Option<Vec<i64>> = w["Costs"].as_array().map(|c| {
                c.iter()
                    .map(|x| x.as_i64().expect("integer cost"))
                    .collect()
            });
            if optimum.is_some() && costs != optimum {
                continue;
            }
            let mut atoms: Vec<String> = w["Value"]
                .as_array()
                .into_iter()
                .flatten()
                .map(|s| s.as_str().expect("symbol text").to_string())
                .collect();
            atoms.sort();
            sets.push(atoms);
        }
    }
    sets.sort();
    if optimum.is_some() {
        // optN reports the first optimal model twice (as improving and as optimal).
        sets.dedup();
    }
    (sets, optimum)
}

fn lucent_answers(file: &str) -> Answers {
    let aspif = run("gringo", &["--output=intermediate", file]);
    assert!(
        !aspif.is_empty(),
        "{INSTALL} (gringo gave no output for {file})"
    );
    let program = aspif::read_program(&aspif).expect("gringo's aspif is readable");
    let optimize = !program.minimize.is_empty();
    let config = Config {
        models: 0,
        opt_mode: if optimize {
            OptMode::OptN
        } else {
            OptMode::Opt
        },
        check_models: true,
        ..Config::default()
    };
    let r = Solver::new(&program, config).solve();
    assert!(r.exhausted, "{file}: search not exhausted");
    let mut sets: Vec<Vec<String>> = r
        .models
        .iter()
        .filter(|m| !optimize || m.optimal)
        .map(|m| {
            let mut s = m.symbols.clone();
            s.sort();
            s
        })
        .collect();
    // Distinct answer sets may show the same symbols; clingo prints them all, so do we.
    sets.sort();
    if optimize {
        sets.dedup();
    }
    let optimum = if optimize {
        r.models.last().map(|m| m.costs.clone())
    } else {
        None
    };
    (sets, optimum)
}

#[test]
fn answer_sets_agree_with_clingo() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/solve");
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .expect("tests/data/solve exists")
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "lp"))
        .collect();
    files.sort();
    assert!(files.len() >= 10);
    for f in files {
        let f = f.to_str().expect("UTF-8 path");
        let want = clingo_answers(f);
        let got = lucent_answers(f);
        assert_eq!(got, want, "{f}: Lucent (left) and clingo (right) disagree");
    }
}
