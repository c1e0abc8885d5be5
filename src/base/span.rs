//! Byte spans into source files.
//!
//! Invariant: `start <= end <= len(file)`, both byte offsets on UTF-8 boundaries of the file's
//! text (the lexer only cuts at character boundaries). Offsets are `u32`: the command line refuses
//! inputs of 4 GiB or more with a diagnostic rather than truncating.

/// Index of a file in a [`crate::base::SourceMap`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct FileId(pub u32);

/// A half-open byte range `[start, end)` in one file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Span {
    /// The file the range lies in.
    pub file: FileId,
    /// First byte of the range.
    pub start: u32,
    /// One past the last byte of the range.
    pub end: u32,
}

impl Span {
    /// A span in `file` from `start` to `end`.
    pub fn new(file: FileId, start: u32, end: u32) -> Span {
        debug_assert!(start <= end, "span start {start} after end {end}");
        Span { file, start, end }
    }

    /// The smallest span covering both `self` and `other` (same file).
    pub fn to(self, other: Span) -> Span {
        Span {
            file: self.file,
            start: self.start.min(other.start),
            end: self.end.max(other.end),
        }
    }

    /// Length in bytes.
    pub fn len(self) -> u32 {
        self.end - self.start
    }

    /// True when the span covers no byte.
    pub fn is_empty(self) -> bool {
        self.start == self.end
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn join_covers_both() {
        let a = Span::new(FileId(0), 3, 5);
        let b = Span::new(FileId(0), 1, 4);
        assert_eq!(a.to(b), Span::new(FileId(0), 1, 5));
        assert_eq!(a.len(), 2);
        assert!(!a.is_empty());
    }
}
