#!/usr/bin/env bash
# The paper's experiments H1-H4 at the paper's sizes (docs/domain.md 7), in process, into
# docs/experiments/: report.md (our tables beside the paper's), report.json, the SVG plots, the
# per-trial results (results/, reused when the script is run again: an interrupted run resumes),
# and command.txt with the command line, the machine and the wall time.
#
# usage: scripts/experiment_full.sh [SEED] [extra `lucent experiment` options...]
#
# Five seeds in one GNU parallel invocation, then one pooled report (every trial computes all
# readings of docs/experiments/gaps.md, so nothing else is needed): scripts/experiment_seeds.sh
# (`scripts/experiment_seeds.sh docs/experiments/five "0 1 2 3 4" 2`).
set -euo pipefail
cd "$(dirname "$0")/.."
seed="${1:-0}"
shift || true
out=docs/experiments
cargo build --release --quiet
mkdir -p "$out"
cmd=("${CARGO_TARGET_DIR:-target}/release/lucent" experiment all --seed "$seed" --out "$out" "$@")
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
start=$(date +%s%N)
if [ -x /usr/bin/time ]; then
  /usr/bin/time -o "$out/.time" -f '%U %S %M' "${cmd[@]}" >/dev/null
else
  "${cmd[@]}" >/dev/null
  echo "? ? ?" > "$out/.time"
fi
end=$(date +%s%N)
read -r user sys rss < "$out/.time"
rm -f "$out/.time"
ms=$(( (end - start) / 1000000 ))
wall="$((ms / 1000)).$(printf %03d $((ms % 1000)))"
{
  echo "command: ${cmd[*]}"
  echo "machine: $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')), load average before: ${load_before}, after: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "commit: ${commit}"
  echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "wall time: ${wall} s; user CPU ${user} s, system ${sys} s, max RSS ${rss} KB"
  echo "trials reused from an earlier run: see the 'experiment:' line on standard error"
} > "$out/command.txt"
# The hand-written section on the gaps to the paper (docs/experiments/gaps.md) follows the
# generated tables.
[ -f "$out/gaps.md" ] && cat "$out/gaps.md" >> "$out/report.md"
cat "$out/command.txt"
