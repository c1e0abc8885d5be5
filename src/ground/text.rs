//! The readable form of a ground program, as `gringo --text` prints it: facts `a.`, rules
//! `a:-b,not c.`, choices `{a;b}:-c.`, weight bodies as `#sum` aggregates, minimize statements
//! and shown terms; with provenance, each rule preceded by one comment per origin
//! (`% from rule at file:line:col with X=1; grounding proved q(1), not r(1)`, or
//! `% aggregate auxiliary of rule at ...`), and at the end the atoms grounding proved false
//! with the removed rule instances that could have derived them.
//!
//! Invariant: atoms print by name when they have one, and auxiliary atoms as `#aux(N)` with
//! their aspif number, so the text is stable for a given ground program.

use std::fmt::Write;

use super::program::{AtomStatus, BodyRef, DeadReason, GAtom, HeadKind, Lit, Origin, RuleOrigin};
use super::Grounding;
use crate::base::SourceMap;

/// The printed names of the aspif atoms (`[a - 1]`), rendered once per text.
type Names = [Option<String>];

fn atom(names: &Names, a: u32) -> String {
    match names.get(a as usize - 1).and_then(|n| n.clone()) {
        Some(n) => n,
        None => format!("#aux({a})"),
    }
}

fn lit(names: &Names, l: Lit) -> String {
    if l > 0 {
        atom(names, l as u32)
    } else {
        format!("not {}", atom(names, (-l) as u32))
    }
}

/// Where statement `stmt` is: `file:line:col`.
fn stmt_loc(g: &Grounding, src: &SourceMap, stmt: u32) -> String {
    match g.statement_spans.get(stmt as usize) {
        Some(&span) => {
            let loc = src.location(span);
            loc.rsplit_once('-')
                .map_or(loc.clone(), |(l, _)| l.to_string())
        }
        None => format!("statement {stmt}"),
    }
}

/// One origin as a sentence (without the `% `).
fn origin_text(g: &Grounding, src: &SourceMap, o: &Origin) -> String {
    let mut out = match &o.rule {
        RuleOrigin::Statement { stmt, .. } => format!("from rule at {}", stmt_loc(g, src, *stmt)),
        RuleOrigin::Auxiliary { of_stmt, kind, .. } => format!(
            "{} auxiliary of rule at {}",
            kind.name(),
            stmt_loc(g, src, *of_stmt)
        ),
        RuleOrigin::Complement => "an atom and its classical negation exclude each other".into(),
    };
    let b = g.bindings_text(o.rule.bindings());
    if !b.is_empty() {
        let _ = write!(out, " with {b}");
    }
    if !o.removed.is_empty() {
        let r: Vec<String> = o.removed.iter().map(|l| g.removed_text(l)).collect();
        let _ = write!(out, "; grounding proved {}", r.join(", "));
    }
    out
}

/// Why a removed rule could not derive anything, as a phrase.
fn dead_text(g: &Grounding, why: DeadReason) -> String {
    match why {
        DeadReason::Literal {
            positive: true,
            atom,
        } => format!("{} is false", g.atom_text(atom)),
        DeadReason::Literal {
            positive: false,
            atom,
        } => format!("not {} is false ({0} is a fact)", g.atom_text(atom)),
        DeadReason::HeadFact(atom) => format!("the fact {} satisfies it", g.atom_text(atom)),
        DeadReason::Contradictory => "its body holds a literal and its negation".into(),
        DeadReason::Unreachable => "its weight body cannot reach its bound".into(),
    }
}

/// The atoms that grounding proved false (named ones, not the rewriting's own predicates),
/// each with the removed rule instances that could have derived it.
fn write_false_atoms(
    g: &Grounding,
    src: &SourceMap,
    out: &mut String,
    w: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    let p = &g.program.provenance;
    for (i, r) in p.atoms.iter().enumerate() {
        if r.status != AtomStatus::False || r.sym.is_none() {
            continue;
        }
        let atom = i as GAtom + 1;
        let name = g.atom_text(atom);
        if name.starts_with('#') || name.starts_with("-#") {
            continue;
        }
        spill(out, w)?;
        let mut dead = p.dead_rules_for(atom).peekable();
        if dead.peek().is_none() {
            let _ = writeln!(out, "% false: {name}: no rule instance derives it");
            continue;
        }
        let _ = writeln!(out, "% false: {name}:");
        for d in dead {
            for o in &d.origins {
                let _ = writeln!(
                    out,
                    "%   {}; removed because {}",
                    origin_text(g, src, o),
                    dead_text(g, d.why)
                );
            }
        }
    }
    Ok(())
}

/// Writes `out` to `w` and empties it once it holds more than 64 KiB (the text of a large
/// program with provenance runs to hundreds of megabytes).
fn spill(out: &mut String, w: &mut dyn std::io::Write) -> std::io::Result<()> {
    if out.len() > 1 << 16 {
        w.write_all(out.as_bytes())?;
        out.clear();
    }
    Ok(())
}

/// Prints the ground program; with `sources` and provenance recorded, each rule is preceded
/// by its origins and the false atoms are listed at the end.
pub fn write_text(g: &Grounding, sources: Option<&SourceMap>) -> String {
    let mut out = Vec::new();
    write_text_to(g, sources, &mut out).expect("writing to memory");
    String::from_utf8(out).expect("the text is UTF-8")
}

/// [`write_text`] written to `w` as it goes.
pub fn write_text_to(
    g: &Grounding,
    sources: Option<&SourceMap>,
    w: &mut dyn std::io::Write,
) -> std::io::Result<()> {
    let p = &g.program;
    let mut names = g.atom_names();
    // Theory atoms print as themselves (their conditions name ordinary atoms).
    let mut theory_text = Vec::new();
    for t in &p.theory_atoms {
        let mut s = String::new();
        t.write(&mut s, &mut |l| lit(&names, l));
        theory_text.push(s);
    }
    for (t, s) in p.theory_atoms.iter().zip(&theory_text) {
        if t.atom != 0 {
            if let Some(n) = names.get_mut(t.atom as usize - 1) {
                *n = Some(s.clone());
            }
        }
    }
    let mut out = String::new();
    for (t, s) in p.theory_atoms.iter().zip(&theory_text) {
        if t.atom == 0 {
            let _ = writeln!(out, "{s}.");
        }
    }
    for (i, r) in p.rules.iter().enumerate() {
        spill(&mut out, w)?;
        if let Some(src) = sources {
            for o in p.provenance.origins(i) {
                let _ = writeln!(out, "% {}", origin_text(g, src, o));
            }
        }
        let head: Vec<String> = r.head.iter().map(|&a| atom(&names, a)).collect();
        match r.head_kind {
            HeadKind::Choice => {
                let _ = write!(out, "{{{}}}", head.join(";"));
            }
            HeadKind::Disjunction => out.push_str(&head.join("|")),
        }
        let body: Vec<String> = match r.body {
            BodyRef::Normal(ls) => ls.iter().map(|&l| lit(&names, l)).collect(),
            BodyRef::Weight { lower, lits } => {
                let elems: Vec<String> = lits
                    .iter()
                    .enumerate()
                    .map(|(i, &(l, w))| format!("{w},{i}:{}", lit(&names, l)))
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
            .map(|(i, &(l, w))| format!("{w}@{},{i}:{}", m.priority, lit(&names, l)))
            .collect();
        let _ = writeln!(out, "#minimize{{{}}}.", elems.join(";"));
    }
    for &a in &p.projections {
        let _ = writeln!(out, "#project {}.", atom(&names, a));
    }
    for &(a, v) in &p.externals {
        if p.theory_atoms.iter().any(|t| t.atom == a) {
            continue;
        }
        let _ = writeln!(
            out,
            "#external {}. [{}]",
            atom(&names, a),
            format!("{v:?}").to_lowercase()
        );
    }
    // The facts as a set: one look-up per output (a list search made 200,000 shown facts take
    // 40 s).
    let facts = g.facts();
    let facts: std::collections::HashSet<&str> = facts.iter().map(String::as_str).collect();
    for o in &p.outputs {
        let named = o.condition.len() == 1
            && o.condition[0] > 0
            && names
                .get(o.condition[0] as usize - 1)
                .and_then(|n| n.as_deref())
                == Some(o.symbol.as_str());
        if named || (o.condition.is_empty() && facts.contains(o.symbol.as_str())) {
            continue;
        }
        let cond: Vec<String> = o.condition.iter().map(|&l| lit(&names, l)).collect();
        if cond.is_empty() {
            let _ = writeln!(out, "#show {}.", o.symbol);
        } else {
            let _ = writeln!(out, "#show {}:{}.", o.symbol, cond.join(","));
        }
    }
    if let Some(src) = sources {
        write_false_atoms(g, src, &mut out, w)?;
    }
    w.write_all(out.as_bytes())
}
