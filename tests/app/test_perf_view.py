"""The Performance tab's static charts (app_ui/perf_view.py), drawn from a design report without
Streamlit: the points drawn are the report's numbers, in SI and in US customary units, at the
place their axis says; the requirement lines at their values; the red crosses exactly on the
speeds that break an operating limit; valid XML with a title, never "nan", "None" or "-0.0"."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from dataclasses import replace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from aerostat_core import design, thesis_baseline
from aerostat_core.output.report import design_report
from app_ui import formats, perf_view

SVG = "{http://www.w3.org/2000/svg}"
FT, KT, LBF = 0.3048, 1852.0 / 3600.0, 0.45359237 * 9.80665
#: What a drawing must never show: a missing value as text, an infinity, a negative zero.
RAW = re.compile(r"\b(?:nan|NaN|None|inf|Infinity)\b|(?<![\w.])-0(?:\.0+)?(?![\d.])")


@pytest.fixture(scope="module")
def rep():
    r = design_report(design(*thesis_baseline()))
    limited = np.asarray(r.perf.limited, bool)
    assert limited.any() and not limited.all()  # the thesis baseline breaks its blow-by limit
    return r


@pytest.fixture
def us():
    formats.use_system("US")
    yield
    formats.use_system("SI")


def _charts(rep) -> dict:
    out = {}
    for c in perf_view.performance_charts(rep):
        assert not RAW.search(c.svg), (c.key, RAW.search(c.svg).group(0))
        assert not RAW.search(c.alt), c.alt
        root = ET.fromstring(c.svg)  # valid XML
        assert root.get("data-chart") == c.key
        out[c.key] = root
    assert list(out) == [k for k, _ in perf_view.CHARTS]
    return out


def _series(root, key: str) -> tuple[np.ndarray, np.ndarray, str]:
    g = next(g for g in root.iter(f"{SVG}g") if g.get("data-series") == key)
    return (
        np.array(g.get("data-x").split(), float),
        np.array(g.get("data-y").split(), float),
        g.get("data-axis"),
    )


def _ticks(root, axis: str) -> tuple[np.ndarray, np.ndarray]:
    """(values, pixel places) of an axis' ticks."""
    ticks = [g for g in root.iter(f"{SVG}g") if g.get("data-tick") == axis]
    return (
        np.array([float(g.get("data-value")) for g in ticks]),
        np.array([float(g.get("data-px")) for g in ticks]),
    )


def _value_at(root, axis: str, px: np.ndarray) -> np.ndarray:
    """A place in the drawing read back as a value through the axis' ticks (linear)."""
    v, p = _ticks(root, axis)
    assert len(v) >= 3 and np.all(np.diff(v) > 0)
    slope = (v[-1] - v[0]) / (p[-1] - p[0])
    return v[0] + (np.asarray(px, float) - p[0]) * slope


def _tolerance(root, axis: str) -> float:
    """One drawing pixel in the axis' unit (the coordinates are written to 0.1 px)."""
    v, p = _ticks(root, axis)
    return abs((v[-1] - v[0]) / (p[-1] - p[0]))


def _markers(root) -> list[ET.Element]:
    return [c for c in root.iter(f"{SVG}circle") if c.get("data-limited") is not None]


def _limit_lines(root) -> dict[str, ET.Element]:
    return {e.get("data-limit"): e for e in root.iter(f"{SVG}line") if e.get("data-limit")}


def _check_points(rep, charts, scale: dict[str, float]) -> None:
    """The series hold the report's numbers (SI / ``scale``) and the markers sit where their
    axis puts those numbers."""
    p = rep.perf
    wind = np.asarray(p.wind_speed) / scale["wind"]
    for key, field, q in (
        ("perf_blow_by", "blow_by", "length"),
        ("perf_alpha", "alpha_eq", "angle"),
        ("perf_lift", "dynamic_lift", "force"),
        ("perf_tension", "tension_top", "force"),
        ("perf_tension", "tension_winch", "force"),
        ("perf_tension", "safety_factor", "ratio"),
    ):
        root = charts[key]
        x, y, axis = _series(root, field)
        np.testing.assert_allclose(x, wind, rtol=1e-8)
        np.testing.assert_allclose(y, np.asarray(getattr(p, field)) / scale[q], rtol=1e-8,
                                   atol=1e-12)  # fmt: skip
        assert axis == ("y2" if field == "safety_factor" else "y")
    for key in ("perf_blow_by", "perf_alpha", "perf_lift", "perf_tension"):
        root = charts[key]
        marks = _markers(root)
        mx = np.array([float(c.get("data-x")) for c in marks])
        my = np.array([float(c.get("data-y")) for c in marks])
        np.testing.assert_allclose(mx, wind, rtol=1e-8)
        cx = np.array([float(c.get("cx")) for c in marks])
        cy = np.array([float(c.get("cy")) for c in marks])
        np.testing.assert_allclose(_value_at(root, "x", cx), mx, atol=0.1 * _tolerance(root, "x"))
        np.testing.assert_allclose(_value_at(root, "y", cy), my, atol=0.1 * _tolerance(root, "y"))
    c = rep.cm
    a, cm, _ = _series(charts["perf_cm"], "cm")
    np.testing.assert_allclose(a, c.alpha_deg, rtol=1e-8)
    np.testing.assert_allclose(cm, c.cm, rtol=1e-8, atol=1e-12)


def test_points_are_the_reports_numbers_in_si(rep):
    charts = _charts(rep)
    _check_points(rep, charts, {"wind": 1.0, "length": 1.0, "force": 1.0, "angle": 1.0,
                                "ratio": 1.0})  # fmt: skip
    assert charts["perf_blow_by"].get("data-y-unit") == "m"
    assert charts["perf_tension"].get("data-y2-unit") == "-"


def test_points_are_the_reports_numbers_in_us_units(rep, us):
    charts = _charts(rep)
    _check_points(rep, charts, {"wind": KT, "length": FT, "force": LBF, "angle": 1.0,
                                "ratio": 1.0})  # fmt: skip
    blow = charts["perf_blow_by"]
    assert (blow.get("data-x-unit"), blow.get("data-y-unit")) == ("kt", "ft")
    assert charts["perf_tension"].get("data-y-unit") == "lbf"
    texts = {"".join(t.itertext()) for r in charts.values() for t in r.iter(f"{SVG}text")}
    assert {"Blow-by [ft]", "Wind speed at the aerostat [kt]", "Tether tension [lbf]",
            "Dynamic lift [lbf]"} <= texts  # fmt: skip
    assert f"blow-by limit {rep.limits.blow_by_limit / FT:.1f} ft" in texts
    assert not any("[m]" in t or "[N]" in t or "m/s" in t for t in texts), texts


@pytest.mark.parametrize("system", ["SI", "US"])
def test_requirement_lines_are_at_their_values(rep, system):
    formats.use_system(system)
    try:
        charts = _charts(rep)
    finally:
        formats.use_system("SI")
    wind, length = (KT, FT) if system == "US" else (1.0, 1.0)
    lim = rep.limits
    expected = {
        "perf_blow_by": {"design_wind": lim.design_wind / wind,
                         "blow_by_limit": lim.blow_by_limit / length},
        "perf_alpha": {"design_wind": lim.design_wind / wind, "stall_deg": lim.stall_deg},
        "perf_lift": {"design_wind": lim.design_wind / wind},
        "perf_tension": {"design_wind": lim.design_wind / wind,
                         "min_safety_factor": lim.min_safety_factor},
        "perf_cm": {"zero": 0.0},
    }  # fmt: skip
    for key, lines in expected.items():
        root = charts[key]
        drawn = _limit_lines(root)
        assert set(drawn) == set(lines), key
        for name, value in lines.items():
            e = drawn[name]
            # written to 9 significant digits
            assert float(e.get("data-value")) == pytest.approx(value, rel=1e-8), (key, name)
            axis = e.get("data-axis")
            place = float(e.get("x1")) if axis == "x" else float(e.get("y1"))
            assert _value_at(root, axis, place) == pytest.approx(
                value, abs=0.1 * _tolerance(root, axis)
            ), (key, name)
    # the limit lines are drawn in the limit colour, the safety factor's in its curve's
    assert _limit_lines(charts["perf_blow_by"])["blow_by_limit"].get("stroke") == "#d62728"
    assert _limit_lines(charts["perf_tension"])["min_safety_factor"].get("stroke") == "#009e73"


def test_red_crosses_exactly_where_a_limit_is_broken(rep):
    charts = _charts(rep)
    p = rep.perf
    limited = np.asarray(p.limited, bool)
    for key in ("perf_blow_by", "perf_alpha", "perf_lift", "perf_tension"):
        root = charts[key]
        crosses = [g for g in root.iter(f"{SVG}g") if g.get("data-limit-point")]
        np.testing.assert_allclose([float(g.get("data-x")) for g in crosses],
                                   p.wind_speed[limited])  # fmt: skip
        # each cross says why (the table's last column), in the limit colour
        idx = np.flatnonzero(limited)
        assert [g.find(f"{SVG}title").text for g in crosses] == [p.flag_text[i] for i in idx]
        assert all(g.find(f"{SVG}path").get("stroke") == "#d62728" for g in crosses)
        assert [int(c.get("data-limited")) for c in _markers(root)] == limited.astype(int).tolist()
        assert "operating limit exceeded" in ET.tostring(root, encoding="unicode")
    assert not [g for g in charts["perf_cm"].iter(f"{SVG}g") if g.get("data-limit-point")]


def test_no_cross_and_no_legend_entry_when_nothing_is_broken(rep):
    n = rep.perf.wind_speed.size
    calm = replace(rep, perf=replace(rep.perf, limited=np.zeros(n, bool), flag_text=("",) * n))
    for root in _charts(calm).values():
        assert not [g for g in root.iter(f"{SVG}g") if g.get("data-limit-point")]
        assert "operating limit exceeded" not in ET.tostring(root, encoding="unicode")


def test_trim_point_is_on_the_cm_curve(rep):
    root = _charts(rep)["perf_cm"]
    trim = next(g for g in root.iter(f"{SVG}g") if g.get("data-trim"))
    a_eq = float(rep.cm.alpha_eq_deg)
    assert float(trim.get("data-x")) == pytest.approx(a_eq)
    assert float(trim.get("data-y")) == pytest.approx(np.interp(a_eq, rep.cm.alpha_deg, rep.cm.cm))
    dot = trim.find(f"{SVG}circle")
    assert dot.get("fill") == "#009e73"  # green, as the caption says
    assert _value_at(root, "x", float(dot.get("cx"))) == pytest.approx(
        a_eq, abs=0.1 * _tolerance(root, "x")
    )


def test_every_chart_has_a_title_and_a_text_alternative(rep):
    charts = perf_view.performance_charts(rep)
    for c in charts:
        root = ET.fromstring(c.svg)
        assert root[0].tag == f"{SVG}title" and root[0].text == c.alt
        assert root.get("role") == "img"
    alts = {c.key: c.alt for c in charts}
    assert "blow-by limit 53.4 m" in alts["perf_blow_by"]
    assert "5 sweep speeds break an operating limit" in alts["perf_blow_by"]
    assert "required safety factor 3" in alts["perf_tension"]


def test_a_missing_value_leaves_a_gap_not_nan(rep):
    y = np.array(rep.perf.blow_by, float)
    y[3] = np.nan
    y[10] = np.inf
    holes = replace(rep, perf=replace(rep.perf, blow_by=y))
    root = _charts(holes)["perf_blow_by"]  # no "nan"/"inf" text (checked in _charts)
    x, drawn, _ = _series(root, "blow_by")
    keep = np.isfinite(y)
    np.testing.assert_allclose(drawn, y[keep])
    np.testing.assert_allclose(x, rep.perf.wind_speed[keep])
    path = next(g for g in root.iter(f"{SVG}g") if g.get("data-series") == "blow_by")
    assert path.find(f"{SVG}path").get("d").count("M") == 3  # three pieces around two holes


@settings(max_examples=200, deadline=None)
@given(
    st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False),
    st.floats(0, 1e6, allow_nan=False, allow_infinity=False),
)
def test_nice_ticks_cover_the_range_with_round_steps(lo, span):
    hi = lo + span
    t = perf_view.nice_ticks(lo, hi)
    assert 3 <= len(t) <= 12
    steps = np.diff(t)
    step = steps[0]
    # every value within the axis, to a billionth of a step (rounding noise: -2e-15 deg is 0)
    slack = 1e-9 * step + 1e-12 * max(abs(lo), abs(hi))
    assert t[0] <= lo + slack and t[-1] >= hi - slack
    # a round step (1, 2 or 5 x 10^k), to the float resolution of the tick values
    k = 10.0 ** np.floor(np.log10(step))
    nice = min((m * k for m in (1.0, 2.0, 5.0, 10.0)), key=lambda c: abs(c - step))
    np.testing.assert_allclose(steps, nice, rtol=1e-9, atol=8 * np.spacing(np.abs(t).max()))
    labels = [perf_view._tick_text(v, t) for v in t]
    assert len(set(labels)) == len(labels)  # every tick label differs from its neighbours
    assert not any(RAW.search(s) for s in labels), labels


def test_the_modules_examples_hold():
    import doctest

    assert doctest.testmod(perf_view).failed == 0


# --- the sweep's tables (app_ui/tables.py: performance_html) -----------------------------------


def _perf_tables(rep) -> tuple[list[str], list[ET.Element], str]:
    from app_ui import tables

    html = tables.performance_html(tables.performance_frame(rep.performance_rows))
    assert not RAW.search(html.split("</style>", 1)[1]), RAW.search(html).group(0)
    root = ET.fromstring(html.split("</style>", 1)[1])  # the block is valid XML: all escaped
    titles = ["".join(p.itertext()) for p in root.iter("p") if p.find("strong") is not None]
    return titles, list(root.iter("table")), html


@pytest.mark.parametrize("system", ["SI", "US"])
def test_sweep_tables_show_every_value_as_formatted_with_limited_rows_red(rep, system):
    from app_ui import tables

    formats.use_system(system)
    try:
        titles, found, html = _perf_tables(rep)
        df = tables.performance_frame(rep.performance_rows)
        assert titles == list(tables.PERF_TABLES)
        limited = np.asarray(rep.perf.limited, bool)
        for (title, columns), t in zip(tables.PERF_TABLES.items(), found):
            heads = [th for th in t.iter("th")]
            assert ["".join(h.itertext()) for h in heads] == [formats.relabel(c) for c in columns]
            for h, c in zip(heads, columns):  # the short header's explanation on hover
                assert h.get("title") == tables.PERF_HELP.get(c)
            rows = list(t.find("tbody"))
            assert [r.get("class") == "limit" for r in rows] == limited.tolist(), title
            for j, c in enumerate(columns):
                cells = ["".join(r[j].itertext()) for r in rows]
                if c in tables.PERF_KINDS:
                    fmt = formats.shown_formatter(tables.PERF_KINDS[c])
                    assert cells == [fmt(v) for v in df[c]], (title, c)
                else:
                    assert cells == list(df[c]), (title, c)
        assert "background-color: #fde2e2" in html  # the red of the plots' limited rows
    finally:
        formats.use_system("SI")
    if system == "US":
        heads = ["".join(h.itertext()) for h in found[0].iter("th")]
        assert heads[:3] == ["Wind [kt]", "Blow-by [ft]", "Flying height [ft]"]
        first = ["".join(c.itertext()) for c in found[0].find("tbody")[-1]]
        assert first[1] == f"{rep.perf.blow_by[-1] / FT:,.1f}"
