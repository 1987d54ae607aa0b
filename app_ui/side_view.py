"""The side view of the Design page's first tab as a static SVG drawing, to scale.

Why not plotly: the first tab is what a fresh browser shows first, and the 4.7 MB plotly.js
bundle that a chart pulls in held the first result back by about 3 s on 2 busy cores
(benchmarks/bench_app.py, first result in a fresh browser). The drawing needs no interaction;
the interactive plotly side view is in a section below it, drawn once opened. Pure: data in, SVG text out (no Streamlit).

Shown with ``st.image`` (an ``<img>`` of a data URL: ``st.html`` strips SVG). Every marked point
carries its coordinates (``data-xi``, ``data-z`` in metres), so a test reads back what is drawn.
"""

from __future__ import annotations

import math
from html import escape

import numpy as np

from aerostat_core.output.report import DesignReport, hull_outline

from . import formats
from .perf_view import nice_step
from .theme import ACCENT, FONT, LIMIT_COLOUR, NEUTRAL, THIRD

#: Marked points: field of rep.points, label, short name, colour.
POINTS = (
    ("cb", "centre of buoyancy (CB)", "CB", THIRD),
    ("cg", "centre of gravity (CG)", "CG", "#000000"),
    ("c", "confluence point (C)", "C", LIMIT_COLOUR),
)
_W = 720.0  # drawing width [px of the viewBox]
_PAD = 36.0


def side_view_svg(rep: DesignReport) -> str:
    """Side view to scale (nose left, z up): hull outline, fins, confluence lines, CB, CG and
    the confluence point, a station axis in the chosen unit (m or ft). Returns the SVG markup."""
    h = rep.hull
    xi, r = (np.asarray(a, float) for a in hull_outline(h.a1, h.a2, h.b, shape=rep.shape))
    hull_x = np.concatenate([xi, xi[::-1]])
    hull_z = np.concatenate([r, -r[::-1]])
    fins = [np.asarray(o, float) for o in rep.fins.outlines]
    fins = [p for p in fins if not np.allclose(p[:, 2], 0.0, atol=1e-9)]  # edge-on fins
    lines = [np.asarray(ln, float) for ln in rep.confluence_lines]
    pts = {k: tuple(float(v) for v in getattr(rep.points, k)) for k, *_ in POINTS}
    xs = np.concatenate([hull_x, *[p[:, 0] for p in fins], *[ln[:, 0] for ln in lines]])
    zs = np.concatenate([hull_z, *[p[:, 2] for p in fins], *[ln[:, 1] for ln in lines]])
    x0, x1 = float(xs.min()), float(xs.max())
    z0, z1 = float(zs.min()), float(zs.max())
    scale = (_W - 2 * _PAD) / max(x1 - x0, 1e-9)  # px per metre, the same on both axes
    height = (z1 - z0) * scale + 2 * _PAD + 24

    def px(x: float) -> float:
        return _PAD + (x - x0) * scale

    def pz(z: float) -> float:
        return _PAD + (z1 - z) * scale

    def path(x: np.ndarray, z: np.ndarray) -> str:
        return " ".join(f"{px(a):.1f},{pz(b):.1f}" for a, b in zip(x, z))

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {_W:.0f} {height:.0f}" '
        f'width="100%" role="img" data-testid="side-view" data-scale="{scale:.6g}" '
        f'font-family="{FONT["family"]}" font-size="{FONT["size"]}">',
        "<title>Side view (to scale, level hull)</title>",
        f'<polygon data-part="hull" points="{path(hull_x, hull_z)}" '
        f'fill="rgba(143,169,204,0.35)" stroke="{ACCENT}" stroke-width="2"/>',
    ]
    out += [
        f'<polygon data-part="fin" points="{path(p[:, 0], p[:, 2])}" '
        'fill="rgba(230,159,0,0.45)" stroke="#b07800"/>'
        for p in fins
    ]
    out += [
        f'<polyline data-part="confluence line" points="{path(ln[:, 0], ln[:, 1])}" '
        f'fill="none" stroke="#555555" stroke-width="1.5"/>'
        for ln in lines
    ]
    for key, label, short, colour in POINTS:
        x, z = pts[key]
        tip = f"{label}: ξ = {formats.shown(x, 'length', with_unit=True)}, " + (
            f"z = {formats.shown(z, 'length', with_unit=True)}"
        )
        out.append(
            f'<g data-point="{key}" data-xi="{x:.9g}" data-z="{z:.9g}"><title>{escape(tip)}'
            f'</title><circle cx="{px(x):.1f}" cy="{pz(z):.1f}" r="5" fill="{colour}"/>'
            f'<text x="{px(x) + 7:.1f}" y="{pz(z) - 7:.1f}" fill="{colour}">{short}</text></g>'
        )
    # station axis under the drawing: round ticks from the nose in the chosen unit (m or ft)
    du = formats.display("length")
    y_axis = height - 22
    step = nice_step((x1 - x0) * du.scale, 8)
    out.append(
        f'<line x1="{px(x0):.1f}" y1="{y_axis:.1f}" x2="{px(x1):.1f}" y2="{y_axis:.1f}" '
        f'stroke="{NEUTRAL}"/>'
    )
    t = math.ceil(du.show(x0) / step) * step
    while t <= du.show(x1) + 1e-9:
        at = px(du.to_si(t))
        out.append(
            f'<line x1="{at:.1f}" y1="{y_axis:.1f}" x2="{at:.1f}" y2="{y_axis + 5:.1f}" '
            f'stroke="{NEUTRAL}"/><text x="{at:.1f}" y="{y_axis + 17:.1f}" '
            f'text-anchor="middle" fill="{NEUTRAL}">{t:g}</text>'
        )
        t += step
    out.append(
        f'<text x="{px(x1):.1f}" y="{y_axis - 6:.1f}" text-anchor="end" fill="{NEUTRAL}">'
        f"station from the nose ξ [{du.unit}]</text>"
    )
    out.append("</svg>")
    return "".join(out)
