#!/usr/bin/env bash
# How the generic `lucent explain PROGRAM --why ATOM` scales with program size (issue 14, item 6):
# for each benchmark row, the wall time of solving alone (`lucent ENC INST`, first model) and of
# `--why` on one atom of that first model (ground with provenance, solve, build and re-check the
# proof tree), the ground program's size (lines of `lucent --text`) and the proof tree's size
# (nodes in the `--outf=2` JSON).
#
# Usage: [LUCENT=path/to/lucent] scripts/bench_why.sh [BENCH_DIR] [TIMEOUT_SECONDS]
#   BENCH_DIR defaults to ../shared/data/bench (the folder holding MANIFEST.tsv). The atom asked
#   about is the last shown atom of the first model. Without LUCENT, a release binary is built.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
bench="${1:-$here/../shared/data/bench}"
limit="${2:-120}"
if [ -z "${LUCENT:-}" ]; then
  cargo build --quiet --release --no-default-features --bin lucent --manifest-path "$here/Cargo.toml"
  LUCENT="$here/target/release/lucent"
fi
lucent="$LUCENT"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

rows=(
  "tc/encoding.lp tc/chain-400.lp"
  "tc/encoding.lp tc/tc-n300-m600-s51.lp"
  "tc/encoding.lp tc/tc-n500-m1000-s52.lp"
  "tc/encoding.lp tc/tc-n800-m1300-s53.lp"
  "color/encoding.lp color/rand-n350-m820-s12.lp"
  "color/encoding.lp color/rand-n500-m1175-s10.lp"
  "hamcycle/encoding.lp hamcycle/ham-n600-e3000-s47.lp"
  "hamcycle/encoding.lp hamcycle/ham-n1000-e5000-s48.lp"
  "queens/encoding.lp queens/size-030.lp"
  "planning-ricochet/encoding_single.asp planning-ricochet/038-ricochetrobot-13-0.asp"
  "planning-labyrinth/encoding_single.asp planning-labyrinth/0025-labyrinth-14-0.asp"
)

secs() { echo "$2 - $1" | bc -l | awk '{printf "%.3f", $1}'; }

printf "| program | ground lines | solve s | --why s | ratio | tree nodes | atom |\n|---|---|---|---|---|---|---|\n"
for row in "${rows[@]}"; do
  set -- $row
  enc="$bench/$1"; inst="$bench/$2"
  t0=$(date +%s.%N)
  timeout "$limit" "$lucent" "$enc" "$inst" >"$tmp/solve.out" 2>/dev/null || true
  t1=$(date +%s.%N)
  atom=$(awk '/^Answer: 1/{getline; print; exit}' "$tmp/solve.out" | tr ' ' '\n' | grep -v '^$' | tail -1 || true)
  if [ -z "$atom" ]; then
    echo "| $2 | - | $(secs "$t0" "$t1") | no model | | | |"
    continue
  fi
  lines=$(timeout "$limit" "$lucent" --text "$enc" "$inst" 2>/dev/null | wc -l || echo -)
  t2=$(date +%s.%N)
  timeout "$limit" "$lucent" explain "$enc" "$inst" --why "$atom" --outf=2 >"$tmp/why.out" 2>"$tmp/why.err" || true
  t3=$(date +%s.%N)
  nodes=$(python3 -c 'import json,sys
try:
    d=json.load(open(sys.argv[1])); print(len(d.get("tree",{}).get("nodes",[])))
except Exception as e:
    print("fail")' "$tmp/why.out")
  s=$(secs "$t0" "$t1"); w=$(secs "$t2" "$t3")
  r=$(echo "$w / $s" | bc -l | awk '{printf "%.2f", $1}')
  echo "| $2 | $lines | $s | $w | $r | $nodes | \`$atom\` |"
done
