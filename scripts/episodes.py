#!/usr/bin/env python3
"""Episodes of the sense-plan-act loop (issue 13): `lucent run` on generated scenes of both
presets with a random goal each (docs/domain.md 7.1), 15% perception and 15% actuation noise by
default, and a table of how many reach the goal, the replans per episode and why each failure
failed. Every episode is a function of its preset and seed.

usage: scripts/episodes.py [--lucent target/release/lucent] [--episodes 100] [--first-seed 1]
                           [--out DIR] [--presets real,simulated] [-- extra lucent run options]
Half of the episodes use the `real` preset, half `simulated` (seeds first..first+n/2-1 each);
--presets simulated runs only that half (two such processes can share the work).
The histories are kept in DIR (default target/episodes) as preset-seed.json.
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import time


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lucent", default="target/release/lucent")
    ap.add_argument("--episodes", type=int, default=100)
    ap.add_argument("--first-seed", type=int, default=1)
    ap.add_argument("--out", default="target/episodes")
    ap.add_argument("--presets", default="real,simulated")
    ap.add_argument("--timeout", type=float, default=900.0,
                    help="seconds an episode may take before it counts as a failure")
    ap.add_argument("extra", nargs="*")
    ap.add_argument("--summarize", nargs="*", metavar="DIR",
                    help="only summarize the histories (preset-seed.json) already in DIRs")
    args = ap.parse_args()
    if args.summarize is not None:
        rows = []
        for d in args.summarize:
            for name in sorted(os.listdir(d)):
                if name.endswith(".json") and "-" in name:
                    preset, seed = name[:-5].rsplit("-", 1)
                    rows.append(row_of(preset, int(seed), os.path.join(d, name), None, 0.0))
        rows.sort(key=lambda r: (r[0] != "real", r[1]))
        report(rows, sorted({r[0] for r in rows}, key=lambda p: p != "real"), 0.0)
        return
    os.makedirs(args.out, exist_ok=True)
    half = args.episodes // 2
    presets = args.presets.split(",")
    runs = [(p, s) for p in presets
            for s in range(args.first_seed, args.first_seed + half)]
    rows = []
    start = time.time()
    for preset, seed in runs:
        path = os.path.join(args.out, f"{preset}-{seed}.json")
        t0 = time.time()
        c0 = children_cpu()
        cmd = [args.lucent, "run", "--preset", preset, "--seed", str(seed),
               "--perception-noise", "0.15", "--actuation-noise", "0.15",
               "--save-history", path] + args.extra
        try:
            proc = subprocess.run(cmd, capture_output=True, text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            secs = time.time() - t0
            rows.append((preset, seed, "?", False, 0, 0, f"timed out after {secs:.0f} s", secs,
                         children_cpu() - c0))
            print(f"{preset:9} {seed:3} FAIL timed out", file=sys.stderr, flush=True)
            continue
        secs = time.time() - t0
        cpu = children_cpu() - c0
        if proc.returncode not in (0, 20) or not os.path.exists(path):
            rows.append((preset, seed, "?", False, 0, 0, f"exit {proc.returncode}: "
                         + proc.stderr.strip().splitlines()[-1:][0] if proc.stderr.strip() else "", secs,
                         cpu))
            continue
        rows.append(row_of(preset, seed, path, proc.returncode, secs, cpu))
        r = rows[-1]
        print(f"{preset:9} {seed:3} {'ok  ' if r[3] else 'FAIL'} replans {r[4]} "
              f"actions {r[5]} {secs:6.1f}s wall {cpu:6.1f}s cpu {r[6]}", file=sys.stderr,
              flush=True)
    report(rows, presets, time.time() - start)


def children_cpu():
    """CPU seconds (user + system) of the finished child processes so far."""
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def row_of(preset, seed, path, code, secs, cpu=None):
    """One table row from a saved history (`code`: the exit code, None to judge by the file)."""
    h = json.load(open(path))
    ending = h["ending"]
    if isinstance(ending, dict):
        (k, v), = ending.items()
        ending = f"{k} {v}"
    ok = ending == "GoalObserved" and h["goal_in_truth"] is not False
    if code is not None:
        ok = code == 0
    why = "" if ok else f"{ending}; goal in truth: {h['goal_in_truth']}"
    actions = len([s for s in h["steps"] if s.get("happened")])
    return (preset, seed, ",".join(h["goal"]), ok, max(len(h["plans"]) - 1, 0), actions, why, secs,
            cpu)


def report(rows, presets, total):
    n = len(rows)
    ok = sum(1 for r in rows if r[3])
    print(f"# {n} episodes, {ok} reached the goal ({100.0 * ok / max(n, 1):.1f}%), "
          f"{total:.0f} s in all")
    for preset in presets:
        sub = [r for r in rows if r[0] == preset]
        if not sub:
            continue
        rp = [r[4] for r in sub]
        print(f"# {preset}: {sum(1 for r in sub if r[3])}/{len(sub)} reached; replans per "
              f"episode mean {sum(rp) / len(rp):.2f}, max {max(rp)}; actions mean "
              f"{sum(r[5] for r in sub) / len(sub):.2f}")
    hist = {}
    for r in rows:
        hist[r[4]] = hist.get(r[4], 0) + 1
    print("# replans: " + ", ".join(f"{k}: {hist[k]}" for k in sorted(hist)))
    cpus = [r[8] for r in rows if r[8] is not None]
    if cpus:
        print(f"# CPU s per episode: mean {sum(cpus) / len(cpus):.1f}, max {max(cpus):.1f}, "
              f"sum {sum(cpus):.0f}")
    print("\n| preset | seed | goal | reached | replans | actions | wall s | CPU s | why not |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        cpu = "" if r[8] is None else f"{r[8]:.1f}"
        print(f"| {r[0]} | {r[1]} | `{r[2]}` | {'yes' if r[3] else 'NO'} | {r[4]} | {r[5]} "
              f"| {r[7]:.1f} | {cpu} | {r[6]} |")


if __name__ == "__main__":
    main()
