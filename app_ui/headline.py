"""Headline numbers as one block of escaped HTML (no Streamlit import): a page's key results,
each a label with its unit, a value, an optional delta and its help on hover.

Why not ``st.metric``: each metric is an element of its own, and a fresh browser's first result
waits for React to render the page's element tree several times while the messages arrive
(about 200 ms a render, more with more elements). The Design page's ten metrics and their two
row containers were 13 of its 52 elements; as one block the first result showed about 250 ms
sooner (interleaved browser probe, 2026-12-03, ``benchmarks/bench_app.py``). The block keeps
what a metric shows: the label and unit, the value at its decimals, the delta with its colour,
and the help (the item's ``title``, a native tooltip on hover, and shown under the number when
the item has the focus, for a keyboard or a touch screen).

The block wraps: at 1024 px a number moves to the next line whole, never cut to "1…". Its style
(sizes, wrapping, the help's dotted underline) is the page style sheet's,
:data:`app_ui.theme.PAGE_CSS`, sent once per page rather than with every block.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from html import escape
from typing import Literal

from aerostat_core.model.constraints import limit_met

from .theme import LIMIT_COLOUR, NEUTRAL, THIRD

Tone = Literal["good", "bad", "neutral"]
#: Colour of a delta by what it says about the design (the theme's, defined once there).
TONE_COLOUR: dict[str, str] = {"good": THIRD, "bad": LIMIT_COLOUR, "neutral": NEUTRAL}


@dataclass(frozen=True)
class Headline:
    """One headline number: ``label`` with its unit ("Volume [m³]"), ``value`` as shown (already
    formatted), ``help`` on hover, ``delta`` a short text under the value ("+3.1", "sized")
    coloured by ``tone``."""

    label: str
    value: str
    help: str = ""
    delta: str = ""
    tone: Tone = "neutral"


@dataclass(frozen=True)
class Note:
    """A caption on a line of its own inside the block ("At the design wind, 10.0 m/s:"); the
    numbers after it start a new line."""

    text: str


Item = Headline | Note


def limit_tone(value: float, limit: float, kind: Literal["max", "min"]) -> Tone:
    """The tone of a value beside its limit, by the constraint table's rule
    (:func:`aerostat_core.model.constraints.limit_met`), so a sized hull at its limit reads
    "good" exactly when the verdict calls it met; "neutral" when either number is not finite.

    >>> limit_tone(150.0, 150.0, "max"), limit_tone(150.1, 150.0, "max")
    ('good', 'bad')
    >>> limit_tone(2.9999999, 3.0, "min"), limit_tone(float("nan"), 3.0, "min")
    ('good', 'neutral')
    """
    if not (math.isfinite(value) and math.isfinite(limit)) or limit == 0:
        return "neutral"
    return "good" if limit_met(value, limit, kind) else "bad"


def _item_html(it: Item) -> str:
    if isinstance(it, Note):
        return f'<p class="hl-note" data-testid="headline-note">{escape(it.text)}</p>'
    # the help on hover (title) and, for a keyboard or a touch screen, on focus: the page style
    # sheet shows data-help under the block, so it names the number it explains
    note = f"{it.label}: {it.help}"
    title = (f' title="{escape(it.help)}" data-help="{escape(note)}" tabindex="0"'
             if it.help else "")
    delta = ""
    if it.delta:
        colour = TONE_COLOUR[it.tone]
        delta = (
            f'<div><span class="hl-delta" data-testid="headline-delta" data-tone="{it.tone}" '
            f'style="color:{colour};background:{colour}1a">{escape(it.delta)}</span></div>'
        )
    return (
        f'<div data-testid="headline"{title}>'
        f'<div class="hl-label" data-testid="headline-label">{escape(it.label)}</div>'
        f'<div class="hl-value" data-testid="headline-value">{escape(it.value)}</div>'
        f"{delta}</div>"
    )


def headline_html(items: Sequence[Item]) -> str:
    """The headline numbers (and their notes) as one wrapping block, every text HTML-escaped.

    >>> html = headline_html([Headline("Volume [m³]", "170.0", "Hull volume.", "sized")])
    >>> 'data-testid="headline-value">170.0<' in html and 'title="Hull volume."' in html
    True
    >>> "<b>" in headline_html([Headline("<b>", "1")])
    False
    """
    return '<div class="aerostat-hl">' + "".join(map(_item_html, items)) + "</div>"
