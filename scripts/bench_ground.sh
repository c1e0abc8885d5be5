#!/usr/bin/env bash
# Grounds every (encoding, instance, args) row of a benchmark MANIFEST.tsv with gringo and with
# Lucent's grounder (examples/ground.rs, aspif output) in one run, and prints per row the number
# of ground rules (aspif statements `1 ...`) and the wall time of each, with the ratios and their
# geometric means.
#
# Usage: scripts/bench_ground.sh [BENCH_DIR] [TIMEOUT_SECONDS]
#   BENCH_DIR defaults to ../shared/data/bench (the folder holding MANIFEST.tsv).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bench="${1:-$here/../shared/data/bench}"
limit="${2:-120}"
command -v gringo >/dev/null || { echo "install clingo: apt-get install -y gringo clasp" >&2; exit 1; }
cargo build --quiet --release --no-default-features --example ground --manifest-path "$here/Cargo.toml"
ours="$here/target/release/examples/ground"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# run NAME CMD... : time a grounder, leave its output in $tmp/NAME.out; prints "seconds rules".
run() {
  local name="$1"; shift
  local t0 t1 rc=0
  t0=$(date +%s.%N)
  timeout "$limit" "$@" >"$tmp/$name.out" 2>"$tmp/$name.err" || rc=$?
  t1=$(date +%s.%N)
  if [ "$rc" -ne 0 ]; then
    echo "fail($rc) -"
  else
    echo "$(echo "$t1 - $t0" | bc -l) $(grep -c '^1 ' "$tmp/$name.out" || true)"
  fi
}

printf '%-60s %10s %10s %7s %9s %9s %7s\n' row gringo_rules lucent_rules r_ratio gringo_s lucent_s t_ratio
tail -n +2 "$bench/MANIFEST.tsv" | cut -f1-4 | sort -u | while IFS=$'\t' read -r family enc inst args; do
  # shellcheck disable=SC2086
  read -r gt gr < <(run gringo gringo --output=intermediate $args "$bench/$enc" "$bench/$inst")
  # shellcheck disable=SC2086
  read -r lt lr < <(run lucent "$ours" $args "$bench/$enc" "$bench/$inst")
  name="$(basename "$inst" .lp)"; name="${family}/${name%.asp}${args:+ $args}"
  if [[ "$gt" == fail* || "$lt" == fail* ]]; then
    printf '%-60s %10s %10s %7s %9s %9s %7s\n' "$name" "$gr" "$lr" - "$gt" "$lt" -
  else
    rr=$(echo "$lr / $gr" | bc -l 2>/dev/null || echo 0)
    tr=$(echo "$lt / $gt" | bc -l)
    printf '%-60s %10d %10d %7.2f %9.3f %9.3f %7.2f\n' "$name" "$gr" "$lr" "$rr" "$gt" "$lt" "$tr"
  fi
done | tee "$tmp/table"
awk 'NR > 1 && $(NF-3) ~ /^[0-9.]+$/ && $(NF-3) > 0 && $NF ~ /^[0-9.]+$/ && $NF > 0 {
       n++; r += log($(NF-3)); t += log($NF) }
     END { if (n) printf "geometric mean over %d rows: rules %.2fx, time %.2fx\n", n, exp(r/n), exp(t/n) }' "$tmp/table"
