//! Answers and proof trees as `--outf=2` JSON: an answer's type, English, literals, and the
//! proof tree it used with the learned axioms its path cites.
//!
//! Invariants: nodes are written in index order (children before parents) and referred to by
//! index; the JSON says what the answer's English says (the same literals, the same cited
//! learned axioms).

use super::Answer;
use crate::control::Symbol;
use crate::explain::tree::{LearnedAxiom, NodeId, ProofTree};

impl Answer {
    /// The answer as `--outf=2` JSON: `type`, `answer` (the English), `literals` (program
    /// syntax) and, when the answer used one, `tree` (nodes children first, roots, path).
    pub fn to_json(&self) -> serde_json::Value {
        let mut obj = serde_json::json!({
            "type": self.kind,
            "answer": self.text,
            "literals": self.literals.iter().map(Symbol::to_string).collect::<Vec<_>>(),
        });
        if let Some(tree) = &self.tree {
            obj["tree"] = tree_json(tree);
            if !tree.source_notes.is_empty() {
                obj["source"] = serde_json::Value::Array(tree.source_notes.clone());
            }
            // The learned axioms the answer's path cites (as its English says).
            let cited: Vec<serde_json::Value> = tree
                .learned
                .iter()
                .filter(|l| {
                    tree.path
                        .iter()
                        .any(|&id| tree.learned_of(id).is_some_and(|x| x.label == l.label))
                })
                .map(learned_json)
                .collect();
            if !cited.is_empty() {
                obj["learned"] = serde_json::Value::Array(cited);
            }
        }
        obj
    }
}

/// A learned axiom as JSON: `label`, `strength`, `axiom` (AL_d).
fn learned_json(l: &LearnedAxiom) -> serde_json::Value {
    serde_json::json!({"label": l.label, "strength": l.strength, "axiom": l.text})
}

/// A proof tree as JSON: `nodes` (index order, children before parents) with `literal`,
/// `step`, `holds`, `kind`, `rule` (the ground rule instance, as text), `children`, `blocked`
/// and `no_evidence`, and `learned` (label, strength, axiom) when the rule instance comes from
/// a learned axiom; `roots`; `path`.
pub fn tree_json(tree: &ProofTree) -> serde_json::Value {
    let nodes: Vec<serde_json::Value> = tree
        .nodes
        .iter()
        .enumerate()
        .map(|(i, n)| {
            let mut node = serde_json::json!({
                "literal": n.literal.to_string(),
                "step": n.step,
                "holds": n.holds,
                "kind": n.kind.words(),
                "rule": n.rule.as_ref().map(|r| r.to_string()),
                "children": n.children.iter().map(|c| c.0).collect::<Vec<_>>(),
                "blocked": n.blocked.iter().map(|r| r.to_string()).collect::<Vec<_>>(),
                "no_evidence": n.no_evidence.iter().map(Symbol::to_string).collect::<Vec<_>>(),
            });
            if let Some(l) = tree.learned_of(NodeId(i as u32)) {
                node["learned"] = learned_json(l);
            }
            node
        })
        .collect();
    serde_json::json!({
        "nodes": nodes,
        "roots": tree.roots.iter().map(|r| r.0).collect::<Vec<_>>(),
        "path": tree.path.iter().map(|r| r.0).collect::<Vec<_>>(),
    })
}
