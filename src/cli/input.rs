//! Reading the inputs named on the command line into a [`SourceMap`].
//!
//! Invariants: a file that cannot be read is a diagnostic (`<cmd>: error: file could not be
//! opened`), never a panic; invalid UTF-8 is reported with the position of the first bad byte and
//! the text is decoded lossily so that parsing can still report further problems; inputs of
//! 4 GiB or more are refused, since spans are `u32` byte offsets.

use std::io::Read;

use crate::base::{Diagnostic, SourceMap, Span};

/// The largest input Lucent accepts, in bytes.
pub const MAX_INPUT: usize = u32::MAX as usize - 1;

/// One input after reading.
#[derive(Debug, Clone)]
pub struct LoadedInput {
    /// Id in the source map.
    pub file: crate::base::FileId,
    /// The name given on the command line (`-` for standard input).
    pub name: String,
}

/// Reads every file of `names` (standard input for `-` or when `names` is empty) into
/// `sources`. Returns the loaded inputs and the diagnostics of inputs that failed.
pub fn load(
    names: &[String],
    stdin: &mut dyn Read,
    sources: &mut SourceMap,
) -> (Vec<LoadedInput>, Vec<Diagnostic>) {
    let stdin_name = ["-".to_string()];
    let names: &[String] = if names.is_empty() { &stdin_name } else { names };
    let mut loaded = Vec::new();
    let mut diagnostics = Vec::new();
    let mut stdin_read = false;
    for name in names {
        let bytes = if name == "-" {
            if stdin_read {
                continue;
            }
            stdin_read = true;
            let mut buf = Vec::new();
            stdin.read_to_end(&mut buf).map(|_| buf)
        } else {
            std::fs::read(name)
        };
        match bytes {
            Ok(bytes) => {
                let (file, diag) = add_bytes(sources, name, bytes);
                diagnostics.extend(diag);
                loaded.push(LoadedInput {
                    file,
                    name: name.clone(),
                });
            }
            Err(_) => {
                let cmd = sources.add("<cmd>", "");
                diagnostics.push(
                    Diagnostic::error(Span::new(cmd, 0, 0), "file could not be opened")
                        .with_snippet(name.clone()),
                );
            }
        }
    }
    (loaded, diagnostics)
}

/// Adds `bytes` as a source file named `name`, checking size and encoding.
pub fn add_bytes(
    sources: &mut SourceMap,
    name: &str,
    bytes: Vec<u8>,
) -> (crate::base::FileId, Option<Diagnostic>) {
    if bytes.len() > MAX_INPUT {
        let file = sources.add(name, "");
        let diag = Diagnostic::error(
            Span::new(file, 0, 0),
            format!(
                "input of {} bytes is too large (at most {} bytes are supported)",
                bytes.len(),
                MAX_INPUT
            ),
        );
        return (file, Some(diag));
    }
    // Decoding is the syntax layer's rule (lossy, one error at the first invalid byte); the
    // file gets its id first so the diagnostic can point into it.
    let placeholder = sources.len() as u32;
    let (text, diag) = crate::syntax::decode_source(crate::base::FileId(placeholder), &bytes);
    let file = sources.add(name, text);
    debug_assert_eq!(file.0, placeholder);
    (file, diag)
}

/// True when the file `name` starts with aspif's header
/// ([`crate::ground::aspif::is_aspif`]); false when it cannot be read (the text pipeline then
/// reports it).
pub fn file_is_aspif(name: &str) -> bool {
    let mut head = Vec::with_capacity(256);
    match std::fs::File::open(name) {
        Ok(f) => {
            f.take(256).read_to_end(&mut head).is_ok() && crate::ground::aspif::is_aspif(&head)
        }
        Err(_) => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn missing_file_is_a_diagnostic() {
        let mut sources = SourceMap::new();
        let (loaded, diags) = load(
            &["/nonexistent/x.lp".to_string()],
            &mut std::io::empty(),
            &mut sources,
        );
        assert!(loaded.is_empty());
        assert_eq!(
            diags[0].render(&sources),
            "<cmd>: error: file could not be opened:\n  /nonexistent/x.lp\n\n"
        );
    }

    #[test]
    fn invalid_utf8_points_at_first_bad_byte() {
        let mut sources = SourceMap::new();
        let (file, diag) = add_bytes(&mut sources, "-", b"a.\nb\xff.".to_vec());
        let diag = diag.expect("a diagnostic");
        assert_eq!(sources.location(diag.span), "-:2:2-5");
        assert_eq!(sources.get(file).text, "a.\nb\u{fffd}.");
    }

    #[test]
    fn stdin_is_read_once() {
        let mut sources = SourceMap::new();
        let mut input: &[u8] = b"a.";
        let names = vec!["-".to_string(), "-".to_string()];
        let (loaded, diags) = load(&names, &mut input, &mut sources);
        assert_eq!(loaded.len(), 1);
        assert!(diags.is_empty());
    }
}
