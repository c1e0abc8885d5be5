#!/usr/bin/env python3
"""How much Lucent's search depends on the order of its own grounding: for each manifest row
(no extra arguments, family matching --rows), the row is grounded twice, by Lucent
(`lucent --mode=gringo`) and by gringo (`gringo`, aspif), and Lucent's solver runs on both
(`lucent --mode=clasp -q FILE`), with clasp on gringo's as a reference. The two groundings
number atoms alike and hold the same rules; they differ in the order of rules (and of body
literals), so any difference in Lucent's time is search order. Prints CPU seconds per row
and the geometric mean of own / gringo-ordered over the rows both finished.
A development script: it reads ../shared's benchmark table.

  scripts/order_sensitivity.py [--lucent BIN] [--manifest M.tsv] [--rows REGEX] [--timeout 20]
"""
import argparse
import csv
import math
import os
import re
import resource
import subprocess
import tempfile


def cpu(cmd, timeout):
    """User CPU seconds of one run of `cmd`, None on timeout."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime - before.ru_utime


def main():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    ap = argparse.ArgumentParser()
    ap.add_argument("--lucent", default=os.path.join(root, "target", "release", "lucent"))
    ap.add_argument("--manifest",
                    default=os.path.join(root, "..", "shared", "data", "bench", "MANIFEST.tsv"))
    ap.add_argument("--rows", default="planning|color")
    ap.add_argument("--timeout", type=float, default=20)
    a = ap.parse_args()
    base = os.path.dirname(a.manifest)
    tmp = tempfile.mkdtemp(prefix="lucent-order-")
    own, theirs = os.path.join(tmp, "own.aspif"), os.path.join(tmp, "gringo.aspif")
    ratios = []
    with open(a.manifest) as fh:
        rows = list(csv.reader(fh, delimiter="\t"))[1:]
    for fam, enc, inst, args, *_ in rows:
        if args or not re.search(a.rows, fam):
            continue
        enc, inst = os.path.join(base, enc), os.path.join(base, inst)
        for cmd, path in (([a.lucent, "--mode=gringo", enc, inst], own),
                          (["gringo", enc, inst], theirs)):
            with open(path, "w") as out:
                subprocess.run(cmd, stdout=out, stderr=subprocess.DEVNULL)
        t_own = cpu([a.lucent, "--mode=clasp", "-q", own], a.timeout)
        t_theirs = cpu([a.lucent, "--mode=clasp", "-q", theirs], a.timeout)
        t_clasp = cpu(["clasp", "-q", theirs], a.timeout)
        show = lambda t: "TIMEOUT" if t is None else f"{t:.2f}"
        print(f"{fam:20} {os.path.basename(inst):32} own {show(t_own):>7}  "
              f"gringo-ordered {show(t_theirs):>7}  clasp {show(t_clasp):>7}", flush=True)
        if t_own is not None and t_theirs is not None:
            ratios.append(max(t_own, 0.01) / max(t_theirs, 0.01))
    if ratios:
        g = math.exp(sum(math.log(r) for r in ratios) / len(ratios))
        print(f"geometric mean own / gringo-ordered: {g:.2f} over {len(ratios)} rows")


if __name__ == "__main__":
    main()
