#!/usr/bin/env python3
"""Generates the random ground programs of this directory and records clingo's answers.

Run from this directory: python3 generate.py   (needs clingo 5.8.3: pip install clingo)

Each NNN.aspif is also translated, statement by statement, into a clingo source program
(NNN.lp: atom i becomes a(i), weight bodies and minimize statements become #sum and #minimize
with one tuple per literal, externals stay free) and clingo 5.8.3, the semantic reference
(docs/reference.md), solves that source. It does not read the aspif file directly because clasp
(3.3.5, and the clasp inside clingo 5.8.3) loses answer sets on some raw aspif rules that gringo
never writes: e.g. on `{a2; a5} :- #sum{2: not a6; 1: not a7; 3: a2} >= 3` written as
`1 1 2 2 5 1 3 3 -6 2 -7 1 2 3` it finds only {} and {a5} (programs 000, 006 and 046 of this
set disagree in this way). Through the source, gringo adds auxiliary atoms and the answers are
right.

For each NNN.aspif it writes
  NNN.models   all stable models:  python3 -m clingo -n 0 --opt-mode=ignore --outf=2 NNN.lp
  NNN.optimal  optimal models (only with minimize statements, CR ones included):
               python3 -m clingo --opt-mode=optN -n 0 --outf=2 NNN.lp, witnesses whose costs
               equal the final costs
one model per line as sorted atom numbers (application atoms of CR rules are not shown),
lines sorted and without duplicates in .optimal.
"""
import json
import random
import subprocess

rng = random.Random(20261122)


def lit(k):
    a = rng.randint(1, k)
    return -a if rng.random() < 0.4 else a


def program(index):
    k = rng.randint(3, 8)
    lines = []
    for _ in range(rng.randint(2, 9)):
        kind = rng.random()
        if kind < 0.55:
            n = rng.randint(0, 3)
            body = " ".join(str(x) for x in [0, n] + [lit(k) for _ in range(n)])
        else:
            n = rng.randint(1, 4)
            wl = []
            for _ in range(n):
                wl += [lit(k), rng.randint(1, 3)]
            body = "1 %d %d %s" % (rng.randint(0, 4), n, " ".join(map(str, wl)))
        h = rng.random()
        if h < 0.15:
            head = "0 0"
        elif h < 0.45:
            atoms = rng.sample(range(1, k + 1), rng.randint(1, min(3, k)))
            head = "1 %d %s" % (len(atoms), " ".join(map(str, atoms)))
        elif h < 0.65:
            atoms = rng.sample(range(1, k + 1), rng.randint(2, min(3, k)))
            head = "0 %d %s" % (len(atoms), " ".join(map(str, atoms)))
        else:
            head = "0 1 %d" % rng.randint(1, k)
        lines.append("1 %s %s" % (head, body))
    if rng.random() < 0.2:
        lines.append("5 %d 0" % rng.randint(1, k))
    priorities = []
    for _ in range(rng.choice([0, 0, 1, 2])):
        p = rng.randint(0, 2)
        n = rng.randint(1, 3)
        wl = []
        for _ in range(n):
            wl += [lit(k), rng.randint(-2, 3)]
        lines.append("2 %d %d %s" % (p, n, " ".join(map(str, wl))))
        priorities.append(p)
    shown = list(range(1, k + 1))
    cr = []
    if rng.random() < 0.3:
        for j in range(rng.randint(1, 3)):
            appl = k + 1 + j
            lines.append("1 1 1 %d 0 0" % appl)
            lines.append("1 0 1 %d 0 1 %d" % (rng.randint(1, k), appl))
            cr.append(appl)
        lines.append("1 0 0 0 1 %d" % -rng.randint(1, k))
    for a in shown:
        lines.append("4 %d a%d 1 %d" % (len("a%d" % a), a, a))
    for j, appl in enumerate(cr):
        lines.append("10 lucent-cr %d r%d" % (appl, j + 1))
    if cr:
        p = max(priorities) + 1 if priorities else 0
        lines.append("10 lucent-cr-minimize %d" % p)
        lines.append("2 %d %d %s" % (p, len(cr), " ".join("%d 1" % a for a in cr)))
        priorities.append(p)
    return "asp 1 0 0\n" + "\n".join(lines) + "\n0\n", bool(priorities)


def atoms_of(symbols, shown):
    atoms = sorted(int(s[2:-1]) for s in symbols)
    return " ".join(str(a) for a in atoms if a in shown)


def source_lit(l):
    return "a(%d)" % l if l > 0 else "not a(%d)" % -l


def to_source(text):
    """The clingo source program equivalent to an aspif text (rules, minimize, externals)."""
    out = []
    for line in text.splitlines()[1:]:
        t = line.split()
        if t[0] == "1":
            choice, m = int(t[1]), int(t[2])
            head = ["a(%s)" % a for a in t[3:3 + m]]
            rest = t[3 + m:]
            if rest[0] == "0":
                body = [source_lit(int(x)) for x in rest[2:]]
            else:
                lower, n = int(rest[1]), int(rest[2])
                elems = ["%s,%d: %s" % (rest[3 + 2 * k + 1], k, source_lit(int(rest[3 + 2 * k])))
                         for k in range(n)]
                body = ["#sum{ %s } >= %d" % ("; ".join(elems), lower)]
            h = ("{ %s }" % "; ".join(head)) if choice else "; ".join(head)
            out.append("%s :- %s." % (h, ", ".join(body)) if body else "%s." % h if h else ":- #true.")
        elif t[0] == "2":
            p, n = int(t[1]), int(t[2])
            for k in range(n):
                l, w = int(t[3 + 2 * k]), int(t[4 + 2 * k])
                out.append(":~ %s. [%d@%d,%d,%s]" % (source_lit(l), w, p, k, "m%d" % len(out)))
        elif t[0] == "5":
            out.append("#external a(%s). [free]" % t[1])
    out.append("#show a/1.")
    return "\n".join(out) + "\n"


def clingo_json(path, *args):
    run = subprocess.run(["python3", "-m", "clingo", *args, "--outf=2", path],
                         capture_output=True, text=True)
    return json.loads(run.stdout)


for i in range(60):
    text, optimize = program(i)
    name = "%03d" % i
    with open(name + ".aspif", "w") as f:
        f.write(text)
    shown = {int(l.split()[2][1:]) for l in text.splitlines() if l.startswith("4 ")}
    with open(name + ".lp", "w") as f:
        f.write(to_source(text))
    out = clingo_json(name + ".lp", "-n", "0", "--opt-mode=ignore")
    witnesses = out["Call"][0].get("Witnesses", [])
    models = sorted(atoms_of(w["Value"], shown) for w in witnesses)
    with open(name + ".models", "w") as f:
        f.write("".join(m + "\n" for m in models))
    if optimize:
        out = clingo_json(name + ".lp", "--opt-mode=optN", "-n", "0")
        best = out["Models"].get("Costs")
        witnesses = out["Call"][0].get("Witnesses", [])
        optimal = sorted({atoms_of(w["Value"], shown) for w in witnesses if w.get("Costs") == best})
        with open(name + ".optimal", "w") as f:
            f.write("".join(m + "\n" for m in optimal))
