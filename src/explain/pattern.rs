//! Patterns, and the literal helpers the explainer needs on ground terms.
//!
//! Ground data (atoms, literals, actions, constants) is `control::Symbol` everywhere in the
//! explainer, as at the front door: models, proof trees and answers hold symbols. A
//! [`Pattern`] is the one non-ground form: a term with variables, for the lexicon's entries
//! (`putdown(R,X,Y)`, `in_hand(R,X)`) and for a question's action whose target was not named
//! (`putdown(rob1,white_block,_)`). A pattern matches symbols ([`Pattern::matches`]) and
//! grounds into one ([`Pattern::ground`], [`Pattern::to_symbol`]); every symbol is a pattern
//! without variables ([`Pattern::from`]).
//!
//! [`SymbolExt`] adds to `Symbol` what literals need: the `i`-th argument, the classical
//! complement and the positive form, and whether a symbol is a constant.
//!
//! Invariants: [`Pattern::parse`] reads the program syntax that `Display` writes
//! (`Pattern::parse(&p.to_string()) == Ok(p)`, checked by a test); a `Var` name starts with an
//! upper-case letter or `_`; `negative` is only set on functions and constants;
//! `Pattern::from(&s).to_symbol() == Some(s)` for every symbol but `#inf`/`#sup` (which the
//! explainer never meets).

use std::fmt;

use crate::control::Symbol;
use crate::syntax::printer;

/// What literals need of a ground term, beyond `control::Symbol`'s own methods.
pub trait SymbolExt {
    /// The `i`-th argument of a function.
    fn arg(&self, i: usize) -> Option<&Symbol>;
    /// The same term without classical negation.
    fn positive(&self) -> Symbol;
    /// Whether this is a constant (a function without arguments and with a name).
    fn is_constant(&self) -> bool;
}

impl SymbolExt for Symbol {
    fn arg(&self, i: usize) -> Option<&Symbol> {
        self.args().get(i)
    }

    fn positive(&self) -> Symbol {
        match self {
            Symbol::Function { name, args, .. } => Symbol::Function {
                name: name.clone(),
                args: args.clone(),
                negative: false,
            },
            s => s.clone(),
        }
    }

    fn is_constant(&self) -> bool {
        matches!(self, Symbol::Function { name, args, .. } if !name.is_empty() && args.is_empty())
    }
}

/// A term that may contain variables.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Pattern {
    /// An integer.
    Num(i32),
    /// A string constant (its unescaped text).
    Str(String),
    /// A function `name(args)`; a constant when `args` is empty; a tuple when `name` is empty.
    Fun {
        /// The function name (empty for tuples).
        name: String,
        /// The arguments.
        args: Vec<Pattern>,
        /// Classical negation: `-name(args)`.
        negative: bool,
    },
    /// A variable; `_` matches anything and binds nothing.
    Var(String),
}

/// Variable bindings of a match: `(name, value)`.
pub type Bindings = Vec<(String, Symbol)>;

/// What a pattern is matched against: a symbol ([`Pattern::matches`]) or a pattern whose
/// variables count as constants ([`Pattern::subsumes`]); one algorithm, [`match_into`], serves
/// both.
trait Subject: Clone + PartialEq {
    /// Name, arguments and classical sign, if this is a function term.
    fn function(&self) -> Option<(&str, &[Self], bool)>;
    /// Whether this is `leaf`, a number or string pattern.
    fn is_leaf(&self, leaf: &Pattern) -> bool;
}

impl Subject for Symbol {
    fn function(&self) -> Option<(&str, &[Symbol], bool)> {
        Some((self.name()?, self.args(), self.is_negative()))
    }

    fn is_leaf(&self, leaf: &Pattern) -> bool {
        match (leaf, self) {
            (Pattern::Num(a), Symbol::Number(b)) => a == b,
            (Pattern::Str(a), Symbol::String(b)) => a == b,
            _ => false,
        }
    }
}

impl Subject for Pattern {
    fn function(&self) -> Option<(&str, &[Pattern], bool)> {
        let negative = matches!(self, Pattern::Fun { negative: true, .. });
        Some((self.name()?, self.args(), negative))
    }

    fn is_leaf(&self, leaf: &Pattern) -> bool {
        self == leaf
    }
}

/// One-way matching of `pattern` against `subject`, extending `bindings`: a variable binds the
/// subject (the same value each time it occurs; `_` binds nothing), a function matches a
/// function of the same name, sign and arity argument by argument, a number or a string only
/// itself. On failure `bindings` may hold partial bindings.
fn match_into<S: Subject>(pattern: &Pattern, subject: &S, bindings: &mut Vec<(String, S)>) -> bool {
    match pattern {
        Pattern::Var(v) => {
            if v == "_" {
                return true;
            }
            if let Some((_, bound)) = bindings.iter().find(|(name, _)| name == v) {
                return bound == subject;
            }
            bindings.push((v.clone(), subject.clone()));
            true
        }
        Pattern::Fun {
            name,
            args,
            negative,
        } => subject.function().is_some_and(|(n2, a2, g2)| {
            name == n2
                && *negative == g2
                && args.len() == a2.len()
                && args.iter().zip(a2).all(|(p, s)| match_into(p, s, bindings))
        }),
        leaf => subject.is_leaf(leaf),
    }
}

impl Pattern {
    /// The function name, if this is a function or constant.
    pub fn name(&self) -> Option<&str> {
        match self {
            Pattern::Fun { name, .. } => Some(name),
            _ => None,
        }
    }

    /// The arguments (empty for anything but a function).
    pub fn args(&self) -> &[Pattern] {
        match self {
            Pattern::Fun { args, .. } => args,
            _ => &[],
        }
    }

    /// The `i`-th argument.
    pub fn arg(&self, i: usize) -> Option<&Pattern> {
        self.args().get(i)
    }

    /// The same pattern with its classical sign flipped; `None` for numbers, strings,
    /// variables and tuples, which have no sign.
    pub fn complement(&self) -> Option<Pattern> {
        match self {
            Pattern::Fun {
                name,
                args,
                negative,
            } if !name.is_empty() => Some(Pattern::Fun {
                name: name.clone(),
                args: args.clone(),
                negative: !negative,
            }),
            _ => None,
        }
    }

    /// The same pattern without classical negation.
    pub fn positive(&self) -> Pattern {
        match self {
            Pattern::Fun { name, args, .. } => Pattern::Fun {
                name: name.clone(),
                args: args.clone(),
                negative: false,
            },
            p => p.clone(),
        }
    }

    /// Whether the pattern contains no variable.
    pub fn is_ground(&self) -> bool {
        match self {
            Pattern::Var(_) => false,
            Pattern::Fun { args, .. } => args.iter().all(Pattern::is_ground),
            _ => true,
        }
    }

    /// Whether this is the variable `name`.
    pub fn is_var(&self, name: &str) -> bool {
        matches!(self, Pattern::Var(v) if v == name)
    }

    /// The symbol, if the pattern has no variable.
    pub fn to_symbol(&self) -> Option<Symbol> {
        Some(match self {
            Pattern::Num(n) => Symbol::Number(*n),
            Pattern::Str(s) => Symbol::String(s.clone()),
            Pattern::Fun {
                name,
                args,
                negative,
            } => Symbol::Function {
                name: name.into(),
                args: args
                    .iter()
                    .map(Pattern::to_symbol)
                    .collect::<Option<Vec<_>>>()?,
                negative: *negative,
            },
            Pattern::Var(_) => return None,
        })
    }

    /// Matches this pattern against a symbol, extending `bindings`. On failure `bindings` may
    /// hold partial bindings.
    pub fn matches(&self, sym: &Symbol, bindings: &mut Bindings) -> bool {
        match_into(self, sym, bindings)
    }

    /// Matches this pattern against another one, as if the other's variables were constants
    /// that only a variable matches (a question's `putdown(rob1,a,_)` against the lexicon's
    /// `putdown(R,X,Y)`: `Y` is bound to `_`). Bindings are patterns.
    pub fn subsumes(&self, other: &Pattern, bindings: &mut Vec<(String, Pattern)>) -> bool {
        match_into(self, other, bindings)
    }

    /// The pattern with its variables replaced by their bindings (unbound variables stay).
    pub fn substitute(&self, bindings: &[(String, Pattern)]) -> Pattern {
        match self {
            Pattern::Var(v) => bindings
                .iter()
                .find(|(name, _)| name == v)
                .map(|(_, p)| p.clone())
                .unwrap_or_else(|| self.clone()),
            Pattern::Fun {
                name,
                args,
                negative,
            } => Pattern::Fun {
                name: name.clone(),
                args: args.iter().map(|a| a.substitute(bindings)).collect(),
                negative: *negative,
            },
            p => p.clone(),
        }
    }

    /// The symbol this pattern becomes under `bindings`, if they bind every variable.
    pub fn ground(&self, bindings: &Bindings) -> Option<Symbol> {
        let b: Vec<(String, Pattern)> = bindings
            .iter()
            .map(|(v, s)| (v.clone(), Pattern::from(s)))
            .collect();
        self.substitute(&b).to_symbol()
    }

    /// Parses one pattern in the program syntax (`putdown(R,X,Y)`, `-stable(X)`, `"text"`,
    /// `(1,2)`); the whole text must be the pattern, up to white space.
    pub fn parse(text: &str) -> Result<Pattern, PatternError> {
        let mut p = PatternParser {
            text: text.as_bytes(),
            pos: 0,
        };
        let t = p.pattern()?;
        p.skip_ws();
        if p.pos != p.text.len() {
            return Err(p.error("unexpected text after the term"));
        }
        Ok(t)
    }
}

impl From<&Symbol> for Pattern {
    fn from(s: &Symbol) -> Pattern {
        match s {
            Symbol::Number(n) => Pattern::Num(*n),
            Symbol::String(t) => Pattern::Str(t.clone()),
            Symbol::Function {
                name,
                args,
                negative,
            } => Pattern::Fun {
                name: name.to_string(),
                args: args.iter().map(Pattern::from).collect(),
                negative: *negative,
            },
            // Never in the explainer's programs; kept printable.
            Symbol::Inf => Pattern::Fun {
                name: "#inf".into(),
                args: Vec::new(),
                negative: false,
            },
            Symbol::Sup => Pattern::Fun {
                name: "#sup".into(),
                args: Vec::new(),
                negative: false,
            },
        }
    }
}

/// A pattern that could not be read, with the byte offset where reading stopped.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{message} at byte {offset}")]
pub struct PatternError {
    /// What went wrong.
    pub message: String,
    /// Byte offset into the text.
    pub offset: usize,
}

/// Recursive-descent reader of the pattern syntax.
struct PatternParser<'a> {
    /// The whole text.
    text: &'a [u8],
    /// Current byte offset.
    pos: usize,
}

impl PatternParser<'_> {
    fn error(&self, message: &str) -> PatternError {
        PatternError {
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

    fn pattern(&mut self) -> Result<Pattern, PatternError> {
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
                            .map(Pattern::Num)
                            .ok_or_else(|| self.error("number out of range"))
                    }
                    Some(c) if c.is_ascii_lowercase() => match self.pattern()? {
                        Pattern::Fun {
                            name,
                            args,
                            negative,
                        } => Ok(Pattern::Fun {
                            name,
                            args,
                            negative: !negative,
                        }),
                        _ => Err(self.error("only functions can be classically negated")),
                    },
                    _ => Err(self.error("expected a number or a function after '-'")),
                }
            }
            Some(c) if c.is_ascii_digit() => Ok(Pattern::Num(self.number()?)),
            Some(b'"') => self.string(),
            Some(b'(') => {
                let args = self.args()?;
                if args.len() == 1 {
                    Ok(args.into_iter().next().expect("one argument"))
                } else {
                    Ok(Pattern::Fun {
                        name: String::new(),
                        args,
                        negative: false,
                    })
                }
            }
            Some(c) if c.is_ascii_uppercase() || c == b'_' => Ok(Pattern::Var(self.ident())),
            Some(c) if c.is_ascii_lowercase() => {
                let name = self.ident();
                self.skip_ws();
                let args = if self.peek() == Some(b'(') {
                    self.args()?
                } else {
                    Vec::new()
                };
                Ok(Pattern::Fun {
                    name,
                    args,
                    negative: false,
                })
            }
            Some(_) => Err(self.error("expected a term")),
        }
    }

    fn number(&mut self) -> Result<i32, PatternError> {
        let start = self.pos;
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.pos += 1;
        }
        std::str::from_utf8(&self.text[start..self.pos])
            .ok()
            .and_then(|s| s.parse().ok())
            .ok_or_else(|| self.error("number out of range"))
    }

    fn string(&mut self) -> Result<Pattern, PatternError> {
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
        Ok(Pattern::Str(String::from_utf8_lossy(&out).into_owned()))
    }

    /// `( pattern, ... )`, the opening parenthesis at the current position.
    fn args(&mut self) -> Result<Vec<Pattern>, PatternError> {
        self.pos += 1;
        let mut args = Vec::new();
        self.skip_ws();
        if self.peek() == Some(b')') {
            self.pos += 1;
            return Ok(args);
        }
        loop {
            args.push(self.pattern()?);
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

impl fmt::Display for Pattern {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        // Numbers, strings and functions print as the symbol would (one printer for both).
        match self {
            Pattern::Var(v) => f.write_str(v),
            Pattern::Num(n) => write!(f, "{n}"),
            Pattern::Str(s) => printer::write_string(f, s),
            Pattern::Fun {
                name,
                args,
                negative,
            } => printer::write_function(f, name, *negative, args.iter(), |f, a| write!(f, "{a}")),
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
            "has_size(b,small)",
            "\"a \\\"quoted\\\" text\"",
            "f(X,_,-3)",
            "(1,2)",
            "()",
            "t",
        ] {
            let p = Pattern::parse(text).unwrap();
            assert_eq!(p.to_string(), text, "{p:?}");
        }
    }

    #[test]
    fn errors_are_values() {
        assert!(Pattern::parse("f(a").is_err());
        assert!(Pattern::parse("f(a) g").is_err());
        assert!(Pattern::parse("").is_err());
        assert!(Pattern::parse("-\"s\"").is_err());
        assert!(Pattern::parse("99999999999").is_err());
    }

    #[test]
    fn symbols_are_patterns_without_variables() {
        for text in ["-holds(in_hand(rob1,a),3)", "f(\"s\",(1,2),-3)", "c"] {
            let s = Symbol::parse(text).unwrap();
            let p = Pattern::from(&s);
            assert!(p.is_ground());
            assert_eq!(p.to_symbol(), Some(s.clone()));
            assert_eq!(p.to_string(), s.to_string());
        }
        assert_eq!(Pattern::parse("f(X)").unwrap().to_symbol(), None);
    }

    #[test]
    fn matching_binds_variables() {
        let p = Pattern::parse("putdown(R,A,A)").unwrap();
        let mut b = Vec::new();
        assert!(!p.matches(&Symbol::parse("putdown(rob1,a,b)").unwrap(), &mut b));
        let mut b = Vec::new();
        assert!(p.matches(&Symbol::parse("putdown(rob1,a,a)").unwrap(), &mut b));
        assert_eq!(
            p.ground(&b),
            Some(Symbol::parse("putdown(rob1,a,a)").unwrap())
        );
        let q = Pattern::parse("putdown(rob1,a,_)").unwrap();
        let mut b = Vec::new();
        assert!(Pattern::parse("putdown(R,X,Y)")
            .unwrap()
            .subsumes(&q, &mut b));
        assert_eq!(b[2], ("Y".to_string(), Pattern::Var("_".into())));
        assert_eq!(
            Symbol::parse("-stable(a)").unwrap().complement(),
            Some(Symbol::parse("stable(a)").unwrap())
        );
    }
}
