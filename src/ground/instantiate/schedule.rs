//! Scheduling: facts first, then the strongly connected components of the statement
//! dependency graph in gringo's order (`Graph::tarjan`, the positive split), each to its
//! fixpoint by semi-naive rounds (or naive rounds for recursive aggregates); then gringo's
//! warnings for atoms no rule heads and for `#show p/n.` signatures no statement mentions.
//!
//! Invariant: a predicate is complete once every statement heading it is grounded, and its
//! readers come after it (or in the same component).

use super::*;

/// Lists of numbers stored one after another (compressed rows): row `i` is
/// `items[start[i]..start[i + 1]]`. The schedule's per-statement tables (heads, reads,
/// providers, dependency edges, components) are built this way, with no allocation per row.
pub(super) struct Rows {
    start: Vec<u32>,
    items: Vec<u32>,
}

impl Rows {
    /// No rows, room for `rows` rows of `items` items in all.
    pub(super) fn with_capacity(rows: usize, items: usize) -> Rows {
        let mut start = Vec::with_capacity(rows + 1);
        start.push(0);
        Rows {
            start,
            items: Vec::with_capacity(items),
        }
    }

    /// Ends the row being built: its items are those pushed since the previous row ended.
    pub(super) fn end_row(&mut self) {
        self.start.push(self.items.len() as u32);
    }

    /// The number of rows.
    pub(super) fn len(&self) -> usize {
        self.start.len() - 1
    }

    /// Row `i`.
    pub(super) fn row(&self, i: usize) -> &[u32] {
        &self.items[self.start[i] as usize..self.start[i + 1] as usize]
    }

    /// The positions of row `i` in `items`.
    fn span(&self, i: usize) -> std::ops::Range<usize> {
        self.start[i] as usize..self.start[i + 1] as usize
    }

    /// The items of the row being built.
    fn open_row(&self) -> &[u32] {
        &self.items[*self.start.last().expect("a start") as usize..]
    }
}

impl Grounder<'_> {
    /// Grounds the whole compiled program.
    pub fn run(&mut self, prog: &Compiled) {
        let n = prog.preds.len();
        let ns = prog.stmts.len();
        // Head predicates of each statement, and the predicates each statement reads.
        let mut heads = Rows::with_capacity(ns, ns);
        let mut reads = Rows::with_capacity(ns, 3 * ns);
        // What each statement reads other than under default negation.
        let mut pos_reads = Rows::with_capacity(ns, 3 * ns);
        // The atom of each read (aligned with `reads.items` and `pos_reads.items`): the
        // dependency edges below go only to statements whose head atoms unify with it.
        let mut read_atoms: Vec<&NAtom> = Vec::with_capacity(3 * ns);
        let mut pos_read_atoms: Vec<&NAtom> = Vec::with_capacity(3 * ns);
        let negative = |l: &NLit| matches!(l, NLit::Pred { sign, .. } if *sign != Sign::Positive);
        let mut by_source: Vec<&NLit> = Vec::new();
        for s in &prog.stmts {
            stmt_heads(s, &mut heads);
            heads.end_row();
            // In gringo's order of the body (positive literals last to first, then the negative
            // ones), which decides the order of its depth-first search.
            // (The planned body is in evaluation order; the source order is that of the spans.)
            by_source.clear();
            by_source.extend(s.body.iter());
            by_source.sort_by_key(|l| source_pos(l));
            for l in by_source.iter().rev().filter(|l| !negative(l)) {
                lit_occs(l, &mut pos_reads.items, &mut pos_read_atoms);
            }
            let pos_start = *pos_reads.start.last().expect("a start") as usize;
            reads.items.extend_from_slice(&pos_reads.items[pos_start..]);
            read_atoms.extend_from_slice(&pos_read_atoms[pos_start..]);
            for l in by_source.iter().filter(|l| negative(l)) {
                lit_occs(l, &mut reads.items, &mut read_atoms);
            }
            if let NHead::Disj(es) | NHead::Choice(es) = &s.head {
                for e in es {
                    for l in &e.cond {
                        lit_occs(l, &mut reads.items, &mut read_atoms);
                        lit_occs(l, &mut pos_reads.items, &mut pos_read_atoms);
                    }
                    for l in e.conj.iter().filter(|l| l.sign != Sign::Positive) {
                        reads.items.push(l.atom.pred);
                        read_atoms.push(&l.atom);
                    }
                }
            }
            reads.end_row();
            pos_reads.end_row();
        }
        self.warn_undefined(prog, &heads);
        self.warn_unshown(prog, &reads);
        // SPARC sorts: facts of their hidden predicates.
        for &(pred, v) in &prog.sort_facts {
            let name = prog.preds[pred as usize].name;
            let sym = self.syms.fun(name, false, &[v]);
            let a = self.atom_of(sym, pred);
            self.derive(a);
            self.atoms[a.index()].fact = true;
            if a.index() < self.old_atoms {
                self.touched.push(a);
            }
        }
        // Statement dependency graph, as gringo's (Dependency::analyze): a statement depends on
        // every statement heading an atom that unifies with one it reads (the edges are made
        // below). Ground facts are no nodes (gringo keeps
        // them apart and outputs them first); they are grounded before everything.
        let mut nodes: Vec<u32> = Vec::new();
        let mut node_of = vec![u32::MAX; ns];
        // The statements heading each predicate, in order (counted, then placed).
        let mut providers = Rows {
            start: vec![0; n + 1],
            items: vec![0; heads.items.len()],
        };
        for &p in &heads.items {
            providers.start[p as usize + 1] += 1;
        }
        for i in 1..=n {
            providers.start[i] += providers.start[i - 1];
        }
        // Statements still to ground per predicate: a predicate is complete once all are done.
        let mut pending: Vec<u32> = (0..n)
            .map(|p| providers.start[p + 1] - providers.start[p])
            .collect();
        let mut fill: Vec<u32> = providers.start[..n].to_vec();
        for (si, s) in prog.stmts.iter().enumerate() {
            if !is_ground_fact(s) {
                node_of[si] = nodes.len() as u32;
                nodes.push(si as u32);
            }
            for &p in heads.row(si) {
                providers.items[fill[p as usize] as usize] = si as u32;
                fill[p as usize] += 1;
            }
        }
        drop(fill);
        for (d, &left) in self.domains.iter_mut().zip(&pending) {
            // (Multi-shot: a predicate of an earlier grounding that this one's statements head
            // is open again until they are grounded.)
            d.complete = left == 0;
        }
        let finished = |g: &mut Self, si: usize, pending: &mut Vec<u32>| {
            for &p in heads.row(si) {
                pending[p as usize] -= 1;
                if pending[p as usize] == 0 {
                    g.domains[p as usize].complete = true;
                }
            }
        };
        // Facts over values first, then those over other ground terms (`p(-1).`), as gringo
        // makes their atoms (and so lists them in a model).
        let passes: &[bool] = if prog.late_facts.is_empty() {
            &[false]
        } else {
            &[false, true]
        };
        for &late in passes {
            for (si, s) in prog.stmts.iter().enumerate() {
                if node_of[si] == u32::MAX && prog.late_facts.binary_search(&s.stmt).is_ok() == late
                {
                    if self.stopped.is_some() {
                        return;
                    }
                    self.ground_stmt(s, &[]);
                    finished(self, si, &mut pending);
                }
            }
        }
        // A statement depends on a statement heading an atom that unifies with one it reads
        // (gringo's `Dependency::analyze`): `p(a)` does not wait for the rules of `p(b, ..)`.
        let syms = &self.syms;
        let edges_of = |reads: &Rows, atoms: &[&NAtom]| -> Rows {
            let mut e = Rows::with_capacity(nodes.len(), reads.items.len());
            for &si in &nodes {
                let span = reads.span(si as usize);
                for (&p, &atom) in reads.items[span.clone()].iter().zip(&atoms[span]) {
                    for &t in providers.row(p as usize) {
                        let tn = node_of[t as usize];
                        if tn != u32::MAX && heads_unify(syms, &prog.stmts[t as usize], atom) {
                            e.items.push(tn);
                        }
                    }
                }
                e.end_row();
            }
            e
        };
        let edges = edges_of(&reads, &read_atoms);
        let pos_edges = edges_of(&pos_reads, &pos_read_atoms);
        drop((read_atoms, pos_read_atoms));
        drop((reads, pos_reads));
        let comps = positive_split(gringo_tarjan(&edges), &pos_edges);
        let mut comp_mark = vec![usize::MAX; n];
        let mut stmts: Vec<&NStmt> = Vec::new();
        let mut preds: Vec<PredId> = Vec::new();
        for ci in 0..comps.len() {
            if self.stopped.is_some() {
                break;
            }
            let comp = comps.row(ci);
            stmts.clear();
            stmts.extend(
                comp.iter()
                    .map(|&v| &prog.stmts[nodes[v as usize] as usize]),
            );
            preds.clear();
            for &v in comp {
                for &p in heads.row(nodes[v as usize] as usize) {
                    if comp_mark[p as usize] != ci {
                        comp_mark[p as usize] = ci;
                        preds.push(p);
                    }
                }
            }
            let in_comp = |p: PredId| comp_mark[p as usize] == ci;
            let naive = stmts
                .iter()
                .any(|s| s.body.iter().any(|l| nested_reads(l, &in_comp)))
                || stmts.iter().any(|s| match &s.head {
                    NHead::Disj(es) | NHead::Choice(es) => es.iter().any(|e| {
                        let mut r = Vec::new();
                        e.cond.iter().for_each(|l| lit_preds(l, &mut r));
                        r.into_iter().any(in_comp)
                    }),
                    NHead::None => false,
                });
            let recursive = stmts.iter().any(|s| {
                s.body
                    .iter()
                    .any(|l| matches!(l, NLit::Pred { sign: Sign::Positive, atom } if in_comp(atom.pred)))
            });
            if naive {
                self.naive = true;
                self.ground_naive(&stmts, &preds);
                self.naive = false;
            } else if recursive {
                self.ground_seminaive(&stmts, &preds, &in_comp);
            } else {
                for s in &stmts {
                    self.ground_stmt(s, &[]);
                }
            }
            for &v in comp {
                finished(self, nodes[v as usize] as usize, &mut pending);
            }
        }
    }

    /// Grounds a component with recursive aggregates: first its domain, by rounds in which
    /// such aggregates are assumed true (each round's rules are discarded), until no atom is
    /// added; then one final round with the aggregates evaluated over the complete domain.
    pub(super) fn ground_naive(&mut self, stmts: &[&NStmt], comp: &[PredId]) {
        self.optimistic = true;
        loop {
            let rules_start = self.rules.len();
            let cr_start = self.directives.cr_rules.len();
            let size_before: usize = comp
                .iter()
                .map(|&p| self.domains[p as usize].atoms.len())
                .sum();
            for s in stmts {
                self.ground_stmt(s, &[]);
            }
            let size_after: usize = comp
                .iter()
                .map(|&p| self.domains[p as usize].atoms.len())
                .sum();
            self.forget_rules_from(rules_start);
            for (a, _) in self.directives.cr_rules.drain(cr_start..) {
                self.cr_appl.retain(|_, v| *v != a);
            }
            if self.stopped.is_some() || size_after == size_before {
                break;
            }
        }
        self.optimistic = false;
        for s in stmts {
            self.ground_stmt(s, &[]);
        }
    }

    pub(super) fn forget_rules_from(&mut self, start: usize) {
        while self.rule_hashes.len() > start {
            let hash = self.rule_hashes.pop().expect("len > start");
            let idx = self.rule_hashes.len() as u32;
            if let Ok(e) = self.rule_set.find_entry(hash, |&i| i == idx) {
                e.remove();
            }
            if self.provenance {
                self.prov.origins.pop();
            }
        }
        if self.provenance {
            self.prov.more_origins.retain(|&i, _| (i as usize) < start);
        }
        self.rules.truncate(start);
        // Their defining rules may be gone; fresh auxiliaries are made next round.
        self.notnot.clear();
    }

    pub(super) fn ground_seminaive(
        &mut self,
        stmts: &[&NStmt],
        comp: &[PredId],
        in_comp: &dyn Fn(PredId) -> bool,
    ) {
        // Round 0: everything over what is known.
        for &p in comp {
            let d = &mut self.domains[p as usize];
            d.old = 0;
            d.delta = d.atoms.len() as u32;
        }
        for s in stmts {
            let ranges: Vec<Option<Range>> = s
                .body
                .iter()
                .map(|l| match l {
                    NLit::Pred {
                        sign: Sign::Positive,
                        atom,
                    } if in_comp(atom.pred) => Some((0, self.domains[atom.pred as usize].delta)),
                    _ => None,
                })
                .collect();
            // The first recursive literal reads every atom as new (gringo's first round).
            self.new_lit = ranges
                .iter()
                .position(Option::is_some)
                .map_or(0, |i| &s.body[i] as *const NLit as usize);
            self.ground_stmt(s, &ranges);
        }
        self.new_lit = 0;
        // Later rounds follow gringo's queue of instantiators (Queue::process): an instantiator
        // is a statement with one recursive literal over the last round's new atoms (earlier
        // recursive literals over older atoms, later ones over all). After a round, the
        // statements of that round, in order, enqueue the instantiators reading what they head
        // whose literal has new atoms, in the order the instantiators were registered. Only
        // the order of the output rules (hence the atom numbering) depends on this order.
        let rec: Vec<Vec<usize>> = stmts
            .iter()
            .map(|s| {
                s.body
                    .iter()
                    .enumerate()
                    .filter(|(_, l)| matches!(l, NLit::Pred { sign: Sign::Positive, atom } if in_comp(atom.pred)))
                    .map(|(i, _)| i)
                    .collect()
            })
            .collect();
        let mut heads = Rows::with_capacity(stmts.len(), stmts.len());
        for s in stmts {
            stmt_heads(s, &mut heads);
            heads.end_row();
        }
        let rec_pred = |t: usize, jj: usize| -> PredId {
            match &stmts[t].body[rec[t][jj]] {
                NLit::Pred { atom, .. } => atom.pred,
                _ => unreachable!("recursive literals are predicate literals"),
            }
        };
        // deps[s]: the instantiators (statement, recursive literal) reading a predicate that
        // statement s heads, in registration order.
        let mut deps: Vec<Vec<(usize, usize)>> = vec![Vec::new(); stmts.len()];
        for (t, r) in rec.iter().enumerate() {
            for jj in 0..r.len() {
                let p = rec_pred(t, jj);
                for (s, d) in deps.iter_mut().enumerate() {
                    if heads.row(s).contains(&p) {
                        d.push((t, jj));
                    }
                }
            }
        }
        let offset: Vec<usize> = rec
            .iter()
            .scan(0usize, |acc, r| {
                let o = *acc;
                *acc += r.len();
                Some(o)
            })
            .collect();
        let mut enqueued =
            vec![false; offset.last().map_or(0, |&o| o) + rec.last().map_or(0, |r| r.len())];
        // The statements whose heads propagate after the current round, in order.
        let mut current: Vec<usize> = (0..stmts.len()).collect();
        loop {
            let mut any = false;
            for &p in comp {
                let d = &mut self.domains[p as usize];
                d.old = d.delta;
                d.delta = d.atoms.len() as u32;
                any |= d.delta > d.old;
            }
            if !any || self.stopped.is_some() {
                return;
            }
            let mut queue: Vec<(usize, usize)> = Vec::new();
            for &s in &current {
                for &(t, jj) in &deps[s] {
                    let d = &self.domains[rec_pred(t, jj) as usize];
                    if !enqueued[offset[t] + jj] && d.delta > d.old {
                        enqueued[offset[t] + jj] = true;
                        queue.push((t, jj));
                    }
                }
            }
            current.clear();
            for &(t, jj) in &queue {
                enqueued[offset[t] + jj] = false;
                current.push(t);
                let s = stmts[t];
                let mut ranges: Vec<Option<Range>> = vec![None; s.body.len()];
                let mut empty = false;
                for (kk, &i) in rec[t].iter().enumerate() {
                    let NLit::Pred { atom, .. } = &s.body[i] else {
                        continue;
                    };
                    let d = &self.domains[atom.pred as usize];
                    let r = match kk.cmp(&jj) {
                        std::cmp::Ordering::Less => (0, d.old),
                        std::cmp::Ordering::Equal => (d.old, d.delta),
                        std::cmp::Ordering::Greater => (0, d.delta),
                    };
                    empty |= r.0 >= r.1;
                    ranges[i] = Some(r);
                }
                if !empty {
                    self.new_lit = &s.body[rec[t][jj]] as *const NLit as usize;
                    self.ground_stmt(s, &ranges);
                    self.new_lit = 0;
                }
            }
        }
    }

    /// gringo's `atom does not occur in any rule head` for positive body atoms of predicates
    /// that nothing defines.
    pub(super) fn warn_undefined(&mut self, prog: &Compiled, heads: &Rows) {
        // Predicates an earlier grounding defined count as defined (multi-shot).
        let mut defined = std::mem::take(&mut self.defined);
        defined.resize(prog.preds.len().max(defined.len()), false);
        for &p in &heads.items {
            defined[p as usize] = true;
        }
        for &p in &prog.defined {
            defined[p as usize] = true;
        }
        let mut seen: hashbrown::HashSet<Span> = hashbrown::HashSet::new();
        let mut atoms: Vec<&NAtom> = Vec::new();
        for s in &prog.stmts {
            atoms.clear();
            for l in &s.body {
                positive_atoms(l, &mut atoms);
            }
            if let NHead::Disj(es) | NHead::Choice(es) = &s.head {
                for e in es {
                    e.cond.iter().for_each(|l| positive_atoms(l, &mut atoms));
                }
            }
            for &a in &atoms {
                if !a.sort && !defined[a.pred as usize] && seen.insert(a.span) {
                    let d = Diagnostic::warning(
                        WarningKind::AtomUndefined,
                        a.span,
                        "atom does not occur in any rule head",
                    );
                    let snip = self.snippet(a.span);
                    self.diags.push(if snip.is_empty() {
                        d
                    } else {
                        d.with_snippet(snip)
                    });
                }
            }
        }
        self.defined = defined;
    }
}

impl Grounder<'_> {
    /// gringo's `no atoms over signature occur in program` for each `#show p/n.` whose
    /// predicate no statement mentions (in a head, in a body, or in an earlier grounding's
    /// heads), one per signature, in the order of the signatures (name, arity, sign).
    /// Runs after `warn_undefined`, whose `defined` covers the heads.
    fn warn_unshown(&mut self, prog: &Compiled, reads: &Rows) {
        let show = &prog.show;
        if show.signature_sites.is_empty() {
            return;
        }
        let mut mentioned = self.defined.clone();
        mentioned.resize(prog.preds.len().max(mentioned.len()), false);
        for &p in &reads.items {
            mentioned[p as usize] = true;
        }
        let mut missing: Vec<(&str, u32, bool, Span)> = Vec::new();
        for &(p, span) in &show.signature_sites {
            if !mentioned[p as usize] {
                let pred = &prog.preds[p as usize];
                let name = self.syms.names.resolve(pred.name);
                missing.push((name, pred.arity, pred.neg, span));
            }
        }
        missing.sort_by(|a, b| (a.0, a.1, a.2).cmp(&(b.0, b.1, b.2)));
        missing.dedup_by(|a, b| (a.0, a.1, a.2) == (b.0, b.1, b.2));
        for (name, arity, neg, span) in missing {
            let sign = if neg { "-" } else { "" };
            let d = Diagnostic::warning(
                WarningKind::AtomUndefined,
                span,
                "no atoms over signature occur in program",
            )
            .with_snippet(format!("{sign}{name}/{arity}"));
            self.diags.push(d);
        }
    }
}

pub(super) fn positive_atoms<'x>(l: &'x NLit, out: &mut Vec<&'x NAtom>) {
    match l {
        NLit::Pred { atom, .. } => out.push(atom),
        NLit::Agg(a) => {
            for e in &a.elems {
                e.cond.iter().for_each(|c| positive_atoms(c, out));
                e.lit_lits().for_each(|l| positive_atoms(l, out));
            }
        }
        _ => {}
    }
}

/// Predicates a literal reads (including inside aggregates).
pub(super) fn lit_preds(l: &NLit, out: &mut Vec<PredId>) {
    match l {
        NLit::Pred { atom, .. } => out.push(atom.pred),
        NLit::Agg(a) => {
            for e in &a.elems {
                e.cond.iter().for_each(|c| lit_preds(c, out));
                e.lit_lits().for_each(|l| lit_preds(l, out));
            }
        }
        _ => {}
    }
}

/// As [`lit_preds`], with the atom of each predicate read pushed to `atoms`.
fn lit_occs<'p>(l: &'p NLit, preds: &mut Vec<PredId>, atoms: &mut Vec<&'p NAtom>) {
    match l {
        NLit::Pred { atom, .. } => {
            preds.push(atom.pred);
            atoms.push(atom);
        }
        NLit::Agg(a) => {
            for e in &a.elems {
                e.cond.iter().for_each(|c| lit_occs(c, preds, atoms));
                e.lit_lits().for_each(|l| lit_occs(l, preds, atoms));
            }
        }
        _ => {}
    }
}

/// Where a body literal was written: the start of its atom's span (for an aggregate, of its
/// first atom's); literals without an atom come last, in planned order.
fn source_pos(l: &NLit) -> u32 {
    match l {
        NLit::Pred { atom, .. } => atom.span.start,
        NLit::Agg(a) => a
            .elems
            .iter()
            .flat_map(|e| e.cond.iter().chain(e.lit_lits()))
            .map(source_pos)
            .min()
            .unwrap_or(u32::MAX),
        _ => u32::MAX,
    }
}

/// Whether statement `s` heads an atom of `atom`'s predicate whose arguments unify with
/// `atom`'s.
fn heads_unify(syms: &Symbols, s: &NStmt, atom: &NAtom) -> bool {
    let same = |h: &NAtom| {
        h.pred == atom.pred
            && h.args.len() == atom.args.len()
            && h.args
                .iter()
                .zip(&atom.args)
                .all(|(x, y)| may_unify(syms, x, y))
    };
    let head = match &s.head {
        NHead::Disj(es) | NHead::Choice(es) => es.iter().flat_map(|e| e.derived_atoms()).any(same),
        NHead::None => false,
    };
    head || matches!(&s.kind, NKind::External(a, _) if same(a))
}

/// Whether two terms may stand for the same ground term under some substitution. Conservative:
/// a variable, and an operation other than arithmetic, may be anything (variables shared
/// between arguments are not followed); arithmetic yields only integers. So two terms are
/// told apart only by a constant, a function symbol or an integer that differ.
fn may_unify(syms: &Symbols, a: &NTerm, b: &NTerm) -> bool {
    match (a, b) {
        (NTerm::Var(_), _)
        | (_, NTerm::Var(_))
        | (NTerm::Unary { .. }, _)
        | (_, NTerm::Unary { .. }) => true,
        (NTerm::Binary { .. }, NTerm::Binary { .. }) => true,
        (NTerm::Binary { .. }, NTerm::Sym(x)) | (NTerm::Sym(x), NTerm::Binary { .. }) => {
            syms.num(*x).is_some()
        }
        (NTerm::Binary { .. }, NTerm::Fun { .. }) | (NTerm::Fun { .. }, NTerm::Binary { .. }) => {
            false
        }
        (NTerm::Sym(x), NTerm::Sym(y)) => x == y,
        (NTerm::Sym(x), NTerm::Fun { name, neg, args })
        | (NTerm::Fun { name, neg, args }, NTerm::Sym(x)) => match syms.get(*x) {
            SymData::Fun {
                name: n,
                neg: g,
                len,
                ..
            } => {
                n == *name
                    && g == *neg
                    && len as usize == args.len()
                    && syms
                        .args(*x)
                        .iter()
                        .zip(args)
                        .all(|(&s, t)| may_unify(syms, &NTerm::Sym(s), t))
            }
            _ => false,
        },
        (
            NTerm::Fun { name, neg, args },
            NTerm::Fun {
                name: n2,
                neg: g2,
                args: a2,
            },
        ) => {
            name == n2
                && neg == g2
                && args.len() == a2.len()
                && args.iter().zip(a2).all(|(x, y)| may_unify(syms, x, y))
        }
    }
}

/// True when an aggregate of `l` reads a predicate of the current component.
/// The predicates a statement derives atoms of (its head atoms, or the external atom).
/// Adds them to the open row of `out`.
pub(super) fn stmt_heads(s: &NStmt, out: &mut Rows) {
    match &s.head {
        NHead::Disj(es) | NHead::Choice(es) => {
            for a in es.iter().flat_map(|e| e.derived_atoms()) {
                if !out.open_row().contains(&a.pred) {
                    out.items.push(a.pred)
                }
            }
        }
        NHead::None => {}
    }
    if let NKind::External(a, _) = &s.kind {
        out.items.push(a.pred);
    }
}

/// Whether a statement is a ground fact (one unconditional head atom, no body, no variables):
/// gringo keeps these out of its dependency graph and outputs them first.
pub(super) fn is_ground_fact(s: &NStmt) -> bool {
    matches!(s.kind, NKind::Rule)
        && s.body.is_empty()
        && s.num_vars == 0
        && matches!(&s.head, NHead::Disj(es) if es.len() == 1 && es[0].cond.is_empty() && es[0].conj.is_empty())
}

pub(super) fn nested_reads(l: &NLit, in_comp: &dyn Fn(PredId) -> bool) -> bool {
    match l {
        NLit::Agg(_) => {
            let mut r = Vec::new();
            lit_preds(l, &mut r);
            r.into_iter().any(in_comp)
        }
        _ => false,
    }
}

/// Splits each strongly connected component of the statement dependency graph into the
/// components of its positive dependencies, in topological order, as gringo does: a statement
/// read only under default negation by a statement of the same component is grounded after
/// it, which keeps such literals (the predicate is not complete yet) instead of iterating the
/// whole component together. Grounding each part to a fixpoint in this order gives the same
/// rules, in gringo's order. Parts list their statements in gringo's order too.
pub(super) fn positive_split(comps: Rows, pos_edges: &Rows) -> Rows {
    let mut local = vec![u32::MAX; pos_edges.len()];
    let mut out = Rows::with_capacity(comps.len(), comps.items.len());
    let mut sub = Rows::with_capacity(0, 0);
    for ci in 0..comps.len() {
        let comp = comps.row(ci);
        if comp.len() == 1 {
            out.items.push(comp[0]);
            out.end_row();
            continue;
        }
        for (i, &v) in comp.iter().enumerate() {
            local[v as usize] = i as u32;
        }
        sub.start.truncate(1);
        sub.items.clear();
        for &v in comp {
            sub.items.extend(
                pos_edges
                    .row(v as usize)
                    .iter()
                    .map(|&w| local[w as usize])
                    .filter(|&w| w != u32::MAX),
            );
            sub.end_row();
        }
        let parts = gringo_tarjan(&sub);
        for pi in 0..parts.len() {
            out.items
                .extend(parts.row(pi).iter().map(|&i| comp[i as usize]));
            out.end_row();
        }
        for &v in comp {
            local[v as usize] = u32::MAX;
        }
    }
    out
}

/// Strongly connected components, every component after those it has edges to, computed as
/// gringo's `Graph::tarjan` does so that independent components and the members of one
/// component come in gringo's order: depth-first from the nodes in reverse order (gringo's
/// graph prepends inserted nodes), edges in insertion order, and each component listing its
/// nodes as they leave the trail (last reached first).
pub(super) fn gringo_tarjan(edges: &Rows) -> Rows {
    const NEW: u32 = u32::MAX;
    const DONE: u32 = 0;
    let n = edges.len();
    // NEW, DONE, or the node's current low value (from 2 on, as gringo's).
    let mut visited = vec![NEW; n];
    let mut next_edge = vec![0usize; n];
    let mut stack: Vec<u32> = Vec::new();
    let mut trail: Vec<u32> = Vec::new();
    let mut comps = Rows::with_capacity(n, n);
    for root in (0..n).rev() {
        if visited[root] != NEW {
            continue;
        }
        let mut index = 1u32;
        let mut push =
            |x: u32, visited: &mut Vec<u32>, stack: &mut Vec<u32>, trail: &mut Vec<u32>| {
                index += 1;
                visited[x as usize] = index;
                stack.push(x);
                trail.push(x);
            };
        push(root as u32, &mut visited, &mut stack, &mut trail);
        while let Some(&y) = stack.last() {
            let y = y as usize;
            let es = edges.row(y);
            while next_edge[y] < es.len() && visited[es[next_edge[y]] as usize] != NEW {
                next_edge[y] += 1;
            }
            if next_edge[y] < es.len() {
                let z = es[next_edge[y]];
                next_edge[y] += 1;
                push(z, &mut visited, &mut stack, &mut trail);
                continue;
            }
            stack.pop();
            let mut root = true;
            for &z in es {
                let vz = visited[z as usize];
                if vz != DONE && vz < visited[y] {
                    root = false;
                    visited[y] = vz;
                }
            }
            if root {
                loop {
                    let w = trail.pop().expect("scc trail");
                    visited[w as usize] = DONE;
                    comps.items.push(w);
                    if w as usize == y {
                        break;
                    }
                }
                comps.end_row();
            }
        }
    }
    comps
}
