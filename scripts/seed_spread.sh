#!/usr/bin/env bash
# How much of a row's solving time is luck: runs clasp and Lucent's solver side by side on the
# same aspif files with seeds 1..SEEDS and a small random-decision frequency (clasp's
# `--seed=S --rand-freq=R`, the same flags for examples/solve_aspif), and prints per seed the
# conflicts and wall time of both, then per file the medians and the ratio of the median times.
# A run that hits the time limit counts as the limit (so a median is a lower bound when half or
# more of a tool's runs time out, marked with `>`). A development script: it may read ../shared.
#
# Usage: scripts/seed_spread.sh FILE.aspif...      (aspif from `gringo ENC INST -o intermediate`)
# Environment: SEEDS (default 5), RAND (default 0.01), LIMIT (seconds per run, default 60).
# Needs clasp (apt-get install -y gringo clasp).
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
SEEDS=${SEEDS:-5}
RAND=${RAND:-0.01}
LIMIT=${LIMIT:-60}
command -v clasp >/dev/null || {
    echo "install clasp: apt-get install -y gringo clasp" >&2
    exit 1
}
[ $# -ge 1 ] || {
    echo "usage: scripts/seed_spread.sh FILE.aspif..." >&2
    exit 2
}
cargo build --quiet --release --no-default-features --example solve_aspif --manifest-path "$ROOT/Cargo.toml" || exit 1
OURS=${CARGO_TARGET_DIR:-$ROOT/target}/release/examples/solve_aspif

now() { date +%s.%N; }
# Runs "$@" under the limit; prints "CONFLICTS SECONDS" (conflicts "-" on a timeout).
measure() {
    local t0 t1 out c
    t0=$(now)
    out=$(timeout "$LIMIT" "$@" 2>/dev/null)
    t1=$(now)
    c=$(echo "$out" | awk '/^Conflicts/{print $3; exit}')
    if ! echo "$out" | grep -qE '^(SATISFIABLE|UNSATISFIABLE|OPTIMUM FOUND)$'; then
        echo "- $LIMIT"
    else
        echo "${c:-0} $(echo "$t1 - $t0" | bc)"
    fi
}
# Median of the numbers on stdin (the lower middle one for an even count).
median() { sort -g | awk '{v[NR]=$1} END { print v[int((NR+1)/2)] }'; }

printf "%-28s %4s %10s %9s %10s %9s\n" file seed clasp_cfl clasp_s lucent_cfl lucent_s
for f in "$@"; do
    ct=() ot=()
    for s in $(seq 1 "$SEEDS"); do
        read -r cc cs < <(measure clasp -q --stats --seed="$s" --rand-freq="$RAND" "$f")
        read -r oc os < <(measure "$OURS" -q --stats --seed="$s" --rand-freq="$RAND" "$f")
        printf "%-28s %4d %10s %9.3f %10s %9.3f\n" "$(basename "$f")" "$s" "$cc" "$cs" "$oc" "$os"
        ct+=("$cs") ot+=("$os")
    done
    cm=$(printf "%s\n" "${ct[@]}" | median)
    om=$(printf "%s\n" "${ot[@]}" | median)
    cmark=""; omark=""
    [ "$(echo "$cm >= $LIMIT" | bc)" = 1 ] && cmark=">"
    [ "$(echo "$om >= $LIMIT" | bc)" = 1 ] && omark=">"
    printf "%-28s median time: clasp %s%.3f s, lucent %s%.3f s, lucent/clasp %.2f\n" \
        "$(basename "$f")" "$cmark" "$cm" "$omark" "$om" "$(echo "$om/$cm" | bc -l)"
done
