"""``Control.solve(yield_=True)`` / ``async_=True`` handles under clingo 5.8 and under
``import lucent as clingo``: lazy iteration (2^40 answer sets, three read), ``model`` /
``resume`` / ``get`` / ``wait`` / ``cancel`` in clingo's order, ``async_`` with ``on_model``,
and ``Control.interrupt`` from another thread. The Rust side is tests/control/handle.rs."""

import threading

from conftest import sorted_models


def three_of_two_to_the_forty(clingo):
    """Reads three models of 2^40 and leaves the ``with`` block: the search stops there (a
    lucent that enumerated first would not return). Then the Control solves again."""
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..40)}.")
    ctl.ground([("base", [])])
    numbers = []
    with ctl.solve(yield_=True) as h:
        for m in h:
            numbers.append(m.number)
            if len(numbers) == 3:
                break
        h.cancel()
        r = h.get()
        first = (str(r), r.interrupted, r.exhausted)
    enumerated = ctl.statistics["summary"]["models"]["enumerated"]
    ctl.configuration.solve.models = 4
    again = []
    r = ctl.solve(on_model=lambda m: again.append(m.number))
    return numbers, first, enumerated, again, str(r)


def handle_protocol(clingo):
    """clingo's order of results: ``model`` twice is one model, ``resume`` moves on, ``get``
    with a model current is SAT so far, iteration after ``get`` skips the current model."""
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{a; b}. :- a, b.")
    ctl.ground([("base", [])])
    trace = []
    with ctl.solve(yield_=True) as h:
        m1 = h.model()
        m2 = h.model()
        trace.append(("same", m1.number == m2.number, str(m1) == str(m2)))
        h.resume()
        m3 = h.model()
        trace.append(("resumed", m3.number))
        trace.append(("get", str(h.get()), h.model().number, h.wait(0)))
        rest = [m.number for m in h]
        trace.append(("rest", rest, str(h.get()), h.get().exhausted, h.model()))
    seen = []
    with ctl.solve(yield_=True, on_model=lambda m: seen.append(sorted(map(str, m.symbols(atoms=True))))) as h:
        trace.append(("get first", str(h.get())))
        trace.append(("iterated", len(list(h))))
    trace.append(("on_model", sorted(seen)))
    with ctl.solve(yield_=True) as h:
        h.cancel()
        trace.append(("cancelled at once", str(h.get()), h.model()))
    return trace


def async_on_model(clingo):
    """``async_`` without ``yield_``: ``on_model`` sees every model, ``wait`` answers, ``get``
    gives the final result; ``on_finish`` once."""
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{a; b; c}. :- a, not b.")
    ctl.ground([("base", [])])
    models, finished = [], []
    with ctl.solve(on_model=lambda m: models.append(m.symbols(atoms=True)),
                   on_finish=lambda r: finished.append(str(r)), async_=True) as h:
        done = h.wait(30)
        r = h.get()
    return done, str(r), r.exhausted, sorted_models(models), finished


def async_yield_unsat(clingo):
    """``async_`` and ``yield_`` on a program without answer sets, under assumptions: no
    model, UNSAT, ``on_core`` with the failed assumption's literal."""
    ctl = clingo.Control()
    ctl.add("base", [], "{a; b}. :- a, b.")
    ctl.ground([("base", [])])
    a = ctl.symbolic_atoms[clingo.Function("a")].literal
    b = ctl.symbolic_atoms[clingo.Function("b")].literal
    cores = []
    with ctl.solve(assumptions=[a, b], yield_=True, async_=True, on_core=cores.append) as h:
        models = list(h)
        r = h.get()
    return models, str(r), r.exhausted, [sorted(c) == sorted([a, b]) for c in cores]


def interrupted_from_another_thread(clingo):
    """``Control.interrupt`` from a timer thread stops a background search with no model in
    sight (11 pigeons, 10 holes); the result is unknown and interrupted."""
    ctl = clingo.Control()
    ctl.add("base", [], "p(1..11). h(1..10). 1 { in(P, H) : h(H) } 1 :- p(P). "
                        ":- in(P, H), in(Q, H), P < Q.")
    ctl.ground([("base", [])])
    with ctl.solve(async_=True) as h:
        early = h.wait(0.05)
        timer = threading.Timer(0.05, ctl.interrupt)
        timer.start()
        r = h.get()
        timer.join()
    return early, str(r), r.interrupted


def test_three_of_two_to_the_forty(both):
    numbers, first, enumerated, again, r = both(three_of_two_to_the_forty)
    assert numbers == [1, 2, 3] and enumerated == 3 and first == ("SAT", True, False)
    assert (again, r) == ([1, 2, 3, 4], "SAT")


def test_handle_protocol(both):
    both(handle_protocol)


def test_async_on_model(both):
    done, r, exhausted, models, finished = both(async_on_model)
    assert done and r == "SAT" and exhausted and len(models) == 6 and finished == ["SAT"]


def test_async_yield_unsat(both):
    both(async_yield_unsat)


def test_interrupt_from_another_thread(both):
    early, r, interrupted = both(interrupted_from_another_thread)
    assert (early, r, interrupted) == (False, "UNKNOWN", True)


def propagator_in_a_handle(clingo):
    """A Python propagator runs on the search thread of a handle (it takes the GIL the
    waiting reader released): the answers of ``NoConsecutive`` from test_propagator.py."""
    from test_propagator import NoConsecutive

    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{p(1..5)}.")
    ctl.ground([("base", [])])
    ctl.register_propagator(NoConsecutive())
    with ctl.solve(yield_=True, async_=True) as h:
        return sorted_models(m.symbols(atoms=True) for m in h)


def test_propagator_in_a_handle(both):
    models = both(propagator_in_a_handle)
    # Subsets of 1..5 without two consecutive numbers: Fibonacci(7) = 13.
    assert len(models) == 13


def user_statistics(clingo):
    """``on_statistics(step, accu)``: figures the user adds, per call and accumulated, shown
    as ``statistics["user_step"]`` / ``["user_accu"]`` (numbers as floats), also for a
    handle."""
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{a; b}.")
    ctl.ground([("base", [])])

    def count(step, accu):
        step["mine"] = 1
        accu["total"] = accu["total"] + 1 if "total" in accu else 1

    seen = []
    for _ in range(2):
        ctl.solve(on_statistics=count)
        seen.append((ctl.statistics["user_step"], ctl.statistics["user_accu"]))
    with ctl.solve(yield_=True, on_statistics=count) as h:
        list(h)
    seen.append(ctl.statistics["user_accu"])
    return seen


def test_user_statistics(both):
    seen = both(user_statistics)
    assert seen[-1] == {"total": 3.0}
