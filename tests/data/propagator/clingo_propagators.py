"""The propagators of tests/control/propagator.rs under clingo 5.8's Python API.

Run: python3 tests/data/propagator/clingo_propagators.py (needs `pip install clingo`).
Prints one line per scenario, `name<TAB>answer`, answers in the form the Rust test builds:
sorted answer sets, each a sorted list of quoted atoms (Rust's `{:?}` of Vec<Vec<String>>).
"""

import sys

try:
    import clingo
except ImportError:
    sys.exit("clingo 5.8 is needed: python3 -m pip install clingo")


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


def sets(ctl, assumptions=()):
    out = []
    ctl.solve(assumptions=list(assumptions), on_model=lambda m: out.append(sorted(str(s) for s in m.symbols(shown=True))))
    return fmt(out)


def fmt(models):
    models = sorted(sorted(m) for m in models)
    return "[" + ", ".join("[" + ", ".join('"%s"' % a for a in m) + "]" for m in models) + "]"


def line(name, answer):
    print(name + "\t" + answer)


# (a) every answer set of {p(1..6)}. without two consecutive atoms.
for threads in (1, 2):
    ctl = clingo.Control(["0", "-t", str(threads)])
    ctl.add("base", [], "{p(1..6)}.")
    ctl.ground([("base", [])])
    ctl.register_propagator(NoConsecutive())
    line("consecutive-t%d" % threads, sets(ctl))

# (b) check only: answer sets of {p(1..4)}. with an even number of atoms.
ctl = clingo.Control(["0"])
ctl.add("base", [], "{p(1..4)}. q :- p(1), p(4).")
ctl.ground([("base", [])])
ctl.register_propagator(EvenOnly())
line("even", sets(ctl))

# (c) multi-shot with assumptions: one more p atom per step.
ctl = clingo.Control(["0"])
ctl.add("base", [], "{p(1..2)}.")
ctl.add("step", ["k"], "{p(k+2)}. r(k) :- p(k+2), not p(k).")
ctl.ground([("base", [])])
ctl.register_propagator(NoConsecutive())
p2 = clingo.Function("p", [clingo.Number(2)])
for k in range(1, 5):
    ctl.ground([("step", [clingo.Number(k)])])
    line("step%d" % k, sets(ctl))
    line("step%d-p2" % k, sets(ctl, [(p2, True)]))
    line("step%d-not-p2" % k, sets(ctl, [(p2, False)]))

# (d) optimization: the largest sum of non-consecutive indices.
ctl = clingo.Control([])
ctl.add("base", [], "{p(1..7)}. #maximize{ I : p(I) }.")
ctl.ground([("base", [])])
ctl.register_propagator(NoConsecutive())
best = []
ctl.solve(on_model=lambda m: best.append((list(m.cost), sorted(str(s) for s in m.symbols(shown=True)))))
line("optimum", "%s %s" % (best[-1][0], fmt([best[-1][1]])))


class WeightTie:
    """In init: q tied to `p(1) + p(2) + p(3) >= 2` (type -1, 0 or 1, `==` or not)."""

    def __init__(self, kind, equal):
        self.kind, self.equal = kind, equal

    def init(self, init):
        ps = [init.solver_literal(a.literal) for a in init.symbolic_atoms.by_signature("p", 1)]
        q = init.solver_literal(init.symbolic_atoms[clingo.Function("q")].literal)
        init.add_weight_constraint(q, [(l, 1) for l in ps], 2, self.kind, self.equal)


# (e) weight constraints added in init, every type, with and without compare_equal.
for kind in (-1, 0, 1):
    for equal in (False, True):
        ctl = clingo.Control(["0"])
        ctl.add("base", [], "{p(1..3)}. {q}.")
        ctl.ground([("base", [])])
        ctl.register_propagator(WeightTie(kind, equal))
        line("weight%d-%s" % (kind, "eq" if equal else "ge"), sets(ctl))
