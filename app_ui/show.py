"""Small Streamlit display helpers shared by the pages: messages as plain text and a wrapping
row of headline metrics."""

from __future__ import annotations

from typing import Any

import streamlit as st

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
    row = st.container(horizontal=True, wrap=True, gap="medium")
    return [_MetricSlot(row)] * n


def feedback(level: str, text: str) -> None:
    """Show a message (level "success", "info", "warning" or anything else for an error) as
    plain text (see :func:`~app_ui.text.plain`)."""
    show = {"success": st.success, "info": st.info, "warning": st.warning}.get(level, st.error)
    show(plain(text))
