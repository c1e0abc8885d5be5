//! Groundings merged into the Control's tables. Every grounding runs on the Control's one
//! `ground::incremental::Session` (grounder atoms, domains and indexes kept between calls) and
//! the Control's one symbol table; a later grounding's atoms are matched to the Control's by
//! grounder atom, new atoms numbered after the old, and its rules, outputs, minimize
//! statements and provenance (statement ids, grounder atoms) moved into the Control's
//! numbering. The first grounding is adopted as it is (its numbering is the global one, as
//! one-shot `ground::ground` numbers).
//!
//! Invariants: a symbol keeps its atom across groundings (grounder-made `#projN` atoms excepted:
//! they belong to their grounding); an atom that a solve call completed gets no rules later
//! (clingo's redefinition error, the offending rules dropped).

use super::*;
use crate::ground::instantiate::GroundAtom;

impl Control {
    /// Takes the first grounding as it is: its numbering is the global one.
    pub(super) fn adopt(&mut self, mut g: Grounding) {
        let program = std::mem::take(&mut g.program);
        // (The symbols are the Control's already.)
        // Copied, not taken: `take_grounding` hands the grounding back for text output,
        // which renders its atom names from these symbols.
        self.atom_sym = g.atom_syms.clone();
        self.atom_sym.resize(program.num_atoms as usize, None);
        for s in self.atom_sym.iter_mut() {
            if s.is_some_and(|s| is_internal(&self.syms, s)) {
                *s = None;
            }
        }
        self.flags = vec![0; self.atom_sym.len()];
        self.atom_key = vec![Output::LAST; self.atom_sym.len()];
        for (key, &ga) in self.atom_key.iter_mut().zip(self.session.last_gatoms()) {
            *key = self.session.atom_order(ga);
        }
        self.sym_atom = vec![0; self.syms.len()];
        for (i, s) in self.atom_sym.iter().enumerate() {
            if let Some(s) = s {
                self.sym_atom[s.0 as usize] = i as AtomId + 1;
            }
        }
        for (i, &ga) in self.session.last_gatoms().iter().enumerate() {
            set_gatom(&mut self.ctl_of_gatom, ga, i as AtomId + 1);
        }
        for &s in &g.fact_syms {
            if let Some(a) = self.atom_of_sym(s) {
                self.flags[a as usize - 1] |= FACT;
            }
        }
        for r in program.rules.iter() {
            for &h in r.head {
                self.flags[h as usize - 1] |= DEFINED;
            }
        }
        for &(a, v) in &program.externals {
            if self.flags[a as usize - 1] & DEFINED == 0 {
                self.externals.insert(a, external_value(v));
            }
        }
        if self.config.ground.provenance {
            self.gatoms = program.provenance.atoms.clone();
            self.gatom_of_sym = self
                .gatoms
                .iter()
                .enumerate()
                .filter_map(|(i, r)| Some((r.sym?, i as GAtom + 1)))
                .collect();
        }
        self.pending = program;
        self.last = Some(g);
    }

    pub(super) fn atom_of_sym(&self, s: SymId) -> Option<AtomId> {
        match self.sym_atom.get(s.0 as usize) {
            Some(&a) if a != 0 => Some(a),
            _ => None,
        }
    }

    pub(super) fn new_atom(&mut self, sym: Option<SymId>) -> AtomId {
        self.atom_sym.push(sym);
        self.flags.push(0);
        self.atom_key.push(Output::LAST);
        let a = self.atom_sym.len() as AtomId;
        if let Some(s) = sym {
            let i = s.0 as usize;
            if self.sym_atom.len() <= i {
                self.sym_atom.resize(i + 1, 0);
            }
            self.sym_atom[i] = a;
        }
        a
    }

    /// Merges a later grounding: atoms matched by symbol, new ones numbered after the old,
    /// origins moved to the Control's statement ids, symbols and grounder atoms. A rule for an
    /// atom that an earlier solve call completed is gringo's redefinition error: the rules of
    /// such atoms are dropped (clingo keeps the rest of the step) and the error returned.
    pub(super) fn merge(&mut self, mut g: Grounding, stmt_offset: u32) -> Result<(), Diagnostic> {
        let local = std::mem::take(&mut g.program);
        let old_atoms = self.atom_sym.len() as AtomId;
        let gatoms = self.session.last_gatoms().to_vec();
        let map = self.map_atoms(&g, &local, &gatoms);
        let gmap = self.translate_atom_records(&local, &map);
        let MergedRules {
            mut delta,
            defined_here,
            redefined,
            first_redefinition,
            kept,
        } = self.merge_rules(&local, &map, old_atoms, &gatoms);
        self.mark_merged_atoms(&g, &local, &map, old_atoms, &defined_here, &redefined);
        map_statements(&local, &map, &mut delta);
        self.merge_outputs(&local, &map, &mut delta);
        for t in &local.theory_atoms {
            let mut t = t.clone();
            if t.atom != 0 {
                t.atom = map[t.atom as usize];
            }
            for e in &mut t.elements {
                e.condition.iter_mut().for_each(|l| *l = map_lit(&map, *l));
            }
            delta.theory_atoms.push(t);
        }
        if let Some(gmap) = &gmap {
            delta.provenance = self.merge_provenance(&local, gmap, &kept, stmt_offset);
        }
        delta.num_atoms = self.atom_sym.len() as AtomId;
        self.append_pending(delta);
        self.last = Some(g);
        match redefined.first() {
            None => Ok(()),
            Some(&a) => Err(self.redefinition_error(a, &local, first_redefinition, stmt_offset)),
        }
    }

    /// The Control's atom of each atom of the grounding `g` (index 0 unused), by the session's
    /// grounder atom `gatoms`: atoms new to the Control are numbered after the old ones.
    fn map_atoms(
        &mut self,
        g: &Grounding,
        local: &GroundProgram,
        gatoms: &[GroundAtom],
    ) -> Vec<AtomId> {
        // Local atoms to the Control's, by the session's grounder atom.
        let mut map = vec![0 as AtomId; local.num_atoms as usize + 1];
        for (a, slot) in map.iter_mut().enumerate().skip(1) {
            let ga = gatoms[a - 1];
            if let Some(&x) = self.ctl_of_gatom.get(ga.get() as usize) {
                if x != 0 {
                    *slot = x;
                    continue;
                }
            }
            let sym = g
                .atom_syms
                .get(a - 1)
                .copied()
                .flatten()
                .filter(|&s| !is_internal(&self.syms, s));
            *slot = self.new_atom(sym);
            *self.atom_key.last_mut().expect("pushed") = self.session.atom_order(ga);
            set_gatom(&mut self.ctl_of_gatom, ga, *slot);
        }
        map
    }

    /// The rules of a later grounding in the Control's atoms, without those that add nothing
    /// (all heads old facts) and without the rules of redefined atoms (gringo's redefinition
    /// error; the session forgets their facts). Externals defined by a rule become ordinary
    /// atoms.
    fn merge_rules(
        &mut self,
        local: &GroundProgram,
        map: &[AtomId],
        old_atoms: AtomId,
        gatoms: &[GroundAtom],
    ) -> MergedRules {
        let is_old = |a: AtomId| a <= old_atoms;
        let lit = |l: i32| map_lit(map, l);
        // Atoms an earlier solve call completed: in the solver and no longer external there,
        // or released since.
        let solver_atoms = self.solver.as_ref().map_or(0, |s| s.program().num_atoms);
        let complete = |a: AtomId, solver: &Option<Solver>, ext: &HashMap<AtomId, _>| {
            a <= solver_atoms
                && (solver.as_ref().is_some_and(|s| !s.is_external(a))
                    || matches!(ext.get(&a), Some(None)))
        };
        let old_fact = |a: AtomId, flags: &[u8]| is_old(a) && flags[a as usize - 1] & FACT != 0;
        let mut delta = GroundProgram::new();
        let mut defined_here: HashSet<AtomId> = HashSet::new();
        let mut redefined: Vec<AtomId> = Vec::new();
        let mut first_redefinition: Option<usize> = None;
        let mut kept: Vec<usize> = Vec::new();
        for (i, r) in local.rules.iter().enumerate() {
            let heads: Vec<AtomId> = r.head.iter().map(|&h| map[h as usize]).collect();
            // A rule whose heads are all old facts adds nothing (the context's facts).
            if !heads.is_empty() && heads.iter().all(|&h| old_fact(h, &self.flags)) {
                continue;
            }
            if let Some(&h) = heads
                .iter()
                .find(|&&h| complete(h, &self.solver, &self.externals))
            {
                if redefined.is_empty() {
                    first_redefinition = Some(i);
                }
                if !redefined.contains(&h) {
                    redefined.push(h);
                }
                continue;
            }
            let mut rule = r.to_rule();
            rule.head = heads;
            match &mut rule.body {
                ground::program::Body::Normal(ls) => ls.iter_mut().for_each(|l| *l = lit(*l)),
                ground::program::Body::Weight { lits, .. } => {
                    lits.iter_mut().for_each(|(l, _)| *l = lit(*l))
                }
            }
            for &h in &rule.head {
                defined_here.insert(h);
                // An external defined by a rule becomes an ordinary atom (the solver takes
                // such rules incrementally).
                self.externals.remove(&h);
            }
            delta.rules.push(rule);
            kept.push(i);
        }
        // The rules of a redefined atom are dropped, all of them (clingo's state after the
        // error).
        if !redefined.is_empty() {
            let mut keep_rules = GroundProgram::new();
            let mut keep_idx = Vec::new();
            for (r, &i) in delta.rules.iter().zip(&kept) {
                if r.head.iter().any(|h| redefined.contains(h)) {
                    continue;
                }
                keep_rules.rules.push_ref(r);
                keep_idx.push(i);
            }
            delta.rules = keep_rules.rules;
            kept = keep_idx;
            defined_here = delta.rules.iter().flat_map(|r| r.head.to_vec()).collect();
            for (a, &ga) in gatoms.iter().enumerate() {
                if redefined.contains(&map[a + 1]) {
                    self.session.forget_fact(ga);
                }
            }
        }
        MergedRules {
            delta,
            defined_here,
            redefined,
            first_redefinition,
            kept,
        }
    }

    /// Flags the atoms the merged rules define and the grounding's facts (redefined atoms
    /// excepted), and records the grounding's new externals (not old, not defined, not
    /// released).
    fn mark_merged_atoms(
        &mut self,
        g: &Grounding,
        local: &GroundProgram,
        map: &[AtomId],
        old_atoms: AtomId,
        defined_here: &HashSet<AtomId>,
        redefined: &[AtomId],
    ) {
        let is_old = |a: AtomId| a <= old_atoms;
        for &h in defined_here {
            self.flags[h as usize - 1] |= DEFINED;
        }
        for &s in &g.fact_syms {
            if let Some(a) = self.atom_of_sym(s) {
                if !redefined.contains(&a) {
                    self.flags[a as usize - 1] |= FACT;
                }
            }
        }
        for &(a, v) in &local.externals {
            let ga = map[a as usize];
            if is_old(ga) || defined_here.contains(&ga) {
                continue;
            }
            if !self.released.contains(&ga) {
                self.externals.insert(ga, external_value(v));
                self.new_externals.push(ga);
            }
        }
    }

    /// Adds to `delta` the outputs of `local` in the Control's atoms, without those already
    /// present (the context shows old atoms again).
    fn merge_outputs(&mut self, local: &GroundProgram, map: &[AtomId], delta: &mut GroundProgram) {
        let lit = |l: i32| map_lit(map, l);
        // Outputs, without those already present (the context shows old atoms again).
        if self.outputs_seen.is_none() {
            let solver_outputs = match &self.solver {
                Some(s) => s.program().outputs.as_slice(),
                None => &[],
            };
            let seen = solver_outputs
                .iter()
                .chain(self.pending.outputs.iter())
                .map(|o| (o.symbol.clone(), o.condition.clone()))
                .collect();
            self.outputs_seen = Some(seen);
        }
        let seen = self.outputs_seen.as_mut().expect("set above");
        for o in &local.outputs {
            let condition: Vec<i32> = o.condition.iter().map(|&l| lit(l)).collect();
            if seen.insert((o.symbol.clone(), condition.clone())) {
                delta.outputs.push(Output {
                    symbol: o.symbol.clone(),
                    condition,
                    order: o.order,
                });
            }
        }
    }

    /// The provenance of the kept rules (`kept`: their indexes in `local`) and of the dead
    /// rules of `local`, in the Control's ids (`gmap`: grounder atoms).
    fn merge_provenance(
        &mut self,
        local: &GroundProgram,
        gmap: &[GAtom],
        kept: &[usize],
        stmt_offset: u32,
    ) -> ground::program::Provenance {
        let mut prov = ground::program::Provenance::new();
        for &i in kept {
            let origins: Vec<_> = local
                .provenance
                .origins(i)
                .iter()
                .filter_map(|o| self.translate_origin(o, gmap, stmt_offset))
                .collect();
            prov.push_rule(origins);
        }
        for d in &local.provenance.dead {
            let why = match d.why {
                DeadReason::Literal { positive, atom } => DeadReason::Literal {
                    positive,
                    atom: gmap[atom as usize],
                },
                DeadReason::HeadFact(a) => DeadReason::HeadFact(gmap[a as usize]),
                w => w,
            };
            prov.dead.push(ground::program::DeadRule {
                head: d.head.iter().map(|&h| gmap[h as usize]).collect(),
                origins: d
                    .origins
                    .iter()
                    .filter_map(|o| self.translate_origin(o, gmap, stmt_offset))
                    .collect(),
                why,
            });
        }
        prov.set_atoms(self.gatoms.clone());
        prov
    }

    /// Appends the merged `delta` to what is pending.
    fn append_pending(&mut self, mut delta: GroundProgram) {
        // Append the delta to what is pending.
        let p = &mut self.pending;
        if !delta.provenance.is_empty() {
            p.provenance.resize_rules(p.rules.len());
            p.provenance.append(std::mem::take(&mut delta.provenance));
        }
        p.num_atoms = delta.num_atoms;
        p.rules.extend(delta.rules.iter());
        p.minimize.extend(delta.minimize);
        p.projections.extend(delta.projections);
        p.outputs.extend(delta.outputs);
        p.assumptions.extend(delta.assumptions);
        p.heuristics.extend(delta.heuristics);
        p.edges.extend(delta.edges);
        p.theory_atoms.extend(delta.theory_atoms);
        p.cr_rules.extend(delta.cr_rules);
        p.prefers.extend(delta.prefers);
    }

    /// gringo's redefinition error for atom `a`, at the statement of the first rule dropped
    /// (`first_redefinition`, its index in `local`; known with provenance on).
    fn redefinition_error(
        &mut self,
        a: AtomId,
        local: &GroundProgram,
        first_redefinition: Option<usize>,
        stmt_offset: u32,
    ) -> Diagnostic {
        let name = self.symbol(a).map_or_else(String::new, |s| s.to_string());
        // The statement of the first rule dropped (known with provenance on).
        let span = first_redefinition
            .and_then(|i| {
                local
                    .provenance
                    .origins(i)
                    .iter()
                    .find_map(|o| o.rule.stmt())
            })
            .and_then(|k| self.stmts.get((k + stmt_offset) as usize))
            .map(|st| st.statement.span);
        let span = span.unwrap_or_else(|| self.no_position());
        Diagnostic::error(span, format!("redefinition of atom <'{name}',{a}>"))
    }

    /// A span for errors without a source position (gringo's `<cmd>`-like pseudo files).
    fn no_position(&mut self) -> Span {
        let file = self.sources.add("<ground>", "");
        Span::new(file, 0, 0)
    }

    /// Moves a later grounding's atom records into the Control's table (the session's grounder
    /// atoms are the Control's: a record updates the atom's earlier one) and returns the
    /// grounder atom map (`None` without provenance).
    fn translate_atom_records(
        &mut self,
        local: &GroundProgram,
        map: &[AtomId],
    ) -> Option<Vec<GAtom>> {
        if !self.config.ground.provenance || local.provenance.atoms.is_empty() {
            return None;
        }
        let mut gmap = vec![0 as GAtom; local.provenance.atoms.len() + 1];
        for (i, r) in local.provenance.atoms.iter().enumerate() {
            let aspif = if r.aspif == 0 {
                0
            } else {
                map[r.aspif as usize]
            };
            match self.gatoms.get_mut(i) {
                Some(old) => {
                    if r.status != AtomStatus::False && old.status != AtomStatus::Fact {
                        old.status = r.status;
                    }
                    if aspif != 0 {
                        old.aspif = aspif;
                    }
                }
                None => {
                    self.gatoms.push(AtomRecord {
                        sym: r.sym,
                        status: r.status,
                        aspif,
                    });
                    if let Some(s) = r.sym {
                        self.gatom_of_sym.insert(s, i as GAtom + 1);
                    }
                }
            }
            gmap[i + 1] = i as GAtom + 1;
        }
        Some(gmap)
    }

    /// One origin of a later grounding in the Control's ids: statement ids shifted by the
    /// grounding's offset, bindings and atoms in the global tables; `None` for the context
    /// statements (they are no statements of the program).
    fn translate_origin(
        &mut self,
        o: &ground::program::Origin,
        gmap: &[GAtom],
        offset: u32,
    ) -> Option<ground::program::Origin> {
        let n = self.stmts.len() as u32;
        // (Bindings are ids of the Control's table already.)
        let bind = |b: &[(u32, u32)]| -> Vec<(u32, u32)> { b.to_vec() };
        let rule = match &o.rule {
            RuleOrigin::Statement { stmt, bindings } if stmt + offset < n => {
                RuleOrigin::Statement {
                    stmt: stmt + offset,
                    bindings: bind(bindings),
                }
            }
            RuleOrigin::Auxiliary {
                of_stmt,
                kind,
                bindings,
            } if of_stmt + offset < n => RuleOrigin::Auxiliary {
                of_stmt: of_stmt + offset,
                kind: *kind,
                bindings: bind(bindings),
            },
            RuleOrigin::Complement => RuleOrigin::Complement,
            _ => return None,
        };
        Some(ground::program::Origin {
            rule,
            removed: o
                .removed
                .iter()
                .map(|r| RemovedLit {
                    positive: r.positive,
                    atom: gmap[r.atom as usize],
                })
                .collect(),
        })
    }
}

fn external_value(v: ExternalValue) -> Option<TruthValue> {
    match v {
        ExternalValue::Free => Some(TruthValue::Free),
        ExternalValue::True => Some(TruthValue::True),
        ExternalValue::False => Some(TruthValue::False),
        ExternalValue::Release => None,
    }
}

/// Whether `s` names a grounder-made atom (`#projN(..)`): such atoms belong to their
/// grounding, so a later grounding's `#proj1(1)` is another atom than an earlier one's, and
/// they are neither looked up nor part of the context.
fn is_internal(syms: &Symbols, s: SymId) -> bool {
    match syms.get(s) {
        crate::ground::symbol::SymData::Fun { name, .. } => {
            syms.names.resolve(name).starts_with("#proj")
        }
        _ => false,
    }
}

/// Records that grounder atom `ga` is the Control's atom `a`.
fn set_gatom(table: &mut Vec<AtomId>, ga: GroundAtom, a: AtomId) {
    let i = ga.get() as usize;
    if table.len() <= i {
        table.resize(i + 1, 0);
    }
    table[i] = a;
}

/// What `Control::merge_rules` makes of a later grounding's rules.
struct MergedRules {
    /// The kept rules, in the Control's atoms.
    delta: GroundProgram,
    /// The atoms the kept rules define.
    defined_here: HashSet<AtomId>,
    /// Atoms an earlier solve call completed that the grounding gave rules (dropped).
    redefined: Vec<AtomId>,
    /// The index in the grounding of the first rule dropped as a redefinition.
    first_redefinition: Option<usize>,
    /// Per kept rule: its index in the grounding.
    kept: Vec<usize>,
}

/// An aspif literal of a later grounding in the Control's atoms (`map`).
fn map_lit(map: &[AtomId], l: i32) -> i32 {
    let a = map[l.unsigned_abs() as usize] as i32;
    if l < 0 {
        -a
    } else {
        a
    }
}

/// Adds to `delta` the minimize statements, CR rules, preferences, heuristics, edges,
/// projections and assumptions of `local`, in the Control's atoms (`map`).
fn map_statements(local: &GroundProgram, map: &[AtomId], delta: &mut GroundProgram) {
    let lit = |l: i32| map_lit(map, l);
    for m in &local.minimize {
        let mut m = m.clone();
        m.lits.iter_mut().for_each(|(l, _)| *l = lit(*l));
        delta.minimize.push(m);
    }
    for c in &local.cr_rules {
        delta.cr_rules.push(ground::program::CrRule {
            appl: map[c.appl as usize],
            label: c.label.clone(),
        });
    }
    for p in &local.prefers {
        delta.prefers.push(ground::program::Prefer {
            better: map[p.better as usize],
            worse: map[p.worse as usize],
        });
    }
    for h in &local.heuristics {
        let mut h = h.clone();
        h.atom = map[h.atom as usize];
        h.condition.iter_mut().for_each(|l| *l = lit(*l));
        delta.heuristics.push(h);
    }
    for e in &local.edges {
        let mut e = e.clone();
        e.condition.iter_mut().for_each(|l| *l = lit(*l));
        delta.edges.push(e);
    }
    for &p in &local.projections {
        delta.projections.push(map[p as usize]);
    }
    for &l in &local.assumptions {
        delta.assumptions.push(lit(l));
    }
}
