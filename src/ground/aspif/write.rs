//! The aspif writer: statements of a [`GroundProgram`] (or a step's layout) as aspif text,
//! one per line, with Lucent's comment statements for CR rules and preferences.
//!
//! Invariant: every line written is one complete statement ending in `\n`; everything written is
//! ASCII except output symbols, comments and labels, which are UTF-8 `String`s.

use std::io::Write as _;

use super::{AspifStep, Stmt, CR_MINIMIZE_TAG, CR_TAG, PREFER_TAG};
use crate::ground::program::{
    BodyRef, ExternalValue, GroundProgram, HeadKind, HeuristicModifier, Lit, Weight,
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
