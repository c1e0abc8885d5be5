"""A seeded generator of small random programs in the clingo dialect, for the differential run
against clingo 5.8 (scripts/diff_random.py).

Every program is finite to ground and small to solve: constants are 1..3 (facts over `d/1`),
every variable is bound by a positive body atom (or a condition) over them, arithmetic reaches a
head only through a `d(Z)` guard, predicates have arity at most 2. Programs use: facts; normal
rules; choice rules with bounds and conditional elements; head aggregates; integrity
constraints; disjunction (`;`, `|`); default (`not`,
`not not`) and classical (`-`) negation; comparisons and arithmetic; conditional literals;
`#count`, `#sum`, `#sum+`, `#min`, `#max` in bodies (one or two bounds, negated, assigned);
weak constraints, `#minimize` and `#maximize` with priorities and negative weights; `#project`
in both forms (signature, atom with a condition); `#heuristic` with every modifier; `#show`
(signatures, `#show.`, terms with conditions); `#external` with and without a value; the order
of ground terms of every kind (`#min`, `#max`, `<` over `o/1`).

A program is a list of statements; a statement is a list of pieces, each a string or a
`Part` (a list of strings joined when rendered), so that scripts/diff_random.py can shrink a
program by dropping statements and parts' elements without reparsing.

These constructs are left out because clingo 5.8.3 (and 5.4) answers them in ways that are not
the language's meaning, so a difference there is no wrong answer of Lucent's:
- a conditional element of a choice or disjunction whose condition mentions a predicate of the
  rule's head: gringo grounds the element before the head atoms it depends on, and drops it
  (`2 { q(1); s(X) : q(X) } 2.` grounds to `2 <= #count { q(1) }`: unsatisfiable, where
  `{q(1), s(1)}` is an answer set; ARCHITECTURE.md's kept differences);
- disjunctive heads with a conditional element (`a ; p(X) : d(X)`), as in
  tests/support/random_program.rs by default: gringo drops rules around them. `d(1..3).
  {s(1)}. s(Y) ; p(Z) : d(Z) :- s(X), d(Y), N = #count { V : d(V) }.` grounds to no rule for
  `s`/`p`, so clingo accepts `{s(1)}`, which violates the instance Y=2; and beside
  `c ; p(X) : d(X), X > 2 :- s(Y) : s(Y).`, the rule `1 #sum { X,s : s(X) : d(X) } 3 :-
  p(Y) : p(Y). p(3).` (unsatisfiable alone, in clingo too) is dropped, so clingo answers
  `{c, p(3)}`;
- `#external` statements with different values for one atom: clasp takes the last of gringo's
  statements, and gringo's order follows its dependency graph (`#external e(1). [true]
  #external e(1). [free]` leaves e(1) true before `s :- not e(1).` and free after it), so
  the externals of a program share one value;
- `#external` with the value true or free on an atom a rule defines: clasp drops an external
  atom's external status when a rule defines it, and the outcome depends on the order of the
  aspif statements (`5 1 1` `1 1 1 1 0 0` `1 0 0 0 1 1`, external p true, `{p}.`, `:- p.`, is
  satisfiable, and unsatisfiable with the last two swapped; gringo writes the constraint first
  for `:- p(X). 0 #count { V,p : p(V) : d(V) } 2. #external p(V) : d(V). [true]`), and
  on how far gringo simplifies a rule with a body that cannot hold. So externals with any
  value are over `e/1`, which heads no rule, and other predicates get only the default value.

Programs with `#project` also project onto the facts `d/1`: with `--project` (clasp's `auto`),
a program whose `#project` statements ground to no atom projects onto the shown atoms instead,
and which atoms a statement matches depends on how far each grounder simplifies (gringo never
instantiates `{ s(Y) } :- d(Y), s(V) : d(V).`, Lucent keeps its rules, so `#project s/1.`
projects in Lucent and not in clingo). The facts make the projection present in both.

Invariant: the same seed gives the same program (Python's `random.Random` is specified to be
reproducible across platforms for a given seed and call sequence).
"""
import random


class Part:
    """A shrinkable list of strings: rendered as `before + joiner.join(items) + after`, or as
    `empty` when the list is empty; `least` is the fewest items a shrink may leave."""

    def __init__(self, items, joiner=", ", before="", after="", empty="", least=0):
        self.items = list(items)
        self.joiner = joiner
        self.before = before
        self.after = after
        self.empty = empty
        self.least = least

    def render(self):
        if not self.items:
            return self.empty
        return self.before + self.joiner.join(self.items) + self.after

    def without(self, i):
        return Part(self.items[:i] + self.items[i + 1:], self.joiner, self.before, self.after,
                    self.empty, self.least)


def conditional(lit):
    """Whether body literal `lit` is a conditional literal (a `:` outside braces)."""
    depth = 0
    for ch in lit:
        depth += ch == "{"
        depth -= ch == "}"
        if ch == ":" and depth == 0:
            return True
    return False


def body_part(lits, **kw):
    """A body: literals joined by `, `, or by `; ` when one is a conditional literal, whose
    condition would otherwise run on over the literals after it."""
    joiner = "; " if any(conditional(x) for x in lits) else ", "
    return Part(lits, joiner, **kw)


def render_statement(pieces):
    return "".join(p if isinstance(p, str) else p.render() for p in pieces)


def render(statements):
    return "".join(render_statement(s) + "\n" for s in statements)


# Predicates and arities; `d/1` is the domain, `e/1` mostly occurs in #external.
PREDS = [("p", 1), ("q", 1), ("r", 2), ("s", 1), ("a", 0), ("b", 0), ("c", 0)]
HEAD_PREDS = [("p", 1), ("q", 1), ("r", 2), ("s", 1), ("a", 0), ("b", 0), ("c", 0)]
VARS = ["X", "Y"]


class Gen:
    def __init__(self, seed):
        self.rng = random.Random(seed)
        self.fresh = 0
        self.has_opt = False

    def chance(self, p):
        return self.rng.random() * 100 < p

    def pick(self, xs):
        return xs[self.rng.randrange(len(xs))]

    def constant(self):
        return str(self.rng.randint(1, 3))

    def arg(self, bound):
        if bound and self.chance(70):
            return self.pick(bound)
        return self.constant()

    def fresh_var(self):
        self.fresh += 1
        return f"V{self.fresh}"

    def atom_with(self, name, arity, bound, classical=True):
        neg = "-" if classical and name in ("q", "c") and self.chance(30) else ""
        if arity == 0:
            return neg + name
        if arity == 1:
            return f"{neg}{name}({self.arg(bound)})"
        return f"{neg}{name}({self.arg(bound)},{self.arg(bound)})"

    def atom(self, bound):
        name, arity = self.pick(PREDS)
        if self.chance(8):
            name, arity = "e", 1
        return self.atom_with(name, arity, bound)

    def head_atom(self, bound):
        name, arity = self.pick(HEAD_PREDS)
        return self.atom_with(name, arity, bound)

    def bind(self, lits, bound):
        free = [v for v in VARS if v not in bound]
        if not free:
            return
        v = free[0]
        k = self.rng.randrange(6)
        if k <= 1:
            lit = f"d({v})"
        elif k == 2:
            lit = f"p({v})"
        elif k == 3:
            lit = f"-q({v})" if self.chance(50) else f"q({v})"
        elif k == 4:
            lit = f"s({v})" if self.chance(70) else f"e({v})"
        else:
            other = self.arg(bound)
            lit = f"r({v},{other})" if self.chance(50) else f"r({other},{v})"
        lits.append(lit)
        bound.append(v)

    def term(self, bound):
        x = self.arg(bound)
        if self.chance(35):
            op = self.pick(["+", "-", "*", "/", "\\"])
            return f"{x}{op}{self.arg(bound)}"
        return x

    def comparison(self, bound):
        op = self.pick(["<", "<=", ">", ">=", "=", "!="])
        return f"{self.term(bound)}{op}{self.term(bound)}"

    def aggregate_elements(self, bound, kind):
        elems = []
        for _ in range(1 + self.rng.randrange(2)):
            v = self.fresh_var()
            local = bound + [v]
            k = self.rng.randrange(4)
            cond = [[f"p({v})", f"r({v},{self.arg(bound)})", f"d({v})", f"q({v})"][k]]
            if self.chance(40):
                cond.append("not " + self.atom(local))
            if self.chance(20):
                cond.append(self.comparison(local))
            if kind.startswith("#sum") and self.chance(35):
                weight = self.pick([f"{v}-2", f"-{v}", f"2*{v}-3"])
            else:
                weight = v
            elems.append(f"{weight},{self.constant()} : {', '.join(cond)}")
        if self.chance(35):
            w = self.rng.randint(-1, 2) if kind != "#sum+" else self.rng.randint(0, 2)
            elems.append(f"{w} : {self.atom(bound)}")
        return "; ".join(elems)

    def body_aggregate(self, lits, bound):
        kind = self.pick(["#count", "#sum", "#sum+", "#min", "#max"])
        elems = self.aggregate_elements(list(bound), kind)
        op = self.pick(["<", "<=", ">", ">=", "=", "!="])
        n = self.rng.randint(-1, 3)
        if self.chance(25):
            v = self.fresh_var()
            lits.append(f"{v} = {kind} {{ {elems} }}")
            lits.append(f"{v} {op} {n}")
            return
        neg = "not " if self.chance(15) else ""
        if self.chance(20):
            lo = self.rng.randint(-1, 2)
            lits.append(f"{neg}{lo} <= {kind} {{ {elems} }} <= {lo + self.rng.randint(0, 2)}")
        elif self.chance(20):
            lits.append(f"{neg}{n} {self.pick(['<', '<=', '='])} {kind} {{ {elems} }}")
        else:
            lits.append(f"{neg}{kind} {{ {elems} }} {op} {n}")

    def body(self, min_bound, simple=False):
        """Body literals and the variables they bind; `simple`: no aggregates and no
        conditional literals (the conditions of `#minimize` elements allow neither)."""
        lits, bound = [], []
        for _ in range(min_bound):
            self.bind(lits, bound)
        for _ in range(self.rng.randrange(4)):
            k = self.rng.randrange(11)
            if simple and k in (7, 8, 9):
                k = 1
            if k == 0:
                self.bind(lits, bound)
            elif k in (1, 2):
                lits.append(self.atom(bound))
            elif k in (3, 4):
                lits.append("not " + self.atom(bound))
            elif k == 5:
                lits.append("not not " + self.atom(bound))
            elif k == 6:
                lits.append(self.comparison(bound))
            elif k in (7, 8):
                self.body_aggregate(lits, bound)
            elif k == 9:
                v = self.fresh_var()
                head = self.pick(["q", "s", "p", "-q"])
                cond = self.pick(["p", "d", "s", "q"])
                neg = "not " if self.chance(25) else ""
                lits.append(f"{neg}{head}({v}) : {cond}({v})")
            elif bound:
                z = self.fresh_var()
                lits.append(f"{z} = {self.term(bound)}")
                lits.append(f"d({z})")
                bound.append(z)
        return lits, bound

    def choice_head(self, bound):
        elems = [self.head_atom(bound) for _ in range(1 + self.rng.randrange(2))]
        if self.chance(50):
            v = self.fresh_var()
            name = self.pick(["p", "q", "s", "-q"])
            # A condition over no predicate of the head (see the module documentation).
            heads = {e.lstrip("-").split("(")[0] for e in elems} | {name.lstrip("-")}
            cond = self.pick(["d"] + [c for c in ("p", "s", "q") if c not in heads])
            c = f"{name}({v}) : {cond}({v})"
            if self.chance(40):
                c += f", {v} != {self.arg(bound)}"
            elems.append(c)
        lower = f"{self.rng.randrange(3)} " if self.chance(40) else ""
        upper = f" {1 + self.rng.randrange(2)}" if self.chance(40) else ""
        if not lower and not upper and self.chance(15):
            upper = f" = {self.rng.randrange(3)}"
        return [lower + "{ ", Part(elems, "; ", least=1), " }" + upper]

    def head(self, kind, bound):
        if kind <= 6:
            return [self.head_atom(bound)]
        if kind <= 8:
            sep = self.pick([" ; ", " | "])
            elems = [self.head_atom(bound) for _ in range(2 + (1 if self.chance(20) else 0))]
            return [Part(elems, sep, least=1)]
        if kind <= 10:
            return []
        if kind <= 13:
            return self.choice_head(bound)
        agg = self.pick(["#count", "#sum"])
        v = self.fresh_var()
        name = self.pick(["p", "s"])
        lo = self.rng.randrange(2)
        hi = lo + 1 + self.rng.randrange(2)
        elems = [f"{v},{name} : {name}({v}) : d({v})", "1,a : a"]
        if agg == "#sum" and self.chance(30):
            elems.append("-1,b : b")
        return [f"{lo} {agg} {{ ", Part(elems, " ; ", least=1), f" }} {hi}"]

    def rule(self):
        kind = self.rng.randrange(17)
        lits, bound = self.body(self.rng.randrange(3) if kind < 14 else 0)
        head = self.head(kind, bound)
        if kind == 16 or (kind <= 6 and not lits and self.chance(50)):
            name, arity = self.pick(HEAD_PREDS[:4])
            return [self.atom_with(name, arity, []) + "."]
        if not head:
            if not lits:
                lits = ["a", "b"]
            return [":- ", body_part(lits, least=1), "."]
        # Body literals that bind head variables must stay: only unbinding ones may be dropped,
        # and an unsafe shrink is an error on both sides, which then agree (no false reproducer).
        return head + [body_part(lits, before=" :- "), "."]

    def weight(self, bound):
        r = self.rng.randrange(10)
        if r < 2 and bound:
            return f"-{bound[0]}"
        if r < 4 and bound:
            return bound[0]
        return str(self.rng.randint(-2, 3))

    def optimization(self):
        k = self.rng.randrange(3)
        lits, bound = self.body(1 + self.rng.randrange(2), simple=k > 0)
        w = self.weight(bound)
        prio = f"@{self.rng.randrange(3)}" if self.chance(45) else ""
        terms = "".join("," + t for t in bound)
        if self.chance(25):
            terms += "," + self.pick(["a", "1", "f(1)"])
        if k == 0:
            return [":~ ", body_part(lits, least=1), f". [{w}{prio}{terms}]"]
        word = "#minimize" if k == 1 else "#maximize"
        return [f"{word} {{ {w}{prio}{terms} : ", Part(lits, least=1), " }."]

    def project(self):
        k = self.rng.randrange(5)
        if k == 0:
            return [f"#project {self.pick(['p/1', 'q/1', '-q/1', 's/1', 'r/2'])}."]
        if k == 1:
            return [f"#project {self.pick(['a', 'b', 'c', '-c'])}."]
        if k == 2:
            return [f"#project {self.head_atom([])}."]
        v = self.fresh_var()
        name = self.pick(["p", "q", "s"])
        cond = [f"d({v})"]
        if self.chance(50):
            cond.append(f"{v} != {self.constant()}")
        return [f"#project {name}({v}) : ", Part(cond, least=1), "."]

    def heuristic(self):
        mod = self.pick(["true", "false", "level", "sign", "init", "factor"])
        val = self.rng.randint(-2, 3)
        prio = f"@{self.rng.randint(1, 3)}" if self.chance(30) else ""
        if self.chance(50):
            return [f"#heuristic {self.head_atom([])}. [{val}{prio},{mod}]"]
        v = self.fresh_var()
        name = self.pick(["p", "q", "s"])
        cond = [f"d({v})"]
        if self.chance(40):
            cond.append(f"not {self.pick(['p', 'q', 's'])}({v})")
        weight = v if self.chance(50) else str(val)
        return [f"#heuristic {name}({v}) : ", Part(cond, least=1), f". [{weight}{prio},{mod}]"]

    def external(self, value):
        """An external with the program's one `value`: any value over `e/1`, which heads no
        rule; only the default (false) over predicates that rules define (module docs)."""
        if value in ("", " [false]") and self.chance(30):
            names, atoms = ["p", "s"], ["b", "c", "a", "s(3)"]
        else:
            names, atoms = ["e"], ["e(1)", "e(2)", "e(3)"]
        if self.chance(50):
            v = self.fresh_var()
            cond = [f"d({v})"]
            if self.chance(30):
                cond.append(f"{v} > {self.constant()}")
            return [f"#external {self.pick(names)}({v}) : ", Part(cond, least=1), "." + value]
        return [f"#external {self.pick(atoms)}." + value]

    def symbol_order(self):
        """Facts `o(T)` over ground terms of every kind, and their order as rules read it:
        `#min`, `#max` and `<` (predicates of their own, shown unless `#show` restricts)."""
        terms = self.rng.sample(ORDER_TERMS, 2 + self.rng.randrange(4))
        stmts = [[f"o({t})."] for t in terms]
        stmts.append(["omin(X) :- X = #min { T : o(T) }."])
        stmts.append(["omax(X) :- X = #max { T : o(T) }."])
        stmts.append(["olt(X,Y) :- o(X), o(Y), X < Y."])
        return stmts

    def show(self):
        k = self.rng.randrange(7)
        if k == 0:
            return [["#show."], ["#show X : p(X), not s(X)."]]
        if k == 1:
            return [["#show p/1."], ["#show -q/1."], ["#show a/0."]]
        if k == 2:
            return [["#show."], ["#show f(X,Y) : r(X,Y), X != Y."], ["#show b : b."]]
        if k == 3:
            return [["#show q/1."], ["#show e/1."], ["#show (X,1) : s(X)."]]
        if k == 4:
            return [["#show s/1."], ["#show c/0."], ["#show -c/0."]]
        return []


# Ground terms of every kind, for the order of symbols (`#min`/`#max` over them, `<`): the
# empty tuple is the constant with the empty name, strings come after constants, functions
# and tuples after strings, by sign, arity and name.
ORDER_TERMS = ["()", "a", "-a", "b", '"s"', '"a"', "(1,)", "(1,2)", "f(1)", "f(a)", "-f(1)",
               "g(1,2)", "0", "2", "-1", "#inf", "#sup"]


def program(seed):
    """The program of `seed` as a list of statements (see `render`), and the options both
    systems run it with beyond `-n 0`: `project` (`--project`), `heuristic`
    (`--heuristic=domain`)."""
    g = Gen(seed)
    stmts = [[f"% seed {seed}"], ["d(1..3)." if g.chance(85) else "d(1..2)."]]
    for _ in range(g.rng.randrange(3)):
        name, arity = g.pick(HEAD_PREDS[:4])
        stmts.append([g.atom_with(name, arity, []) + "."])
    for _ in range(3 + g.rng.randrange(5)):
        stmts.append(g.rule())
    if g.chance(35):
        for _ in range(1 + (1 if g.chance(30) else 0)):
            stmts.append(g.optimization())
    project = False
    if g.chance(15):
        project = True
        for _ in range(1 + g.rng.randrange(2)):
            stmts.append(g.project())
        stmts.append(["#project d/1."])
    elif g.chance(8):
        project = True  # projection onto the shown atoms
    heuristic = False
    if g.chance(12):
        heuristic = True
        for _ in range(1 + g.rng.randrange(3)):
            stmts.append(g.heuristic())
    if g.chance(20):
        value = g.pick(["", "", " [true]", " [false]", " [free]"])
        for _ in range(1 + g.rng.randrange(2)):
            stmts.append(g.external(value))
    if g.chance(10):
        stmts.extend(g.symbol_order())
    stmts.extend(g.show())
    return stmts, {"project": project, "heuristic": heuristic}
