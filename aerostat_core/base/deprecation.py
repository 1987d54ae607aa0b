"""Deprecated aliases of renamed public names (docs/architecture.md §7).

A module that renames a public name keeps the old one for one release::

    DEPRECATED_NAMES = {"OldName": "NewName"}
    __getattr__ = deprecated_aliases(__name__, globals(), DEPRECATED_NAMES)

Python calls a module-level ``__getattr__`` only for names the module does not define, so the
current names cost nothing; an old name returns the very same object as the new one and emits a
``DeprecationWarning`` that points at the caller's line.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Mapping
from typing import Any


def deprecated_aliases(
    module: str, namespace: Mapping[str, Any], renamed: Mapping[str, str]
) -> Callable[[str], Any]:
    """Module-level ``__getattr__`` that resolves the old names in ``renamed``.

    Parameters
    ----------
    module : str
        The module's ``__name__`` (for the messages).
    namespace : mapping
        The module's ``globals()``, read when an old name is looked up (so names defined after
        the call resolve too).
    renamed : mapping
        {old name: new name}.

    Returns
    -------
    callable
        ``__getattr__(name)``: the object of ``renamed[name]`` with a ``DeprecationWarning``;
        AttributeError, as usual, for any other name.
    """

    def __getattr__(name: str) -> Any:
        """Resolve a deprecated name to its current object (see :func:`deprecated_aliases`)."""
        new = renamed.get(name)
        if new is None:
            raise AttributeError(f"module {module!r} has no attribute {name!r}")
        warnings.warn(
            f"{module}.{name} is deprecated; use {new} (US spelling, as scipy.optimize)",
            DeprecationWarning,
            stacklevel=2,
        )
        return namespace[new]

    return __getattr__



def deprecated_method(old: str, new: str) -> Callable[..., Any]:
    """A method kept under its ``old`` name for one release: calls ``self.<new>`` and emits a
    ``DeprecationWarning`` (e.g. ``realise = deprecated_method("realise", "realize")`` in a
    class body)."""

    def method(self: Any, *args: Any, **kwargs: Any) -> Any:
        warnings.warn(
            f"{type(self).__name__}.{old} is deprecated; use {new} (US spelling)",
            DeprecationWarning,
            stacklevel=2,
        )
        return getattr(self, new)(*args, **kwargs)

    method.__name__ = method.__qualname__ = old
    method.__doc__ = f"Deprecated alias of :meth:`{new}` (US spelling); kept for one release."
    return method
