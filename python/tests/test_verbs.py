"""The robot's verbs from Python: values, not printed text."""

import os

import pytest

import lucent

ROOT = os.path.join(os.path.dirname(__file__), "..", "..")


def test_plan_returns_the_minimal_plans():
    # domains/ra/scenes/tabletop_task.ald states (derived by hand, docs/domain.md 4.5): minimal
    # length 3 and exactly 4 plans; domains/ra/expected/tabletop.plans lists them.
    task = os.path.join(ROOT, "domains/ra/scenes/tabletop_task.ald")
    found = lucent.plan(task, all=True)
    assert found["length"] == 3
    with open(os.path.join(ROOT, "domains/ra/expected/tabletop.plans")) as f:
        expected = sorted(line.strip() for line in f if line.strip())
    got = sorted("; ".join(f"{a}@{i}" for i, a in enumerate(p)) for p in found["plans"])
    assert got == expected


def test_plan_without_a_plan_is_none(tmp_path):
    task = os.path.join(ROOT, "domains/ra/scenes/tabletop_task.ald")
    assert lucent.plan(task, max_horizon=1) is None


def test_plan_bad_input_raises(tmp_path):
    bad = tmp_path / "bad.ald"
    bad.write_text("this is not AL_d")
    with pytest.raises(RuntimeError, match="not a valid AL_d planning problem"):
        lucent.plan(str(bad))


def test_explain_why_an_atom_holds(tmp_path):
    # b holds through `b :- a.` and the fact `a.` (by hand).
    program = tmp_path / "p.lp"
    program.write_text("a. b :- a. c :- not b.\n")
    answer = lucent.explain(str(program), why="b")
    assert isinstance(answer, dict)
    text = str(answer)
    assert "a" in text and "b" in text
    with pytest.raises(RuntimeError):
        lucent.explain(str(tmp_path / "missing.lp"), why="b")
