//! The parser: tokens to the syntax tree of [`super::ast`], by hand-written recursive descent
//! with precedence climbing for terms and sort expressions.
//!
//! Role: reads the clingo dialect (with CR rules `[label:] head :+ body.`) and SPARC sorted
//! programs. The grammar it implements is `grammar/asp.ebnf` and `grammar/sparc.ebnf`.
//!
//! Invariants:
//! - Parsing never fails and never panics: every statement either parses or becomes a
//!   [`StatementKind::Error`] after one diagnostic worded as gringo words it (`syntax error,
//!   unexpected X[, expecting ...]`); the parser then skips to the `.` that ends the statement
//!   and goes on.
//! - Every loop consumes a token per iteration or stops; the statement loop asserts progress.
//! - Nesting (parentheses, unary operators, operator chains, aggregates) is capped at
//!   [`MAX_DEPTH`] levels, so hostile input cannot overflow the stack.
//! - Embedded scripts (`#script`, `@f(...)`) are parsed and kept, and reported once per file
//!   with a single "unsupported" error.
//! - Memory is proportional to the input: tokens are produced on demand (one token of
//!   lookahead beyond the current one), and the tree owns its strings.

use crate::base::{Diagnostic, FileId, Span};

use super::ast::*;
use super::lexer::{describe, Lexer, Token, TokenKind as T};

/// Deepest nesting of terms, aggregates and sort expressions the parser accepts. 256 levels
/// keep the parser, the printer and the span walk well inside a 2 MiB thread stack (the size of
/// test threads) even in unoptimized builds, where one level costs about 5 KiB of stack.
pub const MAX_DEPTH: u32 = 256;

/// The message of the single diagnostic reported for embedded scripts.
pub const UNSUPPORTED_SCRIPT: &str =
    "embedded scripts (#script, @f(...)) are not supported by lucent";

/// The result of parsing one file: the tree and every diagnostic.
#[derive(Clone, Debug)]
pub struct Parse {
    /// The statements that were read (failed ones as [`StatementKind::Error`]).
    pub program: Program,
    /// Lexer and syntax errors, in source order.
    pub diagnostics: Vec<Diagnostic>,
}

impl Parse {
    /// True when some diagnostic is an error.
    pub fn has_errors(&self) -> bool {
        self.diagnostics.iter().any(|d| d.is_error())
    }
}

/// Parses `text` (the contents of `file`) as `dialect`.
pub fn parse(file: FileId, text: &str, dialect: Dialect) -> Parse {
    if text.len() >= u32::MAX as usize {
        return Parse {
            program: Program {
                dialect,
                statements: Vec::new(),
            },
            diagnostics: vec![Diagnostic::error(
                Span::new(file, 0, 0),
                "input too large: files of 4 GiB or more are not supported",
            )],
        };
    }
    let mut parser = Parser::new(file, text, dialect);
    parser.program();
    Parse {
        program: Program {
            dialect,
            statements: parser.statements,
        },
        diagnostics: parser.diags,
    }
}

/// Parses `text`, choosing the dialect with [`detect_dialect`].
pub fn parse_auto(file: FileId, text: &str) -> Parse {
    parse(file, text, detect_dialect(text))
}

/// SPARC when the first token after comments and leading `#const` and `#maxint` statements is the section
/// keyword `sorts`; the clingo dialect otherwise.
pub fn detect_dialect(text: &str) -> Dialect {
    let mut lexer = Lexer::new(FileId(0), text, Dialect::Sparc);
    let mut sink = Vec::new();
    loop {
        let tok = lexer.next_token(&mut sink);
        sink.clear();
        let word = &text[tok.start as usize..tok.end as usize];
        match tok.kind {
            T::Hash if word == "#const" || word == "#maxint" => loop {
                let t = lexer.next_token(&mut sink);
                sink.clear();
                if matches!(t.kind, T::Dot | T::Eof) {
                    break;
                }
            },
            T::Ident if word == "sorts" => {
                let next = lexer.next_token(&mut sink);
                let next_word = &text[next.start as usize..next.end as usize];
                let sparc = matches!(next.kind, T::Hash | T::Eof)
                    || (next.kind == T::Ident && next_word == "predicates");
                return if sparc {
                    Dialect::Sparc
                } else {
                    Dialect::Clingo
                };
            }
            _ => return Dialect::Clingo,
        }
    }
}

/// Marks a statement that failed; its diagnostic has been reported.
struct Failed;

/// Result of a parsing step.
type PResult<T> = Result<T, Failed>;

/// Which kind of statement context a literal is parsed in.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Ctx {
    /// Comparison chains are allowed (bodies and conditions).
    Chain,
    /// One comparison at most (heads, display items).
    Single,
}

/// The parser state for one file.
struct Parser<'a> {
    /// The token source.
    lexer: Lexer<'a>,
    /// The text, for token contents.
    text: &'a str,
    /// The file spans point into.
    file: FileId,
    /// The surface language.
    dialect: Dialect,
    /// The current token.
    tok: Token,
    /// The token after the current one, once looked at.
    peeked: Option<Token>,
    /// End of the last consumed token.
    prev_end: u32,
    /// Diagnostics so far.
    diags: Vec<Diagnostic>,
    /// Statements so far.
    statements: Vec<Statement>,
    /// Current nesting depth.
    depth: u32,
    /// True once the unsupported-script diagnostic was reported.
    script_reported: bool,
    /// The current SPARC section, if any.
    section: Option<Section>,
    /// SPARC sort names defined so far (with `#`): a defined sort may be named like a clingo
    /// directive (`#program`), and is then read as a sort.
    sort_names: std::collections::HashSet<String>,
    /// What gringo lists as expected after the last body element (its LALR states differ by
    /// the kind of element), used when the closing `.` is missing.
    body_end: &'static [&'static str],
}

/// Expected after a body aggregate.
const AFTER_AGGREGATE: &[&str] = &["\",\"", ".", ";"];
/// Expected after a comparison or a Boolean constant.
const AFTER_BUILTIN: &[&str] = &[":", "\",\"", ".", ";"];
/// Expected after a condition ending in a comparison.
const AFTER_CONDITION: &[&str] = &[".", ";"];

/// Aggregate function of a token, if it is `#count`, `#sum`, `#sum+`, `#min` or `#max`.
fn aggregate_function(kind: T, word: &str) -> Option<AggregateFunction> {
    match (kind, word) {
        (T::SumPlus, _) => Some(AggregateFunction::SumPlus),
        (T::Hash, "#count") => Some(AggregateFunction::Count),
        (T::Hash, "#sum") => Some(AggregateFunction::Sum),
        (T::Hash, "#min") => Some(AggregateFunction::Min),
        (T::Hash, "#max") => Some(AggregateFunction::Max),
        _ => None,
    }
}

/// Comparison operator of a token.
fn cmp_op(kind: T) -> Option<CmpOp> {
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

/// `#name`s that are clingo keywords rather than SPARC sort names.
fn is_keyword_hash(word: &str) -> bool {
    matches!(
        word,
        "#count"
            | "#sum"
            | "#min"
            | "#max"
            | "#true"
            | "#false"
            | "#inf"
            | "#sup"
            | "#infimum"
            | "#supremum"
            | "#const"
            | "#show"
            | "#minimize"
            | "#maximize"
            | "#minimise"
            | "#maximise"
            | "#defined"
            | "#project"
            | "#external"
            | "#heuristic"
            | "#edge"
            | "#include"
            | "#program"
            | "#script"
            | "#end"
            | "#maxint"
    )
}

/// The SPARC section named by `word`.
fn section_of(word: &str) -> Option<Section> {
    Some(match word {
        "sorts" => Section::Sorts,
        "predicates" => Section::Predicates,
        "rules" => Section::Rules,
        "display" => Section::Display,
        _ => return None,
    })
}

/// Position of a section in the fixed order of SPARC sections.
fn section_rank(section: Option<Section>) -> u8 {
    match section {
        None => 0,
        Some(Section::Sorts) => 1,
        Some(Section::Predicates) => 2,
        Some(Section::Rules) => 3,
        Some(Section::Display) => 4,
    }
}

/// The symbolic atom a term denotes, if it has the shape of one: `p`, `p(...)`, `-p(...)`.
/// Takes the term by value so names and arguments move instead of being copied; a term of
/// another shape is handed back.
pub(crate) fn term_to_atom(term: Term) -> Result<SymbolicAtom, Term> {
    let is_atom = |t: &Term| match &t.kind {
        TermKind::Constant(_) => true,
        TermKind::Function { name, .. } => !name.is_empty(),
        _ => false,
    };
    let shaped = match &term.kind {
        TermKind::Unary {
            op: UnaryOp::Minus,
            arg,
        } => is_atom(arg),
        _ => is_atom(&term),
    };
    if !shaped {
        return Err(term);
    }
    let span = term.span;
    let (negated, inner) = match term.kind {
        TermKind::Unary { arg, .. } => (true, *arg),
        kind => (false, Term { span, kind }),
    };
    let (name, args) = match inner.kind {
        TermKind::Constant(name) => (name, vec![Vec::new()]),
        TermKind::Function { name, args, .. } => (name, args),
        _ => unreachable!("checked to be an atom's shape above"),
    };
    Ok(SymbolicAtom {
        span,
        negated,
        name,
        args,
    })
}

/// The signature a term denotes, if it has the shape `name/n` or `-name/n`.
fn term_to_signature(term: &Term) -> Option<Signature> {
    let TermKind::Binary {
        op: BinaryOp::Div,
        lhs,
        rhs,
    } = &term.kind
    else {
        return None;
    };
    let TermKind::Integer(arity) = rhs.kind else {
        return None;
    };
    let (negated, name) = match &lhs.kind {
        TermKind::Constant(name) => (false, name),
        TermKind::Unary {
            op: UnaryOp::Minus,
            arg,
        } => match &arg.kind {
            TermKind::Constant(name) => (true, name),
            _ => return None,
        },
        _ => return None,
    };
    Some(Signature {
        negated,
        name: name.clone(),
        arity: u32::try_from(arity).ok()?,
    })
}

impl<'a> Parser<'a> {
    /// A parser at the start of `text`.
    fn new(file: FileId, text: &'a str, dialect: Dialect) -> Parser<'a> {
        let mut lexer = Lexer::new(file, text, dialect);
        let mut diags = Vec::new();
        let tok = lexer.next_token(&mut diags);
        Parser {
            lexer,
            text,
            file,
            dialect,
            tok,
            peeked: None,
            prev_end: 0,
            diags,
            statements: Vec::new(),
            depth: 0,
            script_reported: false,
            section: None,
            sort_names: std::collections::HashSet::new(),
            body_end: &[],
        }
    }

    // ----- token plumbing -----

    /// The text of a token.
    fn word(&self, tok: Token) -> &'a str {
        &self.text[tok.start as usize..tok.end as usize]
    }

    /// The text of the current token.
    fn cur(&self) -> &'a str {
        self.word(self.tok)
    }

    /// A span in this file.
    fn span(&self, start: u32, end: u32) -> Span {
        Span::new(self.file, start, end.max(start))
    }

    /// The span from `start` to the end of the last consumed token.
    fn span_from(&self, start: u32) -> Span {
        self.span(start, self.prev_end)
    }

    /// Consumes the current token and returns it.
    fn bump(&mut self) -> Token {
        let tok = self.tok;
        self.prev_end = tok.end;
        self.tok = match self.peeked.take() {
            Some(t) => t,
            None => self.lexer.next_token(&mut self.diags),
        };
        tok
    }

    /// The token after the current one.
    fn peek(&mut self) -> Token {
        if let Some(t) = self.peeked {
            return t;
        }
        let t = self.lexer.next_token(&mut self.diags);
        self.peeked = Some(t);
        t
    }

    /// True when the current token is `kind`.
    fn at(&self, kind: T) -> bool {
        self.tok.kind == kind
    }

    /// Consumes the current token when it is `kind`.
    fn eat(&mut self, kind: T) -> bool {
        if self.at(kind) {
            self.bump();
            true
        } else {
            false
        }
    }

    /// Reports `syntax error, unexpected X[, expecting a or b]` at the current token.
    fn unexpected(&mut self, expecting: &[&str]) -> Failed {
        let mut msg = format!(
            "syntax error, unexpected {}",
            describe(self.tok.kind, self.cur())
        );
        if !expecting.is_empty() {
            msg.push_str(", expecting ");
            msg.push_str(&expecting.join(" or "));
        }
        let span = self.span(self.tok.start, self.tok.end);
        self.diags.push(Diagnostic::error(span, msg));
        Failed
    }

    /// Consumes a token of kind `kind` or reports it missing.
    fn expect(&mut self, kind: T, expecting: &[&str]) -> PResult<Token> {
        if self.at(kind) {
            Ok(self.bump())
        } else {
            Err(self.unexpected(expecting))
        }
    }

    /// Enters one nesting level; reports when the cap is exceeded.
    fn enter(&mut self) -> PResult<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            let span = self.span(self.tok.start, self.tok.end);
            self.diags.push(Diagnostic::error(
                span,
                format!("syntax error, nesting deeper than {MAX_DEPTH} levels"),
            ));
            return Err(Failed);
        }
        Ok(())
    }

    /// Leaves one nesting level.
    fn leave(&mut self) {
        self.depth -= 1;
    }

    /// Reports embedded scripts once per file.
    fn report_script(&mut self, span: Span) {
        if !self.script_reported {
            self.script_reported = true;
            self.diags.push(Diagnostic::error(span, UNSUPPORTED_SCRIPT));
        }
    }

    /// True when the current token is an aggregate function keyword.
    fn at_aggregate(&self) -> bool {
        aggregate_function(self.tok.kind, self.cur()).is_some()
    }

    /// True when the current token is a SPARC sort name `#s`: not a clingo keyword, or a
    /// sort defined under a keyword's name.
    fn at_sort_name(&self) -> bool {
        self.dialect == Dialect::Sparc
            && self.at(T::Hash)
            && (!is_keyword_hash(self.cur()) || self.sort_names.contains(self.cur()))
    }

    /// True when the token can start a term.
    fn starts_term(&self, tok: Token) -> bool {
        match tok.kind {
            T::Ident | T::Variable | T::Anonymous | T::Number | T::String | T::LParen => true,
            T::Minus | T::Tilde | T::At | T::Bar => true,
            T::Hash => matches!(self.word(tok), "#inf" | "#sup" | "#infimum" | "#supremum"),
            _ => false,
        }
    }

    /// True when the current token can start a literal (so a condition is not empty).
    fn starts_literal(&self) -> bool {
        match self.tok.kind {
            T::Not => true,
            T::Bar => false,
            T::Hash => {
                matches!(self.cur(), "#true" | "#false") || self.at_sort_name() || {
                    self.starts_term(self.tok)
                }
            }
            _ => self.starts_term(self.tok),
        }
    }

    // ----- statements -----

    /// Parses every statement of the file.
    fn program(&mut self) {
        while !self.at(T::Eof) {
            let start = self.tok.start;
            let before = self.lexer.pos();
            self.depth = 0;
            let kind = match self.statement() {
                Ok(kind) => kind,
                Err(Failed) => {
                    self.recover();
                    StatementKind::Error
                }
            };
            let span = self.span_from(start);
            self.statements.push(Statement { span, kind });
            debug_assert!(
                self.lexer.pos() > before || self.at(T::Eof),
                "the parser made no progress"
            );
        }
    }

    /// Skips to just after the next `.` (or to the end of input).
    fn recover(&mut self) {
        while !self.at(T::Eof) {
            if self.bump().kind == T::Dot {
                return;
            }
        }
    }

    /// One statement.
    fn statement(&mut self) -> PResult<StatementKind> {
        if self.dialect == Dialect::Sparc {
            if let Some(kind) = self.sparc_statement()? {
                return Ok(kind);
            }
        }
        match self.tok.kind {
            T::If => {
                self.bump();
                let body = self.body()?;
                self.end_of_body()?;
                Ok(StatementKind::Rule(Rule {
                    head: Head::None,
                    body,
                    kind: RuleKind::Normal,
                }))
            }
            T::CrIf => {
                self.bump();
                let body = self.body()?;
                self.end_of_body()?;
                Ok(StatementKind::Rule(Rule {
                    head: Head::None,
                    body,
                    kind: RuleKind::ConsistencyRestoring { label: None },
                }))
            }
            T::WeakIf => self.weak_constraint(),
            T::Hash => match self.cur() {
                "#minimize" | "#minimise" => self.optimize(false),
                "#maximize" | "#maximise" => self.optimize(true),
                "#show" => self.show(),
                "#defined" => {
                    self.bump();
                    let sig = self.signature()?;
                    self.expect(T::Dot, &["."])?;
                    Ok(StatementKind::Defined(sig))
                }
                "#project" => self.project(),
                "#const" => self.const_def(),
                "#external" => self.external(),
                "#heuristic" => self.heuristic(),
                "#edge" => self.edge(),
                "#include" => self.include(),
                "#program" => self.program_part(),
                "#script" => self.script(),
                "#count" | "#sum" | "#min" | "#max" | "#true" | "#false" | "#inf" | "#sup"
                | "#infimum" | "#supremum" => self.rule(),
                _ => Err(self.unexpected(&[])),
            },
            _ => self.rule(),
        }
    }

    /// SPARC statements that differ from the clingo dialect: section headers, sort
    /// definitions, predicate declarations and display items. `None` for ordinary statements.
    fn sparc_statement(&mut self) -> PResult<Option<StatementKind>> {
        if self.at(T::Ident) {
            if let Some(section) = section_of(self.cur()) {
                if section_rank(Some(section)) > section_rank(self.section) {
                    self.bump();
                    self.section = Some(section);
                    return Ok(Some(StatementKind::Section(section)));
                }
            }
        }
        if self.at(T::Hash) && self.cur() == "#const" {
            return Ok(None);
        }
        if self.at(T::Hash)
            && self.cur() == "#maxint"
            && matches!(self.section, None | Some(Section::Sorts))
        {
            self.bump();
            self.expect(T::Eq, &["="])?;
            let value = self.term()?;
            self.expect(T::Dot, &["."])?;
            return Ok(Some(StatementKind::MaxInt(Box::new(value))));
        }
        match self.section {
            Some(Section::Sorts) => self.sort_def().map(Some),
            Some(Section::Predicates) => self.predicate_decl().map(Some),
            Some(Section::Rules) if self.at_sort_name() => self.rule().map(Some),
            Some(Section::Display) => {
                if self.at_sort_name() && self.peek().kind == T::Dot {
                    let tok = self.bump();
                    self.bump();
                    return Ok(Some(StatementKind::DisplaySort(
                        self.word(tok)[1..].to_string(),
                    )));
                }
                let mut lits = Vec::with_capacity(1);
                self.literal(Ctx::Single, &mut lits)?;
                self.expect(T::Dot, &["."])?;
                Ok(Some(StatementKind::Display(Box::new(lits.remove(0)))))
            }
            None if self.at_sort_name() => self.sort_def().map(Some),
            _ => Ok(None),
        }
    }

    /// A fact, rule or CR rule.
    fn rule(&mut self) -> PResult<StatementKind> {
        let (head, first_term) = self.head()?;
        match self.tok.kind {
            T::Dot => {
                self.bump();
                Ok(StatementKind::Rule(Rule {
                    head,
                    body: Vec::new(),
                    kind: RuleKind::Normal,
                }))
            }
            T::If => {
                self.bump();
                let body = self.body()?;
                self.end_of_body()?;
                Ok(StatementKind::Rule(Rule {
                    head,
                    body,
                    kind: RuleKind::Normal,
                }))
            }
            T::CrIf => {
                self.bump();
                let body = self.body()?;
                self.end_of_body()?;
                let (head, label) = split_label(head, first_term);
                Ok(StatementKind::Rule(Rule {
                    head,
                    body,
                    kind: RuleKind::ConsistencyRestoring {
                        label: label.map(Box::new),
                    },
                }))
            }
            _ => {
                let expecting: &[&str] = match head {
                    Head::Choice(_) | Head::Aggregate(_) => &[".", ":-"],
                    _ => &[],
                };
                Err(self.unexpected(expecting))
            }
        }
    }

    /// Expects the `.` that ends a body, with gringo's wording when it is missing.
    fn end_of_body(&mut self) -> PResult<()> {
        let expecting = self.body_end;
        self.expect(T::Dot, expecting)?;
        Ok(())
    }

    /// `:~ body. [w@p, terms]`
    fn weak_constraint(&mut self) -> PResult<StatementKind> {
        self.bump();
        let body = self.body()?;
        self.end_of_body()?;
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
    fn weight_tuple(&mut self) -> PResult<(Term, Option<Term>, Vec<Term>)> {
        let weight = self.term()?;
        let priority = if self.eat(T::At) {
            Some(self.term()?)
        } else {
            None
        };
        let mut terms = Vec::new();
        while self.eat(T::Comma) {
            terms.push(self.term()?);
        }
        Ok((weight, priority, terms))
    }

    /// `#minimize { elements }.`
    fn optimize(&mut self, maximize: bool) -> PResult<StatementKind> {
        self.bump();
        self.expect(T::LBrace, &["{"])?;
        let mut elements = Vec::new();
        if !self.at(T::RBrace) {
            loop {
                let start = self.tok.start;
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
    fn signature(&mut self) -> PResult<Signature> {
        let negated = self.eat(T::Minus);
        let name = self.expect(T::Ident, &["<IDENTIFIER>"])?;
        let name = self.word(name).to_string();
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
    fn show(&mut self) -> PResult<StatementKind> {
        self.bump();
        if self.eat(T::Dot) {
            return Ok(StatementKind::Show(Box::new(Show::Nothing)));
        }
        let term = self.term()?;
        self.body_end = &[];
        let body = if self.eat(T::Colon) {
            self.body()?
        } else {
            Vec::new()
        };
        self.end_of_body()?;
        if body.is_empty() {
            if let Some(sig) = term_to_signature(&term) {
                return Ok(StatementKind::Show(Box::new(Show::Signature(sig))));
            }
        }
        Ok(StatementKind::Show(Box::new(Show::Term { term, body })))
    }

    /// `#project p/n.` or `#project atom : body.`
    fn project(&mut self) -> PResult<StatementKind> {
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
    fn atom_of(&mut self, term: Term) -> PResult<SymbolicAtom> {
        match term_to_atom(term) {
            Ok(atom) => Ok(atom),
            Err(_) => Err(self.unexpected(&[])),
        }
    }

    /// `[: body] .`
    fn directive_body(&mut self) -> PResult<Vec<BodyLiteral>> {
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
    fn const_def(&mut self) -> PResult<StatementKind> {
        self.bump();
        let name = self.expect(T::Ident, &["<IDENTIFIER>"])?;
        let name = self.word(name).to_string();
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
                    self.diags.push(Diagnostic::error(
                        self.span(word.start, word.end),
                        "syntax error, unexpected <IDENTIFIER>, expecting default or override",
                    ));
                    return Err(Failed);
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
    fn external(&mut self) -> PResult<StatementKind> {
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
    fn heuristic(&mut self) -> PResult<StatementKind> {
        self.bump();
        let term = self.term()?;
        let atom = self.atom_of(term)?;
        let body = self.directive_body()?;
        self.expect(T::LBrack, &["["])?;
        let weight = self.term()?;
        let priority = if self.eat(T::At) {
            Some(self.term()?)
        } else {
            None
        };
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
    fn edge(&mut self) -> PResult<StatementKind> {
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
    fn include(&mut self) -> PResult<StatementKind> {
        self.bump();
        let include = if self.at(T::String) {
            let tok = self.bump();
            Include {
                path: self.unescape(tok),
                system: false,
            }
        } else if self.eat(T::Lt) {
            let name = self.expect(T::Ident, &["<IDENTIFIER>"])?;
            let path = self.word(name).to_string();
            self.expect(T::Gt, &[">"])?;
            Include { path, system: true }
        } else {
            return Err(self.unexpected(&["<STRING>", "<"]));
        };
        self.expect(T::Dot, &["."])?;
        Ok(StatementKind::Include(include))
    }

    /// `#program name(params).`
    fn program_part(&mut self) -> PResult<StatementKind> {
        self.bump();
        let name = self.expect(T::Ident, &["<IDENTIFIER>"])?;
        let name = self.word(name).to_string();
        let mut params = Vec::new();
        if self.eat(T::LParen) {
            if !self.at(T::RParen) {
                loop {
                    let p = self.expect(T::Ident, &["<IDENTIFIER>"])?;
                    params.push(self.word(p).to_string());
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
    fn script(&mut self) -> PResult<StatementKind> {
        let start = self.bump();
        self.report_script(self.span(start.start, start.end));
        self.expect(T::LParen, &["("])?;
        let lang = self.expect(T::Ident, &["<IDENTIFIER>"])?;
        let language = self.word(lang).to_string();
        if !self.at(T::RParen) {
            return Err(self.unexpected(&[")"]));
        }
        // The code is raw text: rewind the lexer to just after `)` and scan for `#end.`.
        let code_start = self.tok.end as usize;
        self.prev_end = self.tok.end;
        self.peeked = None;
        self.lexer.set_pos(code_start);
        let found = self.lexer.script_body();
        match found {
            Some((s, e)) => {
                let code = self.text[s..e].to_string();
                self.prev_end = self.lexer.pos() as u32;
                self.tok = self.lexer.next_token(&mut self.diags);
                Ok(StatementKind::Script(Script { language, code }))
            }
            None => {
                self.prev_end = self.lexer.pos() as u32;
                self.tok = self.lexer.next_token(&mut self.diags);
                Err(self.unexpected(&["#end"]))
            }
        }
    }

    // ----- SPARC declarations -----

    /// `#name = sort_expression.`
    fn sort_def(&mut self) -> PResult<StatementKind> {
        // A sort may be named like a clingo directive (`#program = {a}.`): the `=` tells.
        let defines = self.at(T::Hash) && self.peek().kind == T::Eq;
        if !self.at_sort_name() && !defines {
            return Err(self.unexpected(&["<SORT>"]));
        }
        let name = self.bump();
        self.sort_names.insert(self.word(name).to_string());
        let name = self.word(name)[1..].to_string();
        self.expect(T::Eq, &["="])?;
        let expr = self.sort_expr(0)?;
        self.expect(T::Dot, &["."])?;
        Ok(StatementKind::SortDef(Box::new(SortDef { name, expr })))
    }

    /// A sort expression with operators of at least `min_level` (`+ -` are 0, `*` is 1).
    fn sort_expr(&mut self, min_level: u8) -> PResult<SortExpr> {
        self.enter()?;
        let mut lhs = self.sort_primary()?;
        let mut folds = 0;
        loop {
            let level = match self.tok.kind {
                T::Plus | T::Minus => 0,
                T::Star => 1,
                _ => break,
            };
            if level < min_level {
                break;
            }
            let op = self.bump().kind;
            let rhs = self.sort_expr(level + 1)?;
            let span = lhs.span.to(rhs.span);
            let (l, r) = (Box::new(lhs), Box::new(rhs));
            let kind = match op {
                T::Plus => SortExprKind::Union(l, r),
                T::Minus => SortExprKind::Difference(l, r),
                _ => SortExprKind::Intersection(l, r),
            };
            lhs = SortExpr { span, kind };
            self.enter()?;
            folds += 1;
        }
        self.depth -= folds;
        self.leave();
        Ok(lhs)
    }

    /// A sort expression without binary operators.
    fn sort_primary(&mut self) -> PResult<SortExpr> {
        let start = self.tok.start;
        let record = self.at(T::Ident) && self.peek().kind == T::LParen;
        let kind = match self.tok.kind {
            T::LBrace => {
                self.bump();
                let mut items = Vec::new();
                if !self.at(T::RBrace) {
                    loop {
                        items.push(self.term()?);
                        if !self.eat(T::Comma) {
                            break;
                        }
                    }
                }
                self.expect(T::RBrace, &["}", "\",\""])?;
                SortExprKind::Set(items)
            }
            T::LBrack => {
                let mut parts = Vec::new();
                while self.at(T::LBrack) {
                    let part_start = self.bump().start;
                    let kind = self.concat_part()?;
                    self.expect(T::RBrack, &["]"])?;
                    parts.push(SortExpr {
                        span: self.span_from(part_start),
                        kind,
                    });
                }
                SortExprKind::Concat(parts)
            }
            T::LParen => {
                self.bump();
                let inner = self.sort_expr(0)?;
                self.expect(T::RParen, &[")"])?;
                SortExprKind::Paren(Box::new(inner))
            }
            T::Hash if self.at_sort_name() => {
                let tok = self.bump();
                SortExprKind::Ref(self.word(tok)[1..].to_string())
            }
            T::Ident if record => self.record()?,
            _ => {
                let lo = self.unary()?;
                self.expect(T::Dots, &[".."])?;
                let hi = self.unary()?;
                SortExprKind::Range(lo, hi)
            }
        };
        Ok(SortExpr {
            span: self.span_from(start),
            kind,
        })
    }

    /// The inside of one `[...]` part of a concatenation: `#s`, `lo..hi` or `a, b`.
    fn concat_part(&mut self) -> PResult<SortExprKind> {
        if self.at_sort_name() {
            let tok = self.bump();
            return Ok(SortExprKind::Ref(self.word(tok)[1..].to_string()));
        }
        let first = self.unary()?;
        if self.eat(T::Dots) {
            let hi = self.unary()?;
            return Ok(SortExprKind::Range(first, hi));
        }
        let mut items = vec![first];
        while self.eat(T::Comma) {
            items.push(self.unary()?);
        }
        Ok(SortExprKind::Set(items))
    }

    /// `name(#s1[(X)], ...) [: condition]`
    fn record(&mut self) -> PResult<SortExprKind> {
        let name = self.bump();
        let name = self.word(name).to_string();
        self.expect(T::LParen, &["("])?;
        let mut args = Vec::new();
        loop {
            let start = self.tok.start;
            if self.at_sort_name() {
                let tok = self.bump();
                let sort = SortExprKind::Ref(self.word(tok)[1..].to_string());
                let sort = SortExpr {
                    span: self.span_from(start),
                    kind: sort,
                };
                let var = if self.eat(T::LParen) {
                    let v = self.expect(T::Variable, &["<VARIABLE>"])?;
                    let v = self.word(v).to_string();
                    self.expect(T::RParen, &[")"])?;
                    Some(v)
                } else {
                    None
                };
                args.push((sort, var));
            } else {
                args.push((self.sort_expr(0)?, None));
            }
            if !self.eat(T::Comma) {
                break;
            }
        }
        self.expect(T::RParen, &[")", "\",\""])?;
        let condition = if self.eat(T::Colon) {
            Some(Box::new(self.record_condition()?))
        } else {
            None
        };
        Ok(SortExprKind::Record {
            name,
            args,
            condition,
        })
    }

    /// A record sort's condition: comparisons joined by `and` (or `,`) and `or`, `not(c)`,
    /// `(c)`; `and` binds tighter than `or`.
    fn record_condition(&mut self) -> PResult<RecordCondition> {
        self.enter()?;
        let mut lhs = self.record_conjunction()?;
        while self.at(T::Ident) && self.cur() == "or" {
            self.bump();
            let rhs = self.record_conjunction()?;
            lhs = RecordCondition::Or(Box::new(lhs), Box::new(rhs));
        }
        self.leave();
        Ok(lhs)
    }

    /// Comparisons joined by `and`, or by `,` when a variable or `not` follows (otherwise the
    /// `,` ends the record, which may be an argument of another record).
    fn record_conjunction(&mut self) -> PResult<RecordCondition> {
        let mut lhs = self.record_condition_primary()?;
        while (self.at(T::Comma) && matches!(self.peek().kind, T::Variable | T::Not))
            || (self.at(T::Ident) && self.cur() == "and")
        {
            self.bump();
            let rhs = self.record_condition_primary()?;
            lhs = RecordCondition::And(Box::new(lhs), Box::new(rhs));
        }
        Ok(lhs)
    }

    /// `not(c)`, `(c)` or `t1 op t2` with simple operands (variables, constants, numbers).
    fn record_condition_primary(&mut self) -> PResult<RecordCondition> {
        if self.eat(T::Not) {
            self.expect(T::LParen, &["("])?;
            let inner = self.record_condition()?;
            self.expect(T::RParen, &[")"])?;
            return Ok(RecordCondition::Not(Box::new(inner)));
        }
        if self.eat(T::LParen) {
            let inner = self.record_condition()?;
            self.expect(T::RParen, &[")"])?;
            return Ok(RecordCondition::Paren(Box::new(inner)));
        }
        let lhs = self.unary()?;
        let Some(op) = cmp_op(self.tok.kind) else {
            return Err(self.unexpected(&["<", "<=", "=", "!=", ">", ">="]));
        };
        self.bump();
        let rhs = self.unary()?;
        Ok(RecordCondition::Compare { lhs, op, rhs })
    }

    /// `name(#s1, ..., #sn).`
    fn predicate_decl(&mut self) -> PResult<StatementKind> {
        let name = self.expect(T::Ident, &["<IDENTIFIER>"])?;
        let name = self.word(name).to_string();
        let mut sorts = Vec::new();
        if self.eat(T::LParen) {
            if !self.at(T::RParen) {
                loop {
                    if !self.at_sort_name() {
                        return Err(self.unexpected(&["<SORT>"]));
                    }
                    let tok = self.bump();
                    sorts.push(self.word(tok)[1..].to_string());
                    if !self.eat(T::Comma) {
                        break;
                    }
                }
            }
            self.expect(T::RParen, &[")", "\",\""])?;
        }
        self.expect(T::Dot, &["."])?;
        Ok(StatementKind::PredicateDecl(PredicateDecl { name, sorts }))
    }

    // ----- heads -----

    /// A rule head, and the term its first literal was read from (a CR rule's label candidate).
    fn head(&mut self) -> PResult<(Head, Option<Term>)> {
        let start = self.tok.start;
        if self.at(T::LBrace) {
            return Ok((Head::Choice(Box::new(self.choice(start, None)?)), None));
        }
        if self.at_aggregate() {
            return Ok((
                Head::Aggregate(Box::new(self.head_aggregate(start, None)?)),
                None,
            ));
        }
        let mut first = Vec::with_capacity(1);
        let mut first_term = None;
        if self.at(T::Not) || (self.at(T::Hash) && matches!(self.cur(), "#true" | "#false")) {
            self.literal(Ctx::Single, &mut first)?;
        } else {
            let term = self.term()?;
            if self.at(T::LBrace) {
                let guard = Guard {
                    op: CmpOp::Le,
                    term,
                };
                return Ok((
                    Head::Choice(Box::new(self.choice(start, Some(guard))?)),
                    None,
                ));
            }
            if self.at_aggregate() {
                let guard = Guard {
                    op: CmpOp::Le,
                    term,
                };
                return Ok((
                    Head::Aggregate(Box::new(self.head_aggregate(start, Some(guard))?)),
                    None,
                ));
            }
            if let Some(op) = cmp_op(self.tok.kind) {
                let next = self.peek();
                if next.kind == T::LBrace
                    || aggregate_function(next.kind, self.word(next)).is_some()
                {
                    self.bump();
                    let guard = Guard { op, term };
                    if self.at(T::LBrace) {
                        return Ok((
                            Head::Choice(Box::new(self.choice(start, Some(guard))?)),
                            None,
                        ));
                    }
                    return Ok((
                        Head::Aggregate(Box::new(self.head_aggregate(start, Some(guard))?)),
                        None,
                    ));
                }
            }
            // Only `label : head :+ body` needs the term back (as the label), and only when a
            // `:` follows an atom; copy it just then.
            if !self.at_cmp() && self.at(T::Colon) {
                first_term = Some(term.clone());
            }
            self.literal_tail(start, Sign::Positive, term, Ctx::Single, &mut first)?;
        }
        let mut elements = Vec::with_capacity(1);
        let literal = first.remove(0);
        elements.push(self.head_element(start, literal, true)?);
        // gringo separates disjunction elements by `|`, `;` or `,` (a `,` after a condition
        // continues the condition, which `condition` has consumed already).
        while self.at(T::Bar) || self.at(T::Semi) || self.at(T::Comma) {
            self.bump();
            let start = self.tok.start;
            let mut lits = Vec::with_capacity(1);
            self.literal(Ctx::Single, &mut lits)?;
            let literal = lits.remove(0);
            elements.push(self.head_element(start, literal, true)?);
        }
        Ok((Head::Disjunction(elements), first_term))
    }

    /// True when the current token is a comparison operator.
    fn at_cmp(&self) -> bool {
        cmp_op(self.tok.kind).is_some()
    }

    /// The optional `: condition` after a head literal.
    fn head_element(
        &mut self,
        start: u32,
        literal: Literal,
        in_disjunction: bool,
    ) -> PResult<ConditionalLiteral> {
        let has_colon = self.eat(T::Colon);
        let condition = if has_colon {
            self.condition(!in_disjunction)?
        } else {
            Vec::new()
        };
        Ok(ConditionalLiteral {
            span: self.span_from(start),
            literal,
            condition,
            has_colon,
        })
    }

    /// `{ l : c ; ... } [upper]` after an optional lower guard.
    fn choice(&mut self, start: u32, lower: Option<Guard>) -> PResult<Choice> {
        self.enter()?;
        let elements = self.conditional_set()?;
        let upper = self.upper_guard()?;
        self.leave();
        Ok(Choice {
            span: self.span_from(start),
            lower,
            elements,
            upper,
        })
    }

    /// `{ l : c ; ... }`, the braces included.
    fn conditional_set(&mut self) -> PResult<Vec<ConditionalLiteral>> {
        self.expect(T::LBrace, &["{"])?;
        let mut elements = Vec::new();
        if !self.at(T::RBrace) {
            loop {
                let start = self.tok.start;
                let mut lits = Vec::with_capacity(1);
                self.literal(Ctx::Single, &mut lits)?;
                let literal = lits.remove(0);
                elements.push(self.head_element(start, literal, false)?);
                if !self.eat(T::Semi) {
                    break;
                }
            }
        }
        self.expect(T::RBrace, &["}", ";"])?;
        Ok(elements)
    }

    /// An upper guard after `}`: `op term` or a bare term (meaning `<= term`).
    fn upper_guard(&mut self) -> PResult<Option<Guard>> {
        if let Some(op) = cmp_op(self.tok.kind) {
            self.bump();
            let term = self.term()?;
            return Ok(Some(Guard { op, term }));
        }
        // A `|` after `}` can only open an absolute value: no aggregate or choice is followed
        // by a disjunction separator.
        if self.starts_term(self.tok) {
            let term = self.term()?;
            return Ok(Some(Guard {
                op: CmpOp::Le,
                term,
            }));
        }
        Ok(None)
    }

    /// `#f { terms : literal : condition ; ... } [upper]` in a head.
    fn head_aggregate(&mut self, start: u32, lower: Option<Guard>) -> PResult<HeadAggregate> {
        self.enter()?;
        let function = aggregate_function(self.tok.kind, self.cur()).expect("at an aggregate");
        self.bump();
        self.expect(T::LBrace, &["{"])?;
        let mut elements = Vec::new();
        if !self.at(T::RBrace) {
            loop {
                let el_start = self.tok.start;
                let mut terms = Vec::new();
                if !self.at(T::Colon) {
                    loop {
                        terms.push(self.term()?);
                        if !self.eat(T::Comma) {
                            break;
                        }
                    }
                }
                self.expect(T::Colon, &[":"])?;
                let mut lits = Vec::with_capacity(1);
                self.literal(Ctx::Single, &mut lits)?;
                let literal = lits.remove(0);
                let condition = if self.eat(T::Colon) {
                    self.condition(true)?
                } else {
                    Vec::new()
                };
                elements.push(HeadAggregateElement {
                    span: self.span_from(el_start),
                    terms,
                    literal,
                    condition,
                });
                if !self.eat(T::Semi) {
                    break;
                }
            }
        }
        self.expect(T::RBrace, &["}", ";"])?;
        let upper = self.upper_guard()?;
        self.leave();
        Ok(HeadAggregate {
            span: self.span_from(start),
            function,
            lower,
            elements,
            upper,
        })
    }

    // ----- bodies -----

    /// Body literals separated by `,` or `;`, up to (not including) the closing `.`.
    fn body(&mut self) -> PResult<Vec<BodyLiteral>> {
        self.body_end = &[];
        let mut body = Vec::new();
        if self.at(T::Dot) {
            return Ok(body);
        }
        loop {
            self.body_literal(&mut body)?;
            if !(self.eat(T::Comma) || self.eat(T::Semi)) {
                break;
            }
        }
        Ok(body)
    }

    /// One body literal (several for a comparison chain).
    fn body_literal(&mut self, out: &mut Vec<BodyLiteral>) -> PResult<()> {
        let start = self.tok.start;
        let sign = self.sign()?;
        if self.at(T::LBrace) || self.at_aggregate() {
            let aggregate = self.body_aggregate(start, None)?;
            out.push(BodyLiteral::Aggregate {
                sign,
                aggregate: Box::new(aggregate),
            });
            self.body_end = AFTER_AGGREGATE;
            return Ok(());
        }
        let mut lits = Vec::with_capacity(1);
        if self.at(T::Hash) && (matches!(self.cur(), "#true" | "#false") || self.at_sort_name()) {
            self.atom_literal(start, sign, &mut lits)?;
        } else {
            let term = self.term()?;
            if self.at(T::LBrace) || self.at_aggregate() {
                let guard = Guard {
                    op: CmpOp::Le,
                    term,
                };
                let aggregate = self.body_aggregate(start, Some(guard))?;
                out.push(BodyLiteral::Aggregate {
                    sign,
                    aggregate: Box::new(aggregate),
                });
                self.body_end = AFTER_AGGREGATE;
                return Ok(());
            }
            if let Some(op) = cmp_op(self.tok.kind) {
                let next = self.peek();
                if next.kind == T::LBrace
                    || aggregate_function(next.kind, self.word(next)).is_some()
                {
                    self.bump();
                    let guard = Guard { op, term };
                    let aggregate = self.body_aggregate(start, Some(guard))?;
                    out.push(BodyLiteral::Aggregate {
                        sign,
                        aggregate: Box::new(aggregate),
                    });
                    self.body_end = AFTER_AGGREGATE;
                    return Ok(());
                }
            }
            self.literal_tail(start, sign, term, Ctx::Chain, &mut lits)?;
        }
        if lits.len() == 1 && self.at(T::Colon) {
            self.bump();
            let condition = self.condition(true)?;
            let literal = lits.pop().expect("one literal");
            self.body_end = match condition.last() {
                Some(l) if !matches!(l.atom, Atom::Symbolic(_)) => AFTER_CONDITION,
                _ => &[],
            };
            out.push(BodyLiteral::Conditional(ConditionalLiteral {
                span: self.span_from(start),
                literal,
                condition,
                has_colon: true,
            }));
            return Ok(());
        }
        self.body_end = match lits.last() {
            Some(l) if !matches!(l.atom, Atom::Symbolic(_)) => AFTER_BUILTIN,
            _ => &[],
        };
        out.extend(lits.into_iter().map(BodyLiteral::Literal));
        Ok(())
    }

    /// `not`, `not not` or nothing.
    fn sign(&mut self) -> PResult<Sign> {
        if !self.eat(T::Not) {
            return Ok(Sign::Positive);
        }
        if !self.eat(T::Not) {
            return Ok(Sign::Not);
        }
        if self.at(T::Not) {
            return Err(self.unexpected(&[]));
        }
        Ok(Sign::NotNot)
    }

    /// A body aggregate after its optional lower guard.
    fn body_aggregate(&mut self, start: u32, lower: Option<Guard>) -> PResult<BodyAggregate> {
        self.enter()?;
        let (function, elements, set_syntax) = if self.at(T::LBrace) {
            let set = self.conditional_set()?;
            (AggregateFunction::Count, Vec::new(), set)
        } else {
            let function = aggregate_function(self.tok.kind, self.cur()).expect("at an aggregate");
            self.bump();
            self.expect(T::LBrace, &["{"])?;
            let mut elements = Vec::new();
            if !self.at(T::RBrace) {
                loop {
                    let el_start = self.tok.start;
                    let mut terms = Vec::new();
                    if !self.at(T::Colon) {
                        loop {
                            terms.push(self.term()?);
                            if !self.eat(T::Comma) {
                                break;
                            }
                        }
                    }
                    let condition = if self.eat(T::Colon) {
                        self.condition(true)?
                    } else {
                        Vec::new()
                    };
                    elements.push(BodyAggregateElement {
                        span: self.span_from(el_start),
                        terms,
                        condition,
                    });
                    if !self.eat(T::Semi) {
                        break;
                    }
                }
            }
            self.expect(T::RBrace, &["}", ";"])?;
            (function, elements, Vec::new())
        };
        let upper = self.upper_guard()?;
        self.leave();
        Ok(BodyAggregate {
            span: self.span_from(start),
            function,
            lower,
            elements,
            set_syntax,
            upper,
        })
    }

    /// A condition: literals separated by `,` (possibly none, before `;`, `|`, `}` or `.`).
    /// `bar_starts` says whether a `|` opens an absolute value here; in a head disjunction it
    /// separates elements instead.
    fn condition(&mut self, bar_starts: bool) -> PResult<Vec<Literal>> {
        let mut lits = Vec::new();
        if !(self.starts_literal() || (bar_starts && self.at(T::Bar))) {
            return Ok(lits);
        }
        loop {
            self.literal(Ctx::Chain, &mut lits)?;
            if !self.eat(T::Comma) {
                break;
            }
        }
        Ok(lits)
    }

    /// One literal (several for a comparison chain when `ctx` allows chains).
    fn literal(&mut self, ctx: Ctx, out: &mut Vec<Literal>) -> PResult<()> {
        let start = self.tok.start;
        let sign = self.sign()?;
        if self.at(T::Hash) && (matches!(self.cur(), "#true" | "#false") || self.at_sort_name()) {
            return self.atom_literal(start, sign, out);
        }
        let term = self.term()?;
        self.literal_tail(start, sign, term, ctx, out)
    }

    /// `#true`, `#false` or a SPARC sort atom `#s(t)`.
    fn atom_literal(&mut self, start: u32, sign: Sign, out: &mut Vec<Literal>) -> PResult<()> {
        let tok = self.bump();
        let atom = match self.word(tok) {
            "#true" => Atom::Boolean(true),
            "#false" => Atom::Boolean(false),
            word => {
                let sort = word[1..].to_string();
                self.expect(T::LParen, &["("])?;
                let arg = self.term()?;
                self.expect(T::RParen, &[")"])?;
                Atom::Sort {
                    sort,
                    arg: Box::new(arg),
                }
            }
        };
        out.push(Literal {
            span: self.span_from(start),
            sign,
            atom,
        });
        Ok(())
    }

    /// The rest of a literal whose first term was read: a comparison (chain) or an atom.
    fn literal_tail(
        &mut self,
        start: u32,
        sign: Sign,
        term: Term,
        ctx: Ctx,
        out: &mut Vec<Literal>,
    ) -> PResult<()> {
        let Some(op) = cmp_op(self.tok.kind) else {
            let Ok(atom) = term_to_atom(term) else {
                return Err(self.unexpected(&[]));
            };
            out.push(Literal {
                span: self.span_from(start),
                sign,
                atom: Atom::Symbolic(atom),
            });
            return Ok(());
        };
        self.bump();
        let mut lhs = term;
        let mut op = op;
        let mut lit_start = start;
        loop {
            let rhs = self.term()?;
            let next_start = rhs.span.start;
            let chained = ctx == Ctx::Chain && self.at_cmp();
            // In a chain `a < b < c` the middle term is shared: the next part starts with a copy.
            let next_lhs = chained.then(|| rhs.clone());
            out.push(Literal {
                span: self.span_from(lit_start),
                sign,
                atom: Atom::Comparison {
                    lhs: Box::new(lhs),
                    op,
                    rhs: Box::new(rhs),
                },
            });
            let Some(next_lhs) = next_lhs else {
                return Ok(());
            };
            match cmp_op(self.tok.kind) {
                Some(next) if sign == Sign::Positive => {
                    self.bump();
                    lhs = next_lhs;
                    op = next;
                    lit_start = next_start;
                }
                Some(_) => {
                    self.diags.push(Diagnostic::error(
                        self.span(self.tok.start, self.tok.end),
                        "syntax error, negated comparison chains are not supported",
                    ));
                    return Err(Failed);
                }
                None => return Ok(()),
            }
        }
    }

    // ----- terms -----

    /// A term, intervals included.
    fn term(&mut self) -> PResult<Term> {
        self.binary(0)
    }

    /// A term whose binary operators bind at least as tightly as `min_level`.
    /// Levels: `..` 0, `^` 1, `?` 2, `&` 3, `+ -` 4, `* / \` 5, `**` 6 (right-associative).
    fn binary(&mut self, min_level: u8) -> PResult<Term> {
        self.enter()?;
        let mut lhs = self.unary()?;
        let mut folds = 0;
        loop {
            let (level, op) = match self.tok.kind {
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
                _ => break,
            };
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

    /// A term with prefix operators `-` and `~`.
    fn unary(&mut self) -> PResult<Term> {
        let op = match self.tok.kind {
            T::Minus => UnaryOp::Minus,
            T::Tilde => UnaryOp::BitNot,
            _ => return self.primary(),
        };
        self.enter()?;
        let start = self.bump().start;
        let arg = self.unary()?;
        self.leave();
        Ok(Term {
            span: self.span_from(start),
            kind: TermKind::Unary {
                op,
                arg: Box::new(arg),
            },
        })
    }

    /// A term without operators: constants, numbers, strings, variables, functions, tuples,
    /// pools, `|t|`, `#inf`, `#sup`, `@f(...)`.
    fn primary(&mut self) -> PResult<Term> {
        let start = self.tok.start;
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
                TermKind::Variable(self.word(tok).to_string())
            }
            T::Anonymous => {
                self.bump();
                TermKind::Anonymous
            }
            T::Ident => {
                let tok = self.bump();
                let name = self.word(tok).to_string();
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
                let at = self.bump();
                self.report_script(self.span(at.start, self.tok.end.max(at.end)));
                let name = self.expect(T::Ident, &["<IDENTIFIER>"])?;
                let name = self.word(name).to_string();
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

    /// `( alternatives )` of a function: pools `f(1,2;3)`; `f()` is one empty list.
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
            if self.eat(T::Semi) {
                continue;
            }
            self.expect(T::RParen, &[")", ";"])?;
            break;
        }
        Ok(alts)
    }

    /// A parenthesized term: `(t)`, a tuple `()`, `(a,)`, `(a,b)`, or a pool `(a;b)`.
    fn parenthesized(&mut self) -> PResult<TermKind> {
        self.bump();
        if self.eat(T::RParen) {
            return Ok(TermKind::Function {
                name: String::new(),
                args: vec![Vec::new()],
                trailing_comma: false,
            });
        }
        let mut alts: Vec<(u32, Vec<Term>, bool)> = Vec::new();
        loop {
            let alt_start = self.tok.start;
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
                name: String::new(),
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
                            name: String::new(),
                            args: vec![terms],
                            trailing_comma: trailing,
                        },
                    }
                }
            })
            .collect();
        Ok(TermKind::Pool(alternatives))
    }

    /// The value of a number token; out-of-range literals are reported.
    fn integer(&mut self, tok: Token) -> i64 {
        let word = self.word(tok);
        let (digits, radix) = match word.get(..2) {
            Some("0x") | Some("0X") => (&word[2..], 16),
            Some("0o") | Some("0O") => (&word[2..], 8),
            Some("0b") | Some("0B") => (&word[2..], 2),
            _ => (word, 10),
        };
        match i64::from_str_radix(digits, radix) {
            Ok(v) => v,
            Err(_) => {
                self.diags.push(Diagnostic::error(
                    self.span(tok.start, tok.end),
                    "integer literal out of range",
                ));
                i64::MAX
            }
        }
    }

    /// The contents of a string token with escapes resolved (the lexer checked them).
    fn unescape(&self, tok: Token) -> String {
        let raw = &self.text[tok.start as usize + 1..tok.end as usize - 1];
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
}

/// For a CR rule written `label: head :+ body.`, the head was read as a disjunction whose first
/// element is `label : head_literal`; this splits the label off. Without that shape the rule has
/// no label.
fn split_label(head: Head, first_term: Option<Term>) -> (Head, Option<Term>) {
    let Head::Disjunction(mut elements) = head else {
        return (head, None);
    };
    // `label : :+ body.`: the label was read as a head literal with an empty condition.
    let label_only = first_term.is_some()
        && elements.len() == 1
        && elements[0].has_colon
        && elements[0].condition.is_empty()
        && elements[0].literal.sign == Sign::Positive;
    if label_only {
        return (Head::None, first_term);
    }
    let splittable = first_term.is_some()
        && elements.first().is_some_and(|e| {
            e.has_colon && e.condition.len() == 1 && e.literal.sign == Sign::Positive
        });
    if !splittable {
        return (Head::Disjunction(elements), None);
    }
    let first = elements.remove(0);
    let literal = first.condition.into_iter().next().expect("one literal");
    let element = ConditionalLiteral {
        span: literal.span,
        literal,
        condition: Vec::new(),
        has_colon: false,
    };
    elements.insert(0, element);
    (Head::Disjunction(elements), first_term)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ok(text: &str) -> Program {
        let p = parse(FileId(0), text, Dialect::Clingo);
        assert!(p.diagnostics.is_empty(), "{text}: {:?}", p.diagnostics);
        p.program
    }

    fn first_error(text: &str) -> String {
        let p = parse(FileId(0), text, Dialect::Clingo);
        p.diagnostics
            .first()
            .map(|d| format!("{}-{}: {}", d.span.start, d.span.end, d.message))
            .unwrap_or_default()
    }

    #[test]
    fn facts_and_rules() {
        let p = ok("p(1,2). q(X) :- p(X,_), not r(X). :- q(1).");
        assert_eq!(p.statements.len(), 3);
    }

    #[test]
    fn gringo_wording() {
        assert_eq!(
            first_error("a b."),
            "2-3: syntax error, unexpected <IDENTIFIER>"
        );
        assert_eq!(
            first_error("p(1."),
            "3-4: syntax error, unexpected ., expecting ) or ;"
        );
        assert_eq!(first_error("p(\"abc)."), "2-3: lexer error, unexpected \"");
    }

    #[test]
    fn cr_rule_with_label() {
        let p = ok("r(X): p(X) :+ q(X).");
        let StatementKind::Rule(rule) = &p.statements[0].kind else {
            panic!("not a rule")
        };
        let RuleKind::ConsistencyRestoring { label: Some(label) } = &rule.kind else {
            panic!("no label")
        };
        assert!(matches!(&label.kind, TermKind::Function { name, .. } if name == "r"));
    }

    #[test]
    fn recovery_keeps_later_statements() {
        let p = parse(FileId(0), "a b. c. d(.", Dialect::Clingo);
        assert_eq!(p.program.statements.len(), 3);
        assert!(matches!(
            p.program.statements[1].kind,
            StatementKind::Rule(_)
        ));
        assert_eq!(p.diagnostics.len(), 2);
    }

    #[test]
    fn detects_sparc() {
        assert_eq!(
            detect_dialect("% c\n#const n = 3.\nsorts\n#s = 1..n."),
            Dialect::Sparc
        );
        assert_eq!(
            detect_dialect("#maxint = 10.\n#const n = 3.\nsorts\n#s = 1..n."),
            Dialect::Sparc
        );
        assert_eq!(detect_dialect("sorts."), Dialect::Clingo);
        assert_eq!(detect_dialect("a :- b."), Dialect::Clingo);
    }

    #[test]
    fn labelled_cr_rule_without_head() {
        let p = ok("r1: :+ p(c).");
        let StatementKind::Rule(rule) = &p.statements[0].kind else {
            panic!("not a rule")
        };
        assert!(matches!(rule.head, Head::None));
        let RuleKind::ConsistencyRestoring { label: Some(label) } = &rule.kind else {
            panic!("no label")
        };
        assert!(matches!(&label.kind,
            TermKind::Constant(n) | TermKind::Function { name: n, .. } if n == "r1"));
    }

    #[test]
    fn sorts_may_take_the_names_of_directives() {
        let text = "sorts\n#program = {a}.\npredicates\np(#program).\nrules\np(X) :- #program(X).\ndisplay\n#program.\n";
        let p = parse(FileId(0), text, Dialect::Sparc);
        assert!(p.diagnostics.is_empty(), "{:?}", p.diagnostics);
        assert!(
            matches!(&p.program.statements[1].kind, StatementKind::SortDef(d) if d.name == "program")
        );
        assert!(
            matches!(&p.program.statements.last().unwrap().kind, StatementKind::DisplaySort(s) if s == "program")
        );
        // Before its definition, `#program` is still the directive.
        let p = parse(FileId(0), "#program base.\n", Dialect::Sparc);
        assert!(matches!(
            &p.program.statements[0].kind,
            StatementKind::ProgramPart(_)
        ));
    }
}
