#!/usr/bin/env bash
# End to end against clingo: runs clingo and `lucent` on the same benchmark pairs of
# ../shared/data/bench, side by side in one run (the shared bench_compare.py alternates the
# two so machine noise hits both), checks that the answers agree, and prints per-row time
# ratios and their geometric mean. A development script: it may read ../shared.
#
# Usage: scripts/bench_e2e.sh [extra bench_compare.py arguments, e.g. --rows queens --timeout 60]
set -euo pipefail
cd "$(dirname "$0")/.."
shared=${SHARED:-../shared}
cargo build --quiet --release --no-default-features --bin lucent
exec python3 "$shared/tools/bench_compare.py" --ours "$PWD/target/release/lucent" --ref clingo "$@"
