"""Deprecated module name, kept for one release: use :mod:`aerostat_core.dynamics.linearize`
(identifiers in US spelling, docs/architecture.md §7). Every name resolves to the same object
with a ``DeprecationWarning``."""

from aerostat_core.base.deprecation import deprecated_aliases

from . import linearize

#: Old names -> the names in :mod:`.linearize`.
DEPRECATED_NAMES = {"linearise": "linearize", "Linearisation": "Linearization", "Mode": "Mode"}

__getattr__ = deprecated_aliases(__name__, vars(linearize), DEPRECATED_NAMES)
