//! The body of the `aspif` fuzz target (`lucent::solve::fuzzing::check_aspif_bytes`) on the
//! seed corpus, so the target cannot rot: every aspif file of tests/data/aspif (and random/),
//! each cut short at every line, and inputs the fuzzer found interesting.

use lucent::solve::fuzzing::check_aspif_bytes;

fn aspif_files() -> Vec<std::path::PathBuf> {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/aspif");
    let mut paths = Vec::new();
    for dir in [root.to_string(), format!("{root}/random")] {
        for e in std::fs::read_dir(dir).unwrap() {
            let p = e.unwrap().path();
            if p.extension().is_some_and(|x| x == "aspif") {
                paths.push(p);
            }
        }
    }
    paths.sort();
    assert!(paths.len() > 60, "{}", paths.len());
    paths
}

#[test]
fn seed_corpus_keeps_the_invariants() {
    for path in aspif_files() {
        let bytes = std::fs::read(&path).unwrap();
        check_aspif_bytes(&bytes).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        // Every prefix ending at a line break: truncated inputs must give errors, not panics.
        for (i, _) in bytes.iter().enumerate().filter(|(_, &b)| b == b'\n') {
            check_aspif_bytes(&bytes[..i])
                .unwrap_or_else(|e| panic!("{} cut at {i}: {e}", path.display()));
        }
    }
}

#[test]
fn inputs_found_by_the_fuzzer() {
    for input in [
        // A huge atom number: read, but too large to solve here (MAX_ATOMS).
        &b"asp 1 0 0\n1 0 1 2147483647 0 0\n0\n"[..],
        // Incremental header with two steps: `read` accepts it, `read_program` does not.
        b"asp 1 0 0 incremental\n1 0 1 1 0 0\n0\n1 0 1 2 0 1 1\n0\n",
        // Edges forming a cycle, a heuristic and an assumption.
        b"asp 1 0 0\n1 1 2 1 2 0 0\n8 1 2 1 1\n8 2 1 1 2\n7 0 1 1 0 0\n6 1 -2\n0\n",
        // Minimize with a negative weight and priorities.
        b"asp 1 0 0\n1 1 2 1 2 0 0\n2 1 2 1 -3 2 1\n2 0 1 -1 2\n0\n",
    ] {
        check_aspif_bytes(input).unwrap();
    }
}
