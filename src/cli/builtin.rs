//! The domain files built into the binary: `lucent learn`, `experiment`, `demo`, `run`,
//! `explain` and `plan` work from any directory after `cargo install`, where the checkout's
//! `domains/` is not at hand.
//!
//! Invariants: a file on disk always wins; a built-in file is used only when reading the path
//! fails with "not found" and the path, with `.` and `..` resolved, ends with a built-in file's
//! name (`domains/ra/scenes/h1.ald`, or `/anywhere/domains/ra/kb_full.ald` reached through an
//! include). Includes inside a built-in file resolve against its built-in name, so a scene's
//! `include "../kb_full.ald"` finds the built-in KB.

use std::path::{Component, Path, PathBuf};

/// The built-in files, by their path in the repository.
const FILES: &[(&str, &str)] = &[
    (
        "domains/ra/kb_full.ald",
        include_str!("../../domains/ra/kb_full.ald"),
    ),
    (
        "domains/ra/scenes/h1.ald",
        include_str!("../../domains/ra/scenes/h1.ald"),
    ),
    (
        "domains/ra/scenes/tabletop_task.ald",
        include_str!("../../domains/ra/scenes/tabletop_task.ald"),
    ),
    (
        "domains/ra/scenes/execution_example.ald",
        include_str!("../../domains/ra/scenes/execution_example.ald"),
    ),
    (
        "domains/ra/scenes/exception_goal.ald",
        include_str!("../../domains/ra/scenes/exception_goal.ald"),
    ),
];

/// `path` with `.` and `..` resolved lexically.
fn lexical(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => {
                if !out.pop() {
                    out.push("..");
                }
            }
            other => out.push(other.as_os_str()),
        }
    }
    out
}

/// The built-in file whose name `path` ends with, if any.
pub fn builtin(path: &Path) -> Option<&'static str> {
    let path = lexical(path);
    FILES
        .iter()
        .find(|(name, _)| path.ends_with(name))
        .map(|(_, text)| *text)
}

/// Reads a file, falling back to the built-in file of that name when it is not on disk.
pub fn read_to_string(path: impl AsRef<Path>) -> std::io::Result<String> {
    let path = path.as_ref();
    match std::fs::read_to_string(path) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            builtin(path).map(str::to_string).ok_or(e)
        }
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_resolve_through_includes() {
        assert!(builtin(Path::new("domains/ra/scenes/h1.ald")).is_some());
        assert!(builtin(Path::new("/x/domains/ra/scenes/../kb_full.ald")).is_some());
        assert!(builtin(Path::new("/x/ra/kb_full.ald")).is_none());
        assert!(builtin(Path::new("domains/ra/scenes/nothing.ald")).is_none());
    }
}
