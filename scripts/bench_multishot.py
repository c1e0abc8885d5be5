#!/usr/bin/env python3
"""The grid step loop of benches/multishot.rs against clingo 5.8's Python API, in one run.

Lucent: the bench binary with LUCENT_MULTISHOT_ONLY=grid (clingo's incmode loop on one
Control: `base` and `check(0)`, then per step t `query(t-1)` released, `step(t)` and `check(t)`
grounded, `query(t)` true, one model), which writes its program (grid_program) to a file and
prints the ground and solve time of every part. clingo: the same loop over that file in
Python, timed the same way (`Control.ground` and `Control.solve` around each call). Prints, for
parts 1-W and the last W parts, both systems' mean ground times and the ratios last/first, and
the slowest solve of each. The parts of this program grow (the cells reachable in t moves, and so
the `at`/`visited` rules of step t, grow until about step 40), so the script also counts the
ground rules of every part (clingo's, through a `clingo.Observer`: rules and weight rules of each
`ground` call) and prints the ground time per rule, last/first: the measure of a grounder that
keeps its indexes between parts, where the part sizes differ.

usage: scripts/bench_multishot.py [--bench PATH] [--parts 150] [--size 10] [--window 10]
       scripts/bench_multishot.py --counts N    (clingo's model count at each step 0..N)
PATH: the multishot bench binary (target/release/deps/multishot-*, built by
`cargo bench --no-default-features --bench multishot --no-run`).
"""
import argparse
import glob
import os
import re
import subprocess
import sys
import tempfile
import time

import clingo


def step(ctl, t):
    """Grounds the parts of step t and makes query(t) true; returns the ground time."""
    query = lambda k: clingo.Function("query", [clingo.Number(k)])
    start = time.perf_counter()
    if t == 0:
        ctl.ground([("base", []), ("check", [clingo.Number(0)])])
    else:
        ctl.release_external(query(t - 1))
        start = time.perf_counter()
        ctl.ground([("step", [clingo.Number(t)]), ("check", [clingo.Number(t)])])
    g = time.perf_counter() - start
    ctl.assign_external(query(t), True)
    return g


class RuleCount:
    """clingo observer counting the ground rules (normal, choice, weight) output so far."""

    def __init__(self):
        self.rules = 0

    def rule(self, choice, head, body):
        self.rules += 1

    def weight_rule(self, choice, head, lower_bound, body):
        self.rules += 1


def clingo_loop(path, parts):
    """clingo's loop; rows (t, ground ms, solve ms, outcome, ground rules of part t)."""
    ctl = clingo.Control(["--warn=none"])
    count = RuleCount()
    ctl.register_observer(count)
    ctl.load(path)
    out = []
    for t in range(parts + 1):
        before = count.rules
        g = step(ctl, t)
        start = time.perf_counter()
        r = ctl.solve()
        s = time.perf_counter() - start
        out.append((t, g * 1e3, s * 1e3, "SAT" if r.satisfiable else "UNSAT",
                    count.rules - before))
    return out


def lucent_loop(binary, path, parts, size):
    env = dict(os.environ, LUCENT_MULTISHOT_ONLY="grid", LUCENT_MULTISHOT_GRID=str(parts),
               LUCENT_MULTISHOT_GRID_SIZE=str(size), LUCENT_MULTISHOT_GRID_TRACE="1",
               LUCENT_MULTISHOT_GRID_OUT=path)
    text = subprocess.run([binary, "--bench"], env=env, check=True, capture_output=True,
                          text=True).stdout
    pat = re.compile(r"grid part (\d+): ground ([\d.]+) ms, solve ([\d.]+) ms, (\w+)")
    return [(int(m[1]), float(m[2]), float(m[3]), m[4]) for m in pat.finditer(text)]


def summary(name, rows, w):
    parts = [r for r in rows if r[0] > 0]
    first = sum(r[1] for r in parts[:w]) / w
    last = sum(r[1] for r in parts[-w:]) / w
    slow = max(parts, key=lambda r: r[2])
    print(f"{name:7s} ground parts 1-{w}: {first:.3f} ms, last {w}: {last:.3f} ms, "
          f"last/first {last / first:.2f}; solve {sum(r[2] for r in parts):.1f} ms in all, "
          f"slowest {slow[2]:.2f} ms (part {slow[0]})")
    return first, last


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bench")
    ap.add_argument("--parts", type=int, default=150)
    ap.add_argument("--size", type=int, default=10)
    ap.add_argument("--window", type=int, default=10)
    ap.add_argument("--counts", type=int)
    ap.add_argument("--program", help="with --counts: the program (else the bench writes it)")
    a = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    binary = a.bench or max(
        (p for p in glob.glob(os.path.join(os.environ.get("CARGO_TARGET_DIR", os.path.join(
            root, "target")), "release", "deps", "multishot-*")) if os.access(p, os.X_OK)
         and not p.endswith(".d")), key=os.path.getmtime, default=None)
    with tempfile.TemporaryDirectory() as tmp:
        path = a.program or os.path.join(tmp, "grid.lp")
        if a.counts is not None:
            if not a.program:
                lucent_loop(binary, path, 1, a.size)
            ctl = clingo.Control(["0", "--warn=none"])
            ctl.load(path)
            for t in range(a.counts + 1):
                step(ctl, t)
                with ctl.solve(yield_=True) as h:
                    print(t, sum(1 for _ in h))
            return
        if binary is None:
            sys.exit("no bench binary: cargo bench --no-default-features --bench multishot --no-run")
        ours = lucent_loop(binary, path, a.parts, a.size)
        theirs = clingo_loop(path, a.parts)
    disagree = [r[0] for r, s in zip(ours, theirs) if r[3] != s[3]]
    if disagree:
        print("outcomes differ at parts", disagree)
    print(f"grid {a.size}x{a.size}, {a.parts} step parts, window {a.window}")
    lf, ll = summary("lucent", ours, a.window)
    cf, cl = summary("clingo", theirs, a.window)
    parts = [r for r in theirs if r[0] > 0]
    rf = sum(r[4] for r in parts[:a.window]) / a.window
    rl = sum(r[4] for r in parts[-a.window:]) / a.window
    print(f"ground rules per part (clingo's count): parts 1-{a.window} {rf:.1f}, last "
          f"{a.window} {rl:.1f}, last/first {rl / rf:.2f}; ground time per rule, last/first: "
          f"lucent {(ll / rl) / (lf / rf):.2f}, clingo {(cl / rl) / (cf / rf):.2f}")
    print(f"lucent/clingo ground time: parts 1-{a.window} {lf / cf:.2f}, last {a.window} "
          f"{ll / cl:.2f}; solve in all {sum(r[2] for r in ours) / sum(r[2] for r in theirs):.2f}")


if __name__ == "__main__":
    main()
