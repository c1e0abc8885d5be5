"""clingo's ``clingo.control``: the ``Control`` class (the same as ``lucent.Control``)."""

from . import Control  # noqa: F401
