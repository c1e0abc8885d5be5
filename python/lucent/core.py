"""clingo's ``clingo.core``: ``TruthValue`` (the same as ``lucent.TruthValue``)."""

from . import TruthValue  # noqa: F401
