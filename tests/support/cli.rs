//! `lucent` run from the command-line tests (`crate::support::cli`): the real binary as a child
//! process, or `lucent::cli::run` in-process (faster, and it needs no binary).

use std::io::Write;
use std::process::{Command, Stdio};

/// Runs the `lucent` binary with `args` and `stdin`: exit code (-1 when killed by a signal),
/// stdout, stderr.
pub fn lucent_binary(args: &[&str], stdin: &str) -> (i32, String, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_lucent"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the lucent binary runs");
    let mut pipe = child.stdin.take().unwrap();
    pipe.write_all(stdin.as_bytes()).unwrap();
    drop(pipe);
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Runs `lucent ARGS` in-process (`lucent::cli::run`) with `stdin` as its input, in the
/// current directory: exit code, stdout, stderr.
pub fn lucent_in_process(args: &[&str], stdin: &str) -> (i32, String, String) {
    let args: Vec<String> = args.iter().map(|s| s.to_string()).collect();
    let mut out = Vec::new();
    let mut err = Vec::new();
    let code = lucent::cli::run(&args, &mut stdin.as_bytes(), &mut out, &mut err);
    (
        code,
        String::from_utf8(out).unwrap(),
        String::from_utf8(err).unwrap(),
    )
}
