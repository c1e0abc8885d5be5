#!/usr/bin/env python3
"""Does the solver's enumeration order drive H2's fixed-horizon fractions? (issue 34)

Solves the fixed-mode programs that `h2_trace ... dump DIR` wrote (CR-Prolog text of
src/experiment/h2/trace.rs `fixed_program`) with clingo (the Python module, 5.x) instead of
lucent: each CR rule `L : H :+ B.` becomes `{ H } :- B.` with `#minimize { 1,L,vars : H, B }`
(its applications counted, as the fixed mode keeps only answer sets with the fewest), and the
first 50 optimal answer sets are enumerated (`--opt-mode=optN`), as the trial keeps the first 50
of lucent's. For each pair it prints the plans' lengths and the fraction of distinct plans of
length L* (L* and lucent's figures from the trial records, RUN_DIR/results); with the learned
axioms every fixed plan is correct (Table 3: incorrect 0.00), so that fraction is the optimal
fraction (the trial's optimal also asks for the least CR count, which these pairs' least plans
never need in the runs of gaps.md).

usage: scripts/h2_clingo_order.py DIR RUN_DIR PRESET FIRST LAST [clingo options...]
"""
import json, re, sys

import clingo


def convert(text):
    out, k = [], 0
    for line in text.splitlines():
        m = re.match(r"^(?:(\w+)(\(.*?\))? : )?(.*) :\+ (.*)\.$", line)
        if not m:
            out.append(line)
            continue
        k += 1
        label, head, body = m.group(1) or f"cr{k}", m.group(3), m.group(4)
        variables = sorted(set(re.findall(r"\b[A-Z][A-Za-z0-9_]*\b", head + " " + body)))
        out.append(f"{{ {head} }} :- {body}.")
        terms = ",".join([label] + variables)
        out.append(f"#minimize {{ 1,{terms} : {head}, {body} }}.")
    return "\n".join(out)


def plans(path, options):
    ctl = clingo.Control(["--opt-mode=optN", "0"] + options)
    ctl.add("base", [], convert(open(path).read()))
    ctl.ground([("base", [])])
    found = []

    def on_model(m):
        if m.optimality_proven and len(found) < 50:
            steps = sorted((s.arguments[1].number, str(s.arguments[0])) for s in m.symbols(atoms=True)
                           if s.name == "occurs" and len(s.arguments) == 2 and s.positive)
            found.append(tuple(a for _, a in steps))
        return len(found) < 50

    ctl.solve(on_model=on_model)
    return found


def main():
    directory, run, preset = sys.argv[1], sys.argv[2], sys.argv[3]
    first, last = int(sys.argv[4]), int(sys.argv[5])
    options = sys.argv[6:]
    fractions, firsts, lengths, ours = [], [], [], []
    for index in range(first, last + 1):
        rec = json.load(open(f"{run}/results/h2-{preset}-{index:04d}.json"))["result"]
        found = plans(f"{directory}/{preset}-{index:04d}-with.lp", options)
        least = rec["min_length"]
        distinct = list(dict.fromkeys(found))
        mine = rec["with"]["fixed"]
        if not distinct or least is None:
            print(f"pair {index}: clingo {len(found)} answer sets, L* {least}")
            continue
        f = sum(len(p) == least for p in distinct) / len(distinct)
        fractions.append(f)
        firsts.append(len(distinct[0]) == least)
        lengths += [len(p) for p in distinct]
        if mine["plans"]:
            ours.append(mine["optimal"] / (mine["optimal"] + mine["suboptimal"] + mine["incorrect"]))
        print(f"pair {index}: L* {least}; clingo {len(found)} answer sets, {len(distinct)} plans, "
              f"lengths {sorted(set(len(p) for p in distinct))}, of length L* {f:.2f}; "
              f"lucent (record) optimal {ours[-1] if mine['plans'] else float('nan'):.2f}, mean steps {mine['steps']:.2f}")
    if fractions:
        print(f"{preset}, with the learned axioms, first 50 optimal answer sets at horizon 9: clingo "
              f"plans of length L* per pair averaged {sum(fractions) / len(fractions):.2f} over "
              f"{len(fractions)} pairs (first plan of length L* in {sum(firsts)}), mean plan length "
              f"{sum(lengths) / len(lengths):.2f}; lucent optimal {sum(ours) / len(ours):.2f} over {len(ours)} pairs")


main()
