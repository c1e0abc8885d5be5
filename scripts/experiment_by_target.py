#!/usr/bin/env python3
"""Per-target breakdowns of the 'one axiom missing' readings from a run directory's per-trial
records (results/*.json of `lucent experiment`), with 95% percentile-bootstrap intervals
(2000 resamples, fixed seed) over the trials, for docs/experiments/gaps.md:

- H4: precision and recall without the axioms per question kind, by the missing target
  (`removed`), and, under "all five missing", over the trials whose plan equals KB_full's;
- H2: the fixed mode's answer-set counts and times per condition (why the plans and time
  ratios lie below 1).

usage: scripts/experiment_by_target.py RUN_DIR
"""
import collections, functools, glob, json, sys

import bootstrap_ci

# One decimal: the figures here are percentages.
ci = functools.partial(bootstrap_ci.ci, digits=1)
cell = functools.partial(bootstrap_ci.cell, digits=1)


run = sys.argv[1]
for preset in ["real", "simulated"]:
    h4 = [json.load(open(f))["result"] for f in sorted(glob.glob(f"{run}/results/h4-{preset}-*.json"))]
    print(f"## H4 {preset} ({len(h4)} trials): P / R without the axioms, %")
    groups = collections.defaultdict(lambda: collections.defaultdict(lambda: ([], [])))
    for r in h4:
        wo = {q["kind"]: q for q in r.get("without", [])}
        if wo.get("plan", {}).get("precision") == 100.0:
            for k, q in wo.items():
                groups["all five, same plan as KB_full"][k][0].append(q["precision"])
                groups["all five, same plan as KB_full"][k][1].append(q["recall"])
        for q in r.get("without_one", []):
            g = groups[f"only {r.get('removed')} missing"][q["kind"]]
            g[0].append(q["precision"])
            g[1].append(q["recall"])
    for name, kinds in sorted(groups.items()):
        row = "; ".join(f"{k} {cell(p)} / {cell(rc)} (n={len(p)})" for k, (p, rc) in kinds.items())
        print(f"- {name}: {row}")
    h2 = [json.load(open(f))["result"] for f in sorted(glob.glob(f"{run}/results/h2-{preset}-*.json"))]
    both = [r for r in h2 if r["with"]["fixed"]["plans"] and r["without"]["fixed"]["plans"]]
    w = [r["with"]["fixed"] for r in both]
    wo = [r["without"]["fixed"] for r in both]
    print(f"## H2 {preset}, fixed mode, {len(both)} pairs with a plan in both conditions")
    print(f"- answer sets: with fewer than without in {sum(a['plans'] < b['plans'] for a, b in zip(w, wo))},"
          f" equal in {sum(a['plans'] == b['plans'] for a, b in zip(w, wo))},"
          f" more in {sum(a['plans'] > b['plans'] for a, b in zip(w, wo))};"
          f" the cap reached with {sum(a['capped'] for a in w)}, without {sum(b['capped'] for b in wo)}")
    print(f"- mean planning time: with {sum(a['time'] for a in w) / len(w):.2f} s,"
          f" without {sum(b['time'] for b in wo) / len(wo):.2f} s")
