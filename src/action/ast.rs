//! The syntax tree of AL_d system descriptions and histories (grammar/action.ebnf).
//!
//! Invariants:
//! - Every node a diagnostic may point at carries a [`Span`] into the `.ald` file it was parsed
//!   from; the translator copies the statement's span onto every rule it generates.
//! - The tree records what was written: whether a name is a fluent, a static or an action, and
//!   whether a statement is active under the chosen profile, is the checker's business.
//! - Terms are the clingo dialect's [`Term`]s (constants, integers, variables, arithmetic), so
//!   the translator puts them into the CR-Prolog tree unchanged.
//! - A statement that failed to parse is kept as [`StatementKind::Error`] with its span.

use crate::base::Span;
use crate::syntax::ast::{CmpOp, Term};

/// A parsed `.ald` file (or several, once includes are resolved).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Description {
    /// Statements in source order.
    pub statements: Vec<Statement>,
}

/// One statement with its optional guards and label.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Statement {
    /// From the first guard or label to the closing period.
    pub span: Span,
    /// `[switch]` / `[not switch]` prefixes: the statement is active only when all hold.
    pub guards: Vec<Guard>,
    /// `C1:`; the id explanations cite.
    pub label: Option<Name>,
    /// What the statement says.
    pub kind: StatementKind,
}

/// A name with its span.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Name {
    /// Covers the name.
    pub span: Span,
    /// The text.
    pub text: String,
}

/// `[switch]` or `[not switch]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Guard {
    /// Covers the brackets.
    pub span: Span,
    /// True for `[not switch]`.
    pub negated: bool,
    /// The switch.
    pub switch: Name,
}

/// The kinds of statements.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StatementKind {
    /// `sort name = expression.`
    Sort {
        /// The sort.
        name: Name,
        /// Its members.
        expr: SortExpr,
    },
    /// `static p(s1, ..., sn).`, `inertial fluent ...`, `defined fluent ... [without cwa]`,
    /// `action ...`.
    Declaration {
        /// What is declared.
        kind: DeclKind,
        /// The name.
        name: Name,
        /// The argument sorts.
        params: Vec<Name>,
    },
    /// `a causes l if p1, ..., pk.`
    Causal {
        /// The action.
        action: Atom,
        /// The effect.
        effect: Lit,
        /// The conditions.
        body: Vec<BodyItem>,
    },
    /// `l if p1, ..., pk.` (a state constraint, or a static fact or rule).
    Constraint {
        /// The consequence.
        head: Lit,
        /// The conditions.
        body: Vec<BodyItem>,
    },
    /// `impossible a if p1, ..., pk.`
    Impossible {
        /// The action.
        action: Atom,
        /// The conditions.
        body: Vec<BodyItem>,
    },
    /// `normally l if p1, ..., pk.`
    Default {
        /// The default literal.
        head: Lit,
        /// The conditions.
        body: Vec<BodyItem>,
    },
    /// `exception to D: l may be assumed if p1, ..., pk.`
    Exception {
        /// The label of the default.
        default: Name,
        /// The literal assumed (the complement of the default's).
        head: Lit,
        /// The conditions.
        body: Vec<BodyItem>,
    },
    /// `never l if p1, ..., pk.`
    Never {
        /// The forbidden literal.
        lit: Lit,
        /// The conditions.
        body: Vec<BodyItem>,
    },
    /// `goal l1, ..., lm.`
    Goal {
        /// The conjunction.
        body: Vec<BodyItem>,
    },
    /// `observed l at t.`
    Observed {
        /// The observed literal.
        lit: Lit,
        /// The step.
        step: Term,
    },
    /// `happened a at t.`
    Happened {
        /// The action.
        action: Atom,
        /// The step.
        step: Term,
    },
    /// `initially l.`
    Initially {
        /// The literal true at step 0.
        lit: Lit,
    },
    /// `initially normally false except f1, ..., fk.` (the D0 defaults).
    InitialDefault {
        /// Inertial fluents exempt from the default.
        except: Vec<Name>,
    },
    /// `switch name = value.`: declares a profile switch and its default.
    Switch {
        /// The switch.
        name: Name,
        /// Its default.
        value: Value,
    },
    /// `set name = value.`: sets a switch for this description.
    Set {
        /// The switch.
        name: Name,
        /// Its value.
        value: Value,
    },
    /// `profile name: item, ..., item.`
    Profile {
        /// The profile.
        name: Name,
        /// Its switch settings and dropped statements.
        items: Vec<ProfileItem>,
    },
    /// `include "file".`
    Include {
        /// The path as written (relative to the including file).
        path: String,
    },
    /// A statement that did not parse.
    Error,
}

/// The kinds of declarations.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DeclKind {
    /// `static`
    Static,
    /// `inertial fluent`
    Inertial,
    /// `defined fluent`, with the closed-world assumption unless `without cwa`.
    Defined {
        /// Whether the CWA applies.
        cwa: bool,
    },
    /// `action`
    Action,
}

/// Sort expressions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SortExpr {
    /// Covers the expression.
    pub span: Span,
    /// Its parts, united (`a + {b} + 1..3`).
    pub parts: Vec<SortPart>,
}

/// One part of a sort union.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SortPart {
    /// `{a, b, 3}`
    Set(Vec<Term>),
    /// `lo..hi`, integers.
    Range(Term, Term),
    /// Another sort.
    Name(Name),
}

/// An atom `p(t1, ..., tn)`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Atom {
    /// Covers the atom.
    pub span: Span,
    /// The predicate name.
    pub name: Name,
    /// Arguments.
    pub args: Vec<Term>,
}

/// A literal `[-]p(t1, ..., tn)`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Lit {
    /// Covers the literal.
    pub span: Span,
    /// Classical negation.
    pub negated: bool,
    /// The atom.
    pub atom: Atom,
}

/// A condition of a body.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BodyItem {
    /// A fluent, static or sort literal.
    Lit(Lit),
    /// `t1 op t2`
    Compare {
        /// Covers the comparison.
        span: Span,
        /// Left operand.
        lhs: Term,
        /// The relation.
        op: CmpOp,
        /// Right operand.
        rhs: Term,
    },
}

/// A switch value.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Value {
    /// `true`, `on`, `false`, `off`.
    Bool(bool),
    /// An integer.
    Int(i64),
    /// Another word (`creation_only`).
    Word(String),
}

impl std::fmt::Display for Value {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Value::Bool(b) => write!(f, "{b}"),
            Value::Int(n) => write!(f, "{n}"),
            Value::Word(w) => write!(f, "{w}"),
        }
    }
}

/// An item of a profile.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ProfileItem {
    /// `name = value`, `name` (true) or `no name` (false).
    Set {
        /// The switch.
        name: Name,
        /// Its value.
        value: Value,
    },
    /// `drop L`: the statements labelled L are left out.
    Drop(Name),
}
