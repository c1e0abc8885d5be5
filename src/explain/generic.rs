//! Why and why not for any program (the use case xclingo serves): the proof tree of an atom in
//! an answer set, over any [`Oracle`] (in practice `oracle::ProgramOracle` over a clingo
//! program grounded with provenance), written out as text: for a true atom the least proof of
//! `explain::support` (built bottom-up from the answer set, linear in the ground program; the
//! search of `explain::build` when an atom of it rests on a weight body), each step with the
//! rule instance and its source location; default-negated literals as "no evidence of"; for an
//! atom that does not hold, every rule for it with the body literal that blocks it.
//!
//! Invariants: the tree is re-checked (`tree::recheck`) before it is written; the answer's
//! literals are the leaves of the preferred proof (for a false atom, the blocking literals);
//! nothing here panics on any atom, known to the program or not.

use super::build::{BuildConfig, Builder};
use super::oracle::ProgramOracle;
use super::questions::{Answer, AnswerError};
use super::support::Supports;
use super::tree::{recheck, Kind, NodeId, Oracle, ProofTree};
use crate::control::Symbol;

/// Explains why `atom` holds (or, if it does not, why not) in the oracle's answer set.
pub fn why(oracle: &ProgramOracle, atom: &Symbol) -> Result<Answer, AnswerError> {
    let holds = oracle.holds(atom);
    // A true atom's least proof from the bottom-up supports; the search is the fallback.
    let tree = holds
        .then(|| Supports::new(oracle).tree(oracle, atom))
        .flatten()
        .unwrap_or_else(|| Builder::new(oracle, BuildConfig::default()).build(atom));
    recheck(&tree, oracle)?;
    let mut text = String::new();
    let mut literals = Vec::new();
    if holds {
        match tree.roots.first() {
            Some(&root) => {
                text.push_str(&format!("{atom} holds.\n"));
                let mut seen = Vec::new();
                proof(&tree, root, 1, &mut text, &mut literals, &mut seen);
            }
            None => text.push_str(&format!(
                "{atom} holds, but no support was found within the limits (depth {}, {} branches).\n",
                super::tree::MAX_DEPTH,
                super::tree::MAX_BRANCHES
            )),
        }
        return Ok(Answer {
            kind: "why",
            text: text.trim_end().to_string(),
            literals,
            tree: Some(tree),
        });
    }
    why_not_text(oracle, atom, tree)
}

/// Explains why `atom` does not hold (or, if it does, says so and explains why it does).
pub fn why_not(oracle: &ProgramOracle, atom: &Symbol) -> Result<Answer, AnswerError> {
    if oracle.holds(atom) {
        let mut a = why(oracle, atom)?;
        a.kind = "why_not";
        a.text = format!("{atom} is in the answer set. {}", a.text);
        return Ok(a);
    }
    let tree = Builder::new(oracle, BuildConfig::default()).build(atom);
    recheck(&tree, oracle)?;
    why_not_text(oracle, atom, tree)
}

fn why_not_text(
    oracle: &dyn Oracle,
    atom: &Symbol,
    tree: ProofTree,
) -> Result<Answer, AnswerError> {
    let mut text = format!("{atom} does not hold.");
    let mut literals = Vec::new();
    let rules = oracle.rules_for(atom);
    match tree.roots.first() {
        _ if rules.is_empty() => text.push_str(" No rule has it in its head."),
        Some(&root) => {
            let n = tree.node(root);
            text.push_str(" Every rule for it is blocked:");
            for (rule, c) in n.blocked.iter().zip(&n.children) {
                let child = tree.node(*c);
                let why = if child.holds {
                    format!("not {} fails, as {} holds", child.literal, child.literal)
                } else {
                    format!("{} does not hold", child.literal)
                };
                text.push_str(&format!("\n  {} `{rule}`: {why}", rule.label));
                if !literals.contains(&child.literal) {
                    literals.push(child.literal.clone());
                }
            }
        }
        None => text.push_str(" Its rules could not all be shown blocked within the limits."),
    }
    Ok(Answer {
        kind: "why_not",
        text,
        literals,
        tree: Some(tree),
    })
}

/// Writes the preferred proof below `id`: its support, then the first support of each positive
/// body literal.
fn proof(
    tree: &ProofTree,
    id: NodeId,
    depth: usize,
    out: &mut String,
    leaves: &mut Vec<Symbol>,
    seen: &mut Vec<Symbol>,
) {
    let n = tree.node(id);
    let pad = "  ".repeat(depth);
    let rule = n
        .rule
        .as_ref()
        .map(|r| format!(" `{r}`"))
        .unwrap_or_default();
    let how = match &n.kind {
        Kind::Axiom { label, .. } => format!("by {label}"),
        k => k.words(),
    };
    out.push_str(&format!("{pad}{}: {how}{rule}\n", n.literal));
    for t in &n.no_evidence {
        out.push_str(&format!("{pad}  no evidence of {t}\n"));
    }
    if n.children.is_empty() {
        if !leaves.contains(&n.literal) {
            leaves.push(n.literal.clone());
        }
        return;
    }
    tree.each_unseen_child(id, seen, |c, seen| {
        proof(tree, c, depth + 1, out, leaves, seen)
    });
}
