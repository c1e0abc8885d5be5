"""clingo's ``clingo.application``: ``Application``, ``ApplicationOptions``, ``Flag`` and
``clingo_main``, so that a script written as a clingo application runs with ``lucent``.

``clingo_main(app, arguments)`` reads the command line (the application's own options, which
``register_options`` declares; numbers and the solver options that ``lucent.Control`` reads;
``--outf``, ``--verbose``/``-V`` and ``--quiet``/``-q``, which shape the output; every other
argument is an input file), calls ``app.main(control, files)`` (or, without a ``main``, loads
the files, or standard input, grounds ``base`` and solves), and prints what clingo 5.8's
application prints: the header, ``Solving...`` per call, each model (``Answer: N (Time: ...)``,
the shown symbols, ``Optimization: ...``; through ``app.print_model(model, printer)`` when the
application has one), the last call's result and the summary; with ``--outf=2`` the same as
clingo's JSON. It returns clingo's exit code: 10 satisfiable, 20 exhausted (both: 30), 65 or'ed
in when ``main`` raises, 1 for a bad command line.

Invariants: the models printed and counted are exactly those the Control's solve calls hand
to their ``on_model`` (a user callback returning ``False`` still stops the search after the
model is printed, as in clingo); the output of one run is written only through ``_Output``.
Differences from clingo (by design): the header names lucent unless the application sets
``program_name``/``version``; ``--help`` lists only the application's options and the output
options above; times are Lucent's.
"""

import json as _json
import sys as _sys
import time as _time

from . import Control as _Control

__all__ = ["Application", "ApplicationOptions", "Flag", "clingo_main"]


class Flag:
    """A boolean option's value (clingo's ``Flag``), set by ``--option`` on the command line."""

    def __init__(self, value=False):
        self.flag = bool(value)

    def __repr__(self):
        return f"Flag({self.flag})"


class Application:
    """The interface of a clingo application: every member is optional but ``main``.

    ``program_name``, ``version``, ``message_limit``, ``main(control, files)``,
    ``register_options(options)``, ``validate_options()``, ``print_model(model, printer)``,
    ``logger(code, message)``.
    """


class _Option:
    def __init__(self, group, names, description, parser, multi, argument, flag):
        self.group = group
        self.names = names  # long name first, then a one-letter short name if any
        self.description = description
        self.parser = parser
        self.multi = multi
        self.argument = argument
        self.flag = flag
        self.seen = 0


class ApplicationOptions:
    """What ``register_options`` receives: ``add`` declares an option with a value (its
    ``parser(value)`` returns ``False`` to reject the value), ``add_flag`` a switch."""

    def __init__(self):
        self._options = []

    @staticmethod
    def _names(option):
        # clingo's form: "name[,k][@level]" (k: a one-letter short name, level: help level).
        option = option.split("@", 1)[0]
        parts = [p for p in option.split(",") if p]
        if not parts:
            raise ValueError("an option needs a name")
        return parts

    def add(self, group, option, description, parser, multi=False, argument=None):
        self._options.append(
            _Option(group, self._names(option), description, parser, multi, argument, None)
        )

    def add_flag(self, group, option, description, target):
        self._options.append(
            _Option(group, self._names(option), description, None, False, None, target)
        )

    def _find(self, name):
        for o in self._options:
            if name in o.names:
                return o
        return None


class _UsageError(Exception):
    pass


_FLAG_VALUES = {"1": True, "yes": True, "on": True, "true": True,
                "0": False, "no": False, "off": False, "false": False}


class _Settings:
    """The command line split into the application's options, the output's and the Control's."""

    def __init__(self):
        self.control_args = []
        self.files = []
        self.outf = 0
        self.verbose = 1
        self.quiet = 0
        self.help = False


def _parse(arguments, options):
    s = _Settings()
    args = [str(a) for a in arguments]
    i = 0
    while i < len(args):
        arg = args[i]
        i += 1
        if arg in ("-h", "--help") or arg.startswith("--help="):
            s.help = True
            continue
        if arg.startswith("--") and len(arg) > 2:
            name, eq, value = arg[2:].partition("=")
            o = options._find(name)
            if o is None:
                if name == "outf":
                    s.outf = _int_option(name, value)
                elif name == "verbose":
                    s.verbose = _int_option(name, value) if eq else 2
                elif name == "quiet":
                    s.quiet = _int_option(name, value.split(",")[0]) if eq else 2
                else:
                    s.control_args.append(arg)
                continue
            if o.flag is not None:
                if eq and value.lower() not in _FLAG_VALUES:
                    raise _UsageError(f"'{value}' invalid value for: '{o.names[0]}'")
                _set(o, _FLAG_VALUES[value.lower()] if eq else True)
                continue
            if not eq:
                if i >= len(args):
                    raise _UsageError(f"missing value for: '{o.names[0]}'")
                value = args[i]
                i += 1
            _set(o, value)
            continue
        if arg.startswith("-") and len(arg) > 1 and not arg[1:].isdigit():
            short, rest = arg[1], arg[2:]
            o = options._find(short)
            if o is None:
                if short == "V":
                    s.verbose = _int_option("verbose", rest) if rest else 2
                elif short == "q":
                    s.quiet = _int_option("quiet", rest.split(",")[0]) if rest else 2
                else:
                    s.control_args.append(arg)
                continue
            if o.flag is not None:
                _set(o, True)
                continue
            if not rest:
                if i >= len(args):
                    raise _UsageError(f"missing value for: '{o.names[0]}'")
                rest = args[i]
                i += 1
            _set(o, rest)
            continue
        if arg.isdigit():
            s.control_args.append(arg)
        else:
            s.files.append(arg)
    return s


def _int_option(name, value):
    try:
        return int(value)
    except ValueError:
        raise _UsageError(f"'{value}' invalid value for: '{name}'") from None


def _set(option, value):
    option.seen += 1
    if option.seen > 1 and not option.multi:
        raise _UsageError(f"multiple occurrences: '{option.names[0]}'")
    if option.flag is not None:
        option.flag.flag = value
        return
    if option.parser(value) is False:
        raise _UsageError(f"'{value}' invalid value for: '{option.names[0]}'")


class _Output:
    """What clingo's application prints, in text (``outf`` 0) or JSON (2); 3 prints nothing."""

    def __init__(self, app, settings):
        self.app = app
        self.s = settings
        self.start = _time.perf_counter()
        self.cpu = _time.process_time()
        self.calls = []  # per call: {"Start", "Witnesses", "Stop"}
        self.models = 0
        self.result = None  # the last call's SolveResult
        self.costs = None
        self.optimal = 0
        self.first_model = None
        self.name = getattr(app, "program_name", None)
        self.version = getattr(app, "version", None)

    def now(self):
        return _time.perf_counter() - self.start

    def text(self, line):
        if self.s.outf == 0:
            print(line)

    def header(self):
        name = self.name or "lucent"
        if self.version is not None:
            version = self.version
        else:
            try:
                from importlib.metadata import version as _dist_version

                version = _dist_version("lucent")
            except Exception:  # not installed as a distribution (a source tree on the path)
                version = "(source tree)"
        self.solver = f"{name} version {version}"
        self.inputs = list(self.s.files) or ["stdin"]
        if self.s.verbose >= 1:
            self.text(self.solver)
            first = "stdin" if not self.s.files else self.s.files[0]
            self.text("Reading from " + first + (" ..." if len(self.s.files) > 1 else ""))

    def begin_call(self):
        self.calls.append({"Start": self.now(), "Witnesses": []})
        if self.s.verbose >= 1:
            self.text("Solving...")

    def model(self, model):
        self.models += 1
        t = self.now()
        if self.first_model is None:
            self.first_model = t
        cost = list(model.cost)
        if cost:
            self.costs = cost
        if model.optimality_proven:
            self.optimal += 1
        extended = [str(s) for s in model._extended]
        witness = {"Time": t, "Value": [str(s) for s in model.symbols(shown=True)] + extended}
        if cost:
            witness["Costs"] = cost
        self.calls[-1]["Witnesses"].append(witness)
        if self.s.outf != 0 or self.s.quiet >= 2:
            return
        if self.s.verbose >= 1:
            print(f"Answer: {model.number} (Time: {t:.3f}s)")

        def printer():
            print(" ".join([str(model)] + extended) if extended else str(model))

        custom = getattr(self.app, "print_model", None)
        if custom is not None:
            custom(model, printer)
        else:
            printer()
        if cost:
            print("Optimization: " + " ".join(str(c) for c in cost))

    def end_call(self, result):
        self.result = result
        if self.calls:
            self.calls[-1]["Stop"] = self.now()

    def word(self):
        r = self.result
        if r is None or r.unknown:
            return "UNKNOWN"
        if r.unsatisfiable:
            return "UNSATISFIABLE"
        if self.costs is not None and r.exhausted:
            return "OPTIMUM FOUND"
        return "SATISFIABLE"

    def exit_code(self):
        r = self.result
        if r is None:
            return 0
        code = 10 if r.satisfiable else 0
        if r.exhausted:
            code |= 20
        if r.interrupted and not r.exhausted and not r.satisfiable:
            code |= 1
        return code

    def summary(self):
        total = self.now()
        cpu = _time.process_time() - self.cpu
        solve = sum(c.get("Stop", total) - c["Start"] for c in self.calls)
        more = not (self.result is not None and self.result.exhausted)
        optimum = self.costs is not None and self.word() == "OPTIMUM FOUND"
        if self.s.outf == 2:
            out = {
                "Solver": self.solver,
                "Input": self.inputs,
                "Call": [
                    {k: c[k] for k in ("Start", "Witnesses", "Stop") if k in c}
                    for c in self.calls
                ],
                "Result": self.word(),
                "Models": {"Number": self.models, "More": "yes" if more else "no"},
                "Calls": max(len(self.calls), 1),
                "Time": {
                    "Total": round(total, 3),
                    "Solve": round(solve, 3),
                    "Model": round(self.first_model or 0.0, 3),
                    "Unsat": 0.0,
                    "CPU": round(cpu, 3),
                },
            }
            if self.costs is not None:
                out["Models"]["Optimum"] = "yes" if optimum else "no"
                if optimum:
                    out["Models"]["Optimal"] = max(self.optimal, 1)
                out["Models"]["Costs"] = self.costs
            print(_json.dumps(out, indent=2))
            return
        if self.s.outf != 0:
            return
        print(self.word())
        if self.s.verbose < 1:
            return
        print()
        print(f"Models       : {self.models}{'+' if more else ''}")
        if self.costs is not None:
            print(f"  Optimum    : {'yes' if optimum else 'no'}")
            print("Optimization : " + " ".join(str(c) for c in self.costs))
        # clingo counts one call even when ``main`` never solved.
        print(f"Calls        : {max(len(self.calls), 1)}")
        print(
            f"Time         : {total:.3f}s (Solving: {solve:.2f}s "
            f"1st Model: {(self.first_model or 0.0):.2f}s Unsat: 0.00s)"
        )
        print(f"CPU Time     : {cpu:.3f}s")


class _AppControl(_Control):
    """The Control an application's ``main`` receives: every solve call goes through the
    application's output (models printed and counted, the result kept)."""

    def __init__(self, arguments, output):
        super().__init__(arguments)
        object.__setattr__(self, "_out", output)

    def solve(self, assumptions=(), on_model=None, on_finish=None, **kwargs):
        out = self._out
        out.begin_call()

        def seen(model):
            # the user's callback first (it may ``extend`` the model), then the printing
            answer = None if on_model is None else on_model(model)
            out.model(model)
            return answer

        def finished(result):
            out.end_call(result)
            if on_finish is not None:
                on_finish(result)

        return super().solve(assumptions, on_model=seen, on_finish=finished, **kwargs)


def _default_main(control, files):
    if files:
        for f in files:
            control.load(f)
    else:
        control.add("base", [], _sys.stdin.read())
    control.ground([("base", [])])
    control.solve()


def _help(app, options):
    name = getattr(app, "program_name", None) or "lucent"
    print(f"{name} [number] [options] [files]")
    groups = {}
    for o in options._options:
        groups.setdefault(o.group, []).append(o)
    for group, opts in groups.items():
        print(f"\n{group} Options:\n")
        for o in opts:
            long = "--" + o.names[0]
            if o.flag is None:
                long += "=" + (o.argument or "<arg>")
            short = f",-{o.names[1]}" if len(o.names) > 1 else ""
            print(f"  {long}{short}\t: {o.description}")
    print("\nOutput Options:\n\n  --outf=<n>\t: 0 text, 2 JSON, 3 none\n"
          "  --verbose,-V<n>\t: verbosity\n  --quiet,-q<n>\t: 2 prints no models")


def clingo_main(application, arguments=None):
    """Runs ``application`` as clingo's ``clingo_main`` does; returns the exit code."""
    if arguments is None:
        arguments = _sys.argv[1:]
    options = ApplicationOptions()
    name = getattr(application, "program_name", None) or "lucent"
    try:
        register = getattr(application, "register_options", None)
        if register is not None:
            register(options)
        settings = _parse(arguments, options)
        if settings.help:
            _help(application, options)
            return 0
        validate = getattr(application, "validate_options", None)
        if validate is not None and validate() is False:
            raise _UsageError("invalid options")
        output = _Output(application, settings)
        control = _AppControl(settings.control_args, output)
    except (_UsageError, RuntimeError) as e:
        print(f"*** ERROR: ({name}): {e}", file=_sys.stderr)
        print(f"*** Info : ({name}): Try '--help' for usage information", file=_sys.stderr)
        return 1
    output.header()
    code = 0
    main = getattr(application, "main", None)
    try:
        if main is not None:
            main(control, list(settings.files))
        else:
            _default_main(control, list(settings.files))
    except Exception as e:  # clingo prints the error and exits with 65 (or'ed in)
        import traceback

        traceback.print_exc()
        print(f"*** ERROR: ({name}): {e}", file=_sys.stderr)
        code = 65
    output.summary()
    if code:
        # clingo: the error's 65 with the satisfiable bit of the last call (not the exhausted one)
        return code | (output.exit_code() & 10)
    return output.exit_code()
