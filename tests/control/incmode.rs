//! clingo's incremental mode through the command line, in-process: every `tests/data/incmode`
//! case (`X.lp`, options in `X.cmd`, clingo's answers in `X.sol`, recorded as the folder's
//! README says) is run as `lucent 0 X.lp -Wnone`, normalised as clingo's `app/clingo/tests`
//! runner does, and compared with the recorded answers.

use std::path::Path;

/// The normalisation of clingo's `tests/run.py`: per `Solving...` a `Step: N` header and the
/// sorted models (atoms sorted), then the last result word.
fn normalize(out: &str) -> String {
    let (mut state, mut step, mut result) = (0, 0, "ERROR");
    let mut current: Vec<Vec<String>> = Vec::new();
    let mut norm: Vec<String> = Vec::new();
    for line in out.split('\n') {
        if state == 1 {
            if step > 0 {
                norm.push(format!("Step: {step}"));
                let mut models: Vec<String> = current
                    .iter()
                    .map(|m| {
                        let mut m = m.clone();
                        m.sort();
                        m.join(" ")
                    })
                    .collect();
                models.sort();
                norm.extend(models);
            }
            step += 1;
            state = 0;
            current.clear();
        }
        if state == 2 {
            current.push(line.trim().split(' ').map(str::to_string).collect());
            state = 0;
        } else if line.starts_with("Solving...") {
            state = 1;
        } else if line.starts_with("Answer: ") {
            state = 2;
        } else if line.starts_with("SATISFIABLE") {
            (result, state) = ("SAT", 1);
        } else if line.starts_with("UNSATISFIABLE") {
            (result, state) = ("UNSAT", 1);
        } else if line.starts_with("UNKNOWN") {
            (result, state) = ("UNKNOWN", 1);
        } else if line.starts_with("OPTIMUM FOUND") {
            (result, state) = ("OPTIMUM FOUND", 1);
        }
    }
    norm.push(result.to_string());
    norm.join("\n")
}

#[test]
fn incmode_cases_give_clingos_answers() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/incmode");
    let mut cases = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "lp") {
            continue;
        }
        let mut args = vec![
            "0".to_string(),
            path.display().to_string(),
            "-Wnone".to_string(),
        ];
        if let Ok(cmd) = std::fs::read_to_string(path.with_extension("cmd")) {
            args.extend(cmd.split_whitespace().map(str::to_string));
        }
        let (mut out, mut err) = (Vec::new(), Vec::new());
        lucent::cli::run(&args, &mut &b""[..], &mut out, &mut err);
        let got = normalize(&String::from_utf8(out).unwrap());
        let want = std::fs::read_to_string(path.with_extension("sol")).unwrap();
        assert_eq!(
            got.trim(),
            want.trim(),
            "{}: {}",
            path.display(),
            String::from_utf8_lossy(&err)
        );
        cases += 1;
    }
    assert!(cases >= 5, "the incmode cases are missing");
}
