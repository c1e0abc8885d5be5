"""Theory atoms (``Control.theory_atoms``, ``PropagateInit.theory_atoms``) under clingo 5.8 and
under ``import lucent as clingo``: the same atoms, terms and guards, and a propagator that reads
its constraints from theory atoms gives the same answers."""

from conftest import sorted_models

THEORY = """
#theory t {
    term { + : 1, binary, left; * : 2, binary, left; - : 3, unary };
    &sum/0 : term, {<=, =, >=}, term, any;
    &forbid/1 : term, directive
}.
"""

ATOMS = THEORY + """
item(1..3).
{ take(X) : item(X) }.
&sum { W*2, X : take(X), item(X), W = X } <= 4 :- take(1).
&sum { (1,2); [3]; {4}; f(a, -1) } = 1+2*3.
&forbid(pair) { take(1); take(2) }.
"""


def describe(term):
    """A term as nested plain data, independent of the module."""
    return (term.type.name, str(term), [describe(a) for a in term.arguments])


def atoms_script(clingo):
    ctl = clingo.Control()
    ctl.add("base", [], ATOMS)
    ctl.ground([("base", [])])
    out = []
    for atom in ctl.theory_atoms:
        guard = None if atom.guard is None else (atom.guard[0], describe(atom.guard[1]))
        elements = sorted(
            (str(e), [describe(t) for t in e.terms], len(e.condition)) for e in atom.elements
        )
        out.append((str(atom), describe(atom.term), elements, guard, atom.literal != 0))
    return sorted(out)


def test_theory_atoms_agree(both):
    atoms = both(atoms_script)
    assert len(atoms) == 3


FORBID = THEORY + """
p(1..4).
{ q(X) : p(X) }.
&forbid(a) { q(1); q(2) }.
&forbid(b) { q(2); q(3); q(4) }.
"""


class Forbid:
    """Each ``&forbid`` directive: its elements' atoms are never all true (one clause each)."""

    def init(self, init):
        for atom in init.theory_atoms:
            if atom.term.name != "forbid":
                continue
            lits = []
            for element in atom.elements:
                (term,) = element.terms
                symbol = self.clingo.parse_term(str(term))
                found = init.symbolic_atoms[symbol]
                if found is not None:
                    lits.append(-init.solver_literal(found.literal))
            init.add_clause(lits)


def forbid_script(clingo):
    ctl = clingo.Control(["0"])
    propagator = Forbid()
    propagator.clingo = clingo
    ctl.register_propagator(propagator)
    ctl.add("base", [], FORBID)
    ctl.ground([("base", [])])
    models = []
    ctl.solve(on_model=lambda m: models.append(m.symbols(shown=True)))
    return sorted_models(models)


def test_a_propagator_reads_its_constraints_from_theory_atoms(both):
    models = both(forbid_script)
    # 16 subsets of q(1..4), minus those with q(1), q(2) (4) and with q(2), q(3), q(4) (2),
    # one subset counted in both: 16 - 4 - 2 + 1.
    assert len(models) == 11


CONDITIONS = """#theory c { term { }; &a/0 : term, any }.
{p(1..3)}. {q}. &a { x : p(1), p(2); y : p(3); z : q, not p(1); w }."""


class ConditionLiterals:
    """Each element's ``solver_literal(condition_id)`` is watched and checked against its
    condition at every total assignment; the clause ``-x | -p(3)`` over x's condition literal
    forbids p(1), p(2), p(3) together. clingo 5.8 hands the theory atoms to the first call's
    ``init`` only (its clause stays); Lucent to every call's."""

    def __init__(self):
        self.wrong, self.ids = 0, None

    def init(self, init):
        self.defs = []
        first = self.ids is None
        self.ids = self.ids or []
        p3 = init.solver_literal(init.symbolic_atoms[self.p3].literal)
        for atom in init.theory_atoms:
            for e in atom.elements:
                cid = e.condition_id
                if first:
                    self.ids.append((str(e.terms[0]), cid == 0, len(e.condition) == 1 and cid == e.condition[0],
                                     cid > 2**28))
                if cid == 0:
                    continue
                lit = init.solver_literal(cid)
                body = [init.solver_literal(l) for l in e.condition]
                init.add_watch(lit)
                self.defs.append((lit, body))
                if str(e.terms[0]) == "x":
                    init.add_clause([-lit, -p3])

    def check(self, control):
        a = control.assignment
        for lit, body in self.defs:
            if a.is_true(lit) != all(a.is_true(b) for b in body):
                self.wrong += 1


def condition_literals(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], CONDITIONS)
    ctl.ground([("base", [])])
    # Keyed by the term: Lucent prints the condition "z: not p(1),q", clingo "z: q,not p(1)".
    ids = [(str(e.terms[0]), e.condition_id > 2**28) for a in ctl.theory_atoms for e in a.elements]
    prop = ConditionLiterals()
    prop.p3 = clingo.Function("p", [clingo.Number(3)])
    ctl.register_propagator(prop)
    out = []
    for _ in range(2):
        models = []
        ctl.solve(on_model=lambda m: models.append(m.symbols(shown=True)))
        out.append(sorted_models(models))
    return out, sorted(prop.ids), sorted(ids), prop.wrong


def test_condition_ids_name_conjunctions(both):
    calls, init_ids, ids, wrong = both(condition_literals)
    assert [len(c) for c in calls] == [14, 14] and wrong == 0
    assert [i for (_, _, _, i) in init_ids].count(True) == 2
