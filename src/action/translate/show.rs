//! One line of AL_d for an origin: `putdown(R, A, L) causes relation(on, A, L)`, the text an
//! answer cites. Pure functions over the AL_d syntax tree.

use super::*;

/// One line of AL_d for origins.
pub(super) fn show_lit(l: &Lit) -> String {
    let mut s = String::new();
    if l.negated {
        s.push('-');
    }
    s.push_str(&show_atom(&l.atom));
    s
}

pub(super) fn show_atom(a: &Atom) -> String {
    let mut s = a.name.text.clone();
    if !a.args.is_empty() {
        s.push('(');
        for (i, t) in a.args.iter().enumerate() {
            if i > 0 {
                s.push_str(", ");
            }
            crate::syntax::printer::term(&mut s, t);
        }
        s.push(')');
    }
    s
}

pub(super) fn show_body(b: &[BodyItem]) -> String {
    let mut parts = Vec::new();
    for item in b {
        match item {
            BodyItem::Lit(l) => parts.push(show_lit(l)),
            BodyItem::Compare { lhs, op, rhs, .. } => {
                let mut s = String::new();
                crate::syntax::printer::term(&mut s, lhs);
                s.push_str(match op {
                    CmpOp::Eq => " = ",
                    CmpOp::Ne => " != ",
                    CmpOp::Lt => " < ",
                    CmpOp::Le => " <= ",
                    CmpOp::Gt => " > ",
                    CmpOp::Ge => " >= ",
                });
                crate::syntax::printer::term(&mut s, rhs);
                parts.push(s);
            }
        }
    }
    if parts.is_empty() {
        String::new()
    } else {
        format!(" if {}", parts.join(", "))
    }
}

/// The statement in one line.
pub fn show_statement(kind: &StatementKind) -> String {
    match kind {
        StatementKind::Causal {
            action,
            effect,
            body,
        } => format!(
            "{} causes {}{}",
            show_atom(action),
            show_lit(effect),
            show_body(body)
        ),
        StatementKind::Constraint { head, body } => {
            format!("{}{}", show_lit(head), show_body(body))
        }
        StatementKind::Impossible { action, body } => {
            format!("impossible {}{}", show_atom(action), show_body(body))
        }
        StatementKind::Default { head, body } => {
            format!("normally {}{}", show_lit(head), show_body(body))
        }
        StatementKind::Exception {
            default,
            head,
            body,
        } => format!(
            "exception to {}: {} may be assumed{}",
            default.text,
            show_lit(head),
            show_body(body)
        ),
        StatementKind::Never { lit, body } => format!("never {}{}", show_lit(lit), show_body(body)),
        StatementKind::Goal { body } => format!("goal{}", show_body(body).replacen(" if", "", 1)),
        StatementKind::Observed { lit, step } => {
            let mut s = format!("observed {} at ", show_lit(lit));
            crate::syntax::printer::term(&mut s, step);
            s
        }
        StatementKind::Happened { action, step } => {
            let mut s = format!("happened {} at ", show_atom(action));
            crate::syntax::printer::term(&mut s, step);
            s
        }
        StatementKind::Initially { lit } => format!("initially {}", show_lit(lit)),
        StatementKind::InitialDefault { except } => {
            let names: Vec<&str> = except.iter().map(|n| n.text.as_str()).collect();
            if names.is_empty() {
                "initially normally false".to_string()
            } else {
                format!("initially normally false except {}", names.join(", "))
            }
        }
        StatementKind::Declaration { kind, name, params } => {
            let k = match kind {
                DeclKind::Static => "static",
                DeclKind::Inertial => "inertial fluent",
                DeclKind::Defined { .. } => "defined fluent",
                DeclKind::Action => "action",
            };
            let ps: Vec<&str> = params.iter().map(|p| p.text.as_str()).collect();
            if ps.is_empty() {
                format!("{k} {}", name.text)
            } else {
                format!("{k} {}({})", name.text, ps.join(", "))
            }
        }
        StatementKind::Sort { name, .. } => format!("sort {}", name.text),
        _ => String::new(),
    }
}
