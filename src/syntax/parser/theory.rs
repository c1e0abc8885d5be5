//! Theory syntax (clingo 5's "Theory solving"): `#theory` definitions and theory atoms
//! `&name(args){ terms : condition; ... } op guard` in heads, bodies and directives.
//!
//! Theory terms are read in the lexer's theory mode, where a run of operator characters is one
//! token; their operators are kept as written ([`TheoryTermKind::Unparsed`]) because only the
//! theory's operator table, which may come later in the input, says how they bind
//! (`syntax::theory` resolves them).
//!
//! Invariants: every mode switch re-reads the current token in the new mode, so no token is
//! read in the wrong mode; the lexer is back in normal mode when a theory construct ends, also
//! after an error (the statement loop switches it off before recovery).

use super::cursor::integer_value;
use super::*;
use crate::syntax::name::Name;

impl<'a> Parser<'a> {
    /// Switches the lexer's theory mode and reads the current token again in that mode.
    pub(super) fn theory_mode(&mut self, on: bool) {
        self.cursor.relex(on);
    }

    /// A theory operator: a [`T::TheoryOp`] token or `not`.
    fn theory_op(&mut self) -> Option<String> {
        if self.at(T::TheoryOp) || self.at(T::Not) {
            let tok = self.bump();
            Some(self.word(tok).to_string())
        } else {
            None
        }
    }

    // ----- definitions -----

    /// `#theory name { definitions }.`
    pub(super) fn theory_def(&mut self) -> PResult<StatementKind> {
        self.bump();
        let name = self.identifier()?;
        self.expect(T::LBrace, &["{"])?;
        let mut def = TheoryDef {
            name,
            terms: Vec::new(),
            atoms: Vec::new(),
        };
        if !self.eat(T::RBrace) {
            loop {
                let start = self.tok.start();
                if self.eat(T::Amp) {
                    def.atoms.push(self.theory_atom_def(start)?);
                } else {
                    def.terms.push(self.theory_term_def(start)?);
                }
                if self.eat(T::Semi) {
                    continue;
                }
                self.expect(T::RBrace, &[";", "}"])?;
                break;
            }
        }
        self.expect(T::Dot, &["."])?;
        Ok(StatementKind::Theory(Box::new(def)))
    }

    /// `name { op : priority, unary|binary, left|right; ... }`
    fn theory_term_def(&mut self, start: u32) -> PResult<TheoryTermDef> {
        let name = self.identifier()?;
        if !self.at(T::LBrace) {
            return Err(self.unexpected(&["{"]));
        }
        self.theory_mode(true);
        self.bump();
        let mut ops = Vec::new();
        if !self.at(T::RBrace) {
            loop {
                let op_start = self.tok.start();
                let Some(op) = self.theory_op() else {
                    self.theory_mode(false);
                    return Err(self.unexpected(&["<THEORYOP>"]));
                };
                self.theory_mode(false);
                self.expect(T::Colon, &[":"])?;
                let tok = self.expect(T::Number, &["<NUMBER>"])?;
                let priority = integer_value(self.word(tok))
                    .and_then(|v| u32::try_from(v).ok())
                    .unwrap_or(u32::MAX);
                self.expect(T::Comma, &["\",\""])?;
                let kind = if self.eat_word("unary") {
                    TheoryOpKind::Unary
                } else if self.eat_word("binary") {
                    self.expect(T::Comma, &["\",\""])?;
                    if self.eat_word("left") {
                        TheoryOpKind::BinaryLeft
                    } else if self.eat_word("right") {
                        TheoryOpKind::BinaryRight
                    } else {
                        return Err(self.unexpected(&["left", "right"]));
                    }
                } else {
                    return Err(self.unexpected(&["unary", "binary"]));
                };
                ops.push(TheoryOpDef {
                    span: self.span_from(op_start),
                    op,
                    priority,
                    kind,
                });
                if self.at(T::Semi) {
                    self.theory_mode(true);
                    self.bump();
                    continue;
                }
                break;
            }
        }
        self.theory_mode(false);
        self.expect(T::RBrace, &[";", "}"])?;
        Ok(TheoryTermDef {
            span: self.span_from(start),
            name,
            ops,
        })
    }

    /// `&name/arity : elements, [{ops}, guard,] head|body|any|directive` after the `&`.
    fn theory_atom_def(&mut self, start: u32) -> PResult<TheoryAtomDef> {
        let name = self.identifier()?;
        self.expect(T::Slash, &["/"])?;
        let tok = self.expect(T::Number, &["<NUMBER>"])?;
        let arity = integer_value(self.word(tok))
            .and_then(|v| u32::try_from(v).ok())
            .unwrap_or(u32::MAX);
        self.expect(T::Colon, &[":"])?;
        let elements = self.identifier()?;
        self.expect(T::Comma, &["\",\""])?;
        let mut guard = None;
        if self.at(T::LBrace) {
            self.theory_mode(true);
            self.bump();
            let mut ops = Vec::new();
            if !self.at(T::RBrace) {
                loop {
                    let Some(op) = self.theory_op() else {
                        self.theory_mode(false);
                        return Err(self.unexpected(&["<THEORYOP>"]));
                    };
                    ops.push(op);
                    if !self.eat(T::Comma) {
                        break;
                    }
                }
            }
            self.theory_mode(false);
            self.expect(T::RBrace, &["\",\"", "}"])?;
            self.expect(T::Comma, &["\",\""])?;
            let term = self.identifier()?;
            self.expect(T::Comma, &["\",\""])?;
            guard = Some((ops, term));
        }
        let kind = match self.cur() {
            "head" if self.at(T::Ident) => TheoryAtomKind::Head,
            "body" if self.at(T::Ident) => TheoryAtomKind::Body,
            "any" if self.at(T::Ident) => TheoryAtomKind::Any,
            "directive" if self.at(T::Ident) => TheoryAtomKind::Directive,
            _ => return Err(self.unexpected(&["{"])),
        };
        self.bump();
        Ok(TheoryAtomDef {
            span: self.span_from(start),
            name,
            arity,
            elements,
            guard,
            kind,
        })
    }

    // ----- atoms -----

    /// A theory atom, the current token its `&`; leaves the lexer in normal mode.
    pub(super) fn theory_atom(&mut self) -> PResult<TheoryAtom> {
        let r = self.theory_atom_inner();
        if r.is_err() {
            self.theory_mode(false);
        }
        r
    }

    fn theory_atom_inner(&mut self) -> PResult<TheoryAtom> {
        let start = self.tok.start();
        self.bump();
        let name_start = self.tok.start();
        let tok = self.expect(T::Ident, &["<IDENTIFIER>"])?;
        let name = Name::new(self.word(tok));
        let args = if self.at(T::LParen) {
            self.enter()?;
            let args = self.theory_name_args()?;
            self.leave();
            args
        } else {
            vec![Vec::new()]
        };
        let name = SymbolicAtom {
            span: self.span_from(name_start),
            negated: false,
            name,
            args,
        };
        let mut elements = Vec::new();
        let mut guard = None;
        if self.at(T::LBrace) {
            self.enter()?;
            self.theory_mode(true);
            self.bump();
            if !self.at(T::RBrace) {
                loop {
                    elements.push(self.theory_element()?);
                    if self.at(T::Semi) {
                        self.theory_mode(true);
                        self.bump();
                        continue;
                    }
                    break;
                }
            }
            self.theory_mode(true);
            self.expect(T::RBrace, &[";", "}"])?;
            self.leave();
            if let Some(op) = self.theory_op() {
                guard = Some((op, self.theory_opterm()?));
            }
            self.theory_mode(false);
        }
        Ok(TheoryAtom {
            span: self.span_from(start),
            name,
            elements,
            guard,
        })
    }

    /// The arguments of a theory atom's name: ordinary terms (pools allowed).
    fn theory_name_args(&mut self) -> PResult<Vec<Vec<Term>>> {
        self.bump();
        if self.eat(T::RParen) {
            return Ok(vec![Vec::new()]);
        }
        let mut alts = Vec::new();
        loop {
            let mut terms = Vec::new();
            loop {
                terms.push(self.term()?);
                if !self.eat(T::Comma) {
                    break;
                }
            }
            alts.push(terms);
            if self.eat(T::Semi) {
                continue;
            }
            self.expect(T::RParen, &[")", ";"])?;
            return Ok(alts);
        }
    }

    /// `t1, ..., tn [: condition]` or `: condition`, in theory mode; ends in theory mode.
    fn theory_element(&mut self) -> PResult<TheoryElement> {
        let start = self.tok.start();
        let mut terms = Vec::new();
        if self.at(T::RBrace) {
            return Err(self.unexpected(&[":"]));
        }
        if !self.at(T::Colon) {
            loop {
                terms.push(self.theory_opterm()?);
                if !self.eat(T::Comma) {
                    break;
                }
            }
        }
        let mut condition = Vec::new();
        if self.at(T::Colon) {
            self.theory_mode(false);
            self.bump();
            condition = self.condition(true)?;
            self.theory_mode(true);
        } else if terms.is_empty() {
            return Err(self.unexpected(&[":"]));
        }
        Ok(TheoryElement {
            span: self.span_from(start),
            terms,
            condition,
        })
    }

    /// `op* term (op+ term)*`: the term alone when no operator was written.
    fn theory_opterm(&mut self) -> PResult<TheoryTerm> {
        let start = self.tok.start();
        let mut parts: Vec<(Vec<String>, TheoryTerm)> = Vec::new();
        loop {
            let mut ops = Vec::new();
            while let Some(op) = self.theory_op() {
                ops.push(op);
            }
            if !parts.is_empty() && ops.is_empty() {
                break;
            }
            let term = self.theory_term()?;
            parts.push((ops, term));
            if !(self.at(T::TheoryOp) || self.at(T::Not)) {
                break;
            }
        }
        if parts.len() == 1 && parts[0].0.is_empty() {
            return Ok(parts.pop().expect("one part").1);
        }
        Ok(TheoryTerm {
            span: self.span_from(start),
            kind: TheoryTermKind::Unparsed(parts),
        })
    }

    /// Comma-separated theory terms up to `close` (consumed).
    fn theory_terms_until(&mut self, close: T, expecting: &[&str]) -> PResult<Vec<TheoryTerm>> {
        let mut terms = Vec::new();
        if !self.eat(close) {
            loop {
                terms.push(self.theory_opterm()?);
                if !self.eat(T::Comma) {
                    break;
                }
            }
            self.expect(close, expecting)?;
        }
        Ok(terms)
    }

    /// One theory term without operators at its top.
    fn theory_term(&mut self) -> PResult<TheoryTerm> {
        self.enter()?;
        let start = self.tok.start();
        let fun = self.at(T::Ident) && self.peek().kind == T::LParen;
        let kind = match self.tok.kind {
            T::LBrace => {
                self.bump();
                TheoryTermKind::Set(self.theory_terms_until(T::RBrace, &["\",\"", "}"])?)
            }
            T::LBrack => {
                self.bump();
                TheoryTermKind::List(self.theory_terms_until(T::RBrack, &["\",\"", "]"])?)
            }
            T::LParen => {
                self.bump();
                if self.eat(T::RParen) {
                    TheoryTermKind::Tuple(Vec::new())
                } else {
                    let first = self.theory_opterm()?;
                    if self.eat(T::RParen) {
                        self.leave();
                        return Ok(first);
                    }
                    self.expect(T::Comma, &["\",\"", ")"])?;
                    let mut items = vec![first];
                    items.extend(self.theory_terms_until(T::RParen, &[")"])?);
                    TheoryTermKind::Tuple(items)
                }
            }
            T::Ident if fun => {
                let tok = self.bump();
                let name = self.word(tok).to_string();
                self.bump();
                let args = self.theory_terms_until(T::RParen, &[")"])?;
                TheoryTermKind::Function { name, args }
            }
            _ => TheoryTermKind::Symbol(self.theory_symbol()?),
        };
        self.leave();
        Ok(TheoryTerm {
            span: self.span_from(start),
            kind,
        })
    }

    /// An identifier, number, string, `#inf`, `#sup` or variable, as an ordinary term.
    fn theory_symbol(&mut self) -> PResult<Term> {
        let tok = self.tok;
        let word = self.word(tok);
        let kind = match tok.kind {
            T::Ident => TermKind::Constant(Name::new(word)),
            T::Variable => TermKind::Variable(Name::new(word)),
            T::Number => match integer_value(word) {
                Some(v) => TermKind::Integer(v),
                None => {
                    let span = self.span_of(tok);
                    return Err(self.error(span, "syntax error, integer out of range"));
                }
            },
            T::String => TermKind::String(self.unescape(tok)),
            T::Hash if matches!(word, "#inf" | "#infimum") => TermKind::Infimum,
            T::Hash if matches!(word, "#sup" | "#supremum") => TermKind::Supremum,
            _ => return Err(self.unexpected(&[])),
        };
        self.bump();
        Ok(Term {
            span: self.span_of(tok),
            kind,
        })
    }
}
