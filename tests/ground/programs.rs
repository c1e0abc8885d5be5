//! Data-driven grounder tests over `tests/data/ground/*.lp`:
//! - answer sets: ground with Lucent, write aspif, solve with clasp, and compare the sorted answer
//!   sets and costs with `NAME.expected.json` (recorded from clingo 5.4.1, or 5.8.3 where the
//!   program's first line says so; command inside);
//! - the same with Lucent's solver on Lucent's grounding, so the recorded answers check the
//!   whole pipeline (the non-head-cycle-free saturation encodings of recursive sums with
//!   weights of both signs, `recursive_sum_mixed_*.lp`, are solver regressions);
//! - atoms: the shown (possibly true) atoms of Lucent's ground program equal gringo's
//!   (`gringo --output=intermediate`), and gringo's facts are facts here too.
//!
//! These tests need gringo and clasp; they fail (never skip) when those are missing.

use std::collections::BTreeSet;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use lucent::base::SourceMap;
use lucent::ground::{aspif, GroundConfig, Grounding};

fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/ground")
}

fn programs() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(data_dir())
        .expect("tests/data/ground")
        .map(|e| e.expect("dir entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "lp"))
        .collect();
    v.sort();
    assert!(!v.is_empty());
    v
}

use crate::support::ground as ground_support;

fn ground_file(path: &Path) -> (Grounding, SourceMap) {
    let text = std::fs::read_to_string(path).expect("program");
    ground_support::ground_text(&path.display().to_string(), &text, &GroundConfig::default())
}

fn tool(name: &str) -> Command {
    let found = Command::new("sh")
        .arg("-c")
        .arg(format!("command -v {name}"))
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    assert!(found, "install clingo: apt-get install -y gringo clasp");
    Command::new(name)
}

/// Sorted (atoms, costs) of every answer set clasp finds for an aspif program.
fn clasp_models(aspif_text: &str) -> Vec<(Vec<String>, Vec<i64>)> {
    let mut child = tool("clasp")
        .args(["-n0", "--outf=2", "--opt-mode=enum"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("clasp runs");
    child
        .stdin
        .take()
        .expect("stdin")
        .write_all(aspif_text.as_bytes())
        .expect("write aspif");
    let out = child.wait_with_output().expect("clasp output");
    let js: serde_json::Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("clasp json: {e}: {}", String::from_utf8_lossy(&out.stdout)));
    let mut models = Vec::new();
    for call in js["Call"].as_array().into_iter().flatten() {
        for w in call["Witnesses"].as_array().into_iter().flatten() {
            let mut atoms: Vec<String> = w["Value"]
                .as_array()
                .into_iter()
                .flatten()
                .map(|v| v.as_str().expect("atom").to_string())
                .collect();
            atoms.sort();
            let costs = w["Costs"]
                .as_array()
                .into_iter()
                .flatten()
                .map(|c| c.as_i64().expect("cost"))
                .collect();
            models.push((atoms, costs));
        }
    }
    models.sort();
    models
}

fn expected_models(path: &Path) -> Vec<(Vec<String>, Vec<i64>)> {
    let text =
        std::fs::read_to_string(path.with_extension("expected.json")).expect("expected file");
    let js: serde_json::Value = serde_json::from_str(&text).expect("expected json");
    let mut models: Vec<(Vec<String>, Vec<i64>)> = js["models"]
        .as_array()
        .expect("models")
        .iter()
        .map(|m| {
            let atoms = m["atoms"]
                .as_array()
                .expect("atoms")
                .iter()
                .map(|a| a.as_str().expect("atom").to_string())
                .collect();
            let costs = m["costs"]
                .as_array()
                .expect("costs")
                .iter()
                .map(|c| c.as_i64().expect("cost"))
                .collect();
            (atoms, costs)
        })
        .collect();
    models.sort();
    models
}

#[test]
fn answer_sets_match_clingo() {
    for path in programs() {
        let (g, _) = ground_file(&path);
        let text = aspif::write_program(&g.program);
        let got = clasp_models(&text);
        let want = expected_models(&path);
        assert_eq!(got, want, "{}", path.display());
    }
}

#[test]
fn lucent_solver_matches_clingo() {
    use lucent::solve::{Config, OptMode, Solver};
    for path in programs() {
        let (g, _) = ground_file(&path);
        let config = Config {
            models: 0,
            opt_mode: OptMode::Enum(Vec::new()),
            check_models: true,
            ..Config::default()
        };
        let r = Solver::new(&g.program, config).solve();
        assert!(r.exhausted, "{}: search not exhausted", path.display());
        let mut got: Vec<(Vec<String>, Vec<i64>)> = r
            .models
            .iter()
            .map(|m| {
                let mut atoms = m.symbols.clone();
                atoms.sort();
                (atoms, m.costs.clone())
            })
            .collect();
        got.sort();
        assert_eq!(got, expected_models(&path), "{}", path.display());
    }
}

/// Shown symbols of an aspif text, split into unconditional (facts) and conditional ones.
fn gringo_outputs(path: &Path) -> (BTreeSet<String>, BTreeSet<String>) {
    let out = tool("gringo")
        .args(["--output=intermediate", "-Wnone"])
        .arg(path)
        .output()
        .expect("gringo runs");
    let text = String::from_utf8(out.stdout).expect("utf8");
    let (mut facts, mut others) = (BTreeSet::new(), BTreeSet::new());
    for line in text.lines() {
        let mut it = line.split(' ');
        if it.next() != Some("4") {
            continue;
        }
        let len: usize = it.next().expect("length").parse().expect("number");
        let rest = &line[line.find(' ').expect("sp") + 1..];
        let rest = &rest[rest.find(' ').expect("sp") + 1..];
        let (sym, tail) = rest.split_at(len);
        let n: usize = tail
            .trim()
            .split(' ')
            .next()
            .expect("count")
            .parse()
            .expect("number");
        if n == 0 {
            facts.insert(sym.to_string());
        } else {
            others.insert(sym.to_string());
        }
    }
    (facts, others)
}

#[test]
fn atoms_match_gringo() {
    for path in programs() {
        // Programs recorded with clingo 5.8.3 are there because gringo 5.4.1 grounds them
        // differently (record.py); their answer sets are checked above.
        let text = std::fs::read_to_string(&path).expect("program");
        if text.starts_with("% record with clingo 5.8.3") {
            continue;
        }
        let (g, _) = ground_file(&path);
        let mut facts = BTreeSet::new();
        let mut others = BTreeSet::new();
        for o in &g.program.outputs {
            if o.condition.is_empty() {
                facts.insert(o.symbol.clone());
            } else {
                others.insert(o.symbol.clone());
            }
        }
        let (gf, go) = gringo_outputs(&path);
        // The same possibly-true atoms; every gringo fact is a fact here too (Lucent may
        // simplify further, e.g. inside recursive aggregates).
        let ours: BTreeSet<_> = facts.union(&others).cloned().collect();
        let theirs: BTreeSet<_> = gf.union(&go).cloned().collect();
        assert_eq!(ours, theirs, "shown atoms of {}", path.display());
        assert!(
            facts.is_superset(&gf),
            "facts of {}: {facts:?} vs {gf:?}",
            path.display()
        );
    }
}
