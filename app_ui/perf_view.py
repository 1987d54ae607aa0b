"""The Performance tab's five charts as static SVG drawings: blow-by, equilibrium angle of attack
and dynamic lift versus wind speed, tether tension with the safety factor on a second axis, and
the pitching-moment curve C_m(α) with its trim point.

Why not plotly: five plotly charts were most of a switch to the Performance tab in a browser
without a GPU (benchmarks/bench_app.py: about 1 s, half of it front-end render after the last
message, 1.7 s of chromium CPU), as the Mass tab's one chart was before it became a drawing
(:mod:`app_ui.mass_view`). What the drawings do not do is zoom and hover labels: the plotly
figures of :mod:`app_ui.plots` are a toggle away on the tab, and the tables above the charts
list every number. Pure: report in, SVG text out (no Streamlit).

The drawings follow the plotly figures: values and axis titles in the session's unit system
(:mod:`app_ui.formats`), the requirement lines (design wind, blow-by limit, fin stall, required
safety factor; dashed), the sweep speeds that break an operating limit marked by red crosses,
the safety factor on a right-hand axis, the trim point on the C_m curve; colours and fonts from
:mod:`app_ui.theme`.

What a test reads back (every value in the unit the chart shows, its unit on the root): the root
``<svg>`` carries ``data-chart`` (the plotly chart's key: ``perf_blow_by`` ...), ``data-x-unit``,
``data-y-unit`` (and ``data-y2-unit``); every line ``data-series`` with the ``data-x`` and
``data-y`` of its points (space-separated); every marker ``data-x``, ``data-y``,
``data-limited``; every red cross ``data-limit-point`` with its point; every requirement line
``data-limit`` (its name) and ``data-value``; every tick ``data-tick`` (axis), ``data-value``
and ``data-px`` (its place in the drawing).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from html import escape

import numpy as np

from aerostat_core.output.report import DesignReport

from . import formats
from .theme import ACCENT, FONT, LIMIT_COLOUR, NEUTRAL, THIRD, TITLE_SIZE

#: Width of each drawing [px of the viewBox]; shown at :data:`WIDTH_PX`.
_W = 380.0
#: Width each chart is shown at [px]: one a row in the result column at 1024 px (about 500 px
#: wide), two a row at 1400 px (about 760 px, with room for a 17 px scroll bar); near the
#: drawing's own scale, so its 13 px text stays over 12 px on screen.
WIDTH_PX = 360
_LEFT = 62.0  # room for the tick labels and the rotated axis title
_RIGHT = 16.0
_RIGHT2 = 54.0  # with a second (right-hand) axis
_TOP = 36.0  # under the title
_PLOT_H = 170.0
_TICK_FONT = 12
_NOTE_FONT = 11
_LEGEND_ROW = 17.0
_GRID = "#e6e6e6"
#: A white outline behind a text drawn over lines (the notes of the requirement lines).
_HALO = 'paint-order="stroke" stroke="#ffffff" stroke-width="3" stroke-linejoin="round"'

#: The charts in the order drawn: key (as the plotly chart's), what it shows.
CHARTS = (
    ("perf_blow_by", "blow_by"),
    ("perf_alpha", "alpha_eq"),
    ("perf_lift", "dynamic_lift"),
    ("perf_tension", "tension"),
    ("perf_cm", "cm"),
)
#: Field of ``rep.perf`` -> (title, axis name, quantity of :mod:`app_ui.formats`).
_WIND_CHARTS = {
    "blow_by": ("Blow-by (downwind offset)", "Blow-by", "blow_by"),
    "alpha_eq": ("Equilibrium angle of attack", "α_eq", "alpha_eq"),
    "dynamic_lift": ("Dynamic lift", "Dynamic lift", "dynamic_lift"),
}
LIMIT_NAME = "operating limit exceeded"


@dataclass(frozen=True)
class Chart:
    """One drawing: its key (as the plotly chart's), the SVG markup and a text alternative (what
    a screen reader says for the image)."""

    key: str
    svg: str
    alt: str


# --- numbers and ticks ----------------------------------------------------------------------


def _num(x: float) -> str:
    """A value for a data attribute: 9 significant digits, never "-0"."""
    return f"{float(x) + 0.0:.9g}"


def _px(x: float) -> str:
    """A coordinate of the drawing (0.1 px), never "-0.0"."""
    s = f"{x:.1f}"
    return "0.0" if s == "-0.0" else s


def nice_step(span: float, target: int = 5) -> float:
    """A round tick step (1, 2 or 5 x 10^k) giving about ``target`` intervals over ``span``
    (the static drawings' one rule: these charts and the side view's station axis).

    >>> nice_step(76.4), nice_step(0.5), nice_step(31.0, 8)
    (20.0, 0.1, 5.0)
    """
    raw = span / max(target, 1)
    k = 10.0 ** math.floor(math.log10(raw))
    return next(m * k for m in (1.0, 2.0, 5.0, 10.0) if m * k >= raw * (1 - 1e-9))


def nice_ticks(lo: float, hi: float, target: int = 5) -> np.ndarray:
    """Round ticks (a step of 1, 2 or 5 x 10^k) from at or below ``lo`` to at or above ``hi``,
    about ``target`` intervals; a range of zero width is widened to show its value.

    >>> nice_ticks(0.0, 76.4).tolist()
    [0.0, 20.0, 40.0, 60.0, 80.0]
    >>> nice_ticks(-0.37, 0.13).tolist()
    [-0.4, -0.3, -0.2, -0.1, 0.0, 0.1, 0.2]
    >>> nice_ticks(5.0, 5.0).tolist()
    [4.0, 4.5, 5.0, 5.5, 6.0]
    """
    lo, hi = float(lo), float(hi)
    if hi < lo:
        lo, hi = hi, lo
    if hi - lo <= 1e-12 * max(abs(lo), abs(hi), 1.0):
        pad = abs(lo) * 0.2 if abs(lo) >= 1e-9 else 1.0
        lo, hi = lo - pad, hi + pad
    step = nice_step(hi - lo, target)
    first = math.floor(lo / step + 1e-9)
    last = math.ceil(hi / step - 1e-9)
    digits = max(0, -math.floor(math.log10(step))) + 1
    ticks = np.round(np.arange(first, last + 1) * step, digits) + 0.0
    return ticks


def _tick_text(t: float, ticks: np.ndarray) -> str:
    """A tick label at the decimals its step needs (1,600; 0.25; -0.2), never "-0"."""
    step = float(ticks[1] - ticks[0]) if len(ticks) > 1 else 1.0
    d = max(0, -math.floor(math.log10(step) + 1e-9))
    if abs(round(step, d) - step) > 1e-9 * step:
        d += 1  # 0.25
    s = f"{t:,.{d}f}"
    return s[1:] if s.startswith("-") and float(s.replace(",", "")) == 0 else s


def _finite(*arrays: Sequence[float]) -> np.ndarray:
    """Rows where every array is finite (a value that is not there is not drawn)."""
    ok = np.ones(np.shape(arrays[0]), bool)
    for a in arrays:
        ok &= np.isfinite(np.asarray(a, float))
    return ok


# --- one chart --------------------------------------------------------------------------------


@dataclass
class _Axis:
    """A linear axis: shown values ``ticks[0]..ticks[-1]`` onto pixels ``p0..p1``."""

    ticks: np.ndarray
    p0: float
    p1: float

    def __call__(self, v: float) -> float:
        t0, t1 = float(self.ticks[0]), float(self.ticks[-1])
        return self.p0 + (float(v) - t0) * (self.p1 - self.p0) / (t1 - t0)


def _axis_ticks(values: Sequence[float], extra: Sequence[float] = (), zero: bool = False):
    v = np.asarray(values, float)
    v = np.concatenate([v[np.isfinite(v)], np.asarray(extra, float)])
    v = v[np.isfinite(v)]
    if zero:
        v = np.append(v, 0.0)
    if v.size == 0:
        return nice_ticks(0.0, 1.0)
    return nice_ticks(float(v.min()), float(v.max()))


@dataclass
class _Series:
    """A line (and its markers) in shown units: key, x, y, colour, dash, marked, y axis."""

    key: str
    name: str
    x: np.ndarray
    y: np.ndarray
    colour: str = ACCENT
    width: float = 2.5
    dash: str = ""
    markers: bool = False
    limited: np.ndarray | None = None
    axis: str = "y"


@dataclass
class _Line:
    """A requirement line: ``axis`` "x" (vertical) or "y"/"y2" (horizontal) at ``value``."""

    name: str
    axis: str
    value: float
    text: str
    colour: str = NEUTRAL
    dash: str = "6 4"


def _design_wind_line(lim) -> _Line:
    """The vertical line at the design wind, in the chosen units (every wind-speed chart has it)."""
    return _Line(
        "design_wind",
        "x",
        float(formats.convert(lim.design_wind, "wind")),
        "design wind",
        dash="2 3",
    )


def _legend(items: list[tuple[str, str]], x0: float, y0: float, width: float) -> tuple[list, float]:
    """Legend entries (symbol markup, text) in rows within ``width``; the markup and the rows'
    height."""
    out, x, y = [], x0, y0
    char = 0.48 * _TICK_FONT  # about a sans-serif character's width
    for symbol, text in items:
        w = 24 + len(text) * char + 12
        if x > x0 and x + w > x0 + width:
            x, y = x0, y + _LEGEND_ROW
        out.append(
            f'<g transform="translate({_px(x)},{_px(y)})">{symbol}'
            f'<text x="24" y="4" font-size="{_TICK_FONT}">{escape(text)}</text></g>'
        )
        x += w
    return out, (y - y0 + _LEGEND_ROW) if items else 0.0


def _line_symbol(colour: str, width: float, dash: str = "", marker: bool = False) -> str:
    d = f' stroke-dasharray="{dash}"' if dash else ""
    dot = f'<circle cx="10" cy="0" r="2.5" fill="{colour}"/>' if marker else ""
    return f'<line x1="0" y1="0" x2="20" y2="0" stroke="{colour}" stroke-width="{width}"{d}/>' + dot


def _cross(x: float, y: float, r: float = 4.5) -> str:
    return (
        f'<path d="M{_px(x - r)},{_px(y - r)}L{_px(x + r)},{_px(y + r)}M{_px(x - r)},'
        f'{_px(y + r)}L{_px(x + r)},{_px(y - r)}" stroke="{LIMIT_COLOUR}" stroke-width="2"/>'
    )


def _chart(
    key: str,
    title: str,
    description: str,
    xlabel: tuple[str, str],
    ylabel: tuple[str, str],
    series: list[_Series],
    lines: list[_Line],
    *,
    y2label: tuple[str, str] | None = None,
    flags: Sequence[str] = (),
    trim: tuple[float, float] | None = None,
    y_zero: bool = False,
    legend: list[tuple[str, str]] | None = None,
) -> str:
    """One chart's SVG: axes with round ticks and grid lines, the series, the requirement
    lines, the red crosses of the limited points (``flags``: their texts), the trim point and a
    legend under the x-axis title. ``xlabel``, ``ylabel``: (name, unit)."""
    right = _RIGHT2 if y2label else _RIGHT
    px0, px1 = _LEFT, _W - right
    py0, py1 = _TOP + _PLOT_H, _TOP  # bottom, top

    def on(axis: str) -> list[_Series]:
        return [s for s in series if s.axis == axis]

    def limits_on(axis: str) -> list[float]:
        return [ln.value for ln in lines if ln.axis == axis]

    xs = np.concatenate([s.x for s in series])
    ax = _Axis(_axis_ticks(xs, limits_on("x")), px0, px1)
    ay = _Axis(
        _axis_ticks(np.concatenate([s.y for s in on("y")]), limits_on("y"), y_zero), py0, py1
    )
    axes = {"x": ax, "y": ay}
    if y2label:
        axes["y2"] = _Axis(
            _axis_ticks(np.concatenate([s.y for s in on("y2")]), limits_on("y2"), y_zero), py0, py1
        )
    legend = list(legend or [])
    legend_rows, legend_h = _legend(legend, 8.0, py0 + 56.0, _W - 16.0)
    height = py0 + 44.0 + (legend_h + 6.0 if legend else 0.0)

    units = f'data-x-unit="{escape(xlabel[1])}" data-y-unit="{escape(ylabel[1])}"'
    if y2label:
        units += f' data-y2-unit="{escape(y2label[1])}"'
    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {_W:.0f} {height:.0f}" '
        f'width="{_W:.0f}" height="{height:.0f}" role="img" data-chart="{key}" {units} '
        f'font-family="{FONT["family"]}" font-size="{FONT["size"]}">',
        f"<title>{escape(description)}</title>",
        f'<rect width="{_W:.0f}" height="{height:.0f}" fill="#ffffff"/>',
        f'<text x="8" y="20" font-size="{TITLE_SIZE}">{escape(title)}</text>',
    ]
    # grid and ticks
    for t in ax.ticks:
        p = ax(t)
        out.append(
            f'<g data-tick="x" data-value="{_num(t)}" data-px="{_px(p)}"><line x1="{_px(p)}" '
            f'y1="{_px(py1)}" x2="{_px(p)}" y2="{_px(py0 + 4)}" stroke="{_GRID}"/>'
            f'<text x="{_px(p)}" y="{_px(py0 + 17)}" text-anchor="middle" '
            f'font-size="{_TICK_FONT}" fill="#444">{_tick_text(t, ax.ticks)}</text></g>'
        )
    for t in ay.ticks:
        p = ay(t)
        out.append(
            f'<g data-tick="y" data-value="{_num(t)}" data-px="{_px(p)}"><line x1="{_px(px0 - 4)}" '
            f'y1="{_px(p)}" x2="{_px(px1)}" y2="{_px(p)}" stroke="{_GRID}"/>'
            f'<text x="{_px(px0 - 7)}" y="{_px(p + 4)}" text-anchor="end" '
            f'font-size="{_TICK_FONT}" fill="#444">{_tick_text(t, ay.ticks)}</text></g>'
        )
    if y2label:
        a2 = axes["y2"]
        for t in a2.ticks:
            p = a2(t)
            out.append(
                f'<g data-tick="y2" data-value="{_num(t)}" data-px="{_px(p)}"><line '
                f'x1="{_px(px1)}" y1="{_px(p)}" x2="{_px(px1 + 4)}" y2="{_px(p)}" '
                f'stroke="{THIRD}"/><text x="{_px(px1 + 7)}" y="{_px(p + 4)}" '
                f'font-size="{_TICK_FONT}" fill="{THIRD}">{_tick_text(t, a2.ticks)}</text></g>'
            )
    out.append(
        f'<rect x="{_px(px0)}" y="{_px(py1)}" width="{_px(px1 - px0)}" height="{_px(py0 - py1)}" '
        f'fill="none" stroke="{NEUTRAL}" stroke-width="0.8"/>'
    )
    # axis titles
    out.append(
        f'<text x="{_px((px0 + px1) / 2)}" y="{_px(py0 + 36)}" text-anchor="middle">'
        f"{escape(_bracket(*xlabel))}</text>"
    )
    out.append(
        f'<text transform="translate(15,{_px((py0 + py1) / 2)}) rotate(-90)" '
        f'text-anchor="middle">{escape(_bracket(*ylabel))}</text>'
    )
    if y2label:
        out.append(
            # rotated a quarter turn clockwise: the glyphs stand to the right of the anchor
            f'<text transform="translate({_px(_W - 17)},{_px((py0 + py1) / 2)}) rotate(90)" '
            f'text-anchor="middle" fill="{THIRD}">{escape(_bracket(*y2label))}</text>'
        )
    # requirement lines (under the data)
    for ln in lines:
        a = axes[ln.axis]
        p = a(ln.value)
        common = (
            f'data-limit="{ln.name}" data-axis="{ln.axis}" data-value="{_num(ln.value)}" '
            f'stroke="{ln.colour}" stroke-width="1.5" stroke-dasharray="{ln.dash}"'
        )
        if ln.axis == "x":
            out.append(
                f'<line {common} x1="{_px(p)}" y1="{_px(py1)}" x2="{_px(p)}" y2="{_px(py0)}"/>'
            )
            out.append(
                f'<text x="{_px(p + 3)}" y="{_px(py1 + 12)}" font-size="{_NOTE_FONT}" '
                f'fill="{ln.colour}" {_HALO}>{escape(ln.text)}</text>'
            )
        else:
            out.append(
                f'<line {common} x1="{_px(px0)}" y1="{_px(p)}" x2="{_px(px1)}" y2="{_px(p)}"/>'
            )
            # the note above the line, or under it when the line is at the top of the plot
            ty = p - 4 if p - 14 > py1 else p + 13
            tx, anchor = (px0 + 4, "start") if ln.axis == "y" else (px1 - 4, "end")
            if ln.text:
                out.append(
                    f'<text x="{_px(tx)}" y="{_px(ty)}" text-anchor="{anchor}" '
                    f'font-size="{_NOTE_FONT}" fill="{ln.colour}" {_HALO}>{escape(ln.text)}'
                    "</text>"
                )
    # the series: a path through the finite points (a gap where one is missing), markers
    for s in series:
        a = axes[s.axis]
        ok = _finite(s.x, s.y)
        d, pen = [], "M"
        for xv, yv, good in zip(s.x, s.y, ok):
            if not good:
                pen = "M"
                continue
            d.append(f"{pen}{_px(ax(xv))},{_px(a(yv))}")
            pen = "L"
        dash = f' stroke-dasharray="{s.dash}"' if s.dash else ""
        xs_ok, ys_ok = s.x[ok], s.y[ok]
        out.append(
            f'<g data-series="{s.key}" data-axis="{s.axis}" '
            f'data-x="{" ".join(_num(v) for v in xs_ok)}" '
            f'data-y="{" ".join(_num(v) for v in ys_ok)}"><title>{escape(s.name)}</title>'
            f'<path d="{"".join(d)}" fill="none" stroke="{s.colour}" stroke-width="{s.width}"'
            f' stroke-linejoin="round"{dash}/>'
        )
        if s.markers:
            lim = np.zeros(s.x.shape, bool) if s.limited is None else s.limited
            for xv, yv, flag in zip(xs_ok, ys_ok, lim[ok]):
                out.append(
                    f'<circle data-x="{_num(xv)}" data-y="{_num(yv)}" '
                    f'data-limited="{int(bool(flag))}" cx="{_px(ax(xv))}" cy="{_px(a(yv))}" '
                    f'r="2.5" fill="{s.colour}"/>'
                )
        out.append("</g>")
    # red crosses where an operating limit is broken (on the first marked series)
    marked = next((s for s in series if s.limited is not None), None)
    if marked is not None:
        a = axes[marked.axis]
        ok = _finite(marked.x, marked.y) & np.asarray(marked.limited, bool)
        for i in np.flatnonzero(ok):
            xv, yv = float(marked.x[i]), float(marked.y[i])
            why = flags[i] if i < len(flags) and flags[i] else LIMIT_NAME
            out.append(
                f'<g data-limit-point="{marked.key}" data-x="{_num(xv)}" data-y="{_num(yv)}">'
                f"<title>{escape(why)}</title>{_cross(ax(xv), a(yv))}</g>"
            )
    if trim is not None and all(math.isfinite(v) for v in trim):
        out.append(
            f'<g data-trim="1" data-x="{_num(trim[0])}" data-y="{_num(trim[1])}"><title>'
            f'trim (α_eq at the design wind)</title><circle cx="{_px(ax(trim[0]))}" '
            f'cy="{_px(ay(trim[1]))}" r="5.5" fill="{THIRD}" stroke="#ffffff" '
            'stroke-width="1.5"/></g>'
        )
    out += legend_rows
    out.append("</svg>")
    return "".join(out)


def _bracket(name: str, unit: str) -> str:
    return f"{name} [{unit}]"


def _shown(values: Sequence[float], quantity: str) -> np.ndarray:
    """SI values in the current unit system (as :func:`app_ui.formats.convert`)."""
    du = formats.display(quantity)
    return np.asarray(values, float) * du.scale + du.offset


def _range_text(values: np.ndarray, quantity: str = "", decimals: int = 3) -> str:
    """ "lowest to highest unit" of shown values at the decimals of their quantity (without a
    quantity: at ``decimals``, no unit)."""
    v = values[np.isfinite(values)]
    if v.size == 0:
        return formats.missing("no value in the sweep")
    u = formats.unit_of(quantity) if quantity else ""
    unit = "" if u in ("-", "") else f" {u}"
    d = formats.decimals(quantity) if quantity else decimals

    def t(x: float) -> str:
        s = f"{x:,.{d}f}"
        return s[1:] if s.startswith("-") and float(s.replace(",", "")) == 0 else s

    return f"{t(float(v.min()))} to {t(float(v.max()))}{unit}"


# --- the five charts --------------------------------------------------------------------------


def _wind_axis() -> tuple[str, str]:
    return ("Wind speed at the aerostat", formats.unit_of("wind"))


def _limited_note(rep: DesignReport) -> str:
    n = int(np.count_nonzero(np.asarray(rep.perf.limited, bool)))
    if not n:
        return "No sweep speed breaks an operating limit."
    return f"{n} sweep speed{'s' if n > 1 else ''} break an operating limit (red crosses)."


def _limit_legend(rep: DesignReport) -> list[tuple[str, str]]:
    if not np.asarray(rep.perf.limited, bool).any():
        return []
    return [(_cross(10, 0, 4.0), LIMIT_NAME)]


def wind_chart(rep: DesignReport, field: str, key: str = "") -> Chart:
    """Blow-by, α_eq or dynamic lift (``field`` of ``rep.perf``) versus wind speed, with the
    design wind, the quantity's own limit line (blow-by limit, fin stall) and red crosses on the
    speeds that break an operating limit."""
    p, lim = rep.perf, rep.limits
    title, name, quantity = _WIND_CHARTS[field]
    key = key or next(k for k, f in CHARTS if f == field)
    x, y = _shown(p.wind_speed, "wind"), _shown(getattr(p, field), quantity)
    lines = [_design_wind_line(lim)]
    if field == "blow_by":
        lines.append(
            _Line(
                "blow_by_limit",
                "y",
                formats.convert(lim.blow_by_limit, "blow_by_limit"),
                f"blow-by limit {formats.shown(lim.blow_by_limit, 'blow_by_limit', with_unit=True)}",
                LIMIT_COLOUR,
            )
        )
    elif field == "alpha_eq":
        lines.append(
            _Line(
                "stall_deg",
                "y",
                float(lim.stall_deg),
                f"fin stall {formats.text(lim.stall_deg, 'alpha_eq', with_unit=True)}",
                LIMIT_COLOUR,
            )
        )
    unit = formats.unit_of(quantity)
    series = [_Series(field, title, x, y, markers=True, limited=np.asarray(p.limited, bool))]
    wind = formats.shown(lim.design_wind, "wind", with_unit=True)
    description = (
        f"{title} versus wind speed: {_range_text(y, quantity)} over "
        f"{_range_text(x, 'wind')}; design wind {wind}"
        + "".join(f"; {ln.text}" for ln in lines[1:])
        + ". "
        + _limited_note(rep)
    )
    svg = _chart(
        key,
        title,
        description,
        _wind_axis(),
        (name, unit),
        series,
        lines,
        flags=p.flag_text,
        legend=_limit_legend(rep),
    )
    return Chart(key, svg, description)


def tension_chart(rep: DesignReport) -> Chart:
    """Tether tension at the confluence point (markers, red crosses where a limit is broken)
    and at the winch (dashed) on the left axis, the safety factor on the right axis with the
    required one, and the design wind."""
    p, lim = rep.perf, rep.limits
    x = _shown(p.wind_speed, "wind")
    top, winch = _shown(p.tension_top, "tension"), _shown(p.tension_winch, "tension")
    sf = np.asarray(p.safety_factor, float)
    unit = formats.unit_of("tension")
    series = [
        _Series(
            "tension_top",
            "tension at the confluence point",
            x,
            top,
            markers=True,
            limited=np.asarray(p.limited, bool),
        ),
        _Series("tension_winch", "tension at the winch", x, winch, width=1.5, dash="6 4"),
        _Series("safety_factor", "safety factor", x, sf, colour=THIRD, width=2.0, axis="y2"),
    ]
    required = f"required safety factor {lim.min_safety_factor:g}"
    lines = [
        _design_wind_line(lim),
        _Line("min_safety_factor", "y2", float(lim.min_safety_factor), required, THIRD, "2 3"),
    ]
    legend = [
        (_line_symbol(ACCENT, 2.5, marker=True), "tension at the confluence point"),
        (_line_symbol(ACCENT, 1.5, "6 4"), "at the winch"),
        (_line_symbol(THIRD, 2.0), "safety factor (right axis)"),
        *_limit_legend(rep),
    ]
    wind = formats.shown(lim.design_wind, "wind", with_unit=True)
    description = (
        f"Tether tension and safety factor versus wind speed: tension at the confluence point "
        f"{_range_text(top, 'tension')}, at the winch {_range_text(winch, 'tension')}; safety "
        f"factor {_range_text(sf, 'safety_factor')} ({required}); design wind {wind}. "
        + _limited_note(rep)
    )
    svg = _chart(
        "perf_tension",
        "Tether tension and safety factor",
        description,
        _wind_axis(),
        ("Tether tension", unit),
        series,
        lines,
        y2label=("Safety factor", "-"),
        flags=p.flag_text,
        y_zero=True,
        legend=legend,
    )
    return Chart("perf_tension", svg, description)


def cm_chart(rep: DesignReport) -> Chart:
    """Pitching-moment coefficient about the confluence point versus angle of attack, the zero
    line and the trim point (α_eq at the design wind)."""
    c = rep.cm
    a, cm = np.asarray(c.alpha_deg, float), np.asarray(c.cm, float)
    a_eq = float(c.alpha_eq_deg)
    ok = _finite(a, cm)
    cm_eq = float(np.interp(a_eq, a[ok], cm[ok])) if ok.any() else float("nan")
    wind = formats.shown(c.wind, "wind", with_unit=True)
    title = f"Pitching moment C_m at {wind}"
    series = [_Series("cm", "C_m", a, cm)]
    lines = [_Line("zero", "y", 0.0, "", NEUTRAL, "none")]  # solid, as in the plotly figure
    description = (
        f"{title} versus angle of attack: C_m about the confluence point "
        f"{_range_text(cm)} over {_range_text(a, 'alpha_eq')}; trim at "
        f"α_eq {formats.text(a_eq, 'alpha_eq', with_unit=True)} (green point)."
    )
    svg = _chart(
        "perf_cm",
        title,
        description,
        ("Angle of attack α", "deg"),
        ("C_m", "-"),  # about the confluence point: the description and the page's caption
        series,
        lines,
        trim=(a_eq, cm_eq),
        legend=[
            (_line_symbol(ACCENT, 2.5), "C_m"),
            (
                f'<circle cx="10" cy="0" r="5" fill="{THIRD}"/>',
                "trim (α_eq at the design wind)",
            ),
        ],
    )
    return Chart("perf_cm", svg, description)


def performance_charts(rep: DesignReport) -> list[Chart]:
    """The Performance tab's five drawings, in the order of :data:`CHARTS`, in the session's
    unit system."""
    return [
        wind_chart(rep, "blow_by"),
        wind_chart(rep, "alpha_eq"),
        wind_chart(rep, "dynamic_lift"),
        tension_chart(rep),
        cm_chart(rep),
    ]
