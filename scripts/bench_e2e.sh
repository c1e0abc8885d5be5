#!/usr/bin/env bash
# End to end against clingo: runs clingo and `lucent` on the same benchmark pairs of
# ../shared/data/bench, side by side in one run (scripts/bench_e2e.py alternates the two so
# machine noise hits both), checks that the answers agree, and prints per-row time ratios and
# peak-memory (max RSS) ratios with the geometric mean of each. A development script: it may
# read ../shared.
#
# Usage: scripts/bench_e2e.sh [extra bench_e2e.py arguments, e.g. --rows queens --timeout 60]
set -euo pipefail
cd "$(dirname "$0")/.."
shared=${SHARED:-../shared}
cargo build --quiet --release --no-default-features --bin lucent
exec python3 scripts/bench_e2e.py --manifest "$shared/data/bench/MANIFEST.tsv" \
    --ours "$PWD/target/release/lucent" --ref clingo "$@"
