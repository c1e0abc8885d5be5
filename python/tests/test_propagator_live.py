"""Propagators over the live solver under clingo 5.8 and under ``import lucent as clingo``:
``add_literal`` during search and in ``init``, an assignment that shows what the propagator
just did, and the assignment's members (levels, decisions, trail, root level, sequence)
checked against each other; the answers and the checks' verdicts compared."""

from conftest import sorted_models


def p_lits(init):
    out = {}
    for atom in init.symbolic_atoms.by_signature("p", 1):
        out[atom.symbol.arguments[0].number] = init.solver_literal(atom.literal)
    return [out[k] for k in sorted(out)]


class NotAllThree:
    """When p(1) becomes true: a fresh literal y defined as p(1) & p(2) (three clauses, so no
    models are added) and the clause -y | -p(3). Every call makes its own y."""

    def __init__(self):
        self.made = 0

    def init(self, init):
        self.p = p_lits(init)
        init.add_watch(self.p[0])
        self.y = None

    def propagate(self, control, changes):
        if self.y is None:
            self.y = control.add_literal()
            self.made += 1
            self.fresh = control.assignment.value(self.y) is None and control.assignment.has_literal(self.y)
        y, (p1, p2, p3) = self.y, self.p
        for c in ([-y, p1], [-y, p2], [y, -p1, -p2], [-y, -p3]):
            if not control.add_clause(c) or not control.propagate():
                return


def not_all_three(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..3)}.")
    ctl.ground([("base", [])])
    prop = NotAllThree()
    ctl.register_propagator(prop)
    out = []
    for _ in range(2):
        models = []
        ctl.solve(on_model=lambda m: models.append(m.symbols(atoms=True)))
        out.append(sorted_models(models))
    return out, prop.made, prop.fresh


def test_add_literal_during_search(both):
    calls, made, fresh = both(not_all_three)
    assert [len(c) for c in calls] == [7, 7] and made == 2 and fresh


class SeesItsClauses:
    """When p(i) becomes true, adds -p(i) | -p(i+1) and propagates: afterwards p(i+1) must
    read false at once (a live assignment). The first time p(1) is true it also makes a
    literal x, defined as not p(1): x is free when made, false on the current level once the
    clause -p(1) | -x is propagated."""

    def init(self, init):
        self.p = p_lits(init)
        for lit in self.p:
            init.add_watch(lit)
        self.x = None
        self.fresh = []
        self.wrong = 0

    def propagate(self, control, changes):
        a = control.assignment
        for lit in changes:
            i = self.p.index(lit)
            if i == 0 and self.x is None:
                self.x = x = control.add_literal()
                self.fresh.append(a.is_free(x))
                if not control.add_clause([-lit, -x]) or not control.propagate():
                    return
                self.fresh.append(a.is_false(x) and a.level(x) == a.decision_level)
                if not control.add_clause([x, lit]):
                    return
            if i + 1 == len(self.p):
                continue
            nxt = self.p[i + 1]
            if not control.add_clause([-lit, -nxt]) or not control.propagate():
                return
            if not a.is_false(nxt) or a.value(nxt) is not False:
                self.wrong += 1


def sees_its_clauses(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..5)}.")
    ctl.ground([("base", [])])
    prop = SeesItsClauses()
    ctl.register_propagator(prop)
    models = []
    ctl.solve(on_model=lambda m: models.append(m.symbols(atoms=True)))
    return len(models), prop.fresh, prop.wrong


def test_the_assignment_is_live(both):
    # Subsets of five in a row with no two neighbours: Fibonacci, 13.
    assert both(sees_its_clauses) == (13, [True, True], 0)


class Inspector:
    """At every total assignment, reads every member of the assignment and records whether
    they agree with each other (the verdicts must be clingo's: all True)."""

    def init(self, init):
        self.p = p_lits(init)
        a = init.assignment
        self.verdicts = {
            "init_len": len(a) >= len(self.p),
            "init_free": all(a.is_free(lit) and not a.is_fixed(lit) for lit in self.p),
            "init_fact": a.is_true(init.solver_literal(init.symbolic_atoms[self.q].literal)),
        }
        self.bad = set()

    def check(self, control):
        a = control.assignment
        n = len(a)
        trail = list(a.trail)
        assigned = [v if a.is_true(v) else -v for v in range(1, n + 1) if a.value(v) is not None]
        checks = {
            "total": a.is_total,
            "no_conflict": not a.has_conflict,
            "sequence": list(a) == list(range(1, n + 1)) and a[0] == 1 and a[-1] == n,
            "has_literal": a.has_literal(n) and a.has_literal(-1) and not a.has_literal(n + 1)
            and not a.has_literal(0),
            "trail_is_assignment": sorted(trail) == sorted(assigned),
            "levels": all(a.trail.begin(lv) <= a.trail.end(lv) for lv in range(a.decision_level + 1)),
            "trail_levels": all(
                a.level(trail[i]) == lv
                for lv in range(a.decision_level + 1)
                for i in range(a.trail.begin(lv), a.trail.end(lv))
            ),
            # Level 0 included: clingo's decision(0) is its always-true literal 1.
            "decisions": all(
                a.is_true(a.decision(lv)) and a.level(a.decision(lv)) == lv
                for lv in range(0, a.decision_level + 1)
            ),
            "decision0": a.decision(0) == 1 and a.is_fixed(1),
            "root": 0 <= a.root_level <= a.decision_level,
            "values": all(
                (a.value(lit) is True) == a.is_true(lit) and (a.value(-lit) is True) == a.is_false(lit)
                for lit in self.p
            ),
            "fixed_level": all(a.is_fixed(lit) == (a.level(lit) == 0) for lit in self.p),
        }
        self.bad.update(k for k, ok in checks.items() if not ok)


def inspect(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..4)}. q. :- p(1), p(2), p(3).")
    ctl.ground([("base", [])])
    prop = Inspector()
    prop.q = clingo.Function("q")
    ctl.register_propagator(prop)
    models = []
    ctl.solve(on_model=lambda m: models.append(m.symbols(atoms=True)))
    return len(models), prop.verdicts, sorted(prop.bad)


def test_the_assignment_members_agree(both):
    n, verdicts, bad = both(inspect)
    assert n == 14 and all(verdicts.values()) and bad == []


class FixedByInit:
    """``init`` adds a literal x, the clauses x and -x | -p(1), and reads back what they did:
    add_clause answers True, x is fixed true, p(1) fixed false."""

    def init(self, init):
        p = p_lits(init)
        x = init.add_literal()
        self.ok = [init.add_clause([x]), init.add_clause([-x, -p[0]])]
        a = init.assignment
        self.ok.append(a.has_literal(x))


def fixed_by_init(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..2)}.")
    ctl.ground([("base", [])])
    prop = FixedByInit()
    ctl.register_propagator(prop)
    models = []
    ctl.solve(on_model=lambda m: models.append(m.symbols(atoms=True)))
    return sorted_models(models), prop.ok


def test_add_literal_in_init(both):
    models, ok = both(fixed_by_init)
    assert models == [[], ["p(2)"]] and ok == [True, True, True]
