//! Terms, for both parsers: precedence climbing over the binary operators, unary operators,
//! primaries (numbers, strings, constants, functions, tuples, pools, intervals), integers and
//! string escapes. The cursor's [`TermGrammar`] says which of them are read: AL_d's
//! [`TermGrammar::Arithmetic`] is the subset of `+ - * / \`, unary minus, numbers, variables,
//! constants, functions and parentheses.
//!
//! Invariant: term nesting (operator chains included) is capped at the grammar's
//! [`TermGrammar::max_depth`]; integers out of range are reported, never wrapped silently.

use super::cursor::{integer_value, Cursor, PResult, TermGrammar};
use crate::base::Span;
use crate::syntax::ast::{BinaryOp, Name, Term, TermKind, UnaryOp};
use crate::syntax::lexer::{Token, TokenKind as T};

/// What [`TermGrammar::Arithmetic`] expects where a term starts.
const ARITHMETIC_START: &[&str] = &["<IDENTIFIER>", "<VARIABLE>", "<NUMBER>"];

impl<'a> Cursor<'a> {
    /// A term, intervals included (in the clingo grammar).
    pub(crate) fn term(&mut self) -> PResult<Term> {
        self.binary(0)
    }

    /// A term whose binary operators bind at least as tightly as `min_level`.
    /// Levels: `..` 0, `^` 1, `?` 2, `&` 3, `+ -` 4, `* / \` 5, `**` 6 (right-associative).
    fn binary(&mut self, min_level: u8) -> PResult<Term> {
        if let Some(leaf) = self.leaf() {
            return Ok(leaf);
        }
        self.enter()?;
        let mut lhs = self.unary()?;
        let mut folds = 0;
        while let Some((level, op)) = self.binary_operator(self.tok.kind) {
            if level < min_level {
                break;
            }
            self.bump();
            let next_min = if op == Some(BinaryOp::Pow) {
                level
            } else {
                level + 1
            };
            let rhs = self.binary(next_min)?;
            let span = lhs.span.to(rhs.span);
            let kind = match op {
                None => TermKind::Interval {
                    lo: Box::new(lhs),
                    hi: Box::new(rhs),
                },
                Some(op) => TermKind::Binary {
                    op,
                    lhs: Box::new(lhs),
                    rhs: Box::new(rhs),
                },
            };
            lhs = Term { span, kind };
            // A left-associative chain nests the tree one level per operator, and every later
            // stage (printer, span walk, drop) recurses over it, so it counts as nesting.
            self.enter()?;
            folds += 1;
        }
        self.depth -= folds;
        self.leave();
        Ok(lhs)
    }

    /// The fast path of [`Cursor::binary`] for the commonest terms: a variable, a constant or a
    /// decimal number that no operator, argument list or interval follows, read here without the
    /// precedence chain. `None` (nothing consumed) for any other term, and at the nesting cap,
    /// where the chain reports it.
    #[inline]
    fn leaf(&mut self) -> Option<Term> {
        if !matches!(self.tok.kind, T::Variable | T::Ident | T::Number)
            || self.depth >= self.grammar.max_depth()
        {
            return None;
        }
        let next = self.peek().kind;
        if self.binary_operator(next).is_some() || next == T::LParen {
            return None;
        }
        let tok = self.bump();
        let kind = match tok.kind {
            T::Variable => TermKind::Variable(Name::new(self.word(tok))),
            T::Ident => TermKind::Constant(Name::new(self.word(tok))),
            _ => TermKind::Integer(self.integer(tok)),
        };
        Some(Term {
            span: self.span_of(tok),
            kind,
        })
    }

    /// A term with prefix operators `-` and `~` (`-` only in the arithmetic grammar, where a
    /// minus before an integer folds into it: `-3` is the integer -3, as clingo reads it).
    pub(crate) fn unary(&mut self) -> PResult<Term> {
        let op = match self.tok.kind {
            T::Minus => UnaryOp::Minus,
            T::Tilde if self.grammar == TermGrammar::Clingo => UnaryOp::BitNot,
            _ => return self.primary(),
        };
        self.enter()?;
        let start = self.bump().start();
        let arg = self.unary()?;
        self.leave();
        let span = self.span_from(start);
        if let (TermGrammar::Arithmetic, TermKind::Integer(n)) = (self.grammar, &arg.kind) {
            return Ok(Term {
                span,
                kind: TermKind::Integer(-n),
            });
        }
        Ok(Term {
            span,
            kind: TermKind::Unary {
                op,
                arg: Box::new(arg),
            },
        })
    }

    /// A term without operators: constants, numbers, strings, variables, functions, tuples,
    /// pools, `|t|`, `#inf`, `#sup`, `@f(...)`; in the arithmetic grammar numbers, variables,
    /// constants, functions and `(t)` only.
    fn primary(&mut self) -> PResult<Term> {
        let start = self.tok.start();
        if self.grammar == TermGrammar::Arithmetic
            && !matches!(
                self.tok.kind,
                T::Number | T::Variable | T::Ident | T::LParen
            )
        {
            return Err(self.unexpected(ARITHMETIC_START));
        }
        let kind = match self.tok.kind {
            T::Number => {
                let tok = self.bump();
                TermKind::Integer(self.integer(tok))
            }
            T::String => {
                let tok = self.bump();
                TermKind::String(self.unescape(tok))
            }
            T::Variable => {
                let tok = self.bump();
                TermKind::Variable(Name::new(self.word(tok)))
            }
            T::Anonymous => {
                self.bump();
                TermKind::Anonymous
            }
            T::Ident => {
                let tok = self.bump();
                let name = Name::new(self.word(tok));
                if self.at(T::LParen) {
                    let args = self.arguments()?;
                    TermKind::Function {
                        name,
                        args,
                        trailing_comma: false,
                    }
                } else {
                    TermKind::Constant(name)
                }
            }
            T::Hash => match self.cur() {
                "#inf" | "#infimum" => {
                    self.bump();
                    TermKind::Infimum
                }
                "#sup" | "#supremum" => {
                    self.bump();
                    TermKind::Supremum
                }
                _ => return Err(self.unexpected(&[])),
            },
            T::At => {
                self.bump();
                let name = self.identifier()?;
                let mut args = Vec::new();
                if self.eat(T::LParen) {
                    if !self.at(T::RParen) {
                        loop {
                            args.push(self.term()?);
                            if !self.eat(T::Comma) {
                                break;
                            }
                        }
                    }
                    self.expect(T::RParen, &[")", "\",\""])?;
                }
                TermKind::ScriptCall { name, args }
            }
            T::Bar => {
                self.bump();
                let arg = self.term()?;
                self.expect(T::Bar, &["|"])?;
                TermKind::Unary {
                    op: UnaryOp::Abs,
                    arg: Box::new(arg),
                }
            }
            T::LParen => self.parenthesized()?,
            _ => return Err(self.unexpected(&[])),
        };
        Ok(Term {
            span: self.span_from(start),
            kind,
        })
    }

    /// `( alternatives )` of a function: pools `f(1,2;3)` (not in the arithmetic grammar);
    /// `f()` is one empty list.
    fn arguments(&mut self) -> PResult<Vec<Vec<Term>>> {
        self.bump();
        let mut alts = Vec::with_capacity(1);
        if self.eat(T::RParen) {
            return Ok(vec![Vec::new()]);
        }
        loop {
            let mut terms = Vec::with_capacity(2);
            loop {
                terms.push(self.term()?);
                if !self.eat(T::Comma) {
                    break;
                }
            }
            alts.push(terms);
            if self.grammar == TermGrammar::Arithmetic {
                self.expect(T::RParen, &["\")\"", "\",\""])?;
                break;
            }
            if self.eat(T::Semi) {
                continue;
            }
            self.expect(T::RParen, &[")", ";"])?;
            break;
        }
        Ok(alts)
    }

    /// A parenthesized term: `(t)`, a tuple `()`, `(a,)`, `(a,b)`, or a pool `(a;b)`; only
    /// `(t)` in the arithmetic grammar.
    fn parenthesized(&mut self) -> PResult<TermKind> {
        self.bump();
        if self.grammar == TermGrammar::Arithmetic {
            let inner = self.term()?;
            self.expect(T::RParen, &["\")\""])?;
            return Ok(TermKind::Paren(Box::new(inner)));
        }
        if self.eat(T::RParen) {
            return Ok(TermKind::Function {
                name: Name::default(),
                args: vec![Vec::new()],
                trailing_comma: false,
            });
        }
        let mut alts: Vec<(u32, Vec<Term>, bool)> = Vec::new();
        loop {
            let alt_start = self.tok.start();
            let mut terms = vec![self.term()?];
            let mut trailing = false;
            while self.eat(T::Comma) {
                if self.at(T::RParen) || self.at(T::Semi) {
                    trailing = true;
                    break;
                }
                terms.push(self.term()?);
            }
            alts.push((alt_start, terms, trailing));
            if self.eat(T::Semi) {
                continue;
            }
            self.expect(T::RParen, &[")", ";"])?;
            break;
        }
        if alts.len() == 1 {
            let (_, mut terms, trailing) = alts.pop().expect("one alternative");
            if terms.len() == 1 && !trailing {
                return Ok(TermKind::Paren(Box::new(terms.pop().expect("one term"))));
            }
            return Ok(TermKind::Function {
                name: Name::default(),
                args: vec![terms],
                trailing_comma: trailing,
            });
        }
        let file = self.file;
        let alternatives = alts
            .into_iter()
            .map(|(alt_start, mut terms, trailing)| {
                if terms.len() == 1 && !trailing {
                    terms.pop().expect("one term")
                } else {
                    let end = terms.last().map_or(alt_start, |t| t.span.end);
                    Term {
                        span: Span::new(file, alt_start, end),
                        kind: TermKind::Function {
                            name: Name::default(),
                            args: vec![terms],
                            trailing_comma: trailing,
                        },
                    }
                }
            })
            .collect();
        Ok(TermKind::Pool(alternatives))
    }

    /// The value of a number token; out-of-range literals are reported (and read as
    /// `i64::MAX` in the clingo grammar, 0 in the arithmetic one, which bounds sorts by them).
    pub(crate) fn integer(&mut self, tok: Token) -> i64 {
        let (max, instead) = match self.grammar {
            TermGrammar::Clingo => (i64::MAX, i64::MAX),
            TermGrammar::Arithmetic => (i64::from(i32::MAX), 0),
        };
        match integer_value(self.word(tok)) {
            Some(v) if v <= max => v,
            _ => {
                let span = self.span_of(tok);
                self.error(span, "integer literal out of range");
                instead
            }
        }
    }

    /// The contents of a string token with escapes resolved (the lexer checked them).
    pub(crate) fn unescape(&self, tok: Token) -> String {
        let raw = &self.text[tok.start() as usize + 1..tok.end() as usize - 1];
        if !raw.contains('\\') {
            return raw.to_string();
        }
        let mut out = String::with_capacity(raw.len());
        let mut chars = raw.chars();
        while let Some(c) = chars.next() {
            if c == '\\' {
                match chars.next() {
                    Some('n') => out.push('\n'),
                    Some(other) => out.push(other),
                    None => {}
                }
            } else {
                out.push(c);
            }
        }
        out
    }

    /// The level and operator of a token that continues a term in this grammar (`None` for
    /// `..`, an interval), as [`Cursor::binary`] reads them; `None` for any other token.
    #[inline]
    fn binary_operator(&self, kind: T) -> Option<(u8, Option<BinaryOp>)> {
        let found = clingo_binary_operator(kind)?;
        match (self.grammar, found.0) {
            (TermGrammar::Arithmetic, 4 | 5) | (TermGrammar::Clingo, _) => Some(found),
            (TermGrammar::Arithmetic, _) => None,
        }
    }
}

/// The level and operator of a token that continues a clingo term (`None` for `..`, an
/// interval); `None` for any other token.
#[inline]
fn clingo_binary_operator(kind: T) -> Option<(u8, Option<BinaryOp>)> {
    Some(match kind {
        T::Dots => (0, None),
        T::Caret => (1, Some(BinaryOp::BitXor)),
        T::Question => (2, Some(BinaryOp::BitOr)),
        T::Amp => (3, Some(BinaryOp::BitAnd)),
        T::Plus => (4, Some(BinaryOp::Add)),
        T::Minus => (4, Some(BinaryOp::Sub)),
        T::Star => (5, Some(BinaryOp::Mul)),
        T::Slash => (5, Some(BinaryOp::Div)),
        T::Backslash => (5, Some(BinaryOp::Mod)),
        T::Pow => (6, Some(BinaryOp::Pow)),
        _ => return None,
    })
}
