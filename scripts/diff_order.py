#!/usr/bin/env python3
"""The order of a model's symbols, clingo 5.8 against Lucent: random programs
(scripts/random_asp.py) with exactly one answer set are grounded and solved through clingo's
Python API and through `import lucent as clingo`, each in its own process, and the lists
`symbols(atoms=True)` and `symbols(shown=True)` compared as lists (what a script printing a
model prints). Programs with optimization, projection or heuristics are left out (several
optimal models may be reported); a program whose two answer sets differ as sets is reported as
such (it would be a wrong answer, which scripts/diff_random.py checks in full).

Prints the counts: programs with one answer set, equal atom lists, equal shown lists, equal
order of predicates, equal order within each predicate; with --show, each program whose lists
differ. Exits 1 when a set differs, or when fewer than --min-equal (a fraction) of the atom
lists are equal.

usage: scripts/diff_order.py [--count N] [--seed S] [--python PY] [--show] [--min-equal F]
       (PY: the Python that imports lucent, default the current one)
"""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import random_asp  # noqa: E402

PROBE = r'''
import json, sys
clingo = __import__(sys.argv[1])
out = []
for text in json.loads(sys.stdin.read()):
    try:
        ctl = clingo.Control(["0", "--warn=none"])
        ctl.add("base", [], text)
        ctl.ground([("base", [])])
        models = []
        ctl.solve(on_model=lambda m: models.append(
            ([str(s) for s in m.symbols(atoms=True)], [str(s) for s in m.symbols(shown=True)])))
        out.append(models if len(models) <= 1 else len(models))
    except Exception as e:
        out.append("error: " + str(e)[:200])
print(json.dumps(out))
'''


def run(python, module, texts):
    done = subprocess.run([python, "-c", PROBE, module], input=json.dumps(texts),
                          capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{module} under {python} failed:\n{done.stderr[-3000:]}")
    return json.loads(done.stdout)


def pred(s):
    neg = s.startswith("-") and not s[1:2].isdigit()
    return ("-" if neg else "") + (s[1:] if neg else s).split("(")[0]


def domains(atoms):
    seen = []
    for s in atoms:
        if pred(s) not in seen:
            seen.append(pred(s))
    return seen


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--python", default=sys.executable,
                    help="the Python that imports lucent (clingo 5.8 comes from python3)")
    ap.add_argument("--clingo-python", default="python3")
    ap.add_argument("--show", action="store_true", help="print each program whose lists differ")
    ap.add_argument("--min-equal", type=float, default=0.0)
    a = ap.parse_args()
    texts, seeds = [], []
    for seed in range(a.seed, a.seed + a.count):
        stmts, opts = random_asp.program(seed)
        text = random_asp.render(stmts)
        if opts["project"] or opts["heuristic"] or "imize" in text or ":~" in text:
            continue
        texts.append(text)
        seeds.append(seed)
    ours = run(a.python, "lucent", texts)
    ref = run(a.clingo_python, "clingo", texts)
    n = dict(one=0, atoms=0, shown=0, domains=0, within=0, set_differs=0)
    for seed, text, x, y in zip(seeds, texts, ref, ours):
        if not (isinstance(x, list) and len(x) == 1 and isinstance(y, list) and len(y) == 1):
            continue
        n["one"] += 1
        (xa, xs), (ya, ys) = x[0], y[0]
        if sorted(xa) != sorted(ya):
            n["set_differs"] += 1
            print(f"seed {seed}: the answer sets differ\n{text}\nclingo {xa}\nlucent {ya}")
            continue
        n["atoms"] += xa == ya
        n["shown"] += xs == ys
        n["domains"] += domains(xa) == domains(ya)
        n["within"] += all([s for s in xa if pred(s) == p] == [s for s in ya if pred(s) == p]
                           for p in domains(xa))
        if a.show and (xa != ya or xs != ys):
            print(f"---- seed {seed}\n{text}\nclingo {xa} | {xs}\nlucent {ya} | {ys}")
    print(" ".join(f"{k}={v}" for k, v in n.items()))
    if n["set_differs"] or (n["one"] and n["atoms"] < a.min_equal * n["one"]):
        sys.exit(1)


if __name__ == "__main__":
    main()
