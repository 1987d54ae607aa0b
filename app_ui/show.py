"""Small Streamlit display helpers shared by the pages: messages as plain text and a wrapping
row of headline metrics."""

from __future__ import annotations

from typing import Any

import streamlit as st

from aerostat_core.fields import field_spec

from .text import plain


class _MetricSlot:
    """One place in a :func:`metric_row`: ``.metric(...)`` sized to its content."""

    def __init__(self, row: Any) -> None:
        self._row = row

    def metric(self, *args: Any, **kwargs: Any) -> Any:
        kwargs.setdefault("width", "content")
        return self._row.metric(*args, **kwargs)


def metric_row(n: int) -> list[_MetricSlot]:
    """``n`` places for headline numbers, used like ``st.columns(n)``: a wrapping horizontal
    row whose metrics take the width of their label and value, so a narrow window moves a
    metric to the next line instead of cutting it to "1…" (fixed columns did at 1024 px)."""
    row = st.container(horizontal=True, wrap=True, gap="large")
    return [_MetricSlot(row)] * n


def spec_number(col: Any, owner: type, name: str, value: float, key: str) -> float:
    """A number box for field ``name`` of input dataclass ``owner``: label, unit, range, step
    and help from the field registry (aerostat_core.fields). Returns the value in SI units; an
    open bound is left to the engine's check, which names the range."""
    s = field_spec(owner, name)
    shown = col.number_input(
        f"{s.label} [{s.shown_unit}]",
        min_value=None if s.lo_open else float(s.lo * s.scale),
        max_value=None if s.hi_open else float(s.hi * s.scale),
        value=float(value * s.scale),
        step=float(s.step or 1.0),
        key=key,
        help=s.help or None,
    )
    return float(shown) / s.scale


def feedback(level: str, text: str) -> None:
    """Show a message (level "success", "info", "warning" or anything else for an error) as
    plain text (see :func:`~app_ui.text.plain`)."""
    show = {"success": st.success, "info": st.info, "warning": st.warning}.get(level, st.error)
    show(plain(text))
