//! The command line: arguments, clingo-compatible output and exit codes. The only module that
//! does I/O.

#[cfg(feature = "sim")]
pub mod sim;

/// Runs the command line and returns the process exit code.
pub fn main() -> i32 {
    eprintln!("lucent: not built yet");
    128
}
