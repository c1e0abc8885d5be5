#!/usr/bin/env bash
# Runs examples/solve_aspif with the given search flags on the aspif of every benchmark pair
# (the rows of ../shared/data/bench/MANIFEST.tsv, ground by gringo as scripts/bench_solve.sh
# does and cached in the same place) and prints, per row, the conflicts, the solving time and
# the result; the last line gives the geometric mean of the conflicts (a row that hits the
# conflict or time limit counts with its count at the stop). Conflict counts are
# deterministic, so two settings are compared with `scripts/tune_search.sh --compare A B`
# even on a busy machine. A development script: it may read ../shared.
#
# Usage: scripts/tune_search.sh OUT.tsv [SOLVE_ASPIF_FLAGS...]
#        scripts/tune_search.sh --compare A.tsv B.tsv
# Environment: LIMIT (conflicts, default 300000), SECS (seconds per row, default 30),
# JOBS (parallel rows, default 2), FILTER (regex on the family), SKIP (regex on family/instance
# of rows to leave out, e.g. those clasp does not solve in time), GROUNDER (gringo, the default,
# or lucent: ground with `lucent --mode=gringo` instead, afresh on every run, to compare the
# search on our ground program with the search on gringo's), CLOCK (`wall`, the default, or
# `cpu`: the time column holds user plus system seconds instead of elapsed ones, which a busy
# shared machine disturbs much less; the time limit SECS stays in elapsed seconds).
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
if [ "${1:-}" = --compare ]; then
    # Per-row conflict ratio B/A and the geometric means of conflicts and times.
    join -t $'\t' <(sort "$2") <(sort "$3") | awk -F'\t' '
        { a=($2<1?1:$2); b=($5<1?1:$5); ta=($3<0.01?0.01:$3); tb=($6<0.01?0.01:$6);
          r=b/a; s+=log(r); st+=log(tb/ta); n++;
          printf "%-52s %9d %9d %7.2f %8.3f %8.3f %s%s\n", $1, $2, $5, r, $3, $6, ($4!=$7?"RESULT "$4"/"$7:""), (r>2||r<0.5?" *":"") }
        END { printf "rows %d: geomean conflicts B/A %.3f, time B/A %.3f\n", n, exp(s/n), exp(st/n) }'
    exit 0
fi
OUT=$1
shift
BENCH=${BENCH_DIR:-$ROOT/../shared/data/bench}
TMP=${TMPDIR:-/tmp}/lucent-bench-solve
OURS=${CARGO_TARGET_DIR:-$ROOT/target}/release/examples/solve_aspif
LUCENT=${CARGO_TARGET_DIR:-$ROOT/target}/release/lucent
LTMP=$(mktemp -d "${TMPDIR:-/tmp}/lucent-bench-ground.XXXXXX")
trap 'rm -rf "$LTMP"' EXIT
mkdir -p "$TMP"
export OURS TMP LIMIT=${LIMIT:-300000} SECS=${SECS:-30} CLOCK=${CLOCK:-wall}
run_row() {
    # $1 label, $2 aspif, $3 mode, then flags
    local label=$1 aspif=$2 mode=$3
    shift 3
    local nopt=""
    case $mode in n1) nopt="-n1" ;; n0) nopt="-n0" ;; esac
    local t0 t1 out secs cpu
    cpu=$(mktemp)
    t0=$(date +%s.%N)
    out=$(/usr/bin/time -f '%U %S' -o "$cpu" timeout "$SECS" "$OURS" $nopt -q --stats --solve-limit="$LIMIT" "$@" "$aspif" 2>/dev/null)
    t1=$(date +%s.%N)
    if [ "$CLOCK" = cpu ]; then
        secs=$(awk 'END{print $1 + $2}' "$cpu")
    else
        secs=$(echo "$t1 - $t0" | bc)
    fi
    rm -f "$cpu"
    local c r
    c=$(echo "$out" | awk '/^Conflicts/{print $3}')
    r=$(echo "$out" | awk '/^(SATISFIABLE|UNSATISFIABLE|OPTIMUM FOUND|UNKNOWN)$/{r=$0} END{print (r==""?"TIMEOUT":r)}')
    [ -z "$c" ] && c=$LIMIT
    printf "%s\t%s\t%.3f\t%s\n" "$label" "$c" "$secs" "${r// /_}"
}
export -f run_row
tail -n +2 "$BENCH/MANIFEST.tsv" | awk -F'\t' -v OFS=$'\x1f' '{print $1,$2,$3,($4==""?"-":$4),$5}' |
    while IFS=$'\x1f' read -r family enc inst args mode; do
        [[ $family =~ ${FILTER:-.} ]] || continue
        [ -n "${SKIP:-}" ] && [[ "$family/$inst" =~ $SKIP ]] && continue
        [ "$args" = "-" ] && args=
        key=$(echo "$enc $inst $args" | md5sum | cut -c1-12)
        aspif="$TMP/$key.aspif"
        if [ "${GROUNDER:-gringo}" = lucent ]; then
            aspif="$LTMP/$key.aspif"
            # shellcheck disable=SC2086
            timeout 300 "$LUCENT" --mode=gringo "$BENCH/$enc" "$BENCH/$inst" $args >"$aspif" 2>/dev/null || {
                rm -f "$aspif"
                continue
            }
        elif [ ! -s "$aspif" ]; then
            # shellcheck disable=SC2086
            timeout 300 gringo --output=intermediate "$BENCH/$enc" "$BENCH/$inst" $args >"$aspif" 2>/dev/null || {
                rm -f "$aspif"
                continue
            }
        fi
        printf '%s\0%s\0%s\0' "$family/$(basename "$enc" .asp)/$(basename "$inst")$args" "$aspif" "$mode"
    done | xargs -0 -n 3 -P "${JOBS:-2}" bash -c 'run_row "$@" '"$(printf '%q ' "$@")" _ | tr ' ' '_' >"$OUT"
awk -F'\t' '{ c=($2<1?1:$2); s+=log(c); n++ } END { printf "rows %d: geomean conflicts %.1f\n", n, exp(s/n) }' "$OUT"
