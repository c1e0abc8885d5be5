#!/usr/bin/env python3
"""The learner's inner loop, Lucent against clingo's Python API in one run: N times parse,
ground, solve a one-step program and read the model (every true atom), with a fresh control
each time. Lucent runs examples/learner_loop.rs (library calls through control::Control, built
with the release-lto profile, mimalloc as its allocator);
clingo runs Control(), add, ground, solve with the model's atoms read as symbols.
Prints calls per second for both and the ratio.

usage: scripts/bench_learner_loop.py [--n N] [PROGRAM]   (default benches/data/learner_step.lp)
"""
import argparse
import os
import re
import subprocess
import sys
import time


def clingo_loop(text, n):
    import clingo
    atoms = 0
    start = time.perf_counter()
    for _ in range(n):
        ctl = clingo.Control(["0"])
        ctl.add("base", [], text)
        ctl.ground([("base", [])])
        with ctl.solve(yield_=True) as handle:
            for model in handle:
                atoms += len(model.symbols(atoms=True))
    secs = time.perf_counter() - start
    return n / secs, secs, atoms


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=2000)
    ap.add_argument("program", nargs="?",
                    default=os.path.join(root, "benches", "data", "learner_step.lp"))
    a = ap.parse_args()
    # The release-lto profile (Cargo.toml): release with fat LTO and one codegen unit.
    subprocess.run(["cargo", "build", "--profile", "release-lto", "--quiet",
                    "--no-default-features", "--example", "learner_loop"], cwd=root, check=True)
    exe = os.path.join(root, "target", "release-lto", "examples", "learner_loop")
    out = subprocess.run([exe, a.program, str(a.n)], capture_output=True, text=True,
                         check=True).stdout
    m = re.search(r"calls_per_second=([0-9.]+)", out)
    lucent = float(m.group(1))
    with open(a.program) as fh:
        text = fh.read()
    clingo_rate, secs, atoms = clingo_loop(text, a.n)
    import clingo
    print(out.strip())
    print("clingo-python {} calls={} seconds={:.3f} calls_per_second={:.1f} atoms_read={}".format(
        clingo.__version__, a.n, secs, clingo_rate, atoms))
    print("ratio lucent/clingo = {:.2f}".format(lucent / clingo_rate))


if __name__ == "__main__":
    sys.exit(main())
