"""Lucent from Python, on the model of clingo's Python API (issue 33 item 2).

A typical clingo script runs with ``import lucent as clingo``::

    import lucent as clingo
    ctl = clingo.Control(["0"])
    ctl.add("base", [], "{a; b}.")
    ctl.ground([("base", [])])
    ctl.solve(on_model=print)

The native module ``lucent._lucent`` (Rust, PyO3) holds ``Symbol``, ``Model`` and the
Control's calls; this module shapes them as clingo's classes (``Control``, ``SolveResult``,
``SolveHandle``, ``SymbolicAtoms``, ``Backend``, ``configuration``, ``statistics``) and adds
the robot's verbs ``plan`` and ``explain``, which return Python values.

Applications (``Application``, ``clingo_main``) are in ``lucent.application``, clingo's
submodules (``symbol``, ``control``, ``solving``, ``core``, ``theory_atoms``,
``propagator``) beside it.

Differences from clingo, by design or not yet done (docs/reference.md, "Python"): handles
search on a thread of their own, lazily with ``yield_``, but without ``yield_``, ``async_`` hands the models to ``on_model`` on the thread that calls
``wait``/``get`` (clingo: on the search thread); ``on_unsat`` gets the lower bounds of core-guided
optimization (``--opt-strategy=usc``), each core's, as clingo, but the cores are Lucent's own;
atoms added through the backend are not seen by later groundings.
"""

import enum as _enum
import functools as _functools
import json as _json
import sys as _sys

from . import _lucent
from ._lucent import (  # noqa: F401 (re-exported: clingo's names)
    Function,
    Infimum,
    Model,
    Number,
    String,
    Supremum,
    Symbol,
    SymbolType,
    Tuple_,
    parse_term,
)
from .propagator import (  # noqa: F401 (re-exported: clingo's names)
    Assignment,
    PropagateControl,
    PropagateInit,
    Propagator,
    PropagatorCheckMode,
    PropagatorUndoMode,
    Trail,
)

__version__ = "5.8.0"
"""The clingo Python API version this module follows."""


class _SymbolSequence(list):
    """A model's symbols (``Model.symbols``), as clingo's sequence: printed, the symbols show
    as ``str`` (``[a, b(1)]``); its ``repr`` and a plain list of them show each symbol's
    ``repr`` (``Function('a', [], True)``)."""

    def __str__(self):
        return "[" + ", ".join(str(s) for s in self) + "]"


@_functools.total_ordering
class OrderedEnum(_enum.Enum):
    """clingo's ``OrderedEnum``: an enum whose members compare by their values."""

    def __lt__(self, other):
        if self.__class__ is other.__class__:
            return self.value < other.value
        return NotImplemented


def version():
    """The clingo version whose Python API this module follows, as clingo's ``version()``."""
    return tuple(int(p) for p in __version__.split("."))


class MessageCode(OrderedEnum):
    """clingo's ``MessageCode`` (the first argument of a ``logger``)."""

    OperationUndefined = 0
    RuntimeError = 1
    AtomUndefined = 2
    FileIncluded = 3
    VariableUnbounded = 4
    GlobalVariable = 5
    Other = 6


class TruthValue(_enum.Enum):
    """clingo's ``TruthValue`` for externals."""

    True_ = True
    False_ = False
    Free = None
    Release = "release"


class HeuristicType(OrderedEnum):
    """clingo's ``HeuristicType``: the modifier of a ``#heuristic`` directive
    (``Backend.add_heuristic``)."""

    Level = 0
    Sign = 1
    Factor = 2
    Init = 3
    True_ = 4
    False_ = 5


class ModelType(OrderedEnum):
    """clingo's ``ModelType``: stable models, or the brave or cautious consequences found so
    far under ``--enum-mode``."""

    StableModel = 0
    BraveConsequences = 1
    CautiousConsequences = 2


class SolveResult:
    """clingo's ``SolveResult``."""

    __slots__ = ("satisfiable", "unsatisfiable", "exhausted", "interrupted")

    def __init__(self, sat, unsat, exhausted, interrupted):
        self.satisfiable = True if sat else (False if unsat else None)
        self.unsatisfiable = True if unsat else (False if sat else None)
        self.exhausted = exhausted
        self.interrupted = interrupted

    @property
    def unknown(self):
        return self.satisfiable is None

    def __str__(self):
        if self.satisfiable:
            return "SAT"
        if self.unsatisfiable:
            return "UNSAT"
        return "UNKNOWN"

    __repr__ = __str__


class SolveHandle:
    """clingo's ``SolveHandle``: a context manager and an iterator over the call's models.

    The search runs on a thread of its own (python/src/handle.rs) and stops after each model
    until ``resume`` (``yield_``), so a loop that breaks early pays for the models it read;
    with ``async_`` it starts at once, and without ``yield_`` it runs ahead, the models going
    to ``on_model`` when ``wait`` or ``get`` is called (clingo calls it from the search
    thread). Every wait releases the GIL.
    """

    def __init__(self, native, yield_, on_model=None, on_finish=None, on_core=None, on_last=None,
                 on_statistics=None):
        self._h = native
        self._yield = yield_
        self._on_model = on_model
        self._on_finish = on_finish
        self._on_core = on_core
        self._on_last = on_last
        self._on_statistics = on_statistics
        self._seen = None
        self._last = None
        self._stop = False
        self._result = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __iter__(self):
        return self

    def __next__(self):
        self.resume()
        model = self.model()
        if model is None:
            raise StopIteration
        return model

    def _see(self, model):
        """``on_model`` once per model; ``False`` stops the search after it."""
        if model is None or model is self._seen:
            return
        self._seen = model
        self._last = model
        if self._on_model is not None and self._on_model(model) is False:
            self._stop = True

    def _flags(self):
        (sat, unsat, exhausted, interrupted, core), finished = self._h.get()
        if finished and self._result is None:
            self._result = SolveResult(sat, unsat, exhausted, interrupted)
            if self._on_core is not None and unsat and core is not None:
                self._on_core(core)
            if self._on_last is not None and self._last is not None:
                self._on_last(self._last)
            if self._on_statistics is not None:
                self._on_statistics()
            if self._on_finish is not None:
                self._on_finish(self._result)
        return SolveResult(sat, unsat, exhausted, interrupted)

    def _drain(self, timeout):
        """Without ``yield_``: hands the models found to ``on_model`` until the end or the
        timeout; True at the end."""
        import time

        deadline = None if timeout is None else time.monotonic() + timeout
        while True:
            left = None if deadline is None else max(0.0, deadline - time.monotonic())
            if not self._h.wait(left):
                return False
            model = self._h.model()
            if model is None:
                self._flags()
                return True
            self._see(model)
            if self._stop:
                self.cancel()
                return True
            self._h.resume()

    def resume(self):
        """Discards the current model; the search goes on."""
        if self._stop:
            self.cancel()
        else:
            self._h.resume()

    def model(self):
        """The current model (waiting for it), or ``None`` when the search is over."""
        model = self._h.model()
        if model is None:
            self._flags()
        self._see(model)
        return model

    def wait(self, timeout=None):
        """Waits up to ``timeout`` seconds (forever: ``None``) for the next result; True when
        it is there (without ``yield_``: when the search is over)."""
        if not self._yield:
            return self._drain(timeout)
        ready = self._h.wait(timeout)
        if ready:
            self.model()
        return ready

    def get(self):
        """The call's ``SolveResult`` once the next result is there (with ``yield_`` and a
        model current: satisfiable so far)."""
        if not self._yield:
            self._drain(None)
        else:
            self.model()
        return self._flags()

    def core(self):
        """The failed assumptions (program literals) once the call is unsatisfiable under
        assumptions, else an empty list (clingo 5.8's ``SolveHandle.core``)."""
        result = self.get()
        (_, unsat, _, _, core), _ = self._h.get()
        return list(core) if result.unsatisfiable and unsat and core is not None else []

    def last(self):
        """The last model handed out so far, or ``None`` (clingo 5.8's ``SolveHandle.last``)."""
        return self._last

    def cancel(self):
        """Stops the search."""
        self._h.cancel()
        self._flags()

    def close(self):
        """Stops what is unfinished and gives the Control back (leaving a ``with`` block)."""
        self._h.close()
        self._flags()


class SymbolicAtom:
    """clingo's ``SymbolicAtom``."""

    __slots__ = ("symbol", "literal", "is_fact", "is_external")

    def __init__(self, symbol, literal, is_fact, is_external):
        self.symbol = symbol
        self.literal = literal
        self.is_fact = is_fact
        self.is_external = is_external

    def match(self, name, arity, positive=True):
        return self.symbol.match(name, arity, positive)


class SymbolicAtoms:
    """clingo's ``SymbolicAtoms``: iteration, lookup by symbol, ``by_signature``."""

    def __init__(self, native):
        # The native Control, or a model's context (``SolveControl``: ``_atoms``, ``_atom``).
        self._atoms = getattr(native, "_atoms", None) or native.symbolic_atoms
        self._atom = getattr(native, "_atom", None) or native.symbolic_atom

    def _all(self):
        return [SymbolicAtom(*t) for t in self._atoms()]

    def __iter__(self):
        return iter(self._all())

    def __len__(self):
        return len(self._atoms())

    def __getitem__(self, symbol):
        found = self._atom(symbol)
        if found is None:
            return None
        return SymbolicAtom(symbol, *found)

    def __contains__(self, symbol):
        return self._atom(symbol) is not None

    def by_signature(self, name, arity, positive=True):
        return iter([a for a in self._all() if a.symbol.match(name, arity, positive)])

    @property
    def signatures(self):
        seen = []
        for a in self._all():
            s = a.symbol
            if s.type == SymbolType.Function:
                sig = (s.name, len(s.arguments), s.positive)
                if sig not in seen:
                    seen.append(sig)
        return seen


class _SolveConfiguration:
    """``configuration.solve``: ``models``, ``opt_mode`` and ``enum_mode``, string-valued as
    clingo's."""

    def __init__(self, native):
        object.__setattr__(self, "_c", native)
        object.__setattr__(self, "_opt_mode", "opt")
        object.__setattr__(self, "_enum_mode", "auto")

    @property
    def models(self):
        n = self._c.models
        return "-1" if n is None else str(n)

    @property
    def opt_mode(self):
        return self._opt_mode

    @property
    def enum_mode(self):
        return self._enum_mode

    def __setattr__(self, key, value):
        if key == "models":
            n = int(value)
            self._c.models = None if n < 0 else n
        elif key == "opt_mode":
            self._c.set_opt_mode(str(value))
            object.__setattr__(self, "_opt_mode", str(value))
        elif key == "enum_mode":
            self._c.set_enum_mode(str(value))
            object.__setattr__(self, "_enum_mode", str(value))
        else:
            raise RuntimeError(f"lucent: configuration option solve.{key} is not supported")


class Configuration:
    """``Control.configuration`` (the ``solve`` group)."""

    def __init__(self, native):
        self.solve = _SolveConfiguration(native)


class Backend:
    """clingo's ``Backend``: ground statements added from code (a context manager)."""

    def __init__(self, native):
        self._c = native

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def close(self):
        pass

    def add_atom(self, symbol=None):
        return self._c.backend_add_atom(symbol)

    def add_rule(self, head, body=(), choice=False):
        self._c.backend_add_rule(list(head), list(body), choice)

    def add_weight_rule(self, head, lower, body, choice=False):
        self._c.backend_add_weight_rule(list(head), lower, [tuple(x) for x in body], choice)

    def add_minimize(self, priority, literals):
        self._c.backend_add_minimize(priority, [tuple(x) for x in literals])

    def add_external(self, atom, value=TruthValue.False_):
        if value == TruthValue.Release:
            self._c.release_external(atom)
        else:
            self._c.backend_add_external(atom, _truth(value))

    def add_assume(self, literals):
        self._c.backend_add_assume(list(literals))

    def add_project(self, atoms):
        """Projection atoms (read with ``--project``)."""
        self._c.backend_add_project(list(atoms))

    def add_heuristic(self, atom, type_, bias, priority, condition):
        """A ``#heuristic`` directive (read with ``--heuristic=Domain``)."""
        self._c.backend_add_heuristic(atom, HeuristicType(type_).value, bias, priority,
                                      list(condition))

    def add_acyc_edge(self, node_u, node_v, condition):
        """An edge of the acyclicity constraint, present when ``condition`` holds."""
        self._c.backend_add_acyc_edge(node_u, node_v, list(condition))


def _floats(value):
    """User statistics as clingo shows them: numbers as floats, maps and lists kept."""
    if isinstance(value, dict):
        return {k: _floats(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_floats(v) for v in value]
    return float(value)


def _truth(value):
    if isinstance(value, TruthValue):
        return value.value
    return value


class _AtomList:
    """``init.symbolic_atoms``: iteration, lookup by symbol and ``by_signature``."""

    def __init__(self, atoms):
        self._atoms = atoms
        self._by_symbol = None

    def __getitem__(self, symbol):
        if self._by_symbol is None:
            self._by_symbol = {a.symbol: a for a in self._atoms}
        return self._by_symbol.get(symbol)

    def __contains__(self, symbol):
        return self[symbol] is not None

    def __iter__(self):
        return iter(self._atoms)

    def __len__(self):
        return len(self._atoms)

    def by_signature(self, name, arity, positive=True):
        return iter([a for a in self._atoms if a.symbol.match(name, arity, positive)])


class TheoryTermType(OrderedEnum):
    """clingo's ``TheoryTermType``, with clingo 5.8's numbers (an ordered enum as clingo's:
    ``str`` is ``TheoryTermType.Number``, not the number)."""

    Tuple = 0
    List = 1
    Set = 2
    Function = 3
    Number = 4
    Symbol = 5


_BRACKETS = {TheoryTermType.Tuple: "()", TheoryTermType.List: "[]", TheoryTermType.Set: "{}"}
_OPERATOR = set("-+*/\\^?&|<=>@!~")


class TheoryTerm:
    """clingo's ``TheoryTerm``: ``type``, ``name``, ``number``, ``arguments``; printed as clingo
    prints it."""

    def __init__(self, type_, name, number, arguments):
        self.type = TheoryTermType(type_)
        self.name = name
        self.number = number
        self.arguments = arguments

    @staticmethod
    def _read(nodes, i=0):
        type_, name, number, arity = nodes[i]
        i += 1
        args = []
        for _ in range(arity):
            arg, i = TheoryTerm._read(nodes, i)
            args.append(arg)
        return TheoryTerm(type_, name, number, args), i

    def _key(self):
        return (int(self.type), self.name, self.number, [a._key() for a in self.arguments])

    def __eq__(self, other):
        return isinstance(other, TheoryTerm) and self._key() == other._key()

    def __lt__(self, other):
        return self._key() < other._key()

    def __hash__(self):
        return hash(str(self))

    def __str__(self):
        if self.type == TheoryTermType.Number:
            return str(self.number)
        if self.type == TheoryTermType.Symbol:
            return self.name
        args = ",".join(str(a) for a in self.arguments)
        if self.type == TheoryTermType.Function:
            op = self.name and all(c in _OPERATOR for c in self.name)
            if op and len(self.arguments) == 1:
                return f"({self.name}{self.arguments[0]})"
            if op and len(self.arguments) == 2:
                return f"({self.arguments[0]}{self.name}{self.arguments[1]})"
            return f"{self.name}({args})"
        left, right = _BRACKETS[self.type]
        if self.type == TheoryTermType.Tuple and len(self.arguments) == 1:
            args += ","
        return f"{left}{args}{right}"

    def __repr__(self):
        return f"TheoryTerm({self})"


class TheoryElement:
    """clingo's ``TheoryElement``: ``terms``, ``condition`` (program literals) and
    ``condition_id``: 0 for an empty condition, its literal for one literal, and for several
    a number of its own above the atoms (from ``2**28 + 1``, as clingo 5.8), which
    ``PropagateInit.solver_literal`` turns into a literal true exactly when the condition
    holds."""

    def __init__(self, terms, condition, condition_id, text):
        self.terms = [TheoryTerm._read(t)[0] for t in terms]
        self.condition = list(condition)
        self.condition_id = condition_id
        self._text = text

    def __str__(self):
        return self._text

    def __repr__(self):
        return f"TheoryElement({self._text})"


class TheoryAtom:
    """clingo's ``TheoryAtom``: ``term``, ``elements``, ``guard`` (``(operator, TheoryTerm)`` or
    ``None``) and ``literal`` (its program atom; 0 for a directive); ``str`` as clingo 5.8."""

    def __init__(self, literal, term, elements, guard, text):
        self.literal = literal
        self.term = TheoryTerm._read(term)[0]
        self.elements = [TheoryElement(*e) for e in elements]
        self.guard = None if guard is None else (guard[0], TheoryTerm._read(guard[1])[0])
        self._text = text

    def __str__(self):
        return self._text

    def __repr__(self):
        return f"TheoryAtom({self._text})"


class _PropagatorAdapter:
    """What the native Control calls (python/src/propagator.rs): each callback gets a live
    view of the solver, valid while it runs (``lucent.propagator``)."""

    def __init__(self, propagator):
        self._p = propagator
        # The Control's theory atoms when the solve call started (set by Control.solve).
        self._theory = ()

    def _init(self, atoms, threads, live):
        symbolic = _AtomList([SymbolicAtom(s, a, f, e) for (s, a, f, e, _) in atoms])
        init = PropagateInit(atoms, threads, live, self._theory, symbolic)
        if hasattr(self._p, "init"):
            self._p.init(init)
        return int(init.check_mode)

    def _propagate(self, thread_id, changes, live):
        if hasattr(self._p, "propagate"):
            self._p.propagate(PropagateControl(thread_id, live), changes)

    def _undo(self, thread_id, changes, live):
        if hasattr(self._p, "undo"):
            self._p.undo(thread_id, Assignment(live), changes)

    def _check(self, thread_id, live):
        if hasattr(self._p, "check"):
            self._p.check(PropagateControl(thread_id, live))


class Control:
    """clingo's ``Control``: add, load, ground, solve, externals, symbolic atoms, backend."""

    def __init__(self, arguments=(), logger=None, message_limit=20):
        # clingo's options (-n, -c, --opt-mode, --project, -t, --heuristic) are read by
        # lucent::Control::from_args; a bad one raises RuntimeError.
        self._c = _lucent.Control([str(a) for a in arguments])
        # Warnings go to `logger(code, message)`, else to standard error, at most
        # `message_limit` of them, as clingo's.
        self._logger = logger
        self._message_limit = message_limit
        self._interrupter = self._c.interrupter()
        # on_statistics: the user's maps (``user_step`` of the last call, ``user_accu`` kept).
        self._user = None
        # The model whose on_model callback runs (Control.solve), else None.
        self._model = None
        # The constants as the running solve call began (get_const inside on_model).
        self._consts = {}
        self.configuration = Configuration(self._c)
        object.__setattr__(self.configuration.solve, "_opt_mode", self._c.opt_mode)
        object.__setattr__(self.configuration.solve, "_enum_mode", self._c.enum_mode)
        self._adapters = []

    def _messages(self):
        """Hands the warnings of the last call to the logger (or standard error)."""
        for code, text in self._c.take_messages():
            if self._message_limit <= 0:
                continue
            self._message_limit -= 1
            if self._logger is not None:
                self._logger(MessageCode(code), text)
            else:
                print(text, file=_sys.stderr)

    def add(self, name, parameters=None, program=None):
        """``add(name, parameters, program)`` or clingo 5.8's ``add(program)`` (to ``base``)."""
        if parameters is None and program is None:
            name, parameters, program = "base", [], name
        try:
            self._c.add(name, list(parameters), program)
        finally:
            self._messages()

    def load(self, path):
        try:
            self._c.load(str(path))
        finally:
            self._messages()

    def get_const(self, name):
        """The value of the constant ``name`` (``#const`` or ``-c``) as a ``Symbol``, or ``None``
        (inside ``on_model`` too, as in clingo: from the constants read when the call began)."""
        if self._model is not None:
            return self._consts.get(str(name))
        return self._c.get_const(str(name))

    @property
    def is_conflicting(self):
        """clingo's ``is_conflicting``: no answer set whatever the externals and assumptions
        (an empty constraint was grounded, or a search met a top-level conflict)."""
        return self._c.is_conflicting()


    def ground(self, parts=(("base", ()),), context=None):
        """Grounds ``parts``; ``@f(...)`` calls ``context.f`` with ``Symbol`` arguments (it
        returns a ``Symbol`` or a list of them, as in clingo)."""
        try:
            self._c.ground([(n, list(a)) for n, a in parts], context)
        finally:
            self._messages()

    def solve(
        self,
        assumptions=(),
        on_model=None,
        on_unsat=None,
        on_statistics=None,
        on_finish=None,
        on_core=None,
        on_last=None,
        yield_=False,
        async_=False,
    ):
        self._theory_for_propagators()
        if yield_ or async_:
            native = self._c.solve_handle(
                list(assumptions), bool(yield_), bool(async_), on_unsat
            )
            # clingo 5.8 does not call on_core for a handle.
            stats = None if on_statistics is None else (lambda: self._user_statistics(on_statistics))
            return SolveHandle(native, bool(yield_), on_model, on_finish, None, on_last, stats)
        last = []
        callback = None
        if on_model is not None:
            # The native Control is busy while on_model runs: get_const reads these.
            self._consts = dict(self._c.consts())
        if on_model is not None or on_last is not None:
            def callback(m):
                if on_last is not None:
                    last[:] = [m]
                if on_model is None:
                    return None
                # The native Control is busy with the search while on_model runs: reads of
                # the symbolic atoms go to the model's context meanwhile (clingo allows them).
                self._model = m
                try:
                    return on_model(m)
                finally:
                    self._model = None
        sat, unsat, exhausted, interrupted, _, core = self._c.solve(
            list(assumptions), callback, False, on_unsat
        )
        result = SolveResult(sat, unsat, exhausted, interrupted)
        if on_core is not None and unsat and core is not None:
            on_core(core)
        if last:
            on_last(last[0])
        if on_statistics is not None:
            self._user_statistics(on_statistics)
        if on_finish is not None:
            on_finish(result)
        return result

    def assign_external(self, external, truth):
        """clingo 5.8's: ``True`` or ``False`` fixes the external, ``None`` frees it. Any other
        value counts by its truth, as in clingo 5.8: a ``TruthValue`` member is truthy, so
        ``TruthValue.False_`` and ``TruthValue.Free`` fix the atom true there (scripts that
        pass booleans and ``None`` get what they ask for under both)."""
        if truth is None:
            value = None
        else:
            value = bool(truth)
        self._c.assign_external(external, value)

    def release_external(self, external):
        self._c.release_external(external)

    def register_propagator(self, propagator):
        """clingo's ``register_propagator``: ``init``, ``propagate``, ``undo``, ``check`` as
        clingo calls them, over live views of the solver (``lucent.propagator``)."""
        adapter = _PropagatorAdapter(propagator)
        self._adapters.append(adapter)
        self._c.register_propagator(adapter)

    @property
    def theory_atoms(self):
        """The ground theory atoms of everything grounded so far (clingo's ``theory_atoms``)."""
        return [TheoryAtom(*a) for a in self._c.theory_atoms()]

    def _theory_for_propagators(self):
        """Hands the propagators the theory atoms their ``init`` will see."""
        if self._adapters:
            atoms = self.theory_atoms
            for adapter in self._adapters:
                adapter._theory = atoms

    @property
    def symbolic_atoms(self):
        if self._model is not None:
            return SymbolicAtoms(self._model.context)
        return SymbolicAtoms(self._c)

    def _user_statistics(self, on_statistics):
        """clingo's ``on_statistics(step, accu)``: the user's own figures, shown as
        ``statistics["user_step"]`` and ``statistics["user_accu"]``."""
        accu = {} if self._user is None else self._user[1]
        step = {}
        on_statistics(step, accu)
        self._user = (step, accu)

    @property
    def statistics(self):
        if self._model is not None:
            # As clingo: the figures exist once the call is over.
            raise RuntimeError("statistics not (yet) available")
        out = self._c.statistics()
        if self._user is not None:
            out["user_step"] = _floats(self._user[0])
            out["user_accu"] = _floats(self._user[1])
        return out

    def backend(self):
        return Backend(self._c)

    def cleanup(self):
        pass

    def interrupt(self):
        """Stops the running solve call (from any thread, as clingo's)."""
        self._interrupter.interrupt()


def _cli(args):
    code, out, err = _lucent.run_cli([str(a) for a in args])
    return code, out, err


def plan(
    problem,
    *,
    scene=None,
    goal=None,
    all=False,
    max_horizon=None,
    fixed=None,
    check=False,
    profile=None,
    consts=None,
):
    """The planner (``lucent plan``) on an AL_d problem file: a dict with ``plans`` (lists of
    actions as strings), ``length``, ``cr_applied``, ``minimal_plans`` ... as ``lucent plan
    --outf=2`` prints it; ``None`` when there is no plan within the horizon budget. Bad input
    raises ``RuntimeError`` with the diagnostics."""
    args = ["plan", problem, "--outf=2"]
    for flag, v in (("--scene", scene), ("--goal", goal), ("--max-horizon", max_horizon),
                    ("--fixed", fixed), ("--profile", profile)):
        if v is not None:
            args += [flag, v]
    if all:
        args.append("--all")
    if check:
        args.append("--check")
    for name, v in (consts or {}).items():
        args += ["-c", f"{name}={v}"]
    code, out, err = _cli(args)
    if code == 20:
        return None
    if code != 0:
        raise RuntimeError(err.strip())
    return _json.loads(out)


def explain(*files, question=None, happened=None, goal=None, why=None, why_not=None,
            max_horizon=None, profile=None, consts=None):
    """An explanation (``lucent explain``): a question about a history of AL_d scene files
    (``question``, with ``happened``/``goal``), or ``why``/``why_not`` an atom of a clingo
    program's first answer set. Returns the dict ``lucent explain --outf=2`` prints
    (``type``, ``answer``, ``literals``, ``tree``); bad input or a question not understood
    raises ``RuntimeError``."""
    args = ["explain", *files, "--outf=2"]
    for flag, v in (("-q", question), ("--happened", happened), ("--goal", goal),
                    ("--why", why), ("--why-not", why_not), ("--max-horizon", max_horizon),
                    ("--profile", profile)):
        if v is not None:
            args += [flag, v]
    for name, v in (consts or {}).items():
        args += ["-c", f"{name}={v}"]
    code, out, err = _cli(args)
    if code != 0 or not out.strip():
        raise RuntimeError((err or out).strip())
    return _json.loads(out.strip().splitlines()[-1])


# clingo's submodules (``from clingo.symbol import Function``, ``from clingo.application
# import Application, clingo_main``, ...) and the application interface at the top level, as
# clingo has them.
from . import application, backend, control, core, solving, symbol, theory_atoms  # noqa: E402,F401
from .application import Application, ApplicationOptions, Flag, clingo_main  # noqa: E402,F401
