"""``Control.solve(on_unsat=...)`` under clingo 5.8 and under ``import lucent as clingo``:
core-guided optimization (``--opt-strategy=usc``) reports each lower bound a core proves,
the optima of the priority levels done first; branch and bound (the default) reports none.
The cores are each solver's own, so the properties of the sequence are compared, not the
sequence (clingo 5.8 reports [1], ..., [6] on the cover below)."""

COVER = """node(1..8). edge(X,Y) :- node(X), node(Y), X<Y, (X+Y)\\3 != 0.
{in(X)} :- node(X). :- edge(X,Y), not in(X), not in(Y)."""

ONE = "#minimize{1,X:in(X)}."
TWO = "#minimize{1@2,X:in(X), X < 5}. #minimize{1@1,X:in(X), X >= 5}."


def bounds(clingo, args, program, handle=False):
    """The bounds reported and the optimum's costs."""
    ctl = clingo.Control(args)
    ctl.add("base", [], program)
    ctl.ground([("base", [])])
    told, costs = [], []
    if handle:
        with ctl.solve(on_unsat=lambda b: told.append(list(b)), yield_=True) as h:
            for m in h:
                costs.append(list(m.cost))
    else:
        ctl.solve(on_model=lambda m: costs.append(list(m.cost)), on_unsat=lambda b: told.append(list(b)))
    return told, costs[-1] if costs else None


def shape(told, best):
    """What both solvers must agree on: any bound told, rising, never above the optimum, the
    levels done at their optima, the last bound of the last level."""
    return {
        "told": bool(told),
        "rising": all(a < b for a, b in zip(told, told[1:])),
        "sound": all(b <= best[: len(b)] for b in told),
        "levels_done_at_optimum": all(b[:-1] == best[: len(b) - 1] for b in told),
        "ends_at_optimum": bool(told) and told[-1] == best,
        "best": best,
    }


def one_level(clingo):
    return shape(*bounds(clingo, ["--opt-strategy=usc"], COVER + ONE))


def two_levels(clingo):
    out = shape(*bounds(clingo, ["--opt-strategy=usc"], COVER + TWO))
    del out["ends_at_optimum"]  # clingo 5.8 stops at [2, 3] below the model's [2, 4]
    return out


def in_a_handle(clingo):
    return shape(*bounds(clingo, ["--opt-strategy=usc"], COVER + ONE, handle=True))


def nothing_told(clingo):
    return [
        bounds(clingo, [], COVER + ONE)[0],
        bounds(clingo, ["--opt-strategy=usc"], COVER)[0],
        bounds(clingo, ["--opt-strategy=usc"], COVER + ONE + ":- node(1).")[0],
    ]


def test_core_guided_bounds(both):
    got = both(one_level)
    assert got["told"] and got["rising"] and got["ends_at_optimum"] and got["best"] == [6]


def test_core_guided_bounds_per_level(both):
    got = both(two_levels)
    assert got["told"] and got["rising"] and got["sound"] and got["levels_done_at_optimum"]


def test_core_guided_bounds_in_a_handle(both):
    assert both(in_a_handle)["ends_at_optimum"]


def test_branch_and_bound_tells_nothing(both):
    assert both(nothing_told) == [[], [], []]
