"""Grounding context functions (``ground(parts, context=obj)``: ``@f(...)`` calls ``obj.f``),
``solve(on_core=...)`` and ``Control(arguments)``: each script runs under clingo 5.8 and under
``import lucent as clingo`` with equal answers."""

import pytest
from conftest import modules, sorted_models


def make_context(clingo):
    class Context:
        calls = 0

        def inc(self, x):
            Context.calls += 1
            return clingo.Number(x.number + 1)

        def both(self, x):
            return [clingo.Number(x.number), clingo.Number(x.number * 10)]

        def up(self, s):
            return clingo.String(s.string.upper())

        def pair(self, a, b):
            return clingo.Tuple_([b, a])

        def none(self, x):
            return []

        def seq(self, n):
            return (clingo.Number(i) for i in range(n.number))

    return Context()


def context_functions(clingo):
    """@f in heads, bodies, comparisons, nested, lists, strings, tuples, generators."""
    out = []
    for program in [
        "p(1..3). q(@inc(X)) :- p(X).",
        "p(1..2). q(@both(X)) :- p(X). r(Y) :- p(X), Y = @both(X), Y > 5.",
        "#const k = @inc(2). #const m = @inc(k). p(1..k). q(m).",
        'q(@up("ab")). r(@up(S)) :- S = ("x";"yz").',
        "p(1). q(X) :- p(X), r(@inc(X)). r(2). s :- p(X), @inc(X) > 1.",
        "q(X) :- X = @inc(@inc(1)). r(@pair(1, a)). s(@none(1)). t.",
        "q(@seq(3)).",
        "p(1..2). { q(@inc(X)) : p(X) } = 2. s(N) :- N = #sum{ @inc(X) : p(X) }.",
    ]:
        ctl = clingo.Control(["0"])
        ctl.add("base", [], program)
        ctl.ground([("base", [])], context=make_context(clingo))
        models = []
        ctl.solve(on_model=lambda m: models.append(m.symbols(atoms=True)))
        out.append((program, sorted_models(models)))
    return out


def context_functions_in_steps(clingo):
    """The incremental loop with a context: each step's part calls @inc(t)."""
    ctl = clingo.Control()
    ctl.add("base", [], "at(0).")
    ctl.add("step", ["t"], "at(@inc(t)) :- at(t). #external stop(t). :- stop(t), at(@inc(t)).")
    ctx = make_context(clingo)
    ctl.ground([("base", [])], context=ctx)
    trace = []
    for t in range(4):
        ctl.ground([("step", [clingo.Number(t)])], context=ctx)
        if t > 0:
            ctl.assign_external(clingo.Function("stop", [clingo.Number(t - 1)]), False)
        ctl.assign_external(clingo.Function("stop", [clingo.Number(t)]), t == 2)
        models = []
        result = ctl.solve(on_model=lambda m: models.append(m.symbols(atoms=True)))
        trace.append((t, str(result), sorted_models(models)))
    return trace


def context_errors(clingo):
    """An unknown function raises the context's AttributeError; a function's own exception
    is raised again by ground."""

    class Failing:
        def boom(self, x):
            raise ValueError(f"boom {x}")

    out = []
    for program in ["q(@nope(1)).", "q(@boom(1))."]:
        ctl = clingo.Control()
        ctl.add("base", [], program)
        try:
            ctl.ground([("base", [])], context=Failing())
            out.append("grounded")
        except Exception as e:  # noqa: BLE001 - the type is the answer
            out.append((type(e).__name__, str(e)))
    return out


def unsat_core(clingo):
    """on_core receives the program literals of the failed assumptions (here every core is
    forced: each assumption alone is consistent, and the program refutes exactly these)."""
    out = []
    for program, assumptions in [
        ("{a; b; c}. :- a, b.", [("a", True), ("b", True)]),
        ("{a; b; c}. :- a.", [("a", True)]),
        ("{a; b}. :- not a, not b.", [("a", False), ("b", False)]),
        ("{a; b}.", [("a", True)]),
    ]:
        ctl = clingo.Control()
        ctl.add("base", [], program)
        ctl.ground([("base", [])])
        names = {a.literal: str(a.symbol) for a in ctl.symbolic_atoms}
        cores = []
        result = ctl.solve(
            assumptions=[(clingo.Function(n), v) for n, v in assumptions],
            on_core=lambda c: cores.append(sorted(("" if l > 0 else "-") + names[abs(l)] for l in c)),
        )
        out.append((program, str(result), cores))
    return out


def control_arguments(clingo):
    """clingo's options read by Control(arguments): models, constants, projection, threads,
    the optimization mode and the domain heuristic."""
    plain = "#const k = 1. {p(1..k)}. {q}. #show p/1."
    optimize = "{p(1..3)}. :- not p(1), not p(2). #minimize {1, X : p(X)}."
    domain = "{p(1..3)}. #heuristic p(X) : X < 3. [1, true]"
    out = []
    for args, program in [
        (["-n", "0"], plain),
        (["--models=1"], plain),
        (["0", "-c", "k=3"], plain),
        (["0", "--const", "k=2"], plain),
        (["0", "-c", "k=2", "--project"], plain),
        (["0", "--project=show", "-c", "k=2"], plain),
        (["0", "-t", "2"], plain),
        (["0", "--parallel-mode=2,compete"], plain),
        (["--opt-mode=optN", "0"], optimize),
        (["--opt-mode", "enum", "0"], optimize),
        (["--heuristic=Domain", "1"], domain),
    ]:
        ctl = clingo.Control(args)
        ctl.add("base", [], program)
        ctl.ground([("base", [])])
        models = []
        ctl.solve(on_model=lambda m: models.append((m.symbols(shown=True), m.cost)))
        if "--opt-mode=optN" in args:
            # Improving models differ between solvers, and the optimum found by the search is
            # reported again with the others: the set of optimal models is compared.
            best = min(c for _, c in models)
            unique = {tuple(sorted(map(str, m))): (m, c) for m, c in models if c == best}
            models = list(unique.values())
        if len(models) > 1 or "1" not in args:
            models.sort(key=lambda mc: (sorted(map(str, mc[0])), mc[1]))
        out.append((args, [(sorted(map(str, m)), c) for m, c in models]))
    return out


def test_context_functions(both):
    both(context_functions)


def test_context_functions_in_steps(both):
    both(context_functions_in_steps)


def test_context_errors(both):
    clingo, lucent = modules()
    expected = context_errors(clingo)
    got = context_errors(lucent)
    # clingo's AttributeError text names the context's class, as Python words it; lucent
    # raises the same exception object.
    assert got == expected


def test_unsat_core(both):
    both(unsat_core)


def test_control_arguments(both):
    both(control_arguments)


def test_context_function_calls_are_cached_per_grounding():
    """lucent calls each distinct @f(args) once per grounding (clingo may call more often):
    here @inc(1..3) for q and again for r, three calls."""
    _, lucent = modules()
    ctx = make_context(lucent)
    type(ctx).calls = 0
    ctl = lucent.Control()
    ctl.add("base", [], "p(1..3). q(@inc(X)) :- p(X). r(@inc(X)) :- p(X).")
    ctl.ground([("base", [])], context=ctx)
    assert type(ctx).calls == 3


def test_without_context_calls_are_errors():
    _, lucent = modules()
    ctl = lucent.Control()
    ctl.add("base", [], "q(@inc(1)).")
    with pytest.raises(RuntimeError, match="without a grounding context"):
        ctl.ground([("base", [])])
