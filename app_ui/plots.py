"""Plot and table builders: pure functions from the typed report
(:class:`~aerostat_core.output.report.DesignReport` of :func:`aerostat_core.output.report.design_report`) to plotly figures and display-ready pandas frames (no
Streamlit; tested directly).

Conventions: drawn in SI units, every axis title with its unit in brackets, then shown in the
session's unit system by :func:`app_ui.formats.figure_dict_in_system` (the brackets say which
axes convert); operating-limit rows marked with red crosses (trace
name :data:`LIMIT_TRACE`); requirement limits drawn as dashed lines; tether and side views to
scale (equal axis aspect).

Speed: each figure is assembled as plain dicts and validated once by ``go.Figure(dict)``;
building it with ``add_trace``/``add_hline``/templates was 5-10x slower (plotly re-validates on
every incremental update), which mattered for the 300 ms rerun budget of the Design page.
"""

from __future__ import annotations

import html
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import plotly.graph_objects as go

from aerostat_core.output.report import (
    DesignReport,
    TetherProfiles,
    hull_outline,
    hull_surface,
    tether_profiles,
)

from . import formats
from .tables import (  # noqa: F401 - the Design and Compare pages' tables, re-exported
    DIFF_ROW_STYLE,
    LIMIT_ROW_STYLE,
    PERF_COLUMNS,
    comparison_frame,
    comparison_styler,
    format_value,
    geometry_frame,
    mass_frame,
    performance_frame,
    performance_styler,
)
from .theme import ACCENT, LIMIT_COLOUR, NEUTRAL, PALETTE, THIRD, base_layout

LIMIT_TRACE = "operating limit exceeded"

#: Performance quantities: field of rep.perf -> (title, axis label with unit).
PERF_QUANTITIES: dict[str, tuple[str, str]] = {
    "blow_by": ("Blow-by (downwind offset)", "Blow-by [m]"),
    "alpha_eq": ("Equilibrium angle of attack", "α_eq [deg]"),
    "dynamic_lift": ("Dynamic lift", "Dynamic lift [N]"),
    "tension_top": ("Tether tension at the top", "Tension [N]"),
    "tension_winch": ("Tether tension at the winch", "Tension [N]"),
    "safety_factor": ("Tether safety factor", "Safety factor [-]"),
    "drag": ("Aerodynamic drag", "Drag [N]"),
    "flying_height": ("Flying height", "Height [m]"),
}
WIND_AXIS = "Wind speed at the aerostat [m/s]"
#: Quantity of each performance curve (decimals of its hover text, :mod:`app_ui.formats`).
PERF_KINDS = {"tension_top": "tension", "tension_winch": "tension"}
_LEN = formats.d3("length")


def perf_hover(key: str, unit: str) -> str:
    """Hover text of a performance curve: wind and value at the decimals of their kinds."""
    d = formats.d3(PERF_KINDS.get(key, key))
    u = "" if unit == "-" else f" {unit}"
    return f"%{{x:{formats.d3('wind')}}} m/s: %{{y:{d}}}{u}<extra>%{{fullData.name}}</extra>"


def _l(a: Any) -> list:
    return np.asarray(a, dtype=float).tolist()


def _axis(title: str, **kw: Any) -> dict:
    return dict(title=dict(text=title), **kw)


def _ref_line(
    axis: str,
    value: float,
    text: str = "",
    colour: str = NEUTRAL,
    dash: str = "dash",
    yref: str = "y",
) -> tuple[dict, dict | None]:
    """A horizontal (``axis="y"``) or vertical (``axis="x"``) reference line across the plot."""
    line = dict(color=colour, dash=dash, width=1.5)
    if axis == "y":
        shape = dict(
            type="line", xref="paper", x0=0, x1=1, yref=yref, y0=value, y1=value, line=line
        )
        note = dict(
            xref="paper",
            x=0.01,
            xanchor="left",
            yref=yref,
            y=value,
            yanchor="bottom",
            text=text,
            showarrow=False,
            font=dict(color=colour, size=11),
        )
    else:
        shape = dict(type="line", yref="paper", y0=0, y1=1, xref="x", x0=value, x1=value, line=line)
        note = dict(
            yref="paper",
            y=1.0,
            yanchor="bottom",
            xref="x",
            x=value,
            xanchor="left",
            text=text,
            showarrow=False,
            font=dict(color=colour, size=11),
        )
    return shape, (note if text else None)


def _figure(
    traces: list[dict], title: str, *, lines: Sequence[dict] = (), **layout: Any
) -> go.Figure:
    """One validated figure from trace dicts, a title, reference lines and layout options.
    No plotly template: ``st.plotly_chart`` applies the app's Streamlit theme."""
    lay = base_layout(title)
    shapes, notes = [], []
    for ln in lines:
        shape, note = _ref_line(**ln)
        shapes.append(shape)
        if note:
            notes.append(note)
    if shapes:
        lay["shapes"] = shapes
        lay["annotations"] = notes
    lay.update(layout)
    # drawn in SI, shown in the session's unit system (ft, kt, lbf, lb in US customary)
    return go.Figure(formats.figure_dict_in_system({"data": traces, "layout": lay}))


def _limit_trace(x: Any, y: Any, limited: Any, text: Sequence[str], **kw: Any) -> list[dict]:
    """Red crosses on the rows that break an operating limit (hover says which); [] if none."""
    idx = np.flatnonzero(np.asarray(limited, bool))
    if idx.size == 0:
        return []
    trace = dict(
        type="scatter",
        x=np.asarray(x, float)[idx].tolist(),
        y=np.asarray(y, float)[idx].tolist(),
        mode="markers",
        name=LIMIT_TRACE,
        marker=dict(symbol="x", size=11, color=LIMIT_COLOUR, line=dict(width=1)),
        text=[text[i] for i in idx],
        hovertemplate=f"%{{x:{formats.d3('wind')}}} m/s: %{{text}}<extra></extra>",
    )
    trace.update(kw)
    return [trace]


# --- geometry ---------------------------------------------------------------------------------

_POINTS = (
    ("cb", "centre of buoyancy (CB)", "CB", "circle", THIRD),
    ("cg", "centre of gravity (CG)", "CG", "diamond", "#000000"),
    ("c", "confluence point (C)", "C", "triangle-down", LIMIT_COLOUR),
)


def _grid_triangles(n_rows: int, n_cols: int) -> tuple[list[int], list[int], list[int]]:
    """Two triangles per cell of an (n_rows, n_cols) vertex grid (row-major), as mesh3d i, j, k."""
    r, c = np.meshgrid(np.arange(n_rows - 1), np.arange(n_cols - 1), indexing="ij")
    p = (r * n_cols + c).ravel()
    q, d = p + 1, p + n_cols
    return (
        np.concatenate([p, q]).tolist(),
        np.concatenate([q, q + n_cols]).tolist(),
        np.concatenate([d, d]).tolist(),
    )


#: ``st.plotly_chart`` config of a WebGL (3-D) figure: plotly.js draws a 3-D scene at twice the
#: screen resolution by default, four times the pixels; in software WebGL (no GPU) that cost a
#: third of the 3-D view's time (benchmarks/bench_app.py, CPU time of chromium's GPU process).
GL_CONFIG = {"plotGlPixelRatio": 1}


def _octahedron(centre: Sequence[float], r: float) -> tuple[np.ndarray, list[tuple[int, int, int]]]:
    """Vertices (6, 3) and the 8 faces (local indices) of an octahedron of radius ``r``: a
    marked point drawn as part of the 3-D view's single mesh."""
    c = np.asarray(centre, float)
    v = c + r * np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]])
    faces = [(a, b, t) for a in (0, 1) for b in (2, 3) for t in (4, 5)]
    return v, faces


def _rod(p0: Sequence[float], p1: Sequence[float], r: float) -> tuple[np.ndarray, list]:
    """Vertices (6, 3) and the 6 side faces of a thin triangular prism from ``p0`` to ``p1``
    (radius ``r``): a line drawn as part of the 3-D view's single mesh."""
    a, b = np.asarray(p0, float), np.asarray(p1, float)
    d = b - a
    d = d / max(float(np.linalg.norm(d)), 1e-12)
    u = np.cross(d, [0.0, 1.0, 0.0] if abs(d[1]) < 0.9 else [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u)
    w = np.cross(d, u)
    ring = [r * (np.cos(t) * u + np.sin(t) * w) for t in (0.0, 2 * np.pi / 3, 4 * np.pi / 3)]
    v = np.array([a + q for q in ring] + [b + q for q in ring])
    faces = []
    for k in range(3):
        n = (k + 1) % 3
        faces += [(k, n, 3 + k), (n, 3 + n, 3 + k)]
    return v, faces


def hull_3d_figure(rep: DesignReport) -> go.Figure:
    """Interactive 3-D view: NPL hull (surface of revolution), fins, CB/CG/confluence point and
    the (schematic) confluence lines, to scale.

    One WebGL trace: the hull, the fins, the three points (small octahedra) and the confluence
    lines (thin rods) are one mesh with face colours. In a browser without a GPU (software
    WebGL, SwiftShader) the time goes into setting up each trace and rasterising the canvas,
    not into the vertices (benchmarks/bench_app.py: a 16x coarser surface saved little; 9
    traces -> 3 about halved it, 3 -> 1 cut it by another third). The points are named in the
    legend entry and the page's caption; what is lost against separate marker traces is their
    hover label. Draw it with :data:`GL_CONFIG`. The mesh is sent as typed arrays (half the
    bytes of JSON lists).
    """
    h = rep.hull
    x, y, z = (np.asarray(a, float) for a in hull_surface(h.a1, h.a2, h.b, shape=rep.shape))
    n_rows, n_cols = x.shape
    vx, vy, vz = [x.ravel()], [y.ravel()], [z.ravel()]
    ii, jj, kk = (np.asarray(a) for a in _grid_triangles(n_rows, n_cols))
    fi, fj, fk = [ii], [jj], [kk]
    colours = ["#a9bfdc"] * ii.size
    o = x.size
    for outline in rep.fins.outlines:
        p = np.asarray(outline, float)[:4]
        vx.append(p[:, 0])
        vy.append(p[:, 1])
        vz.append(p[:, 2])
        fi.append(np.array([o, o]))
        fj.append(np.array([o + 1, o + 2]))
        fk.append(np.array([o + 2, o + 3]))
        colours += ["#e69f00"] * 2
        o += 4
    length = float(np.ptp(x)) or 1.0
    parts = [
        (_octahedron((float(p[0]), 0.0, float(p[1])), 0.012 * length), colour)
        for p, colour in ((getattr(rep.points, key), c) for key, _l, _s, _sym, c in _POINTS)
    ]
    parts += [
        (_rod((line[0, 0], 0.0, line[0, 1]), (line[1, 0], 0.0, line[1, 1]), 0.002 * length),
         "#555555")
        for line in (np.asarray(ln, float) for ln in rep.confluence_lines)
    ]
    for (verts, faces), colour in parts:
        vx.append(verts[:, 0])
        vy.append(verts[:, 1])
        vz.append(verts[:, 2])
        f = np.asarray(faces) + o
        fi.append(f[:, 0])
        fj.append(f[:, 1])
        fk.append(f[:, 2])
        colours += [colour] * len(faces)
        o += len(verts)
    index = np.uint16 if o < 2**16 else np.uint32
    traces: list[dict] = [
        dict(
            type="mesh3d",
            # numpy arrays go to the browser as typed arrays (base64), not as JSON lists: the
            # message is half the size; float32 is finer than 0.1 mm on a 100 m hull
            x=np.concatenate(vx).astype(np.float32),
            y=np.concatenate(vy).astype(np.float32),
            z=np.concatenate(vz).astype(np.float32),
            i=np.concatenate(fi).astype(index),
            j=np.concatenate(fj).astype(index),
            k=np.concatenate(fk).astype(index),
            facecolor=colours,
            name="hull (blue), fins (orange), CB (green), CG (black), confluence point C "
            "(red), confluence lines (grey, schematic)",
            showlegend=True,
            hoverinfo="skip",
            lighting=dict(ambient=0.6, diffuse=0.6, specular=0.2),
        )
    ]
    # No axis box (grid, ticks, titles): in software WebGL it cost more than the hull itself
    # (benchmarks/bench_app.py: ~0.6 s of a ~0.9 s draw); the page's caption gives the scale.
    # The titles stay for the unit conversion of the data (US customary in ft).
    scene = dict(
        aspectmode="data",
        xaxis=_axis("ξ from nose [m]", visible=False),
        yaxis=_axis("y [m]", visible=False),
        zaxis=_axis("z [m]", visible=False),
        camera=dict(eye=dict(x=-0.8, y=-1.2, z=0.5)),
    )
    return _figure(
        traces,
        "Hull and fins (3-D, to scale)",
        scene=scene,
        height=620,
        margin=dict(l=0, r=0, t=40, b=0),
    )


def side_view_figure(rep: DesignReport) -> go.Figure:
    """Side view to scale: hull outline, fins, centre of buoyancy, centre of gravity,
    confluence point and (schematic) confluence lines; nose on the left, z up."""
    h = rep.hull
    xi, r = hull_outline(h.a1, h.a2, h.b, shape=rep.shape)
    traces: list[dict] = [
        dict(
            type="scatter",
            x=_l(np.concatenate([xi, xi[::-1]])),
            y=_l(np.concatenate([r, -r[::-1]])),
            mode="lines",
            fill="toself",
            fillcolor="rgba(143,169,204,0.35)",
            line=dict(color=ACCENT, width=2),
            name="hull",
            hoverinfo="skip",
        )
    ]
    first = True
    for outline in rep.fins.outlines:
        p = np.asarray(outline)
        if np.allclose(p[:, 2], 0.0, atol=1e-9):
            continue  # a horizontal fin is edge-on in the side view
        traces.append(
            dict(
                type="scatter",
                x=_l(p[:, 0]),
                y=_l(p[:, 2]),
                mode="lines",
                fill="toself",
                fillcolor="rgba(230,159,0,0.45)",
                line=dict(color="#b07800"),
                name="fins",
                legendgroup="fins",
                showlegend=first,
                hoverinfo="skip",
            )
        )
        first = False
    for k, line in enumerate(rep.confluence_lines):
        traces.append(
            dict(
                type="scatter",
                x=_l(line[:, 0]),
                y=_l(line[:, 1]),
                mode="lines",
                line=dict(color="#555555", width=1.5),
                name="confluence lines (schematic)",
                legendgroup="cl",
                showlegend=k == 0,
                hoverinfo="skip",
            )
        )
    for key, label, short, symbol, colour in _POINTS:
        x0, z0 = getattr(rep.points, key)
        traces.append(
            dict(
                type="scatter",
                x=[float(x0)],
                y=[float(z0)],
                mode="markers+text",
                name=label,
                text=[short],
                textposition="top right",
                marker=dict(symbol=symbol, size=11, color=colour),
                hovertemplate=f"{label}: ξ = %{{x:{_LEN}}} m, z = %{{y:{_LEN}}} m<extra></extra>",
            )
        )
    return _figure(
        traces,
        "Side view (to scale, level hull)",
        height=420,
        xaxis=_axis("Station from the nose ξ [m]", zeroline=False),
        yaxis=_axis(
            "Height above the hull axis z [m]", scaleanchor="x", scaleratio=1, zeroline=False
        ),
    )


# --- performance ------------------------------------------------------------------------------


def performance_figure(rep: DesignReport, key: str) -> go.Figure:
    """One performance quantity (a field of ``rep.perf``) versus wind speed, with limit markers
    and requirement lines."""
    p, lim = rep.perf, rep.limits
    title, ylabel = PERF_QUANTITIES[key]
    v, y = p.wind_speed, getattr(p, key)
    traces = [
        dict(
            type="scatter",
            x=_l(v),
            y=_l(y),
            mode="lines+markers",
            name=title,
            line=dict(color=ACCENT, width=2.5),
            marker=dict(size=5),
            hovertemplate=perf_hover(key, ylabel.rsplit("[", 1)[-1].rstrip("]")),
        )
    ]
    traces += _limit_trace(v, y, p.limited, p.flag_text)
    lines = [dict(axis="x", value=lim.design_wind, text="design wind", dash="dot")]
    # horizontal limit line of this quantity, if it has one: (limit key, label format)
    limit_line = {
        "blow_by": ("blow_by_limit", "blow-by limit {:g} m"),
        "alpha_eq": ("stall_deg", "fin stall {:g} deg"),
        "safety_factor": ("min_safety_factor", "required {:g}"),
    }.get(key)
    if limit_line is not None:
        name, label = limit_line
        lines.append(
            dict(
                axis="y",
                value=getattr(lim, name),
                colour=LIMIT_COLOUR,
                text=label.format(getattr(lim, name)),
            )
        )
    return _figure(
        traces, title, lines=lines, height=360, xaxis=_axis(WIND_AXIS), yaxis=_axis(ylabel)
    )


def tension_figure(rep: DesignReport) -> go.Figure:
    """Tether tension at the top and at the winch [N] (left) and the safety factor (right)."""
    p, lim = rep.perf, rep.limits
    v = p.wind_speed
    traces = [
        dict(
            type="scatter",
            x=_l(v),
            y=_l(p.tension_top),
            mode="lines+markers",
            name="tension at the confluence point [N]",
            line=dict(color=ACCENT, width=2.5),
            marker=dict(size=5),
            hovertemplate=perf_hover("tension_top", "N"),
        ),
        dict(
            type="scatter",
            x=_l(v),
            y=_l(p.tension_winch),
            mode="lines",
            name="tension at the winch [N]",
            line=dict(color=ACCENT, width=1.5, dash="dash"),
            hovertemplate=perf_hover("tension_winch", "N"),
        ),
        dict(
            type="scatter",
            x=_l(v),
            y=_l(p.safety_factor),
            mode="lines",
            name="safety factor [-]",
            yaxis="y2",
            line=dict(color=THIRD, width=2),
            hovertemplate=perf_hover("safety_factor", "-"),
        ),
    ]
    traces += _limit_trace(v, p.tension_top, p.limited, p.flag_text)
    lines = [
        dict(
            axis="y",
            value=lim.min_safety_factor,
            colour=THIRD,
            dash="dot",
            yref="y2",
            text=f"required safety factor {lim.min_safety_factor:g}",
        ),
        dict(axis="x", value=lim.design_wind, text="design wind", dash="dot"),
    ]
    return _figure(
        traces,
        "Tether tension and safety factor",
        lines=lines,
        height=380,
        xaxis=_axis(WIND_AXIS),
        yaxis=_axis("Tether tension [N]", rangemode="tozero"),
        # tickmode "auto": an overlaying axis otherwise syncs to the primary grid (5.12, 10.23)
        yaxis2=_axis(
            "Safety factor [-]",
            overlaying="y",
            side="right",
            rangemode="tozero",
            showgrid=False,
            tickmode="auto",
        ),
    )


def cm_figure(rep: DesignReport) -> go.Figure:
    """Pitching-moment coefficient about the confluence point versus angle of attack."""
    c = rep.cm
    a, cm = np.asarray(c.alpha_deg, float), np.asarray(c.cm, float)
    a_eq = float(c.alpha_eq_deg)
    traces = [
        dict(
            type="scatter",
            x=_l(a),
            y=_l(cm),
            mode="lines",
            name="C_m",
            line=dict(color=ACCENT, width=2.5),
        ),
        dict(
            type="scatter",
            x=[a_eq],
            y=[float(np.interp(a_eq, a, cm))],
            mode="markers",
            name="trim (α_eq at the design wind)",
            marker=dict(size=11, color=THIRD, symbol="circle"),
        ),
    ]
    return _figure(
        traces,
        f"Pitching moment C_m at {c.wind:g} m/s",
        lines=[dict(axis="y", value=0.0, dash="solid")],
        height=360,
        xaxis=_axis("Angle of attack α [deg]"),
        yaxis=_axis("C_m about the confluence point [-]"),
    )


# --- tether -----------------------------------------------------------------------------------


def default_tether_speeds(wind_speed: Sequence[float], n: int = 5) -> list[float]:
    """About ``n`` evenly spread sweep speeds above zero (the largest included).

    >>> default_tether_speeds([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10], 5)
    [2.0, 4.0, 6.0, 8.0, 10.0]
    """
    v = [float(s) for s in wind_speed if s > 0]
    if len(v) <= n:
        return v
    idx = np.unique(np.round(np.linspace(-1, len(v) - 1, n + 1)[1:]).astype(int))
    return [v[i] for i in idx]


def _line(x: Any, y: Any, name: str, colour: str, **kw: Any) -> dict:
    """A solid line trace of width 2.2 in ``colour``."""
    return dict(
        type="scatter",
        x=_l(x),
        y=_l(y),
        mode="lines",
        name=name,
        line=dict(color=colour, width=2.2),
        **kw,
    )


def tether_speeds(tether: TetherProfiles | Mapping[str, Any]) -> list[float]:
    """Speeds with a tether profile [m/s]: the sweep's, and the design wind (its own profile,
    also when the sweep steps over it). ``tether`` is ``rep.tether`` (or its plain dict)."""
    t = tether_profiles(tether)
    speeds = {float(v) for v in t.wind_speed}
    if t.design is not None:
        speeds.add(float(t.design.wind))
    return sorted(speeds)


def default_profile_speeds(tether: TetherProfiles | Mapping[str, Any], n: int = 5) -> list[float]:
    """:func:`default_tether_speeds` of the sweep, plus the design wind."""
    t = tether_profiles(tether)
    chosen = set(default_tether_speeds([float(v) for v in t.wind_speed], n))
    if t.design is not None and float(t.design.wind) > 0:
        chosen.add(float(t.design.wind))
    return sorted(chosen)


def _profile_at(tether: TetherProfiles, speed: float) -> tuple[np.ndarray, np.ndarray, float]:
    """Tether profile (x, z) [m] at the sweep speed nearest ``speed`` (or the design wind's own
    profile when ``speed`` is the design wind), and that speed [m/s]."""
    design = tether.design
    if design is not None and abs(float(speed) - float(design.wind)) < 1e-9:
        return np.asarray(design.x), np.asarray(design.z), float(design.wind)
    ws = np.asarray(tether.wind_speed, float)
    j = int(np.argmin(np.abs(ws - speed)))
    return np.asarray(tether.x)[:, j], np.asarray(tether.z)[:, j], float(ws[j])


def _winch_trace(label: bool) -> dict:
    """The winch at the origin (black square), optionally labelled."""
    return dict(
        type="scatter",
        x=[0.0],
        y=[0.0],
        mode="markers+text" if label else "markers",
        name="winch",
        text=["winch"] if label else None,
        textposition="bottom center",
        marker=dict(symbol="square", size=12, color="#000000"),
    )


def _to_scale_figure(traces: list[dict], title: str, **kw: Any) -> go.Figure:
    """Tether plot with equal axis scales, winch at the origin."""
    return _figure(
        traces,
        title,
        height=560,
        xaxis=_axis("Downwind distance from the winch [m]"),
        yaxis=_axis(
            "Height above the winch [m]", scaleanchor="x", scaleratio=1, rangemode="tozero"
        ),
        **kw,
    )


def tether_figure(rep: DesignReport, speeds: Sequence[float] | None = None) -> go.Figure:
    """Tether profiles for several wind speeds, to scale, with the winch and the aerostat."""
    t, lim = rep.tether, rep.limits
    ws = np.asarray(t.wind_speed, float)
    speeds = default_tether_speeds(ws) if speeds is None else list(speeds)
    traces: list[dict] = []
    tops_x, tops_z, tops_t = [], [], []
    for k, s in enumerate(speeds):
        x, z, w = _profile_at(t, s)
        traces.append(_line(x, z, f"{w:g} m/s", PALETTE[k % len(PALETTE)]))
        top = int(np.argmax(z))
        tops_x.append(float(x[top]))
        tops_z.append(float(z[top]))
        tops_t.append(
            f"{w:g} m/s: blow-by {formats.text(x[top], 'blow_by')} m, "
            f"height {formats.text(z[top], 'flying_height')} m"
        )
    traces.append(
        dict(
            type="scatter",
            x=tops_x,
            y=tops_z,
            mode="markers",
            name="aerostat (confluence point)",
            text=tops_t,
            hovertemplate="%{text}<extra></extra>",
            marker=dict(
                symbol="circle", size=12, color="#8fa9cc", line=dict(color=ACCENT, width=2)
            ),
        )
    )
    traces.append(_winch_trace(label=True))
    lines = [
        dict(
            axis="x",
            value=lim.blow_by_limit,
            colour=LIMIT_COLOUR,
            text=f"blow-by limit {lim.blow_by_limit:g} m",
        )
    ]
    return _to_scale_figure(
        traces,
        "Tether profiles (to scale)",
        legend=dict(orientation="v", x=1.02, y=1.0),
        lines=lines,
    )


# --- comparison of saved cases --------------------------------------------------------------


def plain_label(text: str) -> str:
    """A user's text as a plotly label: plotly reads a subset of HTML in names (``<a href>``,
    ``<b>``), so ``& < >`` are escaped and the text shows as typed."""
    return html.escape(str(text), quote=False)


def compare_performance_figure(reps: Mapping[str, DesignReport], key: str) -> go.Figure:
    """One performance quantity versus wind speed, one line per case (limit rows marked)."""
    title, ylabel = PERF_QUANTITIES[key]
    traces: list[dict] = []
    for k, (case, rep) in enumerate(reps.items()):
        name = plain_label(case)
        p = rep.perf
        colour = PALETTE[k % len(PALETTE)]
        hover = perf_hover(key, ylabel.rsplit("[", 1)[-1].rstrip("]"))
        y = getattr(p, key)
        traces.append(_line(p.wind_speed, y, name, colour, legendgroup=name, hovertemplate=hover))
        traces += _limit_trace(
            p.wind_speed,
            y,
            p.limited,
            p.flag_text,
            name=f"{name}: {LIMIT_TRACE}",
            legendgroup=name,
            showlegend=False,
            marker=dict(symbol="x", size=10, color=colour, line=dict(width=1)),
        )
    return _figure(traces, title, height=360, xaxis=_axis(WIND_AXIS), yaxis=_axis(ylabel))


def compare_tether_figure(reps: Mapping[str, DesignReport], wind: float) -> go.Figure:
    """Tether profiles of every case at the sweep speed nearest ``wind``, to scale."""
    traces: list[dict] = []
    for k, (case, rep) in enumerate(reps.items()):
        name = plain_label(case)
        x, z, w = _profile_at(rep.tether, wind)
        colour = PALETTE[k % len(PALETTE)]
        top = int(np.argmax(z))
        traces.append(_line(x, z, f"{name} ({w:g} m/s)", colour, legendgroup=name))
        traces.append(
            dict(
                type="scatter",
                x=[float(x[top])],
                y=[float(z[top])],
                mode="markers",
                name=f"{name}: aerostat",
                legendgroup=name,
                showlegend=False,
                marker=dict(size=11, color=colour, line=dict(color="#000", width=1)),
            )
        )
    traces.append(_winch_trace(label=False))
    return _to_scale_figure(traces, f"Tether profiles at {wind:g} m/s (to scale)")
