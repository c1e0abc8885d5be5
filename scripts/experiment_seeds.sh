#!/usr/bin/env bash
# Several seeds of the paper's experiments H1-H4 in ONE GNU parallel invocation, then one pooled
# report. Every trial computes all readings of docs/experiments/gaps.md (H2's one-missing
# readings, iterative and fixed, and L*+1; H4's one-missing), so the job list is the whole
# experiment. Seed S runs in OUT/seed-S (a rerun reuses the stored trials: an interrupted run
# resumes); the pooled report goes to OUT/seeds. The classification experiment is not a trial
# (`lucent experiment all` runs it in process), so it is not in the job list.
#
# usage: scripts/experiment_seeds.sh OUT [SEEDS] [JOBS] [lucent experiment options...]
#   SEEDS: a list as "0 1 2 3 4" (default); JOBS: parallel's -j (default 2, this machine's cores);
#   further options go to every seed's `lucent experiment all` (e.g. a small configuration:
#   --runs 2 --episodes 1 --configurations 1 --goals 1)
# Each seed's job list lists H1 first (H2-H4 trials read the learned axioms of H1's runs), and
# the lists are concatenated seed by seed, so whole seeds finish in order.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:?usage: experiment_seeds.sh OUT [SEEDS] [JOBS]}"
seeds="${2:-0 1 2 3 4}"
jobs="${3:-2}"
shift $(( $# < 3 ? $# : 3 ))
bin="${CARGO_TARGET_DIR:-target}/release/lucent"
cargo build --release --quiet
mkdir -p "$out"
: > "$out/jobs.txt"
dirs=()
for s in $seeds; do
  "$bin" experiment all --seed "$s" --out "$out/seed-$s" --emit-jobs "$out/seed-$s/jobs.txt" "$@" 2>/dev/null
  cat "$out/seed-$s/jobs.txt" >> "$out/jobs.txt"
  dirs+=("$out/seed-$s")
done
echo "$(wc -l < "$out/jobs.txt") jobs for seeds ${seeds}; load average $(cut -d' ' -f1-3 /proc/loadavg)"
start=$(date +%s)
# One process per job and one thread each (RAYON_NUM_THREADS), JOBS at a time.
RAYON_NUM_THREADS=1 parallel --will-cite --halt now,fail=1 -j "$jobs" --joblog "$out/joblog.txt" < "$out/jobs.txt"
end=$(date +%s)
echo "parallel: $((end - start)) s wall; load average after $(cut -d' ' -f1-3 /proc/loadavg)"
"$bin" experiment merge "${dirs[@]}" --out "$out/seeds" > /dev/null
echo "pooled report: $out/seeds/report.md"
