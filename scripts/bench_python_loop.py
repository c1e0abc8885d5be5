#!/usr/bin/env python3
"""The tiny add-ground-solve loop from Python (issue 33 item 2): clingo 5.8's Python API
against `import lucent as clingo`, run in the same process, ratios printed.

  fresh:  N times: a new Control, add a small program, ground, solve (models read)
  one:    one Control with a part step(i) added once, N times: ground step(i), solve (one
          model) under an assumption

Usage: python3 scripts/bench_python_loop.py [N] (default 1000; needs `pip install .` and
clingo 5.8). Both loops check that the two modules counted the same models.
"""

import sys
import time

PROGRAM = "item(1..3). { pick(X) : item(X) } 2. :- pick(1), pick(3). ok :- pick(2)."
STEP = "#external e(i). { p(i); q(i) }. :- p(i), q(i), not e(i). r(i) :- p(i)."


def fresh(clingo, n):
    models = 0
    for _ in range(n):
        ctl = clingo.Control(["0"])
        ctl.add("base", [], PROGRAM)
        ctl.ground([("base", [])])
        count = []
        ctl.solve(on_model=lambda m: count.append(len(m.symbols(shown=True))))
        models += len(count)
    return models


def one(clingo, n):
    # One model per call: the step parts multiply the answer sets by 3 each.
    ctl = clingo.Control(["1"])
    ctl.add("base", [], PROGRAM)
    # Added once: adding the text again at every step would ground every copy (both modules).
    ctl.add("step", ["i"], STEP)
    ctl.ground([("base", [])])
    models = 0
    for i in range(1, n + 1):
        ctl.ground([("step", [clingo.Number(i)])])
        r = clingo.Function("r", [clingo.Number(i)])
        count = []
        ctl.solve(assumptions=[(r, True)], on_model=lambda m: count.append(1))
        models += len(count)
    return models


def timed(f, module, n, repeat=3):
    best, result = None, None
    for _ in range(repeat):
        t = time.perf_counter()
        result = f(module, n)
        dt = time.perf_counter() - t
        best = dt if best is None or dt < best else best
    return best, result


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    import clingo
    import lucent

    print(f"clingo {clingo.__version__}, lucent {lucent.__version__} API; N = {n}; best of 3")
    print(f"{'loop':8} {'clingo s':>10} {'lucent s':>10} {'clingo/lucent':>14}  models")
    for name, f in (("fresh", fresh), ("one", one)):
        tc, mc = timed(f, clingo, n)
        tl, ml = timed(f, lucent, n)
        if mc != ml:
            raise SystemExit(f"{name}: clingo counted {mc} models, lucent {ml}")
        print(f"{name:8} {tc:10.3f} {tl:10.3f} {tc / tl:14.1f}  {ml}")


if __name__ == "__main__":
    main()
