"""The unit system the user chooses (issue 24 item 5): the inputs typed in it, the plots and the
other pages shown in it, and the conversions exact enough that switching units never changes a
design. AppTest (headless) and pure checks; the browser test is tests/e2e/test_ux_e2e.py."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from streamlit.testing.v1 import AppTest

from aerostat_core.model.input_paths import all_specs
from app_ui import formats, show
from app_ui.form_model import FIELDS, build_inputs, widget_values
from tests.app.conftest import APP_PATH
from tests.app.helpers import (
    chart,
    goto,
    messages,
    metrics,
    open_groups,
    perf_charts,
    show_tab,
    submit,
    svg_limit_lines,
    svg_series,
)

#: 1 ft, 1 lb, 1 kt in SI (exact definitions).
FT, LB, KT = 0.3048, 0.45359237, 1852.0 / 3600.0
LBF = LB * 9.80665  # 1 lbf in N
NUMBERS = [p for p in all_specs() if p.spec.kind == "number" and p.spec.lo is not None]


def _app() -> AppTest:
    at = AppTest.from_file(str(APP_PATH), default_timeout=180).run()
    assert not at.exception, [e.value for e in at.exception]
    return at


def _units(at: AppTest, system: str) -> AppTest:
    """Choose the unit system with the sidebar's switch (AppTest keeps app.py's sidebar only in
    the first run's tree: later, as the switch's callback does, through the session)."""
    switch = [w for w in at.radio if w.key == "unit_system"]
    if switch:
        switch[0].set_value(system).run()
    else:
        at.session_state[show.CHOICE_KEY] = system
        at.run()
    assert not at.exception, [e.value for e in at.exception]
    return at


def _box(at: AppTest, key: str):
    open_groups(at, key)
    return next(w for w in at.text_input if w.key == key)


# --- conversions over each field's range --------------------------------------------------------


@settings(max_examples=300, deadline=None)
@given(st.sampled_from(NUMBERS), st.floats(0.0, 1.0))
def test_box_conversions_round_trip_over_each_fields_range(entry, t):
    """Every registry number, anywhere in its range: its US box shows the US value to 6
    significant digits; the unrounded US value gives the SI value back to 12 (the program's
    exactness); the SI box is exact as before."""
    s = entry.spec
    lo, hi = float(s.lo), float(min(s.hi, 1e9))
    x = lo + t * (hi - lo)
    for system in ("SI", "US"):
        du = formats.field_unit(s, system)
        assert formats.box_to_si(du.show(x), s, system) == pytest.approx(x, rel=1e-11, abs=1e-12)
        shown = float(formats.box_text(x, s, system))
        if system == "SI":
            back = formats.box_to_si(shown, s, system)
            assert back == pytest.approx(x, rel=1e-11, abs=1e-9 * max(1.0, abs(hi))), entry.path
        else:
            # 6 significant digits of the value in the box's own unit. Compared there, not in
            # SI: for an affine unit the SI error of a rounded box is not relative to the SI
            # value (25.3342 degF is -3.70322 degC, 1.5e-5 of it, for 1e-4 degF).
            u = du.show(x)
            assert shown == pytest.approx(u, rel=6e-6, abs=1e-9 * max(1.0, abs(hi))), entry.path
    lo_b, hi_b, step = formats.box_bounds(s, "US")
    if lo_b is not None:
        assert formats.box_to_si(lo_b, s, "US") == pytest.approx(lo, rel=1e-9, abs=1e-12)
    if step is not None:
        assert step > 0


def test_us_boxes_speak_feet_knots_pounds_and_fahrenheit():
    us = {f.key: f.label_in("US") for f in FIELDS}
    assert us["in_payload"].startswith("Payload mass [lb]")
    assert "[ft]" in us["in_altitude"] and "[kt]" in us["in_design_wind"]
    assert "[ft³]" in us["in_volume"] and "[°F]" in us["in_site_temp"]
    assert "[lbf]" in us["in_tether_mbl"] and "[in]" in us["in_tether_dia"]
    # dimensionless and percent boxes read the same in both systems
    assert us["in_fineness"] == FIELDS[[f.key for f in FIELDS].index("in_fineness")].label
    help_us = next(f for f in FIELDS if f.key == "in_payload").help_in("US")
    assert "lb" in help_us and "22046.2" in help_us


def test_a_value_typed_in_us_units_builds_the_design_of_its_si_equivalent(thesis_at):
    base = thesis_at.session_state["design_inputs"]
    us = widget_values(base, system="US")
    si = widget_values(base, system="SI")
    typed_us = {**us, "in_altitude": "1000", "in_payload": "22", "in_wind_max": "30"}
    typed_si = {
        **si,
        "in_altitude": "304.8",
        "in_payload": f"{22 * LB:.12g}",
        "in_wind_max": f"{30 * KT:.12g}",
    }
    a = build_inputs(typed_us, base, "US")
    b = build_inputs(typed_si, base, "SI")
    assert a == b
    assert a[0].altitude == 304.8 and a[0].payload_mass == pytest.approx(22 * LB, rel=1e-11)
    # the untouched boxes keep their exact SI values in either system
    assert build_inputs(us, base, "US") == build_inputs(si, base, "SI")


# --- the app: the Design form in US units -------------------------------------------------------


def test_design_form_takes_us_units_and_the_switch_never_changes_the_design():
    at = _units(_app(), "US")
    assert _box(at, "in_altitude").label == "Operating altitude [ft]"
    assert _box(at, "in_payload").label == "Payload mass [lb]"
    before = at.session_state["design_inputs"]
    assert float(_box(at, "in_altitude").value) == pytest.approx(
        before["requirement"]["altitude"] / FT, rel=1e-6
    )
    # applying the US boxes untouched, and switching back and applying, keep the design
    at.button(key="in_submit").click().run()
    assert at.session_state["design_inputs"] == before
    _units(at, "SI")
    at.button(key="in_submit").click().run()
    assert at.session_state["design_inputs"] == before
    assert _box(at, "in_altitude").label == "Operating altitude [m]"
    # a US user types 1000 ft and 22 lb: the design is 304.8 m and 9.979 kg
    _units(at, "US")
    submit(at, in_altitude="1000", in_payload="22", in_design_wind="30")
    assert not at.exception and not at.error, [e.value for e in at.error]
    req = at.session_state["design_inputs"]["requirement"]
    assert req["altitude"] == 304.8
    assert req["payload_mass"] == pytest.approx(22 * LB, rel=1e-11)
    assert req["design_wind"] == pytest.approx(30 * KT, rel=1e-11)
    assert _box(at, "in_altitude").value == "1000"
    assert [m.label for m in metrics(at)][:2] == ["Volume [ft³]", "Length [ft]"]
    # the design-wind line inside the headline block, in knots, before the wind numbers
    body = next(str(e.proto.body) for e in at.get("html") if "headline-note" in str(e.proto.body))
    note = body.index('data-testid="headline-note">At the design wind, 30.0 kt:</p>')
    assert note < body.index(">Blow-by [ft]<")
    assert body.index(">Free lift [lb]<") < note


def test_an_edit_not_applied_is_converted_by_a_switch():
    """A box the design does not show (a rejected value stays in its box to be corrected) keeps
    its number through a switch, in the new unit. (Text typed in the form and not submitted stays
    in the browser: a rerun does not see it.)"""
    at = _app()
    submit(at, in_altitude="5")  # 5 m: below the range, rejected, left in the box
    assert at.error
    _units(at, "US")
    assert _box(at, "in_altitude").value == "16.4042"
    assert _box(at, "in_payload").value == "22.0462"  # 10 kg, untouched


def test_a_rejected_us_value_is_named_in_us_units():
    at = _units(_app(), "US")
    submit(at, in_altitude="5")
    text = " ".join(messages(at, "error"))
    assert "Operating altitude [ft]: 5 is not allowed" in text and "32.8084 and 16404.2" in text


def test_design_plots_follow_the_unit_system():
    at = _app()
    show_tab(at, "Performance")
    si = perf_charts(at)
    at = _units(at, "US")
    us = perf_charts(at)
    # the static drawings: axes, points and requirement lines in kt, ft and lbf
    blow = us["perf_blow_by"]
    assert (blow.get("data-x-unit"), blow.get("data-y-unit")) == ("kt", "ft")
    texts = ["".join(t.itertext()) for t in blow.iter("{http://www.w3.org/2000/svg}text")]
    assert "Blow-by [ft]" in texts and "Wind speed at the aerostat [kt]" in texts
    for key, field, factor in (("perf_blow_by", "blow_by", FT), ("perf_alpha", "alpha_eq", 1.0),
                               ("perf_lift", "dynamic_lift", LBF),
                               ("perf_tension", "tension_top", LBF),
                               ("perf_tension", "safety_factor", 1.0)):  # fmt: skip
        x_si, y_si = svg_series(si[key], field)
        x_us, y_us = svg_series(us[key], field)
        np.testing.assert_allclose(x_us, x_si / KT, rtol=1e-8)
        np.testing.assert_allclose(y_us, y_si / factor, rtol=1e-8, atol=1e-12)
        assert svg_limit_lines(us[key])["design_wind"] == pytest.approx(
            svg_limit_lines(si[key])["design_wind"] / KT
        )
    assert svg_limit_lines(blow)["blow_by_limit"] == pytest.approx(
        svg_limit_lines(si["perf_blow_by"])["blow_by_limit"] / FT
    )
    assert us["perf_tension"].get("data-y-unit") == "lbf"
    assert svg_limit_lines(us["perf_tension"])["min_safety_factor"] == svg_limit_lines(
        si["perf_tension"]
    )["min_safety_factor"]  # dimensionless: the same number
    # the interactive plotly figures too
    at.toggle(key="perf_interactive").set_value(True).run()
    fig = chart(at, "perf_blow_by")
    assert fig["layout"]["yaxis"]["title"]["text"] == "Blow-by [ft]"
    assert fig["layout"]["xaxis"]["title"]["text"].endswith("[kt]")
    tension = chart(at, "perf_tension")
    assert tension["layout"]["yaxis"]["title"]["text"] == "Tether tension [lbf]"


# --- the other pages in US units ----------------------------------------------------------------


def _page(page: str) -> AppTest:
    at = _units(_app(), "US")
    goto(at, page)
    assert not at.exception, [e.value for e in at.exception]
    return at


def test_sensitivity_page_in_us_units():
    at = _page("pages/3_Sensitivity.py")
    text = " ".join(str(m.value) for m in at.markdown)
    assert " lb at " in text and " ft; blow-by limit " in text and " kt;" in text
    fig = chart(at, "sens_ofat")
    titles = [
        v["title"]["text"]
        for k, v in fig["layout"].items()
        if k.startswith("yaxis") and isinstance(v, dict) and v.get("title")
    ]
    assert any("[lb]" in t for t in titles) and not any("[kg]" in t for t in titles)


def test_optimise_page_limit_box_in_feet():
    from aerostat_core.model.io import inputs_from_dict

    at = _page("pages/4_Optimise.py")
    box = next(w for w in at.text_input if w.key == "opt_limit")
    assert box.label.endswith("[ft]")
    limit = inputs_from_dict(at.session_state["design_inputs"])[0].resolved().blow_by_limit
    assert float(box.value) == pytest.approx(limit / FT, rel=1e-6)
    caption = " ".join(str(c.value) for c in at.caption)
    assert " lb at " in caption and " ft, rule set " in caption


def test_compare_shapes_and_method_pages_in_us_units():
    at = _page("pages/7_Shapes.py")
    fig = chart(at, "shape_fig_full")
    assert fig["layout"]["yaxis"]["title"]["text"] == "Blow-by [ft]"
    goto(at, "pages/6_Method.py")
    assert not at.exception, [e.value for e in at.exception]
    goto(at, "pages/2_Compare.py")
    assert not at.exception, [e.value for e in at.exception]


def test_envelope_tab_in_us_units():
    at = _units(_app(), "US")
    show_tab(at, "Envelope")
    assert not at.exception, [e.value for e in at.exception]
    fig = chart(at, "envelope_map")
    assert fig["layout"]["yaxis"]["title"]["text"] == "Altitude = tether length [ft]"
    assert fig["layout"]["xaxis"]["title"]["text"].endswith("[kt]")
    site = next(w for w in at.text_input if w.key == "site_c")
    assert site.label.endswith("[kt]") and math.isclose(float(site.value), 6.0 / KT, rel_tol=1e-5)


# --- tables of the study pages ------------------------------------------------------------------


@pytest.fixture
def us():
    formats.use_system("US")
    yield
    formats.use_system("SI")


def test_a_table_with_a_unit_column_shows_each_row_in_the_chosen_units(us):
    from app_ui.tables import labelled_table

    rows = [
        {"signal": "x_C", "unit": "m", "mean": 30.48, "ratio": 2.0, "t": 5.0},
        {"signal": "theta", "unit": "deg", "mean": 3.0, "ratio": 2.0, "t": 5.0},
    ]
    cols = {
        "signal": ("Signal", None),
        "unit": ("Unit", None),
        "mean": ("Mean", "{:.1f}"),
        "ratio": ("Ours / thesis [-]", "{:.1f}"),
        "t": ("First at [s]", "{:.1f}"),
    }
    df = labelled_table(rows, cols)
    assert df["Unit"].tolist() == ["ft", "deg"]
    assert df["Mean"].tolist() == ["100.0", "3.0"]
    assert df["Ours / thesis [-]"].tolist() == ["2.0", "2.0"]  # its own unit: unchanged
    assert df["First at [s]"].tolist() == ["5.0", "5.0"]


def test_optimise_tables_follow_the_unit_system(us):
    import pandas as pd

    from app_ui.optimize_tables import styled

    df = pd.DataFrame({"Total mass [kg]": [LB * 100], "Blow-by [m]": [FT * 500], "f [-]": [3.0]})
    shown = styled(df)
    assert list(shown.data.columns) == ["Total mass [lb]", "Blow-by [ft]", "f [-]"]
    html = shown.to_html()
    assert "100.0" in html and "500.0" in html


def test_csv_downloads_keep_si_with_a_unit_row_and_add_the_chosen_units(us):
    import csv
    import io

    from app_ui.cache import csv_bytes

    got = list(csv.reader(io.StringIO(csv_bytes([{"blow_by_m": FT * 100, "f": 3.0}]).decode())))
    assert got[0] == ["blow_by_m", "blow_by_ft", "f"]
    assert got[1] == ["m", "ft", ""]
    assert float(got[2][0]) == FT * 100 and float(got[2][1]) == pytest.approx(100.0)
    formats.use_system("SI")
    si = list(csv.reader(io.StringIO(csv_bytes([{"blow_by_m": 30.0}]).decode())))
    assert si == [["blow_by_m"], ["m"], ["30.0"]]


def test_dynamics_form_takes_knots_and_runs_in_si():
    """The Dynamics form's registry-built boxes (the generic helper of app_ui.entry) show knots
    in US units and give the request m/s; an untouched box keeps its exact SI default."""
    at = _page("pages/5_Dynamics.py")
    speed = next(w for w in at.text_input if w.key == "dyn_speed")
    assert speed.label.endswith("[kt]")
    assert float(speed.value) == pytest.approx(10.0 / KT, rel=1e-5)
    speed.set_value("20")
    next(w for w in at.text_input if w.key == "dyn_duration").set_value("5")
    at.button(key="dyn_run").click().run()
    assert not at.exception, [e.value for e in at.exception]
    request = at.session_state["dyn_request"].request
    assert request.speed == pytest.approx(20 * KT, rel=1e-11)
    assert request.duration == 5.0
