//! aspif round trips on recorded gringo output: reading then writing is byte-identical, and a
//! program written in the canonical layout reads back to the same program. The `.aspif` files
//! under `tests/data/aspif/` were written by gringo 5.4.1 with the command in the `.cmd` file
//! beside each (or are hand-written, as the `.cmd` file says).

use std::path::{Path, PathBuf};
use std::process::Command;

use lucent::ground::aspif;

fn data_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/aspif")
}

fn files_with(ext: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(data_dir())
        .expect("tests/data/aspif exists")
        .map(|e| e.expect("readable directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == ext))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no .{ext} files under tests/data/aspif");
    files
}

#[test]
fn reading_then_writing_is_byte_identical() {
    for path in files_with("aspif") {
        let text = std::fs::read_to_string(&path).unwrap();
        let parsed =
            aspif::read(text.as_bytes()).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert_eq!(aspif::write(&parsed), text, "{}", path.display());
    }
}

#[test]
fn canonical_layout_reads_back_to_the_same_program() {
    for path in files_with("aspif") {
        let text = std::fs::read_to_string(&path).unwrap();
        let parsed = aspif::read(text.as_bytes()).unwrap();
        for step in &parsed.steps {
            let program = &step.program;
            let again = aspif::read_program(aspif::write_program(program).as_bytes())
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            // Projection statements are merged into one by the canonical layout, which keeps
            // the atoms; everything else must be equal.
            assert_eq!(&again, program, "{}", path.display());
        }
    }
}

#[test]
fn recorded_files_are_what_gringo_writes() {
    for lp in files_with("lp") {
        let output = Command::new("gringo")
            .arg("--output=intermediate")
            .arg(lp.file_name().unwrap())
            .current_dir(data_dir())
            .output();
        let output = match output {
            Ok(o) => o,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                panic!("gringo not found; install clingo: apt-get install -y gringo clasp")
            }
            Err(e) => panic!("running gringo: {e}"),
        };
        assert!(output.status.success(), "gringo failed on {}", lp.display());
        let expected = std::fs::read(lp.with_extension("aspif")).unwrap();
        assert_eq!(
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&expected),
            "{}",
            lp.display()
        );
        let parsed = aspif::read(&output.stdout).unwrap();
        assert_eq!(aspif::write(&parsed).as_bytes(), &output.stdout[..]);
    }
}

#[test]
fn incremental_steps_accumulate_atoms() {
    let text = std::fs::read_to_string(data_dir().join("incremental.aspif")).unwrap();
    let parsed = aspif::read(text.as_bytes()).unwrap();
    assert_eq!(parsed.tags, vec!["incremental".to_string()]);
    assert_eq!(parsed.steps.len(), 2);
    assert_eq!(parsed.steps[0].program.num_atoms, 2);
    assert_eq!(parsed.steps[1].program.num_atoms, 3);
    assert_eq!(
        parsed.steps[1].comments,
        vec!["a comment kept verbatim".to_string()]
    );
    let err = aspif::read_program(text.as_bytes()).unwrap_err();
    assert_eq!(err.kind, aspif::AspifErrorKind::SeveralSteps(2));
}

#[test]
fn lucent_cr_comments_are_recovered() {
    let text = std::fs::read_to_string(data_dir().join("lucent_cr.aspif")).unwrap();
    let program = aspif::read_program(text.as_bytes()).unwrap();
    let labels: Vec<_> = program
        .cr_rules
        .iter()
        .map(|c| (c.appl, c.label.as_str()))
        .collect();
    assert_eq!(labels, vec![(1, "r1"), (2, "r2(1,\"a b\")")]);
    assert_eq!(program.prefers.len(), 1);
    // The CR minimize is not a user minimize; the user's one at priority 0 stays.
    assert_eq!(program.minimize.len(), 1);
    assert_eq!(program.minimize[0].priority, 0);
    assert_eq!(aspif::cr_priority(&program), 1);
}
