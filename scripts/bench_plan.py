#!/usr/bin/env python3
"""Planning benchmark: Lucent's planner against clingo on the same tasks, in one run.

For every task (an AL_d planning problem, or a domain plus a scene of facts and a goal):
  * Lucent: `lucent plan ... --outf=2` (the incremental search on one multi-shot Control);
    its time is the planner's own figure (`time.total`: translation, grounding, solving).
  * clingo: the same problem translated by `lucent translate -c horizon_mode=incremental`
    (base / step(t) / check(t) parts with the external query(t)), CR rules rewritten for
    clingo as SPARC does (`{appl(l)} :- B.  h :- B, appl(l).  #minimize{1,l : appl(l)}.`),
    then clingo's incremental loop in Python (clingo 5.8 API): ground base and check(0), then
    step(k) and check(k) per horizon, query(k) true, until a horizon is satisfiable; there
    the optimum (least CR applications) is proven and one optimal model taken. Its time is
    the Python loop's (add, ground, solve), translation excluded.
Both must agree on the minimal length and CR count; the script prints per-task times, the
ratio Lucent/clingo and their geometric mean, twice: wall clock (Lucent's `time.total`, clingo's
loop) and CPU time (Lucent: the whole `lucent plan` process, start-up and reading the problem
included, from the children's rusage; clingo: `time.process_time()` around its loop). On a
loaded machine the wall-clock ratio swings by +-0.3; the CPU ratio is the steadier figure.

usage: scripts/bench_plan.py [--lucent target/release/lucent] [--repeat 3]
Tasks: the golden scenes and the scenes of facts listed in TASKS; each is written as one AL_d
file by `lucent plan ... --emit-problem` so both systems read the same problem.
"""
import argparse
import json
import math
import os
import re
import resource
import subprocess
import sys
import time

import clingo

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (name, lucent plan arguments)
TASKS = [
    ("tabletop", ["domains/ra/scenes/tabletop_task.ald"]),
    ("exception_goal", ["domains/ra/scenes/exception_goal.ald"]),
    ("execution_example", ["domains/ra/scenes/execution_example.ald"]),
    ("blocks3_hold_a", ["tests/data/plan/three_blocks.ald"]),
    ("facts_mug_on_white", ["domains/ra/kb_full.ald", "--scene", "tests/data/plan/scene.lp",
                            "--goal", "on(mug, white_block)"]),
    ("facts_hold_red", ["domains/ra/kb_full.ald", "--scene", "tests/data/plan/scene.lp",
                        "--goal", "in_hand(rob1, red_block)"]),
    ("h1_white_on_green", ["domains/ra/scenes/h1.ald", "--goal",
                           "on(white_cube_large, green_cube_large)"]),
    ("h1_two_towers", ["domains/ra/scenes/h1.ald", "--goal",
                       "on(red_cube_large, white_cube_large), on(yellow_cube_large, green_cube_large)"]),
]

CR = re.compile(r"^(.*?) : (.*?) :\+ (.*)\.\s*$")


def clingo_program(text):
    """CR rules `l : h :+ B.` as choice, rule and minimize (SPARC's encoding)."""
    out = []
    for line in text.splitlines():
        m = CR.match(line)
        if m:
            label, head, body = m.groups()
            out.append(f"{{ appl({label}) }} :- {body}.")
            out.append(f"{head} :- {body}, appl({label}).")
            out.append(f"#minimize {{ 1,{label} : appl({label}) }}.")
        else:
            out.append(line)
    return "\n".join(out) + "\n"


def clingo_plan(program):
    c0 = time.process_time()
    t0 = time.perf_counter()
    ctl = clingo.Control(["--opt-mode=opt", "-n", "1", "--warn=none"])
    ctl.add("base", [], program)
    ctl.ground([("base", []), ("check", [clingo.Number(0)])])
    k = 0
    while True:
        if k > 0:
            ctl.release_external(clingo.Function("query", [clingo.Number(k - 1)]))
            ctl.ground([("step", [clingo.Number(k)]), ("check", [clingo.Number(k)])])
        ctl.assign_external(clingo.Function("query", [clingo.Number(k)]), True)
        best = []
        with ctl.solve(yield_=True) as h:
            for m in h:
                best = [list(m.cost), [str(s) for s in m.symbols(atoms=True)
                                       if s.name == "occurs" and len(s.arguments) == 2
                                       and s.positive]]
        if best:
            return (time.perf_counter() - t0, k, (best[0][0] if best[0] else 0),
                    time.process_time() - c0)
        k += 1
        if k > 30:
            return time.perf_counter() - t0, None, None, time.process_time() - c0


def child_cpu():
    u = resource.getrusage(resource.RUSAGE_CHILDREN)
    return u.ru_utime + u.ru_stime


def lucent_plan(lucent, args):
    c0 = child_cpu()
    r = subprocess.run([lucent, "plan", *args, "--outf=2"], cwd=ROOT, capture_output=True,
                       text=True)
    cpu = child_cpu() - c0
    if r.returncode != 0:
        raise SystemExit(f"lucent plan {args}: exit {r.returncode}: {r.stderr}")
    v = json.loads(r.stdout)
    return v["time"]["total"], v["length"], v["cr_applied"], cpu


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lucent", default=os.path.join(ROOT, "target/release/lucent"))
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args()
    rows = []
    cpu_rows = []
    print(f"{'task':24} {'len':>3} {'cr':>3} {'lucent s':>9} {'clingo s':>9} {'ratio':>6}"
          f" {'lucent cpu':>10} {'clingo cpu':>10} {'ratio':>6}")
    for name, args in TASKS:
        problem = write_problem(a.lucent, name, args)
        program = clingo_program(
            subprocess.run([a.lucent, "translate", problem, "-c", "horizon_mode=incremental"],
                           cwd=ROOT, capture_output=True, text=True, check=True).stdout)
        ours_all = [lucent_plan(a.lucent, [problem]) for _ in range(a.repeat)]
        theirs_all = [clingo_plan(program) for _ in range(a.repeat)]
        ours = min(ours_all, key=lambda r: r[0])
        theirs = min(theirs_all, key=lambda r: r[0])
        ours_cpu = min(r[3] for r in ours_all)
        theirs_cpu = min(r[3] for r in theirs_all)
        if (ours[1], ours[2]) != (theirs[1], theirs[2]):
            print(f"{name}: DISAGREE lucent {ours[1:3]} clingo {theirs[1:3]}", file=sys.stderr)
        ratio = ours[0] / theirs[0]
        cpu_ratio = ours_cpu / theirs_cpu
        rows.append(ratio)
        cpu_rows.append(cpu_ratio)
        print(f"{name:24} {ours[1]:>3} {ours[2]:>3} {ours[0]:9.3f} {theirs[0]:9.3f} {ratio:6.2f}"
              f" {ours_cpu:10.3f} {theirs_cpu:10.3f} {cpu_ratio:6.2f}")
    g = math.exp(sum(math.log(r) for r in rows) / len(rows))
    gc = math.exp(sum(math.log(r) for r in cpu_rows) / len(cpu_rows))
    print(f"geometric mean of lucent/clingo over {len(rows)} tasks: {g:.2f} (wall clock), "
          f"{gc:.2f} (CPU)")


def write_problem(lucent, name, args):
    """One AL_d file per task: the task's file, or the domain with the scene and goal added
    (through `lucent plan --emit-problem`)."""
    r = subprocess.run([lucent, "plan", *args, "--emit-problem"], cwd=ROOT, capture_output=True,
                       text=True)
    if r.returncode != 0:
        raise SystemExit(f"lucent plan {args} --emit-problem: {r.stderr}")
    path = os.path.join("/tmp", f"bench_plan_{name}.ald")
    with open(path, "w") as f:
        f.write(r.stdout)
    return path


if __name__ == "__main__":
    main()
