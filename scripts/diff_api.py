#!/usr/bin/env python3
"""Random multi-shot sessions through clingo's Python API, run by clingo 5.8 and by `import
lucent as clingo` in one process, their traces compared (issue 33: clingo scripts that are not
ours). Each session, from its seed:

- a base part over `d(1..3)` with externals `e/1`, choices, rules and constraints drawn from
  templates, and a `step(t)` part with an external `q(t)`, a choice, a derived atom and a
  constraint under `q(t)`;
- a random sequence of calls: ground the next step, assign an external true, false or free,
  release one, solve (every model, or with assumptions over `a/1` as symbols or as literals
  from `symbolic_atoms`; through a `yield_` handle or an `async_` one; under a model limit,
  where only the number of models is compared; the optimal models under `--opt-mode=optN`,
  optimization being ignored otherwise), add a rule through the backend, register a
  propagator forbidding a pattern, add and ground a part with a context function, compute
  brave or cautious consequences (the last model compared), read `is_external`/`is_fact` of
  the externals.

The trace records each call's result: the sorted models (all true atoms), `SolveResult` and
`exhausted`, the external flags. Models are compared as sorted lists, since the two solvers find
them in different orders.

usage: scripts/diff_api.py [--count N] [--seed S] [--lucent-python-path DIR]
Prints each disagreeing session (seed, the calls, both traces) and a summary; exit 1 on a
disagreement. Needs clingo 5.8 (`pip install clingo`) and the lucent package importable.
"""
import argparse
import importlib
import random
import sys

RULES = [
    "{{ a(X) }} :- d(X){neg_e}.",
    "b(X) :- a(X), not e(X).",
    "b(X) :- e(X), d(X), not a(X).",
    "c :- a(X), b(X).",
    "c :- e(1), not e(2).",
    ":- a(X), a(Y), X < Y, not c.",
    ":- b({k}), e({k}).",
    "{{ f(X) : d(X) }} 1 :- c.",
    ":- not c, e(3).",
    "g(X) :- f(X), not b(X).",
]
STEP = [
    "#program step(t).",
    "#external q(t).",
    "{ s(t,X) : d(X) } 1.",
    "r(t) :- s(t,X), a(X).",
    "r(t) :- s(t,X), b(X), t > 1.",
    ":- q(t), not r(t).",
]


def program(rng):
    rules = rng.sample(RULES, rng.randint(2, len(RULES)))
    # One value per external atom: with two statements for one atom, clasp takes the last of
    # gringo's, in an order that follows gringo's dependency graph (scripts/random_asp.py).
    if rng.random() < 0.3:
        body = ["d(1..3).", "#external e(X) : d(X), X > 1.", "#external e(1). [true]"]
    else:
        body = ["d(1..3).", "#external e(X) : d(X)."]
    if rng.random() < 0.5:
        body.append("#minimize { X,a : a(X); 1,b,X : b(X) }.")
    for r in rules:
        body.append(r.format(neg_e=rng.choice(["", ", not e(X)"]), k=rng.randint(1, 3)))
    return "\n".join(body + STEP)


def calls(rng):
    """The call sequence: each a tuple the runner interprets."""
    out, step = [], 0
    for _ in range(rng.randint(3, 9)):
        r = rng.random()
        if r < 0.25 and step < 4:
            step += 1
            out.append(("ground", step))
        elif r < 0.5:
            which = ("e", rng.randint(1, 3)) if rng.random() < 0.6 or step == 0 else ("q", rng.randint(1, step))
            out.append(("assign", which, rng.choice([True, False, None])))
        elif r < 0.6:
            which = ("e", rng.randint(1, 3)) if rng.random() < 0.6 or step == 0 else ("q", rng.randint(1, step))
            out.append(("release", which))
        elif r < 0.65:
            out.append(("flags",))
        elif r < 0.72:
            # A rule added through the backend: x(n) :- [not] a(i).  or  :- x(n), [not] b(i).
            out.append(("backend", len(out), rng.randint(1, 3), rng.random() < 0.5,
                        rng.random() < 0.3))
        elif r < 0.78:
            out.append(("limit", rng.randint(1, 3)))
        elif r < 0.83:
            out.append(("handle", rng.random() < 0.5))
        elif r < 0.88:
            out.append(("optimum",))
        elif r < 0.9 and not any(c[0] == "propagator" for c in out):
            out.append(("propagator", rng.randint(1, 3)))
        elif r < 0.93 and not any(c[0] == "extra" for c in out):
            out.append(("extra", rng.randint(1, 3)))
        elif r < 0.96:
            out.append(("consequences", rng.choice(["brave", "cautious"])))
        else:
            k = rng.randint(0, 2)
            assumptions = [(rng.randint(1, 3), rng.random() < 0.5) for _ in range(k)]
            out.append(("solve", assumptions, rng.random() < 0.3))
    out.append(("solve", [], False))
    return out


class Inc:
    """The grounding context of the `extra` part: `@inc(n)` is n + 1."""

    def __init__(self, clingo):
        self.clingo = clingo

    def inc(self, n):
        return self.clingo.Number(n.number + 1)


class Forbid:
    """A propagator that forbids s(t, k) together with a(k): it watches the s/2 atoms with
    second argument k and, when one becomes true, adds the nogood with a(k)."""

    def __init__(self, clingo, k):
        self.clingo, self.k = clingo, k

    def init(self, init):
        self.a = None
        atom = init.symbolic_atoms[self.clingo.Function("a", [self.clingo.Number(self.k)])]
        if atom is not None:
            self.a = init.solver_literal(atom.literal)
        for atom in init.symbolic_atoms.by_signature("s", 2):
            if atom.symbol.arguments[1].number == self.k and self.a is not None:
                init.add_watch(init.solver_literal(atom.literal))

    def propagate(self, control, changes):
        for lit in changes:
            if not control.add_nogood([lit, self.a]) or not control.propagate():
                return


def run(clingo, text, sequence):
    """The trace of one session under `clingo` (either module)."""
    # Optimization statements are ignored except in the `optimum` call (the improving models
    # before an optimum depend on the search).
    ctl = clingo.Control(["0", "--opt-mode=ignore"])
    ctl.add("base", [], text)
    ctl.ground([("base", [])])
    trace = []

    def sym(which):
        name, i = which
        return clingo.Function(name, [clingo.Number(i)])

    for c in sequence:
        try:
            if c[0] == "ground":
                ctl.ground([("step", [clingo.Number(c[1])])])
                trace.append(("ground", c[1]))
            elif c[0] == "assign":
                # clingo 5.8's assign_external takes True, False or None (free).
                ctl.assign_external(sym(c[1]), c[2])
                trace.append(("assign", c[1], c[2]))
            elif c[0] == "release":
                ctl.release_external(sym(c[1]))
                trace.append(("release", c[1]))
            elif c[0] == "flags":
                flags = sorted((str(a.symbol), a.is_external, a.is_fact)
                               for name in ("e", "q") for a in ctl.symbolic_atoms.by_signature(name, 1))
                trace.append(("flags", flags))
            elif c[0] == "backend":
                _, n, i, positive, constraint = c
                atom = ctl.symbolic_atoms[clingo.Function("a", [clingo.Number(i)])]
                with ctl.backend() as b:
                    x = b.add_atom(clingo.Function("x", [clingo.Number(n)]))
                    body = [] if atom is None else [atom.literal if positive else -atom.literal]
                    if constraint:
                        b.add_rule([], [x] + [-l for l in body])
                    b.add_rule([x], body, choice=constraint)
                trace.append(("backend", n, atom is not None))
            elif c[0] == "limit":
                # The models found under a limit depend on the search: only their number.
                count = []
                ctl.configuration.solve.models = c[1]
                result = ctl.solve(on_model=lambda m: count.append(1))
                ctl.configuration.solve.models = 0
                trace.append(("limit", c[1], str(result), len(count)))
            elif c[0] == "optimum":
                ctl.configuration.solve.opt_mode = "optN"
                optimal = []

                def keep_optimal(m):
                    if m.optimality_proven:
                        optimal.append((list(m.cost), sorted(str(s) for s in m.symbols(atoms=True))))

                result = ctl.solve(on_model=keep_optimal)
                ctl.configuration.solve.opt_mode = "ignore"
                trace.append(("optimum", str(result), sorted(optimal)))
            elif c[0] == "consequences":
                # The last model is the consequences (the approximations before it follow the
                # search).
                ctl.configuration.solve.enum_mode = c[1]
                last = []
                result = ctl.solve(on_model=lambda m: last.__setitem__(
                    slice(None), [str(m.type), sorted(str(s) for s in m.symbols(shown=True))]))
                ctl.configuration.solve.enum_mode = "auto"
                trace.append(("consequences", c[1], str(result), last))
            elif c[0] == "extra":
                # A part added mid-session, grounded with a context function.
                ctl.add("extra", ["n"], "z(n,T) :- s(T,n). w(@inc(n)) :- z(n,_). :- w(3), e(3).")
                ctl.ground([("extra", [clingo.Number(c[1])])], context=Inc(clingo))
                trace.append(("extra", c[1]))
            elif c[0] == "propagator":
                ctl.register_propagator(Forbid(clingo, c[1]))
                trace.append(("propagator", c[1]))
            elif c[0] == "handle":
                models = []
                if c[1]:
                    with ctl.solve(yield_=True) as handle:
                        for m in handle:
                            models.append(sorted(str(s) for s in m.symbols(atoms=True)))
                        result = handle.get()
                else:
                    with ctl.solve(async_=True, on_model=lambda m: models.append(
                            sorted(str(s) for s in m.symbols(atoms=True)))) as handle:
                        handle.wait()
                        result = handle.get()
                trace.append(("handle", c[1], str(result), result.exhausted, sorted(models)))
            else:
                _, assumptions, as_literals = c
                assume = []
                for i, truth in assumptions:
                    s = clingo.Function("a", [clingo.Number(i)])
                    if as_literals:
                        atom = ctl.symbolic_atoms[s]
                        if atom is None:
                            continue
                        assume.append(atom.literal if truth else -atom.literal)
                    else:
                        assume.append((s, truth))
                models = []
                result = ctl.solve(assumptions=assume, on_model=lambda m: models.append(
                    sorted(str(s) for s in m.symbols(atoms=True))))
                trace.append(("solve", assumptions, as_literals, str(result), result.exhausted,
                              sorted(models)))
        except RuntimeError as e:
            trace.append((c[0], "RuntimeError"))
    return trace


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--count", type=int, default=200)
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args()
    try:
        clingo = importlib.import_module("clingo")
    except ImportError:
        sys.exit("clingo 5.8's Python module is needed: python3 -m pip install clingo")
    lucent = importlib.import_module("lucent")
    bad = 0
    for seed in range(args.seed, args.seed + args.count):
        rng = random.Random(seed)
        text = program(rng)
        sequence = calls(rng)
        want = run(clingo, text, sequence)
        got = run(lucent, text, sequence)
        if want != got:
            bad += 1
            print(f"== seed {seed} disagrees\n{text}\ncalls: {sequence}")
            for w, g in zip(want, got):
                mark = "  " if w == g else "!!"
                print(f"{mark} clingo {w}\n{mark} lucent {g}")
    print(f"sessions {args.count} (seeds {args.seed}..{args.seed + args.count - 1}), "
          f"disagreed {bad}")
    sys.exit(1 if bad else 0)


if __name__ == "__main__":
    main()
