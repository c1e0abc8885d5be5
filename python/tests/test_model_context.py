"""``Model.thread_id`` and ``Model.context`` (clingo's ``SolveControl``) under clingo 5.8 and
under ``import lucent as clingo``: the thread of each model, the call's symbolic atoms, and
clauses and nogoods added from ``on_model`` that hold for the rest of the call only."""


def threads(clingo):
    out = []
    for args in (["0"], ["0", "-t", "2"]):
        ctl = clingo.Control(args)
        ctl.add("base", [], "{p(1..5)}.")
        ctl.ground([("base", [])])
        ids = []
        ctl.solve(on_model=lambda m: ids.append(m.thread_id))
        out.append((len(ids), all(0 <= t < 2 for t in ids), args == ["0"] and set(ids) == {0}))
    return out


def test_thread_id(both):
    assert both(threads) == [(32, True, True), (32, True, False)]


def atoms_in_context(clingo):
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..3)}. f. #external e. q :- p(1), e.")
    ctl.ground([("base", [])])
    f, e, p1 = clingo.Function("f"), clingo.Function("e"), clingo.Function("p", [clingo.Number(1)])
    lit = ctl.symbolic_atoms[p1].literal
    seen = []

    def on_model(m):
        atoms = m.context.symbolic_atoms
        seen.append((
            sorted(str(a.symbol) for a in atoms),
            atoms[f].is_fact, atoms[e].is_external, atoms[p1].literal == lit,
            atoms[clingo.Function("nothing")] is None, clingo.Function("q") in atoms,
            sorted(str(a.symbol) for a in atoms.by_signature("p", 1)),
        ))
        return False

    ctl.solve(on_model=on_model)
    return seen


def test_symbolic_atoms_in_context(both):
    assert len(both(atoms_in_context)) == 1


def first_then_clause(clingo, add, handle=False):
    """Every model of {p(1..3)}; after the first one ``add(m.context, ...)`` runs. Returns the
    later models' atoms and the next call's model count."""
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..3)}.")
    ctl.ground([("base", [])])
    lits = {a.symbol.arguments[0].number: a.literal for a in ctl.symbolic_atoms.by_signature("p", 1)}
    models = []

    def on_model(m):
        if not models:
            add(clingo, m.context, lits)
        models.append(sorted(str(s) for s in m.symbols(atoms=True)))

    if handle:
        with ctl.solve(yield_=True) as h:
            for m in h:
                on_model(m)
    else:
        ctl.solve(on_model=on_model)
    after = []
    ctl.solve(on_model=lambda m: after.append(m))
    return models[1:], len(models), len(after)


def p(clingo, i):
    return clingo.Function("p", [clingo.Number(i)])


def clause_symbol(clingo, ctx, lits):
    ctx.add_clause([(p(clingo, 1), True)])


def clause_literal(clingo, ctx, lits):
    ctx.add_clause([lits[1]])


def nogood(clingo, ctx, lits):
    ctx.add_nogood([(p(clingo, 2), True)])


def unknown_atoms(clingo, ctx, lits):
    # An atom that does not exist is false: (nothing, True) leaves the clause, so it is p(3);
    # (nothing, False) is true: the clause is satisfied and adds nothing.
    ctx.add_clause([(clingo.Function("nothing"), True), (p(clingo, 3), True)])
    ctx.add_clause([(clingo.Function("nothing"), False), (p(clingo, 1), False)])


def later(clingo, add, atom, holds, handle=False):
    rest, n, after = first_then_clause(clingo, add, handle)
    # The first model may or may not satisfy the clause already: 4 or 5 models in all.
    return all((atom in m) == holds for m in rest), n in (4, 5), after


def test_add_clause_by_symbol(both):
    ok, n, after = both(lambda c: later(c, clause_symbol, "p(1)", True))
    assert ok and n and after == 8


def test_add_clause_by_literal(both):
    ok, n, after = both(lambda c: later(c, clause_literal, "p(1)", True))
    assert ok and n and after == 8


def test_add_nogood(both):
    ok, n, after = both(lambda c: later(c, nogood, "p(2)", False))
    assert ok and n and after == 8


def test_unknown_atoms_in_clauses(both):
    ok, n, after = both(lambda c: later(c, unknown_atoms, "p(3)", True))
    assert ok and n and after == 8


def test_add_clause_in_a_handle(both):
    ok, n, after = both(lambda c: later(c, clause_symbol, "p(1)", True, handle=True))
    assert ok and n and after == 8
