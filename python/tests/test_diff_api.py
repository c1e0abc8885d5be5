"""A brief run of scripts/diff_api.py: random multi-shot sessions (steps, externals assigned,
freed and released, assumptions as symbols and literals, external flags) under clingo 5.8 and
lucent, traces compared. `python3 scripts/diff_api.py --count N --seed S` runs it long."""

import importlib.util
import pathlib
import random

from conftest import modules

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "scripts" / "diff_api.py"


def load():
    spec = importlib.util.spec_from_file_location("diff_api", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_random_sessions_agree_with_clingo():
    clingo, lucent = modules()
    diff_api = load()
    for seed in range(60):
        rng = random.Random(seed)
        text = diff_api.program(rng)
        sequence = diff_api.calls(rng)
        want = diff_api.run(clingo, text, sequence)
        got = diff_api.run(lucent, text, sequence)
        assert got == want, f"seed {seed}\n{text}\n{sequence}"
