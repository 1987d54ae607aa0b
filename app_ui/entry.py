"""Number boxes outside the Design form, read exactly like the form's boxes.

Streamlit's number box is a browser number input: Chromium read "12,5" as 125 and showed an
emptied box as 0. These boxes are text boxes read by :func:`app_ui.widgets.parse_number` (the
Design form's parser): a decimal comma is a decimal point, text with both a comma and a point
is refused as ambiguous, an empty box says it is required. :func:`read` also checks the valid
range and names the box's label in every message.
"""

from __future__ import annotations

from types import SimpleNamespace
from typing import Any

import streamlit as st

from aerostat_core.base.fields import field_spec

from .widgets import format_value, parse_number

#: The error group of these boxes (they are not part of the Design form's groups).
GROUP = "study"


def number_box(
    label: str,
    *,
    key: str,
    value: float | int | None,
    container: Any = None,
    integer: bool = False,
    help: str | None = None,  # noqa: A002 - Streamlit's name
    optional: bool = False,
) -> str:
    """A text box for a number, holding ``value`` until the user types; returns the text.

    Parse the text with :func:`read` (after a form's submit, so a half-typed value is never
    used). The box keeps its text across pages (``persist_state``).
    """
    if key not in st.session_state:
        st.session_state[key] = format_value(value, integer)
    box = st if container is None else container
    return box.text_input(
        label,
        key=key,
        help=help,
        placeholder="optional" if optional else "required",
        persist_state="session",
    )


def read(
    text: Any,
    label: str,
    *,
    integer: bool = False,
    lo: float | None = None,
    hi: float | None = None,
    unit: str = "",
    optional: bool = False,
) -> Any:
    """The number typed in a box labelled ``label`` (``None`` for an empty optional box).

    Raises :class:`app_ui.widgets.InputError` (a ``ValueError``) naming the label, the text
    and, when ``lo``/``hi`` are given, the valid range in the box's unit.

    >>> read("12,5", "Blow-by limit [m]")
    12.5
    """
    box = SimpleNamespace(key=None, label=label, group=GROUP, optional=optional, integer=integer)
    value = parse_number(text, box)
    if value is None:
        return None
    u = f" {unit}" if unit and unit != "-" else ""
    if (lo is not None and value < lo) or (hi is not None and value > hi):
        lo_t = "-∞" if lo is None else format_value(lo)
        hi_t = "∞" if hi is None else format_value(hi)
        raise ValueError(
            f"{label}: {format_value(value, integer)}{u} is outside the valid range "
            f"[{lo_t}, {hi_t}]{u}"
        )
    return value


def _spec_label(owner: type, name: str) -> tuple[Any, str]:
    s = field_spec(owner, name)
    return s, f"{s.label} [{s.shown_unit}]" if s.shown_unit else s.label


def spec_box(container: Any, owner: type, name: str, value: float, key: str) -> str:
    """:func:`number_box` for field ``name`` of input dataclass ``owner``: label, unit, display
    scale and help from the field registry (aerostat_core.base.fields); ``value`` in SI units."""
    s, label = _spec_label(owner, name)
    return number_box(
        label, key=key, value=value * s.scale, container=container, help=s.help or None
    )


def spec_read(text: Any, owner: type, name: str) -> float:
    """The SI value typed in a :func:`spec_box`, checked against the registry's range (an open
    bound is left to the engine's check, which names it); ValueError names the box's label."""
    s, label = _spec_label(owner, name)
    lo = None if s.lo is None or s.lo_open else s.lo * s.scale
    hi = None if s.hi is None or s.hi_open else s.hi * s.scale
    return float(read(text, label, lo=lo, hi=hi, unit=s.shown_unit)) / s.scale
