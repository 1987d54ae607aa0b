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

from aerostat_core.base.fields import FieldSpec, field_spec

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
    """:func:`field_box` for field ``name`` of input dataclass ``owner``, labelled with the
    registry's label; ``value`` in SI units. Read it with :func:`spec_read` (same ``key``)."""
    s = field_spec(owner, name)
    return field_box(container, s, s.label, value, key)


def spec_read(text: Any, owner: type, name: str, key: str | None = None) -> float:
    """:func:`field_read` of a :func:`spec_box`, checked against the registry's range."""
    s = field_spec(owner, name)
    return field_read(text, s, s.label, key)


def field_box(
    container: Any,
    spec: FieldSpec,
    label: str,
    value: Any,
    key: str,
    *,
    help: str | None = None,  # noqa: A002 - Streamlit's name
    with_range: bool = True,
) -> str:
    """:func:`number_box` for a registry field ``spec`` (the generic helper of every
    registry-built box outside the Design form: Mission, site wind, Optimise, Dynamics):
    ``label`` (without unit) gets the field's unit in the session's unit system
    (:func:`app_ui.show.chosen_system`: 30 kt, 1000 ft), the box shows ``value`` (SI) in that
    unit, the help adds the valid range in it (``with_range``). Read it with :func:`field_read`
    (same ``key``).

    After a switch of the unit system the box shows its value in the new unit: an untouched box
    its exact SI value, an edited one its typed number converted."""
    s = spec
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
                si = field_read(text, s, label, key, check_range=False)
            except ValueError:
                si = None
        if si is not None:
            ss[key] = formats.box_text(si, s, system)
            ss[_FILLED + key] = (system, ss[key], si)
    elif filled is None:
        ss[_FILLED + key] = (system, ss[key], None)
    help_text = s.help if help is None else help
    rng = s.range_text(system) if with_range and s.checked and not s.hi_field else ""
    help_text = f"{help_text} Valid {rng}.".strip() if rng else help_text
    return number_box(
        formats.box_label(label, s, system),
        key=key,
        value=None,
        container=container,
        integer=s.integer,
        help=help_text or None,
    )


def field_read(
    text: Any, spec: FieldSpec, label: str, key: str | None = None, *, check_range: bool = True
) -> Any:
    """The SI value typed in a :func:`field_box` (in the unit system it shows: its ``key``
    tells; without it, the session's), an ``int`` for an integer field; ``check_range``: checked
    against the registry's range (an open bound is left to the engine's check, which names it).
    ValueError names the box's label. An untouched box gives back the exact SI value it was
    filled with."""
    s = spec
    filled = st.session_state.get(_FILLED + key) if key is not None else None
    system = filled[0] if filled else show.chosen_system()
    if filled and filled[2] is not None and str(text) == filled[1]:
        return int(filled[2]) if s.integer else float(filled[2])
    lo, hi, _step = formats.box_bounds(s, system) if check_range else (None, None, None)
    shown_label = formats.box_label(label, s, system)
    x = read(text, shown_label, integer=s.integer, lo=lo, hi=hi, unit=formats.box_unit(s, system))
    if s.integer:
        return int(x)
    return formats.box_to_si(float(x), s, system)
