"""Input checks shared by the dynamics dataclasses: one message format naming the field, the
value and the valid range (``Owner.field = value is outside the valid range [lo, hi] unit``)."""

from __future__ import annotations

import math


def check_number(
    owner: str, name: str, value, lo: float, hi: float, unit: str = "", lo_open: bool = False
) -> float:
    """``float(value)`` if finite and in [lo, hi] ((lo, hi] with ``lo_open``), else ValueError."""
    left = "(" if lo_open else "["
    rng = f"{left}{lo:g}, {hi:g}] {unit}".rstrip()
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{owner}.{name} = {value!r} is not a number; valid range {rng}") from None
    if not math.isfinite(v) or v > hi or (v <= lo if lo_open else v < lo):
        raise ValueError(f"{owner}.{name} = {value!r} is outside the valid range {rng}")
    return v
