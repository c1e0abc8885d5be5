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
//! - `#script` blocks are parsed and kept, and reported once per file with a single
//!   "unsupported" error. External function calls `@f(...)` are plain terms here: the grounder
//!   evaluates them through a grounding context (`control::Context`), or reports them when
//!   there is none.
//! - Memory is proportional to the input: tokens are produced on demand (one token of
//!   lookahead beyond the current one), and the tree owns its strings.
//!
//! The token plumbing and the term grammar are the `Cursor`'s (`cursor.rs`, `terms.rs`), which
//! the AL_d parser ([`crate::action::parser`]) stands on too; `Parser` dereferences to its
//! cursor.

use std::ops::{Deref, DerefMut};

use crate::base::{Diagnostic, FileId, Span};

use super::ast::*;
use super::lexer::{Lexer, Token, TokenKind as T};

mod cursor;
mod directives;
mod literals;
mod sparc;
mod terms;
mod theory;

pub(crate) use cursor::{cmp_op, Cursor, Failed, PResult, TermGrammar};

/// Deepest nesting of terms, aggregates and sort expressions the parser accepts. 256 levels
/// keep the parser, the printer and the span walk well inside a 2 MiB thread stack (the size of
/// test threads) even in unoptimized builds, where one level costs about 5 KiB of stack.
pub const MAX_DEPTH: u32 = 256;

/// The message of the single diagnostic reported for `#script` blocks.
pub const UNSUPPORTED_SCRIPT: &str = "#script blocks are not supported by lucent (it embeds no \
     script interpreter; @f(...) calls a function of the grounding context instead)";

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

/// Parses `text` (the contents of `file`) as `dialect`. Errors are diagnostics with their
/// place, never a panic; the statements parsed around them are kept.
///
/// ```
/// use lucent::base::SourceMap;
/// use lucent::syntax::{self, ast::Dialect};
/// let mut sources = SourceMap::new();
/// let text = "p(1..3). q(X) :- p(X), X > 1.\nr :- s(.";
/// let file = sources.add("t.lp", text);
/// let parsed = syntax::parse(file, text, Dialect::Clingo);
/// assert!(parsed.program.statements.len() >= 2); // the two good statements are kept
/// assert!(parsed.has_errors());
/// assert!(sources.location(parsed.diagnostics[0].span).starts_with("t.lp:2:"));
/// ```
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
        diagnostics: parser.cursor.diags,
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
        let word = &text[tok.start() as usize..tok.end() as usize];
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
                let next_word = &text[next.start() as usize..next.end() as usize];
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
    /// The tokens, diagnostics and terms.
    cursor: Cursor<'a>,
    /// The surface language.
    dialect: Dialect,
    /// Statements so far.
    statements: Vec<Statement>,
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
        name: name.to_string(),
        arity: u32::try_from(arity).ok()?,
    })
}

impl<'a> Deref for Parser<'a> {
    type Target = Cursor<'a>;
    fn deref(&self) -> &Cursor<'a> {
        &self.cursor
    }
}

impl<'a> DerefMut for Parser<'a> {
    fn deref_mut(&mut self) -> &mut Cursor<'a> {
        &mut self.cursor
    }
}

impl<'a> Parser<'a> {
    /// A parser at the start of `text`.
    fn new(file: FileId, text: &'a str, dialect: Dialect) -> Parser<'a> {
        Parser {
            cursor: Cursor::new(file, text, dialect, TermGrammar::Clingo),
            dialect,
            statements: Vec::new(),
            section: None,
            sort_names: std::collections::HashSet::new(),
            body_end: &[],
        }
    }

    // ----- token classes -----

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
            let start = self.tok.start();
            let before = self.lexer.pos();
            self.depth = 0;
            let kind = match self.statement() {
                Ok(kind) => kind,
                Err(Failed) => {
                    self.cursor.relex(false);
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

    /// The neck token (`:-`, `:~`, ...), then a body up to its `.`.
    fn neck_body(&mut self) -> PResult<Vec<BodyLiteral>> {
        self.bump();
        let body = self.body()?;
        self.end_of_body()?;
        Ok(body)
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
                let body = self.neck_body()?;
                Ok(StatementKind::Rule(Rule {
                    head: Head::None,
                    body,
                    kind: RuleKind::Normal,
                }))
            }
            T::CrIf => {
                let body = self.neck_body()?;
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
                "#theory" => self.theory_def(),
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
                let body = self.neck_body()?;
                Ok(StatementKind::Rule(Rule {
                    head,
                    body,
                    kind: RuleKind::Normal,
                }))
            }
            T::CrIf => {
                let body = self.neck_body()?;
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
