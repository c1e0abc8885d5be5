"""clingo's ``clingo.propagator``: ``Assignment``, ``Trail``, ``PropagateInit``,
``PropagateControl``, ``PropagatorCheckMode`` and the ``Propagator`` base class, over the live
views of the native module (python/src/live.rs): each callback's objects read the solver as it
is now and act at once,
as clingo's do, and stop working (``RuntimeError``) when the callback returns.

Differences from clingo: ``add_literal`` needs one thread; ``add_clause``'s ``tag`` and
``lock`` are accepted and ignored (clauses added during search are learnt, as clingo's
default); the trail shows 0 for a helper thread's own variables.
"""

from collections.abc import Sequence as _Sequence


class PropagatorCheckMode:
    """clingo's ``PropagatorCheckMode``: when ``check`` runs (total assignments, every
    propagation fixpoint, both, never)."""

    Off = 0
    Total = 1
    Fixpoint = 2
    Both = 3


class PropagatorUndoMode:
    """clingo's ``PropagatorUndoMode``: when ``undo`` is called."""

    Default = 0
    Always = 1


class Propagator:
    """clingo's ``Propagator`` interface, as a base class: every method does nothing, so a
    subclass defines only those it needs (as with clingo, a propagator need not derive from
    it). ``decide`` is not called by Lucent's solver: the decision is always its own."""

    def init(self, init):
        """Called once before each solve call (watches, literal maps)."""

    def propagate(self, control, changes):
        """Called with the watched literals that became true."""

    def undo(self, thread_id, assignment, changes):
        """Called when the literals of ``changes`` are unassigned again."""

    def check(self, control):
        """Called on total assignments (or every fixpoint, by ``check_mode``)."""

    def decide(self, thread_id, assignment, fallback):
        """The literal to decide on (``fallback`` unchanged)."""
        return fallback


class _LiveSequence(_Sequence):
    """A sequence over a live view: indexing (negative indices and slices included) checks
    the bounds and asks ``_item`` for an index in range."""

    _what = "sequence"

    def __init__(self, live):
        self._l = live

    def _item(self, i):
        raise NotImplementedError

    def __getitem__(self, i):
        if isinstance(i, slice):
            return [self[j] for j in range(*i.indices(len(self)))]
        n = len(self)
        if i < 0:
            i += n
        if not 0 <= i < n:
            raise IndexError(f"{self._what} index out of range")
        return self._item(i)


class Trail(_LiveSequence):
    """clingo's ``Trail``: the assigned literals in assignment order; ``begin(level)`` and
    ``end(level)`` delimit a decision level's part."""

    _what = "trail"

    def __len__(self):
        return self._l.trail_len()

    def _item(self, i):
        return self._l.trail_at(i)

    def begin(self, level):
        return self._l.trail_begin(level)

    def end(self, level):
        return self._l.trail_begin(level + 1)


class Assignment(_LiveSequence):
    """clingo's ``Assignment``: the solver's values now; as a sequence, the positive literal
    of each variable (``assignment[i]`` is ``i + 1``, ``len`` the number of variables)."""

    _what = "assignment"

    def __len__(self):
        return self._l.size()

    def _item(self, i):
        return i + 1

    def value(self, literal):
        return self._l.value(literal)

    def is_true(self, literal):
        return self._l.value(literal) is True

    def is_false(self, literal):
        return self._l.value(literal) is False

    def is_free(self, literal):
        return self._l.value(literal) is None

    def is_fixed(self, literal):
        return self._l.is_fixed(literal)

    def level(self, literal):
        return self._l.level(literal)

    def has_literal(self, literal):
        return self._l.has_literal(literal)

    def decision(self, level):
        """The decision literal of ``level`` (0 to ``decision_level``); at level 0 the
        always-true literal 1, as clingo answers (Lucent's literal 1 is the translation's true
        literal: true and fixed at level 0)."""
        if level == 0:
            return 1
        d = self._l.decision(level)
        if d is None:
            raise RuntimeError(f"lucent: no decision at level {level}")
        return d

    @property
    def decision_level(self):
        return self._l.decision_level()

    @property
    def root_level(self):
        return self._l.root_level()

    @property
    def is_total(self):
        return self._l.is_total()

    @property
    def has_conflict(self):
        return self._l.has_conflict()

    @property
    def size(self):
        return self._l.size()

    @property
    def trail(self):
        return Trail(self._l)


class PropagateInit:
    """clingo's ``PropagateInit``: symbolic and theory atoms, solver literals, watches,
    clauses and literals that act at once, the level-0 assignment, the check mode."""

    def __init__(self, atoms, threads, live, theory_atoms, symbolic):
        self._lit = {a: lit for (_, a, _, _, lit) in atoms}
        self._l = live
        self.theory_atoms = list(theory_atoms)
        self.symbolic_atoms = symbolic
        self.number_of_threads = threads
        self.assignment = Assignment(live)
        self.check_mode = PropagatorCheckMode.Total
        # clingo's undo_mode (Default or Always): Lucent calls undo for every watched
        # literal that was reported, as clingo's default; kept for scripts that set it.
        self.undo_mode = PropagatorUndoMode.Default
        # condition_id -> condition, for the theory elements' ids that are no atoms.
        self._conditions = None

    def solver_literal(self, literal):
        if literal < 0:
            return -self.solver_literal(-literal)
        if literal in self._lit:
            return self._lit[literal]
        if self._conditions is None:
            self._conditions = {
                e.condition_id: e.condition
                for a in self.theory_atoms
                for e in a.elements
                if len(e.condition) > 1 or not e.condition
            }
        if literal in self._conditions:
            return self._l.condition_literal(self._conditions[literal])
        raise RuntimeError(f"lucent: {literal} is not a program literal")

    def add_watch(self, literal, thread_id=None):
        self._l.add_watch(literal)

    def add_clause(self, clause):
        return self._l.add_clause(list(clause))

    def add_nogood(self, nogood):
        return self._l.add_clause([-lit for lit in nogood])

    def add_literal(self, freeze=True):
        return self._l.add_literal()

    def remove_watch(self, literal, thread_id=None):
        self._l.remove_watch(literal)

    def freeze_literal(self, literal):
        """Nothing to do: Lucent's solver eliminates no variable a propagator may name."""

    def propagate(self):
        """Propagates the clauses added so far; ``False`` on a conflict."""
        return self._l.propagate()

    def add_weight_constraint(self, literal, literals, bound, type_=0, compare_equal=False):
        """``literal`` tied to ``sum(w * l) >= bound`` (``type_``: -1 the constraint implies
        it, 0 equivalent, 1 it implies the constraint); with ``compare_equal`` as clingo (the
        same tie of ``-literal`` to ``bound + 1`` too). ``False`` on a conflict."""
        return self._l.add_weight_constraint(
            literal, [tuple(x) for x in literals], bound, int(type_), bool(compare_equal)
        )


class PropagateControl:
    """clingo's ``PropagateControl``: the thread, the assignment, clauses, propagation,
    watches and new literals, all at once."""

    def __init__(self, thread_id, live):
        self.thread_id = thread_id
        self._l = live
        self.assignment = Assignment(live)

    def add_clause(self, clause, tag=False, lock=False):
        return self._l.add_clause(list(clause))

    def add_nogood(self, nogood, tag=False, lock=False):
        return self._l.add_clause([-lit for lit in nogood])

    def propagate(self):
        return self._l.propagate()

    def add_literal(self):
        return self._l.add_literal()

    def add_watch(self, literal):
        self._l.add_watch(literal)

    def remove_watch(self, literal):
        self._l.remove_watch(literal)

    def has_watch(self, literal):
        return self._l.has_watch(literal)
