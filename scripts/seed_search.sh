#!/usr/bin/env bash
# Runs examples/solve_aspif with the given search flags on the heavy-tailed benchmark rows
# (by default labyrinth 0025/0060/0075/0082/0157) once per seed with `--seed=S --rand-freq=0.01`
# and prints, per row, the conflicts of each seed and their median (a run that hits the
# conflict or time limit counts with its count at the stop). Search on these rows is dominated
# by luck (clasp needs 617 to 50944 conflicts on labyrinth 0082 across seeds), so a setting is
# judged by the medians, beside the geomean of `scripts/tune_search.sh`. The aspif files are
# the ones `scripts/tune_search.sh` caches (run it once first). A development script: it may
# read ../shared.
#
# Usage: scripts/seed_search.sh [SOLVE_ASPIF_FLAGS...]
# Environment: LIMIT (conflicts, default 60000), SECS (seconds per run, default 60), SEEDS
# (default "1 2 3 4 5"), ROWS (regex on the instance, default the five labyrinth rows).
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BENCH=${BENCH_DIR:-$ROOT/../shared/data/bench}
TMP=${TMPDIR:-/tmp}/lucent-bench-solve
OURS=${CARGO_TARGET_DIR:-$ROOT/target}/release/examples/solve_aspif
LIMIT=${LIMIT:-60000}
SECS=${SECS:-60}
SEEDS=${SEEDS:-1 2 3 4 5}
ROWS=${ROWS:-labyrinth/(0025|0060|0075|0082|0157)-}
tail -n +2 "$BENCH/MANIFEST.tsv" | awk -F'\t' -v OFS=$'\x1f' '{print $2,$3,($4==""?"-":$4)}' |
    while IFS=$'\x1f' read -r enc inst args; do
        [[ $inst =~ $ROWS ]] || continue
        [ "$args" = "-" ] && args=
        key=$(echo "$enc $inst $args" | md5sum | cut -c1-12)
        aspif="$TMP/$key.aspif"
        if [ ! -s "$aspif" ]; then
            echo "$inst: no cached aspif (run scripts/tune_search.sh first)" >&2
            continue
        fi
        counts=()
        for s in $SEEDS; do
            out=$(timeout "$SECS" "$OURS" -q --stats --solve-limit="$LIMIT" --seed="$s" --rand-freq=0.01 "$@" "$aspif" 2>/dev/null)
            c=$(echo "$out" | awk '/^Conflicts/{print $3}')
            counts+=("${c:-$LIMIT}")
        done
        median=$(printf '%s\n' "${counts[@]}" | sort -n | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : int((a[NR/2]+a[NR/2+1])/2))}')
        printf "%s\t%s\tmedian %s\n" "$(basename "$(dirname "$enc")")/$(basename "$enc" .asp)/$(basename "$inst" .asp)" "${counts[*]}" "$median"
    done
