//! README.md as a newcomer would use it: every command of its fenced blocks marked `sh test`
//! runs as written, from a directory laid out like a fresh clone, with the built `lucent` first
//! on PATH, and must succeed (exit 0, or clingo's 10, 20 and 30 after solving; a pipeline fails
//! when any of its commands does). Lines starting with `lucent sim` are run only in builds with
//! the `sim` feature. The README's Rust example is a doctest (`src/lib.rs`, `cargo test --doc`).
//!
//! With the `sim` feature, a command whose comment says "the picture above" must make the
//! README's picture above it pixel for pixel.
//!
//! Commands with `clasp` or `gringo` need clingo 5.4's tools (`scripts/test.sh` installs them).

use std::path::{Path, PathBuf};
use std::process::Command;

/// The commands of the README's `sh test` blocks, without their trailing `# comments`.
fn readme_commands(readme: &str) -> Vec<String> {
    let mut commands = Vec::new();
    let mut in_block = false;
    for line in readme.lines() {
        let trimmed = line.trim();
        if let Some(info) = trimmed.strip_prefix("```") {
            in_block = !in_block && info.split_whitespace().eq(["sh", "test"]);
            continue;
        }
        if !in_block || trimmed.is_empty() {
            continue;
        }
        // A comment starts at `#` after at least two spaces (so `'#show'` in a command stays).
        let command = match line.find("  #") {
            Some(i) => &line[..i],
            None => line,
        };
        commands.push(command.trim().to_string());
    }
    commands
}

/// A scratch directory holding links to every top-level entry of the repository except
/// `target`, so commands see a clone's layout and the files they write stay out of the tree.
fn clone_like_dir(root: &Path) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("lucent-readme-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    for entry in std::fs::read_dir(root).unwrap() {
        let entry = entry.unwrap();
        let name = entry.file_name();
        if name == "target" || name == ".git" {
            continue;
        }
        std::os::unix::fs::symlink(entry.path(), dir.join(&name)).unwrap();
    }
    dir
}

#[test]
fn readme_lists_the_commands_to_test() {
    let commands = readme_commands(include_str!("../../README.md"));
    // The extraction itself: the README has such blocks, and comments are cut.
    assert!(commands.len() >= 10, "{commands:?}");
    assert!(commands.iter().all(|c| !c.contains("  #") && !c.is_empty()));
    assert!(
        commands.contains(&"lucent --help".to_string()),
        "{commands:?}"
    );
}

#[test]
fn every_readme_command_runs_as_written() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let bin_dir = Path::new(env!("CARGO_BIN_EXE_lucent")).parent().unwrap();
    let path = format!(
        "{}:{}",
        bin_dir.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let dir = clone_like_dir(root);
    let mut failures = Vec::new();
    for command in readme_commands(include_str!("../../README.md")) {
        if command.starts_with("lucent sim") && !cfg!(feature = "sim") {
            continue;
        }
        let out = Command::new("bash")
            .args(["-o", "pipefail", "-c", &command])
            .current_dir(&dir)
            .env("PATH", &path)
            .output()
            .expect("bash runs");
        let code = out.status.code().unwrap_or(-1);
        if ![0, 10, 20, 30].contains(&code) {
            failures.push(format!(
                "`{command}` exited {code}:\n{}",
                String::from_utf8_lossy(&out.stderr)
            ));
        }
    }
    #[cfg(feature = "sim")]
    failures.extend(pictures_reproduced(
        include_str!("../../README.md"),
        root,
        &dir,
    ));
    let _ = std::fs::remove_dir_all(&dir);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The exit codes the README promises ("Exit codes"), one command each, run from the clone:
/// solving as clingo (10, 20, 30), a bad command line 1, bad input and an unwritable file 65, jobs
/// 0 when done, `run` 0 when the goal is reached and 20 when not.
#[test]
fn the_exit_codes_the_readme_promises() {
    let readme = include_str!("../../README.md");
    for promise in [
        "10 a model found, 20 no model",
        "30 search exhausted with models",
        "1 a bad command line",
        "65 an error in the input or a file that cannot be read or written",
        "exit 0 when done",
        "exit 0 when the robot reached its goal and 20 when it did not",
    ] {
        let flat = readme.split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(
            flat.contains(promise),
            "the README no longer says `{promise}`"
        );
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lucent = env!("CARGO_BIN_EXE_lucent");
    let dir = std::env::temp_dir().join(format!("lucent-exits-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let code = |args: &[&str], stdin: &str| -> i32 {
        use std::io::Write;
        let mut child = Command::new(lucent)
            .args(args)
            .current_dir(root)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .spawn()
            .unwrap();
        // A command that fails before reading its input (a bad command line) may exit
        // before the write: a broken pipe then, which is no failure of the test.
        if let Err(e) = child.stdin.take().unwrap().write_all(stdin.as_bytes()) {
            assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "{e}");
        }
        child.wait().unwrap().code().unwrap_or(-1)
    };
    let unwritable = dir.join("no/such/dir/out.json");
    let unwritable = unwritable.to_str().unwrap();
    let mut cases: Vec<(Vec<&str>, &str, i32)> = vec![
        (vec![], "{a}.", 10),
        (vec![], "a :- not a.", 20),
        (vec![], "a.", 30),
        (vec!["-n", "0"], "{a}.", 30),
        (vec!["--frobnicate"], "a.", 1),
        (vec![], "a(.", 65),
        (vec!["no-such-file.lp"], "", 65),
        (
            vec![
                "translate",
                "domains/ra/scenes/tabletop_task.ald",
                "-c",
                "horizon=3",
            ],
            "",
            0,
        ),
    ];
    if cfg!(feature = "sim") {
        let sim: Vec<(Vec<&str>, &str, i32)> = vec![
            (
                vec![
                    "run",
                    "--preset",
                    "real",
                    "--seed",
                    "3",
                    "--goal",
                    "on(brown_pot,green_cube)",
                ],
                "",
                0,
            ),
            (
                vec![
                    "run",
                    "--preset",
                    "real",
                    "--seed",
                    "3",
                    "--max-actions",
                    "0",
                ],
                "",
                20,
            ),
            (
                vec![
                    "run",
                    "--preset",
                    "real",
                    "--seed",
                    "3",
                    "--save-history",
                    unwritable,
                ],
                "",
                65,
            ),
            (
                vec!["sim", "generate", "--seed", "1", "-o", unwritable],
                "",
                65,
            ),
        ];
        cases.extend(sim);
    }
    let mut wrong = Vec::new();
    for (args, stdin, want) in &cases {
        let got = code(args, stdin);
        if got != *want {
            wrong.push(format!(
                "lucent {args:?} < {stdin:?}: exit {got}, the README says {want}"
            ));
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

/// The decoded RGB pixels and size of a PNG file.
#[cfg(feature = "sim")]
fn pixels(path: &Path) -> Result<(u32, u32, Vec<u8>), String> {
    let file = std::fs::File::open(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .map_err(|e| format!("{}: {e}", path.display()))?;
    let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("{}: {e}", path.display()))?;
    buf.truncate(info.buffer_size());
    Ok((info.width, info.height, buf))
}

/// The README's pictures are what its commands make: a command whose comment says "the picture
/// above" writes (`-o FILE.png`) the picture the README showed last before that command's
/// block, pixel for pixel.
#[cfg(feature = "sim")]
fn pictures_reproduced(readme: &str, root: &Path, dir: &Path) -> Vec<String> {
    let mut failures = Vec::new();
    let mut shown: Option<&str> = None;
    let mut checked = 0;
    for line in readme.lines() {
        if let Some((_, rest)) = line.split_once("](") {
            if line.trim_start().starts_with("![") {
                shown = rest.split_once(')').map(|(p, _)| p);
            }
        }
        if !line.contains("the picture above") {
            continue;
        }
        let Some(picture) = shown else {
            failures.push(format!("`{line}` names a picture above, but none is shown"));
            continue;
        };
        let Some(made) = line.split_whitespace().skip_while(|w| *w != "-o").nth(1) else {
            failures.push(format!("`{line}` writes no `-o FILE`"));
            continue;
        };
        checked += 1;
        match (pixels(&dir.join(made)), pixels(&root.join(picture))) {
            (Ok(a), Ok(b)) if a == b => (),
            (Ok(_), Ok(_)) => failures.push(format!(
                "`{}` does not reproduce {picture}: the pixels differ (remake the picture with it)",
                line.split("  #").next().unwrap_or(line).trim()
            )),
            (a, b) => failures.push(format!("{:?} {:?}", a.err(), b.err())),
        }
    }
    if checked == 0 {
        failures.push("no README command makes \"the picture above\"".to_string());
    }
    failures
}
