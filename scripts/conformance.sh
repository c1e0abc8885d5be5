#!/usr/bin/env bash
# The shared conformance checks, run by .ci/run when ../shared is present (the repository itself
# never depends on it). Argument: the shared folder (default ../shared).
#  1. The parser over every program in shared/data: no panic, spans in range, round trip.
#  2. The clingo test suite through Lucent end to end, through gringo|lucent --mode=clasp, and
#     through lucent --mode=gringo|clasp.
#  3. The SPARC robot-assistant programs against SPARC's recorded answers.
# Exit status: non-zero when any check fails.
set -uo pipefail
cd "$(dirname "$0")/.."
shared=$(cd "${1:-../shared}" && pwd)
status=0
step() { echo; echo "== $*"; }

# The simulator is not needed here; leaving it out keeps CI's second build short.
cargo build --release --quiet --no-default-features --bin lucent --examples || exit 1
lucent=$PWD/target/release/lucent
export LUCENT=$lucent

step "parser over every program in $shared/data"
target/release/examples/parse_corpus "$shared/data" || status=1

for solver in "$lucent" "scripts/split_pipeline.sh gringo-lucent" "scripts/split_pipeline.sh lucent-clasp"; do
  step "clingo test suite with: $solver"
  python3 "$shared/tools/clingo_suite_check.py" --solver "$solver" --timeout 60 || status=1
done

step "SPARC robot-assistant programs"
python3 scripts/sparc_check.py "$lucent" "$shared/data/sparc" || status=1

exit $status
