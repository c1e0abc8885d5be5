//! SPARC sorted programs (Balai, Gelfond, Zhang): sort definitions are evaluated to sets of
//! ground terms, predicate declarations type every argument position, and the program is
//! lowered to the clingo dialect the rest of the grounder understands.
//!
//! Rules implemented (SPARC's manual, iensen/sparc `User_Manual`):
//! - `#maxint = N.` bounds arithmetic: the built-in sort `#nat` is `0..N`; a program without
//!   `#maxint` has `#nat = 0..1000000`, SPARC's default maximal integer (`sorts/BuiltIn.java`
//!   of iensen/sparc), built only when the program names `#nat`;
//! - a sort is the set its expression denotes: `{a, f(b)}` its elements, `lo..hi` the integers
//!   between (ends may be `#const` names; `hi < lo` is an error), `id1..id2` the identifiers
//!   `s` with `id1 <= s <= id2` and `|id1| <= |s| <= |id2|` over letters, digits and `_`
//!   (by character code; at most 100,000 of them), `[id][1..3]` the constants made by
//!   concatenating one choice per part (`id1`, `id2`, `id3`), `f(#s1, #s2)` every `f(x, y)`
//!   with `x` in `#s1` and `y` in `#s2` and, with variables `f(#s1(X), #s2(Y)) : c`, those
//!   satisfying the condition `c` (comparisons joined by `and`, `or`, `not(...)`), `+` union,
//!   `-` difference, `*` intersection, `#s` a sort defined earlier;
//! - errors: a sort defined twice, an empty sort, a predicate declared twice, an undefined
//!   sort, a record condition over variables it does not name, a concatenation of anything
//!   but identifiers and natural numbers, a range mixing an integer and an identifier;
//! - a sort `#s` becomes facts `#s(x)` of a hidden predicate;
//! - every atom `p(t1, ..., tn)` of a rule must match the declaration `p(#s1, ..., #sn)`: an
//!   undeclared predicate, a wrong arity, a ground argument (intervals expanded) outside its
//!   sort, an argument no element of the sort has the shape of (`g(X)` for a sort without
//!   `g`), or arithmetic in an argument whose sort has no numbers is an error at the atom;
//!   an argument with variables gets the typing literal `#si(ti)`, so every variable ranges
//!   over the sort of the positions it occupies. The typing literal goes to the rule body,
//!   except for an element of a choice or head aggregate, or a condition, whose own (local)
//!   variables it types: there it joins the element's condition (`1{has(X,C)}1 :- #r(X).`
//!   chooses one `C` of `has`'s second sort for each `X`);
//! - with `#maxint`, a variable that no atom argument binds outside arithmetic (it occurs
//!   only in comparisons or under `+ - * / \`) ranges over `#nat`;
//! - every declared predicate is `#defined` (SPARC programs get no "atom does not occur in
//!   any rule head" warnings for them);
//! - the `display` section becomes `#show` statements: `p.` shows every `p` atom, `-p.` every
//!   `-p` literal, a pattern `p(X, a).` the atoms matching it, `#s.` the sort's atoms; without
//!   a display section every atom is shown.

use hashbrown::{HashMap, HashSet};

use crate::base::{Diagnostic, Span};
use crate::syntax::ast::{
    self, CmpOp, RecordCondition, Sign, SortExpr, SortExprKind, StatementKind, TermKind,
};

use super::rewrite::{unpool_term, Rewriter};
use super::symbol::{SymData, SymId, Symbols};

mod sorts;
mod typing;

use typing::{sort_literal, variable};

/// SPARC's maximal integer when the program sets no `#maxint`: `#nat` is then `0..1000000`.
const DEFAULT_MAXINT: i32 = 1_000_000;

/// Most elements an identifier range, or the interval expansion of one argument, may have
/// (SPARC's own sort capacity).
const MAX_GENERATED: usize = 100_000;

/// The characters an identifier range ranges over, in character-code order: lower-case letters
/// only, as SPARC's own test suite has it (`[ab..cd]` has 55 members: ab..az, ba..bz, ca..cd).
const ID_CHARS: &[u8] = b"abcdefghijklmnopqrstuvwxyz";

/// The evaluated sorts and predicate declarations of a SPARC program.
#[derive(Default)]
struct Typing {
    /// Elements of each sort (name without `#`), in definition order of first appearance.
    sorts: HashMap<String, Vec<SymId>>,
    /// The same as sets, for membership checks.
    members: HashMap<String, HashSet<SymId>>,
    /// The sorts with at least one integer.
    numeric: HashSet<String>,
    /// Where each sort was defined (`None` for the built-in `#nat`).
    sort_spans: HashMap<String, Option<Span>>,
    /// Argument sorts of each declared predicate.
    decls: HashMap<String, Vec<String>>,
    /// Where each predicate was declared.
    decl_spans: HashMap<String, Span>,
    /// The `#maxint` value, when the program sets one.
    maxint: Option<i32>,
    /// Sorts whose definition had an error (reported once: uses of them stay silent).
    failed: HashSet<String>,
}

fn has_vars(t: &ast::Term) -> bool {
    match &t.kind {
        TermKind::Variable(_) | TermKind::Anonymous => true,
        TermKind::Function { args, .. } => args.iter().flatten().any(has_vars),
        TermKind::Unary { arg, .. } | TermKind::Paren(arg) => has_vars(arg),
        TermKind::Binary { lhs, rhs, .. } => has_vars(lhs) || has_vars(rhs),
        TermKind::Interval { lo, hi } => has_vars(lo) || has_vars(hi),
        TermKind::Pool(ts) => ts.iter().any(has_vars),
        TermKind::ScriptCall { args, .. } => args.iter().any(has_vars),
        _ => false,
    }
}

fn snippet(rw: &Rewriter<'_>, span: Span) -> String {
    match rw.sources {
        Some(s) if (span.file.0 as usize) < s.len() => s.get(span.file).slice(span).to_string(),
        _ => String::new(),
    }
}

/// Reports a second definition (`verb`: "defined", "declared") of `what`, pointing at the
/// first when it has a place.
fn twice(rw: &mut Rewriter<'_>, span: Span, what: String, verb: &str, first: Option<Span>) {
    let d =
        Diagnostic::error(span, format!("{what} is {verb} twice")).with_snippet(snippet(rw, span));
    rw.diags.push(match first {
        Some(f) => d.with_note(Some(f), format!("first {verb} here")),
        None => d.with_note(None, "#nat is built in: 0..#maxint"),
    });
}

/// Lowers a SPARC program to the clingo dialect: registers the sorts (as facts of `#s/1` in
/// `rw.out.sort_facts`) and returns the typed statements, every declared predicate
/// `#defined`, display items turned into `#show`.
pub fn lower(rw: &mut Rewriter<'_>, program: &ast::Program) -> ast::Program {
    let mut typing = Typing::default();
    let mut statements = Vec::new();
    let mut displays: Vec<(Span, &StatementKind)> = Vec::new();
    let user_nat = program
        .statements
        .iter()
        .any(|s| matches!(&s.kind, StatementKind::SortDef(d) if d.name == "nat"));
    let has_maxint = program
        .statements
        .iter()
        .any(|s| matches!(s.kind, StatementKind::MaxInt(_)));
    if !has_maxint && !user_nat && sorts::mentions_sort(program, "nat") {
        // Without #maxint, variables bound by no atom keep their own ranges (`typing.maxint`
        // stays unset); only the sort itself is built in.
        let set: Vec<SymId> = (0..=DEFAULT_MAXINT).map(|i| rw.syms.int(i)).collect();
        typing.define(rw, "nat", set, None);
    }
    for st in &program.statements {
        match &st.kind {
            StatementKind::MaxInt(t) => {
                let Some(v) = rw.eval_ground(t) else { continue };
                let n = rw.syms.num(v).filter(|&n| n >= 0);
                let Some(n) = n else {
                    rw.diags.push(
                        Diagnostic::error(t.span, "#maxint needs a non-negative integer")
                            .with_snippet(snippet(rw, st.span)),
                    );
                    continue;
                };
                if typing.maxint.is_some() {
                    rw.diags.push(
                        Diagnostic::error(st.span, "#maxint is set twice")
                            .with_snippet(snippet(rw, st.span)),
                    );
                    continue;
                }
                typing.maxint = Some(n);
                if !user_nat {
                    let set: Vec<SymId> = (0..=n).map(|i| rw.syms.int(i)).collect();
                    typing.define(rw, "nat", set, None);
                }
            }
            StatementKind::SortDef(d) => {
                if let Some(first) = typing.sort_spans.get(&d.name) {
                    let first = *first;
                    twice(rw, st.span, format!("sort #{}", d.name), "defined", first);
                    continue;
                }
                match typing.eval(rw, &d.expr) {
                    Some(set) if !set.is_empty() => typing.define(rw, &d.name, set, Some(st.span)),
                    failed => {
                        if failed.is_some() {
                            rw.diags.push(
                                Diagnostic::error(st.span, format!("sort #{} is empty", d.name))
                                    .with_snippet(snippet(rw, st.span)),
                            );
                        }
                        typing.failed.insert(d.name.clone());
                        typing.sort_spans.insert(d.name.clone(), Some(st.span));
                        rw.sorts.push(format!("#{}", d.name));
                    }
                }
            }
            StatementKind::PredicateDecl(p) => {
                if let Some(&first) = typing.decl_spans.get(&p.name) {
                    twice(
                        rw,
                        st.span,
                        format!("predicate {}", p.name),
                        "declared",
                        Some(first),
                    );
                    continue;
                }
                for s in &p.sorts {
                    if !typing.sorts.contains_key(s) && !typing.failed.contains(s) {
                        let d = typing.undefined(rw, st.span, s);
                        rw.diags.push(d);
                    }
                }
                typing.decl_spans.insert(p.name.clone(), st.span);
                typing.decls.insert(p.name.clone(), p.sorts.clone());
            }
            StatementKind::Section(_) => {}
            StatementKind::Display(_) | StatementKind::DisplaySort(_) => {
                displays.push((st.span, &st.kind))
            }
            StatementKind::Rule(r) => {
                if let Some(r) = typing.rule(rw, r, st.span) {
                    statements.push(ast::Statement {
                        span: st.span,
                        kind: StatementKind::Rule(r),
                    });
                }
            }
            _ => statements.push(st.clone()),
        }
    }
    // Sort memberships, in definition order.
    let mut names: Vec<&String> = typing.sorts.keys().collect();
    names.sort_by_key(|n| rw.sorts.iter().position(|s| &s[1..] == n.as_str()));
    for name in names {
        let pred = rw.pred(&format!("#{name}"), 1, false);
        for &v in &typing.sorts[name] {
            rw.out.sort_facts.push((pred, v));
        }
    }
    // Declared predicates are defined: no "atom does not occur in any rule head" for them.
    let mut declared: Vec<(&String, &Span)> = typing.decl_spans.iter().collect();
    declared.sort_by_key(|(_, s)| (s.file.0, s.start));
    for (name, &span) in declared {
        for negated in [false, true] {
            statements.push(ast::Statement {
                span,
                kind: StatementKind::Defined(ast::Signature {
                    negated,
                    name: name.clone(),
                    arity: typing.decls[name].len() as u32,
                }),
            });
        }
    }
    displays_to_shows(rw, &typing, displays, &mut statements);
    // Without a display section everything is shown.
    if program
        .statements
        .iter()
        .any(|s| matches!(s.kind, StatementKind::Section(ast::Section::Display)))
    {
        rw.out.show.restricted = true;
    }
    ast::Program {
        dialect: ast::Dialect::Clingo,
        statements,
    }
}

/// The display items as `#show` statements, appended to `statements`: `p.` shows the
/// predicate, `#s.` the sort, a pattern the atoms matching it.
fn displays_to_shows(
    rw: &mut Rewriter<'_>,
    typing: &Typing,
    displays: Vec<(Span, &StatementKind)>,
    statements: &mut Vec<ast::Statement>,
) {
    // display: `p.` shows the predicate, `#s.` the sort, a pattern the atoms matching it.
    for (span, item) in displays {
        let sort_item;
        let l = match item {
            StatementKind::DisplaySort(sort) => {
                if !typing.sorts.contains_key(sort) {
                    let d = typing.undefined(rw, span, sort);
                    rw.diags.push(d);
                    continue;
                }
                // `#s.` is the pattern `#s(X).`: sort predicates are never shown by name.
                sort_item = sort_literal(span, sort, variable(span, "X"));
                &sort_item
            }
            StatementKind::Display(l) => &**l,
            _ => continue,
        };
        match &l.atom {
            ast::Atom::Symbolic(a) if a.args.iter().all(|list| list.is_empty()) => {
                let arity = typing.decls.get(a.name.as_str()).map_or(0, |d| d.len()) as u32;
                statements.push(ast::Statement {
                    span,
                    kind: StatementKind::Show(Box::new(ast::Show::Signature(ast::Signature {
                        negated: a.negated,
                        name: a.name.to_string(),
                        arity,
                    }))),
                });
            }
            ast::Atom::Symbolic(a) => {
                let term = ast::Term {
                    span: a.span,
                    kind: TermKind::Function {
                        name: a.name.clone(),
                        args: a.args.clone(),
                        trailing_comma: false,
                    },
                };
                let term = if a.negated {
                    ast::Term {
                        span: a.span,
                        kind: TermKind::Unary {
                            op: ast::UnaryOp::Minus,
                            arg: Box::new(term),
                        },
                    }
                } else {
                    term
                };
                statements.push(ast::Statement {
                    span,
                    kind: StatementKind::Show(Box::new(ast::Show::Term {
                        term,
                        body: vec![ast::BodyLiteral::Literal(l.clone())],
                    })),
                });
            }
            ast::Atom::Sort { sort, arg } => {
                let term = ast::Term {
                    span: l.span,
                    kind: TermKind::Function {
                        name: format!("#{sort}").into(),
                        args: vec![vec![(**arg).clone()]],
                        trailing_comma: false,
                    },
                };
                statements.push(ast::Statement {
                    span,
                    kind: StatementKind::Show(Box::new(ast::Show::Term {
                        term,
                        body: vec![ast::BodyLiteral::Literal(l.clone())],
                    })),
                });
            }
            _ => {}
        }
    }
}
