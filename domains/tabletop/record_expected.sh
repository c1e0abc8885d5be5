#!/usr/bin/env bash
# Records expected/plans.json from clingo (the reference, never part of Lucent).
# clingo has no CR rules, so the one CR rule `d1` is rewritten into its cardinality-minimal
# encoding (docs/reference.md, docs/domain.md 3.4): guess the application atom when the body holds,
# derive the head, minimize the number of applications. Then all optimal models are kept.
set -euo pipefail
cd "$(dirname "$0")"
# clingo exits 10/20/30 on success (model found / none / exhausted).
clingo_ok() { clingo "$@" || [ $? -ge 10 ]; }
sed -e 's/^d1(A, I): holds(stable(A), I) :+ holds(small_base(A), I)\./{ appl(d1(A, I)) } :- holds(small_base(A), I). holds(stable(A), I) :- appl(d1(A, I)). #minimize { 1@1, X : appl(X) }./' tabletop.lp \
  | clingo_ok --opt-mode=optN -n0 --project --outf=2 - \
  | python3 -c '
import json, sys
d = json.load(sys.stdin)
ws = [w for c in d["Call"] for w in c["Witnesses"]]
best = min(tuple(w.get("Costs", [])) for w in ws)
plans = sorted({tuple(sorted(w["Value"])) for w in ws if tuple(w.get("Costs", [])) == best})
out = {"command": "domains/tabletop/record_expected.sh (" + d["Solver"] + ")",
       "models": [list(p) for p in plans]}
json.dump(out, sys.stdout, indent=1)
print()' > expected/plans.json
