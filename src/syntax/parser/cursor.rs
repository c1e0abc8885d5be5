//! The cursor both parsers stand on: the token stream of one file with one token of lookahead,
//! positions and spans, gringo-worded errors, the nesting cap, and (in `terms.rs`) the term
//! grammar. The clingo/SPARC parser ([`super::Parser`]) holds a cursor and dereferences to it;
//! the AL_d parser ([`crate::action::parser`]) reads its statements with methods of its own on
//! the cursor. Neither has another token stream or term parser.
//!
//! Invariants:
//! - Tokens are produced on demand; lexer diagnostics go to [`Cursor::diags`] in the order the
//!   tokens are read, and [`Cursor::bump`] never moves past end of input.
//! - Spans lie inside the text: they are built from token offsets only.
//! - Every error is reported once, as a [`Diagnostic`], before a step returns [`Failed`].
//! - Nesting is capped at the grammar's [`TermGrammar::max_depth`]; [`Cursor::enter`] reports
//!   the first level beyond it.

use crate::base::{Diagnostic, FileId, Span};
use crate::syntax::ast::{CmpOp, Dialect};
use crate::syntax::lexer::{describe, Lexer, Token, TokenKind as T};

/// Marks a statement that failed; its diagnostic has been reported.
pub(crate) struct Failed;

/// Result of a parsing step.
pub(crate) type PResult<X> = Result<X, Failed>;

/// Which terms the cursor reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum TermGrammar {
    /// The clingo dialect's terms (grammar/asp.ebnf): intervals, pools, tuples, strings, bit
    /// operators, `**`, `|t|`, `#inf`/`#sup`, script calls. Integers range over `i64`.
    Clingo,
    /// AL_d's terms (grammar/action.ebnf): numbers, variables, constants and functions under
    /// `+ - * / \` and unary minus, and parentheses. A minus before an integer folds into it,
    /// and integers range over `0..=i32::MAX` as written (out of range reads as 0).
    Arithmetic,
}

impl TermGrammar {
    /// The deepest nesting accepted. AL_d stays lower than clingo's [`super::MAX_DEPTH`]
    /// because its translation nests every term a few levels deeper before it is printed
    /// and parsed again as the clingo dialect.
    pub(crate) fn max_depth(self) -> u32 {
        match self {
            TermGrammar::Clingo => super::MAX_DEPTH,
            TermGrammar::Arithmetic => 200,
        }
    }
}

/// Comparison operator of a token.
pub(crate) fn cmp_op(kind: T) -> Option<CmpOp> {
    Some(match kind {
        T::Eq => CmpOp::Eq,
        T::Ne => CmpOp::Ne,
        T::Lt => CmpOp::Lt,
        T::Le => CmpOp::Le,
        T::Gt => CmpOp::Gt,
        T::Ge => CmpOp::Ge,
        _ => return None,
    })
}

/// gringo's wording of a syntax error at a token of `kind` and text `word`: `syntax error,
/// unexpected X[, expecting a or b]`.
fn unexpected_message(kind: T, word: &str, expecting: &[&str]) -> String {
    let mut msg = format!("syntax error, unexpected {}", describe(kind, word));
    if !expecting.is_empty() {
        msg.push_str(", expecting ");
        msg.push_str(&expecting.join(" or "));
    }
    msg
}

/// The value of a number token's text (decimal, or `0x`, `0o`, `0b` with either case of the
/// letter); `None` when it does not fit an `i64`.
pub(super) fn integer_value(word: &str) -> Option<i64> {
    let (digits, radix) = match word.get(..2) {
        Some("0x") | Some("0X") => (&word[2..], 16),
        Some("0o") | Some("0O") => (&word[2..], 8),
        Some("0b") | Some("0B") => (&word[2..], 2),
        _ => (word, 10),
    };
    i64::from_str_radix(digits, radix).ok()
}

/// The token stream of one file and what reading it has reported.
pub(crate) struct Cursor<'a> {
    /// The token source.
    pub(super) lexer: Lexer<'a>,
    /// The text, for token contents.
    pub(super) text: &'a str,
    /// The file spans point into.
    pub(super) file: FileId,
    /// The current token.
    pub(crate) tok: Token,
    /// The token after the current one, once looked at.
    peeked: Option<Token>,
    /// End of the last consumed token.
    pub(crate) prev_end: u32,
    /// Diagnostics so far (lexer and parser), in source order.
    pub(crate) diags: Vec<Diagnostic>,
    /// Current nesting depth; a parser resets it at each statement.
    pub(crate) depth: u32,
    /// The terms read.
    pub(super) grammar: TermGrammar,
    /// True once the unsupported-script diagnostic was reported.
    script_reported: bool,
}

impl<'a> Cursor<'a> {
    /// A cursor at the first token of `text`, lexed as `dialect`.
    pub(crate) fn new(
        file: FileId,
        text: &'a str,
        dialect: Dialect,
        grammar: TermGrammar,
    ) -> Cursor<'a> {
        let mut lexer = Lexer::new(file, text, dialect);
        let mut diags = Vec::new();
        let tok = lexer.next_token(&mut diags);
        Cursor {
            lexer,
            text,
            file,
            tok,
            peeked: None,
            prev_end: 0,
            diags,
            depth: 0,
            grammar,
            script_reported: false,
        }
    }

    /// The text of a token.
    pub(crate) fn word(&self, tok: Token) -> &'a str {
        &self.text[tok.start() as usize..tok.end() as usize]
    }

    /// The text of the current token.
    pub(crate) fn cur(&self) -> &'a str {
        self.word(self.tok)
    }

    /// A span in this file.
    pub(crate) fn span(&self, start: u32, end: u32) -> Span {
        Span::new(self.file, start, end.max(start))
    }

    /// The span of a token.
    pub(crate) fn span_of(&self, tok: Token) -> Span {
        self.span(tok.start(), tok.end())
    }

    /// The span from `start` to the end of the last consumed token.
    pub(crate) fn span_from(&self, start: u32) -> Span {
        self.span(start, self.prev_end)
    }

    /// Consumes the current token and returns it; at end of input it stays there.
    pub(crate) fn bump(&mut self) -> Token {
        let tok = self.tok;
        self.prev_end = tok.end();
        if tok.kind != T::Eof {
            self.tok = match self.peeked.take() {
                Some(t) => t,
                None => self.lexer.next_token(&mut self.diags),
            };
        }
        tok
    }

    /// The token after the current one.
    pub(crate) fn peek(&mut self) -> Token {
        if let Some(t) = self.peeked {
            return t;
        }
        let t = self.lexer.next_token(&mut self.diags);
        self.peeked = Some(t);
        t
    }

    /// True when the current token is `kind`.
    pub(crate) fn at(&self, kind: T) -> bool {
        self.tok.kind == kind
    }

    /// True when the current token is the identifier `word` (a contextual keyword).
    pub(crate) fn at_word(&self, word: &str) -> bool {
        self.at(T::Ident) && self.cur() == word
    }

    /// Consumes the current token when it is `kind`.
    pub(crate) fn eat(&mut self, kind: T) -> bool {
        if self.at(kind) {
            self.bump();
            true
        } else {
            false
        }
    }

    /// Consumes the current token when it is the identifier `word`.
    pub(crate) fn eat_word(&mut self, word: &str) -> bool {
        if self.at_word(word) {
            self.bump();
            true
        } else {
            false
        }
    }

    /// Reports an error at `span` and returns the failure marker.
    pub(crate) fn error(&mut self, span: Span, msg: impl Into<String>) -> Failed {
        self.diags.push(Diagnostic::error(span, msg));
        Failed
    }

    /// Reports `syntax error, unexpected X[, expecting a or b]` at the current token.
    pub(crate) fn unexpected(&mut self, expecting: &[&str]) -> Failed {
        let msg = unexpected_message(self.tok.kind, self.cur(), expecting);
        self.error(self.span_of(self.tok), msg)
    }

    /// Consumes a token of kind `kind` or reports it missing.
    pub(crate) fn expect(&mut self, kind: T, expecting: &[&str]) -> PResult<Token> {
        if self.at(kind) {
            Ok(self.bump())
        } else {
            Err(self.unexpected(expecting))
        }
    }

    /// Consumes the identifier `word` or reports it missing.
    pub(crate) fn expect_word(&mut self, word: &str) -> PResult<()> {
        if self.eat_word(word) {
            Ok(())
        } else {
            Err(self.unexpected(&[word]))
        }
    }

    /// Skips to just after the next `.` (or to the end of input): where parsing resumes after
    /// a failed statement.
    pub(crate) fn recover(&mut self) {
        while !self.at(T::Eof) {
            if self.bump().kind == T::Dot {
                return;
            }
        }
    }

    /// An `<IDENTIFIER>` token's text, or an error expecting one.
    pub(crate) fn identifier(&mut self) -> PResult<String> {
        let tok = self.expect(T::Ident, &["<IDENTIFIER>"])?;
        Ok(self.word(tok).to_string())
    }

    /// Enters one nesting level; reports when the cap is exceeded.
    pub(crate) fn enter(&mut self) -> PResult<()> {
        self.depth += 1;
        let max = self.grammar.max_depth();
        if self.depth > max {
            let span = self.span_of(self.tok);
            return Err(self.error(
                span,
                format!("syntax error, nesting deeper than {max} levels"),
            ));
        }
        Ok(())
    }

    /// Leaves one nesting level.
    pub(crate) fn leave(&mut self) {
        self.depth -= 1;
    }

    /// Sets the lexer's theory mode and reads the current token again in it (from the end of
    /// the last consumed token; the lexer errors the first reading reported from there are dropped).
    pub(crate) fn relex(&mut self, theory: bool) {
        if self.lexer.is_theory() == theory {
            return;
        }
        self.lexer.set_theory(theory);
        let from = self.prev_end;
        let file = self.file;
        self.diags.retain(|d| {
            d.span.start < from || d.span.file != file || !d.message.starts_with("lexer error")
        });
        self.peeked = None;
        self.lexer.set_pos(from as usize);
        self.tok = self.lexer.next_token(&mut self.diags);
    }

    /// Reports embedded scripts once per file.
    pub(super) fn report_script(&mut self, span: Span) {
        if !self.script_reported {
            self.script_reported = true;
            self.diags
                .push(Diagnostic::error(span, super::UNSUPPORTED_SCRIPT));
        }
    }

    /// After `#script (lang` with `)` current: the raw code up to `#end`, as `(start, end)`
    /// offsets, and the cursor on the token after `#end` (`None` when there is no `#end`; the
    /// cursor is then at end of input).
    pub(super) fn script_body(&mut self) -> Option<(usize, usize)> {
        let code_start = self.tok.end() as usize;
        self.peeked = None;
        self.lexer.set_pos(code_start);
        let found = self.lexer.script_body();
        self.prev_end = self.lexer.pos() as u32;
        self.tok = self.lexer.next_token(&mut self.diags);
        found
    }
}
