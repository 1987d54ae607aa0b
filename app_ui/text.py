"""Plain text for the UI: numbers as box text, signed deltas, wind lists, Markdown escaping and
the constraint table's display rows. No Streamlit import."""

from __future__ import annotations

import re
from typing import Any

from aerostat_core.base.validation import short

__all__ = [
    "clean",
    "constraint_table_rows",
    "format_value",
    "plain",
    "short",
    "signed",
    "speed_ranges",
]


def clean(x: float) -> float:
    """Round to 12 significant digits so that 0.68 -> 68 % -> 0.68 round-trips exactly."""
    return float(f"{x:.12g}")


def format_value(x: Any, integer: bool = False) -> str:
    """A number as the text of its box: integers without a decimal point, floats with up to 12
    significant digits and no trailing zeros; ``None`` as an empty box.

    >>> format_value(68.0), format_value(0.432), format_value(50, integer=True), format_value(None)
    ('68', '0.432', '50', '')
    """
    if x is None:
        return ""
    if integer:
        return str(int(x))
    text = f"{clean(float(x)):.12g}"
    return "0" if text == "-0" else text


_MD_SPECIAL = re.compile(r"([!-/:-@\[-`{-~])")


def plain(text: Any) -> str:
    """User text (case and file names, messages quoting them) for Streamlit's Markdown
    elements, shown exactly as typed: every ASCII punctuation character is backslash-escaped
    (CommonMark), so ``![i](http://...)`` is text, not an image the browser would fetch, and
    ``:red[x]`` or ``$x$`` are not directives.
    """
    return _MD_SPECIAL.sub(r"\\\1", str(text))


def signed(x: float, digits: int = 1) -> str:
    """``x`` with its sign, rounded, never "-0.0" (a delta that rounds to zero is "0.0").

    >>> signed(-0.04), signed(2.345, 2), signed(-3.0), signed(0.0)
    ('0.0', '+2.35', '-3.0', '0.0')
    """
    r = round(float(x), digits)
    if r == 0:
        return f"{0:.{digits}f}"
    return f"{r:+.{digits}f}"


def speed_ranges(speeds: Any, step: float | None = None) -> str:
    """Wind speeds as ranges: consecutive sweep points (``step`` apart, or the smallest gap)
    collapse into "a–b".

    >>> speed_ranges([0, 1, 2, 3, 7, 8, 9, 12])
    '0–3, 7–9, 12'
    >>> speed_ranges([0.5, 1.0, 1.5, 4.0], 0.5)
    '0.5–1.5, 4'
    """
    v = sorted({float(s) for s in speeds})
    if not v:
        return ""
    if step is None:
        gaps = [b - a for a, b in zip(v, v[1:])]
        step = min(gaps) if gaps else 1.0
    parts, start, prev = [], v[0], v[0]
    for s in v[1:]:
        if s - prev > 1.5 * step:
            parts.append(f"{start:g}" if start == prev else f"{start:g}–{prev:g}")
            start = s
        prev = s
    parts.append(f"{start:g}" if start == prev else f"{start:g}–{prev:g}")
    return ", ".join(parts)


def constraint_table_rows(rows: list[dict]) -> list[dict]:
    """Display rows of the constraint table (aerostat_core.model.constraints via the design report):
    label, where checked, value, limit and margin with the unit (4 significant digits; an
    unbounded margin shows as a dash), and met."""

    def fmt(x: float) -> str:
        if x != x or abs(x) == float("inf"):
            return "–"
        text = f"{x:.4g}"
        return "0" if text == "-0" else text

    return [
        {
            "Constraint": r["label"],
            "Checked at": r["checked_at"],
            "Value": fmt(r["value"]),
            "Limit": fmt(r["limit"]),
            "Margin": fmt(r["margin"]),
            "Unit": r["unit"],
            "Met": "yes" if r["met"] else "NO",
        }
        for r in rows
    ]
