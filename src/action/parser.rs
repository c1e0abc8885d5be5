//! The AL_d parser: text of one `.ald` file to a [`Description`] and diagnostics.
//!
//! Role: the statements of grammar/action.ebnf, by recursive descent in methods (private to
//! this module) on the syntax parser's `Cursor` (`syntax/parser/cursor.rs`): the clingo
//! dialect's tokens, positions, gringo-worded errors and nesting cap, and its term grammar in
//! the `TermGrammar::Arithmetic` form; literals are terms of an atom's shape, as the clingo
//! parser reads them (`term_to_atom`). AL_d keywords (`causes`, `if`, `impossible`, ...) are
//! identifiers recognised by their text where the grammar expects them.
//!
//! Invariants:
//! - Parsing never fails: a statement that does not parse is reported in gringo's form
//!   (`syntax error, unexpected X, expecting Y`), kept as [`StatementKind::Error`], and parsing
//!   resumes after the next period.
//! - Every loop consumes a token per iteration or stops at end of input; nesting is capped by
//!   the cursor, so no input makes the parser spin or overflow.
//! - Spans lie inside the text (they come from the lexer's tokens).

use crate::base::{Diagnostic, FileId, Span};
use crate::syntax::ast::{Dialect, Term, TermKind, UnaryOp};
use crate::syntax::lexer::{Token, TokenKind as T};
use crate::syntax::parser::{cmp_op, term_to_atom, Cursor, PResult, TermGrammar};

use super::ast::*;

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
    let mut cursor = Cursor::new(file, text, Dialect::Clingo, TermGrammar::Arithmetic);
    let statements = cursor.description();
    Parse {
        description: Description { statements },
        diagnostics: cursor.diags,
    }
}

/// What a statement keyword leads to: the rest of the statement after the keyword.
type Rest<'a> = fn(&mut Cursor<'a>) -> PResult<StatementKind>;

/// The AL_d statements, read on the shared cursor (these methods are private to this module).
impl<'a> Cursor<'a> {
    /// Every statement of the file.
    fn description(&mut self) -> Vec<Statement> {
        let mut statements = Vec::new();
        while !self.at(T::Eof) {
            let start = self.tok.start();
            self.depth = 0;
            let statement = self.statement();
            let st = statement.unwrap_or_else(|_| {
                // Resume after the next period; this consumes at least one token.
                self.recover();
                Statement {
                    span: self.span_from(start),
                    guards: Vec::new(),
                    label: None,
                    kind: StatementKind::Error,
                }
            });
            statements.push(st);
        }
        statements
    }

    /// The name a token spells.
    fn name_of(&self, tok: Token) -> Name {
        Name {
            span: self.span_of(tok),
            text: self.word(tok).to_string(),
        }
    }

    /// A name token (identifier or variable), as labels are written.
    fn name(&mut self, what: &[&str]) -> PResult<Name> {
        if matches!(self.tok.kind, T::Ident | T::Variable) {
            let tok = self.bump();
            Ok(self.name_of(tok))
        } else {
            Err(self.unexpected(what))
        }
    }

    /// An identifier that is not a keyword.
    fn ident(&mut self) -> PResult<Name> {
        if !self.at(T::Ident) {
            return Err(self.unexpected(&["<IDENTIFIER>"]));
        }
        let tok = self.bump();
        let word = self.word(tok);
        if KEYWORDS.contains(&word) {
            let msg = format!("syntax error, unexpected keyword {word}, expecting <IDENTIFIER>");
            let span = self.span_of(tok);
            return Err(self.error(span, msg));
        }
        Ok(self.name_of(tok))
    }

    fn statement(&mut self) -> PResult<Statement> {
        let start = self.tok.start();
        let mut guards = Vec::new();
        while self.at(T::LBrack) {
            let open = self.bump();
            let negated = self.eat(T::Not) || self.eat_word("not");
            let switch = self.ident()?;
            self.expect(T::RBrack, &["\"]\""])?;
            guards.push(Guard {
                span: self.span_from(open.start()),
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

    /// A statement after its guards and label: by its keyword, or a law.
    fn statement_kind(&mut self) -> PResult<StatementKind> {
        let keyword = if self.at(T::Ident) { self.cur() } else { "" };
        let rest: Rest<'a> = match keyword {
            "sort" => Cursor::sort_definition,
            "static" => |p| p.declaration(DeclKind::Static),
            "inertial" => |p| p.fluent_declaration(DeclKind::Inertial),
            "defined" => |p| p.fluent_declaration(DeclKind::Defined { cwa: true }),
            "action" => |p| p.declaration(DeclKind::Action),
            "impossible" => |p| {
                let (action, body) = (p.atom()?, p.opt_body()?);
                Ok(StatementKind::Impossible { action, body })
            },
            "normally" => |p| {
                let (head, body) = (p.literal()?, p.opt_body()?);
                Ok(StatementKind::Default { head, body })
            },
            "exception" => Cursor::exception,
            "never" => |p| {
                let (lit, body) = (p.literal()?, p.opt_body()?);
                Ok(StatementKind::Never { lit, body })
            },
            "goal" => |p| Ok(StatementKind::Goal { body: p.body()? }),
            "observed" => |p| {
                let (lit, step) = (p.literal()?, p.at_step()?);
                Ok(StatementKind::Observed { lit, step })
            },
            "happened" => |p| {
                let (action, step) = (p.atom()?, p.at_step()?);
                Ok(StatementKind::Happened { action, step })
            },
            "initially" => Cursor::initially,
            "switch" => |p| {
                let (name, value) = p.setting()?;
                Ok(StatementKind::Switch { name, value })
            },
            "set" => |p| {
                let (name, value) = p.setting()?;
                Ok(StatementKind::Set { name, value })
            },
            "profile" => Cursor::profile,
            "include" => Cursor::include,
            _ => return self.law(),
        };
        self.bump();
        rest(self)
    }

    /// `a causes l [if ...]` or `l [if ...]`.
    fn law(&mut self) -> PResult<StatementKind> {
        let head = self.literal()?;
        if !self.eat_word("causes") {
            let body = self.opt_body()?;
            return Ok(StatementKind::Constraint { head, body });
        }
        if head.negated {
            return Err(self.error(head.span, "an action cannot be negated in a causal law"));
        }
        let (effect, body) = (self.literal()?, self.opt_body()?);
        Ok(StatementKind::Causal {
            action: head.atom,
            effect,
            body,
        })
    }

    /// `name = sort_part {+ sort_part}` after `sort`.
    fn sort_definition(&mut self) -> PResult<StatementKind> {
        let name = self.ident()?;
        self.expect(T::Eq, &["\"=\""])?;
        let expr = self.sort_expr()?;
        Ok(StatementKind::Sort { name, expr })
    }

    /// `fluent signature [without cwa]` after `inertial` or `defined`.
    fn fluent_declaration(&mut self, kind: DeclKind) -> PResult<StatementKind> {
        self.expect_word("fluent")?;
        self.declaration(kind)
    }

    /// `to label: l may be assumed [if ...]` after `exception`.
    fn exception(&mut self) -> PResult<StatementKind> {
        self.expect_word("to")?;
        let default = self.name(&["<IDENTIFIER>", "<VARIABLE>"])?;
        self.expect(T::Colon, &["\":\""])?;
        let head = self.literal()?;
        for word in ["may", "be", "assumed"] {
            self.expect_word(word)?;
        }
        let body = self.opt_body()?;
        Ok(StatementKind::Exception {
            default,
            head,
            body,
        })
    }

    /// `normally false [except names]` or `l` after `initially`.
    fn initially(&mut self) -> PResult<StatementKind> {
        if !self.eat_word("normally") {
            let lit = self.literal()?;
            return Ok(StatementKind::Initially { lit });
        }
        self.expect_word("false")?;
        let mut except = Vec::new();
        if self.eat_word("except") {
            except = self.identifiers()?;
        }
        Ok(StatementKind::InitialDefault { except })
    }

    /// `name = value` after `switch` or `set`.
    fn setting(&mut self) -> PResult<(Name, Value)> {
        let name = self.ident()?;
        self.expect(T::Eq, &["\"=\""])?;
        Ok((name, self.value()?))
    }

    /// `name: item {, item}` after `profile`.
    fn profile(&mut self) -> PResult<StatementKind> {
        let name = self.ident()?;
        self.expect(T::Colon, &["\":\""])?;
        let mut items = vec![self.profile_item()?];
        while self.eat(T::Comma) {
            items.push(self.profile_item()?);
        }
        Ok(StatementKind::Profile { name, items })
    }

    /// `"path"` after `include` (the text between the quotes, as written).
    fn include(&mut self) -> PResult<StatementKind> {
        let tok = self.expect(T::String, &["<STRING>"])?;
        let raw = self.word(tok);
        let path = raw[1..raw.len() - 1].to_string();
        Ok(StatementKind::Include { path })
    }

    /// `name {, name}`
    fn identifiers(&mut self) -> PResult<Vec<Name>> {
        let mut names = vec![self.ident()?];
        while self.eat(T::Comma) {
            names.push(self.ident()?);
        }
        Ok(names)
    }

    /// `at step`
    fn at_step(&mut self) -> PResult<Term> {
        self.expect_word("at")?;
        self.term()
    }

    fn declaration(&mut self, kind: DeclKind) -> PResult<StatementKind> {
        let name = self.ident()?;
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
            return Ok(match self.word(tok) {
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
            let name = self.ident()?;
            return Ok(ProfileItem::Set {
                name,
                value: Value::Bool(false),
            });
        }
        let name = self.ident()?;
        let value = if self.eat(T::Eq) {
            self.value()?
        } else {
            Value::Bool(true)
        };
        Ok(ProfileItem::Set { name, value })
    }

    fn sort_expr(&mut self) -> PResult<SortExpr> {
        let start = self.tok.start();
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
            return Ok(SortPart::Name(self.ident()?));
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
        let start = self.tok.start();
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
        match lit_of(term) {
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
        match lit_of(term) {
            Some(lit) => Ok(lit),
            None => {
                let span = self.span_from(self.prev_end);
                Err(self.error(
                    span,
                    "syntax error, expecting a literal (a name with optional arguments)",
                ))
            }
        }
    }

    /// An atom `p(t1, ..., tn)` (no negation).
    fn atom(&mut self) -> PResult<Atom> {
        let lit = self.literal()?;
        if lit.negated {
            return Err(self.error(lit.span, "an action cannot be negated"));
        }
        Ok(lit.atom)
    }
}

/// Reads a term as a literal: a constant or a function whose name is not a keyword, either
/// under unary minus.
fn lit_of(term: Term) -> Option<Lit> {
    let atom_span = match &term.kind {
        TermKind::Unary {
            op: UnaryOp::Minus,
            arg,
        } => arg.span,
        _ => term.span,
    };
    let mut atom = term_to_atom(term).ok()?;
    if KEYWORDS.contains(&atom.name.as_str()) || atom.args.len() != 1 {
        return None;
    }
    let name_end = atom_span.start + atom.name.len() as u32;
    Some(Lit {
        span: atom.span,
        negated: atom.negated,
        atom: Atom {
            span: atom_span,
            name: Name {
                span: Span::new(atom_span.file, atom_span.start, name_end),
                text: atom.name.to_string(),
            },
            args: atom.args.pop().unwrap_or_default(),
        },
    })
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
