#!/usr/bin/env bash
# Two cores (issue 31 item 3): runs, on the same inputs in one run, `lucent -t 1`, `lucent -t 2`,
# `clingo -t 1` and `clingo -t 2` over the benchmark pairs of ../shared/data/bench
# (MANIFEST.tsv, as scripts/bench_solve.sh) plus a generated 400-node colouring and a
# generated 60-person stable marriage, and prints per-row wall times, the ratios
# lucent(-t1)/lucent(-t2) (our speedup), clingo(-t1)/clingo(-t2), and lucent(-t2)/clingo(-t2),
# then their geometric means over the rows where lucent -t 1 takes over 1 s (the speedup
# figure) and over all rows. Both systems run from text (grounding included). Times are the
# minimum over REPS runs. A development script: it may read ../shared.
#
# Usage: scripts/bench_threads.sh [TIMEOUT_SECONDS] [ROW_REGEX]
# Environment: REPS (default 1), LUCENT (default $CARGO_TARGET_DIR/release/lucent).
# Needs clingo (apt-get install -y gringo clasp, or pip install clingo).
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BENCH=${BENCH_DIR:-$ROOT/../shared/data/bench}
LIMIT=${1:-120}
FILTER=${2:-.}
REPS=${REPS:-1}
command -v clingo >/dev/null || {
    echo "install clingo: apt-get install -y gringo clasp (or pip install clingo)" >&2
    exit 1
}
LUCENT=${LUCENT:-${CARGO_TARGET_DIR:-$ROOT/target}/release/lucent}
[ -x "$LUCENT" ] || cargo build --quiet --release --manifest-path "$ROOT/Cargo.toml" || exit 1
TMP=${TMPDIR:-/tmp}/lucent-bench-threads
mkdir -p "$TMP"
echo "load before: $(uptime)"

# Generated rows: a 400-node 3-colouring with 920 random edges (seed 31) and a 60-person stable
# marriage with random complete preference lists (seed 60); written once.
gen() {
    python3 - "$TMP" <<'EOF'
import random, sys, os
d = sys.argv[1]
r = random.Random(31)
with open(os.path.join(d, "colour.lp"), "w") as f:
    f.write("col(1..3). node(1..400).\n")
    edges = set()
    while len(edges) < 920:
        u, v = r.randrange(1, 401), r.randrange(1, 401)
        if u != v:
            edges.add((min(u, v), max(u, v)))
    for u, v in sorted(edges):
        f.write(f"edge({u},{v}).\n")
    f.write("1 { c(N,C) : col(C) } 1 :- node(N).\n:- edge(U,V), c(U,C), c(V,C).\n")
r = random.Random(60)
n = 60
with open(os.path.join(d, "marriage.lp"), "w") as f:
    for who in ("m", "w"):
        for i in range(1, n + 1):
            prefs = list(range(1, n + 1))
            r.shuffle(prefs)
            for rank, j in enumerate(prefs, 1):
                f.write(f"pref({who},{i},{j},{rank}).\n")
    f.write(
        "man(1..%d). woman(1..%d).\n"
        "1 { match(M,W) : woman(W) } 1 :- man(M).\n"
        ":- match(M1,W), match(M2,W), M1 < M2.\n"
        "better_m(M,W,W2) :- pref(m,M,W,R), pref(m,M,W2,R2), R < R2.\n"
        "better_w(W,M,M2) :- pref(w,W,M,R), pref(w,W,M2,R2), R < R2.\n"
        "has(M,W2) :- match(M,W2).\n"
        ":- man(M), woman(W), not match(M,W), match(M,W2), better_m(M,W,W2),\n"
        "   match(M2,W), better_w(W,M,M2).\n" % (n, n)
    )
EOF
}
[ -s "$TMP/colour.lp" ] && [ -s "$TMP/marriage.lp" ] || gen

now() { date +%s.%N; }
# result word of clingo-style output
result() { grep -E -m1 '^(SATISFIABLE|UNSATISFIABLE|OPTIMUM FOUND|UNKNOWN)$' || echo TIMEOUT; }
# min wall time over REPS runs of "$@"; prints "seconds result"
timed() {
    best="" res=""
    for _ in $(seq "$REPS"); do
        t0=$(now)
        out=$(timeout "$LIMIT" "$@" 2>/dev/null | result)
        t1=$(now)
        t=$(echo "$t1 - $t0" | bc)
        [ "$(echo "$t >= $LIMIT" | bc)" = 1 ] && out=TIMEOUT
        if [ -z "$best" ] || [ "$(echo "$t < $best" | bc)" = 1 ]; then best=$t; fi
        res=$out
    done
    echo "$best $res"
}

rows() {
    echo "generated colour-n400 - $TMP/colour.lp n1"
    echo "generated marriage-n60 - $TMP/marriage.lp n1"
    # Rows without extra arguments; the instance's file name names the row.
    tail -n +2 "$BENCH/MANIFEST.tsv" |
        awk -F'\t' -v B="$BENCH" '$4=="" { k=split($3, p, "/"); print $1, p[k], B"/"$2, B"/"$3, $5 }'
}

printf "%-18s %-32s %-4s %8s %8s %8s %8s %7s %7s %7s  %s\n" family instance mode l1_s l2_s c1_s c2_s l1/l2 c1/c2 l2/c2 results
OUT="$TMP/rows.$$"
: >"$OUT"
rows | while read -r family inst enc file mode; do
    [[ "$family $inst" =~ $FILTER ]] || continue
    files="$file"
    [ "$enc" != "-" ] && files="$enc $file"
    case $mode in n1) n="-n1";; n0) n="-n0";; *) n="";; esac
    # shellcheck disable=SC2086
    read -r l1 r1 < <(timed "$LUCENT" $n -q -t 1 $files)
    # shellcheck disable=SC2086
    read -r l2 r2 < <(timed "$LUCENT" $n -q -t 2 $files)
    # shellcheck disable=SC2086
    read -r c1 s1 < <(timed clingo $n -q -t 1 $files)
    # shellcheck disable=SC2086
    read -r c2 s2 < <(timed clingo $n -q -t 2 $files)
    rr=$(echo "scale=2; $l1/($l2+0.001)" | bc -l)
    cr=$(echo "scale=2; $c1/($c2+0.001)" | bc -l)
    lc=$(echo "scale=2; $l2/($c2+0.001)" | bc -l)
    agree="$r1/$r2/$s1/$s2"
    printf "%-18s %-32s %-4s %8.3f %8.3f %8.3f %8.3f %7s %7s %7s  %s\n" "$family" "$(basename "$inst")" "$mode" "$l1" "$l2" "$c1" "$c2" "$rr" "$cr" "$lc" "$agree"
    case "$agree" in *TIMEOUT*) ;; *) echo "$l1 $l2 $c1 $c2" >>"$OUT" ;; esac
done
awk '
function g(s, n) { return n ? exp(s / n) : 0 }
{ l1=($1<0.01?0.01:$1); l2=($2<0.01?0.01:$2); c1=($3<0.01?0.01:$3); c2=($4<0.01?0.01:$4)
  a+=log(l1/l2); b+=log(c1/c2); c+=log(l2/c2); n++
  if ($1 > 1) { A+=log(l1/l2); B+=log(c1/c2); C+=log(l2/c2); N++ } }
END {
  printf "rows over 1 s at lucent -t 1: %d; geometric means: lucent t1/t2 %.2f, clingo t1/t2 %.2f, lucent t2 / clingo t2 %.2f\n", N, g(A,N), g(B,N), g(C,N)
  printf "all %d finished rows: lucent t1/t2 %.2f, clingo t1/t2 %.2f, lucent t2 / clingo t2 %.2f\n", n, g(a,n), g(b,n), g(c,n)
}' "$OUT"
rm -f "$OUT"
echo "load after: $(uptime)"
