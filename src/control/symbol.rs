//! [`Symbol`]: a ground term as an owned, structured value, the form in which atoms and shown
//! terms cross the library's front door (clingo's `Symbol`).
//!
//! Invariants:
//! - `Display` prints exactly as clingo prints (`f(1,"a\"b",(x,)),-g`, `#inf`, `#sup`), through
//!   the crate's one symbol printer (`syntax::printer::write_symbol`), so
//!   `Symbol::parse(&s.to_string()) == Ok(s)` for every symbol.
//! - `Ord` is clingo's total order, the crate's one symbol order (`ground::symbol::order`, which
//!   orders the grounder's symbol table too): `#inf` < numbers < constants (positive before
//!   negated, then by name; the empty tuple `()` is the constant with the empty name) < strings
//!   < functions and tuples (positive before negated, then by arity, then name, then
//!   arguments) < `#sup`.
//! - Numbers are 32-bit, as in clingo. A constant is a function without arguments; a tuple is a
//!   function with the empty name.
//! - Conversion to and from the grounder's hash-consed table is exact in both directions.

use std::borrow::Borrow;
use std::cmp::Ordering;
use std::fmt;
use std::ops::Deref;
use std::sync::Arc;

use crate::ground::symbol::{SymData, SymId, Symbols};
use crate::syntax::ast;
use crate::syntax::printer::{write_symbol, GroundTerm, Shape};

/// A ground term.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Symbol {
    /// An integer.
    Number(i32),
    /// A string (its text, unescaped).
    String(String),
    /// A function term, a constant (no arguments) or a tuple (empty name).
    Function {
        /// The name; empty for tuples.
        name: Name,
        /// The arguments.
        args: Vec<Symbol>,
        /// Classical negation: `-f(1)`.
        negative: bool,
    },
    /// `#inf`, smaller than every other symbol.
    Inf,
    /// `#sup`, greater than every other symbol.
    Sup,
}

/// The name of a function symbol: shared text, so that a name read from the grounder's table
/// (every atom of every model) or cloned is not copied. It compares, hashes, orders and prints
/// as its `str` (`Debug` included), so it stands where a `String` stood:
/// `Symbol::function("p", ..)`, `name == "p"`, `&*name`, `name.as_str()`.
#[derive(Clone, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct Name(Arc<str>);

impl Name {
    /// The text.
    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl Deref for Name {
    type Target = str;
    fn deref(&self) -> &str {
        &self.0
    }
}

impl AsRef<str> for Name {
    fn as_ref(&self) -> &str {
        &self.0
    }
}

impl Borrow<str> for Name {
    fn borrow(&self) -> &str {
        &self.0
    }
}

impl fmt::Debug for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&*self.0, f)
    }
}

impl fmt::Display for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl From<&str> for Name {
    fn from(s: &str) -> Name {
        Name(Arc::from(s))
    }
}

impl From<String> for Name {
    fn from(s: String) -> Name {
        Name(Arc::from(s))
    }
}

impl From<&String> for Name {
    fn from(s: &String) -> Name {
        Name(Arc::from(s.as_str()))
    }
}

impl From<Arc<str>> for Name {
    fn from(s: Arc<str>) -> Name {
        Name(s)
    }
}

impl From<Name> for String {
    fn from(n: Name) -> String {
        n.0.to_string()
    }
}

impl PartialEq<str> for Name {
    fn eq(&self, other: &str) -> bool {
        &*self.0 == other
    }
}

impl PartialEq<&str> for Name {
    fn eq(&self, other: &&str) -> bool {
        &*self.0 == *other
    }
}

impl PartialEq<String> for Name {
    fn eq(&self, other: &String) -> bool {
        *self.0 == **other
    }
}

impl PartialEq<Name> for str {
    fn eq(&self, other: &Name) -> bool {
        self == &*other.0
    }
}

impl PartialEq<Name> for &str {
    fn eq(&self, other: &Name) -> bool {
        *self == &*other.0
    }
}

/// Why [`Symbol::parse`] rejected a text.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("not a ground term at byte {offset}: {message}")]
pub struct ParseSymbolError {
    /// Byte offset of the problem.
    pub offset: usize,
    /// What was expected.
    pub message: String,
}

impl Symbol {
    /// The integer `n`.
    pub fn number(n: i32) -> Symbol {
        Symbol::Number(n)
    }

    /// The string with text `s`.
    pub fn string(s: impl Into<String>) -> Symbol {
        Symbol::String(s.into())
    }

    /// The same literal with its classical sign flipped; `None` for numbers, strings and
    /// tuples, which have no sign.
    pub fn complement(&self) -> Option<Symbol> {
        match self {
            Symbol::Function {
                name,
                args,
                negative,
            } if !name.is_empty() => Some(Symbol::Function {
                name: name.clone(),
                args: args.clone(),
                negative: !negative,
            }),
            _ => None,
        }
    }

    /// The constant `name`.
    pub fn constant(name: impl Into<Name>) -> Symbol {
        Symbol::function(name, Vec::new())
    }

    /// The function `name(args)` (positive).
    pub fn function(name: impl Into<Name>, args: Vec<Symbol>) -> Symbol {
        Symbol::Function {
            name: name.into(),
            args,
            negative: false,
        }
    }

    /// The tuple `(args)`.
    pub fn tuple(args: Vec<Symbol>) -> Symbol {
        Symbol::function("", args)
    }

    /// The name of a function, constant or tuple (empty), `None` for other symbols.
    pub fn name(&self) -> Option<&str> {
        match self {
            Symbol::Function { name, .. } => Some(name),
            _ => None,
        }
    }

    /// The arguments of a function (empty for other symbols).
    pub fn args(&self) -> &[Symbol] {
        match self {
            Symbol::Function { args, .. } => args,
            _ => &[],
        }
    }

    /// The value of a number.
    pub fn as_number(&self) -> Option<i32> {
        match self {
            Symbol::Number(n) => Some(*n),
            _ => None,
        }
    }

    /// The text of a string.
    pub fn as_str(&self) -> Option<&str> {
        match self {
            Symbol::String(s) => Some(s),
            _ => None,
        }
    }

    /// True for a classically negated function or constant.
    pub fn is_negative(&self) -> bool {
        matches!(self, Symbol::Function { negative: true, .. })
    }

    /// True when this is the function `name` with `arity` arguments (positive or negated).
    pub fn is(&self, name: &str, arity: usize) -> bool {
        matches!(self, Symbol::Function { name: n, args, .. } if n == name && args.len() == arity)
    }

    /// A CR rule's label as the solver reports it (the ground label term's text): the term,
    /// or the text as a string when the label is not a term.
    pub fn from_cr_label(label: &str) -> Symbol {
        Symbol::parse(label).unwrap_or_else(|_| Symbol::String(label.to_string()))
    }

    /// Parses a ground term written as clingo prints it, e.g. `occurs(pickup(rob1,a),1)`,
    /// `-p(2)`, `"text"`, `(1,a)`, `#sup`.
    ///
    /// ```
    /// use lucent::control::Symbol;
    /// let s = Symbol::parse("occurs(pickup(rob1,a),1)").unwrap();
    /// assert_eq!(s.name(), Some("occurs"));
    /// assert_eq!(s.args()[1], Symbol::number(1));
    /// assert_eq!(s.to_string(), "occurs(pickup(rob1,a),1)");
    /// assert!(Symbol::parse("p(X)").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Symbol, ParseSymbolError> {
        Symbol::read(text, false)
    }

    /// A shown term as a model prints it: as [`Symbol::parse`], except that an identifier is a
    /// name whatever its first letter (a context function may return `Function("FOO")`, which
    /// clingo prints `FOO`); text that still does not read (a name with other characters) is
    /// the constant named by the whole text, so that it prints as it was shown.
    ///
    /// ```
    /// use lucent::control::Symbol;
    /// assert_eq!(Symbol::from_shown("u(FOO)").to_string(), "u(FOO)");
    /// assert_eq!(Symbol::from_shown("u(FOO)").args()[0].name(), Some("FOO"));
    /// assert_eq!(Symbol::from_shown("a b(1)").name(), Some("a b(1)"));
    /// ```
    pub fn from_shown(text: &str) -> Symbol {
        Symbol::read(text, true).unwrap_or_else(|_| Symbol::constant(text))
    }

    fn read(text: &str, any_case: bool) -> Result<Symbol, ParseSymbolError> {
        let mut p = Parser {
            s: text.as_bytes(),
            text,
            i: 0,
            any_case,
        };
        let sym = p.term()?;
        p.ws();
        if p.i != p.s.len() {
            return Err(p.error("end of text"));
        }
        Ok(sym)
    }

    /// The symbol as it is in the grounder's table `syms` (`id`).
    pub(crate) fn from_table(syms: &Symbols, id: SymId) -> Symbol {
        match syms.get(id) {
            SymData::Inf => Symbol::Inf,
            SymData::Sup => Symbol::Sup,
            SymData::Num(n) => Symbol::Number(n),
            SymData::Str(s) => Symbol::String(syms.names.resolve(s).to_string()),
            SymData::Fun { name, neg, .. } => {
                let ids = syms.args(id);
                // Each argument is written in place into the vector (`extend` over an exact
                // size): pushing a `Symbol` built on the stack copied it with wider loads than
                // the stores that built it, which stalled on store forwarding (`perf
                // annotate`, the learner-loop benchmark).
                let args: Vec<Symbol> = ids
                    .iter()
                    .map(|&a| Symbol::leaf_from_table(syms, a))
                    .collect();
                Symbol::Function {
                    name: Name(syms.names.resolve_shared(name)),
                    args,
                    negative: neg,
                }
            }
        }
    }

    /// `from_table` for an argument: constants and numbers (most arguments) are made here
    /// without a call, the rest by `from_table`.
    #[inline]
    fn leaf_from_table(syms: &Symbols, id: SymId) -> Symbol {
        match syms.get(id) {
            SymData::Num(n) => Symbol::Number(n),
            SymData::Fun {
                name, neg, len: 0, ..
            } => Symbol::Function {
                name: Name(syms.names.resolve_shared(name)),
                args: Vec::new(),
                negative: neg,
            },
            _ => Symbol::from_table(syms, id),
        }
    }

    /// The id of this symbol in `syms`, if the table holds it (nothing is created).
    pub(crate) fn find_in(&self, syms: &Symbols) -> Option<SymId> {
        match self {
            Symbol::Inf => syms.find_bound(false),
            Symbol::Sup => syms.find_bound(true),
            Symbol::Number(n) => syms.find_int(*n),
            Symbol::String(s) => syms.find_string(s),
            Symbol::Function {
                name,
                args,
                negative,
            } => {
                let name = syms.names.get(name)?;
                let mut ids = Vec::with_capacity(args.len());
                for a in args {
                    ids.push(a.find_in(syms)?);
                }
                syms.find_fun(name, *negative, &ids)
            }
        }
    }

    /// The id of this symbol in `syms`, created when missing.
    pub(crate) fn intern_in(&self, syms: &mut Symbols) -> SymId {
        match self {
            Symbol::Inf => syms.inf(),
            Symbol::Sup => syms.sup(),
            Symbol::Number(n) => syms.int(*n),
            Symbol::String(s) => syms.string(s),
            Symbol::Function {
                name,
                args,
                negative,
            } => {
                let ids: Vec<SymId> = args.iter().map(|a| a.intern_in(syms)).collect();
                syms.fun_str(name, *negative, &ids)
            }
        }
    }

    /// The ground symbol a syntax-tree term denotes, the inverse of `Symbol::to_term` (and of
    /// a constant written plainly); `None` when the term has variables or operations other
    /// than a minus sign.
    pub fn from_term(t: &ast::Term) -> Option<Symbol> {
        match &t.kind {
            ast::TermKind::Integer(n) => i32::try_from(*n).ok().map(Symbol::number),
            ast::TermKind::String(s) => Some(Symbol::string(s.clone())),
            ast::TermKind::Constant(c) => Some(Symbol::constant(c.as_str())),
            ast::TermKind::Function { name, args, .. } if args.len() == 1 => {
                let args: Option<Vec<Symbol>> = args[0].iter().map(Symbol::from_term).collect();
                Some(Symbol::function(name.as_str(), args?))
            }
            ast::TermKind::Unary {
                op: ast::UnaryOp::Minus,
                arg,
            } => match Symbol::from_term(arg)? {
                Symbol::Number(n) => Some(Symbol::number(-n)),
                f @ Symbol::Function { .. } => f.complement(),
                _ => None,
            },
            _ => None,
        }
    }

    /// The ground symbol of a syntax-tree atom, negative when it is classically negated.
    pub fn from_atom(a: &ast::SymbolicAtom) -> Option<Symbol> {
        let [args] = a.args.as_slice() else {
            return (a.args.is_empty() && !a.negated).then(|| Symbol::constant(a.name.as_str()));
        };
        let args: Option<Vec<Symbol>> = args.iter().map(Symbol::from_term).collect();
        let s = Symbol::function(a.name.as_str(), args?);
        if a.negated {
            s.complement()
        } else {
            Some(s)
        }
    }

    /// The symbol as a syntax-tree term (spans default). A constant becomes a function with
    /// one empty argument list, so that `#const` definitions and part parameters never replace
    /// it: the term stands for exactly this symbol.
    pub(crate) fn to_term(&self) -> ast::Term {
        let kind = match self {
            Symbol::Inf => ast::TermKind::Infimum,
            Symbol::Sup => ast::TermKind::Supremum,
            Symbol::Number(n) => ast::TermKind::Integer(i64::from(*n)),
            Symbol::String(s) => ast::TermKind::String(s.clone()),
            Symbol::Function {
                name,
                args,
                negative,
            } => {
                let f = ast::Term {
                    span: Default::default(),
                    kind: ast::TermKind::Function {
                        name: ast::Name::new(name),
                        args: vec![args.iter().map(Symbol::to_term).collect()],
                        trailing_comma: name.is_empty() && args.len() == 1,
                    },
                };
                if *negative {
                    ast::TermKind::Unary {
                        op: ast::UnaryOp::Minus,
                        arg: Box::new(f),
                    }
                } else {
                    return f;
                }
            }
        };
        ast::Term {
            span: Default::default(),
            kind,
        }
    }
}

impl Ord for Symbol {
    fn cmp(&self, other: &Symbol) -> Ordering {
        crate::ground::symbol::order(self, other)
    }
}

impl PartialOrd for Symbol {
    fn partial_cmp(&self, other: &Symbol) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<'s> GroundTerm<'s> for &'s Symbol {
    type Args = std::slice::Iter<'s, Symbol>;
    fn shape(self) -> Shape<'s, Self::Args> {
        match self {
            Symbol::Inf => Shape::Inf,
            Symbol::Sup => Shape::Sup,
            Symbol::Number(n) => Shape::Number(*n),
            Symbol::String(s) => Shape::String(s),
            Symbol::Function {
                name,
                args,
                negative,
            } => Shape::Function {
                name,
                negative: *negative,
                args: args.iter(),
            },
        }
    }
}

impl fmt::Display for Symbol {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write_symbol(f, self)
    }
}

impl std::str::FromStr for Symbol {
    type Err = ParseSymbolError;
    fn from_str(s: &str) -> Result<Symbol, ParseSymbolError> {
        Symbol::parse(s)
    }
}

impl From<i32> for Symbol {
    fn from(n: i32) -> Symbol {
        Symbol::Number(n)
    }
}

/// A recursive-descent reader of printed ground terms.
struct Parser<'a> {
    s: &'a [u8],
    text: &'a str,
    i: usize,
    /// Identifiers starting with a capital are names too (shown text, `Symbol::from_shown`).
    any_case: bool,
}

impl Parser<'_> {
    fn error(&self, expected: &str) -> ParseSymbolError {
        ParseSymbolError {
            offset: self.i,
            message: format!("expected {expected}"),
        }
    }

    fn ws(&mut self) {
        while self.i < self.s.len() && self.s[self.i].is_ascii_whitespace() {
            self.i += 1;
        }
    }

    fn peek(&self) -> Option<u8> {
        self.s.get(self.i).copied()
    }

    fn eat(&mut self, c: u8) -> bool {
        self.ws();
        if self.peek() == Some(c) {
            self.i += 1;
            true
        } else {
            false
        }
    }

    fn term(&mut self) -> Result<Symbol, ParseSymbolError> {
        self.ws();
        match self.peek() {
            Some(b'-') => {
                self.i += 1;
                self.ws();
                match self.peek() {
                    Some(c) if c.is_ascii_digit() => self.number(true),
                    _ => match self.term()? {
                        Symbol::Function {
                            name,
                            args,
                            negative,
                        } if !name.is_empty() => Ok(Symbol::Function {
                            name,
                            args,
                            negative: !negative,
                        }),
                        Symbol::Number(n) => Ok(Symbol::Number(n.wrapping_neg())),
                        _ => Err(self.error("a number or a function after `-`")),
                    },
                }
            }
            Some(c) if c.is_ascii_digit() => self.number(false),
            Some(b'"') => self.string(),
            Some(b'#') => {
                let rest = &self.text[self.i..];
                if rest.starts_with("#inf") {
                    self.i += 4;
                    Ok(Symbol::Inf)
                } else if rest.starts_with("#sup") {
                    self.i += 4;
                    Ok(Symbol::Sup)
                } else {
                    Err(self.error("#inf or #sup"))
                }
            }
            Some(b'(') => {
                self.i += 1;
                let (args, trailing) = self.args()?;
                if args.len() == 1 && !trailing {
                    // `(t)` is `t`.
                    Ok(args.into_iter().next().expect("one argument"))
                } else {
                    Ok(Symbol::tuple(args))
                }
            }
            Some(c)
                if c == b'_'
                    || c.is_ascii_lowercase()
                    || (self.any_case && c.is_ascii_uppercase()) =>
            {
                let start = self.i;
                while self
                    .peek()
                    .is_some_and(|c| c == b'_' || c == b'\'' || c.is_ascii_alphanumeric())
                {
                    self.i += 1;
                }
                let name = self.text[start..self.i].to_string();
                if self.peek() == Some(b'(') {
                    self.i += 1;
                    let (args, trailing) = self.args()?;
                    if trailing {
                        return Err(self.error("an argument after `,`"));
                    }
                    Ok(Symbol::function(name, args))
                } else {
                    Ok(Symbol::constant(name))
                }
            }
            _ => Err(self.error("a ground term")),
        }
    }

    /// Arguments after `(`, through `)`; also says whether a trailing comma was written.
    fn args(&mut self) -> Result<(Vec<Symbol>, bool), ParseSymbolError> {
        let mut args = Vec::new();
        if self.eat(b')') {
            return Ok((args, false));
        }
        loop {
            args.push(self.term()?);
            if self.eat(b')') {
                return Ok((args, false));
            }
            if !self.eat(b',') {
                return Err(self.error("`,` or `)`"));
            }
            if self.eat(b')') {
                return Ok((args, true));
            }
        }
    }

    fn number(&mut self, negative: bool) -> Result<Symbol, ParseSymbolError> {
        let start = self.i;
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.i += 1;
        }
        let digits = &self.text[start..self.i];
        let v: i64 = digits.parse().map_err(|_| self.error("a 32-bit integer"))?;
        let v = if negative { -v } else { v };
        i32::try_from(v)
            .map(Symbol::Number)
            .map_err(|_| self.error("a 32-bit integer"))
    }

    fn string(&mut self) -> Result<Symbol, ParseSymbolError> {
        self.i += 1;
        let mut out = String::new();
        loop {
            let rest = &self.text[self.i..];
            let mut chars = rest.chars();
            match chars.next() {
                None => return Err(self.error("`\"`")),
                Some('"') => {
                    self.i += 1;
                    return Ok(Symbol::String(out));
                }
                Some('\\') => {
                    let c = match chars.next() {
                        Some('n') => '\n',
                        Some('"') => '"',
                        Some('\\') => '\\',
                        _ => return Err(self.error("an escape (\\n, \\\", \\\\)")),
                    };
                    out.push(c);
                    self.i += 2;
                }
                Some(c) => {
                    out.push(c);
                    self.i += c.len_utf8();
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn printing_and_parsing_round_trip() {
        for text in [
            "p",
            "-p",
            "f(1,-2,\"a\\\"b\\\\c\\nd\")",
            "(1,a)",
            "(a,)",
            "()",
            "-f(g(x),(1,2))",
            "#inf",
            "#sup",
            "-2147483648",
            "occurs(pickup(rob1,a),1)",
        ] {
            let s = Symbol::parse(text).unwrap_or_else(|e| panic!("{text}: {e}"));
            assert_eq!(s.to_string(), text);
        }
        assert_eq!(Symbol::parse(" f( 1 , a ) ").unwrap().to_string(), "f(1,a)");
        assert_eq!(Symbol::parse("(3)").unwrap(), Symbol::number(3));
        for bad in [
            "X",
            "f(",
            "f(1,)",
            "1 2",
            "\"a",
            "#foo",
            "2147483648",
            "-\"s\"",
        ] {
            assert!(Symbol::parse(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn order_is_the_grounder_table_order() {
        let texts = [
            "#inf", "-3", "0", "7", "a", "b", "-a", "\"s\"", "\"t\"", "f(1)", "g(0)", "-f(1)",
            "(1,2)", "f(1,2)", "f(2,1)", "#sup", "()", "(a,)",
        ];
        let mut table = Symbols::new();
        let syms: Vec<Symbol> = texts.iter().map(|t| Symbol::parse(t).unwrap()).collect();
        let ids: Vec<SymId> = syms.iter().map(|s| s.intern_in(&mut table)).collect();
        for (i, a) in syms.iter().enumerate() {
            assert_eq!(Symbol::from_table(&table, ids[i]), *a);
            assert_eq!(a.find_in(&table), Some(ids[i]));
            for (j, b) in syms.iter().enumerate() {
                assert_eq!(a.cmp(b), table.compare(ids[i], ids[j]), "{a} vs {b}");
            }
        }
        assert_eq!(Symbol::parse("h(9)").unwrap().find_in(&table), None);
    }
}
