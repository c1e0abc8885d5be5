#!/usr/bin/env python3
"""Asks the four question types over runs of the sense-plan-act loop (issue 28): for each
episode (`lucent run --preset P --seed S --save-history`, noise included, so some actions fail),
`lucent ask --run` gets "describe the plan", "why did you <an executed action>", "why didn't you
<an action the robot never did at that step>" and "why did you believe <a relation> at <step>",
phrased from the run's own objects. A question is answered when the reply is JSON of its type
(not `not_understood`) with a non-empty answer and `ask` exits 0. Prints one row per type and
every unanswered question.

usage: scripts/ask_sweep.py [--lucent target/release/lucent] [--episodes 100] [--first-seed 1]
                            [--out DIR]
Half of the episodes use the `real` preset, half `simulated`.
"""
import argparse
import json
import os
import subprocess
import sys


def words(constant):
    return "the " + constant.replace("_", " ")


def say(action, step):
    name, args = action.split("(", 1)
    args = args.rstrip(")").split(",")
    if name == "pickup":
        return f"pick up {words(args[1])} at step {step}"
    return f"put {words(args[1])} on {words(args[2])} at step {step}"


def questions(run):
    steps = run["steps"]
    objects = [o for o in run["objects"] if o != "table"]
    done = [(s["step"], s["happened"]) for s in steps if s.get("happened")]
    qs = [("plan", "describe the plan")]
    ok = [(i, a) for i, a in done if not (steps[i].get("failure"))]
    if ok:
        i, a = ok[len(ok) // 2]
        qs.append(("why", f"why did you {say(a, i)}?"))
    step = done[0][0] if done else 0
    acted = {a.split(",")[1] for i, a in done if i == step}
    others = [o for o in objects if f"{o})" not in acted and o not in acted]
    if others:
        qs.append(("why_not", f"why didn't you pick up {words(others[-1])} at step {step}?"))
    first = steps[0]["observed"] if steps else []
    rel = [o["fluent"] for o in first
           if o["fluent"].startswith("relation(on,") and o.get("value", True)]
    if rel:
        _, a, b = rel[0][len("relation("):-1].split(",")
        last = len(done)
        qs.append(("belief",
                   f"why did you believe {words(a)} was on {words(b)} at step {last // 2}?"))
    return qs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lucent", default="target/release/lucent")
    ap.add_argument("--episodes", type=int, default=100)
    ap.add_argument("--first-seed", type=int, default=1)
    ap.add_argument("--out", default="target/ask_sweep")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    per = args.episodes // 2
    tally = {}
    misses = []
    failed_runs = 0
    for preset in ["real", "simulated"]:
        for seed in range(args.first_seed, args.first_seed + per):
            path = os.path.join(args.out, f"{preset}-{seed}.json")
            r = subprocess.run([args.lucent, "run", "--preset", preset, "--seed", str(seed),
                                "--save-history", path],
                               capture_output=True, text=True, timeout=900)
            if not os.path.exists(path):
                print(f"{preset}-{seed}: no history saved (exit {r.returncode})",
                      file=sys.stderr)
                continue
            run = json.load(open(path))
            if any(s.get("failure") for s in run["steps"]):
                failed_runs += 1
            qs = questions(run)
            text = "".join(q + "\n" for _, q in qs) + "quit\n"
            r = subprocess.run([args.lucent, "ask", "--run", path, "--outf=2"], input=text,
                               capture_output=True, text=True, timeout=600)
            replies = [json.loads(l) for l in r.stdout.splitlines() if l.startswith("{")]
            for k, (kind, q) in enumerate(qs):
                got = replies[k] if k < len(replies) else None
                good = (r.returncode == 0 and got is not None and got.get("answer")
                        and got.get("type") not in ("not_understood", None))
                t = tally.setdefault(kind, [0, 0])
                t[1] += 1
                if good:
                    t[0] += 1
                else:
                    misses.append(f"{preset}-{seed}: {q} -> {got} (exit {r.returncode})"
                                  f" {r.stderr.strip()[:200]}")
    print(f"{args.episodes} episodes, {failed_runs} with a failed action")
    print("| type | answered | asked |")
    print("|---|---|---|")
    for kind in ["plan", "why", "why_not", "belief"]:
        a, n = tally.get(kind, [0, 0])
        print(f"| {kind} | {a} | {n} |")
    for m in misses:
        print(m)
    sys.exit(1 if misses else 0)


if __name__ == "__main__":
    main()
