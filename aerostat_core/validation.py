"""Input checks shared by every dataclass: one message format naming field, value and range."""

from __future__ import annotations

import math
from numbers import Real


def check_number(
    owner: str,
    field: str,
    value: object,
    lo: float,
    hi: float,
    unit: str = "",
    *,
    lo_open: bool = False,
    hi_open: bool = False,
) -> float:
    """Return ``value`` as float or raise ``ValueError`` naming the field, value and valid range.

    Parameters
    ----------
    owner, field : str
        Names used in the message, e.g. ``"Requirement"``, ``"payload_mass"``.
    value : object
        The value to check; must be a real, finite number (``bool`` is rejected).
    lo, hi : float
        Bounds of the valid range.
    unit : str
        Unit shown in the message, e.g. ``"kg"``.
    lo_open, hi_open : bool
        Whether the bounds are excluded.

    Examples
    --------
    >>> check_number("Requirement", "payload_mass", 10, 0, 500, "kg", lo_open=True)
    10.0
    >>> check_number("Requirement", "payload_mass", -1, 0, 500, "kg", lo_open=True)
    Traceback (most recent call last):
    ...
    ValueError: Requirement.payload_mass = -1 kg is outside the valid range (0, 500] kg
    """
    u = f" {unit}" if unit else ""
    rng = f"{'(' if lo_open else '['}{lo:g}, {hi:g}{')' if hi_open else ']'}{u}"
    if isinstance(value, bool) or not isinstance(value, Real):
        raise ValueError(f"{owner}.{field} = {value!r} is not a number; valid range {rng}")
    try:
        v = float(value)
    except OverflowError:  # an integer too large for a float
        v = math.inf
    if not math.isfinite(v):
        shown = repr(value) if len(repr(value)) <= 30 else repr(value)[:27] + "..."
        raise ValueError(f"{owner}.{field} = {shown} is not finite; valid range {rng}")
    below = v <= lo if lo_open else v < lo
    above = v >= hi if hi_open else v > hi
    if below or above:
        raise ValueError(f"{owner}.{field} = {value:g}{u} is outside the valid range {rng}")
    return v


def check_choice(owner: str, field: str, value: object, choices: tuple[str, ...]) -> str:
    """Return ``value`` if it is one of ``choices``, else raise ``ValueError`` listing them.

    >>> check_choice("LiftingGas", "kind", "argon", ("helium", "hydrogen"))
    Traceback (most recent call last):
    ...
    ValueError: LiftingGas.kind = 'argon' is not one of: helium, hydrogen
    """
    if not isinstance(value, str) or value not in choices:
        raise ValueError(f"{owner}.{field} = {value!r} is not one of: {', '.join(choices)}")
    return value


def check_int(owner: str, field: str, value: object, lo: int, hi: int) -> int:
    """Return ``value`` as int if it is a whole number in [lo, hi], else raise ``ValueError``."""
    try:
        bad = (isinstance(value, bool) or not isinstance(value, Real)
               or not math.isfinite(float(value)) or float(value) != int(value))
    except OverflowError:
        bad = True
    if bad:
        raise ValueError(f"{owner}.{field} = {value!r} is not a whole number in [{lo}, {hi}]")
    v = int(value)
    if not lo <= v <= hi:
        raise ValueError(f"{owner}.{field} = {v} is outside the valid range [{lo}, {hi}]")
    return v


#: Longest name accepted for catalogue items and cases [characters].
MAX_NAME_LENGTH = 100


def check_name(owner: str, field: str, value: object) -> str:
    """Return ``value`` as a stripped string of 1-100 characters, else raise ``ValueError``.

    >>> check_name("Fabric", "name", "x" * 101)
    Traceback (most recent call last):
    ...
    ValueError: Fabric.name is 101 characters long; the limit is 100
    """
    text = str(value).strip()
    if not text:
        raise ValueError(f"{owner}.{field} must not be empty")
    if any(ord(ch) < 32 for ch in text):
        raise ValueError(f"{owner}.{field} contains control characters")
    if len(text) > MAX_NAME_LENGTH:
        raise ValueError(f"{owner}.{field} is {len(text)} characters long; the limit is "
                         f"{MAX_NAME_LENGTH}")
    return text
