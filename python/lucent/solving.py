"""clingo's ``clingo.solving``: models, solve handles and results (``lucent``'s own classes)."""

from . import Model, ModelType, SolveHandle, SolveResult  # noqa: F401
