//! Theory terms and definitions (clingo 5's `#theory`): operator tables, the resolution of
//! terms written with operators into trees, and the printed form of definitions and atoms.
//!
//! Invariants:
//! - Resolution is gringo's shift-reduce reading: the first operators of a term and every
//!   operator after the first of a run are unary; the first of a run between two terms is
//!   binary; an operator on the stack is applied before a binary operator of lower priority, or
//!   of equal priority when that one is left-associative. An operator the table lacks (unary or
//!   binary, as it is used) is reported by name and the term is not resolved.
//! - Resolved operator terms are [`TheoryTermKind::Function`]s named by the operator; the
//!   printer writes terms as they were written (resolution changes nothing in the tree it
//!   was given), so printing and parsing again gives the same tree.

use hashbrown::HashMap;

use super::ast::*;
use super::printer;

/// The operators of one theory term definition.
#[derive(Clone, Debug, Default)]
pub struct OpTable {
    /// Unary operators with their priority.
    unary: HashMap<String, u32>,
    /// Binary operators with their priority and whether they are left-associative.
    binary: HashMap<String, (u32, bool)>,
}

impl OpTable {
    /// The table of a term definition.
    pub fn new(def: &TheoryTermDef) -> OpTable {
        let mut t = OpTable::default();
        for op in &def.ops {
            match op.kind {
                TheoryOpKind::Unary => {
                    t.unary.insert(op.op.clone(), op.priority);
                }
                TheoryOpKind::BinaryLeft => {
                    t.binary.insert(op.op.clone(), (op.priority, true));
                }
                TheoryOpKind::BinaryRight => {
                    t.binary.insert(op.op.clone(), (op.priority, false));
                }
            }
        }
        t
    }

    fn priority(&self, op: &str, unary: bool) -> u32 {
        if unary {
            self.unary.get(op).copied().unwrap_or(0)
        } else {
            self.binary.get(op).map_or(0, |p| p.0)
        }
    }
}

/// One entry of the resolution stack.
enum Entry {
    Op(String, bool),
    Term(TheoryTerm),
}

/// `term` with its operators resolved by `table` (recursively); `Err(op)` names the first
/// operator the table does not define.
pub fn resolve(term: &TheoryTerm, table: &OpTable) -> Result<TheoryTerm, String> {
    let span = term.span;
    let list = |ts: &[TheoryTerm]| -> Result<Vec<TheoryTerm>, String> {
        ts.iter().map(|t| resolve(t, table)).collect()
    };
    let kind = match &term.kind {
        TheoryTermKind::Symbol(_) => return Ok(term.clone()),
        TheoryTermKind::Function { name, args } => TheoryTermKind::Function {
            name: name.clone(),
            args: list(args)?,
        },
        TheoryTermKind::Tuple(ts) => TheoryTermKind::Tuple(list(ts)?),
        TheoryTermKind::Set(ts) => TheoryTermKind::Set(list(ts)?),
        TheoryTermKind::List(ts) => TheoryTermKind::List(list(ts)?),
        TheoryTermKind::Unparsed(parts) => {
            let mut stack: Vec<Entry> = Vec::new();
            let mut unary = true;
            for (ops, t) in parts {
                for op in ops {
                    let known = if unary {
                        table.unary.contains_key(op)
                    } else {
                        table.binary.contains_key(op)
                    };
                    if !known {
                        return Err(op.clone());
                    }
                    if !unary {
                        let (prio, left) = table.binary[op];
                        while stack.len() >= 2 {
                            let Entry::Op(prev, prev_unary) = &stack[stack.len() - 2] else {
                                break;
                            };
                            let p = table.priority(prev, *prev_unary);
                            if p > prio || (p == prio && left) {
                                reduce(&mut stack, span);
                            } else {
                                break;
                            }
                        }
                    }
                    stack.push(Entry::Op(op.clone(), unary));
                    unary = true;
                }
                stack.push(Entry::Term(resolve(t, table)?));
                unary = false;
            }
            while stack.len() > 1 {
                reduce(&mut stack, span);
            }
            return match stack.pop() {
                Some(Entry::Term(t)) => Ok(t),
                _ => Ok(term.clone()),
            };
        }
    };
    Ok(TheoryTerm { span, kind })
}

/// Applies the operator below the top term of `stack` to it (and, for a binary operator, to
/// the term below the operator).
fn reduce(stack: &mut Vec<Entry>, span: crate::base::Span) {
    let Some(Entry::Term(b)) = stack.pop() else {
        return;
    };
    let Some(Entry::Op(op, unary)) = stack.pop() else {
        return;
    };
    let args = if unary {
        vec![b]
    } else {
        let Some(Entry::Term(a)) = stack.pop() else {
            return;
        };
        vec![a, b]
    };
    stack.push(Entry::Term(TheoryTerm {
        span,
        kind: TheoryTermKind::Function { name: op, args },
    }));
}

/// Every variable name of `term`, in order of occurrence (repeats included).
pub fn variables<'t>(term: &'t TheoryTerm, out: &mut Vec<&'t Term>) {
    match &term.kind {
        TheoryTermKind::Symbol(t) => {
            if matches!(t.kind, TermKind::Variable(_)) {
                out.push(t);
            }
        }
        TheoryTermKind::Function { args: ts, .. }
        | TheoryTermKind::Tuple(ts)
        | TheoryTermKind::Set(ts)
        | TheoryTermKind::List(ts) => ts.iter().for_each(|t| variables(t, out)),
        TheoryTermKind::Unparsed(parts) => parts.iter().for_each(|(_, t)| variables(t, out)),
    }
}

// ----- printing, as written -----

/// `#theory name { ... }.`
pub fn write_def(out: &mut String, def: &TheoryDef) {
    out.push_str("#theory ");
    out.push_str(&def.name);
    out.push_str(" {");
    let mut first = true;
    for t in &def.terms {
        out.push_str(if first { " " } else { "; " });
        first = false;
        out.push_str(&t.name);
        out.push_str(" {");
        for (i, op) in t.ops.iter().enumerate() {
            out.push_str(if i == 0 { " " } else { "; " });
            out.push_str(&op.op);
            out.push_str(" : ");
            out.push_str(&op.priority.to_string());
            out.push_str(match op.kind {
                TheoryOpKind::Unary => ", unary",
                TheoryOpKind::BinaryLeft => ", binary, left",
                TheoryOpKind::BinaryRight => ", binary, right",
            });
        }
        out.push_str(" }");
    }
    for a in &def.atoms {
        out.push_str(if first { " " } else { "; " });
        first = false;
        out.push('&');
        out.push_str(&a.name);
        out.push('/');
        out.push_str(&a.arity.to_string());
        out.push_str(" : ");
        out.push_str(&a.elements);
        out.push_str(", ");
        if let Some((ops, guard)) = &a.guard {
            out.push_str("{ ");
            out.push_str(&ops.join(", "));
            out.push_str(" }, ");
            out.push_str(guard);
            out.push_str(", ");
        }
        out.push_str(match a.kind {
            TheoryAtomKind::Head => "head",
            TheoryAtomKind::Body => "body",
            TheoryAtomKind::Any => "any",
            TheoryAtomKind::Directive => "directive",
        });
    }
    out.push_str(" }.");
}

/// `&name(args){ elements } op guard`, as written.
pub fn write_atom(out: &mut String, atom: &TheoryAtom) {
    out.push('&');
    printer::symbolic(out, &atom.name);
    out.push_str(" {");
    for (i, e) in atom.elements.iter().enumerate() {
        out.push_str(if i == 0 { " " } else { "; " });
        write_terms(out, &e.terms);
        if !e.condition.is_empty() {
            out.push_str(" : ");
            printer::literals(out, &e.condition);
        } else if e.terms.is_empty() {
            out.push(':');
        }
    }
    out.push_str(" }");
    if let Some((op, t)) = &atom.guard {
        out.push(' ');
        out.push_str(op);
        out.push(' ');
        write_term(out, t);
    }
}

fn write_terms(out: &mut String, ts: &[TheoryTerm]) {
    for (i, t) in ts.iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        write_term(out, t);
    }
}

/// A theory term as written (operators separated by spaces, so runs stay apart).
pub fn write_term(out: &mut String, t: &TheoryTerm) {
    match &t.kind {
        TheoryTermKind::Symbol(s) => printer::term(out, s),
        TheoryTermKind::Function { name, args } => {
            out.push_str(name);
            out.push('(');
            write_terms(out, args);
            out.push(')');
        }
        TheoryTermKind::Tuple(ts) => {
            out.push('(');
            write_terms(out, ts);
            if ts.len() == 1 {
                out.push(',');
            }
            out.push(')');
        }
        TheoryTermKind::Set(ts) => {
            out.push('{');
            write_terms(out, ts);
            out.push('}');
        }
        TheoryTermKind::List(ts) => {
            out.push('[');
            write_terms(out, ts);
            out.push(']');
        }
        TheoryTermKind::Unparsed(parts) => {
            out.push('(');
            let mut first = true;
            for (ops, term) in parts {
                for op in ops {
                    if !first {
                        out.push(' ');
                    }
                    first = false;
                    out.push_str(op);
                }
                if !first {
                    out.push(' ');
                }
                first = false;
                write_term(out, term);
            }
            out.push(')');
        }
    }
}
