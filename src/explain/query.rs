//! Queries as users ask them: `--why 'reach(1,X)'` explains each true atom of the answer set
//! that the (possibly non-ground) atom matches, `--why-not 'reach(1,X)'` each false atom of the
//! ground program (including those grounding proved false) that it matches, one `generic`
//! answer per atom, in clingo's symbol order.
//!
//! Invariants: a ground query is exactly `generic::why`/`why_not`; every answer given is
//! re-checked (by `generic`); at most [`MAX_MATCHES`] atoms are explained, and the answer says
//! how many more matched; the combined answer's tree is the first match's.

use super::generic;
use super::oracle::ProgramOracle;
use super::pattern::Pattern;
use super::questions::{Answer, AnswerError};
use super::tree::Oracle;
use crate::control::Symbol;

/// The most atoms one query explains.
pub const MAX_MATCHES: usize = 100;

/// Reads a query: an atom in program syntax, variables allowed (`reach(1,X)`, `-p(_)`).
pub fn parse(text: &str) -> Result<Pattern, String> {
    let bad = || format!("'{text}': expected an atom such as p(1,a) or p(1,X)");
    let p = Pattern::parse(text).map_err(|_| bad())?;
    match p.name() {
        Some(n) if n.starts_with(|c: char| c.is_ascii_lowercase() || c == '_') => Ok(p),
        _ => Err(bad()),
    }
}

/// The atoms the query matches: true ones when `holding`, else false ones known to the ground
/// program; sorted, without duplicates.
pub fn matches(oracle: &ProgramOracle, query: &Pattern, holding: bool) -> Vec<Symbol> {
    let mut out: Vec<Symbol> = if holding {
        oracle.true_literals()
    } else {
        oracle
            .atom_term
            .iter()
            .chain(oracle.g_term.iter())
            .flatten()
            .filter(|s| !oracle.holds(s))
            .cloned()
            .collect()
    };
    out.retain(|s| s.name() != Some("#aux") && query.matches(s, &mut Default::default()));
    out.sort();
    out.dedup();
    out
}

/// Why (or, with `negative`, why not) each atom the query matches; with `full`, each with
/// every reason (`generic::add_full`).
pub fn explain(
    oracle: &ProgramOracle,
    query: &Pattern,
    negative: bool,
    full: bool,
) -> Result<Answer, AnswerError> {
    let one = |atom: &Symbol| {
        let mut a = if negative {
            generic::why_not(oracle, atom)
        } else {
            generic::why(oracle, atom)
        }?;
        if full {
            generic::add_full(oracle, atom, &mut a);
        }
        Ok(a)
    };
    if let Some(atom) = query.to_symbol() {
        return one(&atom);
    }
    let kind = if negative { "why_not" } else { "why" };
    let found = matches(oracle, query, !negative);
    if found.is_empty() {
        let text = if negative {
            format!("Every atom of the program that matches {query} holds (or none exists).")
        } else {
            format!("No atom of the answer set matches {query}.")
        };
        return Ok(Answer {
            kind,
            text,
            literals: Vec::new(),
            tree: None,
        });
    }
    let mut text = format!(
        "{} atom{} match{} {query}{}.",
        found.len(),
        if found.len() == 1 { "" } else { "s" },
        if found.len() == 1 { "es" } else { "" },
        if negative {
            " and do not hold"
        } else {
            " and hold"
        },
    );
    let mut literals = Vec::new();
    let mut tree = None;
    for atom in found.iter().take(MAX_MATCHES) {
        let a = one(atom)?;
        text.push_str("\n\n");
        text.push_str(&a.text);
        for l in a.literals {
            if !literals.contains(&l) {
                literals.push(l);
            }
        }
        if tree.is_none() {
            tree = a.tree;
        }
    }
    if found.len() > MAX_MATCHES {
        text.push_str(&format!(
            "\n\n({} more atoms match; they are not explained.)",
            found.len() - MAX_MATCHES
        ));
    }
    Ok(Answer {
        kind,
        text,
        literals,
        tree,
    })
}
