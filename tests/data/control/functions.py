"""Records the answers of tests/control/functions.rs from clingo 5.8's Python API: each
program is grounded with a context whose functions are those of the Rust test's context, and
its first model's atoms are printed sorted (clingo's order), one program per line.

    python3 tests/data/control/functions.py
"""
import clingo


class Ctx:
    def inc(self, x):
        return clingo.Number(x.number + 1)

    def both(self, x):
        return [clingo.Number(x.number), clingo.Number(x.number * 10)]

    def up(self, s):
        return clingo.String(s.string.upper())

    def none(self, x):
        return []

    def pair(self, a, b):
        return clingo.Function("", [b, a])

    def zero(self):
        return clingo.Function("z")


PROGRAMS = [
    "p(1..3). q(@inc(X)) :- p(X).",
    "p(1..2). q(@both(X)) :- p(X).",
    "p(1..2). q(Y) :- p(X), Y = @both(X).",
    'q(@up("ab")). r(@up(S)) :- S = ("x";"yz").',
    "p(1). q(X) :- p(X), r(@inc(X)). r(2). s :- p(X), @inc(X) > 1.",
    "q(X) :- X = @inc(@inc(1)).",
    "q(@none(1)). r.",
    "q(@pair(1, a)). r(@zero). r(@zero()).",
    "p(1..2). { q(@inc(X)) : p(X) } = 2. s(N) :- N = #sum{ @inc(X) : p(X) }.",
    "#const k = @inc(2). #const m = @inc(k). p(1..k). q(m). r(@zero).",
]


def main():
    for prog in PROGRAMS:
        ctl = clingo.Control()
        ctl.add("base", [], prog)
        ctl.ground([("base", [])], context=Ctx())
        models = []
        ctl.solve(on_model=lambda m: models.append(sorted(m.symbols(atoms=True))))
        print(prog, "=>", " ".join(str(s) for s in models[0]))
    # Multi-shot: a step part calling @inc(t).
    ctl = clingo.Control()
    ctl.add("base", [], "at(0).")
    ctl.add("step", ["t"], "at(@inc(t)) :- at(t).")
    ctl.ground([("base", [])], context=Ctx())
    for t in range(3):
        ctl.ground([("step", [clingo.Number(t)])], context=Ctx())
    models = []
    ctl.solve(on_model=lambda m: models.append(sorted(m.symbols(atoms=True))))
    print("step(0..2) =>", " ".join(str(s) for s in models[0]))


main()
