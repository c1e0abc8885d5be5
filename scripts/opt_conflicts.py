#!/usr/bin/env python3
"""Search effort of Lucent against clasp on the optimization rows (benches/data/opt/*.lp, see
scripts/bench_opt.py): models, choices and conflicts from `--stats` and the CPU seconds of one
run, solver only (gringo's aspif to `clasp -q --stats` and `lucent --mode=clasp -q --stats`)
and end to end (`clingo` against `lucent`, each grounding itself, so the ground programs and
their numbering differ). Conflicts per second tell the speed of the search apart from its
length: a row far over its time target with few conflicts is slow per conflict, one with many
conflicts took a longer search path (the branch-and-bound bound, restarts, heuristic).

  scripts/opt_conflicts.py [--lucent target/release/lucent] [--rows RE] [--timeout 60]
                           [--args "--opt-strategy=usc"]"""
import argparse
import os
import re
import sys
import tempfile

from bench_opt import child_cpu, default_lucent, ground_aspif, rows


def stats(cmd, timeout):
    """(cpu seconds, models, choices, conflicts, optimum) of one run with --stats."""
    r = child_cpu(cmd + ["--stats"], timeout)
    if r is None:
        return None
    cpu, out = r

    def num(key):
        m = re.search(rf"^{key}\s*:\s*(\d+)", out, re.M)
        return int(m.group(1)) if m else -1

    m = re.search(r"^Optimization\s*:\s*(.*)$", out, re.M)
    opt = m.group(1).strip() if m and "OPTIMUM FOUND" in out else "-"
    return cpu, num("Models"), num("Choices"), num("Conflicts"), opt


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lucent", default=default_lucent())
    ap.add_argument("--rows", default=".")
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--args", default="", help="extra arguments for both sides")
    a = ap.parse_args()
    extra = a.args.split()
    files = rows(a.rows)
    if not files:
        sys.exit("no rows")
    tmp = tempfile.mkdtemp(prefix="lucent-opt-conflicts-")
    print(f"{'row':14} {'part':6} {'who':6} {'cpu':>7} {'models':>6} {'choices':>8} "
          f"{'conflicts':>9} {'confl/s':>8}  optimum")
    for name, f in files:
        aspif = ground_aspif(f, tmp)
        runs = [("solver", "clasp", ["clasp", "-q", aspif]),
                ("solver", "lucent", [a.lucent, "--mode=clasp", "-q", aspif]),
                ("e2e", "clingo", ["clingo", "-q", f]),
                ("e2e", "lucent", [a.lucent, "-q", f])]
        for part, who, cmd in runs:
            r = stats(cmd + extra, a.timeout)
            if r is None:
                print(f"{name:14} {part:6} {who:6} TIMEOUT")
                continue
            cpu, models, choices, conflicts, opt = r
            rate = conflicts / max(cpu, 0.001)
            print(f"{name:14} {part:6} {who:6} {cpu:7.3f} {models:6} {choices:8} "
                  f"{conflicts:9} {rate:8.0f}  {opt}", flush=True)
        os.remove(aspif)
    os.rmdir(tmp)


if __name__ == "__main__":
    main()
