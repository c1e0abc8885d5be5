"""clingo's ``clingo.symbol``: symbols and their constructors (the same objects as ``lucent``'s)."""

from . import Function, Infimum, Number, String, Supremum, Symbol, SymbolType, Tuple_, parse_term  # noqa: F401
