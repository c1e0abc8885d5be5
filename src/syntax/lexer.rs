//! The lexer: bytes of one source file to tokens with byte spans, on demand.
//!
//! Role: a hand-written, byte-based scanner for the clingo dialect and for SPARC. It never fails:
//! a character that cannot start a token is reported as gringo reports it (`lexer error,
//! unexpected X`) and skipped, so the parser sees the rest of the input.
//!
//! Invariants:
//! - Every token's `start..end` lies inside the text and on UTF-8 character boundaries (the
//!   lexer only cuts after ASCII bytes or after whole characters).
//! - Each call of [`Lexer::next_token`] either returns [`TokenKind::Eof`] or advances the
//!   position by at least one byte, so a loop over tokens always terminates.
//! - Comments are `%` to the end of the line and `%* ... *%` blocks, which nest as in gringo.
//!   SPARC files have only line comments (a SPARC line such as `%****` is a line comment).
//! - The lexer keeps no state beyond its position and its mode, so the parser can save and
//!   restore it. In theory mode (inside theory atoms and `#theory` definitions, set by the
//!   parser) a run of the characters `/!<=>+-*\\?&@|:;~^.` is one [`TokenKind::TheoryOp`],
//!   as in gringo, unless the run is exactly `.`, `:`, `;` or `:-`.

use crate::base::{Diagnostic, FileId, Span};

use super::ast::Dialect;

/// The kinds of tokens.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TokenKind {
    /// A lower-case identifier, possibly with leading underscores: `p`, `_q`.
    Ident,
    /// A variable: upper-case first letter after optional underscores: `X`, `_Y`.
    Variable,
    /// The anonymous variable `_`.
    Anonymous,
    /// A decimal, hexadecimal (`0x`), octal (`0o`) or binary (`0b`) integer.
    Number,
    /// A string literal with its quotes; escapes are checked by the lexer.
    String,
    /// A `#name` directive or SPARC sort name; `#sum+` is [`TokenKind::SumPlus`].
    Hash,
    /// `#sum+`
    SumPlus,
    /// The keyword `not`.
    Not,
    /// `.`
    Dot,
    /// `..`
    Dots,
    /// `,`
    Comma,
    /// `;`
    Semi,
    /// `:`
    Colon,
    /// `:-`
    If,
    /// `:~`
    WeakIf,
    /// `:+`
    CrIf,
    /// `|`
    Bar,
    /// `(`
    LParen,
    /// `)`
    RParen,
    /// `{`
    LBrace,
    /// `}`
    RBrace,
    /// `[`
    LBrack,
    /// `]`
    RBrack,
    /// `=` or `==`
    Eq,
    /// `!=` or `<>`
    Ne,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
    /// `+`
    Plus,
    /// `-`
    Minus,
    /// `*`
    Star,
    /// `**`
    Pow,
    /// `/`
    Slash,
    /// `\`
    Backslash,
    /// `&`
    Amp,
    /// `?`
    Question,
    /// `^`
    Caret,
    /// `~`
    Tilde,
    /// `@`
    At,
    /// A theory operator (theory mode only): a run of `/!<=>+-*\\?&@|:;~^.`.
    TheoryOp,
    /// End of input.
    Eof,
}

/// A token: its kind and the byte range it covers ([`Token::start`], [`Token::end`]).
///
/// Two fields, the range packed in one word, so that the lexer returns a token in two
/// registers and the parser moves it as two scalars: as three fields it was returned through
/// memory and copied with mismatched widths, and the next wide read stalled on store
/// forwarding (a tenth of the parser's cycles in the learner-loop benchmark, `perf annotate`).
#[derive(Clone, Copy, PartialEq, Eq)]
pub struct Token {
    /// What the token is.
    pub kind: TokenKind,
    /// First byte in the low 32 bits, one past the last byte in the high 32 bits.
    range: u64,
}

impl Token {
    /// A token of `kind` over bytes `start..end`.
    #[inline]
    pub fn new(kind: TokenKind, start: u32, end: u32) -> Token {
        Token {
            kind,
            range: start as u64 | (end as u64) << 32,
        }
    }

    /// First byte.
    #[inline]
    pub fn start(self) -> u32 {
        self.range as u32
    }

    /// One past the last byte.
    #[inline]
    pub fn end(self) -> u32 {
        (self.range >> 32) as u32
    }
}

impl std::fmt::Debug for Token {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Token")
            .field("kind", &self.kind)
            .field("start", &self.start())
            .field("end", &self.end())
            .finish()
    }
}

/// The on-demand scanner over one file's text.
#[derive(Clone, Debug)]
pub struct Lexer<'a> {
    /// The text as bytes.
    bytes: &'a [u8],
    /// The text, for slicing character boundaries.
    text: &'a str,
    /// The file spans point into.
    file: FileId,
    /// Whether block comments exist (clingo) or not (SPARC).
    block_comments: bool,
    /// Whether unknown `#name` directives are errors (clingo) or sort names (SPARC).
    sparc: bool,
    /// Current byte offset.
    pos: usize,
    /// Theory mode: operator runs are [`TokenKind::TheoryOp`] tokens.
    theory: bool,
}

/// Directive names the clingo dialect knows (without `#`).
const DIRECTIVES: &[&str] = &[
    "count",
    "sum",
    "min",
    "max",
    "minimize",
    "maximize",
    "minimise",
    "maximise",
    "show",
    "defined",
    "project",
    "const",
    "external",
    "heuristic",
    "edge",
    "include",
    "program",
    "script",
    "end",
    "inf",
    "sup",
    "infimum",
    "supremum",
    "true",
    "false",
    "theory",
];

/// `IDENT[b]` is true for the bytes that may continue an identifier or variable (ASCII
/// letters and digits, `_` and `'`): one table load per byte in the hot scanning loops.
static IDENT: [bool; 256] = {
    let mut t = [false; 256];
    let mut b = 0;
    while b < 256 {
        let c = b as u8;
        t[b] = c.is_ascii_alphanumeric() || c == b'_' || c == b'\'';
        b += 1;
    }
    t
};

/// Byte classes of [`Lexer::next_token`]'s fast path: whitespace, a lower-case letter, an
/// upper-case letter, a digit `1`-`9`; anything else is `C_OTHER` (punctuation, or `_`, `0`,
/// `"`, `#`, `%` and other bytes, which go to the slow path).
const C_OTHER: u8 = 0;
/// ASCII whitespace (what `u8::is_ascii_whitespace` accepts).
const C_SPACE: u8 = 1;
/// `a`-`z`.
const C_LOWER: u8 = 2;
/// `A`-`Z`.
const C_UPPER: u8 = 3;
/// `1`-`9` (a `0` may start a hexadecimal, octal or binary number: slow path).
const C_DIGIT: u8 = 4;

/// `CLASS[b]` is the class of byte `b` (see `C_OTHER`).
static CLASS: [u8; 256] = {
    let mut t = [C_OTHER; 256];
    let mut b = 0;
    while b < 256 {
        let c = b as u8;
        t[b] = if c.is_ascii_whitespace() {
            C_SPACE
        } else if c.is_ascii_lowercase() {
            C_LOWER
        } else if c.is_ascii_uppercase() {
            C_UPPER
        } else if c >= b'1' && c <= b'9' {
            C_DIGIT
        } else {
            C_OTHER
        };
        b += 1;
    }
    t
};

/// True for bytes that may continue an identifier or variable.
#[inline]
fn is_ident_byte(b: u8) -> bool {
    IDENT[b as usize]
}

impl<'a> Lexer<'a> {
    /// A lexer at the start of `text`.
    pub fn new(file: FileId, text: &'a str, dialect: Dialect) -> Lexer<'a> {
        Lexer {
            bytes: text.as_bytes(),
            text,
            file,
            block_comments: dialect == Dialect::Clingo,
            sparc: dialect == Dialect::Sparc,
            pos: 0,
            theory: false,
        }
    }

    /// Whether the lexer is in theory mode.
    pub fn is_theory(&self) -> bool {
        self.theory
    }

    /// Switches theory mode on or off (see the module documentation).
    pub fn set_theory(&mut self, on: bool) {
        self.theory = on;
    }

    /// The current byte offset.
    pub fn pos(&self) -> usize {
        self.pos
    }

    /// Moves to byte offset `pos`, which must be a character boundary of the text.
    pub fn set_pos(&mut self, pos: usize) {
        debug_assert!(self.text.is_char_boundary(pos));
        self.pos = pos;
    }

    /// A span in this lexer's file.
    fn span(&self, start: usize, end: usize) -> Span {
        Span::new(self.file, start as u32, end as u32)
    }

    /// Reports `lexer error, unexpected <what>` at `start..end`.
    #[cold]
    #[inline(never)]
    fn error(&self, diags: &mut Vec<Diagnostic>, start: usize, end: usize, what: &str) {
        diags.push(Diagnostic::error(
            self.span(start, end),
            format!("lexer error, unexpected {what}"),
        ));
    }

    /// Skips whitespace and comments; reports an unterminated block comment.
    #[inline]
    fn skip_trivia(&mut self, diags: &mut Vec<Diagnostic>) {
        let bytes = self.bytes;
        let mut pos = self.pos;
        while pos < bytes.len() && bytes[pos].is_ascii_whitespace() {
            pos += 1;
        }
        self.pos = pos;
        if pos < bytes.len() && bytes[pos] == b'%' {
            self.skip_comments(diags);
        }
    }

    /// Skips comments and the whitespace between them, from a `%`.
    #[inline(never)]
    fn skip_comments(&mut self, diags: &mut Vec<Diagnostic>) {
        let bytes = self.bytes;
        loop {
            while self.pos < bytes.len() && bytes[self.pos].is_ascii_whitespace() {
                self.pos += 1;
            }
            if self.pos >= bytes.len() || bytes[self.pos] != b'%' {
                return;
            }
            if self.block_comments && bytes.get(self.pos + 1) == Some(&b'*') {
                // A block comment `%* ... *%`; gringo nests them.
                let mut depth = 1usize;
                self.pos += 2;
                while depth > 0 {
                    if self.pos >= bytes.len() {
                        self.error(diags, bytes.len(), bytes.len(), "<EOF>");
                        return;
                    }
                    match bytes[self.pos] {
                        b'%' if bytes.get(self.pos + 1) == Some(&b'*') => {
                            depth += 1;
                            self.pos += 2;
                        }
                        b'*' if bytes.get(self.pos + 1) == Some(&b'%') => {
                            depth -= 1;
                            self.pos += 2;
                        }
                        _ => self.pos += 1,
                    }
                }
            } else {
                match memchr_newline(&bytes[self.pos..]) {
                    Some(i) => self.pos += i + 1,
                    None => self.pos = bytes.len(),
                }
            }
        }
    }

    /// The next token; reports and skips characters that start no token.
    ///
    /// The fast path reads the common tokens (names, variables, decimal numbers other than
    /// `0...`, punctuation) after plain whitespace with one class-table load per byte and calls
    /// nothing, so it saves no registers; anything else (comments, strings, `#` names, `_`,
    /// `0x...`, bad characters, the end of the input) goes to `Lexer::next_token_slow`.
    pub fn next_token(&mut self, diags: &mut Vec<Diagnostic>) -> Token {
        use TokenKind as T;
        let bytes = self.bytes;
        let mut pos = self.pos;
        while pos < bytes.len() && CLASS[bytes[pos] as usize] == C_SPACE {
            pos += 1;
        }
        self.pos = pos;
        if pos >= bytes.len() || self.theory {
            return self.next_token_slow(diags);
        }
        let b = bytes[pos];
        let next = if pos + 1 < bytes.len() {
            bytes[pos + 1]
        } else {
            0
        };
        let (kind, end) = match CLASS[b as usize] {
            C_LOWER => {
                let end = self.ident_end(pos + 1);
                let kind = if end == pos + 3 && b == b'n' && next == b'o' && bytes[pos + 2] == b't'
                {
                    T::Not
                } else {
                    T::Ident
                };
                (kind, end)
            }
            C_UPPER => (T::Variable, self.ident_end(pos + 1)),
            C_DIGIT => {
                let mut i = pos + 1;
                while i < bytes.len() && bytes[i].is_ascii_digit() {
                    i += 1;
                }
                (T::Number, i)
            }
            _ => match punct(b, next) {
                Some((kind, len)) => (kind, pos + len),
                None => return self.next_token_slow(diags),
            },
        };
        self.pos = end;
        Token::new(kind, pos as u32, end as u32)
    }

    /// The next token from any position: skips comments, scans every kind of token, and
    /// reports and skips characters that start no token.
    #[inline(never)]
    fn next_token_slow(&mut self, diags: &mut Vec<Diagnostic>) -> Token {
        loop {
            self.skip_trivia(diags);
            let start = self.pos;
            if start >= self.bytes.len() {
                return Token::new(TokenKind::Eof, start as u32, start as u32);
            }
            if let Some(kind) = self.scan(diags) {
                debug_assert!(self.pos > start, "the lexer made no progress");
                return Token::new(kind, start as u32, self.pos as u32);
            }
            debug_assert!(self.pos > start, "the lexer made no progress");
        }
    }

    /// Scans one token starting at `self.pos` (not whitespace, not EOF). Returns `None` after
    /// reporting and skipping an unexpected character.
    fn scan(&mut self, diags: &mut Vec<Diagnostic>) -> Option<TokenKind> {
        use TokenKind as T;
        let bytes = self.bytes;
        let start = self.pos;
        let b = bytes[start];
        let next = bytes.get(start + 1).copied().unwrap_or(0);
        if self.theory && is_theory_op_byte(b) {
            let mut end = start + 1;
            while end < bytes.len() && is_theory_op_byte(bytes[end]) {
                end += 1;
            }
            if !matches!(&self.text[start..end], "." | ":" | ";" | ":-") {
                self.pos = end;
                return Some(T::TheoryOp);
            }
        }
        let (kind, len) = match b {
            b'a'..=b'z' => {
                let end = self.ident_end(start + 1);
                self.pos = end;
                if b == b'n' && end == start + 3 && next == b'o' && bytes[start + 2] == b't' {
                    return Some(T::Not);
                }
                return Some(T::Ident);
            }
            b'A'..=b'Z' => {
                self.pos = self.ident_end(start + 1);
                return Some(T::Variable);
            }
            b'_' => {
                let mut i = start;
                while i < bytes.len() && bytes[i] == b'_' {
                    i += 1;
                }
                return match bytes.get(i) {
                    Some(b'a'..=b'z') => {
                        self.pos = self.ident_end(i + 1);
                        Some(T::Ident)
                    }
                    Some(b'A'..=b'Z') => {
                        self.pos = self.ident_end(i + 1);
                        Some(T::Variable)
                    }
                    _ if i == start + 1 => {
                        self.pos = i;
                        Some(T::Anonymous)
                    }
                    _ => {
                        // `__` followed by no letter: gringo reads `_` tokens one by one.
                        self.pos = start + 1;
                        Some(T::Anonymous)
                    }
                };
            }
            b'0'..=b'9' => {
                self.pos = self.number_end(start);
                return Some(T::Number);
            }
            b'"' => return self.string(diags),
            b'#' => return self.hash(diags),
            _ => match punct(b, next) {
                Some(token) => token,
                None => {
                    self.unexpected_char(diags);
                    return None;
                }
            },
        };
        self.pos = start + len;
        Some(kind)
    }

    /// Reports and skips the character at the position, which starts no token: it is skipped
    /// whole, so spans stay on char boundaries.
    #[cold]
    #[inline(never)]
    fn unexpected_char(&mut self, diags: &mut Vec<Diagnostic>) {
        let start = self.pos;
        let ch = self.text[start..].chars().next().unwrap_or('\u{fffd}');
        let end = start + ch.len_utf8();
        let shown = if ch.is_control() {
            format!("\\x{:02x}", ch as u32)
        } else {
            ch.to_string()
        };
        self.error(diags, start, end, &shown);
        self.pos = end;
    }

    /// The end of an identifier whose remaining characters start at `i`.
    #[inline]
    fn ident_end(&self, mut i: usize) -> usize {
        let bytes = self.bytes;
        while i < bytes.len() && is_ident_byte(bytes[i]) {
            i += 1;
        }
        i
    }

    /// The end of a number starting at `start`.
    fn number_end(&self, start: usize) -> usize {
        let bytes = self.bytes;
        if bytes[start] == b'0' {
            let radix_digit: Option<fn(u8) -> bool> = match bytes.get(start + 1) {
                Some(b'x') | Some(b'X') => Some(|c: u8| c.is_ascii_hexdigit()),
                Some(b'o') | Some(b'O') => Some(|c: u8| (b'0'..=b'7').contains(&c)),
                Some(b'b') | Some(b'B') => Some(|c: u8| c == b'0' || c == b'1'),
                _ => None,
            };
            if let Some(is_digit) = radix_digit {
                let mut i = start + 2;
                while i < bytes.len() && is_digit(bytes[i]) {
                    i += 1;
                }
                if i > start + 2 {
                    return i;
                }
            }
            return start + 1;
        }
        let mut i = start + 1;
        while i < bytes.len() && bytes[i].is_ascii_digit() {
            i += 1;
        }
        i
    }

    /// Scans a string literal. An unterminated string or a bad escape is a lexer error at the
    /// opening quote (as gringo reports it); the quote is skipped and lexing resumes after it.
    #[inline(never)]
    fn string(&mut self, diags: &mut Vec<Diagnostic>) -> Option<TokenKind> {
        let bytes = self.bytes;
        let start = self.pos;
        let mut i = start + 1;
        while i < bytes.len() {
            match bytes[i] {
                b'"' => {
                    self.pos = i + 1;
                    return Some(TokenKind::String);
                }
                b'\\' => match bytes.get(i + 1) {
                    Some(b'"') | Some(b'\\') | Some(b'n') => i += 2,
                    _ => break,
                },
                b'\n' => break,
                _ => i += 1,
            }
        }
        self.error(diags, start, start + 1, "\"");
        self.pos = start + 1;
        None
    }

    /// Scans `#name` (and `#sum+`). In the clingo dialect an unknown name is a lexer error and
    /// is skipped; in SPARC it is a sort name.
    #[inline(never)]
    fn hash(&mut self, diags: &mut Vec<Diagnostic>) -> Option<TokenKind> {
        let bytes = self.bytes;
        let start = self.pos;
        let name_start = start + 1;
        let mut i = name_start;
        while i < bytes.len() && bytes[i] == b'_' {
            i += 1;
        }
        if i < bytes.len() && bytes[i].is_ascii_alphabetic() {
            i = self.ident_end(i + 1);
        } else {
            self.error(diags, start, start + 1, "#");
            self.pos = start + 1;
            return None;
        }
        let name = &self.text[name_start..i];
        if name == "sum" && bytes.get(i) == Some(&b'+') {
            self.pos = i + 1;
            return Some(TokenKind::SumPlus);
        }
        self.pos = i;
        if !self.sparc && !DIRECTIVES.contains(&name) {
            self.error(diags, start, i, &self.text[start..i]);
            return None;
        }
        Some(TokenKind::Hash)
    }

    /// Scans the body of a `#script (lang)` block: everything up to the next `#end`, which must
    /// be followed by `.`. Returns the code and leaves the position after `#end.`; returns
    /// `None` (position at the end of input) when no `#end.` follows.
    pub fn script_body(&mut self) -> Option<(usize, usize)> {
        let start = self.pos;
        let hay = &self.bytes[start..];
        let mut from = 0;
        while let Some(i) = find(&hay[from..], b"#end") {
            let at = from + i;
            let mut j = start + at + 4;
            let after = self.bytes.get(j).copied();
            if after.is_some_and(is_ident_byte) {
                from = at + 4;
                continue;
            }
            while j < self.bytes.len() && self.bytes[j].is_ascii_whitespace() {
                j += 1;
            }
            if self.bytes.get(j) == Some(&b'.') {
                self.pos = j + 1;
                return Some((start, start + at));
            }
            from = at + 4;
        }
        self.pos = self.bytes.len();
        None
    }
}

/// The operator or punctuation token that byte `b` starts when `next` follows it (0 at the end
/// of the input), with its length; `None` when `b` starts no such token.
#[inline(always)]
fn punct(b: u8, next: u8) -> Option<(TokenKind, usize)> {
    use TokenKind as T;
    Some(match b {
        b'.' if next == b'.' => (T::Dots, 2),
        b'.' => (T::Dot, 1),
        b',' => (T::Comma, 1),
        b';' => (T::Semi, 1),
        b':' => match next {
            b'-' => (T::If, 2),
            b'~' => (T::WeakIf, 2),
            b'+' => (T::CrIf, 2),
            _ => (T::Colon, 1),
        },
        b'|' => (T::Bar, 1),
        b'(' => (T::LParen, 1),
        b')' => (T::RParen, 1),
        b'{' => (T::LBrace, 1),
        b'}' => (T::RBrace, 1),
        b'[' => (T::LBrack, 1),
        b']' => (T::RBrack, 1),
        b'=' if next == b'=' => (T::Eq, 2),
        b'=' => (T::Eq, 1),
        b'!' if next == b'=' => (T::Ne, 2),
        b'<' => match next {
            b'=' => (T::Le, 2),
            b'>' => (T::Ne, 2),
            _ => (T::Lt, 1),
        },
        b'>' if next == b'=' => (T::Ge, 2),
        b'>' => (T::Gt, 1),
        b'+' => (T::Plus, 1),
        b'-' => (T::Minus, 1),
        b'*' if next == b'*' => (T::Pow, 2),
        b'*' => (T::Star, 1),
        b'/' => (T::Slash, 1),
        b'\\' => (T::Backslash, 1),
        b'&' => (T::Amp, 1),
        b'?' => (T::Question, 1),
        b'^' => (T::Caret, 1),
        b'~' => (T::Tilde, 1),
        b'@' => (T::At, 1),
        // `!` without `=` and every other byte.
        _ => return None,
    })
}

/// Whether `b` may be part of a theory operator.
fn is_theory_op_byte(b: u8) -> bool {
    matches!(
        b,
        b'/' | b'!'
            | b'<'
            | b'='
            | b'>'
            | b'+'
            | b'-'
            | b'*'
            | b'\\'
            | b'?'
            | b'&'
            | b'@'
            | b'|'
            | b':'
            | b';'
            | b'~'
            | b'^'
            | b'.'
    )
}

/// Position of the first newline in `hay`.
#[inline]
fn memchr_newline(hay: &[u8]) -> Option<usize> {
    hay.iter().position(|&b| b == b'\n')
}

/// Position of the first occurrence of `needle` in `hay`.
fn find(hay: &[u8], needle: &[u8]) -> Option<usize> {
    hay.windows(needle.len()).position(|w| w == needle)
}

/// How gringo names a token in `unexpected ...` messages: quoted literals lose their quotes
/// unless they contain a comma or a backslash, and value tokens have `<NAME>` names.
pub fn describe(kind: TokenKind, text: &str) -> String {
    use TokenKind as T;
    match kind {
        T::Ident => "<IDENTIFIER>".into(),
        T::Variable => "<VARIABLE>".into(),
        T::Anonymous => "<ANONYMOUS>".into(),
        T::Number => "<NUMBER>".into(),
        T::String => "<STRING>".into(),
        T::Eof => "EOF".into(),
        T::Comma => "\",\"".into(),
        T::Backslash => "\"\\\\\"".into(),
        _ => text.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> (Vec<TokenKind>, Vec<Diagnostic>) {
        let mut lexer = Lexer::new(FileId(0), text, Dialect::Clingo);
        let mut diags = Vec::new();
        let mut out = Vec::new();
        loop {
            let t = lexer.next_token(&mut diags);
            if t.kind == TokenKind::Eof {
                return (out, diags);
            }
            out.push(t.kind);
        }
    }

    #[test]
    fn numbers_and_dots() {
        use TokenKind as T;
        let (k, d) = kinds("p(1..2). 0x1F.");
        assert!(d.is_empty());
        assert_eq!(
            k,
            vec![
                T::Ident,
                T::LParen,
                T::Number,
                T::Dots,
                T::Number,
                T::RParen,
                T::Dot,
                T::Number,
                T::Dot
            ]
        );
    }

    #[test]
    fn nested_block_comments() {
        let (k, d) = kinds("a. %* x %* y *% z *% b.");
        assert!(d.is_empty());
        assert_eq!(k.len(), 4);
        let (_, d) = kinds("%* open");
        assert_eq!(d.len(), 1);
        assert_eq!(d[0].message, "lexer error, unexpected <EOF>");
    }

    #[test]
    fn unterminated_string_skips_quote() {
        let (k, d) = kinds("p(\"abc).");
        assert_eq!(d.len(), 1);
        assert_eq!(d[0].span.start, 2);
        assert_eq!(k.len(), 5);
    }

    #[test]
    fn fast_path_agrees_with_slow_path() {
        // Every token the fast path reads, the slow path (the full scanner) reads the same.
        let text = "p(X,Y) :- q(X), not r(Y), X < 10, Y >= 2; a..b. :~ c.[1@2] \\ ** * ! \
                    != <> <= = == | {x} ? ^ ~ & @f / -z+Q. _a _ 0x1f 07 %c\n \"s\" #sum{} not nota";
        for dialect in [Dialect::Clingo, Dialect::Sparc] {
            let mut fast = Lexer::new(FileId(0), text, dialect);
            let mut slow = fast.clone();
            let (mut df, mut ds) = (Vec::new(), Vec::new());
            loop {
                let (a, b) = (fast.next_token(&mut df), slow.next_token_slow(&mut ds));
                assert_eq!(a, b, "at byte {}", a.start());
                assert_eq!(df.len(), ds.len());
                if a.kind == TokenKind::Eof {
                    break;
                }
            }
        }
    }

    #[test]
    fn operators() {
        use TokenKind as T;
        let (k, _) = kinds(":- :~ :+ : <> != == <= ** #sum+ #count not");
        assert_eq!(
            k,
            vec![
                T::If,
                T::WeakIf,
                T::CrIf,
                T::Colon,
                T::Ne,
                T::Ne,
                T::Eq,
                T::Le,
                T::Pow,
                T::SumPlus,
                T::Hash,
                T::Not
            ]
        );
    }
}
