"""clingo's ``clingo.theory_atoms``: ``TheoryAtom``, ``TheoryElement``, ``TheoryTerm`` and
``TheoryTermType`` (the same as ``lucent``'s)."""

from . import TheoryAtom, TheoryElement, TheoryTerm, TheoryTermType  # noqa: F401
