#!/usr/bin/env python3
"""Optimization benchmark: clingo and Lucent, each with branch and bound (bb, the default) and
core-guided optimization (--opt-strategy=usc), on the rows in benches/data/opt/ (written by
scripts/gen_opt_bench.py from fixed seeds), in one run.

  scripts/bench_opt.py [--lucent target/release/lucent] [--timeout 60] [--reps 1] [--rows RE]

End to end: `clingo -q FILE` against `lucent -q FILE`. Solver only: gringo's aspif
(`gringo --output=intermediate`, made once per row) to `clasp -q` against
`lucent --mode=clasp -q` (Lucent reads aspif), as scripts/bench_solve.sh compares solvers.
Times are CPU seconds of the child process (user + system, from the kernel's rusage: steadier
than wall time on a loaded machine), the minimum over --reps runs, floored at 10 ms in ratios.
Each binary runs once untimed before the table (warm-up). Every run must prove the same
optimum as clingo's bb run, or the row is marked. Ratios printed: Lucent bb / clingo bb, Lucent usc / clingo usc and the better Lucent strategy / the better
clingo strategy, with geometric means over the rows where all runs finished. The targets
(issue 31): Lucent's default (bb) within 1.5x clingo end to end and 2x clasp solver only.
Needs clingo, gringo and clasp (apt-get install -y gringo clasp)."""
import argparse
import glob
import math
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")


def child_cpu(cmd, timeout):
    """(CPU seconds of the child, user + system, its stdout) of one run; None on timeout."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout).stdout
    except subprocess.TimeoutExpired:
        return None
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime), out


def rows(pattern):
    """The rows (name, file) of benches/data/opt whose file name matches `pattern`."""
    files = sorted(glob.glob(os.path.join(ROOT, "benches", "data", "opt", "*.lp")))
    return [(os.path.basename(f)[:-3], f) for f in files
            if re.search(pattern, os.path.basename(f))]


def ground_aspif(f, tmp):
    """gringo's aspif of `f`, written once into `tmp` (a later call finds it); returns its
    path."""
    aspif = os.path.join(tmp, os.path.basename(f)[:-3] + ".aspif")
    if os.path.exists(aspif):
        return aspif
    with open(aspif, "w") as out:
        subprocess.run(["gringo", "--output=intermediate", f], stdout=out, check=True)
    return aspif


def default_lucent():
    return os.path.join(os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target")),
                        "release", "lucent")


def run(cmd, timeout):
    """(CPU seconds, optimum text or a failure word) of one run."""
    r = child_cpu(cmd, timeout)
    if r is None:
        return None, "TIMEOUT"
    cpu, out = r
    if "OPTIMUM FOUND" not in out:
        return None, "NO-OPTIMUM"
    m = re.search(r"^Optimization\s*:\s*(.*)$", out, re.M)
    return cpu, m.group(1).strip() if m else "?"


def best_of(cmd, timeout, reps):
    best, opt = None, None
    for _ in range(reps):
        t, o = run(cmd, timeout)
        opt = o
        if t is None:
            return None, o
        best = t if best is None else min(best, t)
    return best, opt


def ratio(a, b):
    if a is None or b is None:
        return None
    return max(a, 0.01) / max(b, 0.01)


def gmean(xs):
    xs = [x for x in xs if x is not None]
    return math.exp(sum(math.log(x) for x in xs) / len(xs)) if xs else float("nan")


def fmt(x):
    return "   -  " if x is None else f"{x:6.2f}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lucent", default=default_lucent())
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--reps", type=int, default=1)
    ap.add_argument("--rows", default=".")
    a = ap.parse_args()
    for tool in ("clingo", "gringo", "clasp"):
        if shutil.which(tool) is None:
            sys.exit(f"{tool} is missing: apt-get install -y gringo clasp")
    if not os.access(a.lucent, os.X_OK):
        sys.exit(f"{a.lucent} is missing: cargo build --release")
    tmp = tempfile.mkdtemp(prefix="lucent-bench-opt-")
    usc = "--opt-strategy=usc"
    cols = {"e2e": ([], [], []), "solver": ([], [], [])}
    print(f"{'row':16} {'part':6} {'clingo_bb':>9} {'clingo_usc':>10} {'lucent_bb':>9} "
          f"{'lucent_usc':>10} {'bb/bb':>6} {'usc/usc':>7} {'best/best':>9}  optimum")
    selected = rows(a.rows)
    # One untimed run of each binary first, so that no tool's first timed run pays for loading
    # it from disk (measured: a fresh build's first `lucent` run on knapsack_25 took 26 ms of
    # CPU, 22 of them system time, against 10 ms for the runs after it).
    if selected:
        f = selected[0][1]
        aspif = ground_aspif(f, tmp)
        for cmd in (["clingo", "-q", f], [a.lucent, "-q", f], ["clasp", "-q", aspif],
                    [a.lucent, "--mode=clasp", "-q", aspif]):
            child_cpu(cmd, a.timeout)
    for name, f in selected:
        aspif = ground_aspif(f, tmp)
        parts = {
            "e2e": (["clingo", "-q", f], [a.lucent, "-q", f]),
            "solver": (["clasp", "-q", aspif], [a.lucent, "--mode=clasp", "-q", aspif]),
        }
        for part, (ref, ours) in parts.items():
            runs = [best_of(ref, a.timeout, a.reps), best_of(ref + [usc], a.timeout, a.reps),
                    best_of(ours, a.timeout, a.reps), best_of(ours + [usc], a.timeout, a.reps)]
            (cb, ob), (cu, ou), (lb, olb), (lu, olu) = runs
            agree = all(o == ob for o in (ou, olb, olu) if not o.isupper())
            note = ob if agree else f"DISAGREE clingo={ob} {ou} lucent={olb} {olu}"
            best_ref = min((t for t in (cb, cu) if t is not None), default=None)
            best_ours = min((t for t in (lb, lu) if t is not None), default=None)
            r = (ratio(lb, cb), ratio(lu, cu), ratio(best_ours, best_ref))
            for k in range(3):
                cols[part][k].append(r[k])
            show = lambda t: f"{t:9.3f}" if t is not None else "  TIMEOUT"
            print(f"{name:16} {part:6} {show(cb)} {show(cu):>10} {show(lb)} {show(lu):>10} "
                  f"{fmt(r[0])} {fmt(r[1]):>7} {fmt(r[2]):>9}  {note}", flush=True)
    for part, (bb, us, best) in cols.items():
        worst = max((x for x in bb if x is not None), default=float("nan"))
        print(f"geometric means {part:6}: lucent bb / clingo bb {gmean(bb):.2f} (worst {worst:.2f}), "
              f"lucent usc / clingo usc {gmean(us):.2f}, best / best {gmean(best):.2f}")
    shutil.rmtree(tmp)


if __name__ == "__main__":
    main()
