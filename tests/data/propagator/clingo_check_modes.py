"""clingo 5.8's answers for tests/control/propagator_modes.rs: a propagator checking at
every fixpoint and reading the decisions (AtMostTwo). Prints
`key<TAB>answers` lines (models sorted, each sorted)."""
import clingo


class AtMostTwo:
    """check_mode Fixpoint: more than two true p atoms are refuted as soon as propagation is
    quiet; records whether some check saw a partial assignment."""

    def init(self, init):
        init.check_mode = clingo.PropagatorCheckMode.Fixpoint
        self.lits = [init.solver_literal(a.literal) for a in init.symbolic_atoms.by_signature("p", 1)]
        self.partial = False

    def check(self, ctl):
        a = ctl.assignment
        if not a.is_total:
            self.partial = True
        for level in range(1, a.decision_level + 1):
            d = a.decision(level)
            assert a.is_true(d) and a.level(d) == level
        true = [l for l in self.lits if a.is_true(l)]
        if len(true) > 2:
            ctl.add_clause([-l for l in true[:3]])


def answers(program, propagator, steps=1):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], program)
    ctl.ground([("base", [])])
    ctl.register_propagator(propagator)
    out = []
    for _ in range(steps):
        models = []
        ctl.solve(on_model=lambda m: models.append(" ".join(sorted(map(str, m.symbols(atoms=True))))))
        out.append(";".join(sorted(models)))
    return "|".join(out)


p = AtMostTwo()
print("at_most_two\t" + answers("{p(1..5)}.", p))
assert p.partial
