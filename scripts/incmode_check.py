#!/usr/bin/env python3
"""Runs incremental-mode cases (`#include <incmode>.`) in the format of clingo's
app/clingo/tests: for every X.lp of the given folders, `SOLVER 0 X.lp -Wnone $(cat X.cmd)`;
the output is normalised as clingo's tests/run.py does (per `Solving...` a `Step: N` header and
the sorted models, then the last result) and compared with X.sol.

usage: scripts/incmode_check.py [--solver CMD] [DIR...]
       scripts/incmode_check.py --normalize < output      (prints the normalised form)

Default folders: tests/data/incmode, and ../shared/data/clingo-tests/app-incmode when present.
Exit status 1 when a case fails.
"""
import argparse
import os
import shlex
import subprocess
import sys


def normalize(out):
    # The state machine of potassco/clingo app/clingo/tests/run.py.
    state, current, step, result, norm = 0, [], 0, "ERROR", []
    for line in out.split("\n"):
        if state == 1:
            if step > 0:
                norm.append("Step: {}".format(step))
                for model in sorted(" ".join(sorted(m)) for m in current):
                    norm.append(model)
            step += 1
            state = 0
            current = []
        if state == 2:
            current.append(line.strip().split(" "))
            state = 0
        elif line.startswith("Solving..."):
            state = 1
        elif line.startswith("Answer: "):
            state = 2
        elif line.startswith("SATISFIABLE"):
            result, state = "SAT", 1
        elif line.startswith("UNSATISFIABLE"):
            result, state = "UNSAT", 1
        elif line.startswith("UNKNOWN"):
            result, state = "UNKNOWN", 1
        elif line.startswith("OPTIMUM FOUND"):
            result, state = "OPTIMUM FOUND", 1
    norm.append(result)
    norm.append("")
    return "\n".join(norm)


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("--solver", default=os.path.join(root, "target", "release", "lucent"))
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--normalize", action="store_true")
    ap.add_argument("dirs", nargs="*")
    a = ap.parse_args()
    if a.normalize:
        sys.stdout.write(normalize(sys.stdin.read()))
        return 0
    dirs = a.dirs or [os.path.join(root, "tests", "data", "incmode")]
    shared = os.path.join(root, "..", "shared", "data", "clingo-tests", "app-incmode")
    if not a.dirs and os.path.isdir(shared):
        dirs.append(shared)
    passed = failed = 0
    for d in dirs:
        for name in sorted(os.listdir(d)):
            if not name.endswith(".lp"):
                continue
            lp = os.path.join(d, name)
            base = lp[:-3]
            if not os.path.exists(base + ".sol"):
                continue
            cmd = ""
            if os.path.exists(base + ".cmd"):
                with open(base + ".cmd") as fh:
                    cmd = fh.read()
            argv = shlex.split(a.solver) + ["0", lp, "-Wnone"] + shlex.split(cmd)
            try:
                run = subprocess.run(argv, capture_output=True, text=True, timeout=a.timeout)
                got = normalize(run.stdout)
            except subprocess.TimeoutExpired:
                got = "timeout"
            with open(base + ".sol") as fh:
                want = fh.read()
            if got.strip() == want.strip():
                passed += 1
            else:
                failed += 1
                print("FAIL {}:\n--- expected\n{}--- got\n{}".format(lp, want, got))
    print("incmode: {} passed, {} failed".format(passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
