//! The syntax tree of the three surface languages: the clingo dialect, CR-Prolog rules in that
//! dialect, and SPARC sorted programs.
//!
//! Invariants:
//! - Every node that a diagnostic may point at carries a [`Span`] into the source it was parsed
//!   from. Spans are ignored by [`Program::same_shape`], which is what the printer's round trip
//!   (`parse(print(t)) ~ t`) compares.
//! - The tree is owned data (no references into the source text), so it can cross to the
//!   grounder and outlive the parse.
//! - The tree records what was written, not what it means: pools, intervals, `#const` names and
//!   sort expressions are kept as written; the grounder unfolds and checks them.
//! - A statement that failed to parse is kept as [`StatementKind::Error`] with its span, so
//!   diagnostics and recovery never lose the rest of the file.

use crate::base::Span;

pub use super::name::Name;

/// A parsed file.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Program {
    /// Which surface language the file was parsed as.
    pub dialect: Dialect,
    /// Statements in source order (for SPARC, section headers are statements too).
    pub statements: Vec<Statement>,
}

/// The surface language of a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default, Hash)]
pub enum Dialect {
    /// gringo's language, with CR rules and `prefer/2`.
    #[default]
    Clingo,
    /// SPARC sorted programs (`sorts`, `predicates`, `rules`, `display` sections).
    Sparc,
}

impl Dialect {
    /// The dialect `--dialect` names: `clingo` (or `asp`), `sparc`.
    pub fn from_name(name: &str) -> Option<Dialect> {
        match name {
            "clingo" | "asp" => Some(Dialect::Clingo),
            "sparc" => Some(Dialect::Sparc),
            _ => None,
        }
    }
}

/// One statement with its span (from its first token to its closing period).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Statement {
    /// Covers the whole statement.
    pub span: Span,
    /// What the statement is.
    pub kind: StatementKind,
}

/// The kinds of statements. Payloads of the rarer, larger kinds are boxed so that a
/// [`Statement`] stays small on the common path (facts and rules).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum StatementKind {
    /// A fact, rule, constraint, or CR rule.
    Rule(Rule),
    /// `:~ body. [weight@priority, terms]`
    WeakConstraint(Box<WeakConstraint>),
    /// `#minimize { ... }.` or `#maximize { ... }.`
    Optimize(Optimize),
    /// `#show.`, `#show p/n.`, `#show -p/n.`, `#show t : body.`
    Show(Box<Show>),
    /// `#defined p/n.`
    Defined(Signature),
    /// `#project p/n.` or `#project a : body.`
    Project(Box<Project>),
    /// `#const name = term. [default|override]`
    Const(Box<ConstDef>),
    /// `#external atom : body. [value]`
    External(Box<External>),
    /// `#heuristic atom : body. [weight@priority, modifier]`
    Heuristic(Box<Heuristic>),
    /// `#edge (u, v) : body.`
    Edge(Box<Edge>),
    /// `#include "file".` or `#include <name>.`
    Include(Include),
    /// `#program name(params).`
    ProgramPart(ProgramPart),
    /// `#script (lang) ... #end.`: kept so the printer can reproduce it; the grounder reports
    /// it as unsupported.
    Script(Script),
    /// A SPARC section header: `sorts`, `predicates`, `rules` or `display`.
    Section(Section),
    /// A SPARC sort definition `#name = sort_expression.`
    SortDef(Box<SortDef>),
    /// A SPARC predicate declaration `name(#sort, ...).`
    PredicateDecl(PredicateDecl),
    /// A SPARC display item, e.g. `occurs.`, `-holds(F, I).`, `#object(O).`
    Display(Box<Literal>),
    /// A SPARC display item naming a sort, `#s.`: shows the sort's atoms (name without `#`).
    DisplaySort(String),
    /// SPARC's `#maxint = N.` directive: integers of arithmetic and of `#nat` are 0..N.
    MaxInt(Box<Term>),
    /// `#theory name { term and atom definitions }.`
    Theory(Box<TheoryDef>),
    /// A statement that did not parse; its diagnostics were reported.
    Error,
}

/// SPARC sections.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Section {
    /// `sorts`
    Sorts,
    /// `predicates`
    Predicates,
    /// `rules`
    Rules,
    /// `display`
    Display,
}

/// A rule `head :- body.`; a fact has an empty body, a constraint a [`Head::None`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Rule {
    /// The head.
    pub head: Head,
    /// The body literals, in order (`,` and `;` both separate body literals at this level).
    pub body: Vec<BodyLiteral>,
    /// Normal rule or consistency-restoring rule.
    pub kind: RuleKind,
}

/// Whether a rule is an ordinary rule or a consistency-restoring rule (`:+`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RuleKind {
    /// `head :- body.`
    Normal,
    /// `[label:] head :+ body.`; the label is a term (a constant or a function whose arguments
    /// may be the rule's variables).
    ConsistencyRestoring {
        /// The label, if written.
        label: Option<Box<Term>>,
    },
}

/// The head of a rule.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Head {
    /// No head: an integrity constraint `:- body.`
    None,
    /// A disjunction of (possibly conditional) literals separated by `|` or `;`. A single
    /// unconditional literal is a disjunction of one element.
    Disjunction(Vec<ConditionalLiteral>),
    /// `lower { elements } upper`
    Choice(Box<Choice>),
    /// A head aggregate `lower #sum { terms : literal : condition ; ... } upper`.
    Aggregate(Box<HeadAggregate>),
    /// A theory atom `&name{ ... }` (with an empty body: a head fact or a directive, as its
    /// definition says).
    Theory(Box<TheoryAtom>),
}

/// `literal : condition` where the condition may be empty.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ConditionalLiteral {
    /// Covers literal and condition.
    pub span: Span,
    /// The literal.
    pub literal: Literal,
    /// The condition (`:` followed by literals separated by `,`); empty when absent.
    pub condition: Vec<Literal>,
    /// True when a `:` was written, even with an empty condition (`a :.` is not valid, but
    /// `p(X) : ` before `;` is kept faithful for printing).
    pub has_colon: bool,
}

/// A comparison guard of an aggregate or choice: `term op` on the left or `op term` on the
/// right.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Guard {
    /// The relation, read as `guard_term op aggregate` for a left guard and
    /// `aggregate op guard_term` for a right guard.
    pub op: CmpOp,
    /// The bound.
    pub term: Term,
}

/// A choice head `lower { a : c ; b } upper`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Choice {
    /// Covers the whole choice.
    pub span: Span,
    /// Left guard; a bare term means `term <=`.
    pub lower: Option<Guard>,
    /// Elements.
    pub elements: Vec<ConditionalLiteral>,
    /// Right guard; a bare term means `<= term`.
    pub upper: Option<Guard>,
}

/// Aggregate functions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum AggregateFunction {
    /// `#count`
    Count,
    /// `#sum`
    Sum,
    /// `#sum+`
    SumPlus,
    /// `#min`
    Min,
    /// `#max`
    Max,
}

/// An element of a body aggregate: `terms : condition`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BodyAggregateElement {
    /// Covers the element.
    pub span: Span,
    /// The tuple (may be empty).
    pub terms: Vec<Term>,
    /// The condition; empty when absent.
    pub condition: Vec<Literal>,
}

/// A body aggregate `lower #f { elements } upper`. An aggregate written with bare braces and no
/// function (`1 { p ; q } 2` in a body) is a `#count` over conditional literals and is kept as
/// [`BodyAggregate::set_syntax`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BodyAggregate {
    /// Covers the aggregate with its guards.
    pub span: Span,
    /// The function.
    pub function: AggregateFunction,
    /// Left guard.
    pub lower: Option<Guard>,
    /// Elements for the `#f { t : c }` form.
    pub elements: Vec<BodyAggregateElement>,
    /// Elements for the set form `{ l : c ; ... }`; when non-empty, `elements` is empty.
    pub set_syntax: Vec<ConditionalLiteral>,
    /// Right guard.
    pub upper: Option<Guard>,
}

/// An element of a head aggregate: `terms : literal : condition`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HeadAggregateElement {
    /// Covers the element.
    pub span: Span,
    /// The tuple.
    pub terms: Vec<Term>,
    /// The literal made true.
    pub literal: Literal,
    /// The condition; empty when absent.
    pub condition: Vec<Literal>,
}

/// A head aggregate.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HeadAggregate {
    /// Covers the aggregate with its guards.
    pub span: Span,
    /// The function.
    pub function: AggregateFunction,
    /// Left guard.
    pub lower: Option<Guard>,
    /// Elements.
    pub elements: Vec<HeadAggregateElement>,
    /// Right guard.
    pub upper: Option<Guard>,
}

/// A literal of a rule body.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum BodyLiteral {
    /// A plain literal, possibly default-negated.
    Literal(Literal),
    /// A conditional literal `l : l1, l2` (in bodies, elements are separated by `;`).
    Conditional(ConditionalLiteral),
    /// A possibly negated aggregate.
    Aggregate {
        /// Default negation in front of the aggregate.
        sign: Sign,
        /// The aggregate.
        aggregate: Box<BodyAggregate>,
    },
    /// A possibly negated theory atom `&name{ ... }`.
    Theory {
        /// Default negation in front of the atom.
        sign: Sign,
        /// The atom.
        atom: Box<TheoryAtom>,
    },
}

/// Default negation prefix.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Sign {
    /// No prefix.
    #[default]
    Positive,
    /// `not`
    Not,
    /// `not not`
    NotNot,
}

/// A literal: an atom with a default-negation sign.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Literal {
    /// Covers sign and atom.
    pub span: Span,
    /// `not`, `not not` or nothing.
    pub sign: Sign,
    /// The atom.
    pub atom: Atom,
}

/// Atoms, including built-in ones.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Atom {
    /// A predicate atom `[-]name(args)`.
    Symbolic(SymbolicAtom),
    /// `lhs op rhs` (gringo also allows chains `a < b < c`; they are stored as a conjunction of
    /// the parts by the parser, one literal each, sharing the middle term).
    Comparison {
        /// Left operand (boxed: comparisons are rare next to predicate atoms).
        lhs: Box<Term>,
        /// The relation.
        op: CmpOp,
        /// Right operand.
        rhs: Box<Term>,
    },
    /// `#true` or `#false`.
    Boolean(bool),
    /// A SPARC sort atom `#sort(term)` in a rule body or display section.
    Sort {
        /// The sort name without `#`.
        sort: String,
        /// The argument (boxed, like the comparison operands).
        arg: Box<Term>,
    },
}

/// A predicate atom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SymbolicAtom {
    /// Covers the atom.
    pub span: Span,
    /// Classical negation `-`.
    pub negated: bool,
    /// Predicate name.
    pub name: Name,
    /// Argument lists: one list normally; several for a pool `p(1,2;3,4)`. A name without
    /// parentheses and `name()` both have one empty list.
    pub args: Vec<Vec<Term>>,
}

/// Comparison operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CmpOp {
    /// `=` (also written `==`)
    Eq,
    /// `!=` (also written `<>`)
    Ne,
    /// `<`
    Lt,
    /// `<=`
    Le,
    /// `>`
    Gt,
    /// `>=`
    Ge,
}

/// A term with its span.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Term {
    /// Covers the term.
    pub span: Span,
    /// What the term is.
    pub kind: TermKind,
}

/// The kinds of terms.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TermKind {
    /// An integer literal (clingo's integers are 32-bit; the grounder checks the range).
    Integer(i64),
    /// A string literal, unescaped.
    String(String),
    /// A constant `name` (lower-case identifier, possibly with leading underscores).
    Constant(Name),
    /// A variable `X`.
    Variable(Name),
    /// The anonymous variable `_`.
    Anonymous,
    /// `#inf`
    Infimum,
    /// `#sup`
    Supremum,
    /// `name(args)`; several argument lists for a pool `f(1;2)`. An empty name is a tuple
    /// `(a, b)`; a one-element tuple is written `(a,)`.
    Function {
        /// The function name, empty for tuples.
        name: Name,
        /// Argument lists (pool alternatives).
        args: Vec<Vec<Term>>,
        /// For tuples: a trailing comma was written, as in `(a,)`.
        trailing_comma: bool,
    },
    /// An external function call `@name(args)`: the grounder calls the grounding context's
    /// function `name` once the arguments are ground.
    ScriptCall {
        /// The function name.
        name: String,
        /// Arguments.
        args: Vec<Term>,
    },
    /// `-t`, `~t`, `|t|`.
    Unary {
        /// The operator.
        op: UnaryOp,
        /// The operand.
        arg: Box<Term>,
    },
    /// `l op r`.
    Binary {
        /// The operator.
        op: BinaryOp,
        /// Left operand.
        lhs: Box<Term>,
        /// Right operand.
        rhs: Box<Term>,
    },
    /// `lo..hi`
    Interval {
        /// Lower end.
        lo: Box<Term>,
        /// Upper end.
        hi: Box<Term>,
    },
    /// `(a;b)` as a term: a pool of alternatives.
    Pool(Vec<Term>),
    /// A term in parentheses `(t)`: kept so printing is faithful; means `t`.
    Paren(Box<Term>),
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum UnaryOp {
    /// `-`
    Minus,
    /// `~` (bitwise complement)
    BitNot,
    /// `|t|`
    Abs,
}

/// Binary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BinaryOp {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/` (integer division, rounding as clingo)
    Div,
    /// `\` (modulo, as clingo)
    Mod,
    /// `**`
    Pow,
    /// `&`
    BitAnd,
    /// `?`
    BitOr,
    /// `^`
    BitXor,
}

/// `:~ body. [weight@priority, terms]`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct WeakConstraint {
    /// Body literals.
    pub body: Vec<BodyLiteral>,
    /// The weight.
    pub weight: Term,
    /// The priority, if written (default 0).
    pub priority: Option<Term>,
    /// Further terms that distinguish tuples.
    pub terms: Vec<Term>,
}

/// `#minimize { w@p, t : c ; ... }.` (or `#maximize`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Optimize {
    /// True for `#maximize`/`#maximise`.
    pub maximize: bool,
    /// Elements.
    pub elements: Vec<OptimizeElement>,
}

/// One element `w@p, t1, t2 : condition` of an optimize statement.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OptimizeElement {
    /// Covers the element.
    pub span: Span,
    /// The weight.
    pub weight: Term,
    /// The priority, if written.
    pub priority: Option<Term>,
    /// Further terms.
    pub terms: Vec<Term>,
    /// The condition.
    pub condition: Vec<Literal>,
}

/// A predicate signature `[-]name/arity`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Signature {
    /// Classical negation.
    pub negated: bool,
    /// The name.
    pub name: String,
    /// The arity.
    pub arity: u32,
}

/// `#show` statements.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Show {
    /// `#show.`: hide everything not shown explicitly.
    Nothing,
    /// `#show p/n.`
    Signature(Signature),
    /// `#show t : body.`
    Term {
        /// The term shown.
        term: Term,
        /// When it is shown.
        body: Vec<BodyLiteral>,
    },
}

/// `#project` statements.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Project {
    /// `#project p/n.`
    Signature(Signature),
    /// `#project a : body.`
    Atom {
        /// The atom.
        atom: SymbolicAtom,
        /// The condition.
        body: Vec<BodyLiteral>,
    },
}

/// How a `#const` interacts with `-c name=value`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum ConstKind {
    /// Overridden by `-c` (no annotation or `[default]`).
    #[default]
    Default,
    /// `[override]`: overrides `-c`.
    Override,
}

/// `#const name = term.`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ConstDef {
    /// The constant's name.
    pub name: String,
    /// Its value.
    pub value: Term,
    /// `[default]` or `[override]`, with whether the annotation was written.
    pub kind: ConstKind,
    /// True when `[default]` or `[override]` was written.
    pub annotated: bool,
}

/// `#external atom : body. [value]`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct External {
    /// The atom.
    pub atom: SymbolicAtom,
    /// The condition.
    pub body: Vec<BodyLiteral>,
    /// `[true]`, `[false]`, `[free]`, `[release]` as written.
    pub value: Option<Term>,
}

/// `#heuristic atom : body. [weight@priority, modifier]`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Heuristic {
    /// The atom.
    pub atom: SymbolicAtom,
    /// The condition.
    pub body: Vec<BodyLiteral>,
    /// The weight.
    pub weight: Term,
    /// The priority, if written.
    pub priority: Option<Term>,
    /// The modifier (`level`, `sign`, `factor`, `init`, `true`, `false`).
    pub modifier: Term,
}

/// `#edge (u, v) : body.`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Edge {
    /// Source node.
    pub from: Term,
    /// Target node.
    pub to: Term,
    /// The condition.
    pub body: Vec<BodyLiteral>,
}

/// `#include "file".` or `#include <name>.`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Include {
    /// The path or library name.
    pub path: String,
    /// True for the `<name>` form.
    pub system: bool,
}

/// `#program name(params).`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ProgramPart {
    /// The part's name.
    pub name: String,
    /// Its parameters.
    pub params: Vec<String>,
}

/// `#script (lang) ... #end.`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Script {
    /// The language, e.g. `python`.
    pub language: String,
    /// The code between the header and `#end.`, verbatim.
    pub code: String,
}

/// SPARC `#name = expression.`
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SortDef {
    /// The sort's name, without `#`.
    pub name: String,
    /// Its definition.
    pub expr: SortExpr,
}

/// SPARC sort expressions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SortExpr {
    /// Covers the expression.
    pub span: Span,
    /// What it is.
    pub kind: SortExprKind,
}

/// The kinds of SPARC sort expressions.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SortExprKind {
    /// `{a, b, f(c)}`: an explicit set of ground terms.
    Set(Vec<Term>),
    /// `lo..hi` with integer or constant ends.
    Range(Term, Term),
    /// `#other`.
    Ref(String),
    /// `[id][1..3]`: concatenation of parts; each part is a set of identifiers or a range.
    Concat(Vec<SortExpr>),
    /// `name(#s1, #s2)` optionally with variables `name(#s1(X), #s2(Y)) : X != Y`.
    Record {
        /// The record (function) name.
        name: String,
        /// Argument sorts, each with an optional variable name.
        args: Vec<(SortExpr, Option<String>)>,
        /// Condition over the variables, when written.
        condition: Option<Box<RecordCondition>>,
    },
    /// `a + b`
    Union(Box<SortExpr>, Box<SortExpr>),
    /// `a - b`
    Difference(Box<SortExpr>, Box<SortExpr>),
    /// `a * b`
    Intersection(Box<SortExpr>, Box<SortExpr>),
    /// `(e)`
    Paren(Box<SortExpr>),
}

/// The condition of a SPARC record sort, `f(#s(X), #s(Y)) : X < Y or not(X = Y)`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum RecordCondition {
    /// `lhs op rhs` over the record's variables (and constants).
    Compare {
        /// Left operand.
        lhs: Term,
        /// The relation.
        op: CmpOp,
        /// Right operand.
        rhs: Term,
    },
    /// `a and b` (also written `a, b`).
    And(Box<RecordCondition>, Box<RecordCondition>),
    /// `a or b`.
    Or(Box<RecordCondition>, Box<RecordCondition>),
    /// `not(a)`.
    Not(Box<RecordCondition>),
    /// `(a)`.
    Paren(Box<RecordCondition>),
}

/// SPARC `name(#s1, ..., #sn).` in the `predicates` section.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PredicateDecl {
    /// The predicate name.
    pub name: String,
    /// Argument sort names, without `#`.
    pub sorts: Vec<String>,
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::mem::size_of;

    /// The common path (facts and simple rules) allocates these by the million; the rare,
    /// large variant payloads are boxed to keep them small. Raise the bounds only with a
    /// measurement showing the parser is not slowed.
    #[test]
    fn node_sizes_stay_small() {
        let sizes = [
            ("Statement", size_of::<Statement>()),
            ("StatementKind", size_of::<StatementKind>()),
            ("Rule", size_of::<Rule>()),
            ("Head", size_of::<Head>()),
            ("BodyLiteral", size_of::<BodyLiteral>()),
            ("ConditionalLiteral", size_of::<ConditionalLiteral>()),
            ("Literal", size_of::<Literal>()),
            ("Atom", size_of::<Atom>()),
            ("SymbolicAtom", size_of::<SymbolicAtom>()),
            ("Term", size_of::<Term>()),
        ];
        for (name, size) in sizes {
            println!("{name}: {size}");
        }
        assert!(size_of::<Statement>() <= 80, "{sizes:?}");
        assert!(size_of::<Literal>() <= 80, "{sizes:?}");
        assert!(size_of::<BodyLiteral>() <= 120, "{sizes:?}");
    }
}

/// `#theory name { definitions }.`: the term definitions (operator tables) and the atom
/// definitions of one theory, in the order written within each kind.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TheoryDef {
    /// The theory's name.
    pub name: String,
    /// `name { op : priority, unary|binary, left|right; ... }`
    pub terms: Vec<TheoryTermDef>,
    /// `&name/arity : term_def, [{ops}, guard_def,] head|body|any|directive`
    pub atoms: Vec<TheoryAtomDef>,
}

/// A theory term definition: the operators its terms may use.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TheoryTermDef {
    /// Covers the definition.
    pub span: Span,
    /// Its name.
    pub name: String,
    /// The operators.
    pub ops: Vec<TheoryOpDef>,
}

/// One operator of a theory term definition.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TheoryOpDef {
    /// Covers the definition.
    pub span: Span,
    /// The operator, a run of `/!<=>+-*\?&@|:;~^.` (or `not`).
    pub op: String,
    /// Binding strength: higher binds tighter.
    pub priority: u32,
    /// Unary, or binary with its associativity.
    pub kind: TheoryOpKind,
}

/// The kinds of theory operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TheoryOpKind {
    /// Prefix operator.
    Unary,
    /// Left-associative infix operator.
    BinaryLeft,
    /// Right-associative infix operator.
    BinaryRight,
}

/// Where a theory atom may occur.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum TheoryAtomKind {
    /// Rule heads only.
    Head,
    /// Rule bodies only.
    Body,
    /// Heads and bodies.
    Any,
    /// Alone, as a statement without body.
    Directive,
}

/// A theory atom definition `&name/arity : elements, [{ops}, guard,] kind`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TheoryAtomDef {
    /// Covers the definition.
    pub span: Span,
    /// The atom's name.
    pub name: String,
    /// The number of arguments of its name.
    pub arity: u32,
    /// The term definition of its elements' terms.
    pub elements: String,
    /// The guard's operators and the term definition of its term, when a guard is allowed.
    pub guard: Option<(Vec<String>, String)>,
    /// Where it may occur.
    pub kind: TheoryAtomKind,
}

/// A theory atom `&name(args){ terms : condition; ... } op guard`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TheoryAtom {
    /// Covers the atom.
    pub span: Span,
    /// Name and ordinary-term arguments (never classically negated).
    pub name: SymbolicAtom,
    /// The elements.
    pub elements: Vec<TheoryElement>,
    /// The guard: operator and term.
    pub guard: Option<(String, TheoryTerm)>,
}

/// A theory atom element `t1, ..., tn : l1, ..., lm`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TheoryElement {
    /// Covers the element.
    pub span: Span,
    /// The tuple of theory terms.
    pub terms: Vec<TheoryTerm>,
    /// The condition (ordinary literals).
    pub condition: Vec<Literal>,
}

/// A theory term with its span.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TheoryTerm {
    /// Covers the term.
    pub span: Span,
    /// What it is.
    pub kind: TheoryTermKind,
}

/// The kinds of theory terms. Operators are read by the parser as written
/// ([`TheoryTermKind::Unparsed`]); the operator tables of the theory resolve them
/// (`syntax::theory`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum TheoryTermKind {
    /// An integer, identifier, string, `#inf`, `#sup` or variable, as an ordinary term.
    Symbol(Term),
    /// `name(args)`.
    Function {
        /// The name: an identifier, or an operator once resolved.
        name: String,
        /// Arguments.
        args: Vec<TheoryTerm>,
    },
    /// `(a, b)`, `(a,)` or `()`.
    Tuple(Vec<TheoryTerm>),
    /// `{a, b}`.
    Set(Vec<TheoryTerm>),
    /// `[a, b]`.
    List(Vec<TheoryTerm>),
    /// `op* term (op+ term)*` as written: each term with the operators before it.
    Unparsed(Vec<(Vec<String>, TheoryTerm)>),
}
