//! Structured terms for the explainer: ground atoms and literals as trees (`holds(relation(on,
//! a, b), 0)`), never as strings that callers slice.
//!
//! This is the explainer's own small term type, shaped like clingo's `Symbol` (numbers, strings,
//! functions with a classical-negation sign; constants are functions without arguments), plus
//! `Var` for the patterns of questions and lexicon entries (`putdown(rob1, white_block, L)` when
//! no target was named). [`Term::parse`] reads the program syntax that [`Term`]'s `Display`
//! writes, so `Term::parse(&t.to_string()) == Ok(t)` for every term (checked by a test); the
//! front door's symbols convert through that text or field by field.
//!
//! Invariants: names are non-empty identifiers (the empty name is a tuple); a `Var` name starts
//! with an upper-case letter or `_`; `neg` is only set on functions and constants.

use std::fmt;

/// A term: a number, a string, a function or constant (possibly classically negated), or a
/// variable of a pattern.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Term {
    /// An integer.
    Num(i32),
    /// A string constant (its unescaped text).
    Str(String),
    /// A function `name(args)`; a constant when `args` is empty; a tuple when `name` is empty.
    Fun {
        /// The function name (empty for tuples).
        name: String,
        /// The arguments.
        args: Vec<Term>,
        /// Classical negation: `-name(args)`.
        neg: bool,
    },
    /// A variable of a pattern; never part of a ground literal.
    Var(String),
}

impl Term {
    /// A constant `name`.
    pub fn constant(name: &str) -> Term {
        Term::Fun {
            name: name.to_string(),
            args: Vec::new(),
            neg: false,
        }
    }

    /// A function `name(args)`.
    pub fn fun(name: &str, args: Vec<Term>) -> Term {
        Term::Fun {
            name: name.to_string(),
            args,
            neg: false,
        }
    }

    /// The function name, if this is a function or constant.
    pub fn name(&self) -> Option<&str> {
        match self {
            Term::Fun { name, .. } => Some(name),
            _ => None,
        }
    }

    /// The arguments (empty for anything but a function).
    pub fn args(&self) -> &[Term] {
        match self {
            Term::Fun { args, .. } => args,
            _ => &[],
        }
    }

    /// The `i`-th argument.
    pub fn arg(&self, i: usize) -> Option<&Term> {
        self.args().get(i)
    }

    /// Whether this is a classically negated function.
    pub fn is_neg(&self) -> bool {
        matches!(self, Term::Fun { neg: true, .. })
    }

    /// The same term with its classical sign flipped; `None` for numbers, strings, variables
    /// and tuples, which have no sign.
    pub fn complement(&self) -> Option<Term> {
        match self {
            Term::Fun { name, args, neg } if !name.is_empty() => Some(Term::Fun {
                name: name.clone(),
                args: args.clone(),
                neg: !neg,
            }),
            _ => None,
        }
    }

    /// The same term without classical negation.
    pub fn positive(&self) -> Term {
        match self {
            Term::Fun { name, args, .. } => Term::Fun {
                name: name.clone(),
                args: args.clone(),
                neg: false,
            },
            t => t.clone(),
        }
    }

    /// The integer, if this is a number.
    pub fn num(&self) -> Option<i32> {
        match self {
            Term::Num(n) => Some(*n),
            _ => None,
        }
    }

    /// Whether the term contains no variable.
    pub fn is_ground(&self) -> bool {
        match self {
            Term::Var(_) => false,
            Term::Fun { args, .. } => args.iter().all(Term::is_ground),
            _ => true,
        }
    }

    /// Whether this is a constant (a function without arguments).
    pub fn is_constant(&self) -> bool {
        matches!(self, Term::Fun { name, args, .. } if !name.is_empty() && args.is_empty())
    }

    /// Matches this pattern against a term, extending `bindings`; a variable named `_` matches
    /// anything and binds nothing. On failure `bindings` may hold partial bindings.
    pub fn matches(&self, term: &Term, bindings: &mut Vec<(String, Term)>) -> bool {
        match (self, term) {
            (Term::Var(v), t) => {
                if v == "_" {
                    return true;
                }
                if let Some((_, bound)) = bindings.iter().find(|(name, _)| name == v) {
                    return bound == t;
                }
                bindings.push((v.clone(), t.clone()));
                true
            }
            (
                Term::Fun { name, args, neg },
                Term::Fun {
                    name: n2,
                    args: a2,
                    neg: g2,
                },
            ) => {
                name == n2
                    && neg == g2
                    && args.len() == a2.len()
                    && args.iter().zip(a2).all(|(p, t)| p.matches(t, bindings))
            }
            (a, b) => a == b,
        }
    }

    /// The term with its variables replaced by their bindings (unbound variables stay).
    pub fn substitute(&self, bindings: &[(String, Term)]) -> Term {
        match self {
            Term::Var(v) => bindings
                .iter()
                .find(|(name, _)| name == v)
                .map(|(_, t)| t.clone())
                .unwrap_or_else(|| self.clone()),
            Term::Fun { name, args, neg } => Term::Fun {
                name: name.clone(),
                args: args.iter().map(|a| a.substitute(bindings)).collect(),
                neg: *neg,
            },
            t => t.clone(),
        }
    }

    /// Parses one term in the program syntax (`-holds(relation(on,a,b),0)`, `"text"`, `X`,
    /// `(1,2)`); the whole text must be the term, up to white space.
    pub fn parse(text: &str) -> Result<Term, TermError> {
        let mut p = TermParser {
            text: text.as_bytes(),
            pos: 0,
        };
        let t = p.term()?;
        p.skip_ws();
        if p.pos != p.text.len() {
            return Err(p.error("unexpected text after the term"));
        }
        Ok(t)
    }
}

/// A term that could not be read, with the byte offset where reading stopped.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{message} at byte {offset}")]
pub struct TermError {
    /// What went wrong.
    pub message: String,
    /// Byte offset into the text.
    pub offset: usize,
}

/// Recursive-descent reader of the term syntax.
struct TermParser<'a> {
    /// The whole text.
    text: &'a [u8],
    /// Current byte offset.
    pos: usize,
}

impl TermParser<'_> {
    fn error(&self, message: &str) -> TermError {
        TermError {
            message: message.to_string(),
            offset: self.pos,
        }
    }

    fn skip_ws(&mut self) {
        while self.pos < self.text.len() && self.text[self.pos].is_ascii_whitespace() {
            self.pos += 1;
        }
    }

    fn peek(&self) -> Option<u8> {
        self.text.get(self.pos).copied()
    }

    fn ident(&mut self) -> String {
        let start = self.pos;
        while let Some(c) = self.peek() {
            if c.is_ascii_alphanumeric() || c == b'_' || c == b'\'' {
                self.pos += 1;
            } else {
                break;
            }
        }
        String::from_utf8_lossy(&self.text[start..self.pos]).into_owned()
    }

    fn term(&mut self) -> Result<Term, TermError> {
        self.skip_ws();
        match self.peek() {
            None => Err(self.error("expected a term")),
            Some(b'-') => {
                self.pos += 1;
                self.skip_ws();
                match self.peek() {
                    Some(c) if c.is_ascii_digit() => {
                        let n = self.number()?;
                        n.checked_neg()
                            .map(Term::Num)
                            .ok_or_else(|| self.error("number out of range"))
                    }
                    Some(c) if c.is_ascii_lowercase() => match self.term()? {
                        Term::Fun { name, args, neg } => Ok(Term::Fun {
                            name,
                            args,
                            neg: !neg,
                        }),
                        _ => Err(self.error("only functions can be classically negated")),
                    },
                    _ => Err(self.error("expected a number or a function after '-'")),
                }
            }
            Some(c) if c.is_ascii_digit() => Ok(Term::Num(self.number()?)),
            Some(b'"') => self.string(),
            Some(b'(') => {
                let args = self.args()?;
                if args.len() == 1 {
                    Ok(args.into_iter().next().expect("one argument"))
                } else {
                    Ok(Term::Fun {
                        name: String::new(),
                        args,
                        neg: false,
                    })
                }
            }
            Some(c) if c.is_ascii_uppercase() || c == b'_' => Ok(Term::Var(self.ident())),
            Some(c) if c.is_ascii_lowercase() => {
                let name = self.ident();
                self.skip_ws();
                let args = if self.peek() == Some(b'(') {
                    self.args()?
                } else {
                    Vec::new()
                };
                Ok(Term::Fun {
                    name,
                    args,
                    neg: false,
                })
            }
            Some(_) => Err(self.error("expected a term")),
        }
    }

    fn number(&mut self) -> Result<i32, TermError> {
        let start = self.pos;
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.pos += 1;
        }
        std::str::from_utf8(&self.text[start..self.pos])
            .ok()
            .and_then(|s| s.parse().ok())
            .ok_or_else(|| self.error("number out of range"))
    }

    fn string(&mut self) -> Result<Term, TermError> {
        self.pos += 1;
        let mut out = Vec::new();
        loop {
            match self.peek() {
                None => return Err(self.error("unterminated string")),
                Some(b'"') => {
                    self.pos += 1;
                    break;
                }
                Some(b'\\') => {
                    self.pos += 1;
                    match self.peek() {
                        Some(b'n') => out.push(b'\n'),
                        Some(b't') => out.push(b'\t'),
                        Some(c) => out.push(c),
                        None => return Err(self.error("unterminated string")),
                    }
                    self.pos += 1;
                }
                Some(c) => {
                    out.push(c);
                    self.pos += 1;
                }
            }
        }
        Ok(Term::Str(String::from_utf8_lossy(&out).into_owned()))
    }

    /// `( term, ... )`, the opening parenthesis at the current position.
    fn args(&mut self) -> Result<Vec<Term>, TermError> {
        self.pos += 1;
        let mut args = Vec::new();
        self.skip_ws();
        if self.peek() == Some(b')') {
            self.pos += 1;
            return Ok(args);
        }
        loop {
            args.push(self.term()?);
            self.skip_ws();
            match self.peek() {
                Some(b',') => self.pos += 1,
                Some(b')') => {
                    self.pos += 1;
                    return Ok(args);
                }
                _ => return Err(self.error("expected ',' or ')'")),
            }
        }
    }
}

impl fmt::Display for Term {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Term::Num(n) => write!(f, "{n}"),
            Term::Str(s) => {
                f.write_str("\"")?;
                for c in s.chars() {
                    match c {
                        '"' => f.write_str("\\\"")?,
                        '\\' => f.write_str("\\\\")?,
                        '\n' => f.write_str("\\n")?,
                        '\t' => f.write_str("\\t")?,
                        c => write!(f, "{c}")?,
                    }
                }
                f.write_str("\"")
            }
            Term::Var(v) => f.write_str(v),
            Term::Fun { name, args, neg } => {
                if *neg {
                    f.write_str("-")?;
                }
                f.write_str(name)?;
                if !args.is_empty() || name.is_empty() {
                    f.write_str("(")?;
                    for (i, a) in args.iter().enumerate() {
                        if i > 0 {
                            f.write_str(",")?;
                        }
                        write!(f, "{a}")?;
                    }
                    if name.is_empty() && args.len() == 1 {
                        f.write_str(",")?;
                    }
                    f.write_str(")")?;
                }
                Ok(())
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip() {
        for text in [
            "holds(relation(below,white_block,green_can),0)",
            "-holds(in_hand(rob1,a),3)",
            "-occurs(pickup(rob1,white_block),0)",
            "has_size(b,small)",
            "\"a \\\"quoted\\\" text\"",
            "f(X,_,-3)",
            "(1,2)",
            "()",
            "t",
        ] {
            let t = Term::parse(text).unwrap();
            assert_eq!(t.to_string(), text, "{t:?}");
        }
    }

    #[test]
    fn errors_are_values() {
        assert!(Term::parse("f(a").is_err());
        assert!(Term::parse("f(a) g").is_err());
        assert!(Term::parse("").is_err());
        assert!(Term::parse("-\"s\"").is_err());
        assert!(Term::parse("99999999999").is_err());
    }

    #[test]
    fn matching_binds_variables() {
        let p = Term::parse("putdown(R,A,A)").unwrap();
        let mut b = Vec::new();
        assert!(!p.matches(&Term::parse("putdown(rob1,a,b)").unwrap(), &mut b));
        let mut b = Vec::new();
        assert!(p.matches(&Term::parse("putdown(rob1,a,a)").unwrap(), &mut b));
        assert_eq!(
            p.substitute(&b).to_string(),
            "putdown(rob1,a,a)".to_string()
        );
        assert_eq!(
            Term::parse("-stable(a)").unwrap().complement(),
            Some(Term::parse("stable(a)").unwrap())
        );
    }
}
