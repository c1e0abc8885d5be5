//! The AL_d parser: text of one `.ald` file to a [`Description`] and diagnostics.
//!
//! Role: hand-written recursive descent over the clingo dialect's tokens
//! ([`crate::syntax::lexer`]); AL_d keywords (`causes`, `if`, `impossible`, ...) are identifiers
//! recognised by their text where grammar/action.ebnf expects them.
//!
//! Invariants:
//! - Parsing never fails: a statement that does not parse is reported in gringo's form
//!   (`syntax error, unexpected X, expecting Y`), kept as [`StatementKind::Error`], and parsing
//!   resumes after the next period.
//! - Every loop consumes a token per iteration or stops at end of input; nesting of
//!   parentheses is capped at [`MAX_DEPTH`], so no input makes the parser spin or overflow.
//! - Spans lie inside the text (they come from the lexer's tokens).

use crate::base::{Diagnostic, FileId, Span};
use crate::syntax::ast::{BinaryOp, Dialect, Term, TermKind, UnaryOp};
use crate::syntax::lexer::{Lexer, Token, TokenKind as T};
use crate::syntax::parser::{cmp_op, integer_value, unexpected_message};

use super::ast::*;

/// Deepest nesting of parentheses in terms.
pub const MAX_DEPTH: u32 = 200;

/// A parsed file with its diagnostics.
#[derive(Clone, Debug, Default)]
pub struct Parse {
    /// The statements (failed ones as [`StatementKind::Error`]).
    pub description: Description,
    /// Syntax errors, in source order.
    pub diagnostics: Vec<Diagnostic>,
}

impl Parse {
    /// True when a diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(Diagnostic::is_error)
    }
}

/// Words that start a statement or separate its parts; they cannot name predicates.
pub const KEYWORDS: &[&str] = &[
    "sort",
    "static",
    "inertial",
    "defined",
    "fluent",
    "action",
    "causes",
    "if",
    "impossible",
    "normally",
    "exception",
    "may",
    "never",
    "goal",
    "observed",
    "happened",
    "at",
    "initially",
    "switch",
    "set",
    "profile",
    "include",
];

/// Parses one AL_d file.
pub fn parse(file: FileId, text: &str) -> Parse {
    let mut p = Parser::new(file, text);
    p.description();
    Parse {
        description: Description {
            statements: p.statements,
        },
        diagnostics: p.diags,
    }
}

/// Marker for a reported syntax error.
struct Failed;

type PResult<X> = Result<X, Failed>;

struct Parser<'a> {
    /// The token source.
    lexer: Lexer<'a>,
    /// The text, for token words.
    text: &'a str,
    /// The file spans point into.
    file: FileId,
    /// The current token.
    tok: Token,
    /// End of the previous token (for spans).
    prev_end: u32,
    /// Parenthesis nesting.
    depth: u32,
    /// Collected diagnostics.
    diags: Vec<Diagnostic>,
    /// Parsed statements.
    statements: Vec<Statement>,
}

impl<'a> Parser<'a> {
    fn new(file: FileId, text: &'a str) -> Parser<'a> {
        let mut lexer = Lexer::new(file, text, Dialect::Clingo);
        let mut diags = Vec::new();
        let tok = lexer.next_token(&mut diags);
        Parser {
            lexer,
            text,
            file,
            tok,
            prev_end: 0,
            depth: 0,
            diags,
            statements: Vec::new(),
        }
    }

    fn word_of(&self, tok: Token) -> &'a str {
        &self.text[tok.start as usize..tok.end as usize]
    }

    fn cur(&self) -> &'a str {
        self.word_of(self.tok)
    }

    fn span(&self, start: u32, end: u32) -> Span {
        Span::new(self.file, start, end.max(start))
    }

    fn span_from(&self, start: u32) -> Span {
        self.span(start, self.prev_end)
    }

    fn bump(&mut self) -> Token {
        let tok = self.tok;
        self.prev_end = tok.end;
        if tok.kind != T::Eof {
            self.tok = self.lexer.next_token(&mut self.diags);
        }
        tok
    }

    /// The token after the current one, without consuming anything.
    fn peek(&self) -> Token {
        let mut lexer = self.lexer.clone();
        lexer.next_token(&mut Vec::new())
    }

    fn at(&self, kind: T) -> bool {
        self.tok.kind == kind
    }

    fn at_word(&self, word: &str) -> bool {
        self.tok.kind == T::Ident && self.cur() == word
    }

    fn eat(&mut self, kind: T) -> bool {
        if self.at(kind) {
            self.bump();
            true
        } else {
            false
        }
    }

    fn eat_word(&mut self, word: &str) -> bool {
        if self.at_word(word) {
            self.bump();
            true
        } else {
            false
        }
    }

    fn unexpected(&mut self, expecting: &[&str]) -> Failed {
        let msg = unexpected_message(self.tok.kind, self.cur(), expecting);
        let span = self.span(self.tok.start, self.tok.end);
        self.diags.push(Diagnostic::error(span, msg));
        Failed
    }

    fn expect(&mut self, kind: T, expecting: &[&str]) -> PResult<Token> {
        if self.at(kind) {
            Ok(self.bump())
        } else {
            Err(self.unexpected(expecting))
        }
    }

    fn expect_word(&mut self, word: &str) -> PResult<()> {
        if self.eat_word(word) {
            Ok(())
        } else {
            Err(self.unexpected(&[word]))
        }
    }

    fn description(&mut self) {
        while !self.at(T::Eof) {
            let start = self.tok.start;
            match self.statement() {
                Ok(st) => self.statements.push(st),
                Err(Failed) => {
                    // Recover after the next period; this consumes at least one token.
                    while !self.at(T::Eof) && !self.at(T::Dot) {
                        self.bump();
                    }
                    self.eat(T::Dot);
                    let span = self.span_from(start);
                    self.statements.push(Statement {
                        span,
                        guards: Vec::new(),
                        label: None,
                        kind: StatementKind::Error,
                    });
                }
            }
        }
    }

    /// A name token (identifier or variable), as labels are written.
    fn name(&mut self, what: &[&str]) -> PResult<Name> {
        if matches!(self.tok.kind, T::Ident | T::Variable) {
            let tok = self.bump();
            Ok(Name {
                span: self.span(tok.start, tok.end),
                text: self.word_of(tok).to_string(),
            })
        } else {
            Err(self.unexpected(what))
        }
    }

    /// An identifier that is not a keyword.
    fn identifier(&mut self) -> PResult<Name> {
        if self.at(T::Ident) && !KEYWORDS.contains(&self.cur()) {
            let tok = self.bump();
            Ok(Name {
                span: self.span(tok.start, tok.end),
                text: self.word_of(tok).to_string(),
            })
        } else if self.at(T::Ident) {
            let span = self.span(self.tok.start, self.tok.end);
            let msg = format!(
                "syntax error, unexpected keyword {}, expecting <IDENTIFIER>",
                self.cur()
            );
            self.diags.push(Diagnostic::error(span, msg));
            Err(Failed)
        } else {
            Err(self.unexpected(&["<IDENTIFIER>"]))
        }
    }

    fn statement(&mut self) -> PResult<Statement> {
        let start = self.tok.start;
        let mut guards = Vec::new();
        while self.at(T::LBrack) {
            let open = self.bump();
            let negated = self.eat(T::Not) || self.eat_word("not");
            let switch = self.identifier()?;
            self.expect(T::RBrack, &["\"]\""])?;
            guards.push(Guard {
                span: self.span_from(open.start),
                negated,
                switch,
            });
        }
        let mut label = None;
        if matches!(self.tok.kind, T::Ident | T::Variable) && self.peek().kind == T::Colon {
            label = Some(self.name(&["<IDENTIFIER>"])?);
            self.bump();
        }
        let kind = self.statement_kind()?;
        self.expect(T::Dot, &["\".\""])?;
        Ok(Statement {
            span: self.span_from(start),
            guards,
            label,
            kind,
        })
    }

    fn statement_kind(&mut self) -> PResult<StatementKind> {
        if self.at(T::Ident) {
            match self.cur() {
                "sort" => {
                    self.bump();
                    let name = self.identifier()?;
                    self.expect(T::Eq, &["\"=\""])?;
                    let expr = self.sort_expr()?;
                    return Ok(StatementKind::Sort { name, expr });
                }
                "static" => {
                    self.bump();
                    return self.declaration(DeclKind::Static);
                }
                "inertial" => {
                    self.bump();
                    self.expect_word("fluent")?;
                    return self.declaration(DeclKind::Inertial);
                }
                "defined" => {
                    self.bump();
                    self.expect_word("fluent")?;
                    return self.declaration(DeclKind::Defined { cwa: true });
                }
                "action" => {
                    self.bump();
                    return self.declaration(DeclKind::Action);
                }
                "impossible" => {
                    self.bump();
                    let action = self.atom()?;
                    let body = self.opt_body()?;
                    return Ok(StatementKind::Impossible { action, body });
                }
                "normally" => {
                    self.bump();
                    let head = self.literal()?;
                    let body = self.opt_body()?;
                    return Ok(StatementKind::Default { head, body });
                }
                "exception" => {
                    self.bump();
                    self.expect_word("to")?;
                    let default = self.name(&["<IDENTIFIER>", "<VARIABLE>"])?;
                    self.expect(T::Colon, &["\":\""])?;
                    let head = self.literal()?;
                    self.expect_word("may")?;
                    self.expect_word("be")?;
                    self.expect_word("assumed")?;
                    let body = self.opt_body()?;
                    return Ok(StatementKind::Exception {
                        default,
                        head,
                        body,
                    });
                }
                "never" => {
                    self.bump();
                    let lit = self.literal()?;
                    let body = self.opt_body()?;
                    return Ok(StatementKind::Never { lit, body });
                }
                "goal" => {
                    self.bump();
                    let body = self.body()?;
                    return Ok(StatementKind::Goal { body });
                }
                "observed" => {
                    self.bump();
                    let lit = self.literal()?;
                    let step = self.at_step()?;
                    return Ok(StatementKind::Observed { lit, step });
                }
                "happened" => {
                    self.bump();
                    let action = self.atom()?;
                    let step = self.at_step()?;
                    return Ok(StatementKind::Happened { action, step });
                }
                "initially" => {
                    self.bump();
                    if self.eat_word("normally") {
                        self.expect_word("false")?;
                        let mut except = Vec::new();
                        if self.eat_word("except") {
                            except = self.identifiers()?;
                        }
                        return Ok(StatementKind::InitialDefault { except });
                    }
                    let lit = self.literal()?;
                    return Ok(StatementKind::Initially { lit });
                }
                "switch" | "set" => {
                    let declare = self.cur() == "switch";
                    self.bump();
                    let name = self.identifier()?;
                    self.expect(T::Eq, &["\"=\""])?;
                    let value = self.value()?;
                    return Ok(if declare {
                        StatementKind::Switch { name, value }
                    } else {
                        StatementKind::Set { name, value }
                    });
                }
                "profile" => {
                    self.bump();
                    let name = self.identifier()?;
                    self.expect(T::Colon, &["\":\""])?;
                    let mut items = vec![self.profile_item()?];
                    while self.eat(T::Comma) {
                        items.push(self.profile_item()?);
                    }
                    return Ok(StatementKind::Profile { name, items });
                }
                "include" => {
                    self.bump();
                    let tok = self.expect(T::String, &["<STRING>"])?;
                    let raw = self.word_of(tok);
                    let path = raw[1..raw.len() - 1].to_string();
                    return Ok(StatementKind::Include { path });
                }
                _ => {}
            }
        }
        let head = self.literal()?;
        if self.eat_word("causes") {
            let action = if head.negated {
                self.diags.push(Diagnostic::error(
                    head.span,
                    "an action cannot be negated in a causal law",
                ));
                return Err(Failed);
            } else {
                head.atom
            };
            let effect = self.literal()?;
            let body = self.opt_body()?;
            return Ok(StatementKind::Causal {
                action,
                effect,
                body,
            });
        }
        let body = self.opt_body()?;
        Ok(StatementKind::Constraint { head, body })
    }

    /// `name {, name}`
    fn identifiers(&mut self) -> PResult<Vec<Name>> {
        let mut names = vec![self.identifier()?];
        while self.eat(T::Comma) {
            names.push(self.identifier()?);
        }
        Ok(names)
    }

    /// `at step`
    fn at_step(&mut self) -> PResult<Term> {
        self.expect_word("at")?;
        self.term()
    }

    fn declaration(&mut self, kind: DeclKind) -> PResult<StatementKind> {
        let name = self.identifier()?;
        let mut params = Vec::new();
        if self.eat(T::LParen) {
            if !self.at(T::RParen) {
                params = self.identifiers()?;
            }
            self.expect(T::RParen, &["\")\"", "\",\""])?;
        }
        let mut kind = kind;
        if matches!(kind, DeclKind::Defined { .. }) && self.eat_word("without") {
            self.expect_word("cwa")?;
            kind = DeclKind::Defined { cwa: false };
        }
        Ok(StatementKind::Declaration { kind, name, params })
    }

    fn value(&mut self) -> PResult<Value> {
        let negative = self.eat(T::Minus);
        if self.at(T::Number) {
            let tok = self.bump();
            let n = self.integer(tok);
            return Ok(Value::Int(if negative { -n } else { n }));
        }
        if negative {
            return Err(self.unexpected(&["<NUMBER>"]));
        }
        if self.at(T::Ident) {
            let tok = self.bump();
            return Ok(match self.word_of(tok) {
                "true" | "on" => Value::Bool(true),
                "false" | "off" => Value::Bool(false),
                w => Value::Word(w.to_string()),
            });
        }
        Err(self.unexpected(&["<NUMBER>", "<IDENTIFIER>"]))
    }

    fn profile_item(&mut self) -> PResult<ProfileItem> {
        if self.at_word("drop") && matches!(self.peek().kind, T::Ident | T::Variable) {
            self.bump();
            return Ok(ProfileItem::Drop(self.name(&["<IDENTIFIER>"])?));
        }
        if self.at_word("no") && self.peek().kind == T::Ident {
            self.bump();
            let name = self.identifier()?;
            return Ok(ProfileItem::Set {
                name,
                value: Value::Bool(false),
            });
        }
        let name = self.identifier()?;
        let value = if self.eat(T::Eq) {
            self.value()?
        } else {
            Value::Bool(true)
        };
        Ok(ProfileItem::Set { name, value })
    }

    fn sort_expr(&mut self) -> PResult<SortExpr> {
        let start = self.tok.start;
        let mut parts = vec![self.sort_part()?];
        while self.eat(T::Plus) {
            parts.push(self.sort_part()?);
        }
        Ok(SortExpr {
            span: self.span_from(start),
            parts,
        })
    }

    fn sort_part(&mut self) -> PResult<SortPart> {
        if self.eat(T::LBrace) {
            let mut members = Vec::new();
            if !self.at(T::RBrace) {
                members.push(self.term()?);
                while self.eat(T::Comma) {
                    members.push(self.term()?);
                }
            }
            self.expect(T::RBrace, &["\"}\"", "\",\""])?;
            return Ok(SortPart::Set(members));
        }
        if self.at(T::Ident) && self.peek().kind != T::Dots {
            return Ok(SortPart::Name(self.identifier()?));
        }
        let lo = self.unary()?;
        self.expect(T::Dots, &["\"..\""])?;
        let hi = self.unary()?;
        Ok(SortPart::Range(lo, hi))
    }

    fn opt_body(&mut self) -> PResult<Vec<BodyItem>> {
        if self.eat_word("if") {
            self.body()
        } else {
            Ok(Vec::new())
        }
    }

    fn body(&mut self) -> PResult<Vec<BodyItem>> {
        let mut items = vec![self.body_item()?];
        while self.eat(T::Comma) {
            items.push(self.body_item()?);
        }
        Ok(items)
    }

    fn body_item(&mut self) -> PResult<BodyItem> {
        let start = self.tok.start;
        let term = self.term()?;
        if let Some(op) = cmp_op(self.tok.kind) {
            self.bump();
            let rhs = self.term()?;
            return Ok(BodyItem::Compare {
                span: self.span_from(start),
                lhs: term,
                op,
                rhs,
            });
        }
        match self.lit_of(term) {
            Some(lit) => Ok(BodyItem::Lit(lit)),
            None => Err(self.unexpected(&["a comparison operator"])),
        }
    }

    /// A literal `[-]p(t1, ..., tn)`.
    fn literal(&mut self) -> PResult<Lit> {
        if !(self.at(T::Minus) || (self.at(T::Ident) && !KEYWORDS.contains(&self.cur()))) {
            return Err(self.unexpected(&["<IDENTIFIER>", "\"-\""]));
        }
        let term = self.term()?;
        match self.lit_of(term) {
            Some(lit) => Ok(lit),
            None => {
                let span = self.span(self.prev_end, self.prev_end);
                self.diags.push(Diagnostic::error(
                    span,
                    "syntax error, expecting a literal (a name with optional arguments)",
                ));
                Err(Failed)
            }
        }
    }

    /// An atom `p(t1, ..., tn)` (no negation).
    fn atom(&mut self) -> PResult<Atom> {
        let lit = self.literal()?;
        if lit.negated {
            self.diags
                .push(Diagnostic::error(lit.span, "an action cannot be negated"));
            return Err(Failed);
        }
        Ok(lit.atom)
    }

    /// Reads a term as a literal: a constant, a function, or either under unary minus.
    fn lit_of(&self, term: Term) -> Option<Lit> {
        let span = term.span;
        match term.kind {
            TermKind::Unary {
                op: UnaryOp::Minus,
                arg,
            } => {
                let inner = self.lit_of(*arg)?;
                if inner.negated {
                    return None;
                }
                Some(Lit {
                    span,
                    negated: true,
                    atom: inner.atom,
                })
            }
            TermKind::Constant(name) if !KEYWORDS.contains(&name.as_str()) => Some(Lit {
                span,
                negated: false,
                atom: Atom {
                    span,
                    name: Name {
                        span: Span::new(span.file, span.start, span.start + name.len() as u32),
                        text: name.to_string(),
                    },
                    args: Vec::new(),
                },
            }),
            TermKind::Function {
                name,
                mut args,
                trailing_comma: false,
            } if !name.is_empty() && args.len() == 1 && !KEYWORDS.contains(&name.as_str()) => {
                Some(Lit {
                    span,
                    negated: false,
                    atom: Atom {
                        span,
                        name: Name {
                            span: Span::new(span.file, span.start, span.start + name.len() as u32),
                            text: name.to_string(),
                        },
                        args: args.pop().unwrap_or_default(),
                    },
                })
            }
            _ => None,
        }
    }

    fn term(&mut self) -> PResult<Term> {
        self.binary(0)
    }

    /// Additive (level 0) and multiplicative (level 1) terms, left-associative.
    fn binary(&mut self, level: u8) -> PResult<Term> {
        let start = self.tok.start;
        let mut lhs = if level == 0 {
            self.binary(1)?
        } else {
            self.unary()?
        };
        loop {
            let op = match (level, self.tok.kind) {
                (0, T::Plus) => BinaryOp::Add,
                (0, T::Minus) => BinaryOp::Sub,
                (1, T::Star) => BinaryOp::Mul,
                (1, T::Slash) => BinaryOp::Div,
                (1, T::Backslash) => BinaryOp::Mod,
                _ => return Ok(lhs),
            };
            self.bump();
            let rhs = if level == 0 {
                self.binary(1)?
            } else {
                self.unary()?
            };
            lhs = Term {
                span: self.span_from(start),
                kind: TermKind::Binary {
                    op,
                    lhs: Box::new(lhs),
                    rhs: Box::new(rhs),
                },
            };
        }
    }

    fn unary(&mut self) -> PResult<Term> {
        let start = self.tok.start;
        if self.eat(T::Minus) {
            self.enter()?;
            let arg = self.unary();
            self.depth -= 1;
            let arg = arg?;
            let span = self.span_from(start);
            // A negative number literal is an integer, as clingo reads it.
            if let TermKind::Integer(n) = arg.kind {
                return Ok(Term {
                    span,
                    kind: TermKind::Integer(-n),
                });
            }
            return Ok(Term {
                span,
                kind: TermKind::Unary {
                    op: UnaryOp::Minus,
                    arg: Box::new(arg),
                },
            });
        }
        self.primary()
    }

    fn enter(&mut self) -> PResult<()> {
        if self.depth >= MAX_DEPTH {
            let span = self.span(self.tok.start, self.tok.end);
            self.diags.push(Diagnostic::error(
                span,
                format!("nesting deeper than {MAX_DEPTH} levels"),
            ));
            return Err(Failed);
        }
        self.depth += 1;
        Ok(())
    }

    fn primary(&mut self) -> PResult<Term> {
        let start = self.tok.start;
        match self.tok.kind {
            T::Number => {
                let tok = self.bump();
                let n = self.integer(tok);
                Ok(Term {
                    span: self.span_from(start),
                    kind: TermKind::Integer(n),
                })
            }
            T::Variable => {
                let tok = self.bump();
                Ok(Term {
                    span: self.span_from(start),
                    kind: TermKind::Variable(self.word_of(tok).into()),
                })
            }
            T::Ident => {
                let tok = self.bump();
                let name = self.word_of(tok).to_string();
                if self.eat(T::LParen) {
                    self.enter()?;
                    let args = self.arguments();
                    self.depth -= 1;
                    let args = args?;
                    Ok(Term {
                        span: self.span_from(start),
                        kind: TermKind::Function {
                            name: name.into(),
                            args: vec![args],
                            trailing_comma: false,
                        },
                    })
                } else {
                    Ok(Term {
                        span: self.span_from(start),
                        kind: TermKind::Constant(name.into()),
                    })
                }
            }
            T::LParen => {
                self.bump();
                self.enter()?;
                let inner = self.term();
                self.depth -= 1;
                let inner = inner?;
                self.expect(T::RParen, &["\")\""])?;
                Ok(Term {
                    span: self.span_from(start),
                    kind: TermKind::Paren(Box::new(inner)),
                })
            }
            _ => Err(self.unexpected(&["<IDENTIFIER>", "<VARIABLE>", "<NUMBER>"])),
        }
    }

    /// `t1, ..., tn )` after an opening parenthesis.
    fn arguments(&mut self) -> PResult<Vec<Term>> {
        let mut args = Vec::new();
        if !self.eat(T::RParen) {
            args.push(self.term()?);
            while self.eat(T::Comma) {
                args.push(self.term()?);
            }
            self.expect(T::RParen, &["\")\"", "\",\""])?;
        }
        Ok(args)
    }

    fn integer(&mut self, tok: Token) -> i64 {
        match integer_value(self.word_of(tok)) {
            Some(v) if v <= i32::MAX as i64 => v,
            _ => {
                self.diags.push(Diagnostic::error(
                    self.span(tok.start, tok.end),
                    "integer literal out of range",
                ));
                0
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> Vec<StatementKind> {
        let p = parse(FileId(0), text);
        assert!(!p.has_errors(), "{:?}", p.diagnostics);
        p.description
            .statements
            .into_iter()
            .map(|s| s.kind)
            .collect()
    }

    #[test]
    fn causal_law_with_label_and_guard() {
        let p = parse(
            FileId(0),
            "[not strict] C1: putdown(R, A, L) causes relation(on, A, L) if A != L.",
        );
        assert!(!p.has_errors(), "{:?}", p.diagnostics);
        let st = &p.description.statements[0];
        assert_eq!(st.label.as_ref().unwrap().text, "C1");
        assert!(st.guards[0].negated);
        assert!(matches!(st.kind, StatementKind::Causal { .. }));
    }

    #[test]
    fn recovers_at_the_next_statement() {
        let p = parse(FileId(0), "sort a = {x}. foo bar. static p(a).");
        assert_eq!(p.diagnostics.len(), 1);
        assert_eq!(p.description.statements.len(), 3);
        assert_eq!(p.description.statements[1].kind, StatementKind::Error);
        assert!(matches!(
            p.description.statements[2].kind,
            StatementKind::Declaration { .. }
        ));
    }

    #[test]
    fn negated_literals_and_comparisons() {
        let k = kinds("-in_hand(R, A) if in_hand(R, B), A != B, N + 1 > 3.");
        let StatementKind::Constraint { head, body } = &k[0] else {
            panic!()
        };
        assert!(head.negated);
        assert_eq!(body.len(), 3);
    }
}
