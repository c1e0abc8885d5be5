//! Ground statements added from code (clingo's `Control.backend()`): atoms with or without a
//! symbol, rules (normal, choice, weight bodies), minimize statements, externals, assumptions,
//! projections, heuristics and acyclicity edges join the Control's pending program exactly as
//! a grounding's rules do (`context`: numbered after the Control's atoms, handed to the solver
//! at the next solve call).
//!
//! ```
//! use lucent::control::{Control, ControlConfig, Symbol};
//! let mut ctl = Control::new(ControlConfig::default());
//! ctl.solve_config_mut().models = 0;
//! let mut b = ctl.backend().unwrap();
//! let a = b.add_atom(Some(&Symbol::constant("a")));
//! let c = b.add_atom(Some(&Symbol::constant("c")));
//! b.add_rule(&[a], &[], true).unwrap(); // {a}.
//! b.add_rule(&[c], &[a as i32], false).unwrap(); // c :- a.
//! let n = ctl.solve_all(&Default::default()).models.len();
//! assert_eq!(n, 2);
//! ```
//!
//! Invariants:
//! - An atom added with a symbol is the symbol's atom: an atom that a grounding (or an earlier
//!   `add_atom`) made is returned again, a new one is numbered after every existing atom and is
//!   found by [`Control::lookup`] and [`Control::symbolic_atoms`]. It is shown unless the
//!   program restricts the output with `#show p/n.` or `#show.` (then only a matching signature
//!   shows it), as clingo does.
//! - Statements are checked before they are kept: a literal must name an existing atom, and a
//!   rule may not define an atom that an earlier solve call completed (clingo's redefinition
//!   error). A rejected statement changes nothing.
//! - The grounder does not see atoms added here: a later grounding does not derive from them
//!   (clingo's grounder would; documented in docs/reference.md's Python section).

use super::*;
use crate::ground::program::{
    Body, Edge, HeadKind, Heuristic, HeuristicModifier, Lit, Minimize, Rule, Weight,
};

/// Adds ground statements to a [`Control`] (see the module documentation).
pub struct Backend<'a> {
    ctl: &'a mut Control,
}

impl Control {
    /// The backend, to add ground statements from code (clingo's `Control.backend()`). A
    /// Control that has not grounded yet grounds nothing first (the empty program), so that the
    /// atoms added here keep their numbers when parts are grounded later.
    pub fn backend(&mut self) -> Result<Backend<'_>, Error> {
        self.begin_update();
        if self.groundings == 0 {
            self.ground_blocks(&[], &[], None)?;
        }
        Ok(Backend { ctl: self })
    }
}

impl Backend<'_> {
    /// The atom of `symbol` (made when missing), or a fresh atom without a symbol.
    pub fn add_atom(&mut self, symbol: Option<&Symbol>) -> AtomId {
        let ctl = &mut *self.ctl;
        let Some(symbol) = symbol else {
            return ctl.new_atom(None);
        };
        if let Some(a) = ctl.lookup(symbol) {
            return a;
        }
        let id = symbol.intern_in(&mut ctl.syms);
        let a = ctl.new_atom(Some(id));
        if ctl.shows(symbol) {
            ctl.pending
                .outputs
                .push(Output::new(symbol.to_string(), vec![a as Lit]));
        }
        ctl.pending.num_atoms = ctl.atom_sym.len() as AtomId;
        a
    }

    /// `head :- body.` (a disjunction, a constraint when `head` is empty) or, with `choice`,
    /// `{head} :- body.`; body literals are atoms, negative for `not`.
    pub fn add_rule(&mut self, head: &[AtomId], body: &[Lit], choice: bool) -> Result<(), String> {
        let lits: Vec<Lit> = body.to_vec();
        self.check(head, lits.iter().copied())?;
        self.push_rule(head, choice, Body::Normal(lits));
        Ok(())
    }

    /// `head :- lower { w1: l1; ... }.` (choice head with `choice`).
    pub fn add_weight_rule(
        &mut self,
        head: &[AtomId],
        lower: Weight,
        body: &[(Lit, Weight)],
        choice: bool,
    ) -> Result<(), String> {
        self.check(head, body.iter().map(|&(l, _)| l))?;
        self.push_rule(
            head,
            choice,
            Body::Weight {
                lower,
                lits: body.to_vec(),
            },
        );
        Ok(())
    }

    /// `#minimize { w1@priority: l1; ... }.`
    pub fn add_minimize(&mut self, priority: Weight, lits: &[(Lit, Weight)]) -> Result<(), String> {
        self.check(&[], lits.iter().map(|&(l, _)| l))?;
        self.ctl.pending.minimize.push(Minimize {
            priority,
            lits: lits.to_vec(),
        });
        Ok(())
    }

    /// `#external a. [value]`: `atom` becomes external with `value` (an atom a rule defines or
    /// a solve call completed is left alone, as clingo does).
    pub fn add_external(&mut self, atom: AtomId, value: TruthValue) -> Result<(), String> {
        self.check(&[], std::iter::once(atom as Lit))?;
        let ctl = &mut *self.ctl;
        let defined = ctl.flags[atom as usize - 1] & DEFINED != 0;
        if defined || ctl.completed(atom) || ctl.released.contains(&atom) {
            return Ok(());
        }
        if ctl.externals.insert(atom, Some(value)).is_none() {
            ctl.new_externals.push(atom);
        }
        Ok(())
    }

    /// Literals assumed in every solve call from now on (aspif's assumptions).
    pub fn add_assume(&mut self, lits: &[Lit]) -> Result<(), String> {
        self.check(&[], lits.iter().copied())?;
        self.ctl.pending.assumptions.extend_from_slice(lits);
        Ok(())
    }

    /// `#project a.` for each of `atoms`: with projection on (`--project`), models are told
    /// apart by these atoms only and show only them, as a grounded `#project` does.
    pub fn add_project(&mut self, atoms: &[AtomId]) -> Result<(), String> {
        self.check(&[], atoms.iter().map(|&a| a as Lit))?;
        self.ctl.pending.projections.extend_from_slice(atoms);
        Ok(())
    }

    /// `#heuristic a : condition. [bias@priority, modifier]` (read under
    /// `--heuristic=domain`, as a grounded `#heuristic`).
    pub fn add_heuristic(
        &mut self,
        atom: AtomId,
        modifier: HeuristicModifier,
        bias: i32,
        priority: u32,
        condition: &[Lit],
    ) -> Result<(), String> {
        self.check(
            &[],
            std::iter::once(atom as Lit).chain(condition.iter().copied()),
        )?;
        self.ctl.pending.heuristics.push(Heuristic {
            modifier,
            atom,
            bias,
            priority,
            condition: condition.to_vec(),
        });
        Ok(())
    }

    /// `#edge (from, to) : condition.`: the edges whose conditions hold form no cycle
    /// (clingo's `add_acyc_edge`; nodes are numbers).
    pub fn add_acyc_edge(&mut self, from: i32, to: i32, condition: &[Lit]) -> Result<(), String> {
        self.check(&[], condition.iter().copied())?;
        self.ctl.pending.edges.push(Edge {
            from,
            to,
            condition: condition.to_vec(),
        });
        Ok(())
    }

    /// The atom of `symbol`, if there is one (as [`Control::lookup`]).
    pub(super) fn lookup(&self, symbol: &Symbol) -> Option<AtomId> {
        self.ctl.lookup(symbol)
    }

    fn check(&self, head: &[AtomId], lits: impl Iterator<Item = Lit>) -> Result<(), String> {
        let n = self.ctl.num_atoms();
        for &h in head {
            if h == 0 || h > n {
                return Err(format!("atom {h} does not exist (atoms are 1..={n})"));
            }
            if self.ctl.completed(h) {
                let name = self.ctl.symbol(h).map_or(h.to_string(), |s| s.to_string());
                return Err(format!("redefinition of atom <'{name}',{h}>"));
            }
        }
        for l in lits {
            let a = l.unsigned_abs();
            if a == 0 || a > n {
                return Err(format!("literal {l} names no atom (atoms are 1..={n})"));
            }
        }
        Ok(())
    }

    fn push_rule(&mut self, head: &[AtomId], choice: bool, body: Body) {
        let ctl = &mut *self.ctl;
        for &h in head {
            ctl.flags[h as usize - 1] |= DEFINED;
            // An external that gets a rule becomes an ordinary atom, as in a grounding.
            ctl.externals.remove(&h);
        }
        let head_kind = if choice {
            HeadKind::Choice
        } else {
            HeadKind::Disjunction
        };
        ctl.pending.rules.push(Rule {
            head_kind,
            head: head.to_vec(),
            body,
        });
        ctl.pending.num_atoms = ctl.atom_sym.len() as AtomId;
    }
}

impl Control {
    /// Whether an earlier solve call completed `atom` (it may get no rules any more).
    fn completed(&self, atom: AtomId) -> bool {
        let in_solver = self
            .solver
            .as_ref()
            .is_some_and(|s| atom <= s.program().num_atoms && !s.is_external(atom));
        in_solver || self.released.contains(&atom)
    }

    /// Whether an atom `symbol` added from code is shown: always without `#show p/n.` and
    /// `#show.`, else when a `#show` signature names it.
    fn shows(&self, symbol: &Symbol) -> bool {
        let mut restricted = false;
        for (_, st) in &self.globals {
            match &st.kind {
                StatementKind::Show(s) => match &**s {
                    ast::Show::Nothing => restricted = true,
                    ast::Show::Signature(sig) => {
                        restricted = true;
                        if sig.negated == symbol.is_negative()
                            && symbol.is(&sig.name, sig.arity as usize)
                        {
                            return true;
                        }
                    }
                    ast::Show::Term { .. } => {}
                },
                _ => continue,
            }
        }
        !restricted
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sorted_answers(ctl: &mut Control) -> Vec<String> {
        let mut out: Vec<String> = ctl
            .solve_all(&SolveOptions::default())
            .models
            .iter()
            .map(|m| {
                let mut s: Vec<String> = m.shown.iter().map(|s| s.to_string()).collect();
                s.sort();
                s.join(" ")
            })
            .collect();
        out.sort();
        out
    }

    fn all_models() -> Control {
        let mut config = ControlConfig::default();
        config.solve.models = 0;
        Control::new(config)
    }

    #[test]
    fn a_program_built_from_code_has_clingos_answers() {
        // The program of the Python test's backend script: {a; c(1)}. x :- a. :- not x, c(1).
        // clingo 5.8 (python3 -c 'import clingo' with the same backend calls) answers
        // {}, {a}, {a, c(1)}; x has no symbol and is not shown.
        let mut ctl = all_models();
        let mut b = ctl.backend().unwrap();
        let a = b.add_atom(Some(&Symbol::constant("a")));
        let c = b.add_atom(Some(&Symbol::function("c", vec![Symbol::number(1)])));
        let x = b.add_atom(None);
        assert_eq!((a, c, x), (1, 2, 3));
        assert_eq!(
            b.add_atom(Some(&Symbol::constant("a"))),
            a,
            "a symbol keeps its atom"
        );
        b.add_rule(&[a, c], &[], true).unwrap();
        b.add_rule(&[x], &[a as Lit], false).unwrap();
        b.add_rule(&[], &[-(x as Lit), c as Lit], false).unwrap();
        assert_eq!(sorted_answers(&mut ctl), ["", "a", "a c(1)"]);
        assert_eq!(ctl.lookup(&Symbol::parse("c(1)").unwrap()), Some(c));
    }

    #[test]
    fn atoms_from_code_join_a_grounded_program_and_respect_show() {
        // With `#show q/0.`, an atom added from code is not shown (clingo 5.8 does the same).
        let mut ctl = all_models();
        ctl.add("base", &[], "q. #show q/0.").unwrap();
        ctl.ground(&[Part::base()]).unwrap();
        let mut b = ctl.backend().unwrap();
        let a = b.add_atom(Some(&Symbol::constant("a")));
        assert_eq!(a, 2, "numbered after q");
        b.add_rule(&[a], &[], true).unwrap();
        let models = ctl.solve_all(&SolveOptions::default()).models;
        assert_eq!(models.len(), 2);
        assert!(models.iter().all(|m| m.shown == [Symbol::constant("q")]));
        assert!(models.iter().any(|m| m.contains(&Symbol::constant("a"))));
    }

    #[test]
    fn weight_rules_minimize_externals_and_assumptions() {
        let mut ctl = all_models();
        let mut b = ctl.backend().unwrap();
        let p: Vec<AtomId> = (1..=3)
            .map(|i| b.add_atom(Some(&Symbol::function("p", vec![Symbol::number(i)]))))
            .collect();
        let two = b.add_atom(Some(&Symbol::constant("two")));
        let e = b.add_atom(Some(&Symbol::constant("e")));
        b.add_rule(&p, &[], true).unwrap();
        // two :- 2 { p(1); p(2); p(3) }.  :- not two.
        let body: Vec<(Lit, Weight)> = p.iter().map(|&a| (a as Lit, 1)).collect();
        b.add_weight_rule(&[two], 2, &body, false).unwrap();
        b.add_rule(&[], &[-(two as Lit)], false).unwrap();
        b.add_external(e, TruthValue::False).unwrap();
        // p(3) only when e: :- p(3), not e.
        b.add_rule(&[], &[p[2] as Lit, -(e as Lit)], false).unwrap();
        // Subsets of {p(1), p(2), p(3)} with at least two, p(3) needs e (false): {p(1), p(2)}.
        assert_eq!(sorted_answers(&mut ctl), ["p(1) p(2) two"]);
        ctl.assign_external(&Symbol::constant("e"), TruthValue::True);
        assert_eq!(
            sorted_answers(&mut ctl).len(),
            4,
            "pairs and the triple, with e"
        );
        // Assume not p(1) for good: {p(2), p(3)}.
        let mut b = ctl.backend().unwrap();
        b.add_assume(&[-(p[0] as Lit)]).unwrap();
        assert_eq!(sorted_answers(&mut ctl), ["e p(2) p(3) two"]);
    }

    #[test]
    fn minimize_from_code_finds_the_optimum() {
        let mut ctl = Control::new(ControlConfig::default());
        let mut b = ctl.backend().unwrap();
        let a = b.add_atom(Some(&Symbol::constant("a")));
        let c = b.add_atom(Some(&Symbol::constant("c")));
        // {a; c}.  :- not a, not c.  #minimize { 3: a; 2: c }.
        b.add_rule(&[a, c], &[], true).unwrap();
        b.add_rule(&[], &[-(a as Lit), -(c as Lit)], false).unwrap();
        b.add_minimize(0, &[(a as Lit, 3), (c as Lit, 2)]).unwrap();
        ctl.solve_config_mut().models = 0;
        let models = ctl.solve_all(&SolveOptions::default()).models;
        let last = models.last().unwrap();
        assert_eq!(last.shown, [Symbol::constant("c")]);
        assert_eq!(last.costs, [2]);
    }

    /// Expected answers recorded from clingo 5.8.3's Python API with the same backend calls on
    /// an empty grounded `base` (`Control(["0", "--project"])`, `Control(["0"])`,
    /// `Control(["1", "--heuristic=Domain"])`; sorted shown symbols of every model).
    #[test]
    fn projections_edges_and_heuristics_from_code() {
        let sym = |s: &str| Symbol::parse(s).unwrap();
        // {p(1); p(2); c}. #project p(1). #project p(2).
        let projected = |args: &[&str]| {
            let mut ctl = Control::from_args(args).unwrap();
            let mut b = ctl.backend().unwrap();
            let atoms: Vec<AtomId> = ["p(1)", "p(2)", "c"]
                .iter()
                .map(|s| b.add_atom(Some(&sym(s))))
                .collect();
            b.add_rule(&atoms, &[], true).unwrap();
            b.add_project(&atoms[..2]).unwrap();
            sorted_answers(&mut ctl)
        };
        assert_eq!(
            projected(&["0", "--project"]),
            ["", "p(1)", "p(1) p(2)", "p(2)"]
        );
        assert_eq!(projected(&["0"]).len(), 8, "without --project every model");
        // {e(0); e(1); e(2)}. with the edges 1->2 if e(0), 2->3 if e(1), 3->1 if e(2).
        let mut ctl = all_models();
        let mut b = ctl.backend().unwrap();
        let e: Vec<AtomId> = (0..3)
            .map(|i| b.add_atom(Some(&Symbol::function("e", vec![Symbol::number(i)]))))
            .collect();
        b.add_rule(&e, &[], true).unwrap();
        for (i, &a) in e.iter().enumerate() {
            let i = i as i32;
            b.add_acyc_edge(i + 1, (i + 1) % 3 + 1, &[a as Lit])
                .unwrap();
        }
        let answers = sorted_answers(&mut ctl);
        assert_eq!(answers.len(), 7, "every subset but the cycle: {answers:?}");
        assert!(!answers.contains(&"e(0) e(1) e(2)".to_string()));
        // {a; b}. :- a, b. :- not a, not b. #heuristic X. [5@1, true], for X = a, then b.
        for (preferred, expected) in [("a", "a"), ("b", "b")] {
            let mut ctl = Control::from_args(&["1", "--heuristic=Domain"]).unwrap();
            let mut b = ctl.backend().unwrap();
            let (a, bb) = (b.add_atom(Some(&sym("a"))), b.add_atom(Some(&sym("b"))));
            b.add_rule(&[a, bb], &[], true).unwrap();
            b.add_rule(&[], &[a as Lit, bb as Lit], false).unwrap();
            b.add_rule(&[], &[-(a as Lit), -(bb as Lit)], false)
                .unwrap();
            let atom = if preferred == "a" { a } else { bb };
            b.add_heuristic(atom, HeuristicModifier::True, 5, 1, &[])
                .unwrap();
            assert_eq!(sorted_answers(&mut ctl), [expected]);
        }
        let mut ctl = all_models();
        let mut b = ctl.backend().unwrap();
        assert!(b.add_project(&[3]).is_err());
        assert!(b.add_acyc_edge(1, 2, &[-4]).is_err());
        assert!(b
            .add_heuristic(9, HeuristicModifier::Sign, 1, 0, &[])
            .is_err());
    }

    #[test]
    fn bad_statements_are_errors_not_panics() {
        let mut ctl = Control::new(ControlConfig::default());
        let mut b = ctl.backend().unwrap();
        let a = b.add_atom(Some(&Symbol::constant("a")));
        assert!(b.add_rule(&[a + 5], &[], false).is_err());
        assert!(b.add_rule(&[a], &[7], false).is_err());
        assert!(b.add_minimize(0, &[(0, 1)]).is_err());
        b.add_rule(&[a], &[], false).unwrap();
        ctl.solve_all(&SolveOptions::default());
        // `a` is complete after the solve call: a rule for it is clingo's redefinition error.
        let mut b = ctl.backend().unwrap();
        let e = b.add_rule(&[a], &[], true).unwrap_err();
        assert!(e.contains("redefinition of atom <'a',1>"), "{e}");
    }
}
