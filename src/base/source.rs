//! Source files held in memory, with line tables for turning spans into `line:column`.
//!
//! Invariant: `line_starts[0] == 0` and the table is strictly increasing; columns are 1-based
//! byte columns, as gringo prints them. The table is built from the text on first use (only
//! diagnostics need it: a call that parses and grounds without a message never does), so a
//! file's `text` is not changed after the file is made.

use super::span::{FileId, Span};

/// One input: its display name (`-` for standard input) and its text.
#[derive(Debug, Clone)]
pub struct SourceFile {
    /// Name shown in diagnostics.
    pub name: String,
    /// The full text.
    pub text: String,
    /// Byte offset of the first character of every line, built on first use.
    line_starts: std::sync::OnceLock<Vec<u32>>,
}

impl SourceFile {
    /// The file `name` with text `text` (its line table is built when first needed).
    pub fn new(name: impl Into<String>, text: impl Into<String>) -> SourceFile {
        SourceFile {
            name: name.into(),
            text: text.into(),
            line_starts: std::sync::OnceLock::new(),
        }
    }

    /// The line table: the byte offset of the first character of every line.
    fn line_starts(&self) -> &[u32] {
        self.line_starts.get_or_init(|| {
            let mut starts = vec![0u32];
            for (i, b) in self.text.bytes().enumerate() {
                if b == b'\n' {
                    starts.push((i + 1) as u32);
                }
            }
            starts
        })
    }

    /// 1-based line and 1-based byte column of a byte offset.
    pub fn line_col(&self, offset: u32) -> (u32, u32) {
        let line_starts = self.line_starts();
        let line = match line_starts.binary_search(&offset) {
            Ok(i) => i,
            Err(i) => i - 1,
        };
        (line as u32 + 1, offset - line_starts[line] + 1)
    }

    /// The text covered by `span`, clipped to the file.
    pub fn slice(&self, span: Span) -> &str {
        let len = self.text.len();
        let s = (span.start as usize).min(len);
        let e = (span.end as usize).min(len).max(s);
        self.text.get(s..e).unwrap_or("")
    }
}

/// All files of one run, addressed by [`FileId`].
#[derive(Debug, Default, Clone)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

impl SourceMap {
    /// An empty map.
    pub fn new() -> SourceMap {
        SourceMap::default()
    }

    /// Adds a file and returns its id.
    pub fn add(&mut self, name: impl Into<String>, text: impl Into<String>) -> FileId {
        self.files.push(SourceFile::new(name, text));
        FileId(self.files.len() as u32 - 1)
    }

    /// The file with id `id`.
    pub fn get(&self, id: FileId) -> &SourceFile {
        &self.files[id.0 as usize]
    }

    /// Number of files.
    pub fn len(&self) -> usize {
        self.files.len()
    }

    /// True when no file was added.
    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// gringo's location format: `file:line:col-col`, or `file:line:col-line:col` across lines.
    pub fn location(&self, span: Span) -> String {
        let file = self.get(span.file);
        if file.name.starts_with('<') && file.text.is_empty() {
            // A pseudo file such as `<cmd>` (the command line) has no positions.
            return file.name.clone();
        }
        let (l1, c1) = file.line_col(span.start);
        let (l2, c2) = file.line_col(span.end.max(span.start));
        if l1 == l2 {
            let c2 = if c2 == c1 { c1 + 1 } else { c2 };
            format!("{}:{}:{}-{}", file.name, l1, c1, c2)
        } else {
            format!("{}:{}:{}-{}:{}", file.name, l1, c1, l2, c2)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_columns() {
        let mut map = SourceMap::new();
        let f = map.add("-", "a.\nbc(X).\n");
        assert_eq!(map.location(Span::new(f, 0, 2)), "-:1:1-3");
        assert_eq!(map.location(Span::new(f, 6, 7)), "-:2:4-5");
        assert_eq!(map.location(Span::new(f, 1, 5)), "-:1:2-2:3");
        // An empty span is shown one column wide, as gringo does for end of file.
        assert_eq!(map.location(Span::new(f, 10, 10)), "-:3:1-2");
    }
}
