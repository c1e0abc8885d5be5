#!/usr/bin/env bash
# Wide terms and long lines, side by side with gringo/clingo 5.4: generates programs whose single
# line holds one very wide atom (issue 17: `p(0,1,...,N-1).`, N = 2,000,000 by default, a 15 MB
# line) and other wide shapes, and prints per row the processor time (user + system, stable on
# a shared machine) and the wall time of the reference and of Lucent, with the ratio of the
# processor times. Both sides write their output to a file, which is compared (aspif rows must
# be byte-identical to gringo's; end-to-end rows must agree on the result line).
#
# Usage: scripts/bench_wide.sh [N] [TIMEOUT_SECONDS]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
n="${1:-2000000}"
limit="${2:-300}"
command -v gringo >/dev/null || { echo "install clingo: apt-get install -y gringo clasp" >&2; exit 1; }
cargo build --quiet --release --no-default-features --manifest-path "$here/Cargo.toml"
lucent="$here/target/release/lucent"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

python3 - "$n" "$tmp" <<'PY'
import sys
n, tmp = int(sys.argv[1]), sys.argv[2]
args = ",".join(map(str, range(n)))
open(f"{tmp}/atom.lp", "w").write(f"p({args}).\n")
open(f"{tmp}/term.lp", "w").write(f"p(f({args})).\n")
open(f"{tmp}/facts.lp", "w").write(" ".join(f"q({i})." for i in range(n // 10)) + "\n")
open(f"{tmp}/pool.lp", "w").write("q(" + ";".join(map(str, range(n // 10))) + ").\n")
PY

# run NAME CMD... : runs CMD with its output in $tmp/NAME.out; prints "cpu_seconds wall_seconds"
# or "fail(CODE) -" (clingo's exit codes 10, 20 and 30 are success).
run() {
  local name="$1"; shift
  local rc=0
  /usr/bin/time -f "%U %S %e" -o "$tmp/$name.time" timeout "$limit" "$@" >"$tmp/$name.out" 2>"$tmp/$name.err" || rc=$?
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 10 ] && [ "$rc" -ne 20 ] && [ "$rc" -ne 30 ]; then
    echo "fail($rc) -"
  else
    tail -n 1 "$tmp/$name.time" | awk '{ printf "%.3f %.3f\n", $1 + $2, $3 }'
  fi
}

printf '%-44s %9s %9s %9s %9s %7s %s\n' row ref_cpu ref_wall luc_cpu luc_wall ratio same
for shape in atom term facts pool; do
  file="$tmp/$shape.lp"
  for mode in ground solve; do
    if [ "$mode" = ground ]; then
      read -r rc rw < <(run ref gringo "$file")
      read -r lc lw < <(run luc "$lucent" --mode=gringo "$file")
      same=$(cmp -s "$tmp/ref.out" "$tmp/luc.out" && echo yes || echo no)
      row="$shape n=$n: gringo | lucent --mode=gringo"
    else
      read -r rc rw < <(run ref clingo "$file")
      read -r lc lw < <(run luc "$lucent" "$file")
      same=$([ "$(grep -E '^(SATISFIABLE|UNSATISFIABLE|UNKNOWN|OPTIMUM FOUND)$' "$tmp/ref.out")" = \
               "$(grep -E '^(SATISFIABLE|UNSATISFIABLE|UNKNOWN|OPTIMUM FOUND)$' "$tmp/luc.out")" ] \
             && cmp -s <(sed -n '/^Answer: 1$/{n;p;q}' "$tmp/ref.out" | tr ' ' '\n' | sort) \
                       <(sed -n '/^Answer: 1$/{n;p;q}' "$tmp/luc.out" | tr ' ' '\n' | sort) \
             && echo yes || echo no)
      row="$shape n=$n: clingo | lucent"
    fi
    if [[ "$rc" == fail* || "$lc" == fail* ]]; then
      printf '%-44s %9s %9s %9s %9s %7s %s\n' "$row" "$rc" "$rw" "$lc" "$lw" - "$same"
    else
      ratio=$(echo "$lc / ($rc + 0.001)" | bc -l)
      printf '%-44s %9.3f %9.3f %9.3f %9.3f %7.2f %s\n' "$row" "$rc" "$rw" "$lc" "$lw" "$ratio" "$same"
    fi
  done
done
echo "(ratio = Lucent's processor time over the reference's; same = identical aspif, or the same result and answer)"
