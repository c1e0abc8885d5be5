"""Bad input from Python is an exception with gringo's message, never a crash."""

import pytest

import lucent


def test_syntax_error_is_a_runtime_error():
    ctl = lucent.Control()
    with pytest.raises(RuntimeError, match="syntax error"):
        ctl.add("base", [], "p(1")


def test_unsafe_rule_is_reported_at_ground():
    ctl = lucent.Control()
    ctl.add("base", [], "p(X) :- not q(X).")
    with pytest.raises(RuntimeError, match="unsafe variables"):
        ctl.ground([("base", [])])


def test_on_model_exception_propagates():
    ctl = lucent.Control(["0"])
    ctl.add("base", [], "{a}.")
    ctl.ground([("base", [])])

    def boom(m):
        raise ValueError("from on_model")

    with pytest.raises(ValueError, match="from on_model"):
        ctl.solve(on_model=boom)


def test_bad_arguments_and_names():
    with pytest.raises(RuntimeError):
        lucent.Control(["--no-such-option"])
    with pytest.raises(RuntimeError):
        lucent.Control(["-c", "n"])
    # Any name is taken, as clingo takes it (clingo 5.8.3: `str(clingo.Function("Upper"))` is
    # 'Upper').
    assert str(lucent.Function("Upper")) == "Upper"
    with pytest.raises(RuntimeError):
        lucent.parse_term("p(")
    with pytest.raises(RuntimeError):
        lucent.Number(1).name
    ctl = lucent.Control()
    with ctl.backend() as b:
        with pytest.raises(RuntimeError):
            b.add_rule([5], [])


def test_add_program_only_form_goes_to_base():
    ctl = lucent.Control()
    ctl.add("a. b :- a.")
    ctl.ground()
    models = []
    ctl.solve(on_model=lambda m: models.append(sorted(map(str, m.symbols(shown=True)))))
    assert models == [["a", "b"]]
