#!/usr/bin/env bash
# The whole test suite, from a fresh machine: installs the reference tools the differential
# tests compare against (clingo 5.4's gringo/clasp/clingo from Debian, clingo 5.8 from PyPI),
# then checks formatting, lints, and runs every test (unit, integration, snapshot, property,
# differential), then builds the Python package and runs its pytest scripts against clingo
# 5.8. Used by README.md and .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."

as_root() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

if ! command -v clingo >/dev/null || ! command -v gringo >/dev/null || ! command -v clasp >/dev/null; then
  echo "== installing clingo 5.4 (gringo, clasp) from Debian"
  as_root apt-get update -qq
  as_root apt-get install -y -qq gringo clasp
fi
if ! python3 -c 'import clingo' 2>/dev/null; then
  echo "== installing clingo 5.8 (Python module) from PyPI"
  if ! python3 -m pip --version >/dev/null 2>&1; then
    as_root apt-get update -qq
    as_root apt-get install -y -qq python3-pip
  fi
  # Debian 12's own python3 is "externally managed" (PEP 668): pip refuses a plain install
  # there, so the second try installs beside the distribution's packages.
  python3 -m pip install -q clingo || python3 -m pip install -q --break-system-packages clingo
fi
# tests/experiment/jobs.rs runs the experiment's job list with GNU parallel.
if ! command -v parallel >/dev/null; then
  echo "== installing GNU parallel"
  as_root apt-get update -qq
  as_root apt-get install -y -qq parallel
fi

# tests/cli/demo.rs renders the run reports in headless Chromium.
if ! command -v chromium >/dev/null && ! command -v chromium-browser >/dev/null; then
  echo "== installing Chromium (the run report test renders HTML headless)"
  as_root apt-get update -qq
  as_root apt-get install -y -qq chromium
fi

echo "== cargo fmt --check"
cargo fmt --all -- --check
# The Python package's native crate is its own workspace, out of the root's reach.
(cd python && cargo fmt --all -- --check)
echo "== cargo clippy"
cargo clippy --all-targets -- -D warnings
echo "== cargo test"
cargo test --all-targets
cargo test --doc
# The Python package (python/): built with the dev profile into the root's target directory,
# so that the dependencies just built can be reused (at most ~3.5 CPU minutes from scratch for
# lucent without `sim`, PyO3 and the module: docs/bench/python-2026-12-06.md), then its pytest
# scripts, which compare with clingo 5.8's Python module (they fail without it).
echo "== python tests"
if ! python3 -m venv --help >/dev/null 2>&1 || ! python3 -c 'import ensurepip' 2>/dev/null; then
  as_root apt-get update -qq
  as_root apt-get install -y -qq python3-venv
fi
CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$PWD/target}" LUCENT_PY_PROFILE=dev scripts/test_python.sh
