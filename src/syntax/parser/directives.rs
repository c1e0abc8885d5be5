//! Statements other than rules: weak constraints, `#minimize`/`#maximize`, `#show`,
//! `#project`, `#const`, `#external`, `#heuristic`, `#edge`, `#include`, `#program` and scripts.
//!
//! Invariant: as in the rest of the parser, every function consumes the tokens of what it
//! returns, or fails after one diagnostic (the statement loop then recovers at the next `.`).

use super::*;

impl<'a> Parser<'a> {
    /// `:~ body. [w@p, terms]`
    pub(super) fn weak_constraint(&mut self) -> PResult<StatementKind> {
        let body = self.neck_body()?;
        self.expect(T::LBrack, &["["])?;
        let (weight, priority, terms) = self.weight_tuple()?;
        self.expect(T::RBrack, &["]"])?;
        Ok(StatementKind::WeakConstraint(Box::new(WeakConstraint {
            body,
            weight,
            priority,
            terms,
        })))
    }

    /// `w[@p] {, t}`
    pub(super) fn weight_tuple(&mut self) -> PResult<(Term, Option<Term>, Vec<Term>)> {
        let weight = self.term()?;
        let priority = self.priority()?;
        let mut terms = Vec::new();
        while self.eat(T::Comma) {
            terms.push(self.term()?);
        }
        Ok((weight, priority, terms))
    }

    /// `[@p]`
    fn priority(&mut self) -> PResult<Option<Term>> {
        Ok(if self.eat(T::At) {
            Some(self.term()?)
        } else {
            None
        })
    }

    /// `#minimize { elements }.`
    pub(super) fn optimize(&mut self, maximize: bool) -> PResult<StatementKind> {
        self.bump();
        self.expect(T::LBrace, &["{"])?;
        let mut elements = Vec::new();
        if !self.at(T::RBrace) {
            loop {
                let start = self.tok.start();
                let (weight, priority, terms) = self.weight_tuple()?;
                let condition = if self.eat(T::Colon) {
                    self.condition(true)?
                } else {
                    Vec::new()
                };
                elements.push(OptimizeElement {
                    span: self.span_from(start),
                    weight,
                    priority,
                    terms,
                    condition,
                });
                if !self.eat(T::Semi) {
                    break;
                }
            }
        }
        self.expect(T::RBrace, &["}", ";"])?;
        self.expect(T::Dot, &["."])?;
        Ok(StatementKind::Optimize(Optimize { maximize, elements }))
    }

    /// `[-]name/arity`
    pub(super) fn signature(&mut self) -> PResult<Signature> {
        let negated = self.eat(T::Minus);
        let name = self.identifier()?;
        self.expect(T::Slash, &["/"])?;
        let n = self.expect(T::Number, &["<NUMBER>"])?;
        let arity = self.integer(n);
        Ok(Signature {
            negated,
            name,
            arity: u32::try_from(arity).unwrap_or(u32::MAX),
        })
    }

    /// `#show.`, `#show p/n.`, `#show t : body.`
    pub(super) fn show(&mut self) -> PResult<StatementKind> {
        self.bump();
        if self.eat(T::Dot) {
            return Ok(StatementKind::Show(Box::new(Show::Nothing)));
        }
        let term = self.term()?;
        let body = self.directive_body()?;
        if body.is_empty() {
            if let Some(sig) = term_to_signature(&term) {
                return Ok(StatementKind::Show(Box::new(Show::Signature(sig))));
            }
        }
        Ok(StatementKind::Show(Box::new(Show::Term { term, body })))
    }

    /// `#project p/n.` or `#project atom : body.`
    pub(super) fn project(&mut self) -> PResult<StatementKind> {
        self.bump();
        let term = self.term()?;
        if let Some(sig) = term_to_signature(&term) {
            self.expect(T::Dot, &["."])?;
            return Ok(StatementKind::Project(Box::new(Project::Signature(sig))));
        }
        let atom = self.atom_of(term)?;
        let body = self.directive_body()?;
        Ok(StatementKind::Project(Box::new(Project::Atom {
            atom,
            body,
        })))
    }

    /// The atom a parsed term denotes, or an error at the current token.
    pub(super) fn atom_of(&mut self, term: Term) -> PResult<SymbolicAtom> {
        match term_to_atom(term) {
            Ok(atom) => Ok(atom),
            Err(_) => Err(self.unexpected(&[])),
        }
    }

    /// `[: body] .`
    pub(super) fn directive_body(&mut self) -> PResult<Vec<BodyLiteral>> {
        self.body_end = &[];
        let body = if self.eat(T::Colon) {
            self.body()?
        } else {
            Vec::new()
        };
        self.end_of_body()?;
        Ok(body)
    }

    /// `#const name = term. [default|override]`
    pub(super) fn const_def(&mut self) -> PResult<StatementKind> {
        self.bump();
        let name = self.identifier()?;
        self.expect(T::Eq, &["="])?;
        let value = self.term()?;
        self.expect(T::Dot, &[])?;
        let mut kind = ConstKind::Default;
        let mut annotated = false;
        if self.at(T::LBrack) {
            self.bump();
            let word = self.expect(T::Ident, &["<IDENTIFIER>"])?;
            kind = match self.word(word) {
                "default" => ConstKind::Default,
                "override" => ConstKind::Override,
                _ => {
                    let span = self.span_of(word);
                    return Err(self.error(
                        span,
                        "syntax error, unexpected <IDENTIFIER>, expecting default or override",
                    ));
                }
            };
            annotated = true;
            self.expect(T::RBrack, &["]"])?;
        }
        Ok(StatementKind::Const(Box::new(ConstDef {
            name,
            value,
            kind,
            annotated,
        })))
    }

    /// `#external atom : body. [value]`
    pub(super) fn external(&mut self) -> PResult<StatementKind> {
        self.bump();
        let term = self.term()?;
        let atom = self.atom_of(term)?;
        let body = self.directive_body()?;
        let value = if self.at(T::LBrack) {
            self.bump();
            let v = self.term()?;
            self.expect(T::RBrack, &["]"])?;
            Some(v)
        } else {
            None
        };
        Ok(StatementKind::External(Box::new(External {
            atom,
            body,
            value,
        })))
    }

    /// `#heuristic atom : body. [w@p, modifier]`
    pub(super) fn heuristic(&mut self) -> PResult<StatementKind> {
        self.bump();
        let term = self.term()?;
        let atom = self.atom_of(term)?;
        let body = self.directive_body()?;
        self.expect(T::LBrack, &["["])?;
        let weight = self.term()?;
        let priority = self.priority()?;
        self.expect(T::Comma, &["\",\""])?;
        let modifier = self.term()?;
        self.expect(T::RBrack, &["]"])?;
        Ok(StatementKind::Heuristic(Box::new(Heuristic {
            atom,
            body,
            weight,
            priority,
            modifier,
        })))
    }

    /// `#edge (u, v) : body.`
    pub(super) fn edge(&mut self) -> PResult<StatementKind> {
        self.bump();
        self.expect(T::LParen, &["("])?;
        let from = self.term()?;
        self.expect(T::Comma, &["\",\""])?;
        let to = self.term()?;
        self.expect(T::RParen, &[")"])?;
        let body = self.directive_body()?;
        Ok(StatementKind::Edge(Box::new(Edge { from, to, body })))
    }

    /// `#include "file".` or `#include <name>.`
    pub(super) fn include(&mut self) -> PResult<StatementKind> {
        self.bump();
        let include = if self.at(T::String) {
            let tok = self.bump();
            Include {
                path: self.unescape(tok),
                system: false,
            }
        } else if self.eat(T::Lt) {
            let path = self.identifier()?;
            self.expect(T::Gt, &[">"])?;
            Include { path, system: true }
        } else {
            return Err(self.unexpected(&["<STRING>", "<"]));
        };
        self.expect(T::Dot, &["."])?;
        Ok(StatementKind::Include(include))
    }

    /// `#program name(params).`
    pub(super) fn program_part(&mut self) -> PResult<StatementKind> {
        self.bump();
        let name = self.identifier()?;
        let mut params = Vec::new();
        if self.eat(T::LParen) {
            if !self.at(T::RParen) {
                loop {
                    params.push(self.identifier()?);
                    if !self.eat(T::Comma) {
                        break;
                    }
                }
            }
            self.expect(T::RParen, &[")", "\",\""])?;
        }
        self.expect(T::Dot, &["."])?;
        Ok(StatementKind::ProgramPart(ProgramPart { name, params }))
    }

    /// `#script (lang) code #end.`
    pub(super) fn script(&mut self) -> PResult<StatementKind> {
        let start = self.bump();
        let span = self.span_of(start);
        self.report_script(span);
        self.expect(T::LParen, &["("])?;
        let language = self.identifier()?;
        if !self.at(T::RParen) {
            return Err(self.unexpected(&[")"]));
        }
        // The code is raw text: the lexer rewinds to just after `)` and scans for `#end.`.
        match self.script_body() {
            Some((s, e)) => {
                let code = self.text[s..e].to_string();
                Ok(StatementKind::Script(Script { language, code }))
            }
            None => Err(self.unexpected(&["#end"])),
        }
    }
}
