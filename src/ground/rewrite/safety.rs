//! Safety: the order in which a body's literals are evaluable (`plan`), which binds every
//! global variable before it is used; a literal no order can evaluate makes its variables
//! unsafe.
//!
//! Invariant: `plan` keeps the relative order of the literals it can choose freely, so the
//! ground rules come out in gringo's order.

use super::*;

/// One flag per variable slot (bound, global), on the stack for rules of up to 32 variables.
pub type Flags = smallvec::SmallVec<[bool; 32]>;

/// Adds the variables of a literal (for aggregates: of guards and elements) to `out`.
pub fn lit_vars(l: &NLit, out: &mut VarList) {
    match l {
        NLit::Pred { atom, .. } => atom.args.iter().for_each(|t| t.vars(out)),
        NLit::Cmp { lhs, rhs, .. } => {
            lhs.vars(out);
            rhs.vars(out)
        }
        NLit::Interval { pat, lo, hi } => {
            pat.vars(out);
            lo.vars(out);
            hi.vars(out)
        }
        NLit::Call { pat, args, .. } => {
            pat.vars(out);
            args.iter().for_each(|t| t.vars(out))
        }
        NLit::Bool(_) => {}
        NLit::Agg(a) => {
            a.guards.iter().for_each(|(_, t)| t.vars(out));
            for e in &a.elems {
                e.terms.iter().for_each(|t| t.vars(out));
                e.cond.iter().for_each(|c| lit_vars(c, out));
                e.lit_lits().for_each(|l| lit_vars(l, out));
            }
        }
    }
}

/// How eagerly a literal should be placed next given the bound variables; `None` when it
/// cannot be evaluated yet. Lower is earlier.
pub(super) fn readiness(
    l: &mut NLit,
    bound: &[bool],
    global: &[bool],
    newly: &mut VarList,
) -> Option<u32> {
    newly.clear();
    match l {
        NLit::Bool(_) => Some(0),
        NLit::Pred { sign, atom } => {
            if *sign == Sign::Positive {
                for t in &atom.args {
                    if !t.binds(bound, newly) {
                        return None;
                    }
                }
                Some(if newly.is_empty() {
                    1
                } else {
                    10 + newly.len() as u32
                })
            } else if atom.args.iter().all(|t| t.bound_by(bound)) {
                Some(1)
            } else {
                None
            }
        }
        NLit::Cmp { op, lhs, rhs } => {
            let (lb, rb) = (lhs.bound_by(bound), rhs.bound_by(bound));
            if lb && rb {
                Some(1)
            } else if *op == CmpOp::Eq
                && ((rb && lhs.binds(bound, newly)) || (lb && rhs.binds(bound, newly)))
            {
                Some(2)
            } else {
                None
            }
        }
        NLit::Interval { pat, lo, hi } => {
            if lo.bound_by(bound) && hi.bound_by(bound) && pat.binds(bound, newly) {
                Some(3)
            } else {
                None
            }
        }
        NLit::Call { pat, args, .. } => {
            if args.iter().all(|t| t.bound_by(bound)) && pat.binds(bound, newly) {
                Some(2)
            } else {
                None
            }
        }
        NLit::Agg(a) => {
            // Every global variable of the elements must be bound first.
            for e in &a.elems {
                let mut vs = VarList::new();
                e.terms.iter().for_each(|t| t.vars(&mut vs));
                e.cond.iter().for_each(|c| lit_vars(c, &mut vs));
                e.lit_lits().for_each(|l| lit_vars(l, &mut vs));
                if vs.iter().any(|&v| global[v as usize] && !bound[v as usize]) {
                    return None;
                }
            }
            a.binder = None;
            for (i, (op, t)) in a.guards.iter().enumerate() {
                if t.bound_by(bound) {
                    continue;
                }
                if *op == CmpOp::Eq && a.sign == Sign::Positive && a.binder.is_none() {
                    // `X = #agg{...}`, and as in gringo any term matching can bind, such as
                    // the linear `X+1 = #min{...}` (a value it cannot match is skipped).
                    let mut vs = VarList::new();
                    if t.binds(bound, &mut vs) && !vs.is_empty() {
                        a.binder = Some(i);
                        newly.extend(vs);
                        continue;
                    }
                }
                return None;
            }
            Some(if a.binder.is_some() { 50 } else { 40 })
        }
    }
}

/// Orders `lits` so each is evaluable when reached, marking what they bind in `bound`; the
/// variables of literals that can never be placed are added to `unsafe_vars`, and those
/// literals dropped (the statement is then reported and discarded).
pub fn plan(
    mut lits: Vec<NLit>,
    bound: &mut [bool],
    global: &[bool],
    unsafe_vars: &mut Vec<u32>,
) -> Vec<NLit> {
    let mut out = Vec::with_capacity(lits.len());
    let mut newly = VarList::new();
    // What the best literal so far binds: `readiness` leaves in `newly` what the literal it
    // scored binds, and `bound` does not change during a round, so the chosen literal's is kept
    // instead of scoring it again (an aggregate's `binder`, set by `readiness`, is likewise the
    // one of this round's bound variables).
    let mut best_newly = VarList::new();
    while !lits.is_empty() {
        let mut best: Option<(u32, usize)> = None;
        for (i, lit) in lits.iter_mut().enumerate() {
            if let Some(score) = readiness(lit, bound, global, &mut newly) {
                if best.is_none_or(|(s, _)| score < s) {
                    best = Some((score, i));
                    std::mem::swap(&mut newly, &mut best_newly);
                }
            }
        }
        let Some((_, i)) = best else {
            for l in &lits {
                let mut vs = VarList::new();
                lit_vars(l, &mut vs);
                for v in vs {
                    if !bound[v as usize]
                        && (global[v as usize] || !matches!(l, NLit::Agg(_)))
                        && !unsafe_vars.contains(&v)
                    {
                        unsafe_vars.push(v);
                    }
                }
            }
            return out;
        };
        let mut l = lits.remove(i);
        for &v in &best_newly {
            bound[v as usize] = true;
        }
        // Plan aggregate element conditions with the global variables bound so far.
        if let NLit::Agg(a) = &mut l {
            for e in &mut a.elems {
                let mut b = Flags::from_slice(bound);
                let cond = std::mem::take(&mut e.cond);
                e.cond = plan(cond, &mut b, global, unsafe_vars);
                let mut vs = VarList::new();
                e.terms.iter().for_each(|t| t.vars(&mut vs));
                // Each alternative of a conditional literal may bind its own local variables.
                for alt in e.lit.iter_mut().flatten() {
                    let mut ba = b.clone();
                    *alt = plan(std::mem::take(alt), &mut ba, global, unsafe_vars);
                    let mut av = VarList::new();
                    alt.iter().for_each(|l| lit_vars(l, &mut av));
                    vs.extend(av.into_iter().filter(|&v| !ba[v as usize]));
                }
                for v in vs {
                    if !b[v as usize] && !unsafe_vars.contains(&v) {
                        unsafe_vars.push(v);
                    }
                }
            }
        }
        out.push(l);
    }
    out
}
