#!/usr/bin/env bash
# Runs clasp and Lucent's solver side by side on the aspif that gringo makes from the benchmark
# pairs in ../shared/data/bench (MANIFEST.tsv), and prints per-row times, the ratio
# lucent/clasp, peak memory (maximum RSS from GNU time, `/usr/bin/time -f %M`) and its ratio,
# whether both agree (result and model count, or optimum), and the geometric means of the time
# and memory ratios over the rows both finished. A development script: it may read ../shared.
#
# Usage: scripts/bench_solve.sh [TIMEOUT_SECONDS] [FAMILY_REGEX]
# Environment: THREADS=N runs both with N threads (clasp `-t N`, its own portfolio; Lucent
# `--parallel-mode=N`); the default is one thread each.
# Needs gringo and clasp (apt-get install -y gringo clasp) and GNU time (apt-get install -y time).
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BENCH=${BENCH_DIR:-$ROOT/../shared/data/bench}
LIMIT=${1:-60}
FILTER=${2:-.}
command -v gringo >/dev/null && command -v clasp >/dev/null || {
    echo "install clingo: apt-get install -y gringo clasp" >&2
    exit 1
}
[ -x /usr/bin/time ] || {
    echo "peak memory needs GNU time: apt-get install -y time" >&2
    exit 1
}
cargo build --quiet --release --no-default-features --example solve_aspif --manifest-path "$ROOT/Cargo.toml" || exit 1
OURS=${CARGO_TARGET_DIR:-$ROOT/target}/release/examples/solve_aspif
TMP=${TMPDIR:-/tmp}/lucent-bench-solve
mkdir -p "$TMP"

now() { date +%s.%N; }
# Peak RSS in KiB of the last command run under `/usr/bin/time -o "$TMP/rss.$$"` (the last line:
# GNU time writes "Command exited with non-zero status N" first when the exit code is not 0).
rss() { tail -n 1 "$TMP/rss.$$" 2>/dev/null | grep -E '^[0-9]+$' || echo 0; }
# result word and model count from clasp-style output
summary() { awk '/^(SATISFIABLE|UNSATISFIABLE|OPTIMUM FOUND|UNKNOWN)$/{r=$0} /^Models/{m=$3} /^Optimization *:/{o=""; for(i=3;i<=NF;i++) o=o" "$i} /^Optimization: /{last=""; for(i=2;i<=NF;i++) last=last" "$i} END{ if (o=="") o=last; printf "%s|%s|%s", r, m, o}'; }

printf "%-20s %-34s %-4s %9s %9s %8s %9s %9s %7s  %s\n" family instance mode clasp_s lucent_s ratio clasp_MB lucent_MB m_ratio agree
RATIOS=()
# Empty fields would collapse with a whitespace separator, so re-separate with a unit separator.
tail -n +2 "$BENCH/MANIFEST.tsv" | awk -F'\t' -v OFS=$'\x1f' '{print $1,$2,$3,($4==""?"-":$4),$5}' |
while IFS=$'\x1f' read -r family enc inst args mode; do
    [[ $family =~ $FILTER ]] || continue
    [ "$args" = "-" ] && args=
    key=$(echo "$enc $inst $args" | md5sum | cut -c1-12)
    aspif="$TMP/$key.aspif"
    if [ ! -s "$aspif" ]; then
        # shellcheck disable=SC2086
        timeout 300 gringo --output=intermediate "$BENCH/$enc" "$BENCH/$inst" $args >"$aspif" 2>/dev/null || { rm -f "$aspif"; echo "$family $inst: grounding failed"; continue; }
    fi
    case $mode in n1) nopt="-n1";; n0) nopt="-n0";; *) nopt="";; esac
    copt="" oopt=""
    if [ "${THREADS:-1}" -gt 1 ]; then copt="-t ${THREADS}"; oopt="--parallel-mode=${THREADS}"; fi
    t0=$(now); cout=$(/usr/bin/time -f %M -o "$TMP/rss.$$" timeout "$LIMIT" clasp $nopt $copt -q "$aspif" 2>/dev/null); t1=$(now)
    cm=$(rss)
    oout=$(/usr/bin/time -f %M -o "$TMP/rss.$$" timeout "$LIMIT" "$OURS" $nopt $oopt -q "$aspif" 2>/dev/null); t2=$(now)
    om=$(rss)
    ct=$(echo "$t1 - $t0" | bc); ot=$(echo "$t2 - $t1" | bc)
    cs=$(echo "$cout" | summary); os=$(echo "$oout" | summary)
    # A solver stopped by `timeout` may still print its last result (clasp answers SIGTERM with
    # the best model so far), so a run that reached the limit is a timeout whatever it printed.
    if [ -z "${cs%%|*}" ] || [ "$(echo "$ct >= $LIMIT" | bc)" = 1 ]; then cs="TIMEOUT||"; fi
    if [ -z "${os%%|*}" ] || [ "$(echo "$ot >= $LIMIT" | bc)" = 1 ]; then os="TIMEOUT||"; fi
    if [ "$mode" = opt ]; then
        # The number of improving models depends on the search; compare result and optimum.
        cs="${cs%%|*}|${cs##*|}"; os="${os%%|*}|${os##*|}"
    fi
    if [ "$cs" = "$os" ]; then agree=yes; else agree="NO clasp=[$cs] lucent=[$os]"; fi
    ratio=$(echo "r=$ot/($ct+0.001); scale=2; r/1" | bc -l)
    mratio=$(echo "r=$om/($cm+1); scale=2; r/1" | bc -l)
    [[ $cs == TIMEOUT* || $os == TIMEOUT* ]] && ratio="-" && mratio="-"
    printf "%-20s %-34s %-4s %9.3f %9.3f %8s %9.1f %9.1f %7s  %s\n" "$family" "$(basename "$inst")" "$mode" "$ct" "$ot" "$ratio" \
        "$(echo "$cm/1024" | bc -l)" "$(echo "$om/1024" | bc -l)" "$mratio" "$agree"
    [ "$ratio" != "-" ] && echo "$ct $ot $cm $om" >>"$TMP/ratios.$$"
done
rm -f "$TMP"/rss.*
if [ -s "$TMP/ratios."* ] 2>/dev/null || ls "$TMP"/ratios.* >/dev/null 2>&1; then
    cat "$TMP"/ratios.* | awk '{ c=($1<0.01?0.01:$1); o=($2<0.01?0.01:$2); s+=log(o/c); n++ } END { if (n) printf "geometric mean of lucent/clasp time ratios over %d rows (times floored at 10 ms): %.2f\n", n, exp(s/n) }'
    cat "$TMP"/ratios.* | awk '$3>0 && $4>0 { r=$4/$3; s+=log(r); n++; if (r>w) w=r } END { if (n) printf "geometric mean of lucent/clasp peak-memory ratios over %d rows: %.2f (worst %.2f)\n", n, exp(s/n), w }'
    rm -f "$TMP"/ratios.*
fi
