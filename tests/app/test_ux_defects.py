"""Issue 24's defects, each with the check that would have caught it, and the unit system
(SI / US customary) of the display: pure functions, no browser (the browser scan of every page
is tests/e2e/test_ux_e2e.py)."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from aerostat_core import Configuration, Requirement, design, thesis_baseline
from aerostat_core.base.fields import US_CUSTOMARY, spec_display, unit_in
from aerostat_core.model.input_paths import all_specs
from aerostat_core.optimize.pareto import nondominated_mask
from aerostat_core.output.html_report import requirement_rows
from aerostat_core.output.report import comparison_rows, design_report
from aerostat_core.studies.envelope import operating_envelope
from app_ui import formats, optimize_view, plots_optimize, shapes_view, tables, theme
from tests.app.helpers import metrics

RAW = re.compile(r"^(nan|NaN|None|True|False|inf|-inf)$|^-0[.,]0*$|^-$")


@pytest.fixture
def us():
    formats.use_system("US")
    yield
    formats.use_system("SI")


# --- raw values -------------------------------------------------------------------------------


def test_envelope_limits_table_says_why_instead_of_nan():
    # a 300 m tether on a 10 m/s hull: the top altitudes are not flyable at the lowest wind,
    # where Envelope.limit_wind is NaN ("nan" in the Envelope table before)
    from app_ui.envelope_view import limits_frame

    d = design(Requirement(), Configuration())
    env = operating_envelope(d)
    assert np.isnan(env.limit_wind()[0]).any(), "the case no longer has an unflyable altitude"
    cells = limits_frame(env)["Flyable up to [m/s]"].tolist()
    assert not any(RAW.match(str(c)) for c in cells)
    assert any(c.startswith("not flyable: ") and "broken at" in c for c in cells)


def test_geometry_unit_of_a_dimensionless_row_is_not_a_markdown_bullet():
    rep = design_report(design(*thesis_baseline()))
    df = tables.geometry_frame(rep.geometry_rows)
    assert "-" not in set(df["Unit"])  # "-" alone in a static table cell rendered as a bullet
    assert "–" in set(df["Unit"])


def test_compare_differs_reads_yes_no():
    from aerostat_core.model.design import design as _design

    req, cfg = thesis_baseline()
    from dataclasses import replace

    designs = {"a": _design(req, cfg), "b": _design(replace(req, payload_mass=20.0), cfg)}
    df = tables.comparison_frame(comparison_rows(designs), list(designs))
    assert set(df["Differs"]) == {"yes", "no"}
    shown = tables.comparison_styler(df)._compute().ctx
    assert shown  # the differing rows are still highlighted


def test_on_front_does_not_flip_on_solver_noise():
    # the same optimum found at two blow-by limits, 1e-5 apart: both on the front (exact
    # dominance put one on and one off, rows that read the same)
    mass = np.array([35.02201, 35.02198, 40.0])
    bb = np.array([128.0003, 128.0001, 100.0])
    assert nondominated_mask(mass, bb).tolist() == [True, True, True]
    assert nondominated_mask(mass, bb, rtol=0.0).tolist() == [False, True, True]


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(1, 1e3), st.floats(1, 1e3)), min_size=1, max_size=20))
def test_points_that_read_the_same_share_their_front_verdict(points):
    a = np.array([p[0] for p in points])
    b = np.array([p[1] for p in points])
    a2, b2 = np.append(a, a[0] * (1 + 1e-6)), np.append(b, b[0] * (1 - 1e-6))
    nd = nondominated_mask(a2, b2)
    assert nd[0] == nd[-1]


def test_pareto_and_sweep_flags_are_words():
    from aerostat_core.optimize import pareto_front

    req, cfg = thesis_baseline()
    front = pareto_front(req, cfg, limits=[60.0, 80.0])
    from app_ui.optimize_tables import pareto_frame

    assert set(pareto_frame(front)["On front"]) <= {"yes", "no"}


def test_labelled_table_has_no_negative_zero_no_bullet_and_says_why():
    df = tables.labelled_table(
        [{"v": -0.0004, "u": "-", "first": None, "x": float("nan")}],
        {
            "v": ("Min", "{:.3f}"),
            "u": ("Unit", None),
            "first": ("First at [s]", "{:.1f}", "not exceeded"),
            "x": ("X", "{:.1f}"),
        },
    )
    assert df.iloc[0].tolist() == ["0.000", "–", "not exceeded", "not computed: no value"]


def test_dynamics_limit_note_carries_its_unit():
    from app_ui.dynamics_view import limit_lines

    out = {"signals": {"T": [10.0, 20.0]}}
    _lines, note = limit_lines(out, ["T"], [(12_000.0, "safe working load")], unit="N")
    assert note == "; not reached: safe working load 12,000 N"


def test_envelope_uncertainty_text_has_no_nan():
    import pandas as pd

    from app_ui.envelope_view import _text_frame

    df = _text_frame(pd.DataFrame({"q": ["a"], "v": [float("nan")]}))
    assert not RAW.match(df["v"].iloc[0]) and df["v"].iloc[0].startswith("not computed")


# --- labels, captions, figures ------------------------------------------------------------------


def test_export_buttons_differ_in_what_a_cut_label_shows():
    labels = [b[1] for b in shapes_view.EXPORT_BUTTONS]
    assert len({lab[:5] for lab in labels}) == len(labels)  # "DXF: ", "SVG: ", ...


def test_resize_caption_matches_the_sweeps():
    from aerostat_core.studies.sensitivity import one_at_a_time

    res = one_at_a_time(Requirement(), Configuration(), n_points=3, resize=True)
    ok = [r for r in res.rows() if r["feasible"]]
    below = all(r["blow_by_m"] < 0.99 * res.blow_by_limit for r in ok)
    cap = optimize_view.resize_caption(res)
    assert below and "below the limit" in cap and "equals the limit" not in cap
    res = one_at_a_time(*thesis_baseline(), n_points=3, resize=True)
    assert "equals the limit" in optimize_view.resize_caption(res)


def test_map_legend_is_clear_of_the_colour_bar():
    from aerostat_core.studies.sensitivity import two_variable_map

    req, cfg = thesis_baseline()
    m = two_variable_map(req, cfg, "fineness_ratio", "position", n=4, resize=False)
    fig = plots_optimize.map_figure(m)
    leg = fig.layout.legend
    # the colour bar (and its title) on the right of the plot, the legend above it on the left
    assert leg.orientation == "h" and leg.y >= 1.0 and leg.x <= 0.1 and leg.yanchor == "bottom"
    bar = fig.data[0].colorbar
    assert bar.title.text and (bar.x is None or bar.x >= 1.0)
    assert fig.layout.margin.t >= 30 + 20 * (fig.layout.title.text.count("<br>") + 1)


def test_long_figure_titles_wrap_instead_of_being_cut():
    title = "Total mass over fin position Δl_f × fineness ratio l/d (hull re-sized at every point)"
    lay = theme.base_layout(title)
    lines = lay["title"]["text"].split("<br>")
    assert len(lines) > 1 and all(len(x) <= theme.TITLE_CHARS for x in lines)
    assert " ".join(lines) == title
    assert lay["margin"]["t"] >= 30 + 20 * len(lines)


# --- unit systems -----------------------------------------------------------------------------


def test_us_customary_factors_are_the_exact_definitions():
    assert unit_in("m", "US").show(0.3048) == pytest.approx(1.0, rel=1e-15)
    assert unit_in("kg", "US").show(0.45359237) == pytest.approx(1.0, rel=1e-15)
    assert unit_in("N", "US").show(4.4482216152605) == pytest.approx(1.0, rel=1e-13)
    assert unit_in("m/s", "US").show(1852 / 3600) == pytest.approx(1.0, rel=1e-15)
    assert unit_in("m3", "US").show(0.3048**3) == pytest.approx(1.0, rel=1e-15)
    assert unit_in("degC", "US").show(100.0) == pytest.approx(212.0)
    assert unit_in("degC", "US").show(-40.0) == pytest.approx(-40.0)


@given(st.sampled_from(sorted(US_CUSTOMARY)), st.floats(-1e6, 1e6))
def test_display_units_round_trip(token, x):
    du = US_CUSTOMARY[token]
    assert du.to_si(du.show(x)) == pytest.approx(x, rel=1e-12, abs=1e-9)


def test_every_field_has_a_display_unit_in_both_systems():
    for p in all_specs():
        if p.spec.kind not in ("number", "integer"):
            continue
        si, us_ = spec_display(p.spec, "SI"), spec_display(p.spec, "US")
        assert si.unit == p.spec.shown_unit and si.scale == p.spec.scale
        assert us_.unit  # never blank
        if p.spec.unit in ("m", "kg", "m/s", "m3") and p.spec.scale == 1.0:
            assert us_.unit in ("ft", "lb", "kt", "ft³", "ft above sea level"), p.path


def test_formats_follow_the_chosen_system(us):
    assert formats.label("Volume", "volume") == "Volume [ft³]"
    assert formats.shown(170.0, "volume") == "6,003.5"
    assert formats.shown(10.0, "wind", with_unit=True) == "19.4 kt"
    assert formats.relabel("Blow-by [m]") == "Blow-by [ft]"
    assert formats.relabel("Share [%]") == "Share [%]"
    # the SI-only helpers keep SI (their labels say SI)
    assert formats.text(170.0, "volume") == "170.0"


def test_design_tables_in_us_units(us):
    rep = design_report(design(*thesis_baseline()))
    perf = tables.performance_styler(tables.performance_frame(rep.performance_rows))
    assert "Blow-by [ft]" in perf.data.columns and "Wind [kt]" in perf.data.columns
    mass = tables.mass_styler(tables.mass_frame(rep.mass_rows))
    assert "Mass [lb]" in mass.data.columns
    # the page's HTML table: US units, no metre left
    page = tables.geometry_html(tables.geometry_frame(rep.geometry_rows))
    assert "<td>ft³</td>" in page and "<td>ft</td>" in page and "<td>m</td>" not in page


def test_report_requirement_has_labels_and_units_and_the_verdict_first():
    req = thesis_baseline()[0]
    rows = requirement_rows(req)
    labels = {r["quantity"] for r in rows}
    assert "Payload mass" in labels and "payload_mass" not in labels
    units = {r["quantity"]: r["unit"] for r in rows}
    assert units["Payload mass"] == "kg" and units["Operating altitude"] == "m"
    us_rows = {r["quantity"]: r for r in requirement_rows(req, "US")}
    assert us_rows["Operating altitude"]["unit"] == "ft"
    assert us_rows["Operating altitude"]["value"] == pytest.approx(req.altitude / 0.3048)
    assert not any(isinstance(r["value"], float) and math.isnan(r["value"]) for r in rows)


def test_exports_keep_si_with_a_unit_row_and_optionally_the_chosen_units():
    import csv
    import io

    rep = design_report(design(*thesis_baseline()))
    si = list(csv.reader(io.StringIO(tables.export_csv(rep.performance_rows, "SI").decode())))
    assert si[0] == list(rep.performance_rows[0])  # the public SI column names, unchanged
    units = dict(zip(si[0], si[1]))
    assert units["blow_by_m"] == "m" and units["wind_speed_m_s"] == "m/s"
    assert units["tension_top_N"] == "N" and units["safety_factor"] == ""
    assert float(si[2][si[0].index("blow_by_m")]) == rep.performance_rows[0]["blow_by_m"]
    us_ = list(csv.DictReader(io.StringIO(tables.export_csv(rep.performance_rows, "US").decode())))
    unit_row, first = us_[0], us_[1]
    assert unit_row["blow_by_ft"] == "ft" and unit_row["wind_speed_kt"] == "kt"
    assert float(first["blow_by_ft"]) == pytest.approx(float(first["blow_by_m"]) / 0.3048)
    assert float(first["tension_top_lbf"]) == pytest.approx(
        float(first["tension_top_N"]) / 4.4482216152605
    )


def test_rule_set_spread_flags_read_yes_no():
    import pandas as pd

    from app_ui.envelope_view import _text_frame

    df = _text_frame(pd.DataFrame({"q": ["feasible", "volume"], "practice": [True, 55.2]}))
    assert df["practice"].tolist() == ["yes", "55.2"]


def test_the_unit_choice_survives_reruns():
    """The sidebar switch's choice holds on every later run (a widget drawn by app.py loses its
    own state on a rerun: the choice is kept apart by its callback)."""
    from pathlib import Path

    from streamlit.testing.v1 import AppTest

    app = Path(__file__).resolve().parents[2] / "app.py"
    at = AppTest.from_file(str(app), default_timeout=180).run()
    switch = next(w for w in at.radio if w.key == "unit_system")
    switch.set_value("US").run()
    assert [m.label for m in metrics(at)][:2] == ["Volume [ft³]", "Length [ft]"]
    at.run()  # a later run (a tab switch, another input) keeps the choice
    assert [m.label for m in metrics(at)][:2] == ["Volume [ft³]", "Length [ft]"]
