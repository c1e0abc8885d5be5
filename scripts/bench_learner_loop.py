#!/usr/bin/env python3
"""The learner's inner loop, Lucent against clingo's Python API in one run: N times parse,
ground, solve a one-step program and read the model (every true atom), with a fresh control
each time. Lucent runs examples/learner_loop.rs (library calls through control::Control, built
with the release-lto profile, mimalloc as its allocator);
clingo runs Control(), add, ground, solve with the model's atoms read as symbols.
Prints calls per second for both and the ratio, and the CPU time per call of both (clingo's:
this process's `time.process_time()` over its loop; Lucent's: the child's user+sys time); with
--rounds, the medians of both ratios over the rounds come last, then the ratio of each side's
fastest round (the steadiest figure on a shared machine).

With --bin (repeatable), prebuilt learner_loop binaries (say main's and a branch's) run instead
of building one, in --rounds rounds of clingo then each binary (their order rotated from round
to round), so that a loaded machine's drift hits them alike.

usage: scripts/bench_learner_loop.py [--n N] [--rounds R] [--bin BIN]... [PROGRAM]
       (default benches/data/learner_step.lp)
"""
import argparse
import statistics
import os
import re
import resource
import subprocess
import sys
import time


def clingo_loop(text, n):
    """N calls of clingo's Python API: calls per second, seconds, atoms read (and, in
    `clingo_loop.cpu`, the CPU seconds of the loop)."""
    import clingo
    atoms = 0
    cpu = time.process_time()
    start = time.perf_counter()
    for _ in range(n):
        ctl = clingo.Control(["0"])
        ctl.add("base", [], text)
        ctl.ground([("base", [])])
        with ctl.solve(yield_=True) as handle:
            for model in handle:
                atoms += len(model.symbols(atoms=True))
    secs = time.perf_counter() - start
    clingo_loop.cpu = time.process_time() - cpu
    return n / secs, secs, atoms


def lucent_run(exe, program, n):
    """Runs one learner_loop binary: its output line, calls per second, CPU seconds."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run([exe, program, str(n)], capture_output=True, text=True,
                         check=True).stdout
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    rate = float(re.search(r"calls_per_second=([0-9.]+)", out).group(1))
    return out.strip(), rate, cpu


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=2000)
    ap.add_argument("--rounds", type=int, default=1)
    ap.add_argument("--bin", action="append", default=[],
                    help="a prebuilt learner_loop binary (repeatable); nothing is built")
    ap.add_argument("program", nargs="?",
                    default=os.path.join(root, "benches", "data", "learner_step.lp"))
    a = ap.parse_args()
    exes = a.bin
    if not exes:
        # The release-lto profile (Cargo.toml): release with fat LTO and one codegen unit.
        subprocess.run(["cargo", "build", "--profile", "release-lto", "--quiet",
                        "--no-default-features", "--example", "learner_loop"], cwd=root,
                       check=True)
        target = os.environ.get("CARGO_TARGET_DIR", os.path.join(root, "target"))
        exes = [os.path.join(target, "release-lto", "examples", "learner_loop")]
    with open(a.program) as fh:
        text = fh.read()
    import clingo
    rate_ratios = {exe: [] for exe in exes}
    cpu_ratios = {exe: [] for exe in exes}
    # CPU seconds per call of every round, for the best-of-rounds ratio.
    cpu_calls = {exe: [] for exe in exes}
    clingo_calls = []
    for r in range(a.rounds):
        if a.rounds > 1 or a.bin:
            print("round {} (load average {:.1f})".format(r, os.getloadavg()[0]))
        if len(exes) == 1:
            runs = [lucent_run(exes[0], a.program, a.n)]
            clingo_rate, secs, atoms = clingo_loop(text, a.n)
        else:
            # Several builds: clingo first, then the builds in an order rotated every round,
            # so that no build always runs right after clingo (the position moved a build's
            # figures by more than the difference between two builds, 2026-12-07).
            clingo_rate, secs, atoms = clingo_loop(text, a.n)
            k = r % len(exes)
            order = exes[k:] + exes[:k]
            done = {exe: lucent_run(exe, a.program, a.n) for exe in order}
            runs = [done[exe] for exe in exes]
        clingo_cpu = clingo_loop.cpu / a.n
        for exe, (out, rate, cpu) in zip(exes, runs):
            if a.bin:
                print(exe)
            print(out)
            print("lucent cpu_per_call_us={:.0f}".format(1e6 * cpu / a.n))
        print("clingo-python {} calls={} seconds={:.3f} calls_per_second={:.1f} "
              "atoms_read={} cpu_per_call_us={:.0f}".format(
                  clingo.__version__, a.n, secs, clingo_rate, atoms, 1e6 * clingo_cpu))
        clingo_calls.append(clingo_cpu)
        for exe, (out, rate, cpu) in zip(exes, runs):
            name = " ({})".format(exe) if a.bin else ""
            cpu_calls[exe].append(cpu / a.n)
            rate_ratios[exe].append(rate / clingo_rate)
            cpu_ratios[exe].append(clingo_cpu / (cpu / a.n))
            print("ratio lucent/clingo = {:.2f}, cpu ratio clingo/lucent = {:.2f}{}".format(
                rate / clingo_rate, clingo_cpu / (cpu / a.n), name))
    if a.rounds > 1:
        for exe in exes:
            name = " ({})".format(exe) if a.bin else ""
            print("median over {} rounds: ratio lucent/clingo = {:.2f}, cpu ratio "
                  "clingo/lucent = {:.2f}{}".format(a.rounds, statistics.median(rate_ratios[exe]),
                                                    statistics.median(cpu_ratios[exe]), name))
            # Each side's fastest round: on a shared machine the rounds a neighbour slowed
            # down drop out of both sides alike.
            print("best of {} rounds: clingo {:.0f} us a call, lucent {:.0f} us a call, cpu "
                  "ratio clingo/lucent = {:.2f}{}".format(
                      a.rounds, 1e6 * min(clingo_calls), 1e6 * min(cpu_calls[exe]),
                      min(clingo_calls) / min(cpu_calls[exe]), name))

if __name__ == "__main__":
    sys.exit(main())
