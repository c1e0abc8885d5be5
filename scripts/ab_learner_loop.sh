#!/bin/bash
# Compares learner_loop builds (examples/learner_loop.rs) on one machine: ROUNDS rounds, each
# running every binary once for N calls, one after the other, so that a shared machine's drift
# hits them alike. Prints, per binary, the fastest and the median run and the fastest run's time
# per call. On a noisy machine the fastest run is the steadiest figure (the medians of two runs
# of the same binary differed by up to 8% on 2026-12-07; the fastest by 2%).
#
# usage: scripts/ab_learner_loop.sh N ROUNDS BIN... [-- PROGRAM]
#        (PROGRAM defaults to benches/data/learner_step.lp)
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
n=$1 rounds=$2
shift 2
bins=()
program=$root/benches/data/learner_step.lp
while [ $# -gt 0 ]; do
    if [ "$1" = "--" ]; then program=$2; break; fi
    bins+=("$1"); shift
done
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for r in $(seq "$rounds"); do
    for i in "${!bins[@]}"; do
        "${bins[$i]}" "$program" "$n" | sed -E 's/.*seconds=([0-9.]+).*/\1/' >> "$tmp/$i"
    done
done
for i in "${!bins[@]}"; do
    sort -n "$tmp/$i" | awk -v b="${bins[$i]}" -v n="$n" \
        '{a[NR]=$1} END {printf "%s fastest %.3f s, median %.3f s, fastest %.1f us a call\n", b, a[1], a[int((NR+1)/2)], a[1]*1e6/n}'
done
