#!/usr/bin/env python3
"""Times `lucent explain G.lp --why-unsat --assume edge/2` on generated unsatisfiable
3-colourings (a sparse random graph with a planted 4-clique) against the same question answered
with clingo's Python API the way clingo-explaid does it (the edge facts become assumptions, one
solve gives a core, deletion-based minimisation shrinks it), run in this script, and prints the
ratio. clingo-explaid itself is not installable here (`pip install clingo-explaid` finds no
distribution), so its algorithm is re-done over clingo 5.8 (`pip install clingo`).

Usage: scripts/bench_why_unsat.py [LUCENT_BINARY] (default: $CARGO_TARGET_DIR or target,
release/lucent). Both sides must name the same set (the clique's edges), which is checked.
"""

import os
import random
import subprocess
import sys
import tempfile
import time

import clingo
import json

ENCODING = """
col(red;green;blue).
1 { color(X,C) : col(C) } 1 :- node(X).
:- edge(X,Y), color(X,C), color(Y,C).
"""


def graph(n, m, seed):
    """A random graph on nodes 5..n with m edges (3-colourable: planted colours), a 4-clique on
    nodes 1-4 and one edge (4,5) between them: every unsatisfiable subset of the edges contains
    the clique (without one of its edges, the clique takes 3 colours and the rest's colours can
    be permuted to fit the one link), so the minimal set is unique."""
    rng = random.Random(seed)
    colour = {v: rng.randrange(3) for v in range(5, n + 1)}
    edges = set()
    while len(edges) < m:
        a, b = rng.randrange(5, n + 1), rng.randrange(5, n + 1)
        if a < b and colour[a] != colour[b]:
            edges.add((a, b))
    clique = [(a, b) for a in range(1, 5) for b in range(a + 1, 5)]
    edges |= set(clique) | {(4, 5)}
    return sorted(edges), clique


def program(n, edges):
    lines = [f"node(1..{n})."]
    lines += [f"edge({a},{b})." for a, b in edges]
    return "\n".join(lines) + ENCODING


def clingo_muc(n, edges):
    """clingo-explaid's MUC: edge facts as assumptions, a core, deletion."""
    ctl = clingo.Control(["--warn=none"])
    ctl.add("base", [], f"node(1..{n}).\n" + "".join(f"{{edge({a},{b})}}.\n" for a, b in edges) + ENCODING)
    ctl.ground([("base", [])])
    lit = {}
    for a, b in edges:
        sym = clingo.Function("edge", [clingo.Number(a), clingo.Number(b)])
        lit[(a, b)] = ctl.symbolic_atoms[sym].literal

    def refute(on):
        on_set = set(on)
        assumptions = [lit[e] if e in on_set else -lit[e] for e in edges]
        core = []
        result = ctl.solve(assumptions=assumptions, on_core=lambda c: core.extend(c))
        if result.satisfiable:
            return None
        used = set(core)
        return [e for e in on if lit[e] in used]

    core = refute(edges)
    for e in list(core):
        if e not in core:
            continue
        smaller = refute([x for x in core if x != e])
        if smaller is not None:
            core = smaller
    return sorted(core)


def timed(f, repeat=3):
    """The least wall time of `repeat` runs of f, and f's last result."""
    best, result = None, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        result = f()
        t = time.perf_counter() - t0
        best = t if best is None else min(best, t)
    return best, result


def main():
    if len(sys.argv) > 2 and sys.argv[1] == "--muc":
        # The clingo side as a process of its own, as clingo-explaid is run: N and edges.
        n, edges = json.loads(open(sys.argv[2]).read())
        print(json.dumps(clingo_muc(n, [tuple(e) for e in edges])))
        return
    target = os.environ.get("CARGO_TARGET_DIR", "target")
    lucent = sys.argv[1] if len(sys.argv) > 1 else os.path.join(target, "release", "lucent")
    print(f"clingo {clingo.__version__}; lucent {lucent}; least of 3 runs each")
    print("| nodes | edges | lucent s | clingo MUC in-process s | ratio | clingo MUC as a process s | ratio | same set |")
    print("|---|---|---|---|---|---|---|---|")
    for n, m, seed in [(12, 10, 1), (100, 150, 2), (300, 450, 3), (1000, 1500, 4), (3000, 4500, 5)]:
        edges, clique = graph(n, m, seed)
        with tempfile.NamedTemporaryFile("w", suffix=".lp", delete=False) as f:
            f.write(program(n, edges))
            path = f.name
        with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as f:
            f.write(json.dumps([n, edges]))
            data = f.name
        ours, out = timed(
            lambda: subprocess.run(
                [lucent, "explain", path, "--why-unsat", "--assume", "edge/2", "--outf=2"],
                capture_output=True,
                text=True,
            )
        )
        got = json.loads(out.stdout)["literals"]
        inproc, ref = timed(lambda: clingo_muc(n, edges))
        proc, _ = timed(
            lambda: subprocess.run(
                [sys.executable, __file__, "--muc", data], capture_output=True, text=True
            )
        )
        os.unlink(path)
        os.unlink(data)
        same = sorted(got) == sorted(f"edge({a},{b})" for a, b in ref)
        print(
            f"| {n} | {len(edges)} | {ours:.3f} | {inproc:.3f} | {ours / inproc:.2f} "
            f"| {proc:.3f} | {ours / proc:.2f} | {same} |"
        )


if __name__ == "__main__":
    main()
