#!/bin/sh
# Builds the `lucent` Python package (pyproject.toml, maturin, PyO3) into a fresh virtual
# environment and runs its tests (python/tests), which compare with clingo 5.8's Python module.
# Usage: scripts/test_python.sh [VENV_DIR]   (default: target/python-venv)
# The environment sees the system's site-packages (clingo); pytest and maturin are installed
# into it with pip when missing. LUCENT_PY_PROFILE=dev builds the native module with the dev
# profile (what scripts/test.sh does: with the root's target directory its dependencies are
# those `cargo test` built); the default is maturin's release build, as `pip install .`.
set -eu
cd "$(dirname "$0")/.."
venv="${1:-${CARGO_TARGET_DIR:-target}/python-venv}"
python3 -m venv --system-site-packages "$venv"
"$venv/bin/python" -c 'import clingo' 2>/dev/null || {
    echo "clingo's Python module is needed: pip install clingo==5.8.*" >&2
    exit 1
}
"$venv/bin/python" -m pip install -q pytest 'maturin>=1.5,<2'
# Without build isolation pip uses the environment's maturin (no download per run), which
# the build hook finds on PATH.
PATH="$venv/bin:$PATH" MATURIN_PEP517_ARGS="--profile ${LUCENT_PY_PROFILE:-release}" \
    "$venv/bin/python" -m pip install -q --no-build-isolation --force-reinstall --no-deps .
cd python/tests
"$venv/bin/python" -m pytest -q
