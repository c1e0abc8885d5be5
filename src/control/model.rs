//! Models as the robot layers read them: shown symbols, the whole answer set as [`Symbol`]s,
//! membership by symbol or atom, costs, applied CR rules and supporting rules; [`OwnedModel`]
//! keeps one after its solve call.
//!
//! Invariants: a [`Model`] borrows the Control's atom tables for the duration of the callback,
//! so reading it never copies the program. Supporting rules are computed on the first read
//! that needs them ([`Model::supports`], [`Model::raw`], [`Model::to_owned_model`]), once per
//! model: most callers only read atoms.

use super::*;

/// The atom tables a model reads its symbols from.
#[derive(Clone, Copy)]
pub(super) struct Names<'a> {
    pub(super) syms: &'a Symbols,
    pub(super) atom_sym: &'a [Option<SymId>],
    pub(super) sym_atom: &'a [AtomId],
}

/// One answer set, as the callback of [`Control::solve`] sees it.
pub struct Model<'a> {
    pub(super) raw: &'a solve::Model,
    pub(super) names: Names<'a>,
    /// The program `raw` is a model of, when `raw` came without the supports the solver
    /// configuration asks for (`Solver::for_each_model_lazy`); `None` when `raw` is complete.
    pub(super) lazy_support: Option<&'a GroundProgram>,
    /// `raw` with its supports, once something asked for them.
    pub(super) full: OnceCell<solve::Model>,
}

impl Model<'_> {
    /// The model's number in its call (1-based).
    pub fn number(&self) -> usize {
        self.raw.number
    }

    /// The shown symbols (`#show`), in clingo's order (by predicate domain, then atom; the
    /// `#show` terms after the atoms: `Output::order`), without duplicates. Each prints as it was
    /// shown ([`Symbol::from_shown`]: a name made by a context function need not be an
    /// identifier).
    pub fn symbols(&self) -> Vec<Symbol> {
        self.raw
            .symbols
            .iter()
            .map(|s| Symbol::from_shown(s))
            .collect()
    }

    /// The portfolio thread that found the model (clingo's `Model.thread_id`; 0 with one
    /// thread).
    pub fn thread_id(&self) -> u32 {
        self.raw.thread_id
    }

    /// The true atoms' numbers, increasing (every true atom, with a symbol or not).
    pub fn atom_ids(&self) -> &[AtomId] {
        &self.raw.atoms
    }

    /// The shown symbols (`#show`) as clingo prints them, in output order: what
    /// [`Model::symbols`] parses.
    pub fn shown_text(&self) -> &[String] {
        &self.raw.symbols
    }

    /// Every true atom with a symbol: the whole answer set (shown or not), in atom order (sort
    /// by [`Control::atom_order`] for clingo's order, as the Python `Model.symbols` does).
    pub fn atoms(&self) -> Vec<Symbol> {
        // Sized once: nearly every true atom has a symbol.
        let mut out = Vec::with_capacity(self.raw.atoms.len());
        for &a in &self.raw.atoms {
            if let Some(&Some(s)) = self.names.atom_sym.get(a as usize - 1) {
                out.push(Symbol::from_table(self.names.syms, s));
            }
        }
        out
    }

    /// The true atoms whose symbol is a positive function `name/arity`, in atom order: what
    /// [`Model::atoms`] would give, filtered, without building the other symbols.
    pub fn atoms_named(&self, name: &str, arity: usize) -> Vec<Symbol> {
        let mut out = Vec::new();
        for &a in &self.raw.atoms {
            if let Some(&Some(s)) = self.names.atom_sym.get(a as usize - 1) {
                if let crate::ground::symbol::SymData::Fun {
                    name: n,
                    neg: false,
                    len,
                    ..
                } = self.names.syms.get(s)
                {
                    if len as usize == arity && self.names.syms.names.resolve(n) == name {
                        out.push(Symbol::from_table(self.names.syms, s));
                    }
                }
            }
        }
        out
    }

    /// Whether the atom of `symbol` is true.
    pub fn contains(&self, symbol: &Symbol) -> bool {
        let Some(id) = symbol.find_in(self.names.syms) else {
            return false;
        };
        match self.names.sym_atom.get(id.0 as usize) {
            Some(&a) if a != 0 => self.raw.holds(a),
            _ => false,
        }
    }

    /// Whether atom `atom` is true.
    pub fn holds(&self, atom: AtomId) -> bool {
        self.raw.holds(atom)
    }

    /// The costs, one per priority level, highest first (empty without optimization).
    pub fn costs(&self) -> &[i64] {
        &self.raw.costs
    }

    /// True when the model is known to be optimal.
    pub fn optimal(&self) -> bool {
        self.raw.optimal
    }

    /// The labels of the applied consistency-restoring rules.
    pub fn cr_applied(&self) -> Vec<Symbol> {
        self.raw
            .cr_applied
            .iter()
            .map(|l| Symbol::from_cr_label(l))
            .collect()
    }

    /// For every true atom, the index of one rule of [`Control::program`] that supports it
    /// (`None` for externals and assumptions without a rule).
    pub fn supports(&self) -> impl Iterator<Item = (AtomId, Option<usize>)> + '_ {
        let raw = self.raw();
        raw.atoms.iter().copied().zip(raw.support.iter().copied())
    }

    /// The solver's form of the model (true atoms as numbers, shown symbols as text), with
    /// its supports when the solver configuration asks for them (computed on the first call).
    pub fn raw(&self) -> &solve::Model {
        match self.lazy_support {
            None => self.raw,
            Some(prog) => self.full.get_or_init(|| {
                let mut m = self.raw.clone();
                m.support = solve::solver::supports(prog, &m.atoms);
                m
            }),
        }
    }

    /// An owned copy, with the whole answer set as symbols.
    pub fn to_owned_model(&self) -> OwnedModel {
        let mut atoms = self.atoms();
        atoms.sort();
        OwnedModel {
            number: self.number(),
            shown: self.symbols(),
            atoms,
            costs: self.raw.costs.clone(),
            cr_applied: self.cr_applied(),
            optimal: self.raw.optimal,
            raw: self.raw().clone(),
        }
    }
}

/// A model kept after its solve call (see [`Control::solve_all`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OwnedModel {
    /// Its number in its call.
    pub number: usize,
    /// The shown symbols.
    pub shown: Vec<Symbol>,
    /// Every true atom with a symbol, in clingo's order.
    pub atoms: Vec<Symbol>,
    /// The costs, highest priority first.
    pub costs: Vec<i64>,
    /// The labels of the applied CR rules.
    pub cr_applied: Vec<Symbol>,
    /// True when known to be optimal.
    pub optimal: bool,
    /// The solver's form.
    pub raw: solve::Model,
}

impl OwnedModel {
    /// Whether `symbol` is a true atom.
    pub fn contains(&self, symbol: &Symbol) -> bool {
        self.atoms.binary_search(symbol).is_ok()
    }
}

impl Control {
    /// Per atom (`[a - 1]`), whether it is a fact; and the atoms that are (still) externals,
    /// increasing: what [`SymbolicAtom`]'s `fact` and `external` say, without building symbols
    /// (a model callback's view of the atoms, `python/src/solve_control.rs`).
    pub fn atom_kinds(&self) -> (Vec<bool>, Vec<AtomId>) {
        let facts = self.flags.iter().map(|f| f & FACT != 0).collect();
        let mut externals: Vec<AtomId> = self.externals.keys().copied().collect();
        externals.sort_unstable();
        (facts, externals)
    }
}
