"""Shared helpers: every clingo-style script runs under clingo 5.8 and under
``import lucent as clingo``, and the answers are compared. Without clingo the tests fail with
how to install it (never skip)."""

import importlib

import pytest


def modules():
    try:
        clingo = importlib.import_module("clingo")
    except ImportError:  # pragma: no cover - the message is the point
        pytest.fail("clingo's Python module is needed for the differential tests: pip install clingo==5.8.*")
    if not clingo.__version__.startswith("5.8"):
        pytest.fail(f"the differential tests compare with clingo 5.8, found {clingo.__version__}: pip install clingo==5.8.*")
    import lucent

    return clingo, lucent


@pytest.fixture
def both():
    """``run(script)``: the script's answer under clingo and under lucent, asserted equal."""
    clingo, lucent = modules()

    def run(script, *args):
        expected = script(clingo, *args)
        got = script(lucent, *args)
        assert got == expected, f"lucent: {got!r}\nclingo: {expected!r}"
        return got

    return run


def sorted_models(models):
    """Models as sorted lists of strings, the list sorted."""
    return sorted(sorted(str(s) for s in m) for m in models)
