"""Input checks of the dynamics arguments that are not dataclass fields (list items, function
arguments). The dynamics dataclasses declare their fields in the field registry
(:mod:`aerostat_core.base.fields`) and validate from it; both raise the same structured
:class:`aerostat_core.base.validation.InputError` (``Owner.field = value is outside the valid range
[lo, hi] unit``)."""

from __future__ import annotations

from aerostat_core.base.validation import check_number as _check_number


def check_number(
    owner: str, name: str, value, lo: float, hi: float, unit: str = "", lo_open: bool = False
) -> float:
    """``float(value)`` if a finite number in [lo, hi] ((lo, hi] with ``lo_open``), else
    :class:`~aerostat_core.base.validation.InputError` (a ``ValueError``)."""
    return _check_number(owner, name, value, lo, hi, unit, lo_open=lo_open)
