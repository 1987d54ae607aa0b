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

from . import formats, show
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


#: Session key prefix of what a registry box was filled with: (unit system, text, SI value).
_FILLED = "_box_filled_"


def spec_box(container: Any, owner: type, name: str, value: float, key: str) -> str:
    """:func:`number_box` for field ``name`` of input dataclass ``owner``: label, unit, display
    scale, valid range and help from the field registry (aerostat_core.base.fields), in the
    session's unit system (:func:`app_ui.show.chosen_system`: 30 kt, 1000 ft); ``value`` in SI
    units. Read it with :func:`spec_read` (same ``key``): the generic helper of every
    registry-built box outside the Design form.

    After a switch of the unit system the box shows its value in the new unit: an untouched box
    its exact SI value, an edited one its typed number converted."""
    s = field_spec(owner, name)
    system = show.chosen_system()
    ss = st.session_state
    filled = ss.get(_FILLED + key)
    if key not in ss:
        ss[key] = formats.box_text(value, s, system)
        ss[_FILLED + key] = (system, ss[key], value)
    elif filled is not None and filled[0] != system:
        text = ss[key]
        if filled[1] == text:
            si = filled[2]
        else:
            try:
                si = spec_read(text, owner, name, key)
            except ValueError:
                si = None
        if si is not None:
            ss[key] = formats.box_text(si, s, system)
            ss[_FILLED + key] = (system, ss[key], si)
    elif filled is None:
        ss[_FILLED + key] = (system, ss[key], None)
    rng = s.range_text(system) if s.checked and not s.hi_field else ""
    help_text = f"{s.help} Valid {rng}.".strip() if rng else s.help
    return number_box(
        formats.box_label(s.label, s, system),
        key=key,
        value=None,
        container=container,
        help=help_text or None,
    )


def spec_read(text: Any, owner: type, name: str, key: str | None = None) -> float:
    """The SI value typed in a :func:`spec_box` (in the unit system it shows: its ``key`` tells;
    without it, the session's), checked against the registry's range (an open bound is left to
    the engine's check, which names it); ValueError names the box's label. An untouched box
    gives back the exact SI value it was filled with."""
    s = field_spec(owner, name)
    filled = st.session_state.get(_FILLED + key) if key is not None else None
    system = filled[0] if filled else show.chosen_system()
    if filled and filled[2] is not None and str(text) == filled[1]:
        return float(filled[2])
    lo, hi, _step = formats.box_bounds(s, system)
    label = formats.box_label(s.label, s, system)
    x = read(text, label, lo=lo, hi=hi, unit=formats.box_unit(s, system))
    return formats.box_to_si(float(x), s, system)
