#!/usr/bin/env python3
"""Records NAME.expected.json for every NAME.lp here with clingo 5.4.1 (/usr/bin/clingo):
    clingo -n0 --outf=2 --opt-mode=enum -Wnone NAME.lp
A program whose first line is `% record with clingo 5.8.3` (where 5.4.1 differs from the
reference semantics) is recorded with `python3 -m clingo` instead (pip install clingo).
Each file keeps that command and the sorted list of answer sets, each as its sorted atoms and
its costs. Re-run after changing a program: python3 record.py"""
import glob, json, subprocess

for lp in sorted(glob.glob("*.lp")):
    with open(lp) as fh:
        modern = fh.readline().startswith("% record with clingo 5.8.3")
    clingo = ["python3", "-m", "clingo"] if modern else ["clingo"]
    cmd = clingo + ["-n0", "--outf=2", "--opt-mode=enum", "-Wnone", lp]
    out = subprocess.run(cmd, capture_output=True, text=True).stdout
    js = json.loads(out)
    models = []
    for call in js.get("Call", []):
        for w in call.get("Witnesses", []):
            models.append({"atoms": sorted(w.get("Value", [])), "costs": w.get("Costs", [])})
    models.sort(key=lambda m: (m["atoms"], m["costs"]))
    with open(lp[:-3] + ".expected.json", "w") as fh:
        json.dump({"command": " ".join(cmd), "clingo": js.get("Solver", ""), "models": models}, fh, indent=1)
        fh.write("\n")
