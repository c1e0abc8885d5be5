//! Theory atoms for Python (clingo's `Control.theory_atoms` and `PropagateInit.theory_atoms`):
//! each ground theory atom as plain data the Python layer turns into clingo's `TheoryAtom`,
//! `TheoryElement` and `TheoryTerm` (python/lucent/__init__.py).
//!
//! Invariant: a term crosses as its nodes in prefix order, each `(type, name, number, arity)`
//! with clingo's `TheoryTermType` numbers, so no recursive Python object is built here.

use lucent::control::theory::{condition_ids, TheoryAtom, TheoryTerm, TheoryTermType};
use lucent::control::Control;

/// One node of a term: clingo's type number, name (functions and symbols), number, arity.
pub type Node = (u8, String, i32, usize);

/// One element: its terms (each as nodes), its condition (program literals), the condition's
/// id (clingo's `condition_id`, `lucent::control::theory::condition_ids`), its text.
pub type Element = (Vec<Vec<Node>>, Vec<i32>, i32, String);

/// One atom: program literal (0 for a directive), name term, elements, guard, text.
pub type Atom = (
    u32,
    Vec<Node>,
    Vec<Element>,
    Option<(String, Vec<Node>)>,
    String,
);

/// clingo 5.8's `TheoryTermType` numbering.
fn type_number(t: TheoryTermType) -> u8 {
    match t {
        TheoryTermType::Tuple => 0,
        TheoryTermType::List => 1,
        TheoryTermType::Set => 2,
        TheoryTermType::Function => 3,
        TheoryTermType::Number => 4,
        TheoryTermType::Symbol => 5,
    }
}

fn nodes(t: &TheoryTerm, out: &mut Vec<Node>) {
    let args = t.arguments();
    out.push((
        type_number(t.term_type()),
        t.name().unwrap_or_default().to_string(),
        t.number().unwrap_or(0),
        args.len(),
    ));
    for a in args {
        nodes(a, out);
    }
}

fn term(t: &TheoryTerm) -> Vec<Node> {
    let mut out = Vec::new();
    nodes(t, &mut out);
    out
}

/// Every theory atom of `ctl` as data.
pub fn atoms(ctl: &Control) -> Vec<Atom> {
    let all = ctl.theory_atoms();
    let ids = condition_ids(all);
    all.iter()
        .zip(ids)
        .map(|(a, ids)| atom(ctl, a, &ids))
        .collect()
}

/// The atom as data (`ids`: its elements' condition ids), its text as clingo 5.8 prints it.
fn atom(ctl: &Control, a: &TheoryAtom, ids: &[i32]) -> Atom {
    let elements = a
        .elements
        .iter()
        .zip(ids)
        .map(|(e, &id)| {
            let terms: Vec<String> = e.terms.iter().map(|t| t.to_string()).collect();
            let mut text = terms.join(",");
            if !e.condition.is_empty() {
                let lits: Vec<String> = e
                    .condition
                    .iter()
                    .map(|&l| ctl.theory_literal_text(l))
                    .collect();
                text.push_str(": ");
                text.push_str(&lits.join(","));
            }
            (
                e.terms.iter().map(term).collect(),
                e.condition.clone(),
                id,
                text,
            )
        })
        .collect();
    let guard = a.guard.as_ref().map(|(op, t)| (op.clone(), term(t)));
    (
        a.atom,
        term(&a.term),
        elements,
        guard,
        ctl.theory_atom_text(a),
    )
}
