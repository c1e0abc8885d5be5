"""``Control.register_propagator`` under clingo 5.8 and under ``import lucent as clingo``:
the same propagators (clingo's protocol: init, propagate, undo, check), the same answers."""

from conftest import sorted_models


class NoConsecutive:
    """Forbids p(i) and p(i+1) together: when p(i) becomes true, adds -p(i) | -p(i+1)."""

    def init(self, init):
        self.lit = {}
        for atom in init.symbolic_atoms.by_signature("p", 1):
            lit = init.solver_literal(atom.literal)
            self.lit[atom.symbol.arguments[0].number] = lit
            init.add_watch(lit)

    def propagate(self, control, changes):
        for l in changes:
            for i, li in self.lit.items():
                if li != l:
                    continue
                for j in (i - 1, i + 1):
                    if j in self.lit:
                        if not control.add_clause([-li, -self.lit[j]]) or not control.propagate():
                            return


class EvenOnly:
    """Checks total assignments only: an odd number of true p atoms is refuted."""

    def init(self, init):
        self.lits = [init.solver_literal(a.literal) for a in init.symbolic_atoms.by_signature("p", 1)]

    def check(self, control):
        a = control.assignment
        true = [l for l in self.lits if a.is_true(l)]
        if len(true) % 2 == 1:
            control.add_clause([-l if a.is_true(l) else l for l in self.lits])


class Counter:
    """Counts true watched p atoms through propagate and undo; check compares."""

    def init(self, init):
        self.lits = [init.solver_literal(a.literal) for a in init.symbolic_atoms.by_signature("p", 1)]
        for l in self.lits:
            init.add_watch(l)
        self.count = [0] * init.number_of_threads
        self.errors = 0

    def propagate(self, control, changes):
        self.count[control.thread_id] += len(changes)

    def undo(self, thread_id, assignment, changes):
        self.count[thread_id] -= len(changes)

    def check(self, control):
        a = control.assignment
        if self.count[control.thread_id] != sum(1 for l in self.lits if a.is_true(l)):
            self.errors += 1


def consecutive(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..6)}.")
    ctl.ground([("base", [])])
    ctl.register_propagator(NoConsecutive())
    models = []
    ctl.solve(on_model=lambda m: models.append(m.symbols(shown=True)))
    return sorted_models(models)


def even(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..4)}. q :- p(1), p(4).")
    ctl.ground([("base", [])])
    ctl.register_propagator(EvenOnly())
    models = []
    ctl.solve(on_model=lambda m: models.append(m.symbols(shown=True)))
    return sorted_models(models)


def steps(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..2)}.")
    ctl.add("step", ["k"], "{p(k+2)}. r(k) :- p(k+2), not p(k).")
    ctl.ground([("base", [])])
    ctl.register_propagator(NoConsecutive())
    p2 = clingo.Function("p", [clingo.Number(2)])
    out = []
    for k in range(1, 4):
        ctl.ground([("step", [clingo.Number(k)])])
        for assumptions in ([], [(p2, True)], [(p2, False)]):
            models = []
            ctl.solve(assumptions=assumptions, on_model=lambda m: models.append(m.symbols(shown=True)))
            out.append(sorted_models(models))
    return out


def optimum(clingo):
    ctl = clingo.Control([])
    ctl.add("base", [], "{p(1..7)}. #maximize{ I : p(I) }.")
    ctl.ground([("base", [])])
    ctl.register_propagator(NoConsecutive())
    best = []
    ctl.solve(on_model=lambda m: best.append((list(m.cost), sorted(str(s) for s in m.symbols(shown=True)))))
    return best[-1]


def counting(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..5)}. :- p(1), not p(2).")
    ctl.ground([("base", [])])
    counter = Counter()
    ctl.register_propagator(counter)
    models = []
    ctl.solve(on_model=lambda m: models.append(m.symbols(shown=True)))
    return len(models), counter.errors


def test_consecutive(both):
    assert len(both(consecutive)) == 21


def test_check_only(both):
    both(even)


def test_steps_and_assumptions(both):
    both(steps)


def test_optimum(both):
    assert both(optimum)[0] == [-16]


def test_undo_keeps_counts(both):
    # 2^5 subsets minus the 8 with p(1) but not p(2).
    assert both(counting) == (24, 0)


class AtMostTwo:
    """check_mode Fixpoint: more than two true p atoms are refuted as soon as propagation is
    quiet; every decision is true (tests/data/propagator/clingo_check_modes.py in Rust)."""

    def __init__(self, clingo):
        self.mode = clingo.PropagatorCheckMode.Fixpoint
        self.partial = False

    def init(self, init):
        init.check_mode = self.mode
        self.lits = [init.solver_literal(a.literal) for a in init.symbolic_atoms.by_signature("p", 1)]

    def check(self, control):
        a = control.assignment
        if not a.is_total:
            self.partial = True
        for level in range(1, a.decision_level + 1):
            assert a.is_true(a.decision(level))
        true = [l for l in self.lits if a.is_true(l)]
        if len(true) > 2:
            control.add_clause([-l for l in true[:3]])


def at_most_two(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..5)}.")
    ctl.ground([("base", [])])
    p = AtMostTwo(clingo)
    ctl.register_propagator(p)
    models = []
    ctl.solve(on_model=lambda m: models.append(m.symbols(atoms=True)))
    return sorted_models(models), p.partial


def test_fixpoint_check_mode(both):
    models, partial = both(at_most_two)
    # Subsets of five atoms with at most two: 1 + 5 + 10.
    assert len(models) == 16 and partial
