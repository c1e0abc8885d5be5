#!/usr/bin/env python3
"""Other readings of H2's Table 3 (issue 34) from plan traces, for docs/experiments/gaps.md.

The traces are JSON lines of `cargo run --release --example h2_trace -- RUN_DIR PRESET SEED 0 99
[HORIZON] [one]` (src/experiment/h2/trace.rs): every plan of every pair in the planner's order,
judged by the trial's own code. This script first checks that the traces give the trial records'
counts (RUN_DIR/results/h2-PRESET-*.json: distinct plans per verdict, per condition and mode),
then prints, per condition and mode, the fractions of optimal / sub-optimal / incorrect plans
under each reading, with 95% percentile-bootstrap intervals over the pairs (2000 resamples, fixed
seed, as src/experiment/interval.rs):

- kept: distinct plans, fractions per pair, averaged over the pairs with a plan (the tables);
- answer sets: every answer set counted (duplicates kept), per pair, averaged;
- first plan: only the first plan the planner returns (the one a robot would execute);
- pooled: distinct plans pooled over the pairs (a plan-weighted mean);
- optimal among found: a correct plan is optimal when no correct plan found for the pair is
  shorter (the paper's "minimal plan" read as minimal among the plans the planner produced);
- goal reached: incorrect only when the goal is false at the end with the steps that cannot be
  executed skipped (the paper's "goal not reached"), else by length as kept;
- best plan of the pair: the pair counts once, as its best plan (optimal when one of its plans
  is; the paper's "plans" read as one outcome per pair);
- no table pickup: the plans that pick up the table left out (the table is not movable);

and, for the incorrect plans, what makes them so: the first step that fails (a pickup while
holding something: E5; a pickup of the table; a pickup of a covered object: E7 or E8; a putdown
of an object not held: E2; another putdown) or the goal false at the end; and the kept optimal
fraction by L*.

usage: scripts/h2_readings.py RUN_DIR TRACE.jsonl [TRACE_H4.jsonl]
"""
import collections, glob, json, re, sys

from bootstrap_ci import ci, cell


def fractions(per_pair):
    """per_pair: list of lists of verdicts; pairs without a plan are left out."""
    rows = [v for v in per_pair if v]
    out = {}
    for q in ("optimal", "sub-optimal", "incorrect"):
        out[q] = [sum(1 for x in v if x == q) / len(v) for v in rows]
    return out, len(rows)


def line(name, per_pair):
    f, n = fractions(per_pair)
    return f"| {name} | {cell(f['optimal'])} | {cell(f['sub-optimal'])} | {cell(f['incorrect'])} | {n} |"


def distinct(plans):
    seen, out = set(), []
    for p in plans:
        k = tuple(p["actions"])
        if k not in seen:
            seen.add(k)
            out.append(p)
    return out


def cause(plan):
    """Why an incorrect plan is incorrect: its first failing step, read with the hand's content."""
    if plan["failed"] is None:
        return "goal false at the end"
    step, reason = plan["failed"]
    if "unstable" in reason:
        return "leaves an object unstable"
    held = None
    for a in plan["actions"][:step]:
        m = re.match(r"(pickup|putdown)\(rob1,([^,)]+)", a)
        if m:
            held = m.group(2) if m.group(1) == "pickup" else None
    m = re.match(r"(pickup|putdown)\(rob1,([^,)]+)", plan["actions"][step])
    kind, obj = m.group(1), m.group(2)
    if kind == "pickup":
        if held is not None:
            return "pickup while holding (E5)"
        if obj == "table":
            return "pickup of the table"
        return "pickup of a covered object (E7/E8)"
    if held != obj:
        return "putdown of an object not held (E2)"
    return "other putdown (E1, stability)"


def readings(traces, condition, mode):
    per = [next((m for m in t["modes"] if m["condition"] == condition and m["mode"] == mode), None) for t in traces]
    rows = []
    kept = [[p["quality"] for p in distinct(m["plans"])] if m else [] for m in per]
    rows.append(line("kept (distinct plans, per pair)", kept))
    rows.append(line("answer sets (duplicates counted)", [[p["quality"] for p in m["plans"]] if m else [] for m in per]))
    rows.append(line("first plan only", [[m["plans"][0]["quality"]] if m and m["plans"] else [] for m in per]))
    pooled = [q for v in kept for q in v]
    if pooled:
        c = collections.Counter(pooled)
        rows.append(f"| pooled over plans | {c['optimal'] / len(pooled):.2f} | {c['sub-optimal'] / len(pooled):.2f} | {c['incorrect'] / len(pooled):.2f} | {len(pooled)} plans |")
    among = []
    for m in per:
        ps = distinct(m["plans"]) if m else []
        ok = [len(p["actions"]) for p in ps if p["quality"] != "incorrect"]
        least = min(ok) if ok else None
        among.append(["incorrect" if p["quality"] == "incorrect" else ("optimal" if len(p["actions"]) == least else "sub-optimal") for p in ps])
    rows.append(line("optimal among found (least correct length found)", among))
    reached = [["incorrect" if not p["goal_if_skipped"] else (p["quality"] if p["quality"] != "incorrect" else "sub-optimal") for p in distinct(m["plans"])] if m else [] for m in per]
    rows.append(line("goal reached (failing steps skipped; such plans sub-optimal)", reached))
    best = [[min((p["quality"] for p in distinct(m["plans"])), key=["optimal", "sub-optimal", "incorrect"].index)] if m and m["plans"] else [] for m in per]
    rows.append(line("best plan of the pair (a pair is optimal when one of its plans is)", best))
    notable = [[p["quality"] for p in distinct(m["plans"]) if "pickup(rob1,table)" not in p["actions"]] if m else [] for m in per]
    rows.append(line("no table pickup", notable))
    causes = collections.Counter(cause(p) for m in per if m for p in distinct(m["plans"]) if p["quality"] == "incorrect")
    firsts = collections.Counter(cause(m["plans"][0]) for m in per if m and m["plans"] and m["plans"][0]["quality"] == "incorrect")
    by_len = collections.defaultdict(list)
    for t, v in zip(traces, kept):
        if v and t["min_length"] is not None:
            by_len[t["min_length"]].append(sum(1 for x in v if x == "optimal") / len(v))
    lengths = [len(p["actions"]) for m in per if m for p in distinct(m["plans"])]
    return rows, causes, firsts, by_len, lengths


def check(run, preset, traces):
    """The traces' distinct-plan verdicts against the trial records."""
    bad = 0
    for t in traces:
        rec = json.load(open(f"{run}/results/h2-{preset}-{t['index']:04d}.json"))["result"]
        for m in t["modes"]:
            if m["condition"] not in ("with", "without") or m["horizon"] not in (None, 9):
                continue
            r = rec[m["condition"]][m["mode"]]
            c = collections.Counter(p["quality"] for p in distinct(m["plans"]))
            if (c["optimal"], c["sub-optimal"], c["incorrect"]) != (r["optimal"], r["suboptimal"], r["incorrect"]):
                bad += 1
                print(f"  mismatch: pair {t['index']} {m['condition']} {m['mode']}: trace {dict(c)}, record {r['optimal']}/{r['suboptimal']}/{r['incorrect']}")
    return bad


def main():
    run, path = sys.argv[1], sys.argv[2]
    traces = [json.loads(l) for l in open(path)]
    preset = traces[0]["preset"]
    print(f"# {preset}: {len(traces)} pairs ({path})")
    bad = check(run, preset, traces)
    print(f"check against {run}/results: {bad} condition-mode cells differ\n")
    ls = [t["min_length"] for t in traces if t["min_length"] is not None]
    print(f"L*: mean {sum(ls) / len(ls):.2f} over {len(ls)} pairs; distribution {sorted(collections.Counter(ls).items())}")
    print(f"goal object covered: {sum(t['goal_object_covered'] for t in traces)}; in_hand goals: {sum(t['goal_text'].startswith('in_hand') for t in traces)}\n")
    conditions = sorted({(m["condition"], m["mode"]) for t in traces for m in t["modes"]}, key=lambda c: (c[0] != "without", c[0] != "with", c))
    for condition, mode in conditions:
        rows, causes, firsts, by_len, lengths = readings(traces, condition, mode)
        print(f"## {condition}, {mode}")
        print("| reading | optimal | sub-optimal | incorrect | pairs |\n|---|---|---|---|---|")
        print("\n".join(rows))
        if lengths:
            print(f"distinct plans' length: mean {sum(lengths) / len(lengths):.2f}, distribution {sorted(collections.Counter(lengths).items())}")
        if causes:
            print(f"incorrect distinct plans by cause: {dict(causes.most_common())}")
            print(f"first plan incorrect, by cause: {dict(firsts.most_common())}")
        print("kept optimal fraction by L*: " + "; ".join(f"L*={k}: {sum(v) / len(v):.2f} (n={len(v)})" for k, v in sorted(by_len.items())))
        print()
    if len(sys.argv) > 3:
        h4 = [json.loads(l) for l in open(sys.argv[3])]
        horizon = h4[0]["modes"][0]["horizon"]
        print(f"# {preset}, fixed mode at horizon {horizon} ({sys.argv[3]})")
        for condition in ("without", "with"):
            rows, causes, _, by_len, lengths = readings(h4, condition, "fixed")
            print(f"## {condition}, fixed, horizon {horizon}")
            print("| reading | optimal | sub-optimal | incorrect | pairs |\n|---|---|---|---|---|")
            print("\n".join(rows[:1] + rows[2:3]))
            print("kept optimal fraction by L*: " + "; ".join(f"L*={k}: {sum(v) / len(v):.2f} (n={len(v)})" for k, v in sorted(by_len.items())))
            nplan = sum(1 for t in h4 for m in t["modes"] if m["condition"] == condition and m["mode"] == "fixed" and not m["plans"])
            print(f"pairs without a plan at horizon {horizon}: {nplan}\n")


main()
