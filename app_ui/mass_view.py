"""The Mass tab's bar chart of the mass breakdown as a static SVG drawing.

Why not plotly: drawing one plotly chart was most of a switch to the Mass tab in a browser
without a GPU (benchmarks/bench_app.py, tab switch: about 0.3 s of front-end render after the
last message, more on a busy machine), and its interaction added nothing there: each bar carries
its mass and share as text, and the table above the chart lists them all. What the drawing
does not do is zoom, hover labels and the PNG download of plotly's tool bar (the browser's own
"save image" works). Pure: data in, SVG text out (no Streamlit).

Shown with ``st.image`` (an ``<img>`` of a data URL). Every bar carries its item and mass
(``data-item``, ``data-mass-kg`` in kilograms), so a test reads back what is drawn.
"""

from __future__ import annotations

from html import escape

from aerostat_core.output.report import DesignReport

from . import formats
from .theme import ACCENT, FONT, NEUTRAL, TITLE_SIZE

_W = 720.0  # drawing width [px of the viewBox]
_LABEL_W = 130.0  # item names, right-aligned before the bars
_TEXT_W = 170.0  # room right of the longest bar for its value text
_ROW = 28.0
_TOP = 44.0


def mass_svg(rep: DesignReport) -> str:
    """Horizontal bars of the mass breakdown (the table's order, the total in the title), each
    with its mass in the chosen unit system and its share of the total. Returns the SVG
    markup."""
    rows = [r for r in rep.mass_rows if r["item"] != "total"]
    total = next(float(r["mass_kg"]) for r in rep.mass_rows if r["item"] == "total")
    largest = max((float(r["mass_kg"]) for r in rows), default=0.0) or 1.0
    span = _W - _LABEL_W - _TEXT_W - 12.0
    height = _TOP + _ROW * len(rows) + 12.0
    title = escape(f"Mass breakdown (total {formats.shown(total, 'mass', with_unit=True)})")
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {_W:.0f} {height:.0f}" '
        f'width="100%" role="img" data-testid="mass-bars" font-family="{FONT["family"]}" '
        f'font-size="{FONT["size"]}">',
        f'<text x="4" y="22" font-size="{TITLE_SIZE}">{title}</text>',
        f'<line x1="{_LABEL_W + 6:.1f}" y1="{_TOP - 6:.1f}" x2="{_LABEL_W + 6:.1f}" '
        f'y2="{height - 8:.1f}" stroke="{NEUTRAL}"/>',
    ]
    for k, r in enumerate(rows):
        m, share = float(r["mass_kg"]), float(r["share_pct"])
        y = _TOP + k * _ROW
        w = max(span * m / largest, 0.0)
        value = (
            f"{formats.shown(m, 'mass', with_unit=True)} ({formats.text(share, 'share')} %)"
        )
        item = escape(str(r["item"]))
        out.append(
            f'<g data-item="{item}" data-mass-kg="{m:.9g}"><title>{item}: {escape(value)}'
            f'</title><text x="{_LABEL_W:.1f}" y="{y + 15:.1f}" text-anchor="end">{item}</text>'
            f'<rect x="{_LABEL_W + 6:.1f}" y="{y + 3:.1f}" width="{w:.1f}" height="{_ROW - 8:.1f}" '
            f'fill="{ACCENT}"/><text x="{_LABEL_W + 12 + w:.1f}" y="{y + 15:.1f}">'
            f"{escape(value)}</text></g>"
        )
    out.append("</svg>")
    return "".join(out)
