//! The readable form of a ground program, as `gringo --text` prints it: facts `a.`, rules
//! `a:-b,not c.`, choices `{a;b}:-c.`, weight bodies as `#sum` aggregates, minimize statements
//! and shown terms; optionally each rule preceded by a `% from rule at file:line:col with X=1`
//! comment giving its origin.
//!
//! Invariant: atoms print by name when they have one, and auxiliary atoms as `#aux(N)` with
//! their aspif number, so the text is stable for a given ground program.

use std::fmt::Write;

use super::program::{BodyRef, HeadKind, Lit};
use super::Grounding;
use crate::base::SourceMap;

fn atom(g: &Grounding, a: u32) -> String {
    match g.atom_names.get(a as usize - 1).and_then(|n| n.clone()) {
        Some(n) => n,
        None => format!("#aux({a})"),
    }
}

fn lit(g: &Grounding, l: Lit) -> String {
    if l > 0 {
        atom(g, l as u32)
    } else {
        format!("not {}", atom(g, (-l) as u32))
    }
}

/// Prints the ground program; with `sources`, each rule with a recorded origin gets a comment.
pub fn write_text(g: &Grounding, sources: Option<&SourceMap>) -> String {
    let p = &g.program;
    let mut out = String::new();
    for (i, r) in p.rules.iter().enumerate() {
        if let (Some(src), Some(o)) = (sources, p.origins.get(i)) {
            if let Some(&span) = g.statement_spans.get(o.rule as usize) {
                let loc = src.location(span);
                let loc = loc
                    .rsplit_once('-')
                    .map_or(loc.clone(), |(l, _)| l.to_string());
                let b = g.bindings_text(o);
                if b.is_empty() {
                    let _ = writeln!(out, "% from rule at {loc}");
                } else {
                    let _ = writeln!(out, "% from rule at {loc} with {b}");
                }
            }
        }
        let head: Vec<String> = r.head.iter().map(|&a| atom(g, a)).collect();
        match r.head_kind {
            HeadKind::Choice => {
                let _ = write!(out, "{{{}}}", head.join(";"));
            }
            HeadKind::Disjunction => out.push_str(&head.join("|")),
        }
        let body: Vec<String> = match r.body {
            BodyRef::Normal(ls) => ls.iter().map(|&l| lit(g, l)).collect(),
            BodyRef::Weight { lower, lits } => {
                let elems: Vec<String> = lits
                    .iter()
                    .enumerate()
                    .map(|(i, &(l, w))| format!("{w},{i}:{}", lit(g, l)))
                    .collect();
                vec![format!("{lower}<=#sum{{{}}}", elems.join(";"))]
            }
        };
        if !body.is_empty() {
            out.push_str(":-");
            out.push_str(&body.join(","));
        } else if r.head.is_empty() {
            out.push_str(":-");
        }
        out.push_str(".\n");
    }
    for m in &p.minimize {
        let elems: Vec<String> = m
            .lits
            .iter()
            .enumerate()
            .map(|(i, &(l, w))| format!("{w}@{},{i}:{}", m.priority, lit(g, l)))
            .collect();
        let _ = writeln!(out, "#minimize{{{}}}.", elems.join(";"));
    }
    for &(a, v) in &p.externals {
        let _ = writeln!(
            out,
            "#external {}. [{}]",
            atom(g, a),
            format!("{v:?}").to_lowercase()
        );
    }
    // The facts as a set: one look-up per output (a list search made 200,000 shown facts take
    // 40 s).
    let facts: std::collections::HashSet<&str> = g.facts.iter().map(String::as_str).collect();
    for o in &p.outputs {
        let named = o.condition.len() == 1
            && o.condition[0] > 0
            && g.atom_names
                .get(o.condition[0] as usize - 1)
                .and_then(|n| n.as_deref())
                == Some(o.symbol.as_str());
        if named || (o.condition.is_empty() && facts.contains(o.symbol.as_str())) {
            continue;
        }
        let cond: Vec<String> = o.condition.iter().map(|&l| lit(g, l)).collect();
        if cond.is_empty() {
            let _ = writeln!(out, "#show {}.", o.symbol);
        } else {
            let _ = writeln!(out, "#show {}:{}.", o.symbol, cond.join(","));
        }
    }
    out
}
