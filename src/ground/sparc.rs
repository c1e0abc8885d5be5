//! SPARC sorted programs (Balai, Gelfond, Zhang) translated to the clingo dialect before
//! grounding.
//!
//! The translation:
//! - Every sort definition `#s = e.` is evaluated to an explicit finite set of ground terms
//!   (sets, ranges with `#const` ends, `[a][1..3]` concatenation, unions `+`, differences `-`,
//!   intersections `*`, record sorts `f(#s1, #s2)` with optional variables and a condition), and
//!   each sort that the program uses becomes facts `sort_s(t).`.
//! - Every atom `p(t1, ..., tn)` of a rule is checked against the declaration
//!   `p(#s1, ..., #sn).`: an undeclared predicate, a wrong arity, or a ground argument outside
//!   its sort is an error at the argument's position (SPARC's typing).
//! - A non-ground argument `ti` adds `sort_si(ti)` to the rule's body (or to the condition it
//!   occurs in), so every variable ranges over the sort of each argument position it occupies,
//!   and rule instances whose arithmetic leaves the sort (e.g. `I+1` past the last step) do not
//!   exist. Sort atoms `#s(X)` in bodies become `sort_s(X)`.
//! - The `display` section becomes `#show.` plus one `#show t : t.` per displayed literal
//!   (`p.` shows every `p` atom; `-p.` every `-p` literal; `#s(X).` the members of `s`); without a
//!   display section every declared predicate is shown, positive and negative.
//!
//! Invariants: the output is an ordinary `Dialect::Clingo` program (CR rules stay CR rules);
//! sort predicates are named `sort_<name>` and never shown unless displayed; spans of generated
//! typing atoms are the spans of the arguments they type, so later diagnostics point at the
//! source.

use std::collections::{BTreeMap, BTreeSet};

use crate::base::{Diagnostic, Span};
use crate::syntax::ast::*;

/// Largest sort the translation builds (record sorts multiply).
const MAX_SORT_SIZE: usize = 5_000_000;

/// A ground value of a sort.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
enum Value {
    /// An integer.
    Int(i64),
    /// A constant.
    Sym(String),
    /// A string.
    Str(String),
    /// A function term or tuple (empty name).
    Func(String, Vec<Value>),
}

impl Value {
    /// clingo's term order: integers < constants < strings < functions (by arity, then name,
    /// then arguments).
    fn clingo_cmp(&self, other: &Value) -> std::cmp::Ordering {
        fn rank(v: &Value) -> u8 {
            match v {
                Value::Int(_) => 0,
                Value::Sym(_) => 1,
                Value::Str(_) => 2,
                Value::Func(..) => 3,
            }
        }
        match (self, other) {
            (Value::Func(n1, a1), Value::Func(n2, a2)) => a1
                .len()
                .cmp(&a2.len())
                .then_with(|| n1.cmp(n2))
                .then_with(|| {
                    for (x, y) in a1.iter().zip(a2) {
                        let c = x.clingo_cmp(y);
                        if c != std::cmp::Ordering::Equal {
                            return c;
                        }
                    }
                    std::cmp::Ordering::Equal
                }),
            (Value::Int(a), Value::Int(b)) => a.cmp(b),
            (Value::Sym(a), Value::Sym(b)) | (Value::Str(a), Value::Str(b)) => a.cmp(b),
            _ => rank(self).cmp(&rank(other)),
        }
    }

    /// The value as a syntax-tree term at `span`.
    fn to_term(&self, span: Span) -> Term {
        let kind = match self {
            Value::Int(i) => TermKind::Integer(*i),
            Value::Sym(s) => TermKind::Constant(s.clone()),
            Value::Str(s) => TermKind::String(s.clone()),
            Value::Func(name, args) => TermKind::Function {
                name: name.clone(),
                args: vec![args.iter().map(|a| a.to_term(span)).collect()],
                trailing_comma: name.is_empty() && args.len() == 1,
            },
        };
        Term { span, kind }
    }

    /// Text used when concatenating sort parts (`[book][1..3]`).
    fn concat_text(&self) -> String {
        match self {
            Value::Int(i) => i.to_string(),
            Value::Sym(s) | Value::Str(s) => s.clone(),
            Value::Func(..) => String::new(),
        }
    }
}

/// The state of one translation.
struct Translator<'a> {
    /// Diagnostics found so far.
    diags: &'a mut Vec<Diagnostic>,
    /// `#const` values that evaluate to ground values.
    consts: BTreeMap<String, Value>,
    /// Evaluated sorts, by name without `#`.
    sorts: BTreeMap<String, BTreeSet<Value>>,
    /// Span of each sort definition.
    sort_spans: BTreeMap<String, Span>,
    /// Declared predicates: name -> argument sort names.
    preds: BTreeMap<String, Vec<String>>,
    /// Sorts whose facts must be emitted.
    used: BTreeSet<String>,
}

/// Translates a SPARC program into the clingo dialect. Errors are appended to `diags`; the
/// returned program is still usable for further diagnostics.
pub fn to_clingo(program: &Program, diags: &mut Vec<Diagnostic>) -> Program {
    let mut t = Translator {
        diags,
        consts: BTreeMap::new(),
        sorts: BTreeMap::new(),
        sort_spans: BTreeMap::new(),
        preds: BTreeMap::new(),
        used: BTreeSet::new(),
    };
    let mut out: Vec<Statement> = Vec::new();
    let mut display: Vec<(Span, Literal)> = Vec::new();
    // Pass 1: constants, sorts and declarations, in order (a sort may use earlier ones).
    for statement in &program.statements {
        match &statement.kind {
            StatementKind::Const(c) => {
                if let Some(v) = t.eval_term(&c.value) {
                    t.consts.insert(c.name.clone(), v);
                }
                out.push(statement.clone());
            }
            StatementKind::SortDef(def) => {
                if let Some(set) = t.eval_sort(&def.expr) {
                    t.sorts.insert(def.name.clone(), set);
                    t.sort_spans.insert(def.name.clone(), statement.span);
                }
            }
            StatementKind::PredicateDecl(decl) => {
                for sort in &decl.sorts {
                    if !t.sorts.contains_key(sort) {
                        t.diags.push(Diagnostic::error(
                            statement.span,
                            format!("undefined sort #{sort} in the declaration of {}", decl.name),
                        ));
                    }
                }
                t.preds.insert(decl.name.clone(), decl.sorts.clone());
            }
            _ => {}
        }
    }
    // Pass 2: rules and display items.
    for statement in &program.statements {
        match &statement.kind {
            StatementKind::Rule(rule) => {
                let rule = t.rule(rule);
                out.push(Statement {
                    span: statement.span,
                    kind: StatementKind::Rule(rule),
                });
            }
            StatementKind::Display(lit) => display.push((statement.span, lit.clone())),
            StatementKind::Const(_)
            | StatementKind::SortDef(_)
            | StatementKind::PredicateDecl(_)
            | StatementKind::Section(_)
            | StatementKind::Error => {}
            _ => out.push(statement.clone()),
        }
    }
    // Show statements.
    let span0 = program
        .statements
        .first()
        .map(|s| s.span)
        .unwrap_or_default();
    out.push(Statement {
        span: span0,
        kind: StatementKind::Show(Show::Nothing),
    });
    if display.is_empty() {
        let preds: Vec<(String, usize)> =
            t.preds.iter().map(|(n, s)| (n.clone(), s.len())).collect();
        for (name, arity) in preds {
            for negated in [false, true] {
                out.push(t.show_all(span0, &name, arity, negated));
            }
        }
    } else {
        for (span, lit) in display {
            if let Some(s) = t.display_item(span, &lit) {
                out.push(s);
            }
        }
    }
    // Sort facts for every sort the program uses.
    let mut facts = Vec::new();
    for name in &t.used {
        let Some(set) = t.sorts.get(name) else {
            continue;
        };
        let span = t.sort_spans.get(name).copied().unwrap_or(span0);
        for value in set {
            let atom = sort_atom(name, value.to_term(span), span);
            facts.push(Statement {
                span,
                kind: StatementKind::Rule(Rule {
                    head: Head::Disjunction(vec![ConditionalLiteral {
                        span,
                        literal: atom,
                        condition: Vec::new(),
                        has_colon: false,
                    }]),
                    body: Vec::new(),
                    kind: RuleKind::Normal,
                }),
            });
        }
    }
    facts.extend(out);
    Program {
        dialect: Dialect::Clingo,
        statements: facts,
    }
}

/// The literal `sort_<name>(term)`.
fn sort_atom(name: &str, term: Term, span: Span) -> Literal {
    Literal {
        span,
        sign: Sign::Positive,
        atom: Atom::Symbolic(SymbolicAtom {
            span,
            negated: false,
            name: format!("sort_{name}"),
            args: vec![vec![term]],
        }),
    }
}

/// True when two typing literals type the same term by the same sort (spans aside).
fn same_typing(a: &Literal, b: &Literal) -> bool {
    let text = |l: &Literal| match &l.atom {
        Atom::Symbolic(atom) => {
            let mut out = atom.name.clone();
            for t in atom.args.iter().flatten() {
                out.push('|');
                crate::syntax::printer::term(&mut out, t);
            }
            out
        }
        _ => String::new(),
    };
    text(a) == text(b)
}

/// True when the term contains a variable.
fn has_variable(term: &Term) -> bool {
    match &term.kind {
        TermKind::Variable(_) | TermKind::Anonymous => true,
        TermKind::Function { args, .. } => args.iter().flatten().any(has_variable),
        TermKind::ScriptCall { args, .. } => args.iter().any(has_variable),
        TermKind::Unary { arg, .. } | TermKind::Paren(arg) => has_variable(arg),
        TermKind::Binary { lhs, rhs, .. } => has_variable(lhs) || has_variable(rhs),
        TermKind::Interval { lo, hi } => has_variable(lo) || has_variable(hi),
        TermKind::Pool(ts) => ts.iter().any(has_variable),
        _ => false,
    }
}

impl Translator<'_> {
    /// Evaluates a ground term (constants replaced by `#const` values, arithmetic done).
    fn eval_term(&self, term: &Term) -> Option<Value> {
        Some(match &term.kind {
            TermKind::Integer(i) => Value::Int(*i),
            TermKind::String(s) => Value::Str(s.clone()),
            TermKind::Constant(c) => self
                .consts
                .get(c)
                .cloned()
                .unwrap_or_else(|| Value::Sym(c.clone())),
            TermKind::Function { name, args, .. } if args.len() == 1 => Value::Func(
                name.clone(),
                args[0]
                    .iter()
                    .map(|a| self.eval_term(a))
                    .collect::<Option<_>>()?,
            ),
            TermKind::Paren(t) => self.eval_term(t)?,
            TermKind::Unary {
                op: UnaryOp::Minus,
                arg,
            } => match self.eval_term(arg)? {
                Value::Int(i) => Value::Int(-i),
                Value::Sym(s) => Value::Func(format!("-{s}"), Vec::new()),
                _ => return None,
            },
            TermKind::Binary { op, lhs, rhs } => {
                let (Value::Int(a), Value::Int(b)) = (self.eval_term(lhs)?, self.eval_term(rhs)?)
                else {
                    return None;
                };
                Value::Int(match op {
                    BinaryOp::Add => a.checked_add(b)?,
                    BinaryOp::Sub => a.checked_sub(b)?,
                    BinaryOp::Mul => a.checked_mul(b)?,
                    BinaryOp::Div if b != 0 => a.div_euclid(b),
                    BinaryOp::Mod if b != 0 => a.rem_euclid(b),
                    _ => return None,
                })
            }
            _ => return None,
        })
    }

    /// An integer for a range end.
    fn eval_int(&mut self, term: &Term) -> Option<i64> {
        match self.eval_term(term) {
            Some(Value::Int(i)) => Some(i),
            _ => {
                self.diags.push(Diagnostic::error(
                    term.span,
                    "a range end of a sort must be an integer or an integer #const",
                ));
                None
            }
        }
    }

    fn check_size(&mut self, span: Span, size: usize) -> bool {
        if size > MAX_SORT_SIZE {
            self.diags.push(Diagnostic::error(
                span,
                format!("sort too large: more than {MAX_SORT_SIZE} elements"),
            ));
            return false;
        }
        true
    }

    /// Evaluates a sort expression to its set of ground terms.
    fn eval_sort(&mut self, expr: &SortExpr) -> Option<BTreeSet<Value>> {
        match &expr.kind {
            SortExprKind::Set(terms) => {
                let mut set = BTreeSet::new();
                for term in terms {
                    if let TermKind::Interval { lo, hi } = &term.kind {
                        let (lo, hi) = (self.eval_int(lo)?, self.eval_int(hi)?);
                        if !self.check_size(term.span, (hi - lo).max(0) as usize) {
                            return None;
                        }
                        set.extend((lo..=hi).map(Value::Int));
                        continue;
                    }
                    match self.eval_term(term) {
                        Some(v) => {
                            set.insert(v);
                        }
                        None => {
                            self.diags.push(Diagnostic::error(
                                term.span,
                                "a sort's elements must be ground terms",
                            ));
                            return None;
                        }
                    }
                }
                Some(set)
            }
            SortExprKind::Range(lo, hi) => {
                let (lo, hi) = (self.eval_int(lo)?, self.eval_int(hi)?);
                if !self.check_size(expr.span, (hi - lo).max(0) as usize) {
                    return None;
                }
                Some((lo..=hi).map(Value::Int).collect())
            }
            SortExprKind::Ref(name) => match self.sorts.get(name) {
                Some(set) => Some(set.clone()),
                None => {
                    self.diags.push(Diagnostic::error(
                        expr.span,
                        format!("undefined sort #{name}"),
                    ));
                    None
                }
            },
            SortExprKind::Concat(parts) => {
                let mut acc: Vec<String> = vec![String::new()];
                for part in parts {
                    let set = self.eval_sort(part)?;
                    if !self.check_size(part.span, acc.len() * set.len()) {
                        return None;
                    }
                    acc = acc
                        .iter()
                        .flat_map(|prefix| {
                            set.iter()
                                .map(move |v| format!("{prefix}{}", v.concat_text()))
                        })
                        .collect();
                }
                Some(
                    acc.into_iter()
                        .map(|s| match s.parse::<i64>() {
                            Ok(i) => Value::Int(i),
                            Err(_) => Value::Sym(s),
                        })
                        .collect(),
                )
            }
            SortExprKind::Record {
                name,
                args,
                condition,
            } => {
                let mut sets = Vec::new();
                let mut size = 1usize;
                for (arg, _) in args {
                    let set = self.eval_sort(arg)?;
                    size = size.saturating_mul(set.len());
                    sets.push(set.into_iter().collect::<Vec<_>>());
                }
                if !self.check_size(expr.span, size) {
                    return None;
                }
                let vars: Vec<Option<&String>> = args.iter().map(|(_, v)| v.as_ref()).collect();
                let mut out = BTreeSet::new();
                let mut tuple: Vec<Value> = Vec::with_capacity(sets.len());
                self.records(&sets, &vars, condition, &mut tuple, name, &mut out)?;
                Some(out)
            }
            SortExprKind::Union(a, b) => {
                let mut x = self.eval_sort(a)?;
                x.extend(self.eval_sort(b)?);
                Some(x)
            }
            SortExprKind::Difference(a, b) => {
                let x = self.eval_sort(a)?;
                let y = self.eval_sort(b)?;
                Some(x.difference(&y).cloned().collect())
            }
            SortExprKind::Intersection(a, b) => {
                let x = self.eval_sort(a)?;
                let y = self.eval_sort(b)?;
                Some(x.intersection(&y).cloned().collect())
            }
            SortExprKind::Paren(e) => self.eval_sort(e),
        }
    }

    /// Enumerates the records `name(v1, ..., vn)` whose arguments satisfy `condition`.
    fn records(
        &mut self,
        sets: &[Vec<Value>],
        vars: &[Option<&String>],
        condition: &[Literal],
        tuple: &mut Vec<Value>,
        name: &str,
        out: &mut BTreeSet<Value>,
    ) -> Option<()> {
        if tuple.len() == sets.len() {
            for lit in condition {
                if !self.condition_holds(lit, vars, tuple)? {
                    return Some(());
                }
            }
            out.insert(Value::Func(name.to_string(), tuple.clone()));
            return Some(());
        }
        for v in &sets[tuple.len()] {
            tuple.push(v.clone());
            self.records(sets, vars, condition, tuple, name, out)?;
            tuple.pop();
        }
        Some(())
    }

    /// Evaluates a record sort's condition literal under the record's variable values.
    fn condition_holds(
        &mut self,
        lit: &Literal,
        vars: &[Option<&String>],
        values: &[Value],
    ) -> Option<bool> {
        let value_of = |t: &Term, me: &Translator| -> Option<Value> {
            if let TermKind::Variable(v) = &t.kind {
                let i = vars.iter().position(|x| x.map(String::as_str) == Some(v))?;
                return Some(values[i].clone());
            }
            me.eval_term(t)
        };
        let Atom::Comparison { lhs, op, rhs } = &lit.atom else {
            self.diags.push(Diagnostic::error(
                lit.span,
                "a record sort's condition may only compare its variables",
            ));
            return None;
        };
        let (Some(a), Some(b)) = (value_of(lhs, self), value_of(rhs, self)) else {
            self.diags.push(Diagnostic::error(
                lit.span,
                "a record sort's condition may only compare its variables and ground terms",
            ));
            return None;
        };
        let ord = a.clingo_cmp(&b);
        let holds = match op {
            CmpOp::Eq => ord.is_eq(),
            CmpOp::Ne => ord.is_ne(),
            CmpOp::Lt => ord.is_lt(),
            CmpOp::Le => ord.is_le(),
            CmpOp::Gt => ord.is_gt(),
            CmpOp::Ge => ord.is_ge(),
        };
        Some(if lit.sign == Sign::Not { !holds } else { holds })
    }

    /// The sort of argument `i` of predicate `name`, checking declaration and arity.
    fn check_atom(&mut self, atom: &SymbolicAtom, typing: &mut Vec<Literal>) {
        let arity = atom.args.first().map_or(0, Vec::len);
        let Some(sorts) = self.preds.get(&atom.name).cloned() else {
            self.diags.push(Diagnostic::error(
                atom.span,
                format!("predicate {}/{arity} is not declared", atom.name),
            ));
            return;
        };
        for args in &atom.args {
            if args.len() != sorts.len() {
                self.diags.push(Diagnostic::error(
                    atom.span,
                    format!(
                        "{} has {} argument(s) but is declared with {}",
                        atom.name,
                        args.len(),
                        sorts.len()
                    ),
                ));
                return;
            }
            for (arg, sort) in args.iter().zip(&sorts) {
                self.used.insert(sort.clone());
                if has_variable(arg) {
                    let lit = sort_atom(sort, arg.clone(), arg.span);
                    if !typing.iter().any(|t| same_typing(t, &lit)) {
                        typing.push(lit);
                    }
                } else if let Some(v) = self.eval_term(arg) {
                    if !self.sorts.get(sort).is_some_and(|s| s.contains(&v)) {
                        self.diags.push(Diagnostic::error(
                            arg.span,
                            format!(
                                "ill-typed atom: argument {} of {} is not of sort #{sort}",
                                {
                                    let mut text = String::new();
                                    crate::syntax::printer::term(&mut text, arg);
                                    text
                                },
                                atom.name
                            ),
                        ));
                    }
                } else {
                    // A ground term that does not evaluate (e.g. undefined arithmetic): type it
                    // at grounding time.
                    typing.push(sort_atom(sort, arg.clone(), arg.span));
                }
            }
        }
    }

    /// Types a literal: checks it and collects typing literals; rewrites sort atoms.
    fn literal(&mut self, lit: &Literal, typing: &mut Vec<Literal>) -> Literal {
        match &lit.atom {
            Atom::Symbolic(a) => {
                self.check_atom(a, typing);
                lit.clone()
            }
            Atom::Sort { sort, arg } => {
                if !self.sorts.contains_key(sort) {
                    self.diags.push(Diagnostic::error(
                        lit.span,
                        format!("undefined sort #{sort}"),
                    ));
                }
                self.used.insert(sort.clone());
                let mut l = sort_atom(sort, arg.clone(), lit.span);
                l.sign = lit.sign;
                l
            }
            _ => lit.clone(),
        }
    }

    /// A condition list with its own typing literals appended.
    fn condition(&mut self, condition: &[Literal]) -> Vec<Literal> {
        let mut typing = Vec::new();
        let mut out: Vec<Literal> = condition
            .iter()
            .map(|l| self.literal(l, &mut typing))
            .collect();
        out.extend(typing);
        out
    }

    fn conditional(
        &mut self,
        c: &ConditionalLiteral,
        typing: &mut Vec<Literal>,
    ) -> ConditionalLiteral {
        let mut local = Vec::new();
        let literal = self.literal(&c.literal, &mut local);
        let mut condition = self.condition(&c.condition);
        if c.condition.is_empty() && !c.has_colon {
            typing.extend(local);
        } else {
            condition.extend(local);
        }
        ConditionalLiteral {
            span: c.span,
            literal,
            has_colon: c.has_colon || !condition.is_empty(),
            condition,
        }
    }

    /// Types a rule.
    fn rule(&mut self, rule: &Rule) -> Rule {
        let mut typing: Vec<Literal> = Vec::new();
        let head = match &rule.head {
            Head::None => Head::None,
            Head::Disjunction(elems) => Head::Disjunction(
                elems
                    .iter()
                    .map(|c| self.conditional(c, &mut typing))
                    .collect(),
            ),
            Head::Choice(choice) => {
                let mut ch = choice.clone();
                ch.elements = choice
                    .elements
                    .iter()
                    .map(|c| {
                        let mut local = Vec::new();
                        let mut c2 = self.conditional(c, &mut local);
                        c2.condition.extend(local);
                        c2.has_colon = c2.has_colon || !c2.condition.is_empty();
                        c2
                    })
                    .collect();
                Head::Choice(ch)
            }
            Head::Aggregate(agg) => Head::Aggregate(agg.clone()),
        };
        let mut body: Vec<BodyLiteral> = Vec::new();
        for b in &rule.body {
            body.push(match b {
                BodyLiteral::Literal(l) => BodyLiteral::Literal(self.literal(l, &mut typing)),
                BodyLiteral::Conditional(c) => {
                    let mut local = Vec::new();
                    let mut c2 = self.conditional(c, &mut local);
                    c2.condition.extend(local);
                    c2.has_colon = c2.has_colon || !c2.condition.is_empty();
                    BodyLiteral::Conditional(c2)
                }
                BodyLiteral::Aggregate { sign, aggregate } => {
                    let mut agg = aggregate.clone();
                    for e in &mut agg.elements {
                        e.condition = self.condition(&e.condition);
                    }
                    BodyLiteral::Aggregate {
                        sign: *sign,
                        aggregate: agg,
                    }
                }
            });
        }
        let mut unique: Vec<Literal> = Vec::new();
        for lit in typing {
            if !unique.iter().any(|u| same_typing(u, &lit)) {
                unique.push(lit);
            }
        }
        body.extend(unique.into_iter().map(BodyLiteral::Literal));
        Rule {
            head,
            body,
            kind: rule.kind.clone(),
        }
    }

    /// `#show t : t.` for every `[-]name/arity` atom.
    fn show_all(&mut self, span: Span, name: &str, arity: usize, negated: bool) -> Statement {
        let args: Vec<Term> = (0..arity)
            .map(|i| Term {
                span,
                kind: TermKind::Variable(format!("X{i}")),
            })
            .collect();
        let atom = SymbolicAtom {
            span,
            negated,
            name: name.to_string(),
            args: vec![args],
        };
        self.show_atom(span, atom)
    }

    fn show_atom(&mut self, span: Span, atom: SymbolicAtom) -> Statement {
        let mut term = Term {
            span,
            kind: TermKind::Function {
                name: atom.name.clone(),
                args: atom.args.clone(),
                trailing_comma: false,
            },
        };
        if atom.negated {
            term = Term {
                span,
                kind: TermKind::Unary {
                    op: UnaryOp::Minus,
                    arg: Box::new(term),
                },
            };
        }
        let lit = Literal {
            span,
            sign: Sign::Positive,
            atom: Atom::Symbolic(atom),
        };
        Statement {
            span,
            kind: StatementKind::Show(Show::Term {
                term,
                body: vec![BodyLiteral::Literal(lit)],
            }),
        }
    }

    /// One display item.
    fn display_item(&mut self, span: Span, lit: &Literal) -> Option<Statement> {
        match &lit.atom {
            Atom::Symbolic(a) => {
                let written = a.args.first().map_or(0, Vec::len);
                let Some(sorts) = self.preds.get(&a.name) else {
                    self.diags.push(Diagnostic::error(
                        a.span,
                        format!("displayed predicate {} is not declared", a.name),
                    ));
                    return None;
                };
                if written == 0 && !sorts.is_empty() {
                    return Some(self.show_all(span, &a.name, sorts.len(), a.negated));
                }
                let mut typing = Vec::new();
                self.check_atom(a, &mut typing);
                Some(self.show_atom(span, a.clone()))
            }
            Atom::Sort { sort, arg } => {
                self.used.insert(sort.clone());
                let term = Term {
                    span,
                    kind: TermKind::Function {
                        name: sort.clone(),
                        args: vec![vec![arg.clone()]],
                        trailing_comma: false,
                    },
                };
                Some(Statement {
                    span,
                    kind: StatementKind::Show(Show::Term {
                        term,
                        body: vec![BodyLiteral::Literal(sort_atom(sort, arg.clone(), span))],
                    }),
                })
            }
            _ => {
                self.diags.push(Diagnostic::error(
                    lit.span,
                    "a display item must be a predicate or a sort atom",
                ));
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::FileId;

    fn translate(text: &str) -> (String, Vec<String>) {
        let parse = crate::syntax::parse(FileId(0), text, Dialect::Sparc);
        assert!(!parse.has_errors(), "{:?}", parse.diagnostics);
        let mut diags = Vec::new();
        let program = to_clingo(&parse.program, &mut diags);
        (
            crate::syntax::print(&program),
            diags.into_iter().map(|d| d.message).collect(),
        )
    }

    #[test]
    fn sorts_evaluate_to_facts() {
        let (text, diags) = translate(
            "#const n = 2.\nsorts\n#b = [book][1..2].\n#s = 0..n.\n#o = #b + {duck}.\n\
             #r = f(#o(X), #o(Y)) : X != Y.\npredicates\np(#r, #s).\nrules\np(f(book1, duck), 0).\n",
        );
        assert!(diags.is_empty(), "{diags:?}");
        // Records over distinct pairs of the three objects: 3 * 2 = 6 facts.
        assert_eq!(text.matches("sort_r(").count(), 6, "{text}");
        assert!(text.contains("sort_r(f(book1, duck))"), "{text}");
        assert!(text.contains("sort_s(2)"), "{text}");
        assert!(!text.contains("sort_s(3)"), "{text}");
    }

    #[test]
    fn variables_are_typed_by_their_positions() {
        let (text, diags) = translate(
            "sorts\n#step = 0..2.\n#obj = {a, b}.\npredicates\nq(#obj, #step).\nr(#obj).\nrules\n\
             q(X, I + 1) :- q(X, I), not r(X).\n",
        );
        assert!(diags.is_empty(), "{diags:?}");
        assert!(
            text.contains(
                "q(X, I + 1) :- q(X, I), not r(X), sort_obj(X), sort_step(I + 1), sort_step(I)."
            ),
            "{text}"
        );
        assert!(text.contains("sort_obj(X)"), "{text}");
        assert!(text.contains("sort_step(I)"), "{text}");
    }

    #[test]
    fn ill_typed_atoms_are_errors() {
        let (_, diags) = translate(
            "sorts\n#obj = {a, b}.\npredicates\nr(#obj).\nrules\nr(c).\ns(a).\nr(a, b).\n",
        );
        assert_eq!(diags.len(), 3, "{diags:?}");
        assert!(diags[0].contains("not of sort #obj"));
        assert!(diags[1].contains("s/1 is not declared"));
        assert!(diags[2].contains("declared with 1"));
    }
}
