//! The aspif writer: statements of a [`GroundProgram`] (or a step's layout) as aspif text,
//! one per line, with Lucent's comment statements for CR rules and preferences.
//!
//! Invariant: every line written is one complete statement ending in `\n`; everything written is
//! ASCII except output symbols, comments and labels, which are UTF-8 `String`s.

use std::io::Write as _;

use super::{AspifStep, Stmt, CR_MINIMIZE_TAG, CR_TAG, PREFER_TAG};
use crate::ground::program::{
    BodyRef, ExternalValue, GroundProgram, HeadKind, HeuristicModifier, Lit, TheoryAtom,
    TheoryTerm, Weight,
};

pub(super) fn write_step(out: &mut Vec<u8>, step: &AspifStep) {
    write_statements(out, &step.program, &step.comments, &step.layout);
}

/// Writes the statements of `layout` over `p` and `comments`, then the step's closing `0`.
fn write_statements(out: &mut Vec<u8>, p: &GroundProgram, comments: &[String], layout: &[Stmt]) {
    for &stmt in layout {
        write_statement(out, p, comments, stmt);
    }
    out.extend_from_slice(b"0\n");
}

/// Writes one statement and its newline.
pub(super) fn write_statement(
    out: &mut Vec<u8>,
    p: &GroundProgram,
    comments: &[String],
    stmt: Stmt,
) {
    match stmt {
        Stmt::Rule(i) => {
            let rule = p.rules.get(i as usize);
            out.extend_from_slice(match rule.head_kind {
                HeadKind::Disjunction => b"1 0",
                HeadKind::Choice => b"1 1",
            });
            write_lits(out, rule.head);
            match rule.body {
                BodyRef::Normal(lits) => {
                    out.extend_from_slice(b" 0");
                    write_lits(out, lits);
                }
                BodyRef::Weight { lower, lits } => {
                    out.extend_from_slice(b" 1");
                    push_int(out, lower);
                    write_wlits(out, lits);
                }
            }
        }
        Stmt::Minimize(i) => {
            let m = &p.minimize[i as usize];
            out.push(b'2');
            push_int(out, m.priority);
            write_wlits(out, &m.lits);
        }
        Stmt::Project { start, len } => {
            out.push(b'3');
            write_lits(out, &p.projections[start as usize..(start + len) as usize]);
        }
        Stmt::Output(i) => {
            let o = &p.outputs[i as usize];
            let _ = write!(out, "4 {} {}", o.symbol.len(), o.symbol);
            write_lits(out, &o.condition);
        }
        Stmt::External(i) => {
            let (atom, value) = p.externals[i as usize];
            let v = match value {
                ExternalValue::Free => 0,
                ExternalValue::True => 1,
                ExternalValue::False => 2,
                ExternalValue::Release => 3,
            };
            let _ = write!(out, "5 {atom} {v}");
        }
        Stmt::Assume { start, len } => {
            out.push(b'6');
            write_lits(out, &p.assumptions[start as usize..(start + len) as usize]);
        }
        Stmt::Heuristic(i) => {
            let h = &p.heuristics[i as usize];
            let m = match h.modifier {
                HeuristicModifier::Level => 0,
                HeuristicModifier::Sign => 1,
                HeuristicModifier::Factor => 2,
                HeuristicModifier::Init => 3,
                HeuristicModifier::True => 4,
                HeuristicModifier::False => 5,
            };
            let _ = write!(out, "7 {m} {} {} {}", h.atom, h.bias, h.priority);
            write_lits(out, &h.condition);
        }
        Stmt::Edge(i) => {
            let e = &p.edges[i as usize];
            let _ = write!(out, "8 {} {}", e.from, e.to);
            write_lits(out, &e.condition);
        }
        Stmt::Theory(i) => {
            let line = &p.theory[i as usize];
            assert!(
                !line.contains('\n'),
                "a theory line must not contain a newline"
            );
            out.extend_from_slice(line.as_bytes());
        }
        Stmt::Comment(i) => {
            let text = &comments[i as usize];
            assert!(
                !text.contains('\n'),
                "an aspif comment must not contain a newline"
            );
            if text.is_empty() {
                out.extend_from_slice(b"10");
            } else {
                let _ = write!(out, "10 {text}");
            }
        }
        Stmt::CrRule(i) => {
            let cr = &p.cr_rules[i as usize];
            assert!(
                !cr.label.contains('\n'),
                "a CR label must not contain a newline"
            );
            let _ = write!(out, "10 {CR_TAG} {} {}", cr.appl, cr.label);
        }
        Stmt::Prefer(i) => {
            let pr = &p.prefers[i as usize];
            let _ = write!(out, "10 {PREFER_TAG} {} {}", pr.better, pr.worse);
        }
        Stmt::CrMinimize(priority) => {
            let _ = write!(
                out,
                "10 {CR_MINIMIZE_TAG} {priority}\n2 {priority} {}",
                p.cr_rules.len()
            );
            for cr in &p.cr_rules {
                let _ = write!(out, " {} 1", cr.appl);
            }
        }
    }
    out.push(b'\n');
}

/// Writes ` n x1 .. xn`.
fn write_lits<T: Copy + Into<i64>>(out: &mut Vec<u8>, lits: &[T]) {
    push_int(out, lits.len() as i64);
    for &l in lits {
        push_int(out, l.into());
    }
}

/// Writes ` n l1 w1 .. ln wn`.
fn write_wlits(out: &mut Vec<u8>, lits: &[(Lit, Weight)]) {
    push_int(out, lits.len() as i64);
    for &(l, w) in lits {
        push_int(out, l.into());
        push_int(out, w);
    }
}

/// Writes a space and then `v` in decimal (the writer's hot path; `write!` is several times
/// slower).
fn push_int(out: &mut Vec<u8>, v: i64) {
    let mut buf = [0u8; 21];
    let mut i = buf.len();
    let mut n = v.unsigned_abs();
    loop {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    if v < 0 {
        i -= 1;
        buf[i] = b'-';
    }
    out.push(b' ');
    out.extend_from_slice(&buf[i..]);
}

/// Theory atoms as aspif theory statements (`9 0` numbers, `9 1` symbols, `9 2` compound
/// terms, `9 4` elements, `9 5`/`9 6` atoms without/with guard), each term and element once,
/// defined before its first use, as gringo writes them.
pub(super) fn write_theory_atoms(out: &mut Vec<u8>, atoms: &[TheoryAtom]) {
    let mut terms: hashbrown::HashMap<TheoryTerm, u32> = hashbrown::HashMap::new();
    let mut names: hashbrown::HashMap<String, u32> = hashbrown::HashMap::new();
    let mut elems: hashbrown::HashMap<(Vec<u32>, Vec<Lit>), u32> = hashbrown::HashMap::new();
    let mut next_term = 0u32;
    for a in atoms {
        let name = theory_term(out, &a.term, &mut terms, &mut names, &mut next_term);
        let mut ids = Vec::with_capacity(a.elements.len());
        for e in &a.elements {
            let ts: Vec<u32> = e
                .terms
                .iter()
                .map(|t| theory_term(out, t, &mut terms, &mut names, &mut next_term))
                .collect();
            let key = (ts, e.condition.clone());
            let n = elems.len() as u32;
            let id = *elems.entry(key.clone()).or_insert_with(|| {
                let _ = write!(out, "9 4 {n} {}", key.0.len());
                key.0.iter().for_each(|t| push_int(out, i64::from(*t)));
                write_lits(out, &key.1);
                out.push(b'\n');
                n
            });
            ids.push(id);
        }
        let guard = a.guard.as_ref().map(|(op, t)| {
            let op = symbol_name(out, op, &mut names, &mut next_term);
            (
                op,
                theory_term(out, t, &mut terms, &mut names, &mut next_term),
            )
        });
        let _ = write!(
            out,
            "9 {} {} {name} {}",
            if guard.is_some() { 6 } else { 5 },
            a.atom,
            ids.len()
        );
        ids.iter().for_each(|v| push_int(out, i64::from(*v)));
        if let Some((op, t)) = guard {
            let _ = write!(out, " {op} {t}");
        }
        out.push(b'\n');
    }
}

/// The id of the symbolic term `name` (a `9 1` statement the first time).
fn symbol_name(
    out: &mut Vec<u8>,
    name: &str,
    names: &mut hashbrown::HashMap<String, u32>,
    next: &mut u32,
) -> u32 {
    if let Some(&id) = names.get(name) {
        return id;
    }
    let id = *next;
    *next += 1;
    let _ = writeln!(out, "9 1 {id} {} {name}", name.len());
    names.insert(name.to_string(), id);
    id
}

/// The id of theory term `t`, its statements (and its parts') written the first time.
fn theory_term(
    out: &mut Vec<u8>,
    t: &TheoryTerm,
    terms: &mut hashbrown::HashMap<TheoryTerm, u32>,
    names: &mut hashbrown::HashMap<String, u32>,
    next: &mut u32,
) -> u32 {
    if let Some(&id) = terms.get(t) {
        return id;
    }
    let id = match t {
        TheoryTerm::Number(n) => {
            let id = *next;
            *next += 1;
            let _ = writeln!(out, "9 0 {id} {n}");
            id
        }
        TheoryTerm::Symbol(s) => symbol_name(out, s, names, next),
        TheoryTerm::Function(_, args)
        | TheoryTerm::Tuple(args)
        | TheoryTerm::Set(args)
        | TheoryTerm::List(args) => {
            let head: i64 = match t {
                TheoryTerm::Function(name, _) => i64::from(symbol_name(out, name, names, next)),
                TheoryTerm::Tuple(_) => -1,
                TheoryTerm::Set(_) => -2,
                _ => -3,
            };
            let ids: Vec<u32> = args
                .iter()
                .map(|a| theory_term(out, a, terms, names, next))
                .collect();
            let id = *next;
            *next += 1;
            let _ = write!(out, "9 2 {id} {head} {}", ids.len());
            ids.iter().for_each(|v| push_int(out, i64::from(*v)));
            out.push(b'\n');
            id
        }
    };
    terms.insert(t.clone(), id);
    id
}
