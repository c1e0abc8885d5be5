//! The built-in domains solved end to end through the binary, against expected answers recorded
//! from clingo (`domains/*/record_expected.sh` writes them, with the clingo version inside).

use std::collections::BTreeSet;
use std::process::Command;

fn expected_plans() -> BTreeSet<Vec<String>> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/domains/tabletop/expected/plans.json"
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    json["models"]
        .as_array()
        .unwrap()
        .iter()
        .map(|m| {
            let mut v: Vec<String> = m
                .as_array()
                .unwrap()
                .iter()
                .map(|a| a.as_str().unwrap().to_string())
                .collect();
            v.sort();
            v
        })
        .collect()
}

#[test]
fn tabletop_answer_sets_match_clingo() {
    let program = concat!(env!("CARGO_MANIFEST_DIR"), "/domains/tabletop/tabletop.lp");
    let out = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .args(["-n0", "--outf=2", "--check", program])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(30),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let got: BTreeSet<Vec<String>> = json["Call"][0]["Witnesses"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| {
            let mut v: Vec<String> = w["Value"]
                .as_array()
                .unwrap()
                .iter()
                .map(|a| a.as_str().unwrap().to_string())
                .collect();
            v.sort();
            v
        })
        .collect();
    // Each answer set is printed once (docs/reference.md), so the count must match too.
    assert_eq!(
        json["Call"][0]["Witnesses"].as_array().unwrap().len(),
        got.len()
    );
    assert_eq!(got, expected_plans());
}
