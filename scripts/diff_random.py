#!/usr/bin/env python3
"""Random differential run: Lucent against clingo 5.8 (the `clingo` Python module) on random
programs (scripts/random_asp.py), in one run of this script.

  scripts/diff_random.py [--count 1000] [--seed 0] [--workers 2] [--lucent PATH] [--out DIR]

Program i of a run is the generator's program of seed S+i. Each is solved by
  lucent -n 0 --outf=2 --opt-mode=optN [--project] [--heuristic=domain] -
(the release binary by default, the program on standard input) and by clingo 5.8 in this
process (`clingo.Control(["--models=0", "--opt-mode=optN", ...])`, the same options). The two
agree when both reject the program (Lucent exit 65, a clingo RuntimeError), or when both give
the same result word (SATISFIABLE, UNSATISFIABLE, OPTIMUM FOUND) and the same multiset of
answer sets (the shown symbols of each, sorted; the order of answer sets is not compared, so
`#heuristic` under `--heuristic=domain` changes nothing compared); with optimization, the same
optimum cost vector and the same multiset of optimal answer sets (clingo's models with
`optimality_proven`, Lucent's last `Models.Optimal` witnesses). With `--project` and `#project`,
answer sets compare on their projected shown symbols (see `Projection`); optima of all zeros
and missing zero levels are normalised (see `answer`, `same`); and a disagreement that
clingo with `--eq=0` does not have counts as agreement, reported apart (see `compare`).
Programs with more than MAX_MODELS (2000) answer sets by clingo are skipped (counted, not run
through Lucent).

Every disagreement is shrunk (statements dropped in halving chunks, then single statements,
then elements of bodies, heads, conditions, and the --project/--heuristic options, for as long
as the two still disagree: delta debugging over the generator's statement structure) and saved
as <out>/seed-<S>.lp with both answers and the commands in comments. Work is spread over
--workers processes (multiprocessing), each with clingo loaded once.

Prints the number of programs, agreements (and of those, both rejected), skipped and
disagreements, how many programs used each construct, and the time taken. Exit status 0 when no
program disagrees and, for runs of at least 500 programs, every construct occurred and at most
10% were skipped; 1 otherwise; 2 when clingo or the binary is missing.
"""
import argparse
import json
import multiprocessing
import os
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no scripts/__pycache__ in the clone
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import random_asp  # noqa: E402

try:
    import clingo
except ImportError:
    clingo = None

INSTALL = ("the differential run needs clingo 5.8's Python module: `python3 -m pip install "
           "clingo` (add `--break-system-packages` on Debian's own Python; scripts/test.sh "
           "installs it)")

# Constructs every long enough run must exercise: a marker in the program text each.
FEATURES = {
    "normal rule": " :- ", "choice": "{ ", "choice bounds": "} 1", "constraint": "\n:- ",
    "not": "not ", "not not": "not not ", "classical": "-q(", "disjunction ;": " ; ",
    "disjunction |": " | ", "#count": "#count", "#sum": "#sum {", "#sum+": "#sum+", "#min": "#min",
    "#max": "#max", "weak constraint": ":~", "#minimize": "#minimize", "#maximize": "#maximize",
    "priority": "@", "negative weight": "[-", "#project sig": "#project q/1",
    "#project atom": "#project p(V", "#heuristic": "#heuristic", "#show": "#show",
    "#external": "#external", "#external free": "[free]", "conditional literal": ") : ",
    "symbol order": "omin(X)",
}

MAX_MODELS = 2000
TIMEOUT = 30


def flags(opts):
    return (["--project"] if opts["project"] else []) + (
        ["--heuristic=domain"] if opts["heuristic"] else [])


def lucent_command(lucent, opts, path="-"):
    return [lucent, "-n", "0", "--outf=2", "--opt-mode=optN"] + flags(opts) + [path]


def clingo_args(opts):
    args = ["--models=0", "--opt-mode=optN"]
    if opts["project"]:
        args.append("--project")
    if opts["heuristic"]:
        args.append("--heuristic=Domain")
    return args


def answer(result, models, optimum=None):
    """The comparable answer: (result word, optimum or None, sorted models). An optimum of
    all zeros compares as no optimization (`SATISFIABLE`, no optimum): whether a minimize
    statement that no answer set pays for is kept at all is the grounder's simplification
    (gringo drops `#maximize { -2 : p(X) }` when it finds no `p` atom; Lucent may keep it and
    find every `p` false while solving); the optimal answer sets are then all answer sets."""
    if optimum is not None and not any(optimum):
        optimum = None
        if result == "OPTIMUM FOUND":
            result = "SATISFIABLE"
    return ("answer", result, optimum, tuple(sorted(tuple(m) for m in models)))


def same(x, y):
    """Equal answers, where optima of different lengths compare without their zero levels: a
    priority level that only atoms no answer set has pay for is kept by one grounder and
    dropped by the other (clingo's [1, 0] against Lucent's [1], or [0, 3] against [3])."""
    if x == y:
        return True
    if x[0] != "answer" or y[0] != "answer" or x[2] is None or y[2] is None:
        return False
    if len(x[2]) == len(y[2]):
        return False
    nz = lambda o: tuple(c for c in o if c != 0)  # noqa: E731
    return x[:2] == y[:2] and x[3] == y[3] and nz(x[2]) == nz(y[2])


def restrict(ans, keep):
    """`ans` with each answer set cut down to the symbols in `keep` (None: unchanged)."""
    if keep is None or ans[0] != "answer":
        return ans
    _, result, optimum, models = ans
    return answer(result, [[s for s in m if s in keep] for m in models], optimum)


class Projection:
    """clingo's ground program observer, for the shown symbols that are projected: with
    `#project`, projective enumeration gives one answer set per projection, and which one
    (its atoms outside the projection) is the search's choice, so answer sets compare on
    the shown symbols whose atoms are projected (or facts) only."""

    def __init__(self):
        self.projected = None
        self.shown = []

    def project(self, atoms):
        self.projected = (self.projected or set()) | set(atoms)

    def output_atom(self, symbol, atom):
        self.shown.append((str(symbol), atom))

    def keep(self):
        if self.projected is None:
            return None
        return {s for s, a in self.shown if a == 0 or a in self.projected}


def run_lucent(lucent, text, opts):
    try:
        p = subprocess.run(lucent_command(lucent, opts), input=text.encode(),
                           capture_output=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return ("failure", f"timeout after {TIMEOUT} s")
    if p.returncode == 65:
        return ("error",)
    if p.returncode not in (0, 10, 20, 30):
        err = p.stderr.decode(errors="replace").strip().splitlines()[-3:]
        return ("failure", f"exit {p.returncode}: {' | '.join(err)}")
    try:
        js = json.loads(p.stdout)
    except ValueError:
        return ("failure", "no JSON output")
    witnesses = [w for call in js.get("Call", []) for w in call.get("Witnesses", [])]
    models = [sorted(w.get("Value", [])) for w in witnesses]
    result = js.get("Result")
    optimal = js.get("Models", {}).get("Optimal")
    if optimal is not None and witnesses:
        last = witnesses[-optimal:] if optimal else []
        costs = tuple(witnesses[-1].get("Costs", []))
        return answer(result, [sorted(w.get("Value", [])) for w in last], costs or None)
    return answer(result, models)


def run_clingo(text, opts, extra=()):
    """clingo 5.8 on `text`: (an answer, ("error",), or None with more than MAX_MODELS
    models; the shown symbols answer sets compare on, None for all, see `Projection`)."""
    obs = Projection()
    try:
        ctl = clingo.Control(clingo_args(opts) + list(extra), logger=lambda c, m: None, message_limit=0)
        if opts["project"]:
            ctl.register_observer(obs)
        ctl.add("base", [], text)
        ctl.ground([("base", [])])
        models = []
        with ctl.solve(yield_=True) as handle:
            for m in handle:
                models.append((sorted(str(s) for s in m.symbols(shown=True)), tuple(m.cost),
                               m.optimality_proven))
                if len(models) > MAX_MODELS:
                    return None, None
            res = handle.get()
    except RuntimeError:
        return ("error",), None
    keep = obs.keep()
    if res.unsatisfiable:
        return answer("UNSATISFIABLE", []), keep
    if not res.satisfiable:
        return ("failure", "clingo: UNKNOWN"), keep
    if models and models[-1][1]:
        proven = [m for m in models if m[2]]
        word = "OPTIMUM FOUND" if res.exhausted else "SATISFIABLE"
        opt = proven[-1][1] if proven else None
        return restrict(answer(word, [m[0] for m in proven], opt), keep), keep
    return restrict(answer("SATISFIABLE", [m[0] for m in models]), keep), keep


def compare(lucent, stmts, opts):
    """(clingo's answer, Lucent's answer or None when skipped). When they differ, clingo runs
    again with `--eq=0` and that answer counts if it is Lucent's: clasp's equivalence
    preprocessing reports wrong answer sets on some non-head-cycle-free programs (gringo's
    translation of `1 #count { X,s : s(X) : d(X) } 2 :- s(Y) : s(Y).` beside
    `1 #count { X,s : s(X) : d(X) } 3.` over d(1..3) gets a 7th answer set, {s(1), s(2),
    s(3)}, which breaks the first rule's upper bound; 6 with --eq=0 or --eq=1, and from
    Lucent)."""
    text = random_asp.render(stmts)
    ref, keep = run_clingo(text, opts)
    if ref is None:
        return None, None
    ours = restrict(run_lucent(lucent, text, opts), keep)
    if same(ref, ours):
        return ref, ref
    ref0, keep0 = run_clingo(text, opts, ["--eq=0"])
    if ref0 is not None and same(restrict(ours, keep0), ref0):
        return ("eq0", ref0), ("eq0", ref0)
    return ref, ours


def differs(lucent, stmts, opts):
    ref, ours = compare(lucent, stmts, opts)
    return ref is not None and not same(ref, ours)


def shrink(lucent, stmts, opts):
    """Delta debugging: the smallest program (statements, parts' elements, options) found
    that still makes the two disagree."""
    stmts = [list(s) for s in stmts]
    changed = True
    while changed:
        changed = False
        chunk = max(1, (len(stmts) - 1) // 2)
        while chunk >= 1:
            i = 1  # statement 0 is the seed comment
            while i < len(stmts):
                cand = stmts[:i] + stmts[i + chunk:]
                if differs(lucent, cand, opts):
                    stmts = cand
                    changed = True
                else:
                    i += chunk
            chunk //= 2
        for si in range(len(stmts)):
            for pi, piece in enumerate(stmts[si]):
                if isinstance(piece, str):
                    continue
                j = 0
                while j < len(stmts[si][pi].items):
                    part = stmts[si][pi]
                    if len(part.items) <= part.least:
                        break
                    cand_stmt = stmts[si][:pi] + [part.without(j)] + stmts[si][pi + 1:]
                    cand = stmts[:si] + [cand_stmt] + stmts[si + 1:]
                    if differs(lucent, cand, opts):
                        stmts = cand
                        changed = True
                    else:
                        j += 1
        for key in ("project", "heuristic"):
            if opts[key]:
                cand = dict(opts, **{key: False})
                if differs(lucent, stmts, cand):
                    opts = cand
                    changed = True
    return stmts, opts


def describe(ans):
    if ans is None:
        return "skipped"
    if ans[0] != "answer":
        return " ".join(str(x) for x in ans)
    _, result, optimum, models = ans
    opt = f" optimum {list(optimum)}" if optimum is not None else ""
    shown = "; ".join("{" + " ".join(m) + "}" for m in models[:30])
    more = f" ... ({len(models)} in all)" if len(models) > 30 else ""
    return f"{result}{opt}, {len(models)} answer sets: {shown}{more}"


_LUCENT = None


def init(lucent):
    global _LUCENT
    _LUCENT = lucent


def check(seed):
    """One program: (seed, outcome, features, reproducer text or None)."""
    stmts, opts = random_asp.program(seed)
    text = random_asp.render(stmts)
    used = [name for name, marker in FEATURES.items() if marker in text]
    ref, ours = compare(_LUCENT, stmts, opts)
    if ref is None:
        return seed, "skipped", used, None
    if ref == ours:
        if ref[0] == "eq0":
            return seed, "agreed with --eq=0", used, None
        return seed, "both rejected" if ref == ("error",) else "agreed", used, None
    small, small_opts = shrink(_LUCENT, stmts, opts)
    ref2, ours2 = compare(_LUCENT, small, small_opts)
    lines = [
        f"% diff_random: seed {seed}, Lucent and clingo 5.8 disagree (shrunk program below)",
        f"% {' '.join(lucent_command('lucent', small_opts, 'FILE'))}",
        f"% clingo 5.8 (Python): Control({clingo_args(small_opts)}), models shown=True",
        f"% lucent: {describe(ours2)}",
        f"% clingo: {describe(ref2)}",
        random_asp.render(small[1:]).rstrip("\n"),
        f"% the original program (options {flags(opts)}):",
        f"% lucent: {describe(ours)}",
        f"% clingo: {describe(ref)}",
    ] + ["% " + line for line in text.splitlines()]
    return seed, "disagreed", used, "\n".join(lines) + "\n"


def default_lucent():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    target = os.environ.get("CARGO_TARGET_DIR", os.path.join(root, "target"))
    return os.path.join(target, "release", "lucent")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--count", type=int, default=1000, help="number of programs [1000]")
    ap.add_argument("--seed", type=int, default=0, help="seed of the first program [0]")
    ap.add_argument("--workers", type=int, default=2, help="worker processes [2]")
    ap.add_argument("--lucent", default=default_lucent(),
                    help="the lucent binary [$CARGO_TARGET_DIR/release/lucent]")
    ap.add_argument("--out", default=os.path.join(tempfile.gettempdir(), "lucent-diff-random"),
                    help="directory for reproducers [%(default)s]")
    ap.add_argument("--print", type=int, metavar="SEED", help="print one program and exit")
    args = ap.parse_args()
    if args.print is not None:
        stmts, opts = random_asp.program(args.print)
        sys.stdout.write(f"% options: {flags(opts)}\n" + random_asp.render(stmts))
        return 0
    if clingo is None:
        print(f"error: {INSTALL}", file=sys.stderr)
        return 2
    if not clingo.__version__.startswith("5.8"):
        print(f"error: clingo {clingo.__version__} found, 5.8 wanted; {INSTALL}", file=sys.stderr)
        return 2
    if not os.access(args.lucent, os.X_OK):
        print(f"error: no lucent binary at {args.lucent} (cargo build --release, or --lucent)",
              file=sys.stderr)
        return 2

    start = time.time()
    counts = {"agreed": 0, "both rejected": 0, "agreed with --eq=0": 0, "skipped": 0,
              "disagreed": 0}
    feature_counts = dict.fromkeys(FEATURES, 0)
    reproducers = []
    seeds = range(args.seed, args.seed + args.count)
    with multiprocessing.Pool(args.workers, initializer=init, initargs=(args.lucent,)) as pool:
        for seed, outcome, used, repro in pool.imap_unordered(check, seeds, chunksize=25):
            counts[outcome] += 1
            for name in used:
                feature_counts[name] += 1
            if repro is not None:
                os.makedirs(args.out, exist_ok=True)
                path = os.path.join(args.out, f"seed-{seed}.lp")
                with open(path, "w") as f:
                    f.write(repro)
                reproducers.append(path)
                print(f"DISAGREE seed {seed}: {path}", flush=True)
    elapsed = time.time() - start

    agreed = counts["agreed"] + counts["both rejected"] + counts["agreed with --eq=0"]
    print(f"programs {args.count} (seeds {args.seed}..{args.seed + args.count - 1}), "
          f"agreed {agreed} (both rejected {counts['both rejected']}, with clingo --eq=0 only "
          f"{counts['agreed with --eq=0']}), skipped "
          f"{counts['skipped']} (over {MAX_MODELS} answer sets), disagreed {counts['disagreed']}")
    print("constructs (programs using each): " + ", ".join(
        f"{k} {v}" for k, v in feature_counts.items()))
    print(f"time {elapsed:.1f} s, {args.count / max(elapsed, 1e-9):.1f} programs/s, "
          f"{args.workers} workers, clingo {clingo.__version__}, lucent {args.lucent}")
    ok = counts["disagreed"] == 0
    if args.count >= 500:
        missing = [k for k, v in feature_counts.items() if v == 0]
        if missing:
            print(f"FAIL: no program used {missing}")
            ok = False
        if counts["skipped"] * 10 > args.count:
            print(f"FAIL: {counts['skipped']} programs skipped, over 10%")
            ok = False
    if reproducers:
        print(f"FAIL: {len(reproducers)} disagreements, reproducers in {args.out}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
