"""clingo applications (``clingo.application``: ``Application``, ``clingo_main``) and the
smaller pieces of clingo's API a script meets (``Model.is_true``/``priority``/``type``/
``extend``, ``Symbol.match``, ``Control.get_const``, clingo's submodules), run
under clingo 5.8 and under ``import lucent as clingo``.

An application prints what clingo's application prints; the two outputs are compared after
``normalise``: times removed, the version line of an application without ``program_name``
masked (clingo names itself, lucent itself), the symbols of each model line sorted and the
models of each solve call compared as a sorted list (two solvers may find models in another
order and print an answer's symbols in another order; with ``-V0``, which prints no
``Answer:`` lines, every line is compared as a sorted list).
"""

import json
import os
import re
import subprocess
import sys
import textwrap

import pytest
from conftest import modules

HERE = os.path.dirname(os.path.abspath(__file__))


def run_app(module, source, args, stdin="", tmp_path=None):
    """Runs ``source`` (a script that imports ``clingo``) with ``module`` in its place; the
    exit code, standard output and standard error."""
    script = source.replace("import clingo", f"import {module} as clingo")
    script = script.replace("from clingo.", f"from {module}.")
    env = dict(os.environ)
    proc = subprocess.run(
        [sys.executable, "-c", script, *args],
        input=stdin,
        capture_output=True,
        text=True,
        timeout=120,
        env=env,
        cwd=tmp_path or HERE,
    )
    return proc.returncode, proc.stdout, proc.stderr


def normalise(text, mask_version=True):
    """clingo's text output as a comparable structure (see the module doc)."""
    out = []
    calls = []
    models = None
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        line = lines[i]
        i += 1
        if mask_version and re.match(r"^\S+ version ", line):
            out.append("VERSION")
            continue
        if line.startswith(("Time ", "CPU Time")):
            continue
        if line == "Solving...":
            models = []
            calls.append(models)
            continue
        m = re.match(r"^Answer: \d+( \(Time: [0-9.]+s\))?$", line)
        if m:
            body = []
            # the model line(s) up to the next Answer/result word/Solving line
            while i < len(lines) and not re.match(
                r"^(Answer: |Solving\.\.\.|SATISFIABLE|UNSATISFIABLE|UNKNOWN|OPTIMUM FOUND)", lines[i]
            ):
                body.append(" ".join(sorted(lines[i].split())))
                i += 1
            models.append(tuple(body))
            continue
        out.append(" ".join(sorted(line.split())))
    if not calls:
        # -V0: no "Solving..." and no "Answer:" lines, the model lines among the rest
        out.sort()
    return out, [sorted(c) for c in calls]


APP = textwrap.dedent(
    '''
    import sys
    import clingo
    from clingo.application import Application, clingo_main, Flag

    class App(Application):
        program_name = "pick"
        version = "1.0"

        def __init__(self):
            self.k = 1
            self.extra = Flag(False)

        def register_options(self, options):
            options.add("Pick", "k-value,k", "how many to pick", self.parse_k, argument="<n>")
            options.add_flag("Pick", "extra", "add the extra fact", self.extra)

        def parse_k(self, value):
            if not value.isdigit():
                return False
            self.k = int(value)
            return True

        def print_model(self, model, printer):
            print("picked", len([s for s in model.symbols(shown=True) if s.match("in", 1)]))
            printer()

        def main(self, ctl, files):
            for f in files:
                ctl.load(f)
            ctl.add("base", [], "item(1..3). {in(X): item(X)} = %d. #show in/1." % self.k)
            if self.extra.flag:
                ctl.add("base", [], "extra. #show extra/0.")
            ctl.ground([("base", [])])
            # extend: a symbol that depends on the model only (not on the order models come in)
            ctl.solve(on_model=lambda m: m.extend(
                [clingo.Function("size", [clingo.Number(len(m.symbols(shown=True)))])]))
            if self.k == 3:
                raise RuntimeError("three is too many")

    sys.exit(int(clingo_main(App(), sys.argv[1:])))
    '''
)


@pytest.mark.parametrize(
    "args",
    [
        ["0"],
        ["--k-value=2", "--extra", "0"],
        ["-k", "2", "--models=0"],
        ["-k", "2", "-V0", "0"],
        ["-k", "3"],  # main raises after solving: 65 or'ed with 10
        ["--k-value=x"],  # the application's parser rejects the value: exit 1
        ["--no-such-option"],  # exit 1
        ["--extra", "--extra"],  # an option given twice: exit 1
    ],
)
def test_application_output_and_exit_code(args):
    modules()
    code_c, out_c, _ = run_app("clingo", APP, args)
    code_l, out_l, err_l = run_app("lucent", APP, args)
    assert code_l == code_c, f"lucent exit {code_l}, clingo {code_c}\n{err_l}"
    assert normalise(out_l, mask_version=False) == normalise(out_c, mask_version=False)


DEFAULT_MAIN = textwrap.dedent(
    '''
    import sys
    from clingo.application import Application, clingo_main

    class Plain(Application):
        pass

    sys.exit(int(clingo_main(Plain(), sys.argv[1:])))
    '''
)


def test_default_main_reads_files_and_stdin(tmp_path):
    modules()
    (tmp_path / "a.lp").write_text("{p(1..3)}. :- p(1), p(2).\n")
    (tmp_path / "b.lp").write_text("q :- p(3).\n")
    for args, stdin in [
        (["a.lp", "b.lp", "0"], ""),
        (["0"], "{x; y}. :- x, y.\n"),
        (["0"], "a. :- a.\n"),
        ([], "{x}.\n"),
    ]:
        code_c, out_c, _ = run_app("clingo", DEFAULT_MAIN, args, stdin, tmp_path)
        code_l, out_l, err_l = run_app("lucent", DEFAULT_MAIN, args, stdin, tmp_path)
        assert code_l == code_c, (args, err_l)
        assert normalise(out_l) == normalise(out_c), args


def json_shape(text):
    """clingo's JSON output without times and the solver's name, models sorted."""
    doc = json.loads(text)
    doc.pop("Solver")
    doc.pop("Time")
    for call in doc["Call"]:
        call.pop("Start")
        call.pop("Stop", None)
        for w in call["Witnesses"]:
            w.pop("Time")
            w["Value"] = sorted(w["Value"])
        call["Witnesses"] = sorted(call["Witnesses"], key=lambda w: (w["Value"], w.get("Costs")))
    return doc


def test_default_main_json_output(tmp_path):
    modules()
    (tmp_path / "a.lp").write_text("{p(1..3)}. :- p(1), p(2).\n")
    code_c, out_c, _ = run_app("clingo", DEFAULT_MAIN, ["--outf=2", "a.lp", "0"], "", tmp_path)
    code_l, out_l, err_l = run_app("lucent", DEFAULT_MAIN, ["--outf=2", "a.lp", "0"], "", tmp_path)
    assert code_l == code_c, err_l
    assert json_shape(out_l) == json_shape(out_c)


OPT_APP = textwrap.dedent(
    '''
    import sys
    from clingo.application import Application, clingo_main

    class Opt(Application):
        def main(self, ctl, files):
            ctl.add("base", [], "{a; b; c}. :- not a, not b. #minimize {2,a: a; 1,b: b; 1,c: c}.")
            ctl.ground([("base", [])])
            ctl.solve()

    sys.exit(int(clingo_main(Opt(), sys.argv[1:])))
    '''
)


def test_optimization_application():
    """Improving models may differ between solvers: compared are the exit code, the result
    word and the summary's optimum lines."""
    modules()
    code_c, out_c, _ = run_app("clingo", OPT_APP, [])
    code_l, out_l, err_l = run_app("lucent", OPT_APP, [])
    assert code_l == code_c == 30, err_l

    def tail(text):
        lines = text.splitlines()
        start = lines.index("OPTIMUM FOUND")
        return [l for l in lines[start:] if l.startswith(("OPTIMUM", "  Optimum", "Optimization", "Calls"))]

    assert tail(out_l) == tail(out_c)


def model_api(clingo):
    """``Model.is_true``/``priority``/``type``/``extend``, ``Symbol.match``, ``get_const``."""
    ctl = clingo.Control(["0", "-c", "n=2"])
    ctl.add("base", [], "#const m = 5. item(1..n). {pick(X): item(X)}. "
                        "#minimize {1@2,X: pick(X)}. #minimize {1@1: item(1)}. -q(1). #show pick/1. #show -q/1.")
    ctl.ground([("base", [])])
    lit = {str(a.symbol): a.literal for a in ctl.symbolic_atoms}
    out = [str(ctl.get_const("n")), str(ctl.get_const("m")), ctl.get_const("k")]

    def on_model(model):
        model.extend([clingo.Function("seen")])
        out.append((
            sorted(str(s) for s in model.symbols(shown=True)),
            model.cost, model.priority, str(model.type),
            model.is_true(lit["pick(1)"]), model.is_true(-lit["pick(1)"]),
            model.is_true(lit["item(2)"]),
            [s.match("pick", 1) for s in model.symbols(shown=True)],
            [s.match("q", 1, False) for s in model.symbols(shown=True)],
            [s.match("q", 1) for s in model.symbols(shown=True)],
        ))

    ctl.configuration.solve.opt_mode = "optN"
    ctl.solve(on_model=lambda m: on_model(m) if m.optimality_proven else None)
    return out


def test_model_and_constant_api(both):
    both(model_api)


def submodules(clingo):
    """``from clingo.symbol import ...`` and the other submodules clingo scripts import."""
    import importlib

    name = clingo.__name__
    sym = importlib.import_module(name + ".symbol")
    ctl_mod = importlib.import_module(name + ".control")
    solving = importlib.import_module(name + ".solving")
    core = importlib.import_module(name + ".core")
    app = importlib.import_module(name + ".application")
    f = sym.Function("p", [sym.Number(1), sym.String("a"), sym.Tuple_([sym.Number(2)])])
    ctl = ctl_mod.Control(["0"])
    ctl.add("base", [], "#external e. a :- e.")
    ctl.ground([("base", [])])
    ctl.assign_external(sym.Function("e"), core.TruthValue.True_)
    res = []
    result = ctl.solve(on_model=lambda m: res.append((str(m), m.type == solving.ModelType.StableModel)))
    return [str(f), str(sym.parse_term("f(1)")), res,
            isinstance(result, solving.SolveResult), hasattr(app, "clingo_main"),
            clingo.Application is app.Application, clingo.clingo_main is app.clingo_main]


def test_submodules(both):
    both(submodules)
