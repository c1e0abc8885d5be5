#!/usr/bin/env python3
"""Times `lucent explain G.lp --why reach(0,T)` against solving G.lp alone and against xclingo
explaining the same atom, on random directed graphs with three out-edges per node (issue 32).

The program is reachability from one source node, kept binary so the atom reads `reach(0,T)`:

    reach(X,Y) :- source(X), edge(X,Y).
    reach(X,Z) :- reach(X,Y), edge(Y,Z).

One source, not all pairs: the question is about one path, and the all-pairs closure at n=1000
is about 10^6 atoms and 3*10^6 ground rules, which neither explainer needs to answer it (xclingo
translates every traced rule instance into its explainer program, so all pairs would time it
on a closure the question does not ask about). T is the target of the longest shortest path
from node 0 (breadth-first search here, ties to the smallest node), so the proof has to run
the whole depth of the graph.

Per size and run, in one process and interleaved: `lucent G.lp` (ground and solve, first
model), `lucent explain G.lp --why reach(0,T)` (ground with provenance, solve, least proof,
`tree::recheck`; the answer must say `reach(0,T) holds.` and name the path's edges), and
`xclingo -n 1 1 X.lp` over the same program with xclingo's annotations (`%!trace_rule` on
both rules, `%!trace` on edges, `%!show_trace` on the one atom); its answer must name the
atom. Prints medians and the ratios explain/solve and lucent/xclingo, with the load average.

Usage: scripts/bench_why_reach.py [LUCENT_BINARY] [RUNS] (default: $CARGO_TARGET_DIR or target,
release/lucent; 5 runs). Needs `pip install xclingo` (2.0b24 was measured). xclingo is run once
per size when its first run takes over 30 s, and stopped after $XCLINGO_LIMIT s (default 1800).
"""

import collections
import os
import random
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

SIZES = [(100, 11), (300, 12), (1000, 13)]
OUT_EDGES = 3
# xclingo is run once per size when its first run takes longer than SLOW seconds, and stopped
# after XCLINGO_LIMIT seconds (then reported as more than the limit).
SLOW = 30.0
XCLINGO_LIMIT = float(os.environ.get("XCLINGO_LIMIT", "1800"))

RULES = """source(0).
reach(X,Y) :- source(X), edge(X,Y).
reach(X,Z) :- reach(X,Y), edge(Y,Z).
"""

XRULES = """source(0).
%!trace_rule {"% reaches % directly", X, Y}.
reach(X,Y) :- source(X), edge(X,Y).
%!trace_rule {"% reaches % through %", X, Z, Y}.
reach(X,Z) :- reach(X,Y), edge(Y,Z).
%!trace {edge(X,Y), "edge % -> %", X, Y}.
"""


def graph(n, seed):
    """Each node 0..n-1 gets three distinct random successors other than itself."""
    rng = random.Random(seed)
    edges = []
    for v in range(n):
        for w in rng.sample([u for u in range(n) if u != v], OUT_EDGES):
            edges.append((v, w))
    return edges


def farthest(n, edges):
    """The target of the longest shortest path from 0 (smallest node among ties) and its
    distance."""
    succ = collections.defaultdict(list)
    for a, b in edges:
        succ[a].append(b)
    dist = {0: 0}
    queue = collections.deque([0])
    while queue:
        v = queue.popleft()
        for w in succ[v]:
            if w not in dist:
                dist[w] = dist[v] + 1
                queue.append(w)
    # Node 0 itself is reached again only through a cycle; the target is another node.
    d = max(dist[v] for v in dist if v != 0)
    return min(v for v in dist if v != 0 and dist[v] == d), d


def check_proof(text, t, d):
    """The proof's edge steps (`  edge(a,b): static ...`) hold a path from 0 to t of d edges:
    the least proof of reach(0,t) follows a shortest path."""
    succ = collections.defaultdict(set)
    for line in text.splitlines():
        m = re.match(r"\s*edge\((\d+),(\d+)\): ", line)
        if m:
            succ[int(m.group(1))].add(int(m.group(2)))
    frontier, steps = {0}, 0
    while t not in frontier and frontier and steps <= d:
        frontier = {w for v in frontier for w in succ[v]}
        steps += 1
    if t not in frontier or steps != d:
        sys.exit(f"the proof of reach(0,{t}) does not follow a path of {d} edges:\n{text[:3000]}")


def timed(cmd, limit=None):
    t = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=limit)
    return time.perf_counter() - t, p


def fmt(v):
    return " ".join(f"{x:.3f}" for x in v)


def main():
    target = os.environ.get("CARGO_TARGET_DIR", "target")
    lucent = sys.argv[1] if len(sys.argv) > 1 else os.path.join(target, "release", "lucent")
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    xclingo = shutil.which("xclingo")
    if xclingo is None:
        sys.exit("xclingo not found: pip install xclingo")
    tmp = tempfile.mkdtemp()
    print(f"load average before: {os.getloadavg()}")
    print(f"lucent {lucent}; xclingo {xclingo}; {runs} runs per size, medians")
    print()
    print("| n | edges | depth | atom | solve s | --why s | xclingo s "
          "| why/solve | lucent/xclingo |")
    print("|---|---|---|---|---|---|---|---|---|")
    for n, seed in SIZES:
        edges = graph(n, seed)
        t, d = farthest(n, edges)
        atom = f"reach(0,{t})"
        facts = "".join(f"edge({a},{b}).\n" for a, b in edges)
        plain = os.path.join(tmp, f"reach{n}.lp")
        with open(plain, "w") as f:
            f.write(RULES + facts)
        annotated = os.path.join(tmp, f"xreach{n}.lp")
        with open(annotated, "w") as f:
            f.write(XRULES + f"%!show_trace {{reach(0,{t})}}.\n" + facts)
        solve, why, xcl = [], [], []
        for _ in range(runs):
            s, p = timed([lucent, plain])
            if p.returncode not in (10, 30):
                sys.exit(f"lucent {plain}: exit {p.returncode}\n{p.stderr}")
            solve.append(s)
            w, p = timed([lucent, "explain", plain, "--why", atom])
            if p.returncode != 0 or not p.stdout.startswith(f"{atom} holds."):
                sys.exit(f"lucent explain --why {atom}: exit {p.returncode}\n"
                         f"{p.stdout[:2000]}\n{p.stderr}")
            check_proof(p.stdout, t, d)
            why.append(w)
            if xcl and (xcl[0] > SLOW or xcl[0] == float("inf")):
                continue
            try:
                x, p = timed([xclingo, "-n", "1", "1", annotated], XCLINGO_LIMIT)
            except subprocess.TimeoutExpired:
                xcl.append(float("inf"))
                continue
            if p.returncode != 0 or f"0 reaches {t} " not in p.stdout:
                sys.exit(f"xclingo: exit {p.returncode}\n{p.stdout[:2000]}\n{p.stderr}")
            xcl.append(x)
        ms, mw, mx = (statistics.median(v) for v in (solve, why, xcl))
        if mx == float("inf"):
            xs, ratio = f"> {XCLINGO_LIMIT:.0f}", f"< {mw / XCLINGO_LIMIT:.5f}"
        else:
            xs, ratio = f"{mx:.3f} ({len(xcl)} runs)", f"{mw / mx:.5f}"
        print(f"| {n} | {len(edges)} | {d} | {atom} | {ms:.3f} | {mw:.3f} | {xs} "
              f"| {mw / ms:.2f} | {ratio} |", flush=True)
        print(f"   solve runs {fmt(solve)}; --why runs {fmt(why)}", flush=True)
    print()
    print(f"load average after: {os.getloadavg()}")
    shutil.rmtree(tmp)


if __name__ == "__main__":
    main()
