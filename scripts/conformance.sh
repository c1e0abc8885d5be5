#!/usr/bin/env bash
# The shared conformance checks, run by .ci/run when ../shared is present (the repository itself
# never depends on it). Argument: the shared folder (default ../shared).
#  1. The parser over every program in shared/data: no panic, spans in range, round trip.
#  2. The clingo test suite through Lucent end to end, through gringo|lucent --mode=clasp, and
#     through lucent --mode=gringo|clasp.
#  3. Incremental mode: Lucent's and clingo's `#include <incmode>` cases (scripts/incmode_check.py).
#  4. The SPARC robot-assistant programs against SPARC's recorded answers.
# Exit status: non-zero when any check fails.
set -uo pipefail
cd "$(dirname "$0")/.."
shared=$(cd "${1:-../shared}" && pwd)
status=0
step() { echo; echo "== $*"; }

# The simulator is not needed here; leaving it out keeps CI's second build short.
cargo build --release --quiet --no-default-features --bin lucent --examples || exit 1
# The build's own target directory (CARGO_TARGET_DIR when set, as cargo uses it).
target=${CARGO_TARGET_DIR:-$PWD/target}
lucent=$target/release/lucent
export LUCENT=$lucent

step "parser over every program in $shared/data"
"$target/release/examples/parse_corpus" "$shared/data" || status=1

# Each suite run is compared with its list of known failures (scripts/known-failures/): a
# failure not on the list fails CI; a listed case that passes is reported, so the list shrinks.
for combo in lucent gringo-lucent lucent-clasp; do
  case $combo in
    lucent) solver=$lucent ;;
    *) solver="scripts/split_pipeline.sh $combo" ;;
  esac
  step "clingo test suite with: $solver"
  out=$(python3 "$shared/tools/clingo_suite_check.py" --solver "$solver" --timeout 60)
  echo "$out" | tail -1
  known=scripts/known-failures/$combo.txt
  failed=$(echo "$out" | sed -n 's/^FAIL \([^ ]* [^:]*\):.*/\1/p' | sort -u)
  new=$(comm -23 <(echo "$failed" | sed '/^$/d') <(grep -v '^#' "$known" | sort -u))
  fixed=$(comm -13 <(echo "$failed" | sed '/^$/d') <(grep -v '^#' "$known" | sort -u))
  if [ -n "$new" ]; then
    echo "NEW failures (not in $known):"; echo "$out" | grep -F -f <(echo "$new") | cut -c1-300
    status=1
  fi
  [ -z "$fixed" ] || { echo "now passing (remove from $known):"; echo "$fixed"; }
  echo "known failures still failing: $(comm -12 <(echo "$failed" | sed '/^$/d') <(grep -v '^#' "$known" | sort -u) | grep -c .)"
done

step "incremental mode (#include <incmode>): tests/data/incmode and clingo's app-incmode cases"
python3 scripts/incmode_check.py --solver "$lucent" tests/data/incmode "$shared/data/clingo-tests/app-incmode" || status=1

step "SPARC robot-assistant programs"
python3 scripts/sparc_check.py "$lucent" "$shared/data/sparc" || status=1

exit $status
