"""clingo's ``clingo.backend``: ``Backend`` and ``HeuristicType`` (``lucent``'s own classes)."""

from . import Backend, HeuristicType  # noqa: F401
