//! The printer: syntax tree back to readable clingo or SPARC source.
//!
//! Role: one statement per line, canonical spacing, operators spelled in their first form
//! (`=` for `==`, `!=` for `<>`), bare `<=` guards only in the `1 { a } 2` forms. Also the home
//! of clingo's spelling of ground terms: the one string escaper ([`write_string`]) and the one
//! symbol printer ([`write_symbol`]), for every representation of symbols ([`GroundTerm`]).
//!
//! Invariant: for every tree `t` the parser produces, `parse(print(t))` has the same shape as
//! `t` (spans aside). The printer needs no extra parentheses for that, because the parser keeps
//! written parentheses as [`TermKind::Paren`] and [`SortExprKind::Paren`] nodes and builds
//! operator trees by the same precedences the printer relies on. Separators are chosen so that
//! tokens never merge (`: -` is never printed as `:-`) and so that a body literal after a
//! conditional literal is not read as part of its condition (`;` is printed after one).

use std::fmt;

use super::ast::*;

/// Prints a whole program.
pub fn print(program: &Program) -> String {
    let mut out = String::new();
    for st in &program.statements {
        statement(&mut out, &st.kind);
        out.push('\n');
    }
    out
}

/// Prints one statement (without a newline).
pub fn statement(out: &mut String, kind: &StatementKind) {
    match kind {
        StatementKind::Rule(r) => rule(out, r),
        StatementKind::WeakConstraint(w) => {
            out.push_str(":~ ");
            body(out, &w.body);
            out.push_str(". [");
            weight(out, &w.weight, &w.priority, &w.terms);
            out.push(']');
        }
        StatementKind::Optimize(o) => optimize(out, o),
        StatementKind::Show(s) => show(out, s),
        StatementKind::Defined(sig) => {
            out.push_str("#defined ");
            signature(out, sig);
            out.push('.');
        }
        StatementKind::Project(p) => project(out, p),
        StatementKind::Const(c) => const_def(out, c),
        StatementKind::External(e) => external(out, e),
        StatementKind::Heuristic(h) => heuristic(out, h),
        StatementKind::Edge(e) => edge(out, e),
        StatementKind::Include(i) => include(out, i),
        StatementKind::ProgramPart(p) => program_part(out, p),
        StatementKind::Script(s) => {
            out.push_str("#script (");
            out.push_str(&s.language);
            out.push(')');
            out.push_str(&s.code);
            out.push_str("#end.");
        }
        StatementKind::Section(s) => out.push_str(match s {
            Section::Sorts => "sorts",
            Section::Predicates => "predicates",
            Section::Rules => "rules",
            Section::Display => "display",
        }),
        StatementKind::SortDef(d) => {
            out.push('#');
            out.push_str(&d.name);
            out.push_str(" = ");
            sort_expr(out, &d.expr);
            out.push('.');
        }
        StatementKind::PredicateDecl(p) => predicate_decl(out, p),
        StatementKind::Display(l) => {
            literal(out, l);
            out.push('.');
        }
        StatementKind::DisplaySort(name) => {
            out.push('#');
            out.push_str(name);
            out.push('.');
        }
        StatementKind::MaxInt(t) => {
            out.push_str("#maxint = ");
            term(out, t);
            out.push('.');
        }
        StatementKind::Theory(def) => super::theory::write_def(out, def),
        StatementKind::Error => out.push_str("% (statement with a syntax error)"),
    }
}

/// A rule, constraint or CR rule, with its final `.`.
fn rule(out: &mut String, rule: &Rule) {
    match &rule.kind {
        RuleKind::Normal => {
            if !matches!(rule.head, Head::None) {
                head(out, &rule.head);
                if !rule.body.is_empty() {
                    out.push_str(" :- ");
                    body(out, &rule.body);
                }
            } else {
                out.push_str(":- ");
                body(out, &rule.body);
            }
        }
        RuleKind::ConsistencyRestoring { label } => {
            if let Some(label) = label {
                term(out, label);
                out.push_str(" : ");
            }
            if !matches!(rule.head, Head::None) {
                head(out, &rule.head);
                out.push(' ');
            }
            out.push_str(":+ ");
            body(out, &rule.body);
        }
    }
    out.push('.');
}

/// `#minimize { ... }.` or `#maximize { ... }.`
fn optimize(out: &mut String, o: &Optimize) {
    out.push_str(if o.maximize {
        "#maximize { "
    } else {
        "#minimize { "
    });
    for (i, e) in o.elements.iter().enumerate() {
        if i > 0 {
            out.push_str("; ");
        }
        weight(out, &e.weight, &e.priority, &e.terms);
        if !e.condition.is_empty() {
            out.push_str(" : ");
            literals(out, &e.condition);
        }
    }
    out.push_str(" }.");
}

/// `#show.`, `#show p/n.` or `#show t : body.`
fn show(out: &mut String, show: &Show) {
    match show {
        Show::Nothing => out.push_str("#show."),
        Show::Signature(sig) => {
            out.push_str("#show ");
            signature(out, sig);
            out.push('.');
        }
        Show::Term { term: t, body: b } => {
            out.push_str("#show ");
            term(out, t);
            if !b.is_empty() {
                out.push_str(" : ");
                body(out, b);
            }
            out.push('.');
        }
    }
}

/// `#project p/n.` or `#project a : body.`
fn project(out: &mut String, p: &Project) {
    out.push_str("#project ");
    match p {
        Project::Signature(sig) => signature(out, sig),
        Project::Atom { atom, body: b } => {
            symbolic(out, atom);
            if !b.is_empty() {
                out.push_str(" : ");
                body(out, b);
            }
        }
    }
    out.push('.');
}

/// `#const name = term. [default|override]`
fn const_def(out: &mut String, c: &ConstDef) {
    out.push_str("#const ");
    out.push_str(&c.name);
    out.push_str(" = ");
    term(out, &c.value);
    out.push('.');
    if c.annotated {
        out.push_str(match c.kind {
            ConstKind::Default => " [default]",
            ConstKind::Override => " [override]",
        });
    }
}

/// `#external atom : body. [value]`
fn external(out: &mut String, e: &External) {
    out.push_str("#external ");
    symbolic(out, &e.atom);
    if !e.body.is_empty() {
        out.push_str(" : ");
        body(out, &e.body);
    }
    out.push('.');
    if let Some(v) = &e.value {
        out.push_str(" [");
        term(out, v);
        out.push(']');
    }
}

/// `#heuristic atom : body. [weight@priority, modifier]`
fn heuristic(out: &mut String, h: &Heuristic) {
    out.push_str("#heuristic ");
    symbolic(out, &h.atom);
    if !h.body.is_empty() {
        out.push_str(" : ");
        body(out, &h.body);
    }
    out.push_str(". [");
    weight(
        out,
        &h.weight,
        &h.priority,
        std::slice::from_ref(&h.modifier),
    );
    out.push(']');
}

/// `#edge (u, v) : body.`
fn edge(out: &mut String, e: &Edge) {
    out.push_str("#edge (");
    term(out, &e.from);
    out.push_str(", ");
    term(out, &e.to);
    out.push(')');
    if !e.body.is_empty() {
        out.push_str(" : ");
        body(out, &e.body);
    }
    out.push('.');
}

/// `#include "file".` or `#include <name>.`
fn include(out: &mut String, i: &Include) {
    out.push_str("#include ");
    if i.system {
        out.push('<');
        out.push_str(&i.path);
        out.push('>');
    } else {
        string(out, &i.path);
    }
    out.push('.');
}

/// `#program name(params).`
fn program_part(out: &mut String, p: &ProgramPart) {
    out.push_str("#program ");
    out.push_str(&p.name);
    if !p.params.is_empty() {
        out.push('(');
        out.push_str(&p.params.join(", "));
        out.push(')');
    }
    out.push('.');
}

/// A SPARC predicate declaration `name(#sort, ...).`
fn predicate_decl(out: &mut String, p: &PredicateDecl) {
    out.push_str(&p.name);
    out.push('(');
    for (i, s) in p.sorts.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        out.push('#');
        out.push_str(s);
    }
    out.push_str(").");
}

/// `w@p, t1, t2`
fn weight(out: &mut String, w: &Term, p: &Option<Term>, ts: &[Term]) {
    term(out, w);
    if let Some(p) = p {
        out.push('@');
        term(out, p);
    }
    for t in ts {
        out.push_str(", ");
        term(out, t);
    }
}

/// `[-]name/n`
fn signature(out: &mut String, sig: &Signature) {
    if sig.negated {
        out.push('-');
    }
    out.push_str(&sig.name);
    out.push('/');
    out.push_str(&sig.arity.to_string());
}

/// A rule head.
fn head(out: &mut String, h: &Head) {
    match h {
        Head::None => {}
        Head::Disjunction(els) => {
            for (i, e) in els.iter().enumerate() {
                if i > 0 {
                    out.push_str(if els[i - 1].has_colon { "; " } else { " | " });
                }
                conditional(out, e);
            }
        }
        Head::Choice(c) => {
            lower(out, &c.lower, true);
            out.push('{');
            conditionals(out, &c.elements);
            out.push('}');
            upper(out, &c.upper, true);
        }
        Head::Aggregate(a) => {
            lower(out, &a.lower, false);
            out.push_str(function(a.function));
            out.push('{');
            for (i, e) in a.elements.iter().enumerate() {
                out.push_str(if i > 0 { "; " } else { " " });
                terms(out, &e.terms);
                out.push_str(if e.terms.is_empty() { ": " } else { " : " });
                literal(out, &e.literal);
                if !e.condition.is_empty() {
                    out.push_str(" : ");
                    literals(out, &e.condition);
                }
            }
            out.push_str(" }");
            upper(out, &a.upper, false);
        }
        Head::Theory(a) => super::theory::write_atom(out, a),
    }
}

/// ` l : c; ... ` inside braces.
fn conditionals(out: &mut String, els: &[ConditionalLiteral]) {
    for (i, e) in els.iter().enumerate() {
        out.push_str(if i > 0 { "; " } else { " " });
        conditional(out, e);
    }
    out.push(' ');
}

/// The aggregate function keyword.
fn function(f: AggregateFunction) -> &'static str {
    match f {
        AggregateFunction::Count => "#count",
        AggregateFunction::Sum => "#sum",
        AggregateFunction::SumPlus => "#sum+",
        AggregateFunction::Min => "#min",
        AggregateFunction::Max => "#max",
    }
}

/// A left guard followed by a space; `<=` is left out when `bare` (the `1 { a } 2` forms).
fn lower(out: &mut String, g: &Option<Guard>, bare: bool) {
    if let Some(g) = g {
        term(out, &g.term);
        if !(bare && g.op == CmpOp::Le) {
            out.push(' ');
            out.push_str(cmp(g.op));
        }
        out.push(' ');
    }
}

/// A right guard preceded by a space; `<=` is left out when `bare`.
fn upper(out: &mut String, g: &Option<Guard>, bare: bool) {
    if let Some(g) = g {
        out.push(' ');
        if !(bare && g.op == CmpOp::Le) {
            out.push_str(cmp(g.op));
            out.push(' ');
        }
        term(out, &g.term);
    }
}

/// `literal [: condition]`
fn conditional(out: &mut String, c: &ConditionalLiteral) {
    literal(out, &c.literal);
    if c.has_colon {
        out.push_str(" :");
        if !c.condition.is_empty() {
            out.push(' ');
            literals(out, &c.condition);
        }
    }
}

/// Body literals; `;` follows a conditional literal so the next literal is not read into its
/// condition.
fn body(out: &mut String, b: &[BodyLiteral]) {
    for (i, l) in b.iter().enumerate() {
        if i > 0 {
            out.push_str(match &b[i - 1] {
                BodyLiteral::Conditional(_) => "; ",
                _ => ", ",
            });
        }
        match l {
            BodyLiteral::Literal(l) => literal(out, l),
            BodyLiteral::Conditional(c) => conditional(out, c),
            BodyLiteral::Aggregate { sign, aggregate: a } => {
                sign_prefix(out, *sign);
                let bare = !a.set_syntax.is_empty();
                lower(out, &a.lower, bare);
                if bare {
                    out.push('{');
                    conditionals(out, &a.set_syntax);
                    out.push('}');
                } else {
                    out.push_str(function(a.function));
                    out.push('{');
                    for (i, e) in a.elements.iter().enumerate() {
                        out.push_str(if i > 0 { "; " } else { " " });
                        terms(out, &e.terms);
                        if e.terms.is_empty() || !e.condition.is_empty() {
                            out.push_str(if e.terms.is_empty() { ":" } else { " :" });
                            if !e.condition.is_empty() {
                                out.push(' ');
                                literals(out, &e.condition);
                            }
                        }
                    }
                    out.push_str(" }");
                }
                upper(out, &a.upper, bare);
            }
            BodyLiteral::Theory { sign, atom } => {
                sign_prefix(out, *sign);
                super::theory::write_atom(out, atom);
            }
        }
    }
}

/// `not `, `not not ` or nothing.
fn sign_prefix(out: &mut String, sign: Sign) {
    out.push_str(match sign {
        Sign::Positive => "",
        Sign::Not => "not ",
        Sign::NotNot => "not not ",
    });
}

/// Literals separated by `, `.
pub(super) fn literals(out: &mut String, ls: &[Literal]) {
    for (i, l) in ls.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        literal(out, l);
    }
}

/// One literal.
fn literal(out: &mut String, l: &Literal) {
    sign_prefix(out, l.sign);
    match &l.atom {
        Atom::Symbolic(a) => symbolic(out, a),
        Atom::Comparison { lhs, op, rhs } => {
            term(out, lhs);
            out.push(' ');
            out.push_str(cmp(*op));
            out.push(' ');
            term(out, rhs);
        }
        Atom::Boolean(true) => out.push_str("#true"),
        Atom::Boolean(false) => out.push_str("#false"),
        Atom::Sort { sort, arg } => {
            out.push('#');
            out.push_str(sort);
            out.push('(');
            term(out, arg);
            out.push(')');
        }
    }
}

/// A comparison operator.
fn cmp(op: CmpOp) -> &'static str {
    match op {
        CmpOp::Eq => "=",
        CmpOp::Ne => "!=",
        CmpOp::Lt => "<",
        CmpOp::Le => "<=",
        CmpOp::Gt => ">",
        CmpOp::Ge => ">=",
    }
}

/// A symbolic atom: `p`, `-p(1)`, `p(1;2)`.
pub(super) fn symbolic(out: &mut String, a: &SymbolicAtom) {
    if a.negated {
        out.push('-');
    }
    out.push_str(&a.name);
    if !(a.args.len() == 1 && a.args[0].is_empty()) {
        arguments(out, &a.args);
    }
}

/// `(a, b; c)`
fn arguments(out: &mut String, args: &[Vec<Term>]) {
    out.push('(');
    for (i, alt) in args.iter().enumerate() {
        if i > 0 {
            out.push_str("; ");
        }
        terms(out, alt);
    }
    out.push(')');
}

/// Terms separated by `, `.
fn terms(out: &mut String, ts: &[Term]) {
    for (i, t) in ts.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        term(out, t);
    }
}

/// A string literal with `\\`, `\"` and `\n` escaped, into a `String`.
pub fn string(out: &mut String, s: &str) {
    // Writing to a `String` does not fail.
    let _ = write_string(out, s);
}

/// Writes a string as clingo prints it, in programs and as a ground symbol: quoted, with `"`,
/// `\` and newlines escaped. The one escaper of the crate.
pub fn write_string(out: &mut impl fmt::Write, s: &str) -> fmt::Result {
    out.write_char('"')?;
    for c in s.chars() {
        match c {
            '"' => out.write_str("\\\"")?,
            '\\' => out.write_str("\\\\")?,
            '\n' => out.write_str("\\n")?,
            c => out.write_char(c)?,
        }
    }
    out.write_char('"')
}

/// The surface of a ground term, as clingo prints and orders it. Whatever holds symbols (the
/// grounder's table, [`crate::control::Symbol`]) shows them through [`GroundTerm`], so that one
/// printer ([`write_symbol`]) and one order (`ground::symbol::order`) serve every
/// representation.
pub enum Shape<'s, I> {
    /// `#inf`.
    Inf,
    /// `#sup`.
    Sup,
    /// An integer.
    Number(i32),
    /// A string (its text, unescaped).
    String(&'s str),
    /// A function, a constant (no arguments) or a tuple (the empty name).
    Function {
        /// The name.
        name: &'s str,
        /// Classical negation `-f(...)`.
        negative: bool,
        /// The arguments, left to right.
        args: I,
    },
}

/// A ground term in some representation, seen as a [`Shape`].
pub trait GroundTerm<'s>: Copy {
    /// The arguments of a function.
    type Args: ExactSizeIterator<Item = Self>;
    /// The term's shape.
    fn shape(self) -> Shape<'s, Self::Args>;
    /// True when the two are known to be the same term without looking further (the same id
    /// of a hash-consed table); false when unknown.
    fn identical(self, _other: Self) -> bool {
        false
    }
}

/// Writes a ground term as clingo prints it (`f(1,"a\"b",(x,))`, `-g`, `#inf`, `#sup`).
pub fn write_symbol<'s, T: GroundTerm<'s>>(out: &mut impl fmt::Write, t: T) -> fmt::Result {
    match t.shape() {
        Shape::Inf => out.write_str("#inf"),
        Shape::Sup => out.write_str("#sup"),
        Shape::Number(n) => write!(out, "{n}"),
        Shape::String(s) => write_string(out, s),
        Shape::Function {
            name,
            negative,
            args,
        } => write_function(out, name, negative, args, |out, a| write_symbol(out, a)),
    }
}

/// Writes a function term as clingo prints it: `-` when classically negated, the name, and the
/// arguments (each by `arg`) in parentheses without spaces (none for a constant; a tuple of one
/// gets a trailing comma). [`write_symbol`] and terms with the same surface that are not ground
/// (the explainer's patterns) print with it.
pub fn write_function<W: fmt::Write, A>(
    out: &mut W,
    name: &str,
    negative: bool,
    args: impl ExactSizeIterator<Item = A>,
    mut arg: impl FnMut(&mut W, A) -> fmt::Result,
) -> fmt::Result {
    if negative {
        out.write_char('-')?;
    }
    out.write_str(name)?;
    let n = args.len();
    if n == 0 && !name.is_empty() {
        return Ok(());
    }
    out.write_char('(')?;
    for (i, a) in args.enumerate() {
        if i > 0 {
            out.write_char(',')?;
        }
        arg(out, a)?;
    }
    if name.is_empty() && n == 1 {
        out.write_char(',')?;
    }
    out.write_char(')')
}

/// The spelling of a binary operator.
fn binary_op(op: BinaryOp) -> &'static str {
    match op {
        BinaryOp::Add => "+",
        BinaryOp::Sub => "-",
        BinaryOp::Mul => "*",
        BinaryOp::Div => "/",
        BinaryOp::Mod => "\\",
        BinaryOp::Pow => "**",
        BinaryOp::BitAnd => "&",
        BinaryOp::BitOr => "?",
        BinaryOp::BitXor => "^",
    }
}

/// A term.
pub fn term(out: &mut String, t: &Term) {
    match &t.kind {
        TermKind::Integer(i) => out.push_str(&i.to_string()),
        TermKind::String(s) => string(out, s),
        TermKind::Constant(c) => out.push_str(c),
        TermKind::Variable(v) => out.push_str(v),
        TermKind::Anonymous => out.push('_'),
        TermKind::Infimum => out.push_str("#inf"),
        TermKind::Supremum => out.push_str("#sup"),
        TermKind::Function {
            name,
            args,
            trailing_comma,
        } => {
            out.push_str(name);
            if name.is_empty() && args.len() == 1 {
                out.push('(');
                terms(out, &args[0]);
                if *trailing_comma {
                    out.push(',');
                }
                out.push(')');
            } else {
                arguments(out, args);
            }
        }
        TermKind::ScriptCall { name, args } => {
            out.push('@');
            out.push_str(name);
            out.push('(');
            terms(out, args);
            out.push(')');
        }
        TermKind::Unary { op, arg } => match op {
            UnaryOp::Minus => {
                out.push('-');
                term(out, arg);
            }
            UnaryOp::BitNot => {
                out.push('~');
                term(out, arg);
            }
            UnaryOp::Abs => {
                out.push('|');
                term(out, arg);
                out.push('|');
            }
        },
        TermKind::Binary { op, lhs, rhs } => {
            term(out, lhs);
            out.push(' ');
            out.push_str(binary_op(*op));
            out.push(' ');
            term(out, rhs);
        }
        TermKind::Interval { lo, hi } => {
            term(out, lo);
            out.push_str("..");
            term(out, hi);
        }
        TermKind::Pool(alts) => {
            out.push('(');
            for (i, a) in alts.iter().enumerate() {
                if i > 0 {
                    out.push_str("; ");
                }
                term(out, a);
            }
            out.push(')');
        }
        TermKind::Paren(inner) => {
            out.push('(');
            term(out, inner);
            out.push(')');
        }
    }
}

/// A SPARC sort expression.
fn sort_expr(out: &mut String, e: &SortExpr) {
    match &e.kind {
        SortExprKind::Set(ts) => {
            out.push('{');
            terms(out, ts);
            out.push('}');
        }
        SortExprKind::Range(lo, hi) => {
            term(out, lo);
            out.push_str("..");
            term(out, hi);
        }
        SortExprKind::Ref(name) => {
            out.push('#');
            out.push_str(name);
        }
        SortExprKind::Concat(parts) => {
            for p in parts {
                out.push('[');
                match &p.kind {
                    SortExprKind::Set(ts) => terms(out, ts),
                    _ => sort_expr(out, p),
                }
                out.push(']');
            }
        }
        SortExprKind::Record {
            name,
            args,
            condition,
        } => {
            out.push_str(name);
            out.push('(');
            for (i, (s, var)) in args.iter().enumerate() {
                if i > 0 {
                    out.push_str(", ");
                }
                sort_expr(out, s);
                if let Some(v) = var {
                    out.push('(');
                    out.push_str(v);
                    out.push(')');
                }
            }
            out.push(')');
            if let Some(c) = condition {
                out.push_str(" : ");
                record_condition(out, c);
            }
        }
        SortExprKind::Union(a, b) => binary_sort(out, a, "+", b),
        SortExprKind::Difference(a, b) => binary_sort(out, a, "-", b),
        SortExprKind::Intersection(a, b) => binary_sort(out, a, "*", b),
        SortExprKind::Paren(a) => {
            out.push('(');
            sort_expr(out, a);
            out.push(')');
        }
    }
}

/// The condition of a record sort.
fn record_condition(out: &mut String, c: &RecordCondition) {
    match c {
        RecordCondition::Compare { lhs, op, rhs } => {
            term(out, lhs);
            out.push(' ');
            out.push_str(cmp(*op));
            out.push(' ');
            term(out, rhs);
        }
        RecordCondition::And(a, b) | RecordCondition::Or(a, b) => {
            record_condition(out, a);
            out.push_str(if matches!(c, RecordCondition::And(..)) {
                " and "
            } else {
                " or "
            });
            record_condition(out, b);
        }
        RecordCondition::Not(a) => {
            out.push_str("not(");
            record_condition(out, a);
            out.push(')');
        }
        RecordCondition::Paren(a) => {
            out.push('(');
            record_condition(out, a);
            out.push(')');
        }
    }
}

/// `a op b` for sort expressions.
fn binary_sort(out: &mut String, a: &SortExpr, op: &str, b: &SortExpr) {
    sort_expr(out, a);
    out.push(' ');
    out.push_str(op);
    out.push(' ');
    sort_expr(out, b);
}
