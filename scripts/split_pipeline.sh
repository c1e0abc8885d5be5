#!/usr/bin/env bash
# Runs a grounder and a solver as a pipe behind clingo's command line, so the shared checkers
# (which call one clingo-like command) can test each half of Lucent against the other half of
# the reference:
#   scripts/split_pipeline.sh gringo-lucent ARGS...   gringo FILES | lucent --mode=clasp OPTS
#   scripts/split_pipeline.sh lucent-clasp  ARGS...   lucent --mode=gringo FILES | clasp OPTS
# Arguments naming existing files go to the grounder, with -c/--const and -W/--warn; all other
# arguments go to the solver. Exit code: the solver's, or 65 when grounding failed.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
lucent=${LUCENT:-$here/../target/release/lucent}
combo=$1; shift
files=(); gopts=(); sopts=()
while [ $# -gt 0 ]; do
  a=$1; shift
  if [ -f "$a" ]; then files+=("$a")
  elif [ "$a" = -c ] || [ "$a" = -W ]; then gopts+=("$a" "$1"); shift
  elif [[ "$a" == -c* || "$a" == --const=* || "$a" == -W* || "$a" == --warn=* ]]; then gopts+=("$a")
  else sopts+=("$a"); fi
done
case $combo in
  gringo-lucent) ground=(gringo --output=intermediate); solve=("$lucent" --mode=clasp) ;;
  lucent-clasp) ground=("$lucent" --mode=gringo); solve=(clasp) ;;
  *) echo "usage: $0 gringo-lucent|lucent-clasp ARGS..." >&2; exit 128 ;;
esac
tmp=$(mktemp); trap 'rm -f "$tmp"' EXIT
if ! "${ground[@]}" "${gopts[@]}" "${files[@]}" > "$tmp"; then exit 65; fi
"${solve[@]}" "${sopts[@]}" < "$tmp"
